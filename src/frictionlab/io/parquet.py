"""Parquet tables (pyarrow): the same columns as the CSV tables, binary and exact.

A file holds one column per name (float64, int64, bool, or dictionary-encoded text), the
unit of each column in its field metadata (``unit``) and all of them in the schema
metadata (``frictionlab.units``, JSON ``{name: unit}``); a masked entry is a null. Float64
values are stored as their 8 bytes: they read back bit for bit. Open with
``pandas.read_parquet(path)`` or :func:`read_parquet` (which gives the units too).
:class:`ParquetStream` appends chunks of rows as row groups (``history.parquet`` written
during a run); :func:`write_parquet_atomic` writes a whole table at once.
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.errors import ParameterError
from frictionlab.io.atomic import atomic_path
from frictionlab.io.closing import Closing
from frictionlab.io.tables import CsvTable

__all__ = ["ParquetStream", "read_parquet", "write_parquet_atomic"]

#: The schema metadata key holding the units (JSON).
UNITS_KEY = b"frictionlab.units"


def _array(name: str, values: np.ndarray) -> Any:
    """One column as an Arrow array (text dictionary-encoded; masked entries null)."""
    import pyarrow as pa

    mask = np.ma.getmaskarray(values) if np.ma.isMaskedArray(values) else None
    data = np.ma.getdata(values) if mask is not None else np.asarray(values)
    kind = data.dtype.kind
    if kind == "f":
        return pa.array(np.asarray(data, np.float64), pa.float64(), mask=mask)
    if kind in "iu":
        return pa.array(np.asarray(data, np.int64), pa.int64(), mask=mask)
    if kind == "b":
        return pa.array(data, pa.bool_(), mask=mask)
    if kind in "UO":
        import pandas as pd

        codes, levels = pd.factorize(np.asarray(data, dtype=object))
        indices = pa.array(codes.astype(np.int32), pa.int32(), mask=mask)
        return pa.DictionaryArray.from_arrays(indices, pa.array([str(t) for t in levels]))
    raise ParameterError(f"column {name}", str(data.dtype), "bool, integer, float or text")


def _table(columns: Mapping[str, np.ndarray], units: Mapping[str, str] | None) -> Any:
    """``columns`` as an Arrow table with the units in its field and schema metadata."""
    import pyarrow as pa

    if not columns:
        raise ParameterError("columns", "{}", "at least one column")
    units = {name: (units or {}).get(name, "-") for name in columns}
    arrays = [_array(name, values) for name, values in columns.items()]
    if len({len(a) for a in arrays}) != 1:
        shapes = {name: np.shape(v) for name, v in columns.items()}
        raise ParameterError("columns", shapes, "1-D arrays of one common length")
    fields = [
        pa.field(name, a.type, metadata={"unit": units[name]})
        for name, a in zip(columns, arrays, strict=True)
    ]
    schema = pa.schema(fields, metadata={UNITS_KEY: json.dumps(units).encode()})
    return pa.Table.from_arrays(arrays, schema=schema)


class ParquetStream(Closing):
    """Append chunks of rows (same columns each time) to a Parquet file, one row group each.

    Use as a context manager; ``rows`` counts the rows written. The file is complete only
    after :meth:`close` (Parquet's footer): write it into an output set's staging folder.
    """

    def __init__(self, path: str | os.PathLike[str], units: Mapping[str, str]) -> None:
        self.path = Path(path)
        self.units = dict(units)
        self.rows = 0
        self._writer: Any = None

    def write(self, columns: Mapping[str, np.ndarray]) -> None:
        import pyarrow.parquet as pq

        table = _table(columns, self.units)
        if self._writer is None:
            self._writer = pq.ParquetWriter(self.path, table.schema)
        self._writer.write_table(table)
        self.rows += table.num_rows

    def close(self) -> None:
        if self._writer is not None:
            self._writer.close()


def write_parquet_atomic(
    path: str | os.PathLike[str],
    columns: Mapping[str, np.ndarray],
    units: Mapping[str, str] | None = None,
) -> Path:
    """Write ``columns`` (equal-length 1-D arrays) as one Parquet file, atomically."""
    import pyarrow.parquet as pq

    table = _table(columns, units)
    with atomic_path(path) as tmp:
        pq.write_table(table, tmp)
    return Path(path)


def read_parquet(path: str | os.PathLike[str]) -> CsvTable:
    """A Parquet table as a :class:`~frictionlab.io.tables.CsvTable`: float64 columns (a
    masked array where there are nulls), int64, bool, or object arrays of text; the units
    from the file's metadata."""
    import pyarrow.parquet as pq

    table = pq.read_table(path)
    meta = table.schema.metadata or {}
    units = json.loads(meta[UNITS_KEY]) if UNITS_KEY in meta else {}
    columns: dict[str, np.ndarray] = {}
    for name, col in zip(table.column_names, table.columns, strict=True):
        values = col.to_numpy(zero_copy_only=False)
        if col.null_count:
            mask = np.asarray(col.is_null().to_numpy(zero_copy_only=False), dtype=bool)
            values = np.ma.MaskedArray(np.where(mask, 0, values).astype(np.float64), mask=mask)
        elif values.dtype.kind == "O":
            values = np.asarray(values, dtype=object)
        columns[name] = values
    return CsvTable(columns, {k: str(v) for k, v in units.items()}, [])
