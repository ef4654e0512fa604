"""CSV tables with units in the titles: pandas-ready, exact round trip, clear errors."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frictionlab.errors import InputError, ParameterError
from frictionlab.io.tables import read_csv, write_csv_atomic


def test_round_trip_is_exact_and_titles_carry_units(tmp_path: Path) -> None:
    rng = np.random.default_rng(7)
    x = rng.normal(size=50) * 10.0 ** rng.integers(-12, 12, 50)
    cols = {"x": x, "n": np.arange(50), "label": np.array(["a", "b"] * 25, dtype=object)}
    path = write_csv_atomic(tmp_path / "t.csv", cols, {"x": "Pa"}, "first line\nsecond line")
    lines = path.read_text().splitlines()
    assert lines[0] == "x [Pa],n [-],label [-]"  # no comment lines: pandas-ready
    assert not any(line.startswith("#") for line in lines)
    back = read_csv(path)
    assert back.units == {"x": "Pa", "n": "-", "label": "-"}
    np.testing.assert_array_equal(back["x"], x)  # shortest repr reads back exactly
    np.testing.assert_array_equal(back["n"], np.arange(50))
    assert list(back["label"][:3]) == ["a", "b", "a"]
    assert not list(tmp_path.glob(".*.tmp*"))


def test_write_rejects_unequal_columns(tmp_path: Path) -> None:
    with pytest.raises(ParameterError, match="columns"):
        write_csv_atomic(tmp_path / "t.csv", {"a": np.zeros(2), "b": np.zeros(3)})
    assert not (tmp_path / "t.csv").exists()


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("", "no header row"),
        ("# only a comment\n", "no header row"),
        ("a,b\n1,2\n3\n", "line 3: 1 values, expected 2"),
        ("a,a\n1,2\n", "repeated column names"),
    ],
)
def test_bad_tables_name_file_and_line(tmp_path: Path, text: str, message: str) -> None:
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(InputError, match=message):
        read_csv(path)


def test_missing_and_binary_files(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="cannot read table"):
        read_csv(tmp_path / "none.csv")
    (tmp_path / "bin.csv").write_bytes(b"\xff\xfe\x00\x01")
    with pytest.raises(InputError, match="not UTF-8"):
        read_csv(tmp_path / "bin.csv")


def test_pandas_reads_every_table_without_options(tmp_path: Path) -> None:
    pd = pytest.importorskip("pandas")
    masked = np.ma.MaskedArray([1.0, 2.0, 3.0], mask=[False, True, False])
    cols = {"time": np.array([0.0, 0.5, 1.0]), "mu": masked, "kind": np.array(["a", "b", "c"])}
    path = write_csv_atomic(tmp_path / "t.csv", cols, {"time": "s", "mu": "1"})
    frame = pd.read_csv(path)
    assert list(frame.columns) == ["time [s]", "mu [-]", "kind [-]"]
    np.testing.assert_array_equal(frame["time [s]"].to_numpy(), cols["time"])
    assert np.isnan(frame["mu [-]"][1]) and frame["mu [-]"][2] == 3.0
    assert frame.dtypes["time [s]"] == np.float64


def test_dataframe_to_csv_output_reads_back_without_its_index(tmp_path: Path) -> None:
    pd = pytest.importorskip("pandas")
    frame = pd.DataFrame({"time [s]": [0.0, 1.0, 2.0], "slip_1 [m]": [0.0, 1e-6, 2e-6]})
    frame.to_csv(tmp_path / "t.csv")  # with the index column (empty title)
    table = read_csv(tmp_path / "t.csv")
    assert list(table) == ["time", "slip_1"]
    assert table.units == {"time": "s", "slip_1": "m"}
    np.testing.assert_array_equal(table["slip_1"], [0.0, 1e-6, 2e-6])
    assert "3 rows" in repr(table)
    back = table.to_dataframe()
    pd.testing.assert_frame_equal(back, frame)


def test_files_of_earlier_versions_still_read(tmp_path: Path) -> None:
    path = tmp_path / "old.csv"
    path.write_text("# title\n# units: time [s], R [1]\ntime,R\n0.0,0.5\n")
    table = read_csv(path)
    assert table.units == {"time": "s", "R": "-"} and table.comments == ["title"]
    np.testing.assert_array_equal(table["R"], [0.5])
