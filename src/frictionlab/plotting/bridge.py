"""The bridge's figure: the fitted law's polar over the roughness polar, and the check.

matplotlib is imported inside the functions; figures are pyplot-free
``matplotlib.figure.Figure`` objects.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from frictionlab.plotting.roughness import radial_limits

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from frictionlab.bridge import AnisotropyFit

__all__ = ["bridge_figure"]


def _sorted(deg: np.ndarray, *values: np.ndarray) -> list[np.ndarray]:
    """Directions in [0, 360) in increasing order with the values in the same order."""
    ring = np.mod(np.asarray(deg, dtype=float), 360.0)
    order = np.argsort(ring, kind="stable")
    return [ring[order], *(np.asarray(v)[order] for v in values)]


def _closed(deg: np.ndarray, radius: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    ring, r = _sorted(deg, radius)
    return np.radians(np.append(ring, ring[0] + 360.0)), np.append(r, r[0])


def _components(deg: np.ndarray, vectors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Components along and across the sliding direction of (N, 2) vectors."""
    t = np.radians(np.asarray(deg, dtype=float))
    along = vectors[:, 0] * np.cos(t) + vectors[:, 1] * np.sin(t)
    across = -vectors[:, 0] * np.sin(t) + vectors[:, 1] * np.cos(t)
    return along, across


def bridge_figure(
    fit: AnisotropyFit,
    curve_deg: np.ndarray,
    curve_fit: np.ndarray,
    check_deg: np.ndarray,
    check_closed_form: np.ndarray,
    check_simulated: np.ndarray,
    *,
    velocity: float,
    factor: float,
    title: str | None = None,
) -> Figure:
    """Three panels against the sliding direction beta.

    Left, polar: |mu| of the roughness polar (points) and of the fitted law's kinetic polar
    (line, same units). Middle: the component along the sliding direction minus its mean
    over the circle, which magnifies the anisotropy (the rotation vector makes it differ
    between beta and beta + 180 deg). Right: the component across the sliding direction
    (the lateral force of a non-coaxial law). The middle and right panels also show the
    check: the fitted law's steady polar at ``velocity`` in closed form (dashed, law units,
    ``factor`` x the fitted size at mu_ss(V)) and the driver's simulated steady sliding
    (crosses) at ``check_deg``. ``curve_deg``, ``curve_fit`` (M, 2): a fine curve of the
    fitted kinetic polar.
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(15.0, 4.8), layout="constrained")
    ax_p = fig.add_subplot(1, 3, 1, projection="polar")
    ax_a = fig.add_subplot(1, 3, 2)
    ax_l = fig.add_subplot(1, 3, 3)
    data_mag = np.hypot(fit.data[:, 0], fit.data[:, 1])
    ax_p.plot(np.radians(fit.beta_deg), data_mag, "o", ms=3.5, color="C0", label="roughness")
    t_c, r_c = _closed(curve_deg, np.hypot(curve_fit[:, 0], curve_fit[:, 1]))
    ax_p.plot(t_c, r_c, "-", lw=1.6, color="C1", label="fitted law (kinetic)")
    r_lo, r_hi = radial_limits(np.concatenate([data_mag, r_c]))
    ax_p.set_rlim(r_lo, r_hi)  # type: ignore[attr-defined]
    origin = f" (radial axis from {r_lo:.3g})" if r_lo > 0 else ""
    ax_p.set_title(f"|mu| against the sliding direction{origin}", fontsize=9)
    if r_lo > 0:
        from frictionlab.plotting.roughness import note_radial_origin

        note_radial_origin(ax_p, r_lo, np.concatenate([data_mag, r_c]))
    ax_p.legend(loc="lower left", bbox_to_anchor=(-0.1, -0.16), fontsize=7, ncol=2)

    series = {
        "roughness": (fit.beta_deg, fit.data, "o", "C0"),
        "fitted law (kinetic)": (curve_deg, curve_fit, "-", "C1"),
        f"law at V = {velocity:g} m/s": (check_deg, check_closed_form, "--", "C2"),
        "simulated steady sliding": (check_deg, check_simulated, "x", "C3"),
    }
    for label, (deg, vectors, style, color) in series.items():
        along, across = _components(deg, vectors)
        ring, along_s, across_s = _sorted(deg, along - along.mean(), across)
        kw = {"ms": 4, "lw": 1.0 if style == "--" else 1.6, "color": color, "label": label}
        _line(ax_a, ring, along_s, style, kw)
        _line(ax_l, ring, across_s, style, kw)
    ax_a.set_ylabel("along the sliding direction, minus its mean")
    ax_l.set_ylabel("across the sliding direction (lateral)")
    beta = np.asarray(fit.rotation)
    ax_a.set_title(f"rotation beta = ({beta[0]:.3g}, {beta[1]:.3g}) (roughness units)", fontsize=9)
    scale_note = "" if math.isclose(factor, 1.0) else f"; law = {factor:.4g} x fitted size"
    ax_l.set_title(
        f"e*_1 at {fit.orthotropy_angle_deg:.3g} deg, C_2/C_1 = {fit.orthotropy[1]:.4g}"
        f"{scale_note}",
        fontsize=9,
    )
    for ax in (ax_a, ax_l):
        ax.set_xlabel("sliding direction beta [deg]")
        ax.set_xlim(0.0, 360.0)
        ax.set_xticks(np.arange(0.0, 361.0, 45.0))
        ax.grid(True, alpha=0.3)
        ax.axhline(0.0, color="k", lw=0.5)
    ax_a.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def _line(ax: Axes, x: np.ndarray, y: np.ndarray, style: str, kw: dict[str, object]) -> None:
    if style in ("o", "x"):
        ax.plot(x, y, style, ms=kw["ms"], color=kw["color"], label=kw["label"])
    else:
        ax.plot(x, y, style, lw=kw["lw"], color=kw["color"], label=kw["label"])
