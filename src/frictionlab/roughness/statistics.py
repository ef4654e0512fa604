"""Surface statistics of a sampled surface through SurfaceTopography.

What users of SurfaceTopography and contact.engineering look at first, for the surface
the friction model sees (after preparation, taken as one period):

* power spectral densities: along x and along y (``power_spectrum_from_profile``, the
  1-D PSD averaged over the lines; y through ``transpose``) and the 2-D isotropic one
  (``power_spectrum_from_area``, radially averaged), wavevector q in rad/m, C in m^3
  (1-D) and m^4 (2-D);
* rms slope against direction theta: the rms of the directional derivative
  ``g_x cos(theta) + g_y sin(theta)`` from SurfaceTopography's periodic first
  derivative (the same slopes the friction law reads, up to the difference stencil);
* height and slope distributions: probability densities (histograms) of the heights
  and of the slopes along x and y.

Pure (no I/O): :func:`surface_statistics` returns arrays; the command writes CSV and
:func:`frictionlab.plotting.roughness.plot_statistics` draws one figure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray, readonly
from frictionlab.errors import ParameterError
from frictionlab.roughness.surface import SampledHeightMap, SampledProfile, Surface

__all__ = ["SurfaceStatistics", "surface_statistics"]


@dataclass(frozen=True)
class SurfaceStatistics:
    """Spectra, directional rms slope and distributions of one surface (SI units).

    ``psd_x = (q, C)`` along x; ``psd_y`` and ``psd_isotropic`` are ``None`` for a
    profile. ``theta_deg`` and ``rms_slope_theta``: rms slope along each direction (a
    profile: ``|cos theta|`` times its rms slope). ``height_bins`` / ``height_density``
    (m, 1/m) and ``slope_bins`` / ``slope_density_x``, ``slope_density_y`` (bin centres
    and densities; y is ``None`` for a profile). ``rms_height`` (m), ``rms_slope``
    (sqrt of <g_x^2 + g_y^2>).
    """

    psd_x: tuple[FloatArray, FloatArray]
    psd_y: tuple[FloatArray, FloatArray] | None
    psd_isotropic: tuple[FloatArray, FloatArray] | None
    theta_deg: FloatArray
    rms_slope_theta: FloatArray
    height_bins: FloatArray
    height_density: FloatArray
    slope_bins: FloatArray
    slope_density_x: FloatArray
    slope_density_y: FloatArray | None
    rms_height: float
    rms_slope: float

    def tables(self) -> dict[str, dict[str, np.ndarray]]:
        """Named tables (columns) for CSV files: psd, rms_slope_direction, distributions."""
        psd: dict[str, np.ndarray] = {"q_x_per_m": self.psd_x[0], "psd_x_m3": self.psd_x[1]}
        out: dict[str, dict[str, np.ndarray]] = {"psd_x": psd}
        if self.psd_y is not None:
            out["psd_y"] = {"q_y_per_m": self.psd_y[0], "psd_y_m3": self.psd_y[1]}
        if self.psd_isotropic is not None:
            out["psd_isotropic"] = {
                "q_per_m": self.psd_isotropic[0],
                "psd_isotropic_m4": self.psd_isotropic[1],
            }
        out["rms_slope_direction"] = {
            "theta_deg": self.theta_deg,
            "rms_slope": self.rms_slope_theta,
        }
        out["height_distribution"] = {
            "height_m": self.height_bins,
            "density_per_m": self.height_density,
        }
        slopes: dict[str, np.ndarray] = {
            "slope": self.slope_bins,
            "density_x": self.slope_density_x,
        }
        if self.slope_density_y is not None:
            slopes["density_y"] = self.slope_density_y
        out["slope_distribution"] = slopes
        return out

    def summary(self) -> dict[str, Any]:
        """JSON-ready scalars: rms height, rms slope, its extremes over direction."""
        i_max = int(np.argmax(self.rms_slope_theta))
        i_min = int(np.argmin(self.rms_slope_theta))
        return {
            "rms_height_m": self.rms_height,
            "rms_slope": self.rms_slope,
            "rms_slope_max": float(self.rms_slope_theta[i_max]),
            "rms_slope_max_theta_deg": float(self.theta_deg[i_max]),
            "rms_slope_min": float(self.rms_slope_theta[i_min]),
            "rms_slope_min_theta_deg": float(self.theta_deg[i_min]),
        }


def _topography(surface: SampledProfile | SampledHeightMap) -> Any:
    from SurfaceTopography import Topography, UniformLineScan

    heights = np.array(surface.heights, dtype=np.float64)
    if isinstance(surface, SampledHeightMap):
        return Topography(heights, tuple(surface.physical_sizes), periodic=True, unit="m")
    return UniformLineScan(heights, surface.size, periodic=True, unit="m")


def _pair(result: Any) -> tuple[FloatArray, FloatArray]:
    q, c = result
    keep = np.isfinite(c) & (np.asarray(q) > 0)
    return (
        readonly(np.asarray(q, dtype=np.float64)[keep], None),
        readonly(np.asarray(c, dtype=np.float64)[keep], None),
    )


def _density(values: FloatArray, bins: int) -> tuple[FloatArray, FloatArray]:
    lo, hi = float(values.min()), float(values.max())
    if hi == lo:
        lo, hi = lo - 0.5, hi + 0.5
    density, edges = np.histogram(values, bins=bins, range=(lo, hi), density=True)
    return 0.5 * (edges[1:] + edges[:-1]), density.astype(np.float64)


def surface_statistics(
    surface: Surface,
    *,
    theta_deg: ArrayLike | None = None,
    bins: int = 64,
) -> SurfaceStatistics:
    """Spectra, rms slope against direction and distributions of a sampled surface.

    ``theta_deg``: directions of the rms slope (default 0 to 355 by 5 degrees);
    ``bins``: histogram bins (>= 4).
    """
    if not isinstance(surface, SampledProfile | SampledHeightMap):
        raise ParameterError(
            "surface", getattr(surface, "kind", type(surface).__name__),
            "a sampled surface (a measured or generated map or line scan)",
        )  # fmt: skip
    if isinstance(bins, bool) or not isinstance(bins, int) or bins < 4:
        raise ParameterError("bins", bins, "an integer >= 4")
    theta = np.arange(0.0, 360.0, 5.0) if theta_deg is None else np.array(theta_deg, float)
    if theta.ndim != 1 or theta.size == 0 or not np.all(np.isfinite(theta)):
        raise ParameterError("theta_deg", theta_deg, "a non-empty list of finite degrees")
    topo = _topography(surface)
    heights = np.asarray(topo.heights(), dtype=np.float64)
    is_map = topo.dim == 2
    psd_x = _pair(topo.power_spectrum_from_profile(window="None", reliable=False))
    psd_y = (
        _pair(topo.transpose().power_spectrum_from_profile(window="None", reliable=False))
        if is_map
        else None
    )
    psd_iso = (
        _pair(topo.power_spectrum_from_area(window="None", reliable=False)) if is_map else None
    )
    derivative = topo.derivative(n=1, periodic=True)
    if is_map:
        gx, gy = (np.asarray(d, dtype=np.float64) for d in derivative)
    else:
        gx = np.asarray(derivative, dtype=np.float64)
        gy = np.zeros_like(gx)
    rad = np.radians(theta)
    cxx, cyy, cxy = float(np.mean(gx * gx)), float(np.mean(gy * gy)), float(np.mean(gx * gy))
    slope_theta = np.sqrt(
        np.clip(
            cxx * np.cos(rad) ** 2 + 2.0 * cxy * np.cos(rad) * np.sin(rad)
            + cyy * np.sin(rad) ** 2,
            0.0, None,
        )
    )  # fmt: skip
    hb, hd = _density(heights.ravel() - heights.mean(), bins)
    both = np.concatenate([gx.ravel(), gy.ravel()]) if is_map else gx.ravel()
    lo, hi = float(both.min()), float(both.max())
    span = (lo, hi) if hi > lo else (lo - 0.5, hi + 0.5)
    dx, edges = np.histogram(gx.ravel(), bins=bins, range=span, density=True)
    dy = np.histogram(gy.ravel(), bins=bins, range=span, density=True)[0] if is_map else None
    return SurfaceStatistics(
        psd_x=psd_x,
        psd_y=psd_y,
        psd_isotropic=psd_iso,
        theta_deg=readonly(theta, None),
        rms_slope_theta=readonly(slope_theta, None),
        height_bins=readonly(hb, None),
        height_density=readonly(hd, None),
        slope_bins=readonly(0.5 * (edges[1:] + edges[:-1]), None),
        slope_density_x=readonly(dx.astype(np.float64), None),
        slope_density_y=None if dy is None else readonly(dy.astype(np.float64), None),
        rms_height=float(np.std(heights)),
        rms_slope=math.sqrt(cxx + cyy),
    )
