"""Plots of adhesion, wear and hierarchy results (how friction evolves over a contact's life).

matplotlib is imported lazily (through :mod:`frictionlab.plotting.roughness`); every
function takes ``ax=None`` and returns the Axes (or a Figure for the ``*_figure``
functions). Undefined (masked) values are left out of the curves, never drawn as NaN.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from frictionlab.plotting._ticks import readable_log_ticks
from frictionlab.plotting.roughness import new_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from frictionlab.roughness.adhesion import AdhesionSweep
    from frictionlab.roughness.hierarchy import HierarchyResult, HierarchyWearHistory
    from frictionlab.roughness.wear import WearHistory

__all__ = [
    "adhesion_figure",
    "fig10_adhesion",
    "fig11_wear",
    "fig12_hierarchy_1d",
    "fig13_hierarchy_2d",
    "fig14_hierarchy_wear",
    "hierarchy_figure",
    "hierarchy_wear_figure",
    "plot_adhesion_force",
    "plot_adhesion_mu",
    "plot_hierarchy",
    "plot_hierarchy_wear",
    "plot_tensile_fraction",
    "plot_wear",
    "wear_figure",
]


def _defined(x: np.ndarray, y: np.ma.MaskedArray | np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    mask = np.ma.getmaskarray(y)
    return np.asarray(x)[~mask], np.asarray(np.ma.getdata(y))[~mask]


def _finish(ax: Axes, xlabel: str, ylabel: str, title: str) -> Axes:
    """Labels, a small title, grid and legend: the end of every panel of this module."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    return ax


#: The x axis of every adhesion panel.
_LOAD_LABEL = "normal load per spring L (N)"


def _load_panel(sweep: AdhesionSweep, ax: Axes | None) -> tuple[Axes, np.ndarray]:
    """The panel of an adhesion plot (a new one when ``ax`` is None), loads in rising order."""
    return (new_figure().add_subplot() if ax is None else ax), np.argsort(sweep.load)


def _titled(fig: Figure, title: str | None) -> Figure:
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def plot_adhesion_mu(
    sweep: AdhesionSweep, *, ax: Axes | None = None, label: str = "", limit: float = 6.0
) -> Axes:
    """mu_a/mu0 (Eq 22) vs load per spring, one curve per direction; L = 0 left out.

    ``limit`` bounds the y axis (mu_a diverges as L -> 0); the non-adhesive mu is dashed.
    """
    ax, order = _load_panel(sweep, ax)
    for k, beta in enumerate(sweep.beta_deg):
        x, y = _defined(sweep.load[order], sweep.mu_apparent[order, k] / sweep.mu0)
        # two branches: mu_a diverges with opposite signs on either side of L = 0
        line = ax.plot(x[x > 0], y[x > 0], marker=".", label=f"{label}beta = {beta:g} deg")[0]
        ax.plot(x[x < 0], y[x < 0], marker=".", color=line.get_color())
        if sweep.mu_no_adhesion is not None:
            xn, yn = _defined(sweep.load[order], sweep.mu_no_adhesion[order, k] / sweep.mu0)
            ax.plot(xn, yn, "--", color=line.get_color(), lw=1.0)
    ax.axvline(0.0, color="0.6", lw=0.8)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_ylim(-limit, limit)
    ylabel = "mu_a / mu0 (Eq 22); dashed: k_t = 0"
    return _finish(ax, _LOAD_LABEL, ylabel, "apparent friction coefficient (undefined at L = 0)")


def plot_adhesion_force(sweep: AdhesionSweep, *, ax: Axes | None = None, label: str = "") -> Axes:
    """Tangential force |R_xy^(c)| per spring vs load per spring."""
    ax, order = _load_panel(sweep, ax)
    for k, beta in enumerate(sweep.beta_deg):
        ax.plot(
            sweep.load[order],
            sweep.tangential_force[order, k],
            marker=".",
            label=f"{label}beta = {beta:g} deg",
        )
    ax.axvline(0.0, color="0.6", lw=0.8)
    ylabel = "tangential force per spring (N)"
    return _finish(ax, _LOAD_LABEL, ylabel, "friction force of the compressed springs")


def plot_tensile_fraction(sweep: AdhesionSweep, *, ax: Axes | None = None, label: str = "") -> Axes:
    """Mean (solid) and largest (dotted) fraction of stretched springs over the period."""
    ax, order = _load_panel(sweep, ax)
    for k, beta in enumerate(sweep.beta_deg):
        line = ax.plot(
            sweep.load[order],
            sweep.tensile_fraction_mean[order, k],
            marker=".",
            label=f"{label}beta = {beta:g} deg",
        )[0]
        ax.plot(
            sweep.load[order], sweep.tensile_fraction_max[order, k], ":", color=line.get_color()
        )
    ax.set_ylim(-0.02, 1.02)
    title = "stretched springs over one period (mean; dotted: max)"
    return _finish(ax, _LOAD_LABEL, "fraction of stretched springs", title)


def adhesion_figure(sweep: AdhesionSweep, title: str | None = None) -> Figure:
    """Three panels: mu_a/mu0, tangential force and stretched fraction vs load."""
    fig = new_figure(14.0, 4.2)
    plot_adhesion_mu(sweep, ax=fig.add_subplot(1, 3, 1))
    plot_adhesion_force(sweep, ax=fig.add_subplot(1, 3, 2))
    plot_tensile_fraction(sweep, ax=fig.add_subplot(1, 3, 3))
    return _titled(fig, title)


def plot_wear(history: WearHistory, *, ax: Axes | None = None, label: str = "") -> Axes:
    """mu/mu0 vs t/T_w, one curve per direction."""
    if ax is None:
        ax = new_figure().add_subplot()
    x = history.time / history.wear_time
    for k, beta in enumerate(history.beta_deg):
        ax.plot(x, history.mu[:, k] / history.mu0, marker=".", label=f"{label}beta = {beta:g} deg")
    ax.axhline(1.0, color="0.6", lw=0.8)
    return _finish(
        ax,
        f"t / T_w (T_w = {history.wear_time:.4g} s)",
        "mu / mu0",
        f"Archard wear ({history.wear.surfaces} surfaces wear)",
    )


def wear_figure(history: WearHistory, title: str | None = None) -> Figure:
    fig = new_figure(6.5, 4.5)
    plot_wear(history, ax=fig.add_subplot())
    return _titled(fig, title)


def plot_hierarchy(result: HierarchyResult, *, ax: Axes | None = None, label: str = "") -> Axes:
    """mu_n/mu0 vs the number of levels n, one curve per direction; invalid levels marked x."""
    if ax is None:
        ax = new_figure().add_subplot()
    n = np.arange(result.n_levels + 1)
    for k, beta in enumerate(result.beta_deg):
        x, y = _defined(n, result.mu[:, k] / result.mu0)
        line = ax.plot(x, y, marker="o", ms=3, label=f"{label}beta = {beta:g} deg")[0]
        bad = int(result.first_invalid_level[k])
        if bad:
            ax.plot([bad], [y[-1]], "x", ms=9, color=line.get_color())
    ax.set_xlabel("number of levels n")
    ax.set_ylabel("mu_n / mu0")
    ax.set_yscale("log")
    ax.set_title(f"hierarchy (mu passed upward: {result.mu_passed}; x: invalid)", fontsize=9)
    ax.grid(True, alpha=0.3, which="both")
    ax.legend(fontsize=7)
    readable_log_ticks(ax.figure)
    return ax


def hierarchy_figure(result: HierarchyResult, title: str | None = None) -> Figure:
    fig = new_figure(6.5, 4.5)
    plot_hierarchy(result, ax=fig.add_subplot())
    return _titled(fig, title)


def plot_hierarchy_wear(
    history: HierarchyWearHistory, *, ax: Axes | None = None, beta_index: int = 0
) -> Axes:
    """mu_i/mu0 of every level vs time (log-spaced windows shown on a linear axis of the
    cumulative drop-out index), dotted lines at the drop-out times of Eq 35."""
    if ax is None:
        ax = new_figure().add_subplot()
    # Windows grow geometrically: plot against the window coordinate i - 1 + progress.
    start, tw = history.start_time, history.wear_time
    progress = np.clip((history.time[:, None] - start[None, :]) / tw[None, :], 0.0, 1.0)
    x = progress.sum(axis=1)
    for i in range(1, history.n_levels + 1):
        ax.plot(x, history.mu[:, i, beta_index] / history.mu0, marker=".", label=f"mu_{i}")
    for i in range(1, history.n_levels + 1):
        ax.axvline(i, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("worn levels (level i flat at i; windows T_w,i of Eq 35)")
    beta = history.beta_deg[beta_index]
    ax.set_ylabel("mu_i / mu0")
    ax.set_title(f"hierarchy with wear, beta = {beta:g} deg (innermost level first)", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    return ax


def hierarchy_wear_figure(history: HierarchyWearHistory, title: str | None = None) -> Figure:
    count = history.beta_deg.size
    fig = new_figure(6.0 * min(count, 3), 4.5)
    for k in range(min(count, 3)):
        plot_hierarchy_wear(history, ax=fig.add_subplot(1, min(count, 3), k + 1), beta_index=k)
    return _titled(fig, title)


# --------------------------------------------------------------- figure families 10-14


def fig10_adhesion(cases: dict[str, AdhesionSweep]) -> Figure:
    """Fig 10: mu_a/mu0 and the stretched fraction vs load for each adhesion case."""
    fig = new_figure(12.0, 4.5)
    ax_mu, ax_t = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    for name, sweep in cases.items():
        plot_adhesion_mu(sweep, ax=ax_mu, label=f"{name}, ")
        plot_tensile_fraction(sweep, ax=ax_t, label=f"{name}, ")
    fig.suptitle("Fig 10 family: adhesion (k_t = k_c / 2), load per spring")
    return fig


def fig11_wear(cases: dict[str, WearHistory]) -> Figure:
    """Fig 11: mu/mu0 vs t/T_w for each wear case."""
    fig = new_figure(5.0 * len(cases), 4.2)
    for k, (name, history) in enumerate(cases.items()):
        ax = plot_wear(history, ax=fig.add_subplot(1, len(cases), k + 1))
        ax.set_title(f"{name} ({history.method})", fontsize=9)
    fig.suptitle("Fig 11 family: Archard wear, mu(t) down to mu0 at T_w")
    return fig


def fig12_hierarchy_1d(cases: dict[str, HierarchyResult]) -> Figure:
    """Fig 12: mu_n/mu0 vs n at beta = 0 (left) and 90 deg (right), Eqs 33-34 dotted."""
    from frictionlab.roughness.closed_forms import (
        hierarchy_flat_on_wedge_90deg,
        hierarchy_wedge_on_wedge_90deg,
    )

    fig = new_figure(12.0, 4.8)
    axes = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    for name, result in cases.items():
        n = np.arange(result.n_levels + 1)
        for k, ax in enumerate(axes):
            x, y = _defined(n, result.mu[:, k] / result.mu0)
            ax.plot(x, y, marker="o", ms=3, label=name)
        if name.startswith("sine"):  # the "red curves": Eqs 33-34 at tan(phi) = 2/pi
            phi = float(np.degrees(np.arctan(2.0 / np.pi)))
            closed = (
                hierarchy_flat_on_wedge_90deg if "flat" in name else hierarchy_wedge_on_wedge_90deg
            )
            axes[1].plot(n, closed(result.mu0, phi, n) / result.mu0, "r:", lw=1.2)
    for ax, beta in zip(axes, result.beta_deg[:2], strict=True):
        ax.set_yscale("log")
        ax.set_xlabel("number of levels n")
        ax.set_ylabel("mu_n / mu0")
        ax.set_title(f"beta = {beta:g} deg (red dotted: Eqs 33-34, mean slope)", fontsize=9)
        ax.grid(True, alpha=0.3, which="both")
    axes[1].legend(fontsize=6, ncol=2)
    fig.suptitle("Fig 12 family: 1-D hierarchies (wedges: Eqs 15-16 recursion; sines: lattice)")
    readable_log_ticks(fig)
    return fig


def fig13_hierarchy_2d(cases: dict[str, HierarchyResult]) -> Figure:
    """Fig 13: mu_n/mu0 vs beta for every level count, one panel per surface."""
    fig = new_figure(5.0 * len(cases), 4.2)
    for k, (name, result) in enumerate(cases.items()):
        ax = fig.add_subplot(1, len(cases), k + 1)
        for i in range(result.n_levels + 1):
            x, y = _defined(result.beta_deg, result.mu[i] / result.mu0)
            ax.plot(x, y, marker=".", label=f"n = {i}")
        ax.set_xlabel("beta (deg)")
        ax.set_ylabel("mu_n / mu0")
        ax.set_title(f"lambda = {name.replace('l', '').replace('_', ', ')}", fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Fig 13 family: 2-D hierarchies of sin x sin y levels vs sliding direction")
    return fig


def fig14_hierarchy_wear(history: HierarchyWearHistory) -> Figure:
    """Fig 14: mu_i/mu0 of every level over the life of a worn hierarchy."""
    fig = new_figure(7.0, 4.5)
    plot_hierarchy_wear(history, ax=fig.add_subplot())
    fig.suptitle("Fig 14 family: hierarchy with wear (Eq 35 windows, innermost first)")
    return fig
