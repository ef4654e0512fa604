"""Fit the law's anisotropy (orthotropy axes, C_1/C_2, rotation vector) to a friction polar.

The data are friction *vectors* per sliding direction theta: the resisting force per unit
normal load ``(mu_x, mu_y)`` of the lattice-spring model (Eqs 5-9 of Berardo & Pugno 2020), which
for a flat pair is ``mu0 (cos theta, sin theta)`` and in general is not parallel to the
sliding direction. The model is the law's steady traction ratio ``f_t / f_n`` in the same
direction (:mod:`frictionlab.bridge.steady`)::

    tau(theta) = k (rho + h(theta; C, phi)),   h = Q(phi) (C_1^2 d*_1, C_2^2 d*_2) / |C d*|

with the coefficient k of the isotropic part, the orthotropy (C_1, C_2) and its angle phi,
and the rotation vector ``beta = k rho`` (Eqs 84, 95-105). Matching the vectors (two
residuals per direction) uses the lateral force too, which fixes the orthotropy axes even
where the magnitudes alone are nearly round. The fit is
:func:`scipy.optimize.least_squares` (trust-region reflective) from several starting
angles; the orthotropy is normalised to ``C_1 = 1 >= C_2`` (e*_1 is the direction of
largest friction), so that k is the friction coefficient along e*_1 without the
rotation. Pure computation: no I/O.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import least_squares

from frictionlab._arrays import readonly
from frictionlab._frames import TableResult
from frictionlab.bridge.steady import steady_direction
from frictionlab.errors import ParameterError

__all__ = [
    "FIT_GROUPS",
    "AnisotropyFit",
    "DirectionalFriction",
    "fit_anisotropy",
]

FloatArray = NDArray[np.float64]

#: What can be fitted: "orthotropy" (C_2/C_1 and the angle of e*_1) and "rotation" (beta).
FIT_GROUPS: tuple[str, ...] = ("orthotropy", "rotation")
#: Largest angular gap (deg) allowed between neighbouring directions on the circle.
MAX_GAP_DEG = 90.0
#: Bounds of C_2/C_1 while fitting (canonicalised to <= 1 afterwards).
_RATIO_BOUNDS = (1e-3, 1e3)
#: C_2/C_1 this close to 1 is reported as isotropic (C_2 = 1, angle 0: the axes are undefined).
_ISOTROPIC = 1e-9


@dataclass(frozen=True)
class DirectionalFriction:
    """Friction vectors ``(mu_x, mu_y)`` per sliding direction ``beta_deg`` (deg from x).

    The resisting force per unit normal load, contact-frame components (x = e_1). At least
    four directions, no two the same modulo 360, and no gap above 90 degrees on the
    circle: the rotation vector is told apart from the symmetric part by opposite
    directions.
    """

    beta_deg: FloatArray
    mu_x: FloatArray
    mu_y: FloatArray

    def __post_init__(self) -> None:
        arrays = {}
        for name in ("beta_deg", "mu_x", "mu_y"):
            try:
                arr = np.array(getattr(self, name), dtype=np.float64)
            except (TypeError, ValueError):
                raise ParameterError(name, getattr(self, name), "an array of numbers") from None
            if arr.ndim != 1 or not np.all(np.isfinite(arr)):
                raise ParameterError(name, arr, "a 1-D array of finite numbers")
            arrays[name] = arr
        n = arrays["beta_deg"].size
        if arrays["mu_x"].size != n or arrays["mu_y"].size != n:
            raise ParameterError("mu_x, mu_y", (arrays["mu_x"].size, arrays["mu_y"].size),
                                 f"one value per direction ({n})")  # fmt: skip
        if n < 4:
            raise ParameterError("beta_deg", arrays["beta_deg"], "at least 4 directions")
        ring = np.sort(np.mod(arrays["beta_deg"], 360.0))
        gaps = np.diff(np.append(ring, ring[0] + 360.0))
        if np.any(gaps < 1e-9):
            raise ParameterError("beta_deg", arrays["beta_deg"], "distinct directions mod 360")
        if gaps.max() > MAX_GAP_DEG + 1e-9:
            raise ParameterError(
                "beta_deg",
                arrays["beta_deg"],
                f"directions around the full circle, no gap above {MAX_GAP_DEG:g} deg "
                f"(largest gap {gaps.max():g} deg)",
            )
        for name, arr in arrays.items():
            object.__setattr__(self, name, readonly(arr, None))

    @classmethod
    def from_polar(cls, polar: Any) -> DirectionalFriction:
        """From a :class:`~frictionlab.roughness.FrictionPolar` (valid directions only)."""
        ok = np.isfinite(polar.mu_x) & np.isfinite(polar.mu_y)
        ok &= np.asarray(getattr(polar, "valid", ok), dtype=bool)
        return cls(polar.beta_deg[ok], polar.mu_x[ok], polar.mu_y[ok])

    @property
    def vectors(self) -> FloatArray:
        """(N, 2) friction vectors."""
        return np.column_stack([self.mu_x, self.mu_y])


@dataclass(frozen=True, repr=False)
class AnisotropyFit(TableResult):
    """The law's anisotropy fitted to a friction polar (SciPy-style result).

    Attributes
    ----------
    beta_deg, data, fitted:
        Directions (deg), the polar's vectors (N, 2) and the fitted law's kinetic polar
        ``tau`` (N, 2), both in the polar's units.
    misfit:
        (N,) ``|tau - data|`` per direction.
    kinetic:
        k: the fitted coefficient of the isotropic part (along e*_1 when the orthotropy
        is fitted, since then C_1 = 1).
    orthotropy, orthotropy_angle:
        (C_1, C_2) ("divide" convention, Eq 95) and the angle [rad] from e_1 to e*_1,
        in (-pi/2, pi/2]; an isotropic fit (C_2 within 1e-9 of 1) reports (1, 1) and 0.
    rotation:
        beta = k rho in the polar's units; ``relative_rotation`` is rho = beta / k.
    fitted:
        The groups that were fitted (subset of :data:`FIT_GROUPS`); the others held.
    rms_misfit, max_misfit, relative_rms_misfit, beta_at_max_misfit_deg:
        Root mean square and largest misfit over the directions (polar units), the rms
        over the mean data magnitude, and where the largest misfit is.
    lobes:
        Dominant harmonic n of the misfit's component along the sliding direction (n
        lobes around the circle; 0 when the misfit vanishes).
    expressible, note:
        False, with a sentence in ``note``, when the law cannot express the polar: the
        relative rms misfit exceeds ``tolerance``, or the rotation lies outside the
        kinetic polar (friction would oppose sliding in some direction).
    success, message, nfev, cost:
        The solver's outcome for the best start.
    anisotropic_misfit:
        The rms misfit over the rms of the polar's anisotropic part (the data minus its
        circle of mean radial friction): the share of the anisotropy the law leaves
        unexplained (0 for an isotropic polar fitted exactly).
    forward_backward_kept:
        Of the forward/backward difference ``mu(beta) - mu(beta + 180)`` (friction along
        the sliding direction, over the direction pairs present), the share the fitted law
        reproduces (projection ``sum D_fit D / sum D^2``); ``None`` without such pairs or
        difference.
    lateral_misfit, beta_at_lateral_misfit_deg:
        The largest misfit across the sliding direction (a lateral force the fitted law
        adds or misses, polar units) and where it is.
    anisotropy_tolerance:
        The threshold of the three checks above (see :func:`fit_anisotropy`).
    """

    beta_deg: FloatArray
    data: FloatArray
    fitted: FloatArray
    misfit: FloatArray
    kinetic: float
    orthotropy: FloatArray
    orthotropy_angle: float
    rotation: FloatArray
    fitted_groups: tuple[str, ...]
    rms_misfit: float
    max_misfit: float
    relative_rms_misfit: float
    beta_at_max_misfit_deg: float
    lobes: int
    tolerance: float
    expressible: bool
    note: str
    success: bool
    message: str
    nfev: int
    cost: float
    anisotropic_misfit: float = 0.0
    forward_backward_kept: float | None = None
    lateral_misfit: float = 0.0
    beta_at_lateral_misfit_deg: float = 0.0
    anisotropy_tolerance: float = 0.1

    @property
    def orthotropy_angle_deg(self) -> float:
        """The angle of e*_1 from e_1 in degrees."""
        return math.degrees(self.orthotropy_angle)

    @property
    def relative_rotation(self) -> FloatArray:
        """rho = beta / k (dimensionless)."""
        return readonly(self.rotation / self.kinetic, None)

    def columns(self) -> dict[str, np.ndarray]:
        """One row per direction: the polar's vector, the fitted one and the misfit."""
        return {
            "beta_deg": self.beta_deg,
            "data_x": self.data[:, 0],
            "data_y": self.data[:, 1],
            "fitted_x": self.fitted[:, 0],
            "fitted_y": self.fitted[:, 1],
            "misfit": self.misfit,
        }

    def units(self) -> dict[str, str]:
        """Degrees for the direction; the polar's own units (``-``) for the rest."""
        return {k: "deg" if k == "beta_deg" else "-" for k in self.columns()}


def _circle_weights(theta: FloatArray) -> FloatArray:
    """Half the angular gap to each neighbour on the circle (quadrature weights)."""
    order = np.argsort(np.mod(theta, 2 * math.pi))
    ring = np.mod(theta, 2 * math.pi)[order]
    gaps = np.diff(np.append(ring, ring[0] + 2 * math.pi))
    w_sorted = 0.5 * (gaps + np.roll(gaps, 1))
    weights = np.empty_like(theta)
    weights[order] = w_sorted
    return weights


def _wrap_half_turn(angle: float) -> float:
    """The axis angle in (-pi/2, pi/2] (an axis, so angles modulo pi)."""
    a = math.remainder(angle, math.pi)
    return math.pi / 2 if a <= -math.pi / 2 else a


def _lobes(theta: FloatArray, radial: FloatArray) -> int:
    """The dominant harmonic n >= 1 of ``radial(theta)`` by least squares (0 if none)."""
    n_max = max(1, min(8, (theta.size - 1) // 2))
    columns = [np.ones_like(theta)]
    for n in range(1, n_max + 1):
        columns += [np.cos(n * theta), np.sin(n * theta)]
    coef = np.linalg.lstsq(np.column_stack(columns), radial, rcond=None)[0]
    amp = np.hypot(coef[1::2], coef[2::2])
    return int(np.argmax(amp)) + 1 if amp.size and amp.max() > 0 else 0


def fit_anisotropy(
    polar: DirectionalFriction | Any,
    *,
    fit: Sequence[str] = FIT_GROUPS,
    orthotropy: ArrayLike = (1.0, 1.0),
    orthotropy_angle: float = 0.0,
    relative_rotation: ArrayLike = (0.0, 0.0),
    tolerance: float = 0.02,
    anisotropy_tolerance: float = 0.1,
) -> AnisotropyFit:
    """Least-squares fit of the law's steady polar to friction vectors (module docstring).

    Parameters
    ----------
    polar:
        A :class:`DirectionalFriction` or a ``FrictionPolar`` of the lattice model.
    fit:
        Groups to fit: ``"orthotropy"`` (C_2/C_1 and the angle) and/or ``"rotation"``
        (beta). The coefficient k is always fitted.
    orthotropy, orthotropy_angle:
        Held values when the orthotropy is not fitted ((C_1, C_2) "divide"; rad).
    relative_rotation:
        Held rho = beta/k when the rotation is not fitted.
    tolerance:
        Largest relative rms misfit (rms over the mean |mu|) still called expressible.
    anisotropy_tolerance:
        Expressible also needs, where the polar is anisotropic beyond ``tolerance``: at
        most this share of the anisotropic part unexplained, at least ``1 -
        anisotropy_tolerance`` of the forward/backward difference kept (where that
        difference exceeds ``tolerance`` of the mean |mu|), and no lateral misfit above
        ``tolerance`` of the mean |mu| (``docs/bridge.md``).
    """
    data_in = (
        polar if isinstance(polar, DirectionalFriction) else DirectionalFriction.from_polar(polar)
    )
    groups = tuple(fit)
    for g in groups:
        if g not in FIT_GROUPS:
            raise ParameterError("fit", g, "groups among " + ", ".join(FIT_GROUPS))
    if not (isinstance(tolerance, int | float) and 0.0 < tolerance < 1.0):
        raise ParameterError("tolerance", tolerance, "0 < tolerance < 1 (relative rms misfit)")
    if not (isinstance(anisotropy_tolerance, int | float) and 0.0 < anisotropy_tolerance < 1.0):
        raise ParameterError(
            "anisotropy_tolerance", anisotropy_tolerance, "0 < anisotropy_tolerance < 1"
        )
    fit_o, fit_r = "orthotropy" in groups, "rotation" in groups
    C_hold = np.asarray(orthotropy, dtype=np.float64)
    rho_hold = np.asarray(relative_rotation, dtype=np.float64)
    if C_hold.shape != (2,) or not np.all(C_hold > 0) or not np.all(np.isfinite(C_hold)):
        raise ParameterError("orthotropy", orthotropy, "(C_1, C_2), both finite and > 0")
    if rho_hold.shape != (2,) or not np.all(np.isfinite(rho_hold)):
        raise ParameterError("relative_rotation", relative_rotation, "a finite pair")
    phi_hold = float(orthotropy_angle)

    beta_deg = data_in.beta_deg
    theta = np.radians(beta_deg)
    data = data_in.vectors
    magnitude = np.hypot(data[:, 0], data[:, 1])
    if not magnitude.mean() > 0:
        raise ParameterError("mu_x, mu_y", "all zero", "a polar with non-zero friction")

    def unpack(x: FloatArray) -> tuple[float, FloatArray, float, FloatArray]:
        k = float(x[0])
        i = 1
        if fit_o:
            C, phi = np.array([1.0, x[1]]), float(x[2])
            i = 3
        else:
            C, phi = C_hold, phi_hold
        b = np.asarray(x[i : i + 2], dtype=np.float64) if fit_r else k * rho_hold
        return k, C, phi, b

    def model(x: FloatArray) -> FloatArray:
        k, C, phi, b = unpack(x)
        return b + k * steady_direction(beta_deg, C, phi)

    def residuals(x: FloatArray) -> FloatArray:
        return (model(x) - data).ravel()

    # starting values: the weighted mean over the circle is beta exactly for the law's
    # own polar (its symmetric part is odd, h(theta + pi) = -h(theta)); the largest
    # remaining magnitude and its direction give k and e*_1, the smallest C_2.
    weights = _circle_weights(theta)
    b0 = (weights[:, None] * data).sum(axis=0) / weights.sum()
    sym = np.hypot(*(data - (b0 if fit_r else 0.0)).T)
    scale = float(magnitude.mean())
    starts: list[list[float]] = []
    if fit_o:
        k0 = float(sym.max())
        r0 = float(np.clip(sym.min() / k0, 0.05, 1.0)) if k0 > 0 else 1.0
        phi0 = float(theta[int(np.argmax(sym))])
        for j, r in ((0, r0), (1, r0), (2, r0), (3, r0), (0, 0.9)):
            starts.append([k0 if k0 > 0 else scale, r, phi0 + j * math.pi / 4])
    else:
        shape = np.hypot(*(steady_direction(beta_deg, C_hold, phi_hold) + rho_hold).T)
        starts.append([scale / float(shape.mean())])
    if fit_r:
        starts = [s + list(b0) for s in starts]
    lower = [scale * 1e-9] + ([_RATIO_BOUNDS[0], -np.inf] if fit_o else [])
    upper = [np.inf] + ([_RATIO_BOUNDS[1], np.inf] if fit_o else [])
    if fit_r:
        lower += [-np.inf, -np.inf]
        upper += [np.inf, np.inf]
    best = None
    for start in starts:
        x0 = np.clip(start, lower, upper)
        res = least_squares(
            residuals, x0, bounds=(lower, upper), method="trf", x_scale="jac",
            ftol=1e-15, xtol=1e-15, gtol=1e-15, max_nfev=400 * len(x0),
        )  # fmt: skip
        if best is None or res.cost < best.cost:
            best = res
    assert best is not None
    k, C, phi, b = unpack(best.x)
    if fit_o:  # canonical form C_1 = 1 >= C_2: swap the axes when C_2 > 1
        if C[1] > 1.0:
            k, C, phi = k * C[1], np.array([1.0, 1.0 / C[1]]), phi + math.pi / 2
        phi = _wrap_half_turn(phi)
        if C[1] >= 1.0 - _ISOTROPIC:  # round: the axes are undefined, report e*_1 = e_1
            C, phi = np.array([1.0, 1.0]), 0.0
    tau = b + k * steady_direction(beta_deg, C, phi)
    diff = tau - data
    misfit = np.hypot(diff[:, 0], diff[:, 1])
    rms = float(np.sqrt(np.mean(misfit**2)))
    i_max = int(np.argmax(misfit))
    relative = rms / scale
    direction = np.column_stack([np.cos(theta), np.sin(theta)])
    radial = np.sum(diff * direction, axis=1)
    lobes = _lobes(theta, radial) if rms > 1e-12 * scale else 0
    # rho inside the kinetic polar: |(rho*_1/C_1, rho*_2/C_2)| < 1: the rotation must stay
    # inside the kinetic cone, or the plastic dissipation could turn negative
    rho = b / k
    c, s = math.cos(phi), math.sin(phi)
    rho_p = np.array([c * rho[0] + s * rho[1], c * rho[1] - s * rho[0]])
    inside = float(np.hypot(*(rho_p / C))) < 1.0
    notes = []
    if relative > tolerance:
        across = np.column_stack([-np.sin(theta), np.cos(theta)])
        lateral = float(np.sqrt(np.mean(np.sum(diff * across, axis=1) ** 2)))
        where = (
            f"the misfit along the sliding direction has mainly {lobes} "
            f"lobe{'s' if lobes != 1 else ''} around the circle"
            if float(np.sqrt(np.mean(radial**2))) >= lateral
            else "the misfit lies mainly across the sliding direction (in the lateral force)"
        )
        notes.append(
            f"The law cannot express this polar: the rms misfit is {relative:.1%} of the mean "
            f"friction coefficient (tolerance {tolerance:.1%}), largest {misfit[i_max]:.3g} at "
            f"beta = {beta_deg[i_max]:g} deg; {where}, while the law's polar "
            "is an ellipse (two lobes, from the orthotropy C_1/C_2) shifted by the rotation "
            "vector."
        )
    honesty = _honesty(theta, beta_deg, data, tau, weights)
    aniso_rms, aniso_rel, kept, d_rms, lateral, i_lat = honesty
    # each check speaks only when the ones before passed (one reason, not a repetition)
    if not notes and aniso_rms > tolerance * scale and aniso_rel > anisotropy_tolerance:
        notes.append(
            f"The law leaves {aniso_rel:.1%} of the polar's anisotropic part unexplained "
            f"(threshold {anisotropy_tolerance:.0%}; overall rms misfit {relative:.1%} of the "
            "mean friction coefficient): its polar is an ellipse shifted by the rotation "
            "vector, which cannot follow this shape."
        )
    if (
        not notes
        and kept is not None
        and d_rms > tolerance * scale
        and kept < 1.0 - anisotropy_tolerance
    ):
        notes.append(
            f"The fitted law keeps {kept:.0%} of the forward/backward difference "
            f"mu(beta) - mu(beta + 180) (threshold {1.0 - anisotropy_tolerance:.0%}): its only "
            "asymmetry is the constant rotation vector (a cos(beta) difference)."
        )
    if not notes and lateral > tolerance * scale:
        notes.append(
            f"The fitted law is off by a lateral force of {lateral:.3g} (across the sliding "
            f"direction) at beta = {beta_deg[i_lat]:g} deg, above {tolerance:.1%} of the mean "
            "friction coefficient."
        )
    if not inside:
        notes.append(
            "The fitted rotation vector lies outside the law's kinetic polar: friction would "
            "oppose sliding in some direction, which the law does not allow (|beta| < mu_k)."
        )
    return AnisotropyFit(
        beta_deg=readonly(beta_deg, None),
        data=readonly(data, None),
        fitted=readonly(tau, None),
        misfit=readonly(misfit, None),
        kinetic=float(k),
        orthotropy=readonly(np.asarray(C, dtype=np.float64), None),
        orthotropy_angle=float(phi),
        rotation=readonly(np.asarray(b, dtype=np.float64), None),
        fitted_groups=groups,
        rms_misfit=rms,
        max_misfit=float(misfit[i_max]),
        relative_rms_misfit=float(relative),
        beta_at_max_misfit_deg=float(beta_deg[i_max]),
        lobes=lobes,
        tolerance=float(tolerance),
        expressible=not notes,
        note=" ".join(notes),
        success=bool(best.success),
        message=str(best.message),
        nfev=int(best.nfev),
        cost=float(best.cost),
        anisotropic_misfit=float(aniso_rel),
        forward_backward_kept=kept,
        lateral_misfit=float(lateral),
        beta_at_lateral_misfit_deg=float(beta_deg[i_lat]),
        anisotropy_tolerance=float(anisotropy_tolerance),
    )


def _honesty(
    theta: FloatArray, beta_deg: FloatArray, data: FloatArray, tau: FloatArray,
    weights: FloatArray,
) -> tuple[float, float, float | None, float, float, int]:  # fmt: skip
    """What the overall misfit hides: the anisotropic part left unexplained, the share of
    the forward/backward difference kept, and the largest lateral misfit.

    Returns (rms of the data's anisotropic part, rms misfit over it, kept share or None,
    rms forward/backward difference, largest lateral misfit, its index).
    """
    along = np.column_stack([np.cos(theta), np.sin(theta)])
    across = np.column_stack([-np.sin(theta), np.cos(theta)])
    radial = np.sum(data * along, axis=1)
    circle = float(np.sum(weights * radial) / np.sum(weights))  # the isotropic part
    aniso = data - circle * along
    aniso_rms = float(np.sqrt(np.mean(np.sum(aniso**2, axis=1))))
    diff = tau - data
    rms = float(np.sqrt(np.mean(np.sum(diff**2, axis=1))))
    aniso_rel = rms / aniso_rms if aniso_rms > 0.0 else (0.0 if rms == 0.0 else math.inf)
    fitted_radial = np.sum(tau * along, axis=1)
    ring = np.mod(beta_deg, 360.0)
    d_data, d_fit = [], []
    for i, b in enumerate(ring):
        if b >= 180.0:
            continue
        j = np.flatnonzero(np.abs(ring - (b + 180.0)) < 1e-9)
        if j.size:
            d_data.append(radial[i] - radial[j[0]])
            d_fit.append(fitted_radial[i] - fitted_radial[j[0]])
    dd, df = np.array(d_data), np.array(d_fit)
    d_rms = float(np.sqrt(np.mean(dd**2))) if dd.size else 0.0
    kept = float(np.dot(df, dd) / np.dot(dd, dd)) if dd.size and np.dot(dd, dd) > 0 else None
    lateral_all = np.abs(np.sum(diff * across, axis=1))
    i_lat = int(np.argmax(lateral_all))
    return aniso_rms, aniso_rel, kept, d_rms, float(lateral_all[i_lat]), i_lat
