"""Reading tribometer exports: a lab's format loads in SI units; bad data are refused."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from frictionlab.errors import InputError
from frictionlab.io.tribometer import read_tribometer

LAB = {"time": "Time", "slip": "Displacement", "friction_ratio": "COF"}


def write(path: Path, lines: list[str]) -> Path:
    path.write_text("\n".join(lines) + "\n")
    return path


def test_lab_export_with_index_comments_units_row_and_extra_columns(tmp_path: Path) -> None:
    f = write(tmp_path / "run.csv", [
        "# exported by TR-2", "# operator: A. N. Other",
        ",Time,Displacement,Normal load,COF",
        ",min,mm,N,-",
        "0,0.0,0.0,10.0,0.0",
        "1,0.5,0.25,10.1,0.31",
        "2,1.0,0.5,9.9,0.32",
        "3,1.5,0.75,10.0,0.30",
        "4,2.0,1.0,10.0,0.305",
    ])  # fmt: skip
    m = read_tribometer(f, LAB)  # units from the units row
    np.testing.assert_allclose(m.time, [0.0, 30.0, 60.0, 90.0, 120.0], rtol=1e-15)
    assert m.slip is not None
    np.testing.assert_allclose(m.slip, [0.0, 2.5e-4, 5e-4, 7.5e-4, 1e-3], rtol=1e-15)
    np.testing.assert_array_equal(m.friction_ratio, [0.0, 0.31, 0.32, 0.30, 0.305])
    assert m.units == {"time": "min", "slip": "mm", "friction_ratio": "-"}


def test_plain_si_file_without_units_row_and_without_slip(tmp_path: Path) -> None:
    f = write(tmp_path / "plain.csv",
              ["time,friction_ratio"] + [f"{t},{0.3 + 0.01 * t}" for t in range(6)])  # fmt: skip
    m = read_tribometer(f, units={"time": "s"})
    np.testing.assert_array_equal(m.time, np.arange(6.0))
    assert m.slip is None


@pytest.mark.parametrize(
    ("rows", "units", "needle"),
    [
        (["Time,Displacement,COF", "0,0,0.1", "2,1,0.2", "1,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "line 4: column 'Time' is not strictly increasing"),
        (["Time,Displacement,COF", "0,0,0.1", "1,1,nan", "2,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "line 3: column 'COF' = 'nan' is not a number"),
        (["Time,Displacement,COF", "0,0,0.1", "1,1,", "2,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "line 3: column 'COF' is empty"),
        (["Time,Displacement,COF", "0,0,0.1", "1,1,0.2"], None, "only 2 samples"),
        (["Time,Displacement,Friction", "0,0,0.1", "1,1,0.2", "2,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "missing column 'COF'"),
        (["Time,COF,Displacement,COF", "0,0.1,0,0.1", "1,0.1,1,0.2", "2,0.1,2,0.3",
          "3,0.1,3,0.3", "4,0.1,4,0.3"], None, "2 columns for friction_ratio: 'COF', 'COF'"),
        (["Time,Displacement,COF", "-1,0,0.1", "1,1,0.2", "2,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "line 2: column 'Time' = -1 s is negative"),
        (["Time,Displacement,COF", "0,0,0.1", "1,1,-0.2", "2,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "line 3: column 'COF' is negative (-0.2)"),
        (["Time,Displacement,COF", "0,0,0.1", "1,1,abc", "2,2,0.3", "3,3,0.3", "4,4,0.3"],
         None, "line 3: column 'COF' = 'abc' is not a number"),
        (["Time,Displacement,COF", "s,mm,-", "0,0,0.1", "1,1,0.1", "2,2,0.3", "3,3,0.3",
          "4,4,0.3"], {"time": "min"},
         "column 'Time': the units row says 's' but the units key says 'min'"),
        (["Time,Displacement,COF", "parsec,mm,-", "0,0,0.1", "1,1,0.1", "2,2,0.3", "3,3,0.3",
          "4,4,0.3"], None, "column 'Time': 'parsec' is not a unit of time"),
    ],
)  # fmt: skip
def test_bad_data_is_one_line_naming_the_file_and_column(
    tmp_path: Path, rows: list[str], units: dict[str, str] | None, needle: str
) -> None:
    f = write(tmp_path / "bad.csv", rows)
    with pytest.raises(InputError) as info:
        read_tribometer(f, LAB, units, where="[[data]] #1.file 'bad.csv'")
    message = str(info.value)
    assert message.startswith("[[data]] #1.file 'bad.csv'") and "\n" not in message
    assert needle in message, message


def test_missing_file_and_empty_file(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="file not found"):
        read_tribometer(tmp_path / "nope.csv")
    with pytest.raises(InputError, match="holds no table"):
        read_tribometer(write(tmp_path / "empty.csv", ["# only a comment"]))


@pytest.fixture
def units_in(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Any]:
    """frictionlab.io.unit_factors with its caches in ``tmp_path``, nothing remembered."""
    import frictionlab._compile_cache as cc
    from frictionlab.io import unit_factors

    cached = (unit_factors.registry, unit_factors.memo_path, unit_factors._memo)
    monkeypatch.setattr(cc, "cache_dir", lambda: tmp_path / "0.0-key")
    for f in cached:
        f.cache_clear()
    yield unit_factors
    for f in cached:
        f.cache_clear()


#: Units and their SI factors by definition (exact in binary where the decimal is).
EXACT = (("min", "time", 60.0), ("h", "time", 3600.0), ("mm", "slip", 1e-3),
         ("kN", "normal_force", 1e3), ("um", "slip", 1e-6))  # fmt: skip


@pytest.mark.parametrize("damage", ["none", "truncated"])
def test_unit_registry_cache_gives_the_si_factors(
    tmp_path: Path, units_in: Any, damage: str
) -> None:
    """pint's on-disk cache (and a damaged one: the plain registry instead) gives the
    definitions' factors: 1 min = 60 s, 1 h = 3600 s, 1 mm = 1e-3 m, 1 kN = 1e3 N."""
    from frictionlab.io import tribometer

    units_in.registry()  # writes the cache
    pickles = list((tmp_path / "pint").glob("*.pickle"))
    assert pickles, "pint wrote no cache"
    if damage == "truncated":
        for p in pickles:
            p.write_bytes(p.read_bytes()[:20])
    units_in.registry.cache_clear()
    for unit, role, factor in EXACT:
        assert tribometer._factor(unit, role, "t") == pytest.approx(factor, rel=1e-15)


@pytest.mark.parametrize("damage", ["none", "garbage", "wrong types"])
def test_remembered_factors_are_pints_and_skip_pint(
    tmp_path: Path, units_in: Any, monkeypatch: pytest.MonkeyPatch, damage: str
) -> None:
    """A factor pint gave once is read back bit for bit without asking pint again; a
    damaged memo is ignored (pint asked, the memo rewritten); a wrong dimension and an
    unknown unit are refused whether remembered or not."""
    from frictionlab.io import tribometer

    first = {unit: tribometer._factor(unit, role, "t") for unit, role, _ in EXACT}
    with pytest.raises(InputError, match="'min' is not a unit of slip"):
        tribometer._factor("min", "slip", "t")
    with pytest.raises(InputError, match="'parsec/fortnight' is not a unit of time"):
        tribometer._factor("parsec/fortnight", "time", "t")
    path = units_in.memo_path()
    assert path is not None and path.parent == tmp_path / "pint" and path.is_file()
    if damage == "garbage":
        path.write_text("{not json")
    elif damage == "wrong types":
        path.write_text('{"min|[time]|s": "60", "h|[time]|s": -1.0, "mm|[length]|m": 1}')
    units_in._memo.cache_clear()
    units_in.registry.cache_clear()
    if damage == "none":  # remembered: pint must not be asked
        monkeypatch.setattr(units_in, "registry", lambda: pytest.fail("pint was asked"))
    again = {unit: tribometer._factor(unit, role, "t") for unit, role, _ in EXACT}
    assert again == first
    assert {unit: f for unit, _, f in EXACT} == pytest.approx(first, rel=1e-15)


#: A fresh process reading a file in minutes and millimetres; prints the modules it loaded.
_READ = """
import sys
from frictionlab.io.tribometer import read_tribometer
m = read_tribometer(sys.argv[1])
assert m.time[-1] == 120.0 and m.slip[-1] == 2e-3, (m.time, m.slip)
print(" ".join(sorted({name.split(".")[0] for name in sys.modules})))
"""


def test_a_second_process_reads_units_without_pint_or_pandas(tmp_path: Path) -> None:
    """pint is imported once per pint version (its factors are then remembered), pandas never."""
    import os
    import subprocess
    import sys

    rows = [f"{k * 0.5},{k * 0.5},0.3" for k in range(5)]  # to 2 min, 2 mm
    path = write(tmp_path / "run.csv", ["Time (min),Displacement (mm),COF", *rows])
    env = dict(os.environ, FRICTIONLAB_CACHE_DIR=str(tmp_path / "cache"))
    loaded = []
    for _ in range(2):
        out = subprocess.run([sys.executable, "-c", _READ, str(path)], env=env,
                             capture_output=True, text=True, timeout=120)  # fmt: skip
        assert out.returncode == 0, out.stderr
        loaded.append(set(out.stdout.split()))
    assert "pint" in loaded[0] and "pandas" not in loaded[0]
    assert not {"pint", "pandas", "dask"} & loaded[1]
