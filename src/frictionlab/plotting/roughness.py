"""Plots of the lattice-spring roughness model: polar mu(beta), surfaces, figure families.

matplotlib is imported inside the functions; figures are ``matplotlib.figure.Figure``
objects (no pyplot state), rendered with the Agg canvas.
"""

from __future__ import annotations

import math
import re
import textwrap
from collections.abc import Mapping, Sequence
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
    "mirrored_scans",
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
    scan: Sequence[float] | None = None,
) -> Axes:
    """A surface as a profile line (1-D) or a height image (2-D) at equal aspect, lengths in
    the unit of their span (m, mm, um or nm).

    A sampled surface is drawn from its samples (one pixel per sample), an analytic one
    evaluated on ``points`` per axis over one period. ``length`` (m) is the x range drawn
    for a surface without period (flat); default 1 mm. ``scan`` (m, one size per axis)
    draws only that part from the origin: for a measured map made periodic by mirroring
    (:func:`~frictionlab.roughness.topography.prepare_topography`'s ``scan_sizes_m``), the
    scan itself instead of its mirrored double. A 2-D image whose sides differ by more
    than :data:`MAX_STRETCH` is stretched to fit and its title says so.
    """
    from frictionlab.plotting.units import length_unit
    from frictionlab.roughness.surface import SampledHeightMap, SampledProfile

    if ax is None:
        ax = new_figure(5.0, 3.5).add_subplot()
    lx, ly = surface.periods
    length_x = lx if lx is not None else (length if length is not None else 1e-3)
    length_y = ly
    if scan is not None:
        length_x = min(float(scan[0]), length_x)
        if length_y is not None and len(scan) > 1:
            length_y = min(float(scan[1]), length_y)
    heading = title or f"{surface.kind} (one period)"
    if surface.ndim == 1:
        if isinstance(surface, SampledProfile):
            n = max(1, round(length_x / surface.size * surface.heights.size))
            x = (np.arange(n) + 0.5) * surface.size / surface.heights.size
            z = np.asarray(surface.heights[:n])
        else:
            x = (np.arange(points) + 0.5) * length_x / points
            z = np.asarray(surface.evaluate(x)[0])
        (xu, xs) = length_unit(0.0, length_x)
        (zu, zs) = length_unit(z.min(), z.max()) if np.ptp(z) > 0 else (xu, xs)
        ax.plot(x / xs, z / zs, lw=1.2)
        ax.set_xlabel(f"x [{xu}]")
        ax.set_ylabel(f"z [{zu}]")
    else:
        assert length_y is not None
        width, height = float(length_x), float(length_y)
        if isinstance(surface, SampledHeightMap):
            nx, ny = surface.heights.shape
            cx = max(1, round(width / surface.sizes[0] * nx))
            cy = max(1, round(height / surface.sizes[1] * ny))
            z = np.asarray(surface.heights[:cx, :cy])
            width, height = cx * surface.sizes[0] / nx, cy * surface.sizes[1] / ny
        else:
            x = ((np.arange(points) + 0.5) * width / points)[:, None]
            y = ((np.arange(points) + 0.5) * height / points)[None, :]
            z = np.asarray(surface.evaluate(x, y)[0])
        unit, scale = length_unit(0.0, max(width, height))
        z_unit, z_scale = length_unit(float(z.min()), float(z.max()))
        stretch = max(width, height) / min(width, height)
        image = ax.imshow(
            z.T / z_scale,
            origin="lower",
            extent=(0.0, width / scale, 0.0, height / scale),
            aspect="equal" if stretch <= MAX_STRETCH else "auto",
            interpolation="nearest",
            cmap="viridis",
        )
        ax.figure.colorbar(image, ax=ax, label=f"z [{z_unit}]")
        ax.set_xlabel(f"x [{unit}]")
        ax.set_ylabel(f"y [{unit}]")
        if stretch > MAX_STRETCH:
            heading += f" (not to scale: y stretched {width / height:.3g} x)"
    ax.set_title(heading, fontsize=9)
    return ax


#: Largest side ratio of a height image drawn at equal aspect.
MAX_STRETCH = 10.0


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
    scans: Mapping[str, Sequence[float]] | None = None,
) -> Figure:
    """The CLI figure: polar mu(beta)/mu0 over the full circle, and both surfaces.

    ``scans``: per side (``"lower"``, ``"upper"``) the sizes (m) of a measured scan that
    was mirrored to make it periodic; that side is drawn as the scan, not the double.
    """
    fig = new_figure(11.0, 5.0)
    grid = fig.add_gridspec(2, 2, width_ratios=(1.3, 1.0))
    plot_polar(polar, ax=fig.add_subplot(grid[:, 0], projection="polar"), requested=requested)
    cell = polar.geometry.cell[0]
    scans = scans or {}
    for row, (side, role, surface) in enumerate(
        (("lower", "fixed", lower), ("upper", "sliding", upper))
    ):
        scan = scans.get(side)
        heading = f"{side} ({role}): {surface.kind}"
        if scan is not None:
            heading += "\nthe scan (mirrored for the model)"
        plot_surface(
            surface, ax=fig.add_subplot(grid[row, 1]), title=heading, length=cell, scan=scan
        )
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def mirrored_scans(sources: Mapping[str, Mapping[str, Any]]) -> dict[str, list[float]]:
    """Per side, the scan sizes (m) of the measured surfaces that were mirrored (from the
    preparation records of :func:`~frictionlab.roughness.topography.prepare_topography`)."""
    return {
        side: list(info["scan_sizes_m"])
        for side, info in sources.items()
        if info.get("periodicity") == "mirror" and "scan_sizes_m" in info
    }


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
