"""Log axes show at least three labelled ticks (rendered with Agg, labels counted)."""

from __future__ import annotations

import itertools
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
import pytest

matplotlib.use("Agg")
from matplotlib.axis import Axis
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from frictionlab.plotting._ticks import readable_log_ticks, readable_tick_values
from frictionlab.plotting.law import (
    plot_healing,
    plot_restart_peaks,
    plot_stability_map,
    plot_steady_friction,
    save_figure,
)
from frictionlab.plotting.sweep import sweep_figure

RANGES = [(0.3, 0.6), (0.1, 3.0), (0.9, 2.1), (1.0, 1.2), (0.05, 0.5), (1e-4, 10.0),
          (2e-3, 8e-3), (1e-12, 1e3), (3e4, 2e6), (1.0, 1.01)]  # fmt: skip


def labelled_ticks(axis: Axis) -> list[str]:
    """The non-empty tick labels (major and minor) drawn inside the axis' view."""
    FigureCanvasAgg(axis.figure)  # a Figure() has a canvas that does not draw
    axis.figure.canvas.draw()
    lo, hi = sorted(axis.get_view_interval())
    out = []
    for minor in (False, True):
        locs = axis.get_minorticklocs() if minor else axis.get_majorticklocs()
        ticks = axis.get_minor_ticks(len(locs)) if minor else axis.get_major_ticks(len(locs))
        for loc, tick in zip(locs, ticks, strict=True):
            label = tick.label1
            inside = lo * (1 - 1e-9) <= loc <= hi * (1 + 1e-9)
            if inside and label.get_visible() and label.get_text().strip():
                out.append(label.get_text())
    return out


def log_axes(fig: Figure) -> list[Axis]:
    return [a for ax in fig.axes for a in (ax.xaxis, ax.yaxis) if a.get_scale() == "log"]


def figure_over(lo: float, hi: float) -> Figure:
    fig = Figure()
    ax = fig.add_subplot()
    ax.plot([lo, hi], [lo, hi])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    return fig


@pytest.mark.parametrize(("lo", "hi"), RANGES)
def test_every_range_gets_three_distinct_labels(lo: float, hi: float) -> None:
    fig = readable_log_ticks(figure_over(lo, hi))
    for axis in log_axes(fig):
        labels = labelled_ticks(axis)
        assert len(labels) >= 3 and len(set(labels)) == len(labels), (lo, hi, labels)
        assert len(labels) <= 12, labels  # readable, not crowded


def test_matplotlib_alone_labels_two_ticks_over_two_decades() -> None:
    # the problem being solved: without the locator this axis has only 0.1 and 1 labelled
    assert len(labelled_ticks(figure_over(0.02, 3.0).axes[0].xaxis)) < 3
    assert len(labelled_ticks(readable_log_ticks(figure_over(0.02, 3.0)).axes[0].xaxis)) >= 3


def test_tick_values_cover_many_ranges() -> None:
    for lo, decades in itertools.product(np.geomspace(1e-9, 1e6, 31), np.linspace(0.005, 14, 57)):
        hi = lo * 10.0**decades
        ticks = readable_tick_values(lo, hi)
        inside = ticks[(ticks >= lo * (1 - 1e-12)) & (ticks <= hi * (1 + 1e-12))]
        assert np.all(ticks > 0) and np.all(np.diff(ticks) > 0)
        assert 3 <= inside.size <= 12, (lo, hi, inside)


def test_explicit_ticks_are_left_alone() -> None:
    fig = figure_over(0.1, 3.0)
    fig.axes[0].set_xticks([0.2, 2.0])
    readable_log_ticks(fig)
    assert list(fig.axes[0].xaxis.get_majorticklocs()) == [0.2, 2.0]


def steady(narrow: bool) -> Figure:
    v = np.geomspace(0.015, 4.0, 4) if narrow else np.geomspace(1e-4, 1.0, 5)
    mu = 0.3 + 0.2 / (1 + v)
    return plot_steady_friction(v, mu, v, mu, (0.3, 0.5)).figure  # type: ignore[return-value]


def restart(narrow: bool) -> Figure:
    t = np.array([0.15, 40.0]) if narrow else np.array([1.0, 10.0, 100.0, 1000.0])
    mu = 0.5 - 0.1 * np.exp(-t / 100)
    return plot_restart_peaks(t, mu, mu, t, mu, 0.5).figure  # type: ignore[return-value]


def healing(narrow: bool) -> Figure:
    t = np.array([0.015, 4.0]) if narrow else np.array([1.0, 10.0, 100.0])
    d = 0.01 * np.log10(t)
    return plot_healing(t, d, np.ones(t.size, int), 0.01, 0.0).figure  # type: ignore[return-value]


def stability(narrow: bool) -> Figure:
    ratio = np.array([0.5, 0.8, 1.25, 2.0]) if narrow else np.array([0.1, 0.5, 2.0, 10.0])
    osc = np.array([4.0, 0.3, 0.1, 0.015]) if narrow else np.array([0.3, 0.2, 1e-3, 5e-4])
    return plot_stability_map(ratio, osc, 0.1).figure  # type: ignore[return-value]


def sweep(narrow: bool) -> Figure:
    x = np.array([0.015, 0.03, 0.5, 4.0]) if narrow else np.geomspace(1e-4, 1.0, 5)
    table = pd.DataFrame({"case": range(x.size), "status": "ok", "dir": "c", "velocity": x,
                          "mu": 0.3 + x})  # fmt: skip
    return sweep_figure(table, ["velocity"])


@pytest.mark.parametrize("narrow", [True, False])  # narrow: about 2 decades, 2 powers of 10
@pytest.mark.parametrize("build", [steady, restart, healing, stability, sweep])
def test_plotting_log_axes_have_three_labels(build, narrow: bool, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    fig = build(narrow)
    axes = log_axes(fig)
    assert axes, build.__name__
    save_figure(fig, tmp_path / "f.png")
    for axis in axes:
        labels = labelled_ticks(axis)
        assert len(labels) >= 3, (build.__name__, axis.axis_name, labels)


@pytest.mark.parametrize(("lo", "hi"), [(1e-300, 1e300), (5e-324, 1.7e308), (1e-10, 1e308)])
def test_extreme_ranges_give_finite_ticks(lo: float, hi: float) -> None:
    """Ranges near the float limits (a slide at 1e300 m/s) neither overflow nor lose labels."""
    ticks = readable_tick_values(lo, hi)
    assert np.all(np.isfinite(ticks)) and np.all(ticks > 0.0)
    inside = ticks[(ticks >= lo) & (ticks <= hi)]
    assert inside.size >= 3
