"""`frictionlab demo` checks its optional extras before it computes anything."""

from __future__ import annotations

import importlib.util
import time
from pathlib import Path

import pytest

from frictionlab.cli import main


def test_demo_without_the_fem_extra_exits_2_at_once_and_writes_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    real = importlib.util.find_spec

    def without_skfem(name: str, *args: object, **kwargs: object) -> object:
        return None if name == "skfem" else real(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(importlib.util, "find_spec", without_skfem)
    out = tmp_path / "demo"
    start = time.perf_counter()
    code = main(["demo", "--out", str(out), "--quiet"])
    seconds = time.perf_counter() - start
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2
    assert len(err) == 1 and "optional extra 'fem'" in err[0] and "skfem" in err[0], err
    assert seconds < 20.0  # before: a minute of computing, then exit 2 at section 11
    assert not out.exists() or not any(out.iterdir())
