"""CSV tables with a units header: exact round trip, clear errors."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frictionlab.errors import InputError, ParameterError
from frictionlab.io.tables import read_csv, write_csv_atomic


def test_round_trip_is_exact_and_has_a_units_line(tmp_path: Path) -> None:
    rng = np.random.default_rng(7)
    x = rng.normal(size=50) * 10.0 ** rng.integers(-12, 12, 50)
    cols = {"x": x, "n": np.arange(50), "label": np.array(["a", "b"] * 25, dtype=object)}
    path = write_csv_atomic(tmp_path / "t.csv", cols, {"x": "Pa"}, "first line\nsecond line")
    lines = path.read_text().splitlines()
    assert lines[:3] == ["# first line", "# second line", "# units: x [Pa], n [1], label [1]"]
    back = read_csv(path)
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
