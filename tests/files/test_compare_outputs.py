"""benchmarks/compare_outputs.py finds what differs between two output trees, and only that."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

_PATH = Path(__file__).resolve().parents[2] / "benchmarks" / "compare_outputs.py"


@pytest.fixture(scope="module")
def compare():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("compare_outputs", _PATH)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _tree(root: Path, mu: str, seconds: float, extra: bool = False) -> Path:
    (root / "a").mkdir(parents=True)
    (root / "a" / "t.csv").write_text(f"# x\nbeta [deg],mu [-]\n0,0.5\n90,{mu}\n")
    summary = {"mu": float(mu), "seconds": seconds, "provenance": {"created_utc": str(seconds)},
               "scenario": f"{root}/pkg/frictionlab/data/s.toml"}  # fmt: skip
    (root / "a" / "summary.json").write_text(json.dumps(summary))
    (root / "a" / "p.png").write_bytes(b"png" + mu.encode())
    if extra:
        (root / "new.json").write_text("{}")
    return root


def test_equal_trees_differ_only_in_timings_and_folders(tmp_path: Path, compare) -> None:  # type: ignore[no-untyped-def]
    old = _tree(tmp_path / "old", "0.7", 1.0)
    new = _tree(tmp_path / "new", "0.7", 2.0)
    assert compare.compare_trees(old, new) == {}
    assert compare.main([str(old), str(new)]) == 0


def test_a_changed_value_and_a_new_file_are_reported(tmp_path: Path, compare) -> None:  # type: ignore[no-untyped-def]
    old = _tree(tmp_path / "old", "0.7", 1.0)
    new = _tree(tmp_path / "new", "0.70001", 1.0, extra=True)
    found = compare.compare_trees(old, new)
    assert found["a/t.csv"] == ["1 cell(s) differ, first row 2 mu [-]: 0.7 -> 0.70001"]
    assert found["a/summary.json"] == [".mu: 0.7 -> 0.70001"]
    assert found["a/p.png"] == ["bytes differ"]
    assert found["new.json"] == ["only in NEW"]
    assert compare.compare_trees(old, new, rtol=1e-4).keys() == {"a/p.png", "new.json"}
    assert compare.main([str(old), str(new)]) == 1
