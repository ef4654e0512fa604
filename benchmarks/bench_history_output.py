"""history.csv writing rate: the column-wise writer against the per-cell ``repr`` writer.

The writers format the same recorded rows (the 20 history columns of a 2-D slide: floats,
step integers and the text columns) in one process, interleaved; the median of the
repeats is reported as CPU time (``time.process_time``: this machine is shared) and wall
time, with the load average. The baseline is the writer this project used before: one
``repr`` per float and one ``",".join`` per row. ``arrow_csv`` is the previous column-wise
writer (orjson's numbers split into an Arrow array per column, then Arrow's CSV writer),
kept here to show what the one-pass row join gained.
Run: ``python benchmarks/bench_history_output.py [rows]``.
"""

from __future__ import annotations

import os
import statistics
import sys
import time
from collections.abc import Callable

import numpy as np

from frictionlab.io.tables import format_csv_bytes


def recorded_rows(rows: int, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """Columns shaped like history.csv: a point/step index, text kinds and float fields."""
    cols: dict[str, np.ndarray] = {
        "point": np.ones(rows, dtype=np.int64),
        "step": np.arange(rows, dtype=np.int64),
        "segment": np.ones(rows, dtype=np.int64),
        "kind": np.array(["slide"] * rows, dtype=object),
    }
    for name in ("time", "slip_1", "slip_2", "approach", "traction_1", "traction_2",
                 "traction_n", "friction_ratio", "R", "F", "plastic_slip", "plastic_work",
                 "dissipation"):  # fmt: skip
        cols[name] = rng.standard_normal(rows) * 10.0 ** rng.integers(-9, 7, rows)
    cols["status"] = np.array(["slip"] * rows, dtype=object)
    cols["substeps"] = np.ones(rows, dtype=np.int64)
    cols["iterations"] = np.full(rows, 3, dtype=np.int64)
    return cols


def repr_writer(cols: dict[str, np.ndarray]) -> bytes:
    """The previous writer: a Python ``repr``/``str`` per cell, a join per row, UTF-8."""
    texts = []
    for values in cols.values():
        if values.dtype.kind == "f":
            texts.append([repr(v) for v in values.tolist()])
        else:
            texts.append([str(v) for v in values.tolist()])
    header = ",".join(f"{k} [-]" for k in cols) + "\n"
    body = "".join(",".join(row) + "\n" for row in zip(*texts, strict=True))
    return (header + body).encode("utf-8")


def arrow_csv_writer(cols: dict[str, np.ndarray]) -> bytes:
    """The previous column-wise writer: per-column Arrow string arrays, Arrow's CSV writer."""
    import orjson
    import pandas as pd
    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.csv as pa_csv

    cells = []
    for values in cols.values():
        if values.dtype.kind == "f":
            text = orjson.dumps(values, option=orjson.OPT_SERIALIZE_NUMPY)[1:-1].decode("ascii")
            cells.append(pc.split_pattern(pa.array([text], pa.string()), ",").flatten())
        elif values.dtype.kind in "iu":
            cells.append(pc.cast(pa.array(values), pa.string()))
        else:
            codes, levels = pd.factorize(values)
            cells.append(pa.array([str(t) for t in levels], pa.string()).take(pa.array(codes)))
    table = pa.table(cells, names=[f"c{k}" for k in range(len(cells))])
    sink = pa.BufferOutputStream()
    pa_csv.write_csv(table, sink, pa_csv.WriteOptions(include_header=False, quoting_style="none"))
    header = ",".join(f"{k} [-]" for k in cols) + "\n"
    return header.encode() + sink.getvalue().to_pybytes()


WRITERS: dict[str, Callable[[dict[str, np.ndarray]], bytes]] = {
    "repr": repr_writer,
    "arrow_csv": arrow_csv_writer,
    "columnwise": format_csv_bytes,
}


def main(rows: int = 200_000, repeats: int = 5) -> dict[str, float]:
    cols = recorded_rows(rows, np.random.default_rng(1))
    body = format_csv_bytes(cols).split(b"\n", 1)[1]  # first call: imports pyarrow and orjson
    assert arrow_csv_writer(cols).split(b"\n", 1)[1] == body  # the same text
    assert repr_writer(cols).count(b"\n") == body.count(b"\n") + 1
    cpu: dict[str, list[float]] = {k: [] for k in WRITERS}
    wall: dict[str, list[float]] = {k: [] for k in WRITERS}
    load = os.getloadavg()[0]
    for _ in range(repeats):
        for name, writer in WRITERS.items():
            t0, c0 = time.perf_counter(), time.process_time()
            writer(cols)
            cpu[name].append((time.process_time() - c0) / rows * 1e6)
            wall[name].append((time.perf_counter() - t0) / rows * 1e6)
    result: dict[str, float] = {}
    for name in WRITERS:
        result[f"{name}_cpu_us_per_row"] = statistics.median(cpu[name])
        result[f"{name}_wall_us_per_row"] = statistics.median(wall[name])
    for name in ("arrow_csv", "columnwise"):
        result[f"{name}_speedup_cpu"] = (
            result["repr_cpu_us_per_row"] / result[f"{name}_cpu_us_per_row"]
        )
    result["load_average"] = (load + os.getloadavg()[0]) / 2
    print(f"rows {rows}, 20 columns, median of {repeats} interleaved runs")
    for key, value in result.items():
        print(f"  {key:32s} {value:8.3f}")
    return result


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200_000)
