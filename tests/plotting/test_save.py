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
from frictionlab.plotting.save import DPI, figure_png_bytes, fixed_layout, texts_fit


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


def _grid(left: float, wspace: float, ylabel: str = "friction ratio [-]") -> Figure:
    """Two panels side by side with fixed margins, both showing their y tick labels."""
    fig = Figure(figsize=(6.0, 3.0))
    axes = fig.subplots(1, 2)
    for ax in axes:
        ax.plot([0.0, 1.0], [1000.0, 3000.0])
        ax.set_ylabel(ylabel)
        ax.set_xlabel("time [s]")
    return fixed_layout(fig, left=left, right=0.1, top=0.1, bottom=0.5, wspace=wspace)


def test_fixed_margins_that_fit_are_kept() -> None:
    """Room for the labels: drawn once, no layout engine, the margins as given [inches]."""
    fig = _grid(left=0.9, wspace=1.0)
    figure_png_bytes(fig)
    assert texts_fit(fig) and fig.get_layout_engine() is None
    left_ax = fig.axes[0].get_position()
    assert left_ax.x0 * 6.0 == pytest.approx(0.9) and fig.axes[1].get_position().x1 * 6.0 == (
        pytest.approx(5.9)
    )
    gap = (fig.axes[1].get_position().x0 - left_ax.x1) * 6.0
    assert gap == pytest.approx(1.0)


@pytest.mark.parametrize(
    ("left", "wspace", "ylabel", "why"),
    [
        (0.05, 1.0, "friction ratio [-]", "the first panel's labels leave the figure"),
        (0.9, 0.02, "friction ratio [-]", "the second panel's labels run into the first"),
        (0.9, 1.0, "a y label far too long for the figure " * 3, "the label leaves the figure"),
    ],
)
def test_margins_too_small_fall_back_to_the_constrained_layout(
    left: float, wspace: float, ylabel: str, why: str
) -> None:
    fig = _grid(left, wspace, ylabel)
    FigureCanvasAgg(fig)
    fig.set_dpi(DPI)
    fig.canvas.draw()
    assert not texts_fit(fig), why
    assert figure_png_bytes(fig).startswith(b"\x89PNG\r\n\x1a\n")
    assert type(fig.get_layout_engine()).__name__ == "ConstrainedLayoutEngine"
    if len(ylabel) < 40:  # a label longer than the figure cannot fit at all
        assert texts_fit(fig), "the constrained layout made room"


def test_calibration_figures_fit_their_fixed_margins() -> None:
    """The curve (panels and single-panel forms) and profile figures need no layout solve."""
    from tests.calibration.support import make_curve

    from frictionlab.calibration import Profile
    from frictionlab.plotting.calibration import _single_panel, plot_curve_fit, plot_profile

    curve = make_curve(0.0)
    model = curve.friction_ratio + 1e-3 * np.sin(curve.time)
    panels = plot_curve_fit(curve, model, band=np.full(curve.n_samples, 0.002))
    one = _single_panel(curve, model, model + 0.01, None)  # > MAX_PANELS sliding segments
    assert len(panels.axes) == 6
    values = np.geomspace(2e10, 9e13, 7)
    delta = np.array([40.0, 4.8, 0.0, 0.3, 0.5, 0.6, 0.6])
    profile = Profile("alpha_t", values, delta / 2, delta, (4e11, None))
    prof = plot_profile(profile, 1.2e12, 1.6e12, log=True).figure
    for fig in (panels, one, prof):
        figure_png_bytes(fig)
        assert fig.get_layout_engine() is None and texts_fit(fig)
