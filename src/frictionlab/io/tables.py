"""CSV tables with a units header, written atomically.

Layout of a file written by :func:`write_csv_atomic`::

    # <header comment, one '# ' line per line of text>
    # units: time [s], slip_1 [m], traction_1 [Pa], status [-]
    time,slip_1,traction_1,status
    0.0,0.0,0.0,initial
    ...

Floats are written with the shortest representation that reads back to the same
float64 (``repr``), so a round trip is exact. :func:`read_csv_table` reads such files
(and any plain CSV with a header row), skipping ``#`` lines.
"""

from __future__ import annotations

import csv
import io
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from frictionlab.errors import InputError
from frictionlab.io.atomic import write_text_atomic

__all__ = ["read_csv_table", "write_csv_atomic"]


def _cells(name: str, values: np.ndarray) -> list[str]:
    arr = np.asarray(values)
    if arr.ndim != 1:
        raise ValueError(f"column {name!r} must be 1-D, got shape {arr.shape}")
    if arr.dtype.kind == "f":
        return [repr(float(v)) for v in arr]
    if arr.dtype.kind in "iub":
        return [str(int(v)) for v in arr]
    return [str(v) for v in arr]


def write_csv_atomic(
    path: str | os.PathLike[str],
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header_comment: str | None = None,
) -> Path:
    """Write equal-length 1-D ``columns`` as CSV to ``path`` atomically; return the path.

    ``units`` (column -> unit, ``-`` for dimensionless) goes into a ``# units:`` comment
    line; ``header_comment`` (possibly several lines) into ``#`` lines above it.
    """
    names = list(columns)
    if not names:
        raise ValueError("no columns to write")
    cells = [_cells(name, columns[name]) for name in names]
    lengths = {len(c) for c in cells}
    if len(lengths) != 1:
        raise ValueError(f"columns have different lengths: {sorted(lengths)}")
    out = io.StringIO()
    if header_comment:
        for line in header_comment.splitlines():
            out.write(f"# {line}\n")
    if units:
        out.write("# units: " + ", ".join(f"{n} [{units.get(n, '-')}]" for n in names) + "\n")
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(names)
    writer.writerows(zip(*cells, strict=True))
    return write_text_atomic(path, out.getvalue())


def read_csv_table(path: str | os.PathLike[str]) -> dict[str, np.ndarray]:
    """Read a CSV file with a header row into columns (``#`` lines are skipped).

    A column whose every cell is a number becomes a float64 array, any other column an
    array of strings. Unreadable, empty or ragged files raise
    :class:`~frictionlab.errors.InputError` naming the file and the line.
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot read table '{p}': {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise InputError(f"table '{p}' is not UTF-8 text") from None
    numbered = [
        (i, line)
        for i, line in enumerate(text.splitlines(), start=1)
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not numbered:
        raise InputError(f"table '{p}' has no header row")
    rows = list(csv.reader(line for _, line in numbered))
    header = [h.strip() for h in rows[0]]
    if any(not h for h in header) or len(set(header)) != len(header):
        raise InputError(f"table '{p}' line {numbered[0][0]}: empty or repeated column names")
    data = rows[1:]
    for (lineno, _), row in zip(numbered[1:], data, strict=True):
        if len(row) != len(header):
            raise InputError(
                f"table '{p}' line {lineno}: {len(row)} values, expected {len(header)} "
                f"({', '.join(header)})"
            )
    out: dict[str, np.ndarray] = {}
    for j, name in enumerate(header):
        cells = [row[j].strip() for row in data]
        try:
            out[name] = np.array([float(c) for c in cells], dtype=np.float64)
        except ValueError:
            out[name] = np.array(cells, dtype=object)
    return out
