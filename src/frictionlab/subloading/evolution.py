"""Evolution of the normal sliding-yield ratio R and of the size F (or mu), Eqs (25)-(30).

Compiled scalar kernels used by the return map:

* :func:`ratio_after` — R after a plastic increment ``dlam`` (= Delta u^p): Eq (29) in
  closed form for U = u cot(pi R/2) (Eq 28), implicit Euler for U = -u ln R (Eq 30);
* :func:`size_after` — F after a plastic increment ``dlam`` and a time increment ``dt``
  (Eq 25 / 69), exact for constant rates over the step or by backward Euler.

Public NumPy closed forms (for users, calibration and tests) follow below them.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._jit import njit
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
#: 1/(pi/2): R = angle/(pi/2) as a product (a division by a constant costs ~10 products).
_INV_HALF_PI = 2.0 / math.pi


# ============================================================================ R
@njit(cache=True)
def ratio_start(law: int, R0: float) -> tuple[float, float]:
    """The per-point constants of :func:`ratio_from`: ``(cos(pi R0/2), sin(pi R0/2))``.

    They depend only on the starting ratio, so the return map evaluates them once per
    point rather than once per Newton iteration (the ln law needs none: zeros).
    """
    if law == U_COT:
        return math.cos(_HALF_PI * R0), math.sin(_HALF_PI * R0)
    return 0.0, 0.0


@njit(cache=True)
def ratio_from(
    law: int, u: float, y0: float, s0: float, R0: float, dlam: float
) -> tuple[float, float]:
    """R and dR/d(dlam) after plastic sliding ``dlam >= 0`` from ``R0`` (no dR/dR0).

    ``(y0, s0) = ratio_start(law, R0)``. Same numbers as :func:`ratio_after`.
    """
    if law == U_COT:
        # one expm1: e^-a = 1 + em and expm1(-2a) = em (2 + em), both to a few ulp
        em = math.expm1(-_HALF_PI * u * dlam)
        y = y0 * (1.0 + em)
        s2 = s0 * s0 - y0 * y0 * (em * (2.0 + em))
        s = math.sqrt(s2) if s2 > 0.0 else 0.0
        R = math.atan2(s, y) * _INV_HALF_PI
        slope = u * y / s if s > 0.0 else math.inf
        return R, slope
    # ln law
    if dlam <= 0.0:
        if R0 <= 0.0:
            return 0.0, math.inf
        return R0, -u * math.log(R0)
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
    return R, -u * x / (1.0 + c / R)


@njit(cache=True)
def ratio_sensitivity(law: int, u: float, y0: float, s0: float, dlam: float, R: float) -> float:
    """dR/dR0 after plastic sliding ``dlam`` that ended at ``R``; ``(y0, s0)`` of ratio_start.

    Needed only for the consistent tangent, so the return map evaluates it once, after
    the local solve has converged.
    """
    if law == U_COT:
        em = math.expm1(-_HALF_PI * u * dlam)  # as in ratio_from
        s2 = s0 * s0 - y0 * y0 * (em * (2.0 + em))
        s = math.sqrt(s2) if s2 > 0.0 else 0.0
        return (1.0 + em) * s0 / s if s > 0.0 else 1.0
    if dlam <= 0.0:
        return 1.0
    return 1.0 / (1.0 + u * dlam / R)


@njit(cache=True)
def ratio_after(law: int, u: float, R0: float, dlam: float) -> tuple[float, float, float]:
    """R, dR/d(dlam) and dR/dR0 after plastic sliding ``dlam >= 0`` from ``R0``.

    Cot law, Eq (29): ``cos(pi R/2) = cos(pi R0/2) exp(-pi u dlam/2)``, evaluated as
    ``R = (2/pi) atan2(sqrt(s0^2 - y0^2 expm1(-2a)), y0 e^-a)`` with ``a = pi u dlam/2``,
    accurate at both R -> 0 and R -> 1 (no arccos of a number near 1, no cancellation in
    1 - cos^2). ``dR/d(dlam) = u cot(pi R/2)``.

    Ln law, Eq (30), implicit Euler: ``R - R0 + u dlam ln R = 0``, solved by
    Newton in ``ln R`` (convex and increasing, so Newton from the right is monotone).

    The composition of :func:`ratio_start`, :func:`ratio_from` and the sensitivity; the
    return map calls the parts (constants once per point, dR/dR0 after convergence).
    """
    y0, s0 = ratio_start(law, R0)
    R, slope = ratio_from(law, u, y0, s0, R0, dlam)
    return R, slope, ratio_sensitivity(law, u, y0, s0, dlam, R)


# ============================================================================ F
@njit(cache=True)
def _recovery_rate(F: float, Fs: float, n: float, form: int) -> tuple[float, float]:
    """psi(F) and psi'(F) of the recovery term of Eq (25) (rate = xi * psi)."""
    if form == ONE_MINUS:
        x = 1.0 - F / Fs
        if x <= 0.0:
            return 0.0, (-1.0 / Fs if n == 1.0 else (0.0 if n > 1.0 else -math.inf))
        if n == 1.0:  # the default exponent without pow (the same numbers)
            return x, -1.0 / Fs
        return x**n, -n * x ** (n - 1.0) / Fs
    x = Fs / F - 1.0
    if x <= 0.0:
        return 0.0, (-Fs / (F * F) if n == 1.0 else (0.0 if n > 1.0 else -math.inf))
    if n == 1.0:
        return x, -Fs / (F * F)
    return x**n, -n * x ** (n - 1.0) * Fs / (F * F)


#: Public name of the recovery function for the kernels (psi, psi').
recovery_rate = _recovery_rate


@njit(cache=True)
def _softening_rate(F: float, Fk: float, m: float) -> tuple[float, float]:
    """phi(F) and phi'(F) of the softening term of Eq (25) (rate = -kappa * phi * |v^p|)."""
    x = F / Fk - 1.0
    if x <= 0.0:
        return 0.0, (1.0 / Fk if m == 1.0 else (0.0 if m > 1.0 else math.inf))
    if m == 1.0:
        return x, 1.0 / Fk
    return x**m, m * x ** (m - 1.0) / Fk


#: Public name of the softening function for the kernels (phi, phi').
softening_rate = _softening_rate


@njit(cache=True)
def _recover_exactly(F0: float, Fs: float, xi: float, n: float, dt: float) -> float:
    """F after pure recovery over dt, closed forms of Eq (25) with kappa = 0 (form 1 - F/F_s)."""
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


# Gauss-Kronrod 7-15 nodes and weights on [-1, 1] (symmetric half, centre last).
_GK_X = np.array([0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                  0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                  0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                  0.207784955007898467600689403773245, 0.0])  # fmt: skip
_GK_WK = np.array([0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                   0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                   0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                   0.204432940075298892414161999234649,
                   0.209482141084727828012999174891714])  # fmt: skip
_GK_WG = np.array([0.0, 0.129484966168869693270611432679082, 0.0,
                   0.279705391489276667901467771423780, 0.0,
                   0.381830050505118944950369775488975, 0.0,
                   0.417959183673469387755102040816327])  # fmt: skip

#: Relative tolerance of the exact (constant-rate) F integration for general exponents.
RTOL_EXACT = 1e-14


@njit(cache=True)
def _drift(F: float, Fs: float, Fk: float, a: float, b: float, m: float, n: float,
           form: int) -> float:  # fmt: skip
    """G(F) = b psi(F) - a phi(F), the rate dF/dtau over a step (tau in [0, 1])."""
    return b * _recovery_rate(F, Fs, n, form)[0] - a * _softening_rate(F, Fk, m)[0]


@njit(cache=True)
def _power_change(base: float, delta: float, p: float) -> float:
    """(base + delta)^p - base^p without cancellation (base >= 0, base + delta >= 0)."""
    if base <= 0.0:
        return max(delta, 0.0) ** p
    return base**p * math.expm1(p * math.log1p(delta / base))


@njit(cache=True)
def _integrand(z: float, F_hi: float, F_lo: float, D0: float, sigma: float, Fs: float,
               Fk: float, a: float, b: float, m: float, n: float,
               form: int) -> tuple[float, float]:  # fmt: skip
    """Integrands in z = ln(|F - F_inf|/D0) of tau and of the a-sensitivity (both >= 0).

    The attractor is carried as ``F_inf = F_hi + F_lo`` (F_lo the sub-ulp Newton
    correction), and G is formed as ``G(F) - G(F_inf)`` from differences of powers
    (``expm1``/``log1p``) with bases taken without cancellation. So the integrand is a
    smooth function of z with full relative precision down to the attractor: the direct
    ``b psi - a phi`` cancels there, and a rounded F or F_inf would add a jitter of
    ulp/|F - F_inf| or an offset |G'(F_inf)| ulp (large for an exponent below 1 near a
    bound).
    """
    d = D0 * math.exp(z)
    F = F_hi + (F_lo - sigma * d)
    F_inf = F_hi + F_lo
    d_soft = _power_change(((F_hi - Fk) + F_lo) / Fk, -sigma * d / Fk, m)
    if form == ONE_MINUS:
        d_rec = _power_change(((Fs - F_hi) - F_lo) / Fs, sigma * d / Fs, n)
    else:
        d_rec = _power_change(((Fs - F_hi) - F_lo) / F_inf, sigma * d * Fs / (F_inf * F), n)
    G = abs(b * d_rec - a * d_soft)
    if not G > 0.0:
        return math.inf, math.inf
    phi = _softening_rate(F, Fk, m)[0]
    ratio = d / G
    return ratio, phi * ratio / G


@njit(cache=True)
def _gk15(lo: float, hi: float, F_hi: float, F_lo: float, D0: float, sigma: float,
          Fs: float, Fk: float, a: float, b: float, m: float, n: float,
          form: int) -> tuple[float, float, float, float]:  # fmt: skip
    """Kronrod-15 estimates of both integrals over [lo, hi] and their error estimates."""
    c = 0.5 * (lo + hi)
    h = 0.5 * (hi - lo)
    k0 = 0.0
    g0 = 0.0
    k1 = 0.0
    g1 = 0.0
    for j in range(8):
        if j == 7:
            v0, v1 = _integrand(c, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form)
        else:
            x = h * _GK_X[j]
            p0, p1 = _integrand(c - x, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form)
            q0, q1 = _integrand(c + x, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form)
            v0 = p0 + q0
            v1 = p1 + q1
        k0 += _GK_WK[j] * v0
        g0 += _GK_WG[j] * v0
        k1 += _GK_WK[j] * v1
        g1 += _GK_WG[j] * v1
    return k0 * h, k1 * h, abs(k0 - g0) * h, abs(k1 - g1) * h


@njit(cache=True)
def _quad(z_lo: float, z_hi: float, F_hi: float, F_lo: float, D0: float, sigma: float, Fs: float,
          Fk: float, a: float, b: float, m: float, n: float, form: int,
          tol: float) -> tuple[float, float]:  # fmt: skip
    """Adaptive Gauss-Kronrod 7-15 of both integrands over [z_lo, z_hi] (z_lo <= z_hi).

    The range is first cut into pieces at most 2 long (the integrands vary on the scale
    of one unit of z, where |F - F_inf| changes by e: a single rule over a long range
    can agree with its own error estimate while missing that variation). A piece is
    accepted when its error estimate is below ``tol`` times its value (both integrands
    are positive, so this bounds the relative error of the sum); explicit stack, at most
    200 bisections per piece (the integrands are smooth: a handful suffice).
    """
    if z_hi <= z_lo:
        return 0.0, 0.0
    total0 = 0.0
    total1 = 0.0
    pieces = math.ceil((z_hi - z_lo) / 2.0)
    stack_lo = np.empty(64)
    stack_hi = np.empty(64)
    for p in range(pieces):
        stack_lo[0] = z_lo + (z_hi - z_lo) * p / pieces
        stack_hi[0] = z_hi if p == pieces - 1 else z_lo + (z_hi - z_lo) * (p + 1) / pieces
        top = 1
        count = 0
        while top > 0:
            top -= 1
            lo = stack_lo[top]
            hi = stack_hi[top]
            k0, k1, d0, d1 = _gk15(lo, hi, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n,
                                   form)  # fmt: skip
            count += 1
            ok = d0 <= tol * k0 and d1 <= tol * k1
            if ok or top >= 62 or count >= 200 or hi - lo <= 1e-9:
                total0 += k0
                total1 += k1
            else:
                c = 0.5 * (lo + hi)
                stack_lo[top] = lo
                stack_hi[top] = c
                stack_lo[top + 1] = c
                stack_hi[top + 1] = hi
                top += 2
    return total0, total1


@njit(cache=True)
def _fixed_point(Fs: float, Fk: float, a: float, b: float, m: float, n: float,
                 form: int) -> float:  # fmt: skip
    """F_inf in [F_k, F_s] with G(F_inf) = 0 (G decreasing: G(F_k) >= 0 >= G(F_s))."""
    lo, hi = Fk, Fs
    if _drift(hi, Fs, Fk, a, b, m, n, form) >= 0.0:
        return hi
    if _drift(lo, Fs, Fk, a, b, m, n, form) <= 0.0:
        return lo
    F = 0.5 * (lo + hi)
    for _ in range(200):
        G = _drift(F, Fs, Fk, a, b, m, n, form)
        if G > 0.0:
            lo = F
        elif G < 0.0:
            hi = F
        else:
            return F
        dG = b * _recovery_rate(F, Fs, n, form)[1] - a * _softening_rate(F, Fk, m)[1]
        F_new = F - G / dG if math.isfinite(dG) and dG < 0.0 else 0.5 * (lo + hi)
        if not lo < F_new < hi:
            F_new = 0.5 * (lo + hi)
        if F_new == F or hi - lo <= 4.4e-16 * hi:
            return F_new
        F = F_new
    return F


@njit(cache=True)
def _attractor_sensitivity(F_inf: float, Fs: float, Fk: float, a: float, b: float,
                           m: float, n: float, form: int) -> float:  # fmt: skip
    """dF_inf/da = phi(F_inf) / G'(F_inf) (F reached its attractor within the step)."""
    phi, dphi = _softening_rate(F_inf, Fk, m)
    dpsi = _recovery_rate(F_inf, Fs, n, form)[1]
    dG = b * dpsi - a * dphi
    if not math.isfinite(dG) or dG >= 0.0:
        return 0.0
    return phi / dG


@njit(cache=True)
def constant_rate_size(
    F0: float, Fs: float, Fk: float, a: float, b: float, m: float, n: float, form: int
) -> tuple[float, float]:
    """Exact F after one step of constant rates, and dF/da.

    Over the step, with pseudo-time tau in [0, 1], ``dF/dtau = G(F) = b psi(F) - a phi(F)``
    where ``a = kappa dlam``, ``b = xi dt``, ``phi = (F/F_k - 1)^m`` and ``psi`` the
    recovery function (``(1 - F/F_s)^n`` or ``(F_s/F - 1)^n``). G is decreasing with one
    root F_inf in [F_k, F_s]; F moves monotonically towards it and the end value solves
    ``int_{F0}^{F1} dF / G(F) = 1``. In ``z = ln(|F - F_inf| / |F0 - F_inf|)`` the
    integrand is bounded (Lipschitz rates) or vanishes (exponents below 1, where F_inf is
    reached in finite time), so adaptive Gauss-Kronrod with a safeguarded Newton iteration
    in z solves it to ``RTOL_EXACT``. The sensitivity is
    ``dF1/da = -|G(F1)| int phi |F - F_inf| / G^2 dz``.
    Composition holds: two half steps equal one step (the equation is autonomous).
    """
    F0 = min(max(F0, Fk), Fs)
    if a == 0.0 and b == 0.0:
        return F0, 0.0
    F_hi = _fixed_point(Fs, Fk, a, b, m, n, form)
    F_lo = 0.0
    if Fk < F_hi < Fs:  # sub-ulp correction of the attractor (one Newton step)
        dG = b * _recovery_rate(F_hi, Fs, n, form)[1] - a * _softening_rate(F_hi, Fk, m)[1]
        if math.isfinite(dG) and dG < 0.0:
            F_lo = -_drift(F_hi, Fs, Fk, a, b, m, n, form) / dG
            if not abs(F_lo) <= 4.4e-16 * F_hi:
                F_lo = 0.0
    F_inf = F_hi + F_lo
    D0 = abs((F0 - F_hi) - F_lo)
    z_min = math.log(max(4.4e-16 * F_inf, 1e-300) / D0) if D0 > 0.0 else 0.0
    if z_min >= 0.0:
        return F_inf, _attractor_sensitivity(F_inf, Fs, Fk, a, b, m, n, form)
    sigma = 1.0 if (F_hi - F0) + F_lo > 0.0 else -1.0
    # safeguarded Newton in z on tau(z) = 1, tau decreasing in z; tau(0) = 0
    z = 0.0
    tau = 0.0
    sens = 0.0
    lo = z_min  # tau(lo) >= 1 not yet known
    hi = 0.0  # tau(hi) <= 1
    lo_known = False
    for _ in range(100):
        h = _integrand(z, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form)[0]
        e = 1.0 - tau
        if abs(e) <= RTOL_EXACT:
            break
        z_new = z - e / h if h > 0.0 and math.isfinite(h) else 0.5 * (lo + hi)
        if not lo < z_new < hi:
            z_new = 0.5 * (lo + hi) if lo_known else max(z_min, 0.5 * (lo + hi), z_new)
        if z_new <= z_min:
            z_new = z_min
        if z_new < z:
            d_tau, d_sens = _quad(z_new, z, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form,
                                  RTOL_EXACT)  # fmt: skip
            tau += d_tau
            sens += d_sens
        else:
            d_tau, d_sens = _quad(z, z_new, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form,
                                  RTOL_EXACT)  # fmt: skip
            tau -= d_tau
            sens -= d_sens
        z = z_new
        if tau >= 1.0:
            lo = z
            lo_known = True
        else:
            hi = z
            if z <= z_min:  # reaches F_inf (to round-off) within the step
                return F_inf, _attractor_sensitivity(F_inf, Fs, Fk, a, b, m, n, form)
        if hi - lo <= 1e-15 * max(1.0, abs(z)) and lo_known:
            break
    d = D0 * math.exp(z)
    F1 = F_hi + (F_lo - sigma * d)
    h1 = _integrand(z, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form)[0]
    g_end = d / h1 if h1 > 0.0 and math.isfinite(h1) else 0.0
    F1 = min(max(F1, Fk), Fs)
    scale = b * _recovery_rate(F1, Fs, n, form)[0] + a * _softening_rate(F1, Fk, m)[0]
    if g_end <= 1e-9 * scale:
        # F1 sits at its attractor to within the rounding of G: -g_end * sens is 0 * inf
        # there, while dF1/da -> dF_inf/da (linear regime, relative error ~ 1e-9)
        return F1, _attractor_sensitivity(F_inf, Fs, Fk, a, b, m, n, form)
    return F1, -g_end * sens


@njit(cache=True)
def size_after(
    F0: float, Fs: float, Fk: float, kappa: float, xi: float, m: float, n: float,
    dlam: float, dt: float, integrator: int, form: int,
) -> tuple[float, float]:  # fmt: skip
    """F (or mu) and dF/d(dlam) after plastic sliding ``dlam`` and time ``dt``, Eq (25)/(69).

    ``integrator == EXPONENTIAL`` (default): exact for constant rates
    over the step (plastic rate dlam/dt and time rate both constant), for every option:

    * m = n = 1 and the default recovery form: closed form,
      ``a = kappa dlam/F_k + xi dt/F_s``, ``F_inf = (kappa dlam + xi dt)/a``,
      ``F = F_inf + (F0 - F_inf) e^-a``;
    * pure softening (dt = 0 or xi = 0), or pure recovery in the default form: the closed
      forms of Eq (25) with one rate set to zero;
    * otherwise :func:`constant_rate_size`, the monotone scalar equation solved to
      ``RTOL_EXACT`` — so a few large steps give the answer of many small ones.

    ``integrator == BACKWARD_EULER``: backward Euler of Eq (25), a monotone scalar
    equation (first order). The result always lies in [F_k, F_s].
    """
    if integrator == BACKWARD_EULER:
        return _backward_euler(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, form)
    if m == 1.0 and n == 1.0 and form == ONE_MINUS:
        # the divisions by the law's constants as products with their quotients (the
        # compiled lanes evaluate them once per call), one reciprocal of a
        a_soft = (kappa / Fk) * dlam
        a = a_soft + xi * dt / Fs
        if a == 0.0:
            return F0, -kappa * (F0 / Fk - 1.0)
        ia = 1.0 / a
        F_inf = (kappa * dlam + xi * dt) * ia
        em = math.expm1(-a)  # one transcendental: e^-a = 1 + em
        e = 1.0 + em
        one_minus_e_over_a = -em * ia
        F = F_inf + (F0 - F_inf) * e
        dF = kappa * (1.0 - F_inf * (1.0 / Fk)) * one_minus_e_over_a + (F_inf - F0) * e * (
            kappa / Fk
        )
        return min(max(F, Fk), Fs), dF
    b = xi * dt
    a = kappa * dlam
    F0 = min(max(F0, Fk), Fs)
    # a rate that cannot move F by one rounding unit over the step is dropped (exact
    # closed forms of the other mechanism; keeps G^2 and the integrals in range)
    recovery_max = 1.0 if form == ONE_MINUS else (Fs / Fk - 1.0) ** n
    if b * recovery_max <= 1e-17 * Fk:
        return _soften_exactly(F0, Fk, kappa, m, dlam)
    if a * (Fs / Fk - 1.0) ** m <= 1e-17 * Fk:
        F1 = recovered_size(F0, Fs, Fk, xi, m, n, dt, integrator, form)
        return F1, -kappa * _softening_rate(F1, Fk, m)[0]
    F1, dF_da = constant_rate_size(F0, Fs, Fk, kappa * dlam, b, m, n, form)
    return F1, kappa * dF_da


@njit(cache=True)
def recovered_size(
    F0: float, Fs: float, Fk: float, xi: float, m: float, n: float, dt: float,
    integrator: int, form: int,
) -> float:  # fmt: skip
    """F after the time ``dt`` with no plastic sliding (recovery only).

    Closed forms of Eq (25) with kappa = 0 for the default form ``1 - F/F_s`` (any n); the exact
    constant-rate solution for the ``F_s/F - 1`` form; backward Euler when chosen.
    """
    if integrator == BACKWARD_EULER:
        return _backward_euler(F0, Fs, Fk, 0.0, xi, m, n, 0.0, dt, form)[0]
    F0 = min(max(F0, Fk), Fs)
    if xi == 0.0 or dt == 0.0:
        return F0
    if form == ONE_MINUS:
        return _recover_exactly(F0, Fs, xi, n, dt)
    if xi * dt * (Fs / Fk - 1.0) ** n <= 1e-17 * Fk:  # cannot move F by one rounding unit
        return F0
    return constant_rate_size(F0, Fs, Fk, 0.0, xi * dt, m, n, form)[0]


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

    ``(2/(pi u)) ln sec(pi R_max/2)``: the hallmark of the subloading concept.
    """
    return plastic_slip_for_ratio(np.zeros_like(np.asarray(R_max, dtype=np.float64)), R_max, u)


def hold_recovery(
    F0: ArrayLike, F_s: float, xi: float, time: ArrayLike, n: float = 1.0
) -> np.ndarray:
    """F after a hold of ``time`` [s] from F0 (no sliding), closed forms of Eq (25)."""
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
    """Steady-sliding size F_ss(V) = (kappa V + xi)/(kappa V/F_k + xi/F_s), Eq (25) at rest.

    For the cone this is mu_ss(V), the steady friction coefficient at sliding speed V.
    """
    V = np.abs(np.asarray(velocity, dtype=np.float64))
    return (kappa * V + xi) / (kappa * V / F_k + xi / F_s)
