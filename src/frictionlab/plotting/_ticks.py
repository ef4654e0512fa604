"""Readable log axes: at least three labelled ticks whatever the range.

Matplotlib labels only the powers of ten of a log axis, so an axis spanning one or two
decades shows two labels, and one spanning less than a decade may show one or none.
:func:`readable_log_ticks` gives every log-scaled axis of a figure a locator that labels
the powers of ten when at least three lie in view, else 1-2-5 steps, else every integer
multiple of a power of ten, else (a range of less than about a factor 1.3) evenly spaced
values; labels read like ``0.02``, ``5`` or ``1e+04``. Axes whose ticks were set
explicitly (a fixed locator) are left alone.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = ["MIN_LABELS", "readable_log_ticks", "readable_tick_values"]

#: The least number of labelled ticks a log axis shows.
MIN_LABELS = 3

_STEPS = ((1.0,), (1.0, 2.0, 5.0), tuple(float(k) for k in range(1, 10)))


def readable_tick_values(vmin: float, vmax: float, minimum: int = MIN_LABELS) -> np.ndarray:
    """Tick positions for a log axis over [vmin, vmax] (> 0), at least ``minimum`` inside.

    The ticks may extend one step beyond the range (matplotlib clips them when drawing).
    """
    lo, hi = sorted((float(vmin), float(vmax)))
    if not (lo > 0.0 and math.isfinite(hi)):
        return np.array([1.0])
    first, last = math.floor(math.log10(lo)) - 1, math.ceil(math.log10(hi)) + 1
    for subs in _STEPS:
        ticks = np.array([float(f"{s:g}e{e}") for e in range(first, last + 1) for s in subs])
        ticks = ticks[np.isfinite(ticks) & (ticks > 0.0)]  # 1e309 overflows, 1e-330 is 0
        inside = ticks[(ticks >= lo * (1 - 1e-12)) & (ticks <= hi * (1 + 1e-12))]
        if inside.size >= minimum:
            return ticks if subs != _STEPS[0] or inside.size < 12 else _thin(ticks, lo, hi)
    # less than about a factor 1.3: evenly spaced values, nice steps
    from matplotlib.ticker import MaxNLocator

    values = np.array([lo, hi])
    for nbins in range(minimum, 4 * minimum):
        raw = np.asarray(MaxNLocator(nbins=nbins, steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi))
        values = raw[raw > 0].astype(np.float64)
        if np.count_nonzero((values >= lo) & (values <= hi)) >= minimum:
            break
    return values


def _thin(ticks: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Every k-th power of ten when many decades are in view (about 6 to 11 labels)."""
    decades = math.log10(hi) - math.log10(lo)  # hi / lo may overflow
    step = max(1, math.ceil(decades / 10))
    exps = np.round(np.log10(ticks)).astype(int)
    return ticks[exps % step == 0]


def _format(value: float, _pos: Any = None) -> str:
    return f"{value:g}"


def readable_log_ticks(fig: Any, minimum: int = MIN_LABELS) -> Any:
    """Give every log-scaled axis of ``fig`` at least ``minimum`` labelled ticks; return fig.

    Works at draw time (the locator sees the final limits), so it may be called before the
    data are complete. Minor ticks stay, unlabelled.
    """
    from matplotlib import ticker

    class ReadableLogLocator(ticker.Locator):
        def __call__(self) -> Any:
            assert self.axis is not None
            vmin, vmax = self.axis.get_view_interval()
            return self.tick_values(vmin, vmax)

        def tick_values(self, vmin: float, vmax: float) -> Any:
            return readable_tick_values(vmin, vmax, minimum)

    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            fixed = isinstance(axis.get_major_locator(), ticker.FixedLocator)
            if axis.get_scale() != "log" or fixed:
                continue
            axis.set_major_locator(ReadableLogLocator())
            axis.set_major_formatter(ticker.FuncFormatter(_format))
            axis.set_minor_formatter(ticker.NullFormatter())
    return fig
