"""CSV tables with units in the column titles, written atomically and read back exactly.

Layout of a file written by :func:`write_csv_atomic`: a header row, then the data::

    time [s],slip_1 [m],traction_1 [Pa],status [-]
    0.0,0.0,0.0,initial
    ...

Every file opens with ``pandas.read_csv(path)`` and no other argument. Each title is
``name [unit]`` (``-`` for dimensionless and text columns; the one spelling used
everywhere). Floats are written in the shortest form that reads back to the same float64
(orjson's shortest round-trip form, e.g. ``1e-6``), so a round trip is exact. Each column
(each run of neighbouring number columns of one kind) is formatted by one vectorised call
and its cells are views of that text; one NumPy gather joins the cells of each row (no
Python object per cell, no per-cell string).
Non-finite values are refused: a table never carries NaN or infinity. Booleans are written
as ``true``/``false``; text cells may not contain commas or line breaks. An undefined value
is given as a masked entry (``numpy.ma``) or, in a text column, as ``None``, and written as
an empty field (as pandas writes a missing value).

:func:`read_csv` reads such files (a numeric column with empty fields comes back as a
masked array), files of earlier versions (``#`` comment lines, a ``# units:`` line),
files written by ``pandas.DataFrame.to_csv`` (the index column is dropped), and any
plain CSV with a header row.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any, BinaryIO

import numpy as np

from frictionlab._frames import column_title, normalise_unit, split_title, to_dataframe
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.atomic import atomic_path
from frictionlab.io.inputs import read_input_text

__all__ = [
    "CsvTable",
    "csv_pieces",
    "format_csv",
    "format_csv_bytes",
    "read_csv",
    "write_csv",
    "write_csv_atomic",
]

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
    return b"".join(csv_pieces(columns, units))


def csv_pieces(
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header: bool = True,
) -> Iterator[bytes | memoryview]:
    """:func:`format_csv_bytes` as pieces to write one after the other (no joined copy).

    The header line first (unless ``header`` is false), then the rows :data:`BLOCK_ROWS`
    at a time; every check is made before the first piece is given.
    """
    names, arrays = _checked(columns, units)
    title = ",".join(column_title(name, (units or {}).get(name)) for name in names) + "\n"
    n = len(arrays[0])
    blocks = [(s, min(s + BLOCK_ROWS, n)) for s in range(0, n, BLOCK_ROWS)]
    for name, values in zip(names, arrays, strict=True):  # refuse before writing anything
        if values.dtype.kind == "f":
            _check_finite(name, values)
    if header:
        yield title.encode()
    for s, e in blocks:
        yield _rows_text([a[s:e] for a in arrays], names)


#: Rows formatted at a time (bounds the text and the gather index held in memory).
BLOCK_ROWS = 65536


def _checked(
    columns: Mapping[str, np.ndarray], units: Mapping[str, str] | None
) -> tuple[list[str], list[np.ndarray]]:
    """The names and arrays of ``columns``, checked (see :func:`format_csv_bytes`)."""
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
    unknown = sorted(set(units or {}) - set(names))
    if unknown:
        raise ParameterError("units", unknown[0], f"one of the columns {names}")
    for name, values in zip(names, arrays, strict=True):
        if values.dtype.kind not in "biufUO":
            raise ParameterError(
                f"column {name}", str(values.dtype), "bool, integer, float or text"
            )
    return names, arrays


def _check_finite(name: str, values: np.ndarray) -> None:
    data = np.ma.getdata(values)
    finite = np.isfinite(data) | np.ma.getmaskarray(values)
    if not finite.all():
        raise ParameterError(f"column {name}", float(data[~finite][0]), "finite numbers only")


#: Cells of one column: ``data[offsets[i]:offsets[i + 1]]`` is row i's text (uint8, int64).
_Cells = tuple[np.ndarray, np.ndarray]


def _rows_text(arrays: list[np.ndarray], names: list[str]) -> memoryview:
    """The CSV lines of equal-length columns, as one contiguous buffer.

    Each run of neighbouring number columns of one kind (floats, or integers) is formatted
    by one vectorised call, its cells being the rows' parts with their separator (``,``
    or the line's end); one gather joins the runs' cells of each row.
    """
    parts: list[_Cells] = []
    start = 0
    while start < len(arrays):
        stop = start + 1
        kind = _number_kind(arrays[start])
        while kind and stop < len(arrays) and _number_kind(arrays[stop]) == kind:
            stop += 1
        sep = b"\n" if stop == len(arrays) else b","
        if kind:
            parts.append(_number_cells(arrays[start:stop], kind, sep))
        else:
            parts.append(_cells(names[start], arrays[start], sep))
        start = stop
    n = len(arrays[0])
    if n >= ARROW_JOIN_ROWS:
        return _arrow_join(parts, n)
    bases = np.cumsum([0] + [len(data) for data, _ in parts])
    starts = [base + offsets[:-1] for base, (_, offsets) in zip(bases, parts, strict=False)]
    lengths = [np.diff(offsets) for _, offsets in parts]
    data = np.concatenate([data for data, _ in parts])
    return _take(data, np.stack(starts, 1).ravel(), np.stack(lengths, 1).ravel())[0].data


#: Rows from which Arrow joins the cells: a NumPy gather costs ~2.5 us/row more, Arrow's
#: import ~0.1 s (a short run writes its small tables without importing pyarrow).
ARROW_JOIN_ROWS = 32768


def _arrow_join(parts: list[_Cells], n: int) -> memoryview:
    """:func:`_rows_text`'s join by Arrow (its cells arrays are views of the parts)."""
    import pyarrow as pa
    import pyarrow.compute as pc

    cells = [
        pa.LargeStringArray.from_buffers(n, pa.py_buffer(offsets), pa.py_buffer(data))
        for data, offsets in parts
    ]
    no_text = pa.py_buffer(b"")
    empty = pa.LargeStringArray.from_buffers(n, pa.py_buffer(np.zeros(n + 1, np.int64)), no_text)
    lines = pc.binary_join_element_wise(*cells, empty)
    offsets = np.frombuffer(lines.buffers()[1], np.int64)[lines.offset :]
    return memoryview(lines.buffers()[2])[offsets[0] : offsets[len(lines)]]


def _take(data: np.ndarray, starts: np.ndarray, lengths: np.ndarray) -> _Cells:
    """The cells ``data[starts[i]:starts[i] + lengths[i]]``, one after the other."""
    offsets = np.zeros(len(lengths) + 1, np.int64)
    np.cumsum(lengths, out=offsets[1:])
    index = np.repeat(starts - offsets[:-1], lengths)
    index += np.arange(offsets[-1], dtype=index.dtype)
    return data[index], offsets


def _number_kind(values: np.ndarray) -> str:
    """``"f"`` or ``"i"`` for a column :func:`_number_cells` formats, else ``""``."""
    if np.ma.isMaskedArray(values):
        return ""
    return {"f": "f", "i": "i", "u": "i"}.get(values.dtype.kind, "")


def _number_cells(columns: list[np.ndarray], kind: str, sep: bytes) -> _Cells:
    """The rows of neighbouring number columns, each part followed by ``sep``.

    One ``orjson.dumps`` of the row-major block: floats in their shortest round-trip
    form (e.g. ``1e-6``, ``0.00001``, ``2.0``; every value reads back as the same
    float64), integers in full. The cells are views of that text: the offsets are the
    positions after every k-th comma (k columns). The block has one spare row of zeros
    so that every row used ends with a comma (the spare one with ``]``).
    """
    import orjson

    n = len(columns[0])
    block = np.zeros((n + 1, len(columns)), np.float64 if kind == "f" else np.int64)
    for j, values in enumerate(columns):
        block[:n, j] = values
    raw = orjson.dumps(block.ravel(), option=orjson.OPT_SERIALIZE_NUMPY)
    text = np.frombuffer(raw, np.uint8)
    k = len(columns)
    ends = np.flatnonzero(text == ord(","))[k - 1 :: k]
    if sep != b",":  # the line's end after each row
        text = text.copy()
        text[ends] = sep[0]
    offsets = np.empty(n + 1, np.int64)  # cells "a,b,", "c,d,", ...
    offsets[0], offsets[1:] = 1, ends + 1
    return text, offsets


def _cells(name: str, values: np.ndarray, sep: bytes) -> _Cells:
    """One column's cells, each followed by ``sep`` (number columns by
    :func:`_number_cells`; undefined entries are empty fields)."""
    n = len(values)
    if np.ma.isMaskedArray(values):
        mask = np.ma.getmaskarray(values)
        data = np.ma.getdata(values)
        text, offsets = _cells(name, np.where(mask, np.zeros((), data.dtype), data), sep)
        starts = np.where(mask, len(text), offsets[:-1])
        lengths = np.where(mask, len(sep), np.diff(offsets))
        return _take(np.concatenate([text, np.frombuffer(sep, np.uint8)]), starts, lengths)
    if values.dtype.kind == "b":
        return _levels([b"false" + sep, b"true" + sep], values.astype(np.int64))
    if values.dtype.kind in "iuf":
        return _number_cells([values], "f" if values.dtype.kind == "f" else "i", sep)
    items = np.asarray(values, dtype=object)  # text: few distinct values (kinds, statuses)
    texts = list(set(items.tolist()))
    bad = [str(t) for t in texts if any(ch in str(t) for ch in ",\n\r")]
    if bad:
        raise ParameterError(f"column {name}", bad[0], "text without commas or line breaks")
    if len(texts) <= 16:
        codes = np.zeros(n, np.int64)
        for k, text in enumerate(texts[1:], start=1):
            codes[items == text] = k
    else:
        lookup = {text: k for k, text in enumerate(texts)}
        codes = np.fromiter(map(lookup.__getitem__, items.tolist()), np.int64, n)
    return _levels([(b"" if t is None else str(t).encode()) + sep for t in texts], codes)


def _levels(texts: list[bytes], codes: np.ndarray) -> _Cells:
    """The cells ``texts[codes]``."""
    lengths = np.array([len(t) for t in texts], np.int64)
    starts = np.zeros(len(texts), np.int64)
    np.cumsum(lengths[:-1], out=starts[1:])
    data = np.frombuffer(b"".join(texts), np.uint8)
    return _take(data, starts[codes], lengths[codes])


def write_csv(
    handle: BinaryIO,
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
    header: bool = True,
) -> None:
    """Write :func:`format_csv_bytes`'s text to an open binary file, piece by piece."""
    for piece in csv_pieces(columns, units, header):
        handle.write(piece)


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
    pieces = csv_pieces(columns, units)
    first = next(pieces)  # every check is made before the file is created
    with atomic_path(path) as tmp, open(tmp, "wb") as handle:
        handle.write(first)
        for piece in pieces:
            handle.write(piece)
    return Path(path)


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
    text = read_input_text(p, "table")
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
