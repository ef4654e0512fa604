"""Tables as pandas DataFrames: column titles with units and a lazy pandas import.

The same column titles are used in every CSV file frictionlab writes, so
``pandas.read_csv(path)`` and ``result.to_dataframe()`` give the same frame.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

__all__ = [
    "DIMENSIONLESS",
    "TableResult",
    "column_title",
    "normalise_unit",
    "short_repr",
    "split_title",
    "to_dataframe",
]

#: The one spelling of a dimensionless unit (and of text columns) in titles and tables.
DIMENSIONLESS = "-"


def normalise_unit(unit: str | None) -> str:
    """``None``, ``""`` and ``"1"`` become :data:`DIMENSIONLESS`; others are kept."""
    text = (unit or "").strip()
    return DIMENSIONLESS if text in ("", "1", "-") else text


def column_title(name: str, unit: str | None) -> str:
    """``"time", "s"`` -> ``"time [s]"``; dimensionless -> ``"R [-]"``."""
    return f"{name} [{normalise_unit(unit)}]"


def split_title(title: str) -> tuple[str, str | None]:
    """``"time [s]"`` -> ``("time", "s")``; a title without ``[unit]`` -> ``(title, None)``."""
    text = title.strip()
    if text.endswith("]") and " [" in text:
        name, _, unit = text[:-1].rpartition(" [")
        if name.strip():
            return name.strip(), normalise_unit(unit)
    return text, None


def to_dataframe(columns: Mapping[str, np.ndarray], units: Mapping[str, str]) -> Any:
    """A :class:`pandas.DataFrame` with titled columns (``name [unit]``).

    Masked entries (undefined values) become NaN, as ``pandas.read_csv`` reads the empty
    fields of the CSV files. ``frame.attrs["units"]`` maps plain names to units.
    pandas is imported here, not when frictionlab is imported.
    """
    import pandas as pd

    data: dict[str, Any] = {}
    for name, values in columns.items():
        if np.ma.isMaskedArray(values):
            values = np.ma.filled(np.ma.asarray(values, dtype=np.float64), np.nan)
        data[column_title(name, units.get(name))] = np.array(values, copy=True)
    frame = pd.DataFrame(data)
    frame.attrs["units"] = {name: normalise_unit(units.get(name)) for name in columns}
    return frame


def short_repr(obj: Any, columns: Mapping[str, np.ndarray]) -> str:
    """A one-line repr of a result object: its table size and scalar fields, no arrays."""
    import dataclasses

    rows = len(next(iter(columns.values()))) if columns else 0
    parts = []
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        if isinstance(value, bool | int | float) or (isinstance(value, str) and value):
            text = repr(value)
            parts.append(f"{f.name}={text if len(text) <= 40 else text[:37] + '...'}")
    fields = "; " + ", ".join(parts) if parts else ""
    return f"{type(obj).__name__}({rows} rows x {len(columns)} columns{fields})"


class TableResult:
    """Mixin of every result object that reads as a table.

    A subclass defines :meth:`columns` (name -> 1-D array, masked where undefined) and
    :meth:`units`; the mixin gives :meth:`to_dataframe` (the titles of the CSV files) and
    a one-line repr. A dataclass using it passes ``repr=False`` so that repr is kept.
    """

    __slots__ = ()

    def columns(self) -> dict[str, np.ndarray]:
        """The result as named columns of equal length."""
        raise NotImplementedError

    def units(self) -> dict[str, str]:
        """The unit of each of :meth:`columns` (``-``: dimensionless)."""
        raise NotImplementedError

    def to_dataframe(self) -> Any:
        """:meth:`columns` as a :class:`pandas.DataFrame`, titles ``name [unit]`` (as the CSV).

        Undefined (masked) values become NaN; pandas is imported on call.
        """
        return to_dataframe(self.columns(), self.units())

    def __repr__(self) -> str:
        return short_repr(self, self.columns())
