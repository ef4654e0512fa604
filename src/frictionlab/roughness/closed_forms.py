"""Closed forms of the lattice-spring model: force multipliers, validity bound, wedge formulas.

Angles: functions whose arguments end in ``_deg`` take degrees, the others radians.
Every function refuses points outside the model's validity domain with
a :class:`~frictionlab.errors.ValidityError` naming the angle, the direction and the
bound; none returns an infinite or negative force.

Contents
--------
* :func:`h_local`: Eqs 2-3, multipliers (H_x, H_y) in the local frame of a contact;
* :func:`normal_force_factor`: Eq 1, N / (k u);
* :func:`max_mu0`: the validity bound of Eq 1 (general form; cot(phi) at beta = 0);
* :func:`h_global`: the frame-free global multiplier (the default);
* :func:`h_rotated`: Eqs 1-4 with the corrected rotation (counter-clockwise alpha), kept
  for cross-checks;
* :func:`wedge_face_weights`: the horizontal-share weights of Eq 14;
* :func:`wedge_friction`: Eqs 15-16, (mu_x, mu_y) of two wedge profiles at any beta;
* :func:`flat_on_wedge_0deg`, :func:`flat_on_wedge_90deg`, :func:`wedge_on_wedge_0deg`,
  :func:`wedge_on_wedge_90deg`: Eqs 17-20;
* :func:`singular_angle_deg`: phi* = arctan(1/mu0), where Eqs 17 and 19 diverge;
* :func:`hierarchy_flat_on_wedge_90deg`, :func:`hierarchy_wedge_on_wedge_90deg`: Eqs 33-34,
  mu_n of n self-similar levels of symmetric wedges at beta = 90 deg.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray
from frictionlab.errors import ParameterError, ValidityError

__all__ = [
    "flat_on_wedge_0deg",
    "flat_on_wedge_90deg",
    "h_global",
    "h_local",
    "h_rotated",
    "hierarchy_flat_on_wedge_90deg",
    "hierarchy_wedge_on_wedge_90deg",
    "max_mu0",
    "normal_force_factor",
    "singular_angle_deg",
    "wedge_face_weights",
    "wedge_friction",
    "wedge_on_wedge_0deg",
    "wedge_on_wedge_90deg",
]


def _check_mu0(mu0: float) -> float:
    try:
        value = float(mu0)
    except (TypeError, ValueError):
        raise ParameterError("mu0", mu0, "a finite number >= 0") from None
    if not (math.isfinite(value) and value >= 0.0):
        raise ParameterError("mu0", mu0, "a finite number >= 0")
    return value


def _finite(name: str, values: ArrayLike, allowed: str) -> FloatArray:
    """``values`` as a float64 array of finite numbers (any shape), else ParameterError."""
    try:
        arr = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError(name, values, allowed) from None
    if not np.all(np.isfinite(arr)):
        raise ParameterError(name, float(arr[~np.isfinite(arr)].ravel()[0]), allowed)
    return arr


def _slopes(gx: ArrayLike, gy: ArrayLike, beta: ArrayLike) -> tuple[FloatArray, ...]:
    """Gradients and direction (rad) checked finite and broadcast together."""
    return tuple(
        np.broadcast_arrays(
            _finite("gx", gx, "finite slopes"),
            _finite("gy", gy, "finite slopes"),
            _finite("beta", beta, "finite angles (rad)"),
        )
    )


def _check_phi(phi: ArrayLike, signed: bool) -> FloatArray:
    try:
        arr = np.asarray(phi, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError("phi", phi, "numbers (rad)") from None
    low = -0.5 * math.pi if signed else 0.0
    ok = np.isfinite(arr) & (arr > low if signed else arr >= low) & (arr < 0.5 * math.pi)
    if not np.all(ok):
        bad = float(arr[~ok].ravel()[0]) if arr.ndim else float(arr)
        allowed = "-pi/2 < phi < pi/2 (rad)" if signed else "0 <= phi < pi/2 (rad)"
        raise ParameterError("phi", bad, allowed)
    return arr


def _local_denominator(mu0: float, phi: FloatArray, beta: FloatArray) -> FloatArray:
    """cos(phi) S - mu0 tan(phi) cos(beta), S = sqrt(1 + tan^2(phi) cos^2(beta)) (Eqs 1-3)."""
    t = np.tan(phi)
    cb = np.cos(beta)
    s = np.sqrt(1.0 + (t * cb) ** 2)
    return np.cos(phi) * s - mu0 * t * cb


def _raise_invalid(
    mu0: float, phi: FloatArray, beta: FloatArray, den: FloatArray, what: str
) -> None:
    bad = ~(den > 0.0)
    if not np.any(bad):
        return
    phi_b, beta_b = np.broadcast_arrays(phi, beta)
    k = int(np.flatnonzero(np.ravel(bad))[0])
    p = float(np.ravel(phi_b)[k])
    b = float(np.ravel(beta_b)[k])
    bound = float(max_mu0(p, b))
    raise ValidityError(
        f"{what}: mu0 = {mu0:g} violates the contact condition of Eq 1 at phi = "
        f"{math.degrees(p):.6g} deg, beta = {math.degrees(b):.6g} deg: allowed mu0 < "
        f"{bound:.6g} (cot(phi) sqrt(cos^2(phi)/cos^2(beta) + sin^2(phi)); at beta = 0 "
        f"mu0 < cot(phi)). {int(np.count_nonzero(bad))} point(s) invalid."
    )


def max_mu0(phi: ArrayLike, beta: ArrayLike) -> FloatArray:
    """Largest admissible local coefficient at a contact (Eq 1 validity).

    ``mu0 < cot(phi) sqrt(cos^2(phi)/cos^2(beta) + sin^2(phi))`` when ``tan(phi) cos(beta)
    > 0`` (rising contact); ``inf`` otherwise (descending or flat contact: no restriction).
    At beta = 0 the bound is ``cot(phi)``. ``phi`` (signed) and ``beta`` (local) in rad.
    """
    p = _finite("phi", phi, "finite angles (rad)")
    b = _finite("beta", beta, "finite angles (rad)")
    a = np.tan(p) * np.cos(b)
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = np.cos(p) * np.sqrt(1.0 + a * a) / a
    return np.asarray(np.where(a > 1e-300, bound, np.inf), dtype=np.float64)


def normal_force_factor(mu0: float, phi: ArrayLike, beta: ArrayLike) -> FloatArray:
    """Eq 1: N / (k u), the normal force on the tangent plane per unit spring force.

    ``phi`` is the signed tilt of the tangent plane, ``beta`` the local sliding
    direction (rad).
    """
    m = _check_mu0(mu0)
    p = _check_phi(phi, signed=True)
    b = _finite("beta", beta, "finite angles (rad)")
    den = _local_denominator(m, p, b)
    _raise_invalid(m, p, b, den, "normal_force_factor")
    s = np.sqrt(1.0 + (np.tan(p) * np.cos(b)) ** 2)
    return np.asarray(s / den, dtype=np.float64)


def h_local(mu0: float, phi: ArrayLike, beta: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Eqs 2-3: the multipliers (H_x, H_y) with F_x' = F_z H_x and F_y' = F_z H_y.

    ``phi``: signed tilt of the tangent plane about y' (rad, |phi| < pi/2); ``beta``:
    sliding direction measured from x' (rad). (F_x', F_y') is the resisting force, i.e.
    minus the horizontal force on the upper body, in local axes. In 1-D ``phi =
    arctan f'(x)`` and ``beta`` is global (Eqs 10-13).
    """
    m = _check_mu0(mu0)
    p = _check_phi(phi, signed=True)
    b = _finite("beta", beta, "finite angles (rad)")
    den = _local_denominator(m, p, b)
    _raise_invalid(m, p, b, den, "h_local")
    t = np.tan(p)
    s = np.sqrt(1.0 + (t * np.cos(b)) ** 2)
    hx = (np.sin(p) * s + m * np.cos(b)) / den  # Eq 2
    hy = m * np.sin(b) / den  # Eq 3
    return np.asarray(hx, dtype=np.float64), np.asarray(hy, dtype=np.float64)


def h_global(
    mu0: float, gx: ArrayLike, gy: ArrayLike, beta: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    """Frame-free global multiplier H(mu0, g, beta) (equivalent to Eqs 1-4).

    ``n = (-g_x, -g_y, 1)/|.|``, ``t = (cos b, sin b, g_x cos b + g_y sin b)/|.|``,
    ``N = 1/(n_z - mu0 t_z)`` (must be > 0), ``F = N (n - mu0 t)``, ``H = (-F_x, -F_y)``.
    ``g`` is the gradient of the contacted surface (dimensionless); ``beta`` the global
    sliding direction (rad). Returns (H_x, H_y) in global axes per unit F_z.
    """
    m = _check_mu0(mu0)
    gxa, gya, b = _slopes(gx, gy, beta)
    cb, sb = np.cos(b), np.sin(b)
    inv_n = 1.0 / np.sqrt(1.0 + gxa**2 + gya**2)
    a = gxa * cb + gya * sb
    inv_t = 1.0 / np.sqrt(1.0 + a * a)
    den = inv_n - m * a * inv_t
    if not np.all(den > 0.0):
        phi = np.arctan(np.hypot(gxa, gya))
        alpha = np.arctan2(gya, gxa)
        _raise_invalid(m, phi, b - alpha, den, "h_global")
    big_n = 1.0 / den
    hx = big_n * (gxa * inv_n + m * cb * inv_t)
    hy = big_n * (gya * inv_n + m * sb * inv_t)
    return np.asarray(hx, dtype=np.float64), np.asarray(hy, dtype=np.float64)


def h_rotated(
    mu0: float, gx: ArrayLike, gy: ArrayLike, beta: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    """Eqs 1-4 in the local frame with the corrected rotation (Eq 4).

    ``alpha = atan2(g_y, g_x)`` (counter-clockwise), ``phi = arctan|g|``, ``beta' = beta -
    alpha``; ``(X', Y') = (H_x, H_y)(mu0, phi, beta')`` (Eqs 2-3) rotated back by
    ``[[cos a, -sin a], [sin a, cos a]]``. Equal to :func:`h_global` to rounding; kept as
    an independent cross-check.
    """
    gxa, gya, b = _slopes(gx, gy, beta)
    alpha = np.arctan2(gya, gxa)
    phi = np.arctan(np.hypot(gxa, gya))
    hx_l, hy_l = h_local(mu0, phi, b - alpha)
    ca, sa = np.cos(alpha), np.sin(alpha)
    return ca * hx_l - sa * hy_l, sa * hx_l + ca * hy_l  # Eq 4 (counter-clockwise alpha)


def _face_weights(rise_deg: FloatArray, fall_deg: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Vectorised Eq 14 weights; (1/2, 1/2) where both angles are 0 (flat)."""
    rise, fall = np.broadcast_arrays(rise_deg, fall_deg)
    ok = np.isfinite(rise) & np.isfinite(fall)
    ok &= (rise >= 0.0) & (rise < 90.0) & (fall >= 0.0) & (fall < 90.0)
    flat = (rise == 0.0) & (fall == 0.0)
    half = (rise == 0.0) ^ (fall == 0.0)
    for bad, allowed in ((~ok, "0 <= angle < 90 degrees"), (half, "both faces > 0 or both 0")):
        if np.any(bad):
            k = int(np.flatnonzero(np.ravel(bad))[0])
            pair = (float(np.ravel(rise)[k]), float(np.ravel(fall)[k]))
            raise ParameterError("angles_deg", pair, allowed)
    t1 = np.tan(np.radians(rise))
    t2 = np.tan(np.radians(fall))
    with np.errstate(invalid="ignore", divide="ignore"):
        w_rise = np.where(flat, 0.5, t2 / (t1 + t2))
        w_fall = np.where(flat, 0.5, t1 / (t1 + t2))
    return w_rise, w_fall


def wedge_face_weights(rise_deg: float, fall_deg: float) -> tuple[float, float]:
    """Eq 14 weights: the horizontal shares psi/(1+psi) and 1/(1+psi) of the two faces.

    ``psi = tan(fall)/tan(rise)``. A flat surface (both angles 0) gives (1/2, 1/2).
    Angles in degrees, in [0, 90); exactly one zero angle is not a wedge.
    """
    try:
        r, f = float(rise_deg), float(fall_deg)
    except (TypeError, ValueError):
        raise ParameterError("angles_deg", (rise_deg, fall_deg), "two angles in degrees") from None
    w_rise, w_fall = _face_weights(np.asarray(r), np.asarray(f))
    return float(w_rise), float(w_fall)


def wedge_friction(
    mu0: float, angles_deg: ArrayLike, beta_deg: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    """Eqs 15-16: (mu_x, mu_y) of two 1-D wedge (saw-tooth) profiles at sliding direction beta.

    ``angles_deg = (phi1, phi2, phi3, phi4)``: lower surface rising/falling, upper surface
    rising/falling, in degrees; ``phi3 = phi4 = 0`` is a flat upper surface (and
    ``phi1 = phi2 = 0`` a flat lower one). Each face contributes its multiplier
    ``H(mu0, +phi_rise)`` or ``H(mu0, -phi_fall)`` with its Eq 14 weight, half from each
    family. Exact for any load and any beta; at beta = 90 deg it is
    the static value, also exact for wedges. Vectorised: ``angles_deg`` may have shape
    (..., 4), broadcast against ``beta_deg``.
    """
    m = _check_mu0(mu0)
    angles = _finite("angles_deg", angles_deg, "four angles (phi1, phi2, phi3, phi4)")
    if angles.ndim == 0 or angles.shape[-1] != 4:
        raise ParameterError("angles_deg", angles_deg, "four angles (phi1, phi2, phi3, phi4)")
    beta = np.radians(_finite("beta_deg", beta_deg, "finite degrees"))
    shape = np.broadcast_shapes(angles.shape[:-1], beta.shape)
    mu_x = np.zeros(shape)
    mu_y = np.zeros(shape)
    for rise, fall in ((angles[..., 0], angles[..., 1]), (angles[..., 2], angles[..., 3])):
        w_rise, w_fall = _face_weights(rise, fall)
        for weight, phi in ((w_rise, rise), (w_fall, -fall)):
            hx, hy = h_local(m, np.broadcast_to(np.radians(phi), shape), beta)
            mu_x += 0.5 * weight * hx  # Eq 15
            mu_y += 0.5 * weight * hy  # Eq 16
    return mu_x, mu_y


def _sin2(phi_deg: ArrayLike) -> FloatArray:
    p = _finite("phi_deg", phi_deg, "0 <= phi < 90 degrees")
    if not np.all(np.isfinite(p) & (p >= 0.0) & (p < 90.0)):
        raise ParameterError("phi_deg", phi_deg, "0 <= phi < 90 degrees")
    return np.asarray(np.sin(np.radians(p)) ** 2, dtype=np.float64)


def _beta0_denominator(mu0: float, phi_deg: ArrayLike, what: str) -> FloatArray:
    s2 = _sin2(phi_deg)
    den = 1.0 - s2 * (1.0 + mu0 * mu0)
    if not np.all(den > 0.0):
        bad = float(
            np.ravel(np.broadcast_to(np.asarray(phi_deg, dtype=float), den.shape))[
                int(np.flatnonzero(~(np.ravel(den) > 0.0))[0])
            ]
        )
        raise ValidityError(
            f"{what}: mu0 = {mu0:g} at phi = {bad:g} deg is beyond the singular angle "
            f"phi* = arctan(1/mu0) = {singular_angle_deg(mu0):.6g} deg: allowed mu0 < cot(phi)"
        )
    return den


def flat_on_wedge_0deg(mu0: float, phi_deg: ArrayLike) -> FloatArray:
    """Eq 17: mu_x of a flat surface on a symmetric wedge, beta = 0.

    ``mu0 [2 - sin^2(phi)(1+mu0^2)] / (2 [1 - sin^2(phi)(1+mu0^2)])``; valid for mu0 < cot(phi).
    """
    m = _check_mu0(mu0)
    den = _beta0_denominator(m, phi_deg, "Eq 17")
    s2 = _sin2(phi_deg)
    return np.asarray(m * (2.0 - s2 * (1.0 + m * m)) / (2.0 * den), dtype=np.float64)


def flat_on_wedge_90deg(mu0: float, phi_deg: ArrayLike) -> FloatArray:
    """Eq 18: mu_y of a flat surface on a symmetric wedge, beta = 90 deg: (mu0/2)(1/cos phi + 1)."""
    m = _check_mu0(mu0)
    _sin2(phi_deg)
    c = np.cos(np.radians(np.asarray(phi_deg, dtype=np.float64)))
    return np.asarray(0.5 * m * (1.0 / c + 1.0), dtype=np.float64)


def wedge_on_wedge_0deg(mu0: float, phi_deg: ArrayLike) -> FloatArray:
    """Eq 19: mu_x of two identical symmetric wedges, beta = 0: mu0 / (1 - sin^2(phi)(1+mu0^2))."""
    m = _check_mu0(mu0)
    den = _beta0_denominator(m, phi_deg, "Eq 19")
    return np.asarray(m / den, dtype=np.float64)


def wedge_on_wedge_90deg(mu0: float, phi_deg: ArrayLike) -> FloatArray:
    """Eq 20: mu_y of two identical symmetric wedges, beta = 90 deg: mu0 / cos(phi)."""
    m = _check_mu0(mu0)
    _sin2(phi_deg)
    return np.asarray(
        m / np.cos(np.radians(np.asarray(phi_deg, dtype=np.float64))), dtype=np.float64
    )


def singular_angle_deg(mu0: float) -> float:
    """phi* = arctan(1/mu0) in degrees: Eqs 17 and 19 diverge there."""
    m = _check_mu0(mu0)
    return 90.0 if m == 0.0 else math.degrees(math.atan(1.0 / m))


def _levels(n: ArrayLike) -> FloatArray:
    arr = np.asarray(n)
    if arr.dtype.kind not in "iu" or np.any(arr < 0):
        raise ParameterError("n", n, "integer numbers of levels >= 0")
    return np.asarray(arr, dtype=np.float64)


def hierarchy_flat_on_wedge_90deg(mu0: float, phi_deg: ArrayLike, n: ArrayLike) -> FloatArray:
    """Eq 33: ``mu_n = mu0 / 2^n (1/cos(phi) + 1)^n``, n levels of a flat surface on a
    symmetric wedge (phi1 = phi2 = phi, phi3 = phi4 = 0), beta = 90 deg: Eq 18 iterated.

    ``phi_deg`` in [0, 90); ``n`` integer >= 0 (n = 0 gives mu0). Broadcasts.
    """
    m = _check_mu0(mu0)
    _sin2(phi_deg)
    levels = _levels(n)
    c = np.cos(np.radians(np.asarray(phi_deg, dtype=np.float64)))
    return np.asarray(m * (0.5 * (1.0 / c + 1.0)) ** levels, dtype=np.float64)


def hierarchy_wedge_on_wedge_90deg(mu0: float, phi_deg: ArrayLike, n: ArrayLike) -> FloatArray:
    """Eq 34: ``mu_n = mu0 / cos^n(phi)``, n levels of two identical symmetric wedges,
    beta = 90 deg: Eq 20 iterated. ``phi_deg`` in [0, 90); ``n`` integer >= 0."""
    m = _check_mu0(mu0)
    _sin2(phi_deg)
    levels = _levels(n)
    c = np.cos(np.radians(np.asarray(phi_deg, dtype=np.float64)))
    return np.asarray(m / c**levels, dtype=np.float64)
