"""Plots of the lattice-spring roughness model: polar mu(beta), surfaces, figure families.

matplotlib is imported inside the functions; figures are ``matplotlib.figure.Figure``
objects (no pyplot state), rendered with the Agg canvas.
"""

from __future__ import annotations

import math
import re
import textwrap
from typing import TYPE_CHECKING, Any

import numpy as np

from frictionlab.plotting.save import figure_png_bytes

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from frictionlab.roughness.families import FamilyTable
    from frictionlab.roughness.lattice import FrictionPolar
    from frictionlab.roughness.surface import Surface

__all__ = [
    "figure_png_bytes",
    "legend_label",
    "new_figure",
    "plot_family_lines",
    "plot_polar",
    "plot_statistics",
    "plot_surface",
    "plot_wavelength_map",
    "radial_limits",
    "scenario_figure",
]


def new_figure(width: float = 6.0, height: float = 4.5) -> Figure:
    """A pyplot-free figure (inches) with constrained layout."""
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


def radial_limits(values: np.ndarray) -> tuple[float, float]:
    """Radial axis limits that show a small anisotropy (not 0 to max).

    With the axis from 0, a 4 % anisotropy draws as a circle. The axis starts below the
    smallest value by half the range (at 0 when the range is large), so the plotted
    radius varies by at least a factor of about 3 between the extremes.
    """
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    if finite.size == 0:
        return 0.0, 1.0
    lo, hi = float(finite.min()), float(finite.max())
    span = hi - lo
    if span <= 1e-12 * max(abs(hi), 1.0):  # isotropic: a circle, +-10 %
        return (0.9 * lo if lo > 0 else 0.0), (1.1 * hi if hi > 0 else 1.0)
    return max(0.0, lo - 0.5 * span), hi + 0.1 * span


def note_radial_origin(ax: Axes, r_lo: float, radius: np.ndarray) -> None:
    """Say on the plot, in red, that the radial axis does not start at 0 and how large the
    spread it magnifies is (a 0.07 % anisotropy otherwise looks like a figure of eight)."""
    hi = float(np.max(radius))
    spread = 100.0 * (hi - float(np.min(radius))) / hi if hi > 0 else 0.0
    ax.text(0.5, -0.1, f"radial axis starts at {r_lo:.4g}, not 0: the spread shown is only "
            f"{spread:.2g} % of the largest value", transform=ax.transAxes, ha="center",
            va="top", fontsize=8, color="C3")  # fmt: skip


def plot_polar(
    polar: FrictionPolar,
    *,
    ax: Axes | None = None,
    normalise: bool = True,
    label: str | None = None,
    requested: np.ndarray | None = None,
) -> Axes:
    """mu(beta) (or mu/mu0) on polar axes spanning the full circle.

    The curve joins the computed directions in angular order and closes when they cover
    the circle. ``requested`` (degrees) marks directions to highlight with dots.
    """
    if ax is None:
        ax = new_figure(5.0, 5.0).add_subplot(projection="polar")
    scale = polar.mu0 if (normalise and polar.mu0 > 0.0) else 1.0
    beta = np.mod(np.asarray(polar.beta_deg, dtype=float), 360.0)
    order = np.argsort(beta, kind="stable")
    theta = np.radians(beta[order])
    radius = np.asarray(polar.mu, dtype=float)[order] / scale
    if theta.size > 1 and (theta[-1] - theta[0]) > np.radians(300.0):
        theta = np.append(theta, theta[0] + 2.0 * math.pi)
        radius = np.append(radius, radius[0])
    ax.plot(theta, radius, "-", lw=1.6, label=label)
    if requested is not None:
        req = np.mod(np.asarray(requested, dtype=float), 360.0)
        sel = np.isin(np.round(beta, 9), np.round(req, 9))
        ax.plot(np.radians(beta[sel]), np.asarray(polar.mu, dtype=float)[sel] / scale, ".", ms=5)
    ax.set_thetalim(0.0, 2.0 * math.pi)  # type: ignore[attr-defined]
    r_lo, r_hi = radial_limits(radius)
    ax.set_rlim(r_lo, r_hi)  # type: ignore[attr-defined]
    name = "mu/mu0" if scale != 1.0 else "mu"
    origin = f"; radial axis from {r_lo:.3g}" if r_lo > 0 else ""
    ax.set_title(
        f"{name} vs sliding direction beta ({polar.settings.mu_definition}{origin})", fontsize=9
    )
    if r_lo > 0:
        note_radial_origin(ax, r_lo, radius)
    return ax


def plot_surface(
    surface: Surface,
    *,
    ax: Axes | None = None,
    points: int = 300,
    title: str | None = None,
    length: float | None = None,
) -> Axes:
    """One period of a surface: a profile line (1-D) or a height image (2-D), in micrometres.

    ``length`` (m) is the x range drawn for a surface without period (flat); default 1 mm.
    """
    if ax is None:
        ax = new_figure(5.0, 3.5).add_subplot()
    lx, ly = surface.periods
    length_x = lx if lx is not None else (length if length is not None else 1e-3)
    if surface.ndim == 1:
        x = (np.arange(points) + 0.5) * length_x / points
        z, _, _ = surface.evaluate(x)
        ax.plot(x * 1e6, z * 1e6, lw=1.2)
        ax.set_xlabel("x (um)")
        ax.set_ylabel("z (um)")
    else:
        assert ly is not None
        x = ((np.arange(points) + 0.5) * length_x / points)[:, None]
        y = ((np.arange(points) + 0.5) * ly / points)[None, :]
        z, _, _ = surface.evaluate(x, y)
        image = ax.imshow(
            z.T * 1e6,
            origin="lower",
            extent=(0.0, length_x * 1e6, 0.0, ly * 1e6),
            aspect="auto",
            cmap="viridis",
        )
        ax.figure.colorbar(image, ax=ax, label="z (um)")
        ax.set_xlabel("x (um)")
        ax.set_ylabel("y (um)")
    ax.set_title(title or f"{surface.kind} (one period)", fontsize=9)
    return ax


def legend_label(case: str) -> str:
    """A readable legend entry for a family case name.

    ``"A"`` .. ``"F"`` (the wedge cases) -> ``"A: flat on symmetric teeth"``;
    ``"l2pi_3pi"`` (wavelengths of a 2-D sinusoid) -> ``"wavelengths 2pi x 3pi"``.
    """
    from frictionlab.roughness.families import CASE_DESCRIPTIONS

    if case in CASE_DESCRIPTIONS:
        return f"{case}: {CASE_DESCRIPTIONS[case]}"
    match = re.fullmatch(r"l([0-9.]+)pi_([0-9.]+)pi", case)
    if match:
        return f"wavelengths {match[1]}pi x {match[2]}pi (x, y)"
    return case


def plot_family_lines(
    table: FamilyTable,
    *,
    prefix: str = "mu_over_mu0_",
    x: str = "beta_deg",
    ax: Axes | None = None,
    ylabel: str = "mu / mu0",
) -> Axes:
    """Every column starting with ``prefix`` against column ``x`` (one line per case)."""
    if ax is None:
        ax = new_figure().add_subplot()
    for name, values in table.columns.items():
        if name.startswith(prefix):
            ax.plot(table[x], values, marker=".", label=legend_label(name[len(prefix) :]))
    ax.set_xlabel("beta (deg)" if x == "beta_deg" else x)
    ax.set_ylabel(ylabel)
    ax.set_title("\n".join(textwrap.wrap(table.description, 80)), fontsize=8)
    ax.grid(True, alpha=0.3)
    # below the axes (constrained layout makes room): the entries never hide a curve
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)
    return ax


def plot_wavelength_map(
    table: FamilyTable, beta_deg: float, *, ax: Axes | None = None, **imshow: Any
) -> Axes:
    """The 5 x 5 mu/mu0 matrix of :func:`~frictionlab.roughness.families.wavelength_map` at beta."""
    from frictionlab.roughness.families import wavelength_matrix

    if ax is None:
        ax = new_figure(4.5, 4.0).add_subplot()
    fx, fy, matrix = wavelength_matrix(table, beta_deg)
    image = ax.imshow(matrix, origin="lower", cmap=imshow.pop("cmap", "magma"), **imshow)
    middle = 0.5 * (np.nanmin(matrix) + np.nanmax(matrix))
    for i in range(fx.size):
        for j in range(fy.size):
            colour = "k" if matrix[i, j] > middle else "w"
            ax.text(j, i, f"{matrix[i, j]:.3f}", ha="center", va="center", fontsize=8, color=colour)
    ax.set_xticks(range(fy.size), [f"{v:g}pi" for v in fy])
    ax.set_yticks(range(fx.size), [f"{v:g}pi" for v in fx])
    ax.set_xlabel("lambda_y")
    ax.set_ylabel("lambda_x")
    ax.set_title(f"mu/mu0 at beta = {beta_deg:g} deg", fontsize=9)
    ax.figure.colorbar(image, ax=ax)
    return ax


def scenario_figure(
    polar: FrictionPolar,
    lower: Surface,
    upper: Surface,
    *,
    requested: np.ndarray | None = None,
    title: str | None = None,
) -> Figure:
    """The CLI figure: polar mu(beta)/mu0 over the full circle, and both surfaces."""
    fig = new_figure(11.0, 5.0)
    grid = fig.add_gridspec(2, 2, width_ratios=(1.3, 1.0))
    plot_polar(polar, ax=fig.add_subplot(grid[:, 0], projection="polar"), requested=requested)
    cell = polar.geometry.cell[0]
    plot_surface(
        lower, ax=fig.add_subplot(grid[0, 1]), title=f"lower (fixed): {lower.kind}", length=cell
    )
    plot_surface(
        upper, ax=fig.add_subplot(grid[1, 1]), title=f"upper (sliding): {upper.kind}", length=cell
    )
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def plot_statistics(stats: Any, title: str | None = None) -> Figure:
    """One figure of a surface's statistics (:mod:`frictionlab.roughness.statistics`):
    PSDs, rms slope against direction, height and slope distributions."""
    fig = new_figure(9.0, 7.0)
    ax_psd = fig.add_subplot(2, 2, 1)
    for pair, label in ((stats.psd_x, "along x"), (stats.psd_y, "along y")):
        if pair is not None and len(pair[0]):
            ax_psd.loglog(pair[0], pair[1], lw=1.2, label=f"1-D, {label} [m^3]")
    if stats.psd_isotropic is not None:
        ax_psd.loglog(*stats.psd_isotropic, lw=1.2, label="2-D isotropic [m^4]")
    ax_psd.set_xlabel("wavevector q [rad/m]")
    ax_psd.set_ylabel("PSD")
    ax_psd.legend(fontsize=7, loc="lower left")
    ax_dir = fig.add_subplot(2, 2, 2, projection="polar")
    theta = np.radians(np.append(stats.theta_deg, stats.theta_deg[:1]))
    ax_dir.plot(theta, np.append(stats.rms_slope_theta, stats.rms_slope_theta[:1]), lw=1.4)
    ax_dir.set_title("rms slope against direction", fontsize=9)
    ax_h = fig.add_subplot(2, 2, 3)
    ax_h.plot(stats.height_bins * 1e6, stats.height_density * 1e-6, lw=1.2)
    ax_h.set_xlabel("height about the mean [um]")
    ax_h.set_ylabel("probability density [1/um]")
    ax_s = fig.add_subplot(2, 2, 4)
    ax_s.plot(stats.slope_bins, stats.slope_density_x, lw=1.2, label="slope along x")
    if stats.slope_density_y is not None:
        ax_s.plot(stats.slope_bins, stats.slope_density_y, lw=1.2, label="slope along y")
    ax_s.set_xlabel("slope [-]")
    ax_s.set_ylabel("probability density")
    ax_s.legend(fontsize=7, loc="upper right")
    if title:
        fig.suptitle(title, fontsize=10)
    return fig
