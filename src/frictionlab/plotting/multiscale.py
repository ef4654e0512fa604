"""Figure of scale-resolved friction: mu/mu0 against the shortest wavelength retained."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from frictionlab.plotting._ticks import readable_log_ticks
from frictionlab.plotting.roughness import new_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from frictionlab.roughness.multiscale import MultiscaleResult

__all__ = ["multiscale_figure", "plot_multiscale", "plot_multiscale_anisotropy"]

#: At most this many directions get their own line (evenly picked).
MAX_LINES = 7


def _picked(count: int) -> list[int]:
    if count <= MAX_LINES:
        return list(range(count))
    return sorted({int(v) for v in np.rint(np.linspace(0, count - 1, MAX_LINES))})


def plot_multiscale(result: MultiscaleResult, *, ax: Axes | None = None) -> Axes:
    """mu/mu0 vs the shortest wavelength retained (log axis, fine scales to the left),
    one line per direction; invalid points left out."""
    if ax is None:
        ax = new_figure().add_subplot()
    ratio = np.where(result.valid, result.mu / result.mu0, np.nan)
    for k in _picked(result.beta_deg.size):
        ax.plot(
            result.cutoff_m, ratio[:, k], marker="o", label=f"beta = {result.beta_deg[k]:g} deg"
        )
    ax.set_xscale("log")
    ax.set_xlabel("shortest wavelength retained (m)")
    ax.set_ylabel("mu / mu0")
    ax.set_title("friction vs the scales retained", fontsize=9)
    ax.grid(True, alpha=0.3, which="both")
    ax.legend(fontsize=7)
    readable_log_ticks(ax.figure)
    return ax


def plot_multiscale_anisotropy(result: MultiscaleResult, *, ax: Axes | None = None) -> Axes:
    """max/min of mu over the directions vs the shortest wavelength retained."""
    if ax is None:
        ax = new_figure().add_subplot()
    mu = np.where(result.valid, result.mu, np.nan)
    with np.errstate(invalid="ignore"):
        ratio = np.nanmax(mu, axis=1) / np.nanmin(mu, axis=1)
    ax.plot(result.cutoff_m, ratio, marker="s", color="C3")
    ax.set_xscale("log")
    ax.set_xlabel("shortest wavelength retained (m)")
    ax.set_ylabel("anisotropy max(mu) / min(mu)")
    ax.set_title("which scales make friction anisotropic", fontsize=9)
    ax.grid(True, alpha=0.3, which="both")
    readable_log_ticks(ax.figure)
    return ax


def multiscale_figure(result: MultiscaleResult, title: str | None = None) -> Figure:
    fig = new_figure(11.0, 4.5)
    plot_multiscale(result, ax=fig.add_subplot(1, 2, 1))
    plot_multiscale_anisotropy(result, ax=fig.add_subplot(1, 2, 2))
    if title:
        fig.suptitle(title, fontsize=10)
    return fig
