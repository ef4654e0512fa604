"""history.csv writing rate: the column-wise writer against the per-cell ``repr`` writer.

Both format the same recorded rows (the 20 history columns of a 2-D slide: floats, step
integers and the text columns) in one process, interleaved, and the median of the repeats
is reported. The baseline is the writer this project used before: one ``repr`` per float
and one ``",".join`` per row. Run: ``python benchmarks/bench_history_output.py [rows]``.
"""

from __future__ import annotations

import statistics
import sys
import time

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


def main(rows: int = 200_000, repeats: int = 5) -> dict[str, float]:
    cols = recorded_rows(rows, np.random.default_rng(1))
    format_csv_bytes(cols)  # first call: imports pyarrow and orjson (timed below separately)
    old, new = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        repr_writer(cols)
        t1 = time.perf_counter()
        format_csv_bytes(cols)
        t2 = time.perf_counter()
        old.append((t1 - t0) / rows)
        new.append((t2 - t1) / rows)
    result = {"repr_us_per_row": statistics.median(old) * 1e6,
              "columnwise_us_per_row": statistics.median(new) * 1e6}  # fmt: skip
    result["speedup"] = result["repr_us_per_row"] / result["columnwise_us_per_row"]
    print(f"rows {rows}, 20 columns, median of {repeats} interleaved runs")
    for key, value in result.items():
        print(f"  {key:24s} {value:8.3f}")
    return result


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200_000)
