"""The CSV writer's two row joins (NumPy below ARROW_JOIN_ROWS, Arrow above) agree, and a
small table is written without importing pyarrow or pandas."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from frictionlab.io import tables
from frictionlab.io.tables import format_csv_bytes


def _mixed(n: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(3)
    return {
        "kind": np.array(rng.choice(["slide", "hold", "µm"], n), dtype=object),
        "step": rng.integers(-(2**62), 2**62, n),
        "point": rng.integers(0, 9, n, dtype=np.uint64),
        "t": rng.standard_normal(n) * 10.0 ** rng.integers(-300, 300, n),
        "ok": rng.random(n) > 0.5,
        "gap": np.ma.MaskedArray(rng.random(n), mask=rng.random(n) > 0.6),
        "count": np.ma.MaskedArray(rng.integers(0, 5, n), mask=rng.random(n) > 0.5),
        "name": np.array([f"s{k}" for k in rng.integers(0, 40, n)], dtype=object),
        "x": rng.random(n),
    }


@pytest.mark.parametrize("n", [1, 2, 257])
@pytest.mark.parametrize("reverse", [False, True])
def test_numpy_and_arrow_joins_write_the_same_bytes(
    n: int, reverse: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    cols = _mixed(n)
    if reverse:  # a text column last, then a number column last
        cols = dict(reversed(list(cols.items())))
    monkeypatch.setattr(tables, "ARROW_JOIN_ROWS", 10**9)
    by_numpy = format_csv_bytes(cols)
    monkeypatch.setattr(tables, "ARROW_JOIN_ROWS", 1)
    by_arrow = format_csv_bytes(cols)
    assert by_numpy == by_arrow
    lines = by_numpy.decode().splitlines()
    assert len(lines) == n + 1 and all(line.count(",") == len(cols) - 1 for line in lines)
    names = list(cols)
    rows = [line.split(",") for line in lines[1:]]
    col = {name: [row[j] for row in rows] for j, name in enumerate(names)}
    assert [float(v) for v in col["t"]] == cols["t"].tolist()
    assert col["ok"] == ["true" if v else "false" for v in cols["ok"]]
    gap, hidden = np.ma.getdata(cols["gap"]).tolist(), np.ma.getmaskarray(cols["gap"]).tolist()
    expected = [None if m else v for v, m in zip(gap, hidden, strict=True)]
    assert [float(v) if v else None for v in col["gap"]] == expected
    assert col["kind"] == cols["kind"].tolist() and col["name"] == cols["name"].tolist()


def test_a_small_table_imports_neither_pyarrow_nor_pandas(tmp_path: Path) -> None:
    code = (
        "import sys, numpy as np\n"
        "from frictionlab.io.tables import write_csv_atomic\n"
        f"write_csv_atomic({str(tmp_path / 't.csv')!r}, {{'x': np.arange(3.0),"
        " 'kind': np.array(['a', 'b', 'a'], dtype=object), 'ok': np.ones(3, bool),"
        " 'm': np.ma.MaskedArray([1.0, 2.0, 3.0], mask=[0, 1, 0])})\n"
        "print(sorted(m for m in ('pyarrow', 'pandas') if m in sys.modules))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"
    assert (tmp_path / "t.csv").read_text().splitlines()[2] == "1.0,b,true,"
