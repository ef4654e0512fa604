"""`[output] format = "parquet"`: history.parquet holds the rows of history.csv bit for bit,
with the units in its metadata.

The CSV text is parsed here with Python's ``float`` (an independent reader) and the
Parquet file with pyarrow alone; the units are compared with the CSV's column titles.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pyarrow.parquet as pq

from frictionlab.cli import main
from frictionlab.io.parquet import read_parquet, write_parquet_atomic

SCENARIO = """
[law]
surface = "cam_clay"
F_s = 2.0
F_k = 1.5
M = 0.5
kappa = 1.0
u = 10.0
xi = 0.001
alpha_t = 1000.0
alpha_n = 1000.0
rotation = [0.1, 0.0]
[initial]
normal_traction = [1.0, 0.7, 1.3]
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.05
steps = 23
[[program]]
kind = "hold"
duration = 10.0
steps = 3
"""


def _run(tmp_path: Path, name: str, output: str) -> Path:
    scenario = tmp_path / f"{name}.toml"
    scenario.write_text(SCENARIO + output)
    out = tmp_path / name
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet", "--no-plots"]) == 0
    return out


def test_history_parquet_is_history_csv_bit_for_bit(tmp_path: Path) -> None:
    text = (_run(tmp_path, "csv", "") / "history.csv").read_text().splitlines()
    out = _run(tmp_path, "pq", '[output]\nformat = "parquet"\n')
    assert not (out / "history.csv").exists()
    table = pq.read_table(out / "history.parquet")
    titles = text[0].split(",")
    names = [t.split(" [")[0] for t in titles]
    assert table.column_names == names
    units = {n: t.split(" [")[1].rstrip("]") for n, t in zip(names, titles, strict=True)}
    for name in names:  # the unit of every column, in its field metadata
        assert table.schema.field(name).metadata == {b"unit": units[name].encode()}
    rows = [line.split(",") for line in text[1:]]
    assert table.num_rows == len(rows) == 3 * 27
    for k, name in enumerate(names):
        cells = [r[k] for r in rows]
        column = table.column(name).to_pylist()
        if table.schema.field(name).type == "double":
            csv_bits = np.array([float(c) for c in cells]).view(np.int64)
            assert np.array_equal(np.array(column, dtype=np.float64).view(np.int64), csv_bits)
        else:
            assert [str(v) for v in column] == cells, name
    back = read_parquet(out / "history.parquet")
    assert back.units == units
    assert np.array_equal(back["traction_1"], np.array(table.column("traction_1").to_pylist()))


def test_masked_values_are_nulls_and_text_reads_back(tmp_path: Path) -> None:
    cols = {
        "a": np.ma.MaskedArray([1.5, -0.0, 5e-324], mask=[False, True, False]),
        "kind": np.array(["slide", "hold", "slide"], dtype=object),
        "n": np.array([1, 2, 2**40]),
    }
    path = write_parquet_atomic(tmp_path / "t.parquet", cols, {"a": "m"})
    table = pq.read_table(path)
    assert table.column("a").to_pylist() == [1.5, None, 5e-324]
    assert table.column("kind").to_pylist() == ["slide", "hold", "slide"]
    back = read_parquet(path)
    assert back.units == {"a": "m", "kind": "-", "n": "-"}
    assert back["a"].mask.tolist() == [False, True, False] and back["a"][2] == 5e-324
    assert back["kind"].tolist() == ["slide", "hold", "slide"] and back["n"][2] == 2**40
