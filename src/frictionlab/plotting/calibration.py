"""Figures of a calibration: data vs model, residuals, correlations, profile likelihoods.

Every function imports matplotlib lazily and returns the Figure or Axes it drew on. The
curve and profile figures have fixed margins (:func:`~frictionlab.plotting.save.fixed_layout`:
no layout solve; the constrained layout where a text would not fit).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from frictionlab.plotting._ticks import readable_log_ticks
from frictionlab.plotting.law import new_figure
from frictionlab.plotting.save import fixed_layout

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from frictionlab.calibration import Curve, Profile

__all__ = ["plot_correlation", "plot_curve_fit", "plot_profile"]


#: Most sliding segments drawn as panels of their own (more: the whole curve in one panel).
MAX_PANELS = 6


def plot_curve_fit(
    curve: Curve,
    model: np.ndarray,
    start_model: np.ndarray | None = None,
    band: np.ndarray | None = None,
) -> Figure:
    """Measured friction ratio (dots) and the fitted model (line), residuals below.

    One panel per segment that is not a hold (time from the segment's start), so that
    seconds of sliding are not lost beside hours of holding; holds are left out (the
    traction stays constant in them). ``band``: (n,) half-width of the model's confidence
    band, shaded.
    """
    from matplotlib.figure import Figure

    seg = curve.segment_of_samples()
    kinds = [type(s).__name__.lower() for s in curve.program]
    shown = [k for k in np.unique(seg) if kinds[k] != "hold"]
    if not 2 <= len(shown) <= MAX_PANELS:
        return _single_panel(curve, model, start_model, band)
    starts = np.concatenate([[0.0], np.cumsum(_durations(curve))])
    fig = Figure(figsize=(3.0 + 2.2 * len(shown), 5.5))
    axes = fig.subplots(2, len(shown), sharey="row", height_ratios=(3, 1), squeeze=False)
    fixed_layout(fig, left=0.85, right=0.15, top=0.6, bottom=0.55, wspace=0.12, hspace=0.4)
    for col, k in enumerate(shown):
        sel = seg == k
        t = curve.model_time[sel] - starts[k]
        ax, ax_r = axes[0, col], axes[1, col]
        ax.plot(t, curve.friction_ratio[sel], ".", ms=2, color="0.55", label="data")
        if start_model is not None:
            ax.plot(t, start_model[sel], "--", lw=1.0, color="C1", label="start law")
        ax.plot(t, model[sel], "-", lw=1.3, color="C0", label="fitted law")
        if band is not None and np.all(np.isfinite(band[sel])):
            ax.fill_between(t, model[sel] - band[sel], model[sel] + band[sel], color="C0",
                            alpha=0.25, lw=0, label="confidence band")  # fmt: skip
        # y given: no search for top tick labels to dodge (there are none; ~10 % of the draw)
        ax.set_title(f"segment {k + 1} ({kinds[k]})", fontsize=9, y=1.0)
        ax.grid(alpha=0.3)
        ax_r.plot(t, model[sel] - curve.friction_ratio[sel], ".", ms=2, color="C3")
        ax_r.axhline(0.0, color="0.3", lw=0.8)
        ax_r.set_xlabel("time in segment [s]")
        ax_r.grid(alpha=0.3)
    axes[0, 0].set_ylabel("friction ratio |f_t|/f_n [-]")
    axes[1, 0].set_ylabel("model - data [-]")
    axes[0, 0].legend(fontsize=7, loc="lower right")
    fig.suptitle(f"{curve.name}: {curve.n_samples} samples (holds not shown)", fontsize=10)
    return fig


def _durations(curve: Curve) -> list[float]:
    from frictionlab.calibration.model import segment_durations

    return segment_durations(curve.program)


def _single_panel(
    curve: Curve, model: np.ndarray, start_model: np.ndarray | None, band: np.ndarray | None
) -> Figure:
    """The whole curve against time in one panel, residuals below."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9.0, 5.5))
    ax, ax_r = fig.subplots(2, 1, sharex=True, height_ratios=(3, 1))
    fixed_layout(fig, left=0.85, right=0.25, top=0.4, bottom=0.55, hspace=0.15)
    t = curve.time
    stride = max(1, t.size // 4000)
    ax.plot(t[::stride], curve.friction_ratio[::stride], ".", ms=2, color="0.55", label="data")
    if start_model is not None:
        ax.plot(t, start_model, "--", lw=1.0, color="C1", label="start law")
    ax.plot(t, model, "-", lw=1.3, color="C0", label="fitted law")
    if band is not None and np.all(np.isfinite(band)):
        ax.fill_between(t, model - band, model + band, color="C0", alpha=0.25, lw=0,
                        label="confidence band")  # fmt: skip
    ax.set_ylabel("friction ratio |f_t|/f_n [-]")
    ax.set_title(f"{curve.name}: {curve.n_samples} samples", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    residual = model - curve.friction_ratio
    ax_r.plot(t[::stride], residual[::stride], ".", ms=2, color="C3")
    ax_r.axhline(0.0, color="0.3", lw=0.8)
    ax_r.set_xlabel("time [s]")
    ax_r.set_ylabel("model - data [-]")
    ax_r.grid(alpha=0.3)
    return fig


def plot_correlation(names: Sequence[str], correlation: np.ndarray, ax: Axes | None = None) -> Axes:
    """The correlation matrix of the fitted parameters, values written in the cells."""
    if ax is None:
        ax = new_figure(1, 1.0 + 0.9 * len(names), 0.6 + 0.8 * len(names))[1][0]
    p = len(names)
    shown = np.nan_to_num(np.asarray(correlation, dtype=float), nan=0.0)
    image = ax.imshow(shown, vmin=-1.0, vmax=1.0, cmap="RdBu_r")
    ax.set_xticks(range(p), list(names), rotation=45, ha="right")
    ax.set_yticks(range(p), list(names))
    for a in range(p):
        for b in range(p):
            c = correlation[a, b]
            text = "n/a" if not np.isfinite(c) else f"{c:.2f}"
            ax.text(b, a, text, ha="center", va="center", fontsize=8,
                    color="white" if np.isfinite(c) and abs(c) > 0.6 else "black")  # fmt: skip
    ax.figure.colorbar(image, ax=ax, shrink=0.8, label="correlation")
    return ax


def plot_profile(
    profile: Profile, value: float, stderr: float, log: bool, ax: Axes | None = None
) -> Axes:
    """delta chi^2 of the profile (dots) with the linearised parabola and the 95 % level."""
    from frictionlab.calibration import CHI2_95

    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(5.5, 4.0))
        ax = fig.add_subplot()
        fixed_layout(fig, left=0.8, right=0.3, top=0.15, bottom=0.55)
    x = profile.values
    ax.plot(x, profile.delta_chi2, "o-", color="C0", label="profile (others re-fitted)")
    if np.isfinite(stderr) and stderr > 0:
        dense = np.geomspace(x.min(), x.max(), 200) if log else np.linspace(x.min(), x.max(), 200)
        # The parabola of the linearisation lives in the fitted space (ln x for log ones).
        z = (np.log(dense / value) / (stderr / value)) if log else (dense - value) / stderr
        ax.plot(dense, z**2, "--", color="0.4", lw=1.0, label="linearised ((x - x_hat)/stderr)^2")
    ax.axhline(CHI2_95, color="C3", lw=1.0, ls=":", label="95 % level (3.84)")
    ax.axvline(value, color="0.6", lw=0.8)
    if log:
        ax.set_xscale("log")
    top = max(2.0 * CHI2_95, float(np.nanmax(profile.delta_chi2)) if profile.delta_chi2.size else 0)
    ax.set_ylim(-0.2, min(top * 1.05, 10 * CHI2_95))
    ax.set_xlabel(profile.name)
    ax.set_ylabel("delta chi^2 [-]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    readable_log_ticks(ax.figure)
    return ax
