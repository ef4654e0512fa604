"""CSV tables with a units header, written atomically.

Layout of a file written by :func:`write_csv_atomic`::

    # <header comment line 1>
    # <header comment line 2>
    # units: beta_deg=deg, mu_x=1, ...
    beta_deg,mu_x,...
    0,0.3,...

Comment lines start with ``#``; the units line is the last comment line and lists one
``name=unit`` pair per column (``1`` for dimensionless). Numbers are written with 17
significant digits, so a read-back reproduces every float64 exactly. Non-finite values
are refused: a table never carries NaN or infinity. An undefined value is given as a
masked entry (``numpy.ma``) and written as an empty field; :func:`read_csv` reads a
numeric column with empty fields back as a masked array.
"""

from __future__ import annotations

import io
import math
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from frictionlab.errors import InputError, ParameterError
from frictionlab.io.atomic import write_text_atomic

__all__ = ["CsvTable", "format_csv", "read_csv", "write_csv_atomic"]

_UNITS_PREFIX = "# units:"


class CsvTable:
    """A table read back by :func:`read_csv`: columns, units and comment lines."""

    def __init__(
        self, columns: dict[str, np.ndarray], units: dict[str, str], comments: list[str]
    ) -> None:
        self.columns = columns
        self.units = units
        self.comments = comments

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]


def format_csv(
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header_comment: str | None = None,
) -> str:
    """Render ``columns`` (equal-length 1-D arrays) as CSV text with a units header.

    Raises :class:`~frictionlab.errors.ParameterError` for ragged columns, non-finite
    values, column names that would break the format, or units of unknown columns.
    """
    if not columns:
        raise ParameterError("columns", "{}", "at least one column")
    names = list(columns)
    for name in names:
        if not name or any(ch in name for ch in ",=#\n\r") or name != name.strip():
            raise ParameterError("column name", name, "non-empty, without , = # or line breaks")
    arrays = [
        columns[name] if np.ma.isMaskedArray(columns[name]) else np.asarray(columns[name])
        for name in names
    ]
    lengths = {a.shape for a in arrays}
    if any(a.ndim != 1 for a in arrays) or len(lengths) != 1:
        shapes = {name: a.shape for name, a in zip(names, arrays, strict=True)}
        raise ParameterError("columns", shapes, "1-D arrays of one common length")
    units = dict(units or {})
    unknown = sorted(set(units) - set(names))
    if unknown:
        raise ParameterError("units", unknown[0], f"one of the columns {names}")
    out = io.StringIO()
    if header_comment:
        for line in header_comment.splitlines():
            out.write(f"# {line}".rstrip() + "\n")
    unit_items = ", ".join(f"{name}={units.get(name, '1')}" for name in names)
    out.write(f"{_UNITS_PREFIX} {unit_items}\n")
    out.write(",".join(names) + "\n")
    columns_text = [_format_column(name, a) for name, a in zip(names, arrays, strict=True)]
    for row in zip(*columns_text, strict=True):
        out.write(",".join(row) + "\n")
    return out.getvalue()


def _format_column(name: str, values: np.ndarray) -> list[str]:
    if np.ma.isMaskedArray(values):
        mask = np.ma.getmaskarray(values)
        filled = _format_column(name, np.asarray(np.ma.getdata(values)[~mask]))
        texts = iter(filled)
        return ["" if m else next(texts) for m in mask.tolist()]
    if values.dtype.kind == "b":
        return ["true" if v else "false" for v in values.tolist()]
    if values.dtype.kind in "iu":
        return [str(int(v)) for v in values.tolist()]
    if values.dtype.kind == "f":
        floats = values.astype(np.float64).tolist()
        bad = [v for v in floats if not math.isfinite(v)]
        if bad:
            raise ParameterError(f"column {name}", bad[0], "finite numbers only")
        return [_format_float(v) for v in floats]
    if values.dtype.kind in "UO":
        text = [str(v) for v in values.tolist()]
        if any(ch in t for t in text for ch in ",\n\r"):
            raise ParameterError(f"column {name}", text, "text without commas or line breaks")
        return text
    raise ParameterError(f"column {name}", str(values.dtype), "bool, integer, float or text")


def _format_float(value: float) -> str:
    text = f"{value:.17g}"
    return "0" if text == "-0" else text


def write_csv_atomic(
    path: str | os.PathLike[str],
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header_comment: str | None = None,
) -> Path:
    """Write ``columns`` as CSV with a units header line, atomically; return the path.

    Parameters
    ----------
    path:
        Target file; its directory is created if needed.
    columns:
        Column name -> 1-D array (all of the same length). Floats are written with 17
        significant digits; NaN and infinities are refused.
    units:
        Column name -> unit string (SI, e.g. ``"m"``, ``"N"``, ``"deg"``); columns
        without an entry are written as dimensionless (``1``).
    header_comment:
        Free text written as ``#`` comment lines above the units line.
    """
    return write_text_atomic(path, format_csv(columns, units, header_comment))


def read_csv(path: str | os.PathLike[str]) -> CsvTable:
    """Read a table written by :func:`write_csv_atomic` (numeric columns as float64)."""
    p = Path(path)
    try:
        lines = p.read_text(encoding="utf-8").splitlines()
    except OSError as exc:
        raise InputError(f"cannot read file '{p}': {exc.strerror or exc}") from None
    comments: list[str] = []
    units: dict[str, str] = {}
    body = []
    for line in lines:
        if line.startswith(_UNITS_PREFIX):
            for item in line[len(_UNITS_PREFIX) :].split(","):
                if "=" in item:
                    key, unit = item.split("=", 1)
                    units[key.strip()] = unit.strip()
        elif line.startswith("#"):
            comments.append(line[1:].strip())
        elif line.strip():
            body.append(line)
    if not body:
        raise InputError(f"file '{p}' has no header row")
    names = body[0].split(",")
    rows = [row.split(",") for row in body[1:]]
    if any(len(row) != len(names) for row in rows):
        raise InputError(f"file '{p}' has rows of different lengths")
    columns: dict[str, np.ndarray] = {}
    for k, name in enumerate(names):
        raw = [row[k] for row in rows]
        empty = [v == "" for v in raw]
        try:
            values = np.array([0.0 if e else float(v) for v, e in zip(raw, empty, strict=True)])
        except ValueError:
            columns[name] = np.array(raw, dtype=object)
            continue
        if any(empty) and not all(empty):
            columns[name] = np.ma.MaskedArray(values, mask=np.array(empty))
        elif any(empty):  # an all-empty column: undefined throughout
            columns[name] = np.ma.masked_all(len(raw))
        else:
            columns[name] = values
    return CsvTable(columns, units, comments)
