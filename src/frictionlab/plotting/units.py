"""Axis units at the scale of the data: a length axis in m, mm, um or nm.

:func:`length_unit` picks the SI prefix that puts the span of the shown values between 1
and 1000; :func:`show_length_in` relabels an axis drawn in metres in that unit (the data
stay in metres; only the tick labels and the axis label change).
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["LENGTH_UNITS", "length_unit", "show_length_in"]

#: Length units and their size in metres, largest first.
LENGTH_UNITS: tuple[tuple[str, float], ...] = (("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9))


def length_unit(low: float, high: float) -> tuple[str, float]:
    """The unit (name, metres) in which the span ``high - low`` [m] reads 1 to 1000."""
    span = abs(float(high) - float(low)) or max(abs(float(low)), abs(float(high)))
    if not math.isfinite(span) or span <= 0:
        return LENGTH_UNITS[0]
    for name, size in LENGTH_UNITS:
        if span / size >= 1.0:
            return name, size
    return LENGTH_UNITS[-1]


def show_length_in(axis: Any, label: str, low: float, high: float) -> str:
    """Label ``axis`` (an x or y axis drawn in metres over [low, high]) in the unit of its
    span: ticks divided by the unit, ``label [unit]`` as axis label; returns the unit."""
    from matplotlib.ticker import FuncFormatter, MaxNLocator

    name, size = length_unit(low, high)
    axis.set_major_locator(MaxNLocator(nbins=6, steps=[1, 2, 2.5, 5, 10]))
    axis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v / size:.6g}"))
    axis.set_label_text(f"{label} [{name}]")
    return name
