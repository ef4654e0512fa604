"""The generic CSV table writer with a units header (io/tables.py)."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.io.tables import format_csv, read_csv, write_csv_atomic


def test_round_trip_is_exact(tmp_path) -> None:
    values = np.array([0.1, 1.0 / 3.0, -2.5e-300, 1e300, 0.0, -0.0, 123456789.123456789])
    path = write_csv_atomic(
        tmp_path / "sub" / "t.csv",
        {"beta_deg": np.arange(7.0), "mu": values, "n": np.arange(7), "ok": np.ones(7, bool)},
        units={"beta_deg": "deg", "mu": "1"},
        header_comment="first line\nsecond line",
    )
    text = path.read_text()
    lines = text.splitlines()
    assert lines[0] == "beta_deg [deg],mu [-],n [-],ok [-]"
    table = read_csv(path)
    np.testing.assert_array_equal(table["mu"], values)
    np.testing.assert_array_equal(table["n"], np.arange(7.0))
    assert table.units == {"beta_deg": "deg", "mu": "-", "n": "-", "ok": "-"}
    assert table.comments == []
    assert list(table["ok"]) == ["true"] * 7


@pytest.mark.parametrize(
    ("columns", "units", "field"),
    [
        ({"a": np.array([1.0, np.nan])}, None, "column a"),
        ({"a": np.array([1.0, np.inf])}, None, "column a"),
        ({"a": np.zeros(2), "b": np.zeros(3)}, None, "columns"),
        ({"a": np.zeros((2, 2))}, None, "columns"),
        ({"a,b": np.zeros(2)}, None, "column name"),
        ({"a": np.zeros(2)}, {"b": "m"}, "units"),
        ({}, None, "columns"),
    ],
)
def test_bad_tables_are_refused_and_nothing_is_written(tmp_path, columns, units, field) -> None:
    target = tmp_path / "t.csv"
    with pytest.raises(ParameterError, match=field):
        write_csv_atomic(target, columns, units)
    assert not target.exists()
    assert list(tmp_path.iterdir()) == []


def test_format_without_comment() -> None:
    text = format_csv({"x": np.array([1.5])})
    assert text == "x [-]\n1.5\n"
