"""Steady sliding of the subloading-friction law in any direction: the law's friction polar.

At steady sliding at speed V in the direction ``d = (cos theta, sin theta)`` of the contact
plane the traction no longer changes, so the elastic sliding velocity vanishes and the whole
sliding velocity is plastic: ``v = v^p = lambda t_bar`` (Eq 32) with ``lambda = V``. Hence

* the plastic flow direction equals the sliding direction, ``t_bar = d``;
* ``R = 1`` (Eq 26 has its fixed point at U(R) = 0, Eq 27) and the size F (or mu) sits at
  its steady value F_ss(V), the root of Eq (25) with ``|v^p| = V``;
* the traction lies on the normal sliding-yield surface ``f(f, beta) = F_ss`` where its
  tangential normal is ``d``.

With ``fhat = f_t - f_n beta`` (Eq 84) written along the principal axes of orthotropy,
``fhat_i`` (angle ``phi`` from e_1 to e*_1), the flow direction is
``t_bar ∝ (fhat_1 / A_1^2, fhat_2 / A_2^2)`` for the cone (Eqs 99-103, ``A_i = C_i``) and
for the closed surfaces (Eqs 87-92, ``A_i = M C_i``) alike, so ``fhat_i ∝ A_i^2 d*_i``
with ``d* = (cos(theta - phi), sin(theta - phi))``. Scaling onto the surface
(``w = sqrt(sum (fhat_i/A_i)^2)`` equal to ``mu f_n`` on the cone, Eq 96, or to
``f_n g^{-1}(F/f_n)`` on a closed surface, Eqs 49, 83) gives the closed form

    f_t / f_n = beta + mu_bar * Q(phi) (C_1^2 d*_1, C_2^2 d*_2) / sqrt(C_1^2 d*_1^2 + C_2^2 d*_2^2)

with ``Q(phi)`` the rotation from the principal axes to the contact frame and the
coefficient ``mu_bar`` = mu_ss(V) for the cone, ``M g^{-1}(F_ss(V)/f_n)`` for a closed
surface (the friction coefficient on its yield surface, Eqs 51-54). Along ``e*_i`` this is
``beta + C_i mu_bar e*_i``; elsewhere the traction is
non-coaxial with the sliding direction. The kinetic polar is the limit ``V -> inf``
(``F_ss = F_k``). Pure functions: no I/O.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import brentq

from frictionlab._arrays import FloatArray, finite_vector
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams, friction_coefficient_on_yield, steady_size

__all__ = [
    "law_polar",
    "steady_coefficient",
    "steady_direction",
    "steady_distance",
    "steady_size_at",
    "steady_traction_ratio",
]


def _angles(theta_deg: ArrayLike) -> FloatArray:
    allowed = "finite sliding directions (deg), shape (N,)"
    return np.radians(finite_vector("theta_deg", theta_deg, allowed, empty=True))


def steady_direction(
    theta_deg: ArrayLike,
    orthotropy: ArrayLike = (1.0, 1.0),
    orthotropy_angle: float = 0.0,
) -> FloatArray:
    """(N, 2) steady ``fhat / (mu_bar f_n)`` for sliding directions ``theta_deg`` (deg).

    The unit-coefficient shape of the steady polar (module docstring): ``Q(phi) (C_1^2 d*_1,
    C_2^2 d*_2) / sqrt(C_1^2 d*_1^2 + C_2^2 d*_2^2)``, contact-frame components.
    ``orthotropy`` = (C_1, C_2) in the "divide" convention (Eq 95), ``orthotropy_angle`` [rad]
    from e_1 to e*_1. Its length is C_1 along e*_1 and C_2 along e*_2.
    """
    theta = _angles(theta_deg)
    C = np.asarray(orthotropy, dtype=np.float64)
    if C.shape != (2,) or not np.all(C > 0) or not np.all(np.isfinite(C)):
        raise ParameterError("orthotropy", orthotropy, "(C_1, C_2), both finite and > 0")
    phi = float(orthotropy_angle)
    if not math.isfinite(phi):
        raise ParameterError("orthotropy_angle", orthotropy_angle, "a finite angle (rad)")
    d1, d2 = np.cos(theta - phi), np.sin(theta - phi)
    a1, a2 = C[0] ** 2 * d1, C[1] ** 2 * d2
    norm = np.sqrt(C[0] ** 2 * d1**2 + C[1] ** 2 * d2**2)
    p1, p2 = a1 / norm, a2 / norm
    c, s = math.cos(phi), math.sin(phi)
    return np.column_stack([c * p1 - s * p2, s * p1 + c * p2])


def steady_traction_ratio(
    theta_deg: ArrayLike,
    mu_bar: float,
    orthotropy: ArrayLike = (1.0, 1.0),
    orthotropy_angle: float = 0.0,
    rotation: ArrayLike = (0.0, 0.0),
) -> FloatArray:
    """(N, 2) steady tangential traction ratio ``f_t / f_n`` in the contact frame.

    ``beta + mu_bar * steady_direction(...)`` (module docstring); ``mu_bar`` is the
    coefficient of the isotropic law at the state (mu_ss(V) for the cone).
    """
    beta = np.asarray(rotation, dtype=np.float64)
    if beta.shape != (2,) or not np.all(np.isfinite(beta)):
        raise ParameterError("rotation", rotation, "a finite pair (beta_1, beta_2)")
    if not (math.isfinite(mu_bar) and mu_bar > 0):
        raise ParameterError("mu_bar", mu_bar, "a finite coefficient > 0")
    return beta + mu_bar * steady_direction(theta_deg, orthotropy, orthotropy_angle)


def _scalar(params: SubloadingParams) -> None:
    if params.per_point:
        raise ParameterError("params", "per-point values", "one law (scalar parameters)")


def _f(params: SubloadingParams, name: str) -> float:
    value = getattr(params, name)
    return float(np.ravel(value)[0])


def steady_size_at(params: SubloadingParams, velocity: float | None) -> float:
    """F_ss(V) (mu_ss for the cone): the root of Eq (25) at plastic rate V in [F_k, F_s].

    ``velocity=None`` gives the kinetic limit F_k (V -> inf). m = n = 1 with the default
    recovery form uses the closed form ``(kappa V + xi) / (kappa V/F_k + xi/F_s)``; other
    exponents or the "ratio" form solve ``kappa V (F/F_k - 1)^m = xi psi(F)`` by Brent's
    method (the left side rises and the right side falls with F, so the root is unique).
    """
    _scalar(params)
    Fs, Fk = _f(params, "static"), _f(params, "kinetic")
    if velocity is None:
        return Fk
    V = float(velocity)
    if not (math.isfinite(V) and V > 0):
        raise ParameterError("velocity", velocity, "a sliding speed > 0 (m/s)")
    kappa, xi, m, n = (_f(params, k) for k in ("kappa", "xi", "m", "n"))
    if kappa * V == 0.0 or Fs == Fk:
        return Fs
    if xi == 0.0:
        return Fk
    if m == 1.0 and n == 1.0 and params.recovery_form == "one_minus":
        return float(steady_size(V, kappa, xi, Fs, Fk))

    def rate(F: float) -> float:
        x = Fs / F - 1.0 if params.recovery_form == "ratio" else 1.0 - F / Fs
        return xi * max(x, 0.0) ** n - kappa * V * max(F / Fk - 1.0, 0.0) ** m

    return float(brentq(rate, Fk, Fs, xtol=1e-15 * Fs, rtol=1e-15, maxiter=200))


def steady_coefficient(
    params: SubloadingParams, velocity: float | None = None, normal_traction: float = 1.0
) -> float:
    """mu_bar: the isotropic steady coefficient at speed V (None: the kinetic limit).

    Cone: mu_ss(V) = F_ss(V). Closed surfaces: ``M g^{-1}(F_ss(V)/f_n)``, the friction
    coefficient on the yield surface of size F_ss at the normal traction ``f_n`` [Pa]
    (Eqs 51-54), which needs ``0 < f_n < F_k``.
    """
    return _coefficient_at(params, steady_size_at(params, velocity), normal_traction)


def _coefficient_at(params: SubloadingParams, F: float, normal_traction: float) -> float:
    if params.is_cone:
        return F
    fn = float(normal_traction)
    Fk = _f(params, "kinetic")
    if not (math.isfinite(fn) and 0.0 < fn < Fk):
        raise ParameterError(
            "normal_traction", normal_traction, f"0 < f_n < F_k = {Fk:g} Pa (closed surface)"
        )
    return float(
        friction_coefficient_on_yield(params.surface, fn, F, _f(params, "M"), params.tear_k)
    )


def law_polar(
    params: SubloadingParams,
    theta_deg: ArrayLike,
    velocity: float | None = None,
    normal_traction: float = 1.0,
) -> FloatArray:
    """(N, 2) steady ``f_t / f_n`` of the law ``params`` sliding along ``theta_deg`` (deg).

    At speed ``velocity`` [m/s] (None: the kinetic polar) and normal traction
    ``normal_traction`` [Pa] (used by the closed surfaces only).
    """
    mu_bar = steady_coefficient(params, velocity, normal_traction)
    return steady_traction_ratio(
        theta_deg,
        mu_bar,
        np.asarray(params.orthotropy),
        _f(params, "orthotropy_angle"),
        np.asarray(params.rotation),
    )


def steady_distance(
    params: SubloadingParams, normal_traction: float = 1.0, lengths: float = 25.0
) -> float:
    """A slide distance [m] after which sliding is steady to about ``exp(-lengths)``.

    ``lengths`` times the longest relaxation length of the transient: F_k/kappa (F toward
    F_ss with m = 1: the decay rate kappa/F_k + xi/(V F_s) is at least kappa/F_k),
    1/u (R toward 1: ``1 - R`` decays like exp(-pi u s/2) for the cot law, exp(-u s) for
    the ln law), and the elastic slip C_max mu_s f_n/alpha_t that builds the traction
    (mu_s: the coefficient of the static surface). For exponents m != 1 the approach to
    F_ss is slower near F_k; give the distance explicitly there.
    """
    _scalar(params)
    kappa, u, alpha_t = _f(params, "kappa"), _f(params, "u"), _f(params, "alpha_t")
    fn = float(normal_traction)
    peak = _coefficient_at(params, _f(params, "static"), fn) * float(np.max(params.orthotropy))
    candidates = [1.0 / u, peak * fn / alpha_t]
    if kappa > 0.0:
        candidates.append(_f(params, "kinetic") / kappa)
    return lengths * max(candidates)
