"""Reading tribometer exports: a lab's format loads in SI units; bad data are refused."""

from __future__ import annotations

from pathlib import Path

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


@pytest.mark.parametrize("damage", ["none", "truncated"])
def test_unit_registry_cache_gives_the_si_factors(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, damage: str
) -> None:
    """pint's on-disk cache (and a damaged one: the plain registry instead) gives the
    definitions' exact factors: 1 min = 60 s, 1 h = 3600 s, 1 mm = 1e-3 m, 1 kN = 1e3 N."""
    import frictionlab._compile_cache as cc
    from frictionlab.io import tribometer

    monkeypatch.setattr(cc, "cache_dir", lambda: tmp_path / "0.0-key")
    tribometer._registry.cache_clear()
    try:
        tribometer._registry()  # writes the cache
        pickles = list((tmp_path / "pint").glob("*.pickle"))
        assert pickles, "pint wrote no cache"
        if damage == "truncated":
            for p in pickles:
                p.write_bytes(p.read_bytes()[:20])
        tribometer._registry.cache_clear()
        assert tribometer._factor("min", "time", "t") == 60.0
        assert tribometer._factor("h", "time", "t") == 3600.0
        assert tribometer._factor("mm", "slip", "t") == pytest.approx(1e-3, rel=1e-15)
        assert tribometer._factor("kN", "normal_force", "t") == pytest.approx(1e3, rel=1e-15)
    finally:
        tribometer._registry.cache_clear()
