"""Scale-resolved friction of a measured surface: spectral bands as hierarchy levels.

Beyond the paper. The cutoffs ``c_1 > c_2 > ... > c_k`` (wavelengths, m) split each
sampled surface into ``k + 1`` bands with SurfaceTopography's ``shortcut`` filter
(:func:`~frictionlab.roughness.topography.band_filter`)::

    B_0 = S(c_1)             wavelengths >= c_1 (the outermost band, with the mean)
    B_i = S(c_{i+1}) - S(c_i) c_{i+1} <= wavelength < c_i
    B_k = h - S(c_k)         wavelengths < c_k (the innermost band)

where ``S(c)`` keeps the wavelengths >= c; the bands add up to the heights exactly. A
flat surface gives flat bands. Each band pair (lower, upper) becomes one level of the
hierarchical model (Eq 29: the global coefficient of a level is the
local coefficient of the level above it), innermost = shortest wavelengths::

    mu(retained down to c_i) = f_{B_0}(f_{B_1}(... f_{B_{i-1}}(mu0)))

each ``f`` the full-contact area average of
:mod:`~frictionlab.roughness.full_contact`. Retaining only the
wavelengths >= c_i gives row ``cutoff_m = c_i``; the row with every band retained has
``cutoff_m`` = the Nyquist wavelength (twice the finest pixel spacing). This answers
which scales of a surface make its friction anisotropic. A level where a contact
violates Eq 1's bound marks that row and direction invalid (or, with ``drop=True``, its
invalid contacts are left out as in ``on_invalid="drop"``).

Pure physics: no I/O.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frictionlab._arrays import FloatArray, readonly
from frictionlab._frames import TableResult
from frictionlab.errors import ParameterError
from frictionlab.roughness.full_contact import full_contact_sums
from frictionlab.roughness.generators import from_array
from frictionlab.roughness.lattice import _cos_sin_deg, check_betas, lattice_geometry
from frictionlab.roughness.surface import SampledHeightMap, SampledProfile, Surface
from frictionlab.roughness.topography import band_filter, resolvable_range

__all__ = [
    "MU_PASSED",
    "MultiscaleResult",
    "band_surfaces",
    "bands_hierarchy",
    "multiscale_friction",
]

MU_PASSED = ("magnitude", "projection")


def band_surfaces(surface: Surface, cutoffs: Sequence[float]) -> list[Surface]:
    """The ``len(cutoffs) + 1`` bands of a sampled surface, outermost (longest) first.

    ``cutoffs``: wavelengths (m), strictly decreasing. A flat surface gives flat bands;
    other analytic surfaces cannot be filtered (ParameterError).
    """
    values = [float(c) for c in cutoffs]
    if not values or any(not (c > 0.0 and math.isfinite(c)) for c in values):
        raise ParameterError("cutoffs", values, "wavelengths > 0 m")
    if any(b >= a for a, b in itertools.pairwise(values)):
        raise ParameterError("cutoffs", values, "strictly decreasing wavelengths")
    if surface.is_flat:
        return [surface] * (len(values) + 1)
    if not isinstance(surface, SampledProfile | SampledHeightMap):
        raise ParameterError(
            "surface", surface.kind, "a sampled (measured or generated) surface, or a flat one"
        )
    heights = np.asarray(surface.heights, dtype=np.float64)
    if isinstance(surface, SampledHeightMap):
        sizes: list[float] = list(surface.physical_sizes)
    else:
        sizes = [surface.size]
    lo, hi = resolvable_range(sizes, heights.shape)
    outside = [c for c in values if not (lo <= c <= hi)]
    if outside:
        raise ParameterError(
            "cutoffs",
            values,
            f"wavelengths in the surface's resolvable range {lo:.4g} m (twice the pixel) to "
            f"{hi:.4g} m (the period); {outside} lie outside it (their bands would be empty)",
        )
    kept = [band_filter(heights, sizes, c, None) for c in values]  # S(c_1), ..., S(c_k)
    parts = [kept[0]]
    parts += [kept[i + 1] - kept[i] for i in range(len(values) - 1)]
    parts.append(heights - kept[-1])
    return [
        from_array(p, sizes if heights.ndim == 2 else sizes[0], gradient=surface.gradient)
        for p in parts
    ]


def _gradients(lower: Surface, upper: Surface) -> tuple[tuple[FloatArray, FloatArray], ...]:
    geometry = lattice_geometry(lower, upper)
    xs, ys = geometry.station_coordinates()
    _, g1x, g1y = (np.ascontiguousarray(a).ravel() for a in lower.evaluate(xs, ys))
    _, g2x, g2y = (np.ascontiguousarray(a).ravel() for a in upper.evaluate(xs, ys))
    n = geometry.n_stations
    return (np.broadcast_to(g1x, n), np.broadcast_to(g1y, n)), (
        np.broadcast_to(g2x, n),
        np.broadcast_to(g2y, n),
    )


def bands_hierarchy(
    levels: Sequence[tuple[Surface, Surface]],
    mu0: float,
    beta_deg: ArrayLike,
    *,
    mu_passed: str = "magnitude",
    drop: bool = False,
    engine: str = "numba",
) -> tuple[FloatArray, FloatArray, FloatArray, NDArray[np.bool_]]:
    """Full-contact hierarchy of surface pairs, innermost first (Eq 29 recursion).

    Every level is the area average of the multipliers with the local coefficient of
    the level below, per direction, all directions in one pass per level. Returns
    ``(mu, mu_x, mu_y, valid)`` of the outermost level per direction; a direction where
    a level violates Eq 1 (``drop=False``) is invalid (NaN) from there on.
    """
    if mu_passed not in MU_PASSED:
        raise ParameterError("mu_passed", mu_passed, f"one of {MU_PASSED}")
    betas = check_betas(beta_deg)
    cs = np.array([_cos_sin_deg(float(b)) for b in betas])  # exact at multiples of 90 deg
    cb, sb = cs[:, 0], cs[:, 1]
    mu = np.full(betas.size, float(mu0))
    mu_x, mu_y = mu * cb, mu * sb
    valid = np.ones(betas.size, dtype=bool)
    for lower, upper in levels:
        if lower.is_flat and upper.is_flat:  # a flat level passes mu through exactly
            mu_x, mu_y = mu * cb, mu * sb
            continue
        g1, g2 = _gradients(lower, upper)
        sums = full_contact_sums(np.where(valid, mu, 0.0), g1, g2, cb, sb, drop=drop, engine=engine)
        valid &= drop | (sums.invalid == 0)
        mu_x = np.where(valid, sums.mu_x, np.nan)
        mu_y = np.where(valid, sums.mu_y, np.nan)
        mu = np.hypot(mu_x, mu_y) if mu_passed == "magnitude" else mu_x * cb + mu_y * sb
    return mu, mu_x, mu_y, valid


@dataclass(frozen=True, repr=False)
class MultiscaleResult(TableResult):
    """mu(beta) against the shortest wavelength retained.

    ``cutoff_m`` (rows, descending): the shortest wavelength retained, the last row the
    Nyquist wavelength (all bands); ``mu``, ``mu_x``, ``mu_y``, ``valid``: (rows,
    directions); ``band_rms_slope``: rms slope of each band (outermost first, the larger
    of the two surfaces); ``mu0`` the local coefficient at the finest retained scale.
    """

    cutoff_m: FloatArray
    beta_deg: FloatArray
    mu: FloatArray
    mu_x: FloatArray
    mu_y: FloatArray
    valid: NDArray[np.bool_]
    band_rms_slope: FloatArray
    mu0: float
    mu_passed: str

    def columns(self) -> dict[str, np.ndarray]:
        """Long table: one row per (cutoff, direction); invalid values masked."""
        rows, nd = self.mu.shape
        mu = np.ma.masked_invalid(self.mu.ravel())
        return {
            "cutoff_m": np.repeat(self.cutoff_m, nd),
            "beta_deg": np.tile(self.beta_deg, rows),
            "mu": mu,
            "mu_over_mu0": mu / self.mu0,
            "valid": self.valid.ravel(),
        }

    @staticmethod
    def units() -> dict[str, str]:
        return {"cutoff_m": "m", "beta_deg": "deg"}


def _nyquist(surface: Surface) -> float:
    if isinstance(surface, SampledHeightMap):
        return 2.0 * min(
            s / n for s, n in zip(surface.physical_sizes, surface.heights.shape, strict=True)
        )
    if isinstance(surface, SampledProfile):
        return 2.0 * surface.size / surface.heights.size
    return math.inf


def multiscale_friction(
    lower: Surface,
    upper: Surface,
    mu0: float,
    beta_deg: ArrayLike,
    cutoffs: Sequence[float],
    *,
    mu_passed: str = "magnitude",
    drop: bool = False,
    engine: str = "numba",
) -> MultiscaleResult:
    """mu(beta) of the bands of two surfaces retained down to each cutoff (module docstring)."""
    if not (isinstance(mu0, int | float) and math.isfinite(mu0) and mu0 > 0.0):
        raise ParameterError("mu0", mu0, "a finite local coefficient > 0")
    betas = check_betas(beta_deg)
    values = sorted((float(c) for c in cutoffs), reverse=True)
    low = band_surfaces(lower, values)
    up = band_surfaces(upper, values)
    pairs = list(zip(low, up, strict=True))  # outermost first
    rows = len(values) + 1
    out = np.zeros((3, rows, betas.size))
    valid = np.zeros((rows, betas.size), dtype=bool)
    for r in range(rows):
        retained = pairs[: r + 1]  # B_0 .. B_r
        mu, mx, my, ok = bands_hierarchy(
            retained[::-1], mu0, betas, mu_passed=mu_passed, drop=drop, engine=engine
        )
        out[0, r], out[1, r], out[2, r] = mu, mx, my
        valid[r] = ok
    nyquist = min(_nyquist(lower), _nyquist(upper))
    slopes = np.array(
        [
            max(float(s.parameters().get("rms_slope", 0.0)) for s in pair if not s.is_flat)
            if not all(s.is_flat for s in pair)
            else 0.0
            for pair in pairs
        ]
    )
    return MultiscaleResult(
        cutoff_m=readonly(np.array([*values, nyquist]), None),
        beta_deg=readonly(betas, None),
        mu=readonly(out[0], None),
        mu_x=readonly(out[1], None),
        mu_y=readonly(out[2], None),
        valid=readonly(valid, None),
        band_rms_slope=readonly(slopes, None),
        mu0=float(mu0),
        mu_passed=mu_passed,
    )
