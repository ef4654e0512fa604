"""The combined sweep table: one row per case, its parameters and its summary figures.

``sweep.csv`` titles carry units as every frictionlab table does (``name [unit]``, ``[-]``
for dimensionless and text columns): a swept key takes the unit its declaration states
(:func:`key_unit`), a summary figure the unit of :func:`~frictionlab.sweep.figures.figure_unit`.
The frame of :func:`sweep_table` keeps plain names with ``frame.attrs["units"]``.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from frictionlab._frames import DIMENSIONLESS, column_title, normalise_unit
from frictionlab.sweep.cases import LINK, Case
from frictionlab.sweep.figures import figure_unit

__all__ = ["format_table", "key_unit", "sweep_table"]

_LEAD = ("case", "id", "status")


def sweep_table(
    cases: Sequence[Case],
    keys: Sequence[str],
    records: Mapping[str, Mapping[str, Any]],
    figures: Mapping[str, Mapping[str, float | None]],
    command: str = "simulate",
) -> pd.DataFrame:
    """Rows in case order; a case without a record is ``pending``.

    Columns: case (1-based), id, status (ok, failed, pending), the swept keys (linked grid
    keys as one column), the
    summary figures (the union over cases, in order of appearance), seconds, error.
    """
    figure_names = list(dict.fromkeys(name for f in figures.values() for name in f))
    rows = []
    for case in cases:
        record = records.get(case.id, {})
        row: dict[str, Any] = {
            "case": case.index + 1,
            "id": case.id,
            "status": record.get("status", "pending"),
        }
        for key in keys:
            row[key] = _cell(case.overrides.get(key.split(LINK)[0]))
        values = figures.get(case.id, {})
        for name in figure_names:
            row[name] = values.get(name)
        row["seconds"] = record.get("seconds")
        row["error"] = _one_line(record.get("error") or "")
        rows.append(row)
    columns = [*_LEAD, *keys, *figure_names, "seconds", "error"]
    frame = pd.DataFrame(rows, columns=columns)
    units: dict[str, str | None] = dict.fromkeys((*_LEAD, "error"), DIMENSIONLESS)
    units.update({key: key_unit(command, key) for key in keys})
    units.update({name: figure_unit(name) for name in figure_names})
    units["seconds"] = "s"
    frame.attrs["units"] = units
    return frame


def format_table(table: pd.DataFrame) -> str:
    """CSV text: one header row of ``name [unit]`` titles (no comment lines: error texts
    may hold ``#``); floats in their shortest exact form."""
    units = table.attrs.get("units", {})
    titled = table.rename(columns=lambda name: _title(name, units.get(name, None)))
    text = titled.to_csv(index=False, float_format=_shortest, lineterminator="\n")
    return str(text)


def key_unit(command: str, key: str) -> str | None:
    """The unit of a swept key (``program.2.duration`` -> ``"s"``, ``law.mu_s`` -> ``"-"``)
    from its declaration in :mod:`frictionlab.schema`; linked keys (``a+b``) take the unit
    they share. None when a key has no declaration or linked keys differ."""
    from frictionlab.schema.core import Section
    from frictionlab.schema.roughness import ROUGHNESS_FILE
    from frictionlab.schema.scenario import SCENARIO_FILE

    root = ROUGHNESS_FILE if command == "roughness" else SCENARIO_FILE
    found = set()
    for dotted in key.split(LINK):
        section: Section | None = root
        unit: str | None = None
        for part in dotted.split("."):
            if part.isdigit():  # an entry of an array of tables
                continue
            if section is None:
                return None
            try:
                field = section[part]
            except KeyError:
                return None
            section = field.table if field.table is not None and field.table.fields else None
            unit = None if section is not None else normalise_unit(field.unit)
        found.add(unit)
    return found.pop() if len(found) == 1 else None


def _title(name: str, unit: str | None) -> str:
    return name if unit is None else column_title(name, unit)


def _shortest(value: float) -> str:
    return repr(float(value))


def _cell(value: Any) -> Any:
    """Scalars as they are; lists and tables as compact JSON text."""
    if isinstance(value, list | dict):
        return json.dumps(value, separators=(",", ":"))
    return value


def _one_line(text: str) -> str:
    return " ".join(str(text).split())
