"""The combined sweep table: one row per case, its parameters and its summary figures."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from frictionlab.sweep.cases import LINK, Case

__all__ = ["format_table", "sweep_table"]

_LEAD = ("case", "id", "status")


def sweep_table(
    cases: Sequence[Case],
    keys: Sequence[str],
    records: Mapping[str, Mapping[str, Any]],
    figures: Mapping[str, Mapping[str, float | None]],
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
    return pd.DataFrame(rows, columns=columns)


def format_table(table: pd.DataFrame) -> str:
    """Plain CSV text (a header row, no comment lines: error texts may hold ``#``);
    floats in their shortest exact form."""
    text = table.to_csv(index=False, float_format=_shortest, lineterminator="\n")
    return str(text)


def _shortest(value: float) -> str:
    return repr(float(value))


def _cell(value: Any) -> Any:
    """Scalars as they are; lists and tables as compact JSON text."""
    if isinstance(value, list | dict):
        return json.dumps(value, separators=(",", ":"))
    return value


def _one_line(text: str) -> str:
    return " ".join(str(text).split())
