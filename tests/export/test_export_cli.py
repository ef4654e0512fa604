"""``frictionlab export abaqus``: the files, their values against the scenario, bad input."""

from __future__ import annotations

import csv
import subprocess
import tomllib
from pathlib import Path

import numpy as np
import pytest

import frictionlab
from frictionlab.cli import main
from frictionlab.export import abaqus, c_core

from .conftest import require

BUNDLED = Path(frictionlab.__file__).parent / "data" / "scenarios"
FILES = {"frictionlab_uinter.c", "props.csv", "statev.csv", "interaction_standard.inp",
         "interaction_explicit.inp", "README.md", "summary.json"}  # fmt: skip


def _props(out: Path) -> dict[str, float]:
    with (out / "props.csv").open() as f:
        return {row["name"]: float(row["value"]) for row in csv.DictReader(f)}


def test_export_abaqus_writes_the_law_of_the_scenario(tmp_path: Path, check_summary) -> None:  # type: ignore[no-untyped-def]
    out = tmp_path / "abaqus"
    assert main(["export", "abaqus", str(BUNDLED / "orthotropy.toml"), "--out", str(out),
                 "--quiet"]) == 0  # fmt: skip
    assert {p.name for p in out.iterdir()} == FILES
    law = tomllib.loads((BUNDLED / "orthotropy.toml").read_text())["law"]
    props = _props(out)
    assert len(props) == 22
    for key in ("alpha_n", "alpha_t", "u", "kappa", "xi"):
        assert props[key] == law[key]
    assert (props["F_s"], props["F_k"]) == (law["mu_s"], law["mu_k"])
    assert props["surface"] == 0.0 and props["F_initial"] == law["mu_s"]
    C = np.asarray(law.get("orthotropy", [1.0, 1.0]), dtype=float)
    if law.get("orthotropy_convention") == "multiply":
        C = C**-0.5
    assert (props["A_1"], props["A_2"]) == pytest.approx(tuple(C), rel=1e-15)
    # the .inp data lines carry the same 22 values, in order
    lines = (out / "interaction_standard.inp").read_text().splitlines()
    assert lines[1].startswith("*SURFACE INTERACTION") and "PROPERTIES=22, DEPVAR=8" in lines[1]
    values = [float(v) for line in lines[2:] for v in line.split(",")]
    assert values == list(props.values())
    with (out / "statev.csv").open() as f:
        assert [row["name"] for row in csv.DictReader(f)] == [n for n, _, _ in abaqus.STATEV]
    summary = check_summary(out / "summary.json")
    assert summary["export"]["props"] == props


def test_exported_source_compiles_alone(tmp_path: Path) -> None:
    cc = require(c_core.compiler(), "a C compiler")
    out = tmp_path / "abaqus"
    assert main(["export", "abaqus", str(BUNDLED / "pressure.toml"), "--out", str(out),
                 "--quiet"]) == 0  # fmt: skip
    done = subprocess.run(
        [cc, *c_core.CFLAGS, "-Wall", "-Wextra", "-Werror", "-c", str(out / abaqus.SOURCE_NAME),
         "-o", str(tmp_path / "uinter.o")], capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    symbols = subprocess.run(["nm", str(tmp_path / "uinter.o")], capture_output=True, text=True)
    assert " T uinter_" in symbols.stdout and " T vuinter_" in symbols.stdout


def test_per_point_law_is_refused_naming_the_key(tmp_path: Path, capsys) -> None:  # type: ignore[no-untyped-def]
    out = tmp_path / "abaqus"
    code = main(["export", "abaqus", str(BUNDLED / "rotation.toml"), "--out", str(out),
                 "--set", "law.mu_k=[0.3, 0.35]"])  # fmt: skip
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1
    assert "law.mu_k" in err and "one value" in err
    assert not out.exists()


def test_the_docs_tables_are_the_routine_tables() -> None:
    """docs/fe-codes.md lists PROPS and STATEV as abaqus.PROPS and abaqus.STATEV do."""
    text = (Path(__file__).resolve().parents[2] / "docs" / "fe-codes.md").read_text()
    for tag, rows in (("props", abaqus.PROPS), ("statev", abaqus.STATEV)):
        block = text.split(f"<!-- {tag}:start -->")[1].split(f"<!-- {tag}:end -->")[0]
        lines = block.strip().splitlines()[2:]
        want = [f"| {k + 1} | {n} | {u} | {m.replace('|', chr(92) + '|')} |"
                for k, (n, u, m) in enumerate(rows)]  # fmt: skip
        assert lines == want, tag
