"""figure_png_bytes draws once and writes the same file as matplotlib's own savefig."""

from __future__ import annotations

import io
from collections.abc import Callable

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from frictionlab.plotting._ticks import readable_log_ticks
from frictionlab.plotting.law import _point_colorbar, new_figure
from frictionlab.plotting.save import DPI, figure_png_bytes


def _two_panels() -> Figure:
    """Constrained layout, a legend below, a suptitle over two lines, a log time axis."""
    fig, (left, right) = new_figure(2, 5.5, 4.0)
    t = np.geomspace(1e-3, 1e3, 200)
    for k in range(3):
        left.plot(t * 1e-6, np.tanh(t / (k + 1)), lw=1.2, label=f"point {k + 1}")
        right.plot(t, np.tanh(t / (k + 1)), lw=1.2, label=f"point {k + 1}")
    right.axvspan(1.0, 10.0, color="0.6", alpha=0.15, lw=0, label="hold")
    right.set_xscale("log")
    left.set_xlabel("slip distance [um]")
    right.set_ylabel("friction ratio |f_t|/f_n [-]")
    right.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=2)
    fig.suptitle("a title\n(plotted: 3 of 40 points)")
    return fig


def _colorbar() -> Figure:
    fig, (ax,) = new_figure(1, 5.0, 4.0)
    numbers = np.arange(1, 41)
    ax.scatter(numbers, np.sqrt(numbers), c=numbers)
    _point_colorbar(fig, [ax], numbers, numbers[::4])
    return fig


def _no_layout() -> Figure:
    fig = Figure(figsize=(4.0, 3.0))
    ax = fig.add_subplot()
    ax.plot([0.5, 2.0], [1.0, 3.0], "o-")
    ax.set_yscale("log")
    return fig


@pytest.mark.parametrize("build", [_two_panels, _colorbar, _no_layout])
def test_png_bytes_equal_savefig(build: Callable[[], Figure]) -> None:
    """The same bytes as matplotlib's two-draw savefig of an identically built figure."""
    reference = build()
    FigureCanvasAgg(reference)
    readable_log_ticks(reference)
    buffer = io.BytesIO()
    reference.savefig(buffer, format="png", dpi=DPI)
    assert figure_png_bytes(build()) == buffer.getvalue()


def test_png_draws_once() -> None:
    """One draw of the figure per PNG (savefig draws a laid-out figure twice)."""
    fig = _colorbar()
    figure_png_bytes(fig)  # gives the figure its Agg canvas
    draws: list[object] = []
    fig.canvas.mpl_connect("draw_event", draws.append)
    assert figure_png_bytes(fig).startswith(b"\x89PNG\r\n\x1a\n")
    assert len(draws) == 1
