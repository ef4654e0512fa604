"""The history as a long-format table: one row per recorded step and point (step-major).

Used for ``history.csv`` (written chunk by chunk as the rows are computed, see
:class:`~frictionlab.driver.recorder.Recording`) and :meth:`History.to_dataframe`, so both
hold the same columns in the same order.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from frictionlab._frames import to_dataframe
from frictionlab.driver.simulate import History, status_labels

__all__ = [
    "HISTORY_UNITS",
    "chunk_columns",
    "history_chunk",
    "history_columns",
    "history_dataframe",
]

#: Units of the history columns (F is in Pa for closed surfaces, see history_columns).
#: ``dissipation`` is a deprecated duplicate of ``plastic_work`` (same values).
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
    "plastic_work": "J/m^2",
    "dissipation": "J/m^2",
    "status": "-",
    "substeps": "-",
    "iterations": "-",
}


def history_chunk(history: History) -> dict[str, np.ndarray]:
    """The whole history as one chunk of rows (the layout a recording sink receives)."""
    kinds = ["initial"] + [""] * max((s.index for s in history.segments), default=0)
    for seg in history.segments:
        kinds[seg.index] = seg.kind
    chunk = {
        "step": history.steps,
        "segment": history.segment,
        "kind": np.array(kinds, dtype=object)[history.segment],
        "substeps": history.substeps,
        "point": history.point_numbers,
        "time": history.time,
        "slip": history.slip,
        "approach": history.approach,
        "traction": history.traction,
        "F": history.F,
        "R": history.R,
        "plastic_slip": history.plastic_slip,
        "plastic_work": history.plastic_work,
        "status": history.status,
        "iterations": history.iterations,
    }
    chunk.update(history.extra)
    return chunk


def chunk_columns(
    chunk: dict[str, np.ndarray], extra: tuple[str, ...] = ()
) -> dict[str, np.ndarray]:
    """Long-format columns (step-major) of a chunk of rows; ``extra``: more (rows, m) series."""
    rows, m = chunk["time"].shape

    def flat(arr: np.ndarray) -> np.ndarray:
        return np.asarray(arr).reshape(rows * m)

    def per_row(arr: np.ndarray) -> np.ndarray:
        return np.repeat(np.asarray(arr), m)

    traction = chunk["traction"]
    fn = traction[..., 2]
    ratio = np.where(
        fn > 0, np.hypot(traction[..., 0], traction[..., 1]) / np.where(fn > 0, fn, 1.0), 0.0
    )
    work = flat(chunk["plastic_work"])
    cols: dict[str, np.ndarray] = {
        "point": np.tile(chunk["point"], rows),
        "step": per_row(chunk["step"]),
        "segment": per_row(chunk["segment"]),
        "kind": per_row(chunk["kind"]),
        "time": flat(chunk["time"]),
        "slip_1": flat(chunk["slip"][..., 0]),
        "slip_2": flat(chunk["slip"][..., 1]),
        "approach": flat(chunk["approach"]),
        "traction_1": flat(traction[..., 0]),
        "traction_2": flat(traction[..., 1]),
        "traction_n": flat(fn),
        "friction_ratio": flat(ratio),
        "R": flat(chunk["R"]),
        "F": flat(chunk["F"]),
        "plastic_slip": flat(chunk["plastic_slip"]),
        "plastic_work": work,
        "dissipation": work,
        "status": status_labels(flat(chunk["status"])),
        "substeps": per_row(chunk["substeps"]),
        "iterations": flat(chunk["iterations"]),
    }
    for key in extra:
        cols[key] = flat(chunk[key])
    return cols


def history_units(history: History | None = None, cone: bool = True) -> dict[str, str]:
    """Units of the history columns (F in Pa for closed surfaces; extra series appended)."""
    units = dict(HISTORY_UNITS)
    if not cone:
        units["F"] = "Pa"
    if history is not None:
        for key in history.extra:
            units[key] = history.extra_units.get(key, "-")
    return units


def history_columns(
    history: History, cone: bool = True
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """The history as long-format columns (step-major) and their units."""
    cols = chunk_columns(history_chunk(history), tuple(history.extra))
    return cols, history_units(history, cone)


def history_dataframe(history: History, cone: bool = True) -> Any:
    """:func:`history_columns` as a :class:`pandas.DataFrame` (titles ``name [unit]``)."""
    cols, units = history_columns(history, cone)
    return to_dataframe(cols, units)
