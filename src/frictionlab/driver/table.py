"""The history as a long-format table: one row per point and recorded step (point-major).

Used for ``history.csv`` and :meth:`History.to_dataframe`, so both hold the same columns.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from frictionlab._frames import to_dataframe
from frictionlab.driver.simulate import History, status_labels

__all__ = ["HISTORY_UNITS", "history_columns", "history_dataframe"]

#: Units of the history columns (F is in Pa for closed surfaces, see history_columns).
HISTORY_UNITS: dict[str, str] = {
    "point": "-",
    "step": "-",
    "segment": "-",
    "kind": "-",
    "time": "s",
    "slip_1": "m",
    "slip_2": "m",
    "approach": "m",
    "traction_1": "Pa",
    "traction_2": "Pa",
    "traction_n": "Pa",
    "friction_ratio": "-",
    "R": "-",
    "F": "-",
    "plastic_slip": "m",
    "dissipation": "J/m^2",
    "status": "-",
    "substeps": "-",
    "iterations": "-",
}


def history_columns(
    history: History, cone: bool = True
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """The history as long-format columns (point-major) and their units."""
    rows, n = history.n_rows, history.n_points

    def flat(arr: np.ndarray) -> np.ndarray:
        return np.ascontiguousarray(np.asarray(arr).T).reshape(n * rows)

    kinds = np.array(["initial"] + [""] * (rows - 1), dtype=object)
    for seg in history.segments:
        kinds[seg.first_row : seg.last_row + 1] = seg.kind
    per_step = np.broadcast_to(np.arange(rows)[:, None], (rows, n))
    cols: dict[str, np.ndarray] = {
        "point": flat(np.broadcast_to(np.arange(1, n + 1), (rows, n))),
        "step": flat(per_step),
        "segment": flat(np.broadcast_to(history.segment[:, None], (rows, n))),
        "kind": flat(np.broadcast_to(kinds[:, None], (rows, n))),
        "time": flat(history.time),
        "slip_1": flat(history.slip[..., 0]),
        "slip_2": flat(history.slip[..., 1]),
        "approach": flat(history.approach),
        "traction_1": flat(history.traction[..., 0]),
        "traction_2": flat(history.traction[..., 1]),
        "traction_n": flat(history.traction[..., 2]),
        "friction_ratio": flat(history.friction_ratio),
        "R": flat(history.R),
        "F": flat(history.F),
        "plastic_slip": flat(history.plastic_slip),
        "dissipation": flat(history.dissipation),
        "status": flat(status_labels(history.status)),
        "substeps": flat(np.broadcast_to(history.substeps[:, None], (rows, n))),
        "iterations": flat(history.iterations),
    }
    units = dict(HISTORY_UNITS)
    if not cone:
        units["F"] = "Pa"
    for key, arr in history.extra.items():
        cols[key] = flat(arr)
        units[key] = history.extra_units.get(key, "-")
    return cols, units


def history_dataframe(history: History, cone: bool = True) -> Any:
    """:func:`history_columns` as a :class:`pandas.DataFrame` (titles ``name [unit]``)."""
    cols, units = history_columns(history, cone)
    return to_dataframe(cols, units)
