"""CSV tables with units in the column titles, written atomically and read back exactly.

Layout of a file written by :func:`write_csv_atomic`: a header row, then the data::

    time [s],slip_1 [m],traction_1 [Pa],status [-]
    0.0,0.0,0.0,initial
    ...

Every file opens with ``pandas.read_csv(path)`` and no other argument. Each title is
``name [unit]`` (``-`` for dimensionless and text columns; the one spelling used
everywhere). Floats are written in the shortest form that reads back to the same float64
(orjson's shortest round-trip form, e.g. ``1e-6``), so a round trip is exact; cells are
formatted column-wise by Arrow's compute kernels, with no Python object per cell.
Non-finite values are refused: a table never carries NaN or infinity. Booleans are written
as ``true``/``false``; text cells may not contain commas or line breaks. An undefined value
is given as a masked entry (``numpy.ma``) and written as an empty field.

:func:`read_csv` reads such files (a numeric column with empty fields comes back as a
masked array), files of earlier versions (``#`` comment lines, a ``# units:`` line),
files written by ``pandas.DataFrame.to_csv`` (the index column is dropped), and any
plain CSV with a header row.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._frames import column_title, normalise_unit, split_title, to_dataframe
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.atomic import write_bytes_atomic

__all__ = ["CsvTable", "format_csv", "format_csv_bytes", "read_csv", "write_csv_atomic"]

_UNITS_PREFIX = "# units:"


class CsvTable(Mapping[str, np.ndarray]):
    """A table read by :func:`read_csv`: a mapping column name -> array, plus units and comments.

    Names are the titles without their ``[unit]``. Numeric columns are float64 arrays,
    other columns object arrays of strings.
    """

    def __init__(
        self, columns: dict[str, np.ndarray], units: dict[str, str], comments: list[str]
    ) -> None:
        self.columns = columns
        self.units = units
        self.comments = comments

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self.columns)

    def __len__(self) -> int:
        return len(self.columns)

    def __repr__(self) -> str:
        rows = len(next(iter(self.columns.values()))) if self.columns else 0
        return f"CsvTable({rows} rows; columns: {', '.join(self.columns)})"

    def to_dataframe(self) -> Any:
        """The table as a :class:`pandas.DataFrame` (titles ``name [unit]``; empty -> NaN)."""
        return to_dataframe(self.columns, self.units)


def format_csv(
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header_comment: str | None = None,
) -> str:
    """:func:`format_csv_bytes` as text."""
    return format_csv_bytes(columns, units, header_comment).decode("utf-8")


def format_csv_bytes(
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header_comment: str | None = None,
) -> bytes:
    """Render ``columns`` (equal-length 1-D arrays) as UTF-8 CSV, titles ``name [unit]``.

    ``header_comment`` is accepted for compatibility and not written: the file is plain
    CSV that any reader opens without options (descriptions live in ``summary.json``
    and the docs). Raises :class:`~frictionlab.errors.ParameterError` for ragged columns, non-finite
    values, column names or text that would break the format, or units of unknown columns.
    """
    if not columns:
        raise ParameterError("columns", "{}", "at least one column")
    names = list(columns)
    for name in names:
        if not name or any(ch in name for ch in ",[]#\n\r") or name != name.strip():
            raise ParameterError("column name", name, "non-empty, without , [ ] # or line breaks")
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
    header = (",".join(column_title(name, units.get(name)) for name in names) + "\n").encode()
    if len(arrays[0]) == 0:
        return header
    import pyarrow as pa
    import pyarrow.csv as pa_csv

    cells = pa.table([_format_column(name, a) for name, a in zip(names, arrays, strict=True)],
                     names=[f"c{k}" for k in range(len(names))])  # fmt: skip
    sink = pa.BufferOutputStream()
    pa_csv.write_csv(cells, sink, pa_csv.WriteOptions(include_header=False, quoting_style="none"))
    return header + sink.getvalue().to_pybytes()


def _format_column(name: str, values: np.ndarray) -> Any:
    """One column's cells as an Arrow string array (vectorised; no Python object per cell).

    Floats are written in their shortest round-trip form (orjson's, e.g. ``1e-6``,
    ``0.00001``, ``2.0``): every value reads back as the same float64.
    """
    import pyarrow as pa
    import pyarrow.compute as pc

    if np.ma.isMaskedArray(values):  # undefined entries: empty fields
        mask = np.ma.getmaskarray(values)
        data = np.ma.getdata(values)
        filled = _format_column(name, np.where(mask, np.zeros((), data.dtype), data))
        return pc.if_else(pa.array(mask), pa.scalar("", pa.string()), filled)
    if values.dtype.kind == "b":
        return pc.if_else(pa.array(values), pa.scalar("true"), pa.scalar("false"))
    if values.dtype.kind in "iu":
        return pc.cast(pa.array(values), pa.string())
    if values.dtype.kind == "f":
        floats = np.ascontiguousarray(values, dtype=np.float64)
        finite = np.isfinite(floats)
        if not finite.all():
            raise ParameterError(f"column {name}", float(floats[~finite][0]), "finite numbers only")
        import orjson

        text = orjson.dumps(floats, option=orjson.OPT_SERIALIZE_NUMPY)[1:-1].decode("ascii")
        return pc.split_pattern(pa.array([text], pa.string()), ",").flatten()
    if values.dtype.kind in "UO":  # few distinct texts (kinds, statuses): codes + levels
        import pandas as pd

        codes, levels = pd.factorize(np.asarray(values, dtype=object))
        texts = [str(t) for t in levels]
        bad = [t for t in texts if any(ch in t for ch in ",\n\r")]
        if bad:
            raise ParameterError(f"column {name}", bad[0], "text without commas or line breaks")
        return pa.array(texts, pa.string()).take(pa.array(codes))
    raise ParameterError(f"column {name}", str(values.dtype), "bool, integer, float or text")


def write_csv_atomic(
    path: str | os.PathLike[str],
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header_comment: str | None = None,
) -> Path:
    """Write ``columns`` as CSV with titles ``name [unit]``, atomically; return the path.

    Parameters
    ----------
    path:
        Target file; its directory is created if needed.
    columns:
        Column name -> 1-D array (all of the same length).
    units:
        Column name -> unit string (SI, e.g. ``"m"``, ``"Pa"``, ``"deg"``); columns
        without an entry are written as dimensionless (``-``).
    header_comment:
        Accepted for compatibility, not written (see :func:`format_csv`).
    """
    return write_bytes_atomic(path, format_csv_bytes(columns, units, header_comment))


def read_csv(path: str | os.PathLike[str]) -> CsvTable:
    """Read a CSV file with a header row; ``#`` lines are comments (a units line is parsed).

    Titles ``name [unit]`` give the column ``name`` and its unit. A first column with an
    empty title (or ``Unnamed: 0``) is an index written by ``pandas.DataFrame.to_csv``
    and is dropped. A column whose every cell is a number becomes a float64 array (a masked
    array when some cells are empty: undefined values), any other column an object array of strings.
    Unreadable, empty or ragged files raise :class:`~frictionlab.errors.InputError` naming
    the file and the line.
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot read table '{p}': {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise InputError(f"table '{p}' is not UTF-8 text") from None
    comments: list[str] = []
    units: dict[str, str] = {}
    body: list[tuple[int, list[str]]] = []
    for lineno, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped.startswith(_UNITS_PREFIX):
            for item in stripped[len(_UNITS_PREFIX) :].split(","):
                name, unit = split_title(item)
                if name and unit is not None:
                    units[name] = unit
        elif stripped.startswith("#"):
            comments.append(stripped[1:].strip())
        elif stripped:
            body.append((lineno, [cell.strip() for cell in line.split(",")]))
    if not body:
        raise InputError(f"table '{p}' has no header row")
    header_line, titles = body[0]
    if len(titles) > 1 and titles[0] in ("", "Unnamed: 0"):  # a pandas index column
        body = [(lineno, row[1:]) for lineno, row in body]
        titles = titles[1:]
    names = []
    for title in titles:
        name, unit = split_title(title)
        names.append(name)
        if unit is not None:
            units[name] = unit
    units = {name: normalise_unit(unit) for name, unit in units.items()}
    if any(not name for name in names) or len(set(names)) != len(names):
        raise InputError(f"table '{p}' line {header_line}: empty or repeated column names")
    for lineno, row in body[1:]:
        if len(row) != len(names):
            raise InputError(
                f"table '{p}' line {lineno}: {len(row)} values, expected {len(names)} "
                f"({', '.join(names)})"
            )
    columns: dict[str, np.ndarray] = {}
    for k, name in enumerate(names):
        raw = [row[k] for _, row in body[1:]]
        empty = [v == "" for v in raw]
        try:
            values = np.array([0.0 if e else float(v) for v, e in zip(raw, empty, strict=True)])
        except ValueError:
            columns[name] = np.array(raw, dtype=object)
            continue
        if not any(empty):
            columns[name] = values
        elif all(empty):  # undefined throughout
            columns[name] = np.ma.masked_all(len(raw))
        else:  # empty fields are undefined values: masked
            columns[name] = np.ma.MaskedArray(values, mask=np.array(empty))
    return CsvTable(columns, units, comments)
