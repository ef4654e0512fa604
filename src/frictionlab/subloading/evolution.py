"""Evolution of the normal sliding-yield ratio R and of the size F (or mu), spec §2.6–2.7, §4.3.

Compiled scalar kernels used by the return map:

* :func:`ratio_after` — R after a plastic increment ``dlam`` (= Delta u^p): Eq (29) in
  closed form for U = u cot(pi R/2) (Eq 28), implicit Euler for U = -u ln R (Eq 30);
* :func:`size_after` — F after a plastic increment ``dlam`` and a time increment ``dt``
  (Eq 25 / 69), with the integrators of spec §4.3.

Public NumPy closed forms (for users, calibration and tests) follow below them.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from frictionlab.errors import ParameterError

__all__ = [
    "BACKWARD_EULER",
    "EXPONENTIAL",
    "ONE_MINUS",
    "RATIO",
    "U_COT",
    "U_LN",
    "U_function",
    "hold_recovery",
    "plastic_slip_for_ratio",
    "ratcheting_slip_per_cycle",
    "ratio_closed_form",
    "steady_size",
]

U_COT, U_LN = 0, 1
EXPONENTIAL, BACKWARD_EULER = 0, 1
ONE_MINUS, RATIO = 0, 1

_HALF_PI = 0.5 * math.pi


# ============================================================================ R
@njit(cache=True)
def ratio_after(law: int, u: float, R0: float, dlam: float) -> tuple[float, float, float]:
    """R, dR/d(dlam) and dR/dR0 after plastic sliding ``dlam >= 0`` from ``R0``.

    Cot law, Eq (29): ``cos(pi R/2) = cos(pi R0/2) exp(-pi u dlam/2)``, evaluated as
    ``R = (2/pi) atan2(sqrt(s0^2 - y0^2 expm1(-2a)), y0 e^-a)`` with ``a = pi u dlam/2``,
    accurate at both R -> 0 and R -> 1 (pitfalls 1, 2). ``dR/d(dlam) = u cot(pi R/2)``.

    Ln law, Eq (30), implicit Euler (spec §4.3): ``R - R0 + u dlam ln R = 0``, solved by
    Newton in ``ln R`` (convex and increasing, so Newton from the right is monotone).
    """
    if law == U_COT:
        a = _HALF_PI * u * dlam
        y0 = math.cos(_HALF_PI * R0)
        s0 = math.sin(_HALF_PI * R0)
        y = y0 * math.exp(-a)
        s2 = s0 * s0 - y0 * y0 * math.expm1(-2.0 * a)
        s = math.sqrt(s2) if s2 > 0.0 else 0.0
        R = math.atan2(s, y) / _HALF_PI
        slope = u * y / s if s > 0.0 else math.inf
        dR0 = math.exp(-a) * s0 / s if s > 0.0 else 1.0
        return R, slope, dR0
    # ln law
    if dlam <= 0.0:
        if R0 <= 0.0:
            return 0.0, math.inf, 1.0
        return R0, -u * math.log(R0), 1.0
    c = u * dlam
    x = 0.0 if R0 <= 1.0 else math.log(R0)
    for _ in range(200):
        ex = math.exp(x)
        h = ex - R0 + c * x
        step = h / (ex + c)
        x -= step
        if abs(step) <= 1e-16 * max(1.0, abs(x)):
            break
    R = math.exp(x)
    return R, -u * x / (1.0 + c / R), 1.0 / (1.0 + c / R)


# ============================================================================ F
@njit(cache=True)
def _recovery_rate(F: float, Fs: float, n: float, form: int) -> tuple[float, float]:
    """psi(F) and psi'(F) of the recovery term of Eq (25) (rate = xi * psi)."""
    if form == ONE_MINUS:
        x = 1.0 - F / Fs
        if x <= 0.0:
            return 0.0, (-1.0 / Fs if n == 1.0 else (0.0 if n > 1.0 else -math.inf))
        return x**n, -n * x ** (n - 1.0) / Fs
    x = Fs / F - 1.0
    if x <= 0.0:
        return 0.0, (-Fs / (F * F) if n == 1.0 else (0.0 if n > 1.0 else -math.inf))
    return x**n, -n * x ** (n - 1.0) * Fs / (F * F)


@njit(cache=True)
def _softening_rate(F: float, Fk: float, m: float) -> tuple[float, float]:
    """phi(F) and phi'(F) of the softening term of Eq (25) (rate = -kappa * phi * |v^p|)."""
    x = F / Fk - 1.0
    if x <= 0.0:
        return 0.0, (1.0 / Fk if m == 1.0 else (0.0 if m > 1.0 else math.inf))
    return x**m, m * x ** (m - 1.0) / Fk


@njit(cache=True)
def _recover_exactly(F0: float, Fs: float, xi: float, n: float, dt: float) -> float:
    """F after pure recovery over dt, closed forms of spec §2.6 (form 1 - F/F_s)."""
    if xi == 0.0 or dt == 0.0:
        return F0
    x0 = max(1.0 - F0 / Fs, 0.0)
    if n == 1.0:
        x = x0 * math.exp(-xi * dt / Fs)
    elif n > 1.0:
        x = 0.0 if x0 == 0.0 else (x0 ** (1.0 - n) + (n - 1.0) * xi * dt / Fs) ** (-1.0 / (n - 1.0))
    else:
        base = x0 ** (1.0 - n) - (1.0 - n) * xi * dt / Fs
        x = base ** (1.0 / (1.0 - n)) if base > 0.0 else 0.0
    return Fs * (1.0 - x)


@njit(cache=True)
def _soften_exactly(
    F1: float, Fk: float, kappa: float, m: float, dlam: float
) -> tuple[float, float]:
    """F and dF/d(dlam) after pure softening by dlam from F1 (closed forms of dF = -kappa phi)."""
    x1 = max(F1 / Fk - 1.0, 0.0)
    if kappa == 0.0 or x1 == 0.0:
        return F1, 0.0 if x1 == 0.0 else -kappa * x1**m
    c = kappa * dlam / Fk
    if m == 1.0:
        x = x1 * math.exp(-c)
    elif m > 1.0:
        x = (x1 ** (1.0 - m) + (m - 1.0) * c) ** (-1.0 / (m - 1.0))
    else:
        base = x1 ** (1.0 - m) - (1.0 - m) * c
        x = base ** (1.0 / (1.0 - m)) if base > 0.0 else 0.0
    return Fk * (1.0 + x), -kappa * x**m


@njit(cache=True)
def _backward_euler(
    F0: float, Fs: float, Fk: float, kappa: float, xi: float, m: float, n: float,
    dlam: float, dt: float, form: int,
) -> tuple[float, float]:  # fmt: skip
    """Backward Euler of Eq (25): h(F) = F - F0 + kappa phi(F) dlam - xi psi(F) dt = 0 on [Fk, Fs].

    h is increasing, h(Fk) <= 0 <= h(Fs); safeguarded Newton with bisection.
    Returns F and dF/d(dlam) = -kappa phi(F) / h'(F).
    """
    kl = kappa * dlam
    xt = xi * dt
    if m == 1.0 and n == 1.0 and form == ONE_MINUS:
        F = (F0 + kl + xt) / (1.0 + kl / Fk + xt / Fs)
    else:
        lo, hi = Fk, Fs
        F = min(max(F0, lo), hi)
        for _ in range(200):
            phi, dphi = _softening_rate(F, Fk, m)
            psi, dpsi = _recovery_rate(F, Fs, n, form)
            h = F - F0 + kl * phi - xt * psi
            if h > 0.0:
                hi = F
            else:
                lo = F
            dh = 1.0 + kl * dphi - xt * dpsi
            Fn = F - h / dh if math.isfinite(dh) and dh > 0.0 else 0.5 * (lo + hi)
            if not (lo < Fn < hi):
                Fn = 0.5 * (lo + hi)
            if abs(Fn - F) <= 1e-15 * Fs or hi - lo <= 1e-15 * Fs:
                F = Fn
                break
            F = Fn
    phi, dphi = _softening_rate(F, Fk, m)
    psi, dpsi = _recovery_rate(F, Fs, n, form)
    dh = 1.0 + kl * dphi - xt * dpsi
    dF = 0.0 if not math.isfinite(dh) else -kappa * phi / dh
    return F, dF


@njit(cache=True)
def size_after(
    F0: float, Fs: float, Fk: float, kappa: float, xi: float, m: float, n: float,
    dlam: float, dt: float, integrator: int, form: int,
) -> tuple[float, float]:  # fmt: skip
    """F (or mu) and dF/d(dlam) after plastic sliding ``dlam`` and time ``dt``, Eq (25)/(69).

    ``integrator == EXPONENTIAL`` (default, spec §4.3, §6 Q10):

    * m = n = 1 and the default recovery form: exact for constant rates,
      ``a = kappa dlam/F_k + xi dt/F_s``, ``F_inf = (kappa dlam + xi dt)/a``,
      ``F = F_inf + (F0 - F_inf) e^-a``;
    * otherwise a split: exact recovery over dt (closed forms of §2.6; backward Euler for
      the "ratio" form, which has none), then exact softening by dlam.

    ``integrator == BACKWARD_EULER``: the monotone scalar equation of §4.3.
    The result always lies in [F_k, F_s] (convex combinations; pitfall 4).
    """
    if integrator == BACKWARD_EULER:
        return _backward_euler(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, form)
    if m == 1.0 and n == 1.0 and form == ONE_MINUS:
        a_soft = kappa * dlam / Fk
        a = a_soft + xi * dt / Fs
        if a == 0.0:
            return F0, -kappa * (F0 / Fk - 1.0)
        F_inf = (kappa * dlam + xi * dt) / a
        e = math.exp(-a)
        one_minus_e_over_a = -math.expm1(-a) / a
        F = F_inf + (F0 - F_inf) * e
        dF = kappa * (1.0 - F_inf / Fk) * one_minus_e_over_a + (F_inf - F0) * e * kappa / Fk
        return min(max(F, Fk), Fs), dF
    if form == ONE_MINUS:
        F1 = _recover_exactly(F0, Fs, xi, n, dt)
    else:
        F1 = _backward_euler(F0, Fs, Fk, 0.0, xi, m, n, 0.0, dt, form)[0]
    return _soften_exactly(F1, Fk, kappa, m, dlam)


# ============================================================================ public closed forms
def U_function(R: ArrayLike, u: float, law: str = "cot") -> np.ndarray:
    """U(R) of Eq (28) (``u cot(pi R/2)``) or Eq (30) (``-u ln R``); +inf at R = 0."""
    R = np.asarray(R, dtype=np.float64)
    with np.errstate(divide="ignore"):
        if law == "cot":
            return u * np.cos(_HALF_PI * R) / np.sin(_HALF_PI * R)
        if law == "ln":
            return -u * np.log(R)
    raise ParameterError("law", law, "'cot' or 'ln'")


def ratio_closed_form(R0: ArrayLike, plastic_slip: ArrayLike, u: float) -> np.ndarray:
    """Eq (29): R after accumulated plastic sliding ``plastic_slip`` [m] from R0."""
    R0 = np.asarray(R0, dtype=np.float64)
    up = np.asarray(plastic_slip, dtype=np.float64)
    return (2.0 / np.pi) * np.arccos(np.cos(_HALF_PI * R0) * np.exp(-_HALF_PI * u * up))


def plastic_slip_for_ratio(R0: ArrayLike, R: ArrayLike, u: float) -> np.ndarray:
    """Inverse of Eq (29): ``(2/(pi u)) ln(cos(pi R0/2) / cos(pi R/2))`` [m]."""
    R0 = np.asarray(R0, dtype=np.float64)
    R = np.asarray(R, dtype=np.float64)
    return (2.0 / (np.pi * u)) * np.log(np.cos(_HALF_PI * R0) / np.cos(_HALF_PI * R))


def ratcheting_slip_per_cycle(R_max: ArrayLike, u: float) -> np.ndarray:
    """Residual slip per traction cycle 0 -> R_max -> 0 with kappa = xi = 0 [m].

    ``(2/(pi u)) ln sec(pi R_max/2)`` (spec A6): the hallmark of the subloading concept.
    """
    return plastic_slip_for_ratio(np.zeros_like(np.asarray(R_max, dtype=np.float64)), R_max, u)


def hold_recovery(
    F0: ArrayLike, F_s: float, xi: float, time: ArrayLike, n: float = 1.0
) -> np.ndarray:
    """F after a hold of ``time`` [s] from F0 (no sliding), closed forms of spec §2.6."""
    F0 = np.asarray(F0, dtype=np.float64)
    t = np.asarray(time, dtype=np.float64)
    x0 = np.maximum(1.0 - F0 / F_s, 0.0)
    if n == 1.0:
        return F_s - F_s * x0 * np.exp(-xi * t / F_s)
    if n > 1.0:
        with np.errstate(divide="ignore"):
            x = (x0 ** (1.0 - n) + (n - 1.0) * xi * t / F_s) ** (-1.0 / (n - 1.0))
        return F_s * (1.0 - x)
    base = x0 ** (1.0 - n) - (1.0 - n) * xi * t / F_s
    return F_s * (1.0 - np.where(base > 0, np.maximum(base, 0.0) ** (1.0 / (1.0 - n)), 0.0))


def steady_size(velocity: ArrayLike, kappa: float, xi: float, F_s: float, F_k: float) -> np.ndarray:
    """Steady-sliding size F_ss(V) = (kappa V + xi)/(kappa V/F_k + xi/F_s), spec §2.6.

    For the cone this is mu_ss(V), the steady friction coefficient at sliding speed V.
    """
    V = np.abs(np.asarray(velocity, dtype=np.float64))
    return (kappa * V + xi) / (kappa * V / F_k + xi / F_s)
