"""The column-wise CSV writer: exact round trips, the cell forms and the refusals.

Each value is checked by parsing the written text with Python's ``float`` (an independent
reader), not by the project's own reader.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from frictionlab.errors import ParameterError
from frictionlab.io.tables import format_csv


def _cells(text: str) -> list[list[str]]:
    return [line.split(",") for line in text.splitlines()[1:]]


def test_every_float64_reads_back_bit_for_bit() -> None:
    rng = np.random.default_rng(7)
    bits = rng.integers(0, 2**63, 20_000, dtype=np.int64).view(np.float64)
    special = np.array([0.0, -0.0, 5e-324, -5e-324, 2.2250738585072014e-308,
                        1.7976931348623157e308, 1e-5, 1e16, 1e22, 0.1, 1 / 3, 100.0])  # fmt: skip
    values = np.concatenate([bits[np.isfinite(bits)], special])
    cells = _cells(format_csv({"x": values}))
    back = np.array([float(row[0]) for row in cells])
    assert back.view(np.int64).tolist() == values.view(np.int64).tolist()  # -0.0 kept too


def test_shortest_forms_and_integral_floats_stay_floats() -> None:
    text = format_csv({"x": np.array([0.0, 2.0, 0.1, 1e16])})
    assert [row[0] for row in _cells(text)] == ["0.0", "2.0", "0.1", "1e+16"]
    frame = pd.read_csv(pd.io.common.StringIO(text))
    assert frame["x [-]"].dtype == np.float64  # "2.0", not "2": pandas keeps floats


def test_mixed_columns_masks_bools_ints_and_text() -> None:
    cols = {
        "a": np.ma.MaskedArray([1.5, 2.0, 3.0], mask=[False, True, False]),
        "ok": np.array([True, False, True]),
        "n": np.array([-3, 0, 2**40]),
        "kind": np.array(["slide", "hold", "slide"], dtype=object),
        "u": np.array(["µm", "x", ""], dtype=object),
    }
    text = format_csv(cols, {"a": "m"})
    assert text.splitlines()[0] == "a [m],ok [-],n [-],kind [-],u [-]"
    assert _cells(text) == [
        ["1.5", "true", "-3", "slide", "µm"],
        ["", "false", "0", "hold", "x"],
        ["3.0", "true", str(2**40), "slide", ""],
    ]


def test_none_in_a_text_column_is_an_empty_cell_as_pandas_writes_it() -> None:
    kind = np.array(["slide", None, "hold", None], dtype=object)
    text = format_csv({"x": np.arange(4.0), "kind": kind})
    assert [row[1] for row in _cells(text)] == ["slide", "", "hold", ""]
    expected = pd.DataFrame({"x [-]": np.arange(4.0), "kind [-]": kind}).to_csv(index=False)
    assert text == expected  # pandas' own writer: a missing value is an empty field
    back = pd.read_csv(pd.io.common.StringIO(text))["kind [-]"]
    assert back.isna().tolist() == [False, True, False, True]


def test_empty_table_is_its_header() -> None:
    assert format_csv({"x": np.array([]), "k": np.array([], dtype=object)}) == "x [-],k [-]\n"


@pytest.mark.parametrize(
    ("cols", "key"),
    [
        ({"x": np.array([1.0, np.nan])}, "column x"),
        ({"x": np.array([np.inf])}, "column x"),
        ({"t": np.array(["a,b"], dtype=object)}, "column t"),
        ({"t": np.array(["a\nb"], dtype=object)}, "column t"),
    ],
)
def test_refusals_name_the_column(cols: dict[str, np.ndarray], key: str) -> None:
    with pytest.raises(ParameterError, match=key):
        format_csv(cols)


def test_runs_of_number_columns_across_blocks_read_back_exactly(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Neighbouring float and integer columns share one formatting call; every cell of
    every block (small blocks here) is still its own value, read by float/int/str."""
    import frictionlab.io.tables as tables

    monkeypatch.setattr(tables, "BLOCK_ROWS", 7)
    rng = np.random.default_rng(3)
    n = 23
    cols: dict[str, np.ndarray] = {
        "i1": rng.integers(-(2**62), 2**62, n),
        "i2": np.arange(n, dtype=np.uint32),
        "f1": rng.standard_normal(n) * 10.0 ** rng.integers(-300, 300, n),
        "f2": np.full(n, -0.0),
        "f3": rng.integers(-5, 5, n).astype(np.float64),
        "kind": np.array(["slide", "hold", "x]"], dtype=object)[rng.integers(0, 3, n)],
        "m": np.ma.MaskedArray(rng.standard_normal(n), mask=rng.random(n) < 0.5),
        "f4": rng.standard_normal(n),
        "ok": rng.random(n) < 0.5,
        "i3": rng.integers(0, 9, n),
        "i4": rng.integers(0, 9, n),
    }
    rows = _cells(format_csv(cols))
    assert len(rows) == n and all(len(row) == len(cols) for row in rows)
    for k, (name, values) in enumerate(cols.items()):
        got = [row[k] for row in rows]
        if np.ma.isMaskedArray(values):
            mask = np.ma.getmaskarray(values)
            assert [g == "" for g in got] == mask.tolist()
            kept = [float(g) for g, m in zip(got, mask, strict=True) if not m]
            assert kept == np.ma.getdata(values)[~mask].tolist()
        elif values.dtype.kind == "f":
            back = np.array([float(g) for g in got])
            assert back.view(np.int64).tolist() == values.view(np.int64).tolist(), name
            assert all("." in g or "e" in g for g in got), name  # floats stay floats
        elif values.dtype.kind in "iu":
            assert [int(g) for g in got] == values.tolist(), name
        elif values.dtype.kind == "b":
            assert got == ["true" if v else "false" for v in values], name
        else:
            assert got == values.tolist(), name


def test_writing_a_table_does_not_import_pandas(tmp_path: Path) -> None:
    """pyarrow.array/scalar import pandas (~0.3 s); a run writing its tables needs none."""
    probe = (
        "import sys, numpy as np\n"
        "from frictionlab.io.tables import write_csv_atomic\n"
        "write_csv_atomic(sys.argv[1], {'t': np.arange(3.0), 'n': np.arange(3),"
        " 'k': np.array(['a', 'b', 'a'], dtype=object), 'ok': np.ones(3, bool),"
        " 'm': np.ma.masked_all(3)})\n"
        "print('pandas' in sys.modules)\n"
    )
    out = tmp_path / "t.csv"
    done = subprocess.run(
        [sys.executable, "-c", probe, str(out)], capture_output=True, text=True, check=True
    )
    assert done.stdout.strip() == "False"
    assert out.read_text().splitlines()[1] == "0.0,0,a,true,"
