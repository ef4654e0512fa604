"""Compiled (numba) implicit return map of the subloading-friction law.

One call of :func:`step_points` advances N independent contact points by one
increment. Per point:

0. rotate the contact-frame components into the principal axes of orthotropy;
1. elastic predictor ``f_t^tr = f_t + alpha_t du_t``, ``f_n^tr = f_n + alpha_n (du_n - gap)``;
   ``f_n^tr <= 0`` opens the contact (zero traction, R = 0, the opening kept in ``gap``);
2. recovery-only size ``F^tr = F(dlam = 0)``;
3. partial-unloading correction of the starting ratio when the straight trial path
   passes its point of smallest |fhat| inside the step (T. Chang's correction);
4. loading test on the trial state (never on the sign of the plastic multiplier, which
   a converged corrector cannot tell apart from rounding);
5. plastic corrector with ONE scalar unknown ``q`` in [0, 1): the backward-Euler flow
   ``fhat_i = fhat_i^tr A_i^2/(A_i^2 + gamma)``, ``gamma = A_ref^2 q/(1 - q)``, gives
   ``dlam = gamma W(gamma)/alpha_t``; for isotropic surfaces this is the radial return
   with ``q = alpha_t dlam / |fhat^tr|`` — the unknown is the plastic increment itself,
   never R (which is flat in dlam near R = 1). Safeguarded Newton inside a sign bracket,
   from a start solved on a cheap model of the residual (see :func:`_start`).
6. update; 7. algorithmic consistent tangent by implicit differentiation of the scalar
   residual (exact for isotropic, rotated and orthotropic surfaces).

The normal traction never changes plastically (no plastic normal sliding, Eq 32).
"""

from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from frictionlab._jit import njit, prange
from frictionlab.subloading.evolution import (
    _HALF_PI,
    _INV_HALF_PI,
    BACKWARD_EULER,
    EXPONENTIAL,
    ONE_MINUS,
    U_COT,
    ratio_from,
    ratio_sensitivity,
    ratio_start,
    recovered_size,
    recovery_rate,
    size_after,
    softening_rate,
)
from frictionlab.subloading.lane_math import (
    atan2_first_quadrant,
    expm1_nonpositive,
    expm1_small,
    sincos_half_pi,
)
from frictionlab.subloading.surfaces import (
    COULOMB,
    MODIFIED_CAM_CLAY,
    PARABOLA,
    TEAR,
    potential,
)

# status codes
STICK, SLIP, OPEN, FAILED = 0, 1, 2, 3

# The steps of one point pass named tuples (values: no reference counting, no positional reads).
#: The point's constants (parameter row; beta in the contact frame and, as ``b1, b2``, in
#: principal axes; option codes).
Law = namedtuple("Law", ["alpha_n", "alpha_t", "Fs", "Fk", "u", "kappa", "xi", "m", "n", "A1",
                         "A2", "Aref", "beta1", "beta2", "b1", "b2", "surface", "tear_k",
                         "ulaw", "integ", "rform"])  # fmt: skip
#: The point's state at the start of the step (contact frame).
Old = namedtuple("Old", ["t1", "t2", "fn", "F", "R", "gap"])
#: Step 1: the trial state and the straight trial path (principal axes) with its derivatives.
Trial = namedtuple("Trial", ["fn_tr", "f1t", "f2t", "fh1t", "fh2t", "w_tr", "phi_tr",
                             "phi_tr_w", "phi_tr_fn", "et", "h1", "h2", "e1", "e2", "fn0",
                             "dfn", "hn1", "hn2", "en1", "en2", "f0n", "dfnn", "ext1", "ext2",
                             "R_prev", "F_path", "dt_path"])  # fmt: skip
#: A point of the trial path: rho = Phi/F, d rho/ds, F, Phi_w, Phi_fn, w, fhat = (q1, q2).
PathPoint = namedtuple("PathPoint", ["rho", "drho", "F", "phi_w", "phi_fn", "w", "q1", "q2"])
#: Step 3: the starting ratio and, when corrected, its gradient in (du1, du2, dun).
Start = namedtuple("Start", ["R_start", "corrected", "gR1", "gR2", "gRn"])
#: Step 5: the scalar residual r(q) = Phi - R F and what the solve and the tangent use.
Residual = namedtuple("Residual", ["r", "r_gamma", "phi_1", "phi_2", "dlam", "R", "dR", "F",
                                   "dF", "phi_fn", "gamma", "W", "hard", "phi", "dR0",
                                   "phi_gamma", "rf_gamma", "cond"])  # fmt: skip
#: Step 5: the outcome of the local solve.
Solution = namedtuple("Solution", ["converged", "iterations", "res"])
#: Step 7: the possibly non-zero entries of the consistent tangent (contact frame).
Tangent = namedtuple("Tangent", ["k00", "k01", "k10", "k11", "k02", "k12", "k22"])
#: The outcome of one point (what :func:`_store` writes).
Result = namedtuple("Result", ["status", "iterations", "t1", "t2", "tn", "F", "R", "gap",
                               "dlam", "vp1", "vp2", "diss", "k00", "k01", "k10", "k11",
                               "k02", "k12", "k22"])  # fmt: skip

# columns of the parameter table (one row shared by all points, or one row per point)
P_ALPHA_N, P_ALPHA_T, P_FS, P_FK, P_U, P_KAPPA, P_XI, P_M, P_N = range(9)
P_BETA1, P_BETA2, P_A1, P_A2, P_ANGLE = range(9, 14)
N_PARAMS = 14

#: Relative tolerance of the scalar residual |f - R F| <= RTOL_RESIDUAL * F.
RTOL_RESIDUAL = 1e-13
#: Accepted residual when the bracket has collapsed to round-off (documented invariant).
RTOL_ACCEPT = 1e-10
#: A trial normal traction at or below this fraction of the terms it is computed from
#: (|f_n| and alpha_n |du_n - gap|) is zero to rounding: the contact opens (the surface
#: is singular at f_n = 0, so a rounding residue must not be treated as contact).
SEPARATION_RTOL = 1e-12
#: Subintervals of the trial path searched for the smallest ratio Phi/F (step 3).
PATH_SAMPLES = 8
MAX_ITERATIONS = 100
#: Newton iterations on the model residual that give the local solve its start.
MODEL_ITERATIONS = 4
#: Relative step of the model's Newton iteration after which the start is taken.
MODEL_RTOL = 1e-3
#: Model iterations allowed when the start comes from the edge of the domain of g.
DOMAIN_MODEL_ITERATIONS = 16


@njit(cache=True)
def _returned(fh1t: float, fh2t: float, A1: float, A2: float, gamma: float):  # fmt: skip
    """Backward-Euler return fhat_i = fhat_i^tr A_i^2/(A_i^2 + gamma).

    Returns (d1, d2, a1, a2, fh1, fh2) with d_i = A_i^2 + gamma and a_i = A_i^2/d_i.
    """
    d1 = A1 * A1 + gamma
    d2 = A2 * A2 + gamma
    a1 = A1 * A1 / d1
    a2 = A2 * A2 / d2
    return d1, d2, a1, a2, fh1t * a1, fh2t * a2


@njit(cache=True)
def _norm(x: float, y: float) -> float:
    """sqrt(x^2 + y^2); by ``math.hypot`` only where the squares could over- or underflow."""
    s = x * x + y * y
    if 1e-290 < s < 1e290:
        return math.sqrt(s)
    return math.hypot(x, y)


@njit(cache=True)
def _state_at(
    q: float,
    omq: float,
    fh1t: float, fh2t: float, fn: float, A1: float, A2: float, Aref: float,
    alpha_t: float, surface: int, tear_k: float,
    R0: float, y0: float, s0: float, u: float, ulaw: int,
    F0: float, Fs: float, Fk: float, kappa: float, xi: float, m: float, n: float,
    dt: float, integ: int, rform: int,
):  # fmt: skip
    """Residual r(q) = Phi(fhat(q), f_n) - R(dlam) F(dlam) and everything derived from it.

    ``omq`` is 1 - q, passed separately so that q close to 1 keeps full precision.
    ``(y0, s0) = ratio_start(ulaw, R0)``, evaluated once per point by the caller.
    Returns a :data:`Residual`; its ``dR0`` (dR/dR0) is left 0: the tangent evaluates it
    after convergence.
    """
    if omq <= 0.0:  # limit gamma -> infinity: fhat -> 0, dlam -> |fhat^tr|/alpha_t
        dlam = _norm(fh1t, fh2t) / alpha_t
        R, dR = ratio_from(ulaw, u, y0, s0, R0, dlam)
        F, dF = size_after(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, integ, rform)
        phi = 0.0 if surface == COULOMB else fn * 1.0
        return Residual(phi - R * F, 0.0, 0.0, 0.0, dlam, R, dR, F, dF, 0.0, 0.0, 0.0, 0.0,
                        phi, 0.0, 0.0, 0.0, 0.0)  # fmt: skip
    # Divisions are the kernel's most expensive arithmetic (after the math library): one
    # reciprocal per distinct denominator, and fhat_i / A_i = A_i t_i, fhat_i / A_i^2 = t_i.
    gamma = Aref * Aref * q / omq
    i1 = 1.0 / (A1 * A1 + gamma)
    i2 = 1.0 / (A2 * A2 + gamma)
    t1 = fh1t * i1  # = fhat_1 / A1^2
    t2 = fh2t * i2
    W = _norm(t1, t2)
    dlam = gamma * W * (1.0 / alpha_t)  # the quotient by a constant as a product
    w = _norm(A1 * t1, A2 * t2)
    phi, phi_w, phi_fn = potential(surface, tear_k, w, fn)
    R, dR = ratio_from(ulaw, u, y0, s0, R0, dlam)
    F, dF = size_after(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, integ, rform)
    r = phi - R * F
    # derivatives with respect to gamma: dfhat_i = -fhat_i / d_i = -A_i^2 t_i / d_i
    dfh1 = -A1 * A1 * t1 * i1
    dfh2 = -A2 * A2 * t2 * i2
    if w > 0.0:
        phi_per_w = phi_w / w
        phi_1 = phi_per_w * t1
        phi_2 = phi_per_w * t2
    else:
        phi_1 = 0.0
        phi_2 = 0.0
    dW = -(t1 * t1 * i1 + t2 * t2 * i2) / W if W > 0.0 else 0.0
    ddlam = (W + gamma * dW) * (1.0 / alpha_t)
    hard = dR * F + R * dF
    phi_gamma = phi_1 * dfh1 + phi_2 * dfh2
    rf_gamma = hard * ddlam
    r_gamma = phi_gamma - rf_gamma
    return Residual(r, r_gamma, phi_1, phi_2, dlam, R, dR, F, dF, phi_fn, gamma, W, hard, phi,
                    0.0, phi_gamma, rf_gamma, phi_w * w)  # fmt: skip


@njit(cache=True)
def _path_ratio(
    s: float, h1: float, h2: float, e1: float, e2: float, fn0: float, dfn: float,
    A1: float, A2: float, surface: int, tear_k: float,
    F_old: float, Fs: float, Fk: float, xi: float, m: float, n: float, dt: float,
    integ: int, rform: int,
):  # fmt: skip
    """rho(s) = Phi(fhat(s), f_n(s)) / F(s) on the trial path and d rho/ds (step 3).

    ``fhat(s) = h + s e``, ``f_n(s) = fn0 + s dfn``, F(s) the recovery-only size after
    ``s dt`` (``dF/ds = dt xi psi(F)``, exact for the exponential integrator; the
    backward-Euler relation otherwise). Returns a :data:`PathPoint` (fhat(s) as q);
    rho = +inf (drho = +inf) outside the domain of g.
    """
    q1 = h1 + s * e1
    q2 = h2 + s * e2
    fns = fn0 + s * dfn
    w = _norm(q1 / A1, q2 / A2)
    phi, phi_w, phi_fn = potential(surface, tear_k, w, fns)
    F = recovered_size(F_old, Fs, Fk, xi, m, n, s * dt, integ, rform)
    dF = _path_size_slope(F, s, Fs, xi, n, dt, integ, rform)
    rho, drho = _ratio_slope(phi, phi_w, phi_fn, w, q1, q2, e1, e2, dfn, A1, A2, F, dF)
    return PathPoint(rho, drho, F, phi_w, phi_fn, w, q1, q2)


@njit(cache=True)
def _path_size_slope(F: float, s: float, Fs: float, xi: float, n: float, dt: float,
                     integ: int, rform: int) -> float:  # fmt: skip
    """dF/ds of the recovery-only size along the path (F = F(s dt))."""
    psi, dpsi = recovery_rate(F, Fs, n, rform)
    if integ == BACKWARD_EULER:
        den = 1.0 - xi * s * dt * dpsi
        return xi * dt * psi / den if den > 0.0 and math.isfinite(den) else 0.0
    return xi * dt * psi


@njit(cache=True)
def _ratio_slope(phi: float, phi_w: float, phi_fn: float, w: float, q1: float, q2: float,
                 e1: float, e2: float, dfn: float, A1: float, A2: float, F: float,
                 dF: float) -> tuple[float, float]:  # fmt: skip
    """rho = Phi/F and d rho/ds at a point q of the path (rho = drho = +inf outside g)."""
    if not math.isfinite(phi):
        return math.inf, math.inf
    if w > 0.0:
        dw = ((q1 / A1) * (e1 / A1) + (q2 / A2) * (e2 / A2)) / w
    else:
        dw = _norm(e1 / A1, e2 / A2)
    rho = phi / F
    return rho, (phi_w * dw + phi_fn * dfn) / F - rho * dF / F


@njit(cache=True)
def _path_minimum(
    h1: float, h2: float, e1: float, e2: float, fn0: float, dfn: float,
    A1: float, A2: float, surface: int, tear_k: float,
    F_old: float, Fs: float, Fk: float, xi: float, m: float, n: float, dt: float,
    integ: int, rform: int, r0: float, d0: float, r1: float, d1: float,
) -> float:  # fmt: skip
    """s* in [0, 1] where rho(s) = Phi/F is smallest along the trial path (step 3).

    ``r0, d0, r1, d1`` are rho and rho' at the two ends (the caller has them).

    Monotone paths (both end slopes of one sign, consistent with the end values) are
    decided at once: forward loading (s* = 0) and rest or pure recovery (s* = 1). Otherwise
    ``PATH_SAMPLES`` subintervals are scanned and every sign change of rho' from - to +
    is refined by the Illinois method; the smallest of these minima and the two ends wins.
    A minimum that turns twice inside one subinterval (1/8 of one increment) is not
    resolved; rho' would need three sign changes along one straight trial path.
    """
    if d0 >= 0.0 and d1 >= 0.0 and r1 >= r0:
        return 0.0
    if d0 <= 0.0 and d1 <= 0.0 and r1 <= r0:
        return 1.0
    best_s = 0.0
    best = r0
    if r1 < best:
        best = r1
        best_s = 1.0
    s_a = 0.0
    d_a = d0
    for k in range(1, PATH_SAMPLES + 1):
        s_b = k / PATH_SAMPLES
        if k == PATH_SAMPLES:
            r_b = r1
            d_b = d1
        else:
            at_b = _path_ratio(s_b, h1, h2, e1, e2, fn0, dfn, A1, A2, surface, tear_k,
                               F_old, Fs, Fk, xi, m, n, dt, integ, rform)  # fmt: skip
            r_b = at_b.rho
            d_b = at_b.drho
            if r_b < best:
                best = r_b
                best_s = s_b
        if d_a < 0.0 and d_b > 0.0 and math.isfinite(d_b):
            lo, hi = s_a, s_b
            f_lo, f_hi = d_a, d_b
            side = 0
            s_m = 0.5 * (lo + hi)
            for _ in range(100):
                s_m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
                if not lo < s_m < hi:
                    s_m = 0.5 * (lo + hi)
                d_m = _path_ratio(s_m, h1, h2, e1, e2, fn0, dfn, A1, A2, surface, tear_k,
                                  F_old, Fs, Fk, xi, m, n, dt, integ, rform).drho  # fmt: skip
                if d_m == 0.0 or not math.isfinite(d_m):
                    break
                if d_m < 0.0:
                    lo, f_lo = s_m, d_m
                    if side == -1:
                        f_hi *= 0.5
                    side = -1
                else:
                    hi, f_hi = s_m, d_m
                    if side == 1:
                        f_lo *= 0.5
                    side = 1
                if hi - lo <= 1e-14:
                    break
            r_m = _path_ratio(s_m, h1, h2, e1, e2, fn0, dfn, A1, A2, surface, tear_k,
                              F_old, Fs, Fk, xi, m, n, dt, integ, rform).rho  # fmt: skip
            if r_m < best:
                best = r_m
                best_s = s_m
        s_a, d_a = s_b, d_b
    return best_s


@njit(cache=True)
def _model_at(
    q: float, fh1t: float, fh2t: float, fn: float, A1: float, A2: float, Aref: float,
    alpha_t: float, surface: int, tear_k: float, R0: float, dR: float, ddR: float,
    dddR: float, F0: float, dF: float, ddF: float,
) -> tuple[float, float, float, float]:  # fmt: skip
    """Model residual m(q) = Phi - R F as (Phi, R F, dPhi/dq, d(R F)/dq), for the start.

    Phi exact (as in :func:`_state_at`), R and F replaced by their Taylor polynomials in
    dlam about the trial state, ``R0 + dR dlam + ddR dlam^2/2 + dddR dlam^3/6`` (held at
    1, and at its value where its slope vanishes) and ``F0 + dF dlam + ddF dlam^2/2``:
    no transcendental function of the law is evaluated.
    """
    omq = 1.0 - q
    gamma = Aref * Aref * q / omq
    i1 = 1.0 / (A1 * A1 + gamma)  # one reciprocal per denominator, as in _state_at
    i2 = 1.0 / (A2 * A2 + gamma)
    t1 = fh1t * i1
    t2 = fh2t * i2
    W = _norm(t1, t2)
    dlam = gamma * W * (1.0 / alpha_t)
    w = _norm(A1 * t1, A2 * t2)
    phi, phi_w, _ = potential(surface, tear_k, w, fn)
    R = R0 + dlam * (dR + dlam * (0.5 * ddR + dlam * dddR * (1.0 / 6.0)))
    Rp = dR + dlam * (ddR + 0.5 * dddR * dlam)
    if R > 1.0 or Rp < 0.0:  # beyond the reach of the series: R saturates
        R = min(R, 1.0)
        Rp = 0.0
    F = F0 + dlam * (dF + 0.5 * ddF * dlam)
    dF = dF + ddF * dlam
    dphi = 0.0  # dPhi/dgamma
    if w > 0.0:
        dphi = -phi_w * (A1 * A1 * t1 * t1 * i1 + A2 * A2 * t2 * t2 * i2) / w
    dW = -(t1 * t1 * i1 + t2 * t2 * i2) / W if W > 0.0 else 0.0
    ddlam = (W + gamma * dW) * (1.0 / alpha_t)
    dgamma = Aref * Aref / (omq * omq)  # d gamma / d q
    return phi, R * F, dphi * dgamma, (Rp * F + R * dF) * ddlam * dgamma


@njit(cache=True)
def _domain_entry(fh1t: float, fh2t: float, fn: float, A1: float, A2: float, Aref: float,
                  surface: int, tear_k: float) -> float:  # fmt: skip
    """q just inside the domain of g on the return path: ``w(q) <= (1 - 5e-4) chi_max f_n``.

    ``w(gamma) = |A_i fhat_i^tr / (A_i^2 + gamma)|`` decreases and is convex in gamma, so
    Newton on ``w(gamma) = (1 - 1e-3) chi_max f_n`` from gamma = 0 (outside) approaches the
    root monotonically from outside and never crosses it; it stops once inside the looser
    bound. For an isotropic surface the first step is exact. Returns -1 when the domain is
    unbounded (cone, Cam-clay surfaces) or the iteration fails.
    """
    if surface == TEAR:
        edge = math.sqrt(2.0 * tear_k + 1.0) * fn
    elif surface == PARABOLA:
        edge = 2.0 * fn
    else:
        return -1.0
    target = (1.0 - 1e-3) * edge
    gamma = 0.0
    for _ in range(60):
        i1 = 1.0 / (A1 * A1 + gamma)
        i2 = 1.0 / (A2 * A2 + gamma)
        v1 = A1 * fh1t * i1
        v2 = A2 * fh2t * i2
        w = _norm(v1, v2)
        if w <= (1.0 - 5e-4) * edge:
            return gamma / (Aref * Aref + gamma)
        dw = -(v1 * v1 * i1 + v2 * v2 * i2) / w  # dw/dgamma < 0
        if not (dw < 0.0 and math.isfinite(dw)):
            return -1.0
        gamma -= (w - target) / dw
    return -1.0


@njit(cache=True)
def _start(
    r0: float, r1: float, phi_tr: float, phi_tr_w: float, w_tr: float, fh1t: float,
    fh2t: float, fn: float, A1: float, A2: float, Aref: float, alpha_t: float,
    surface: int, tear_k: float, R_start: float, y0: float, s0: float, u: float,
    ulaw: int, F_rec: float, Fk: float, kappa: float, m: float,
) -> float:  # fmt: skip
    """Starting value of q for the local solve, from the trial state alone (no residual).

    One Newton step of r(q) from q = 0, whose slope is known there in closed form:
    ``-dPhi/dq = Phi_w W0^2 A_ref^2 / w^tr`` and ``d(dlam)/dq = W0 A_ref^2 / alpha_t``
    with ``W0 = |fhat^tr_i / A_i^2|``, R rising at ``dR/d(dlam) = u cot(pi R_start/2)``
    (or ``-u ln R_start``) and F at ``-kappa phi(F)``. R is concave in dlam, so this
    tangent model stays below the root; so does the model with R = 1 (R never exceeds 1),
    and the larger of the two is taken. A few Newton iterations on the model residual of
    :func:`_model_at` (Phi exact, R and F Taylor polynomials) then leave only the error of
    the truncated Taylor series of R and F. Falls back to regula falsi between r(0) and
    r(1) (when r(1) has been evaluated), then to the return with R F frozen.

    A trial state outside the domain of g (``r0`` infinite: tear and parabola surfaces,
    large steps) starts the model iteration just inside the domain, at the q where the
    returned state crosses ``w = (1 - 1e-3) chi_max f_n`` (:func:`_domain_entry`), and never
    lets it step back out. Returns -1 when that point cannot be found.
    """
    if ulaw == U_COT:
        dR = u * y0 / s0 if s0 > 0.0 else math.inf
    else:
        dR = -u * math.log(R_start) if R_start > 0.0 else math.inf
    phi_soft, dphi_soft = softening_rate(F_rec, Fk, m)
    dF = -kappa * phi_soft
    q_floor = 0.0  # the model iteration stays above it
    iterations = MODEL_ITERATIONS
    if not math.isfinite(r0):
        q = _domain_entry(fh1t, fh2t, fn, A1, A2, Aref, surface, tear_k)
        if not (0.0 < q < 1.0 and math.isfinite(dR)):
            return -1.0
        q_floor = q
        iterations = DOMAIN_MODEL_ITERATIONS
    else:
        A2ref = Aref * Aref
        W0 = _norm(fh1t / (A1 * A1), fh2t / (A2 * A2))
        dphi = phi_tr_w * W0 * W0 / w_tr * A2ref  # -dPhi/dq at q = 0
        ddlam = W0 * A2ref / alpha_t  # d(dlam)/dq at q = 0
        q = -1.0
        den = dphi + (dR * F_rec + R_start * dF) * ddlam
        if den > 0.0 and math.isfinite(den):
            q = r0 / den
        r_sat = phi_tr - F_rec  # r(0) with R = 1
        den_sat = dphi + dF * ddlam
        if r_sat > 0.0 and den_sat > 0.0 and math.isfinite(den_sat):
            q = max(q, r_sat / den_sat)
    if 0.0 < q < 1.0:
        if not math.isfinite(dR):
            return q
        # refine on the model residual: Phi exact (its nonlinearity in q comes from the
        # orthotropy and the closed surfaces' g), R to second order, F to first
        if ulaw == U_COT:  # dR = u cot(pi R/2)
            ddR = -0.5 * math.pi * (u * u + dR * dR) * dR / u
            dddR = -0.5 * math.pi * ddR * (3.0 * dR * dR + u * u) / u
        else:  # implicit Euler R - R0 + u dlam ln R = 0, differentiated at dlam = 0
            ddR = -2.0 * u * dR / R_start
            dddR = 3.0 * u * (dR * dR / R_start - ddR) / R_start
        ddF = -kappa * dphi_soft * dF  # dF = -kappa phi(F)
        # measured (evaluations per sliding point, steps of 1e-3 and 1e-2): Cam-clay
        # 4.2 -> 2.2, tear 7.9/11.2 -> 3.0/2.9; the modified Cam-clay's polynomial g is
        # better served by the plain residual (its worst point 4 -> 8 with the log)
        log_model = surface != COULOMB and surface != MODIFIED_CAM_CLAY
        for _ in range(iterations):
            phi, rf, dphi_q, drf_q = _model_at(q, fh1t, fh2t, fn, A1, A2, Aref, alpha_t,
                                               surface, tear_k, R_start, dR, ddR, dddR,
                                               F_rec, dF, ddF)  # fmt: skip
            if log_model and phi > 0.0 and rf > 0.0:
                # Newton on ln(Phi / (R F)), as the local solve does for the closed
                # surfaces: nearly linear where g grows exponentially (Cam-clay) or has
                # a pole (tear, parabola: the start from the edge of the domain)
                mq = math.log(phi / rf)
                dmq = dphi_q / phi - drf_q / rf
            else:
                mq = phi - rf
                dmq = dphi_q - drf_q
            if not (dmq < 0.0 and math.isfinite(mq) and math.isfinite(dmq)):
                break
            q_new = q - mq / dmq
            if q_new <= q_floor:
                q_new = 0.5 * (q + q_floor)
            elif q_new >= 1.0:
                q_new = 0.5 * (1.0 + q)
            # Newton converges quadratically: after a step of 1e-3 (relative) the iterate
            # is within ~1e-6, below the model's own truncation error, so a further model
            # iteration cannot spare a residual evaluation (measured: the same counts)
            done = abs(q_new - q) <= MODEL_RTOL * min(q_new, 1.0 - q_new)
            q = q_new
            if done:
                break
        return q
    if math.isfinite(r1):
        q = r0 / (r0 - r1)
        if 0.0 < q < 1.0:
            return q
    q = r0 / phi_tr if phi_tr > 0.0 else 0.5
    return q if 0.0 < q < 1.0 else 0.5


@njit(cache=True, inline="always")
def _law(p, ca, sa, surface, tear_k, ulaw, integ, rform):  # fmt: skip
    """The point's constants as a :data:`Law` (``p`` its parameter row, ``(ca, sa)`` the
    cosine and sine of its orthotropy angle; beta in principal axes)."""
    A1 = p[P_A1]
    A2 = p[P_A2]
    return Law(p[P_ALPHA_N], p[P_ALPHA_T], p[P_FS], p[P_FK], p[P_U], p[P_KAPPA], p[P_XI],
               p[P_M], p[P_N], A1, A2, max(A1, A2), p[P_BETA1], p[P_BETA2],
               ca * p[P_BETA1] + sa * p[P_BETA2],
               -sa * p[P_BETA1] + ca * p[P_BETA2], surface, tear_k, ulaw, integ,
               rform)  # fmt: skip


@njit(cache=True, inline="always")
def _trial(law, dt, f1, f2, fn, fn_tr, R_old, F_old, F_rec, gap_old, du1, du2, dun):  # fmt: skip
    """Step 1, the elastic predictor, as the straight trial path of a :data:`Trial`.

    fhat(s) = h + s e, f_n(s) = fn0 + s dfn, s in [0, 1] (principal axes), with the
    derivatives the tangent needs: d e / d du_t = et I, d h / d du_n = hn, d e / d du_n = en,
    d fn0 / d du_n = f0n, d dfn / d du_n = dfnn.
    """
    alpha_n = law.alpha_n
    alpha_t = law.alpha_t
    b1 = law.b1
    b2 = law.b2
    if fn > 0.0:
        et = alpha_t
        f1t = f1 + alpha_t * du1
        f2t = f2 + alpha_t * du2
        h1 = f1 - fn * b1
        h2 = f2 - fn * b2
        fn0 = fn
        hn1 = 0.0
        hn2 = 0.0
        en1 = -alpha_n * b1
        en2 = -alpha_n * b2
        f0n = 0.0
        dfnn = alpha_n
        R_prev = R_old
        F_path = F_old
        dt_path = dt
    else:
        # Re-closing (theory.md, "Re-closing"): the contact forms as a virgin contact,
        # f_t = 0, at the normal traction of the end of the step; only the tangential
        # slip after the closure, the fraction 1 - s_c with s_c = gap/du_n, loads it.
        s_c = gap_old / dun if dun > 0.0 else 0.0
        s_c = min(max(s_c, 0.0), 1.0)
        et = alpha_t * (1.0 - s_c)
        f1t = et * du1
        f2t = et * du2
        h1 = -fn_tr * b1
        h2 = -fn_tr * b2
        fn0 = fn_tr
        hn1 = -alpha_n * b1
        hn2 = -alpha_n * b2
        ds_c = gap_old / (dun * dun) if dun > 0.0 and 0.0 < s_c < 1.0 else 0.0
        en1 = alpha_t * du1 * ds_c
        en2 = alpha_t * du2 * ds_c
        f0n = alpha_n
        dfnn = 0.0
        # No memory: the virgin ratio is the start of the path, never above the surface
        # (R <= 1). The contact forms at the end of the step with the size the opening
        # has recovered to, F_rec: the path starts there and recovers no further.
        R_prev = 1.0
        F_path = F_rec
        dt_path = 0.0
    fh1t = f1t - fn_tr * b1
    fh2t = f2t - fn_tr * b2
    w_tr = _norm(fh1t / law.A1, fh2t / law.A2)
    phi_tr, phi_tr_w, phi_tr_fn = potential(law.surface, law.tear_k, w_tr, fn_tr)
    return Trial(fn_tr, f1t, f2t, fh1t, fh2t, w_tr, phi_tr, phi_tr_w, phi_tr_fn, et, h1, h2,
                 fh1t - h1, fh2t - h2, fn0, fn_tr - fn0, hn1, hn2, en1, en2, f0n, dfnn,
                 hn1 + en1 + alpha_n * b1, hn2 + en2 + alpha_n * b2, R_prev, F_path,
                 dt_path)  # fmt: skip


@njit(cache=True, inline="always")
def _path_at(law, tr, s):  # fmt: skip
    """:func:`_path_ratio` at ``s`` on the trial path ``tr``."""
    return _path_ratio(s, tr.h1, tr.h2, tr.e1, tr.e2, tr.fn0, tr.dfn, law.A1, law.A2,
                       law.surface, law.tear_k, tr.F_path, law.Fs, law.Fk, law.xi, law.m,
                       law.n, tr.dt_path, law.integ, law.rform)  # fmt: skip


@njit(cache=True, inline="always")
def _starting_ratio(law, tr, reclosing, F_rec):  # fmt: skip
    """Step 3, the starting ratio: the smallest Phi/F along the trial path (partial
    unloading, T. Chang's correction; F(s) the recovery-only size over s dt), so that the
    update is continuous in (du, dt) and equals what many small steps do. A :data:`Start`.
    """
    A1 = law.A1
    A2 = law.A2
    R_start = tr.R_prev
    corrected = False
    gR1 = 0.0  # gradient of R_start with respect to (du1, du2, dun), principal axes
    gR2 = 0.0
    gRn = 0.0
    w0 = _norm(tr.h1 / A1, tr.h2 / A2)
    phi0, phi0_w, phi0_fn = potential(law.surface, law.tear_k, w0, tr.fn0)
    dF0 = _path_size_slope(tr.F_path, 0.0, law.Fs, law.xi, law.n, tr.dt_path, law.integ,
                           law.rform)  # fmt: skip
    r_0, d_0 = _ratio_slope(phi0, phi0_w, phi0_fn, w0, tr.h1, tr.h2, tr.e1, tr.e2, tr.dfn,
                            A1, A2, tr.F_path, dF0)  # fmt: skip
    dF1 = _path_size_slope(F_rec, 1.0, law.Fs, law.xi, law.n, tr.dt_path, law.integ,
                           law.rform)  # fmt: skip
    r_1, d_1 = _ratio_slope(tr.phi_tr, tr.phi_tr_w, tr.phi_tr_fn, tr.w_tr, tr.fh1t, tr.fh2t,
                            tr.e1, tr.e2, tr.dfn, A1, A2, F_rec, dF1)  # fmt: skip
    s_star = _path_minimum(tr.h1, tr.h2, tr.e1, tr.e2, tr.fn0, tr.dfn, A1, A2, law.surface,
                           law.tear_k, tr.F_path, law.Fs, law.Fk, law.xi, law.m, law.n,
                           tr.dt_path, law.integ, law.rform, r_0, d_0, r_1, d_1)  # fmt: skip
    if s_star == 0.0:
        rho = r_0
    elif s_star == 1.0:
        rho = r_1  # phi_tr / F_rec: the same number as the loading test
    else:
        rho = math.inf
    at = PathPoint(rho, 0.0, F_rec, 0.0, 0.0, 0.0, 0.0, 0.0)
    if 0.0 < s_star < 1.0:
        at = _path_at(law, tr, s_star)
    # A re-closing path starts at the virgin point of the end-of-step normal traction: its
    # ratio rho(0) depends on du_n, and so does R_start when the minimum is at s* = 0.
    reclosing_start = reclosing and s_star == 0.0
    if reclosing_start:
        at = PathPoint(rho, 0.0, tr.F_path, phi0_w, phi0_fn, w0, tr.h1, tr.h2)
    if at.rho < R_start:
        R_start = at.rho
        if 0.0 < s_star < 1.0 or reclosing_start:
            corrected = True
            # envelope theorem: d rho(s*)/d du at fixed s* (rho'(s*) = 0, or s* = 0 held)
            if at.w > 0.0:
                # q_i / w first: |q_i / w| <= A_i, while A_i^2 w can underflow
                u1 = at.q1 / at.w / (A1 * A1)
                u2 = at.q2 / at.w / (A2 * A2)
            else:
                u1 = 0.0
                u2 = 0.0
            gR1 = at.phi_w * u1 * s_star * tr.et / at.F
            gR2 = at.phi_w * u2 * s_star * tr.et / at.F
            gRn = (at.phi_w * (u1 * (tr.hn1 + s_star * tr.en1) + u2 * (tr.hn2 + s_star * tr.en2))
                   + at.phi_fn * (tr.f0n + s_star * tr.dfnn)) / at.F  # fmt: skip
    return Start(R_start, corrected, gR1, gR2, gRn)


@njit(cache=True, inline="always")
def _elastic(law, tr, F_rec, ca, sa, old, want_tangent):  # fmt: skip
    """Step 4's elastic outcome: the trial state, R = Phi/F (FAILED outside a closed surface)."""
    R_new = tr.phi_tr / F_rec
    if law.surface != COULOMB and R_new > 1.0 + RTOL_ACCEPT:
        # normal traction pushed the state outside a closed surface: the rate form has
        # no tangential mechanism that could bring it back
        return _failed(0, old, law, want_tangent)
    if R_new > 1.0:
        R_new = 1.0
    f1t = tr.f1t
    f2t = tr.f2t
    # f_t = et du_t: d f_t / d du_n = alpha_t du_t gap / du_n^2 when closing
    if want_tangent:
        return _result(STICK, 0, ca * f1t - sa * f2t, sa * f1t + ca * f2t, tr.fn_tr, F_rec,
                       R_new, 0.0, k00=tr.et, k11=tr.et, k02=ca * tr.ext1 - sa * tr.ext2,
                       k12=sa * tr.ext1 + ca * tr.ext2, k22=law.alpha_n)  # fmt: skip
    return _result(STICK, 0, ca * f1t - sa * f2t, sa * f1t + ca * f2t, tr.fn_tr, F_rec,
                   R_new, 0.0)  # fmt: skip


@njit(cache=True, inline="always")
def _residual(law, tr, q, omq, R_start, y0, s0, F_old, dt):  # fmt: skip
    """:func:`_state_at` for the trial state ``tr``: the corrector's :data:`Residual`."""
    return _state_at(q, omq, tr.fh1t, tr.fh2t, tr.fn_tr, law.A1, law.A2, law.Aref,
                     law.alpha_t, law.surface, law.tear_k, R_start, y0, s0, law.u, law.ulaw,
                     F_old, law.Fs, law.Fk, law.kappa, law.xi, law.m, law.n, dt, law.integ,
                     law.rform)  # fmt: skip


@njit(cache=True, inline="always")
def _plastic(law, tr, st, r0, F_old, F_rec, dt, ca, sa, old, want_tangent):  # fmt: skip
    """Step 5, the plastic corrector on the bracket [0, 1] in q: r(0) = r0 > 0 (the loading
    test), r(1) < 0 (checked here); then steps 6 and 7."""
    R_start = st.R_start
    y0, s0 = ratio_start(law.ulaw, R_start)  # cos/sin of pi R_start/2 once per point
    # At q = 1 (fhat = 0) Phi is 0 (cone) or f_n g(0) = f_n (closed surfaces), while
    # R F >= R_start F_k (R only grows with dlam, F never leaves [F_k, F_s]): r(1) < 0 is
    # then known without evaluating it, and the evaluation is only needed otherwise.
    if law.surface == COULOMB:
        need_end = not R_start > 0.0
    else:
        need_end = not tr.fn_tr < 0.999 * R_start * law.Fk
    r1 = -math.inf
    if need_end:
        end = _residual(law, tr, 1.0, 0.0, R_start, y0, s0, F_old, dt)
        r1 = end.r
        if not r1 < 0.0:
            # Even a full return to the rotated axis (fhat = 0) cannot absorb the rise of
            # f: only possible for a closed surface loaded normally with a small tangential
            # traction. The rate form flows until fhat = 0 and is elastic afterwards (no
            # tangential mechanism left), so R = f_n g(0)/F if that is <= 1.
            R_end = end.phi / end.F
            if law.surface == COULOMB or R_end > 1.0 + RTOL_ACCEPT:
                return _failed(0, old, law, want_tangent)
            norm = _norm(tr.fh1t, tr.fh2t)
            # f_t = f_n beta: independent of du_t
            k02 = law.alpha_n * law.beta1 if want_tangent else 0.0
            k12 = law.alpha_n * law.beta2 if want_tangent else 0.0
            return _slip(0, end.dlam, tr.fn_tr * law.b1, tr.fn_tr * law.b2, tr.fh1t / norm,
                         tr.fh2t / norm, tr.fn_tr, end.F, min(R_end, 1.0), ca, sa,
                         Tangent(0.0, 0.0, 0.0, 0.0, k02, k12,
                                 law.alpha_n if want_tangent else 0.0))  # fmt: skip
    q0 = _start(r0, r1, tr.phi_tr, tr.phi_tr_w, tr.w_tr, tr.fh1t, tr.fh2t, tr.fn_tr, law.A1,
                law.A2, law.Aref, law.alpha_t, law.surface, law.tear_k, R_start, y0, s0,
                law.u, law.ulaw, F_rec, law.Fk, law.kappa, law.m)  # fmt: skip
    if q0 < 0.0:  # trial outside the domain of g: locate the root's half first
        mid = _residual(law, tr, 0.5, 0.5, R_start, y0, s0, F_old, dt).r
        q0 = 0.75 if mid > 0.0 else 0.25
    sol = _solve(law, tr, q0, R_start, y0, s0, F_old, dt)
    if not sol.converged:
        return _failed(sol.iterations, old, law, want_tangent)
    res = sol.res
    d1, d2, a1, a2, fh1, fh2 = _returned(tr.fh1t, tr.fh2t, law.A1, law.A2, res.gamma)
    # 6. update (principal axes)
    tb1 = (tr.fh1t / d1) / res.W  # flow direction t-bar at t_{n+1}, Eqs (87), (99)
    tb2 = (tr.fh2t / d2) / res.W
    k = Tangent(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if want_tangent:
        k = _tangent(law, tr, st, res, y0, s0, d1, d2, a1, a2, fh1, fh2, ca, sa)
    return _slip(sol.iterations, res.dlam, tr.fn_tr * law.b1 + fh1, tr.fn_tr * law.b2 + fh2,
                 tb1, tb2, tr.fn_tr, res.F, res.R, ca, sa, k)  # fmt: skip


@njit(cache=True, inline="always")
def _solve(law, tr, q0, R_start, y0, s0, F_old, dt):  # fmt: skip
    """The local solve of step 5 from ``q0``: a :data:`Solution`.

    Unknown t in [0, 1/2]: q = t, or 1 - q = t when q lies in the upper half (switched as
    the iterates move), so that a return almost to the axis (q -> 1) keeps full precision.
    """
    flip = q0 > 0.5
    dqdt = -1.0 if flip else 1.0
    t = 1.0 - q0 if flip else q0
    t_pos = 1.0 if flip else 0.0  # end of the bracket with r > 0 (q = 0)
    t_neg = 0.0 if flip else 1.0  # end with r < 0 (q = 1)
    log_newton = law.surface != COULOMB
    Aref = law.Aref
    converged = False
    it = 0
    dx = 1.0
    dx_old = 1.0
    q = 1.0 - t if flip else t
    omq = t if flip else 1.0 - t
    res = _residual(law, tr, q, omq, R_start, y0, s0, F_old, dt)
    while it < MAX_ITERATIONS:
        it += 1
        r = res.r
        scale = max(res.F, 1e-300)
        if abs(r) <= RTOL_RESIDUAL * scale:
            converged = True
            break
        if r > 0.0:
            t_pos = t
        else:
            t_neg = t
        lo = min(t_pos, t_neg)
        hi = max(t_pos, t_neg)
        if hi - lo <= 4e-16 * max(hi, 1e-300):
            # the bracket has collapsed to round-off: the residual cannot fall below
            # the rounding of Phi, ~ eps Phi_w w (large near the apex of the tear
            # or the parabola, where f_n << F; theory.md, "Accuracy")
            cond = abs(res.cond) if math.isfinite(res.cond) else 0.0
            converged = abs(r) <= RTOL_ACCEPT * max(scale, cond)
            break
        # Newton, safeguarded as in rtsafe: bisect when the step leaves the bracket or
        # does not at least halve the step before last. For the cone on the residual
        # itself (Phi is linear in q for an isotropic cone); for the closed surfaces, whose
        # Phi grows steeply with w, on ln(Phi / (R F)), which has the same root and sign
        # (nearly linear for the exponential Cam-clay surface).
        dgdt = Aref * Aref / (omq * omq) * dqdt  # d gamma / d t
        t_new = -1.0
        if log_newton:
            phi = res.phi
            rf = res.R * res.F
            if phi > 0.0 and math.isfinite(phi) and rf > 0.0:
                dlog = (res.phi_gamma / phi - res.rf_gamma / rf) * dgdt
                if dlog != 0.0 and math.isfinite(dlog):
                    t_new = t - math.log(phi / rf) / dlog
        else:
            slope = res.r_gamma * dgdt
            if slope != 0.0 and math.isfinite(slope) and math.isfinite(r):
                t_new = t - r / slope
        if not (lo < t_new < hi) or abs(t_new - t) > 0.5 * abs(dx_old):
            t_new = 0.5 * (lo + hi)
        dx_old = dx
        dx = t_new - t
        t = t_new
        if t > 0.5:
            # keep the smaller of q and 1 - q as the unknown, so that a root near either
            # end is resolved to full precision (1 - t is exact here)
            flip = not flip
            dqdt = -dqdt
            t = 1.0 - t
            t_pos = 1.0 - t_pos
            t_neg = 1.0 - t_neg
        q = 1.0 - t if flip else t
        omq = t if flip else 1.0 - t
        res = _residual(law, tr, q, omq, R_start, y0, s0, F_old, dt)
    return Solution(converged, it, res)


@njit(cache=True, inline="always")
def _tangent(law, tr, st, res, y0, s0, d1, d2, a1, a2, fh1, fh2, ca, sa):  # fmt: skip
    """Step 7, the consistent tangent (contact frame) by implicit differentiation of
    r(gamma; fhat^tr, f_n) = 0: a :data:`Tangent`."""
    alpha_n = law.alpha_n
    b1 = law.b1
    b2 = law.b2
    gamma = res.gamma
    W = res.W
    hard = res.hard
    r_gamma = res.r_gamma
    # r_fhtr_j = Phi_j a_j - hard * d(dlam)/d(fhat^tr_j)
    ddl1 = gamma * (tr.fh1t / (d1 * d1)) / (W * law.alpha_t)
    ddl2 = gamma * (tr.fh2t / (d2 * d2)) / (W * law.alpha_t)
    c1 = (res.phi_1 * a1 - hard * ddl1) / r_gamma
    c2 = (res.phi_2 * a2 - hard * ddl2) / r_gamma
    cn = res.phi_fn / r_gamma
    G1 = -fh1 / d1
    G2 = -fh2 / d2
    # d g / d fhat^tr (2x2) and d g / d f_n (explicit)
    j11 = a1 - G1 * c1
    j12 = -G1 * c2
    j21 = -G2 * c1
    j22 = a2 - G2 * c2
    jn1 = b1 - G1 * cn
    jn2 = b2 - G2 * cn
    # d fhat^tr = alpha_t d du_t - beta alpha_n d du_n ; d f_n = alpha_n d du_n
    et = tr.et
    T11 = et * j11
    T12 = et * j12
    T21 = et * j21
    T22 = et * j22
    T1n = alpha_n * (jn1 - j11 * b1 - j12 * b2) + j11 * tr.ext1 + j12 * tr.ext2
    T2n = alpha_n * (jn2 - j21 * b1 - j22 * b2) + j21 * tr.ext1 + j22 * tr.ext2
    if st.corrected:  # R_start depends on du: r_R0 = -F dR/dR0
        dR0 = ratio_sensitivity(law.ulaw, law.u, y0, s0, res.dlam, res.R)
        cR = -res.F * dR0 / r_gamma
        T11 -= G1 * cR * st.gR1
        T12 -= G1 * cR * st.gR2
        T21 -= G2 * cR * st.gR1
        T22 -= G2 * cR * st.gR2
        T1n -= G1 * cR * st.gRn
        T2n -= G2 * cR * st.gRn
    # back to the contact frame: T_c = Q^T T_p Q, Q = [[ca, sa], [-sa, ca]]
    p11 = ca * T11 - sa * T21
    p12 = ca * T12 - sa * T22
    p21 = sa * T11 + ca * T21
    p22 = sa * T12 + ca * T22
    return Tangent(p11 * ca - p12 * sa, p11 * sa + p12 * ca, p21 * ca - p22 * sa,
                   p21 * sa + p22 * ca, ca * T1n - sa * T2n, sa * T1n + ca * T2n,
                   alpha_n)  # fmt: skip


@njit(cache=True)
def _point(
    dt, ca, sa, p, t1_old, t2_old, fn, F_old, R_old, gap_old, slip1, slip2, dun,
    surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
):  # fmt: skip
    """Advance one point by one increment (time increment ``dt`` [s]).

    The readable per-point definition of the update (steps 0-7 of the module docstring,
    one named step each); :func:`step_points` and :func:`step_points_parallel` only loop
    over it. Scalars in, scalars out: the point's old traction ``(t1_old, t2_old, fn)``
    [Pa] in the contact frame, its ``F_old`` [Pa], ``R_old``, ``gap_old`` [m], its slip
    increment ``(slip1, slip2, dun)`` [m] and ``p``, its row of the parameter table as a
    tuple (columns ``P_*``). ``(ca, sa)`` are the cosine and sine of the row's orthotropy
    angle (evaluated once by the loops when all points share one row). No array is passed
    in, so that the compiled loop does no reference counting per point (atomic operations
    that cost a third of the kernel's time and serialise the threads); the steps pass
    named tuples, which are values too.

    Returns a :data:`Result`: status, iterations, the new traction (contact frame), F, R,
    gap, dlam, plastic slip increment (two tangential components), plastic work
    increment, then the seven possibly non-zero entries of the consistent tangent
    (``k00, k01, k10, k11, k02, k12, k22``; zero when ``want_tangent`` is False).
    """
    law = _law(p, ca, sa, surface, tear_k, ulaw, integ, rform)
    old = Old(t1_old, t2_old, fn, F_old, R_old, gap_old)
    # 0. into principal axes (contact frame -> (e*_1, e*_2))
    f1 = ca * t1_old + sa * t2_old
    f2 = -sa * t1_old + ca * t2_old
    du1 = ca * slip1 + sa * slip2
    du2 = -sa * slip1 + ca * slip2
    # 2. recovery-only size
    F_rec = recovered_size(F_old, law.Fs, law.Fk, law.xi, law.m, law.n, dt, integ, rform)
    # 1. elastic predictor and separation: a trial normal traction that is zero to
    #    the rounding of its own computation opens the contact
    closing_in = law.alpha_n * (dun - gap_old)
    fn_tr = fn + closing_in
    if fn_tr <= SEPARATION_RTOL * max(abs(fn), abs(closing_in)):
        return _result(OPEN, 0, 0.0, 0.0, 0.0, F_old if open_frozen else F_rec, 0.0,
                       max(-fn_tr / law.alpha_n, 0.0))  # fmt: skip
    tr = _trial(law, dt, f1, f2, fn, fn_tr, R_old, F_old, F_rec, gap_old, du1, du2, dun)
    # 3. starting ratio (partial unloading)
    st = _starting_ratio(law, tr, fn <= 0.0, F_rec)
    # 4. loading test on the trial state
    r0 = tr.phi_tr - st.R_start * F_rec
    if tr.w_tr == 0.0 or r0 <= RTOL_RESIDUAL * F_rec:
        return _elastic(law, tr, F_rec, ca, sa, old, want_tangent)
    # 5.-7. plastic corrector, update, consistent tangent
    return _plastic(law, tr, st, r0, F_old, F_rec, dt, ca, sa, old, want_tangent)


@njit(cache=True)
def _axes(P, row):  # fmt: skip
    """Cosine and sine of the orthotropy angle of parameter row ``row``."""
    return math.cos(P[row, P_ANGLE]), math.sin(P[row, P_ANGLE])


@njit(cache=True)
def step_points_by_point(
    traction, F_old, R_old, gap_old, slip_inc, dt_arr, P, n_shared_dt,
    surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """The readable reference of :func:`step_points`: every point through :func:`_point`.

    ``P`` is the parameter table (1 or N rows, columns ``P_*``); ``dt_arr`` has 1 or N
    entries. Failed points keep their old state, get the elastic tangent and status
    FAILED; no NaN is ever written. ``out_tangent`` may have zero rows when
    ``want_tangent`` is False.
    """
    _by_point(0, traction.shape[0], traction, F_old, R_old, gap_old, slip_inc, dt_arr, P,
              n_shared_dt, surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
              out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
              out_status, out_iter)  # fmt: skip


@njit(cache=True)
def _by_point(
    first, stop, traction, F_old, R_old, gap_old, slip_inc, dt_arr, P, n_shared_dt,
    surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """Points ``first`` to ``stop - 1`` through :func:`_point`, one at a time (serial).

    The array reads and writes stay in the loop: a helper taking the arrays, called per
    point, would be reference-counted on every point.
    """
    shared_p = P.shape[0] == 1
    ca0, sa0 = _axes(P, 0) if shared_p else (1.0, 0.0)
    for i in range(first, stop):
        row = 0 if shared_p else i
        dt = dt_arr[0] if n_shared_dt else dt_arr[i]
        ca, sa = (ca0, sa0) if shared_p else _axes(P, row)
        res = _point(dt, ca, sa, _row(P, row), traction[i, 0], traction[i, 1],
                     traction[i, 2], F_old[i], R_old[i], gap_old[i], slip_inc[i, 0],
                     slip_inc[i, 1], slip_inc[i, 2], surface, tear_k, ulaw, integ, rform,
                     open_frozen, want_tangent)  # fmt: skip
        _store(i, res, want_tangent, out_traction, out_F, out_R, out_gap, out_dlam, out_vp,
               out_diss, out_tangent, out_status, out_iter)  # fmt: skip


@njit(cache=True, error_model="numpy")
def step_points(
    traction, F_old, R_old, gap_old, slip_inc, dt_arr, P, n_shared_dt,
    surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """Advance every point by one increment; results go to the ``out_*`` arrays (serial).

    The numbers of :func:`step_points_by_point` (same arguments) to rounding, computed in
    groups of LANES points where the call is one the lanes cover (see "lanes" below).
    ``error_model="numpy"``: the lanes evaluate both sides of a guarded division and
    keep one; _point, compiled on its own, still raises on a division by zero.
    """
    npts = traction.shape[0]
    first = 0
    if _in_lanes(P, n_shared_dt, surface, ulaw, integ, rform):
        first = npts - npts % LANES
        _lanes_task(0, first, traction, F_old, R_old, gap_old, slip_inc, dt_arr, P, surface,
                    tear_k, ulaw, integ, rform, open_frozen, want_tangent, out_traction,
                    out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
                    out_status, out_iter)  # fmt: skip
    _by_point(first, npts, traction, F_old, R_old, gap_old, slip_inc, dt_arr, P,
              n_shared_dt, surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
              out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
              out_status, out_iter)  # fmt: skip


#: Groups of LANES points per task of the parallel loop (one scratch array per task).
GROUPS_PER_TASK = 64


@njit(cache=True, error_model="numpy")
def _lanes_task(
    first, stop, traction, F_old, R_old, gap_old, slip_inc, dt_arr, P,
    surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """Points ``first`` to ``stop - 1`` (a multiple of LANES apart) in groups of LANES,
    with the call's shared constants and one scratch array."""
    dt = dt_arr[0]
    law, p, ca, sa, e_rec, ext1, ext2 = _call_constants(P, dt, surface, tear_k, ulaw, integ,
                                                        rform)  # fmt: skip
    v = np.zeros(N_ROWS * LANES)
    for base in range(first, stop, LANES):
        _lanes_group(base, v, law, p, ca, sa, dt, e_rec, ext1, ext2, traction, F_old,
                     R_old, gap_old, slip_inc, surface, tear_k, ulaw, integ, rform,
                     open_frozen, want_tangent, out_traction, out_F, out_R, out_gap,
                     out_dlam, out_vp, out_diss, out_tangent, out_status,
                     out_iter)  # fmt: skip


@njit(cache=True, parallel=True, error_model="numpy")
def step_points_parallel(
    traction, F_old, R_old, gap_old, slip_inc, dt_arr, P, n_shared_dt,
    surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """:func:`step_points` with the points shared among numba's threads (``prange``).

    The points are independent and each writes only its own output rows, so the result
    is identical to the serial loop. The loop index is cast to int64: ``prange``
    yields an unsigned index, and ``0 if shared else i`` would otherwise unify to float64.
    """
    npts = traction.shape[0]
    if _in_lanes(P, n_shared_dt, surface, ulaw, integ, rform):
        groups = npts // LANES
        tasks = (groups + GROUPS_PER_TASK - 1) // GROUPS_PER_TASK
        for k in prange(tasks):
            first = np.int64(k) * GROUPS_PER_TASK * LANES
            stop = min(first + GROUPS_PER_TASK * LANES, groups * LANES)
            _lanes_task(first, stop, traction, F_old, R_old, gap_old, slip_inc, dt_arr, P,
                        surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
                        out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss,
                        out_tangent, out_status, out_iter)  # fmt: skip
        _by_point(groups * LANES, npts, traction, F_old, R_old, gap_old, slip_inc, dt_arr, P,
                  n_shared_dt, surface, tear_k, ulaw, integ, rform, open_frozen,
                  want_tangent, out_traction, out_F, out_R, out_gap, out_dlam, out_vp,
                  out_diss, out_tangent, out_status, out_iter)  # fmt: skip
        return
    shared_p = P.shape[0] == 1
    ca0, sa0 = _axes(P, 0) if shared_p else (1.0, 0.0)
    for k in prange(npts):
        i = np.int64(k)
        row = np.int64(0) if shared_p else i
        dt = dt_arr[0] if n_shared_dt else dt_arr[i]
        ca, sa = (ca0, sa0) if shared_p else _axes(P, row)
        res = _point(dt, ca, sa, _row(P, row), traction[i, 0], traction[i, 1],
                     traction[i, 2], F_old[i], R_old[i], gap_old[i], slip_inc[i, 0],
                     slip_inc[i, 1], slip_inc[i, 2], surface, tear_k, ulaw, integ, rform,
                     open_frozen, want_tangent)  # fmt: skip
        _store(i, res, want_tangent, out_traction, out_F, out_R, out_gap, out_dlam, out_vp,
               out_diss, out_tangent, out_status, out_iter)  # fmt: skip


@njit(cache=True)
def _result(status, iterations, t1, t2, tn, F, R, gap, dlam=0.0, vp1=0.0, vp2=0.0, diss=0.0,
            k00=0.0, k01=0.0, k10=0.0, k11=0.0, k02=0.0, k12=0.0, k22=0.0):  # fmt: skip
    """The :data:`Result` of :func:`_point`."""
    return Result(status, iterations, t1, t2, tn, F, R, gap, dlam, vp1, vp2, diss,
                  k00, k01, k10, k11, k02, k12, k22)  # fmt: skip


@njit(cache=True)
def _slip(iterations, dlam, g1, g2, tb1, tb2, fn, F, R, ca, sa, k):  # fmt: skip
    """A plastic result given in principal axes: traction (g1, g2, fn), flow t-bar; the
    :data:`Tangent` ``k`` already in the contact frame."""
    return _result(SLIP, iterations, ca * g1 - sa * g2, sa * g1 + ca * g2, fn, F, R, 0.0,
                   dlam, dlam * (ca * tb1 - sa * tb2), dlam * (sa * tb1 + ca * tb2),
                   dlam * (g1 * tb1 + g2 * tb2), k.k00, k.k01, k.k10, k.k11, k.k02, k.k12,
                   k.k22)  # fmt: skip


@njit(cache=True)
def _failed(iterations, old, law, want_tangent):  # fmt: skip
    """A failed point keeps its :data:`Old` state and gets the elastic tangent (never NaN)."""
    if want_tangent:
        return _result(FAILED, iterations, old.t1, old.t2, old.fn, old.F, old.R, old.gap,
                       k00=law.alpha_t, k11=law.alpha_t, k22=law.alpha_n)  # fmt: skip
    return _result(FAILED, iterations, old.t1, old.t2, old.fn, old.F, old.R, old.gap)


@njit(cache=True)
def _row(P, row):  # fmt: skip
    """Row ``row`` of the parameter table as a tuple (a value: no reference counting)."""
    return (P[row, 0], P[row, 1], P[row, 2], P[row, 3], P[row, 4], P[row, 5], P[row, 6],
            P[row, 7], P[row, 8], P[row, 9], P[row, 10], P[row, 11], P[row, 12],
            P[row, 13])  # fmt: skip


@njit(cache=True)
def _store(i, res, want_tangent, out_traction, out_F, out_R, out_gap, out_dlam, out_vp,
           out_diss, out_tangent, out_status, out_iter):  # fmt: skip
    """Write the :data:`Result` of :func:`_point` to row ``i`` of the outputs."""
    out_status[i] = res.status
    out_iter[i] = res.iterations
    out_traction[i, 0] = res.t1
    out_traction[i, 1] = res.t2
    out_traction[i, 2] = res.tn
    out_F[i] = res.F
    out_R[i] = res.R
    out_gap[i] = res.gap
    out_dlam[i] = res.dlam
    out_vp[i, 0] = res.vp1
    out_vp[i, 1] = res.vp2
    out_vp[i, 2] = 0.0
    out_diss[i] = res.diss
    if want_tangent:
        out_tangent[i, 0, 0] = res.k00
        out_tangent[i, 0, 1] = res.k01
        out_tangent[i, 1, 0] = res.k10
        out_tangent[i, 1, 1] = res.k11
        out_tangent[i, 0, 2] = res.k02
        out_tangent[i, 1, 2] = res.k12
        out_tangent[i, 2, 0] = 0.0
        out_tangent[i, 2, 1] = 0.0
        out_tangent[i, 2, 2] = res.k22


def empty_outputs(n_points: int, tangent: bool = True) -> dict[str, np.ndarray]:
    """Allocate the output arrays of :func:`step_points` (no tangent rows if not wanted).

    Also a ``plastic_slip`` buffer, used by ``update(..., out=...)`` for the new state.
    """
    return {
        "plastic_slip": np.empty(n_points),
        "traction": np.empty((n_points, 3)),
        "F": np.empty(n_points),
        "R": np.empty(n_points),
        "gap": np.empty(n_points),
        "dlam": np.empty(n_points),
        "vp": np.empty((n_points, 3)),
        "diss": np.empty(n_points),
        "tangent": np.empty((n_points if tangent else 0, 3, 3)),
        "status": np.empty(n_points, dtype=np.int8),
        "iterations": np.empty(n_points, dtype=np.int32),
    }


# ============================================================================ lanes
# step_points and step_points_parallel process the points in groups of LANES, one step
# of the law at a time for the whole group, so that the compiled code evaluates a step's
# divisions and square roots for several points in packed (SIMD) instructions instead of
# waiting on each point's chain of dependent scalar ones. Each lane performs the very
# operations of _point in the same order (where the paths differ, both are computed and
# one is selected; a finished lane's values are kept by selects). What the lanes do not
# cover goes to _point itself: opening and re-closing points, a non-monotone trial path
# (the scan of _path_minimum), a solve that has not converged, squares outside the range
# of _norm's plain sqrt, a lane outside the range of a lane_math function, and the
# options other than the defaults (per-point parameters or time increments, the closed
# surfaces, the ln law, backward Euler, exponents other than 1, the ratio recovery form).
# The elementary functions are inline polynomials (lane_math, within 2 ulp), so the lanes
# differ from _point by rounding only (tests/subloading/test_kernel_agreement.py).

#: Points processed together: LLVM vectorises no loop of fewer than 16 iterations.
LANES = 16
#: What a lane does: the elastic outcome, the plastic corrector, or _point (BY_POINT).
ELASTIC, PLASTIC, BY_POINT = 0, 1, 2
#: Rows of the lane scratch, a flat array of N_ROWS x LANES values (one value per lane):
#: row R of lane j is v[R + j]. Flat, so that the compiled code knows every row's offset
#: and can prove that the rows do not overlap (a 2-D array's row stride is a run-time
#: value, and the vectoriser then gives up on a loop that touches many rows).
(V_F1T, V_F2T, V_FN_TR, V_FH1T, V_FH2T, V_W_TR, V_PHI_TR, V_F_OLD, V_F_REC, V_R_START,
 V_R0, V_Y0, V_S0, V_Q, V_T, V_T_POS, V_T_NEG, V_DX, V_DX_OLD, V_FLIP, V_OMQ, V_GAMMA,
 V_I1, V_I2, V_T1, V_T2, V_W, V_DLAM, V_WN, V_ARG_R, V_A, V_EM_R, V_EM_F, V_Y, V_S,
 V_ATAN, V_R, V_F, V_RES, V_R_GAMMA, V_PHI_1, V_PHI_2, V_HARD, V_COND, V_PHI_FN, V_DR,
 V_DDR, V_DDDR, V_DF, V_DDF, V_KIND, V_ACTIVE, V_ITER, V_T1_OLD, V_T2_OLD, V_FN,
 V_R_OLD, V_GAP_OLD, V_SLIP1, V_SLIP2, V_DUN, V_DARG_R, V_DA, V_STEP_OK, V_OUT_T1,
 V_OUT_T2, V_OUT_F, V_OUT_R, V_OUT_DLAM, V_OUT_VP1, V_OUT_VP2, V_OUT_DISS, V_OUT_K00,
 V_OUT_K01, V_OUT_K10, V_OUT_K11, V_OUT_K02, V_OUT_K12, V_PHI_W) = range(0, 79 * LANES,
                                                                     LANES)  # fmt: skip
N_ROWS = 79


@njit(cache=True, inline="always")
def _plain_norm(x, y):  # fmt: skip
    """:func:`_norm` and whether it was the plain square root (else: BY_POINT)."""
    s = x * x + y * y
    return math.sqrt(s), (1e-290 < s < 1e290) or s == 0.0


@njit(cache=True, inline="always")
def _lane_slope(phi, phi_w, phi_fn, w, q1, q2, e1, e2, dfn, A1, A2, F, dF):  # fmt: skip
    """:func:`_ratio_slope` as a lane: (rho, drho, plain norm)."""
    dw_axis, plain = _plain_norm(e1 / A1, e2 / A2)
    dw = ((q1 / A1) * (e1 / A1) + (q2 / A2) * (e2 / A2)) / w if w > 0.0 else dw_axis
    rho = phi / F
    drho = (phi_w * dw + phi_fn * dfn) / F - rho * dF / F
    finite = math.isfinite(phi)
    return (rho if finite else math.inf), (drho if finite else math.inf), plain or w > 0.0


@njit(cache=True, inline="always")
def _lane_trial(law, ca, sa, dt, e_rec, t1_old, t2_old, fn, F_old, R_old, gap_old, slip1,
                slip2, dun):  # fmt: skip
    """Steps 0-4 of :func:`_point` on the cone as a lane: the trial state, the starting
    ratio of a monotone trial path, the loading test. ``e_rec = exp(-xi dt/F_s)``.

    Returns (kind, f1t, f2t, fn_tr, fh1t, fh2t, w_tr, phi_tr, F_rec, R_start, r0,
    Phi_w = 1/fn_tr), the last once per point for every residual of the cone.
    """
    f1 = ca * t1_old + sa * t2_old
    f2 = -sa * t1_old + ca * t2_old
    du1 = ca * slip1 + sa * slip2
    du2 = -sa * slip1 + ca * slip2
    F0 = min(max(F_old, law.Fk), law.Fs)  # recovered_size, exponential, 1 - F/F_s, n = 1
    recovering = not (law.xi == 0.0 or dt == 0.0)
    F_rec = law.Fs * (1.0 - max(1.0 - F0 / law.Fs, 0.0) * e_rec) if recovering else F0
    closing_in = law.alpha_n * (dun - gap_old)
    fn_tr = fn + closing_in
    by_point = fn <= 0.0 or fn_tr <= SEPARATION_RTOL * max(abs(fn), abs(closing_in))
    f1t = f1 + law.alpha_t * du1
    f2t = f2 + law.alpha_t * du2
    h1 = f1 - fn * law.b1
    h2 = f2 - fn * law.b2
    fh1t = f1t - fn_tr * law.b1
    fh2t = f2t - fn_tr * law.b2
    e1 = fh1t - h1
    e2 = fh2t - h2
    dfn = fn_tr - fn
    w_tr, plain = _plain_norm(fh1t / law.A1, fh2t / law.A2)
    inv = 1.0 / fn_tr if fn_tr > 0.0 else 0.0
    phi_tr = w_tr * inv
    # step 3 with s* at an end of the path (the monotone cases of _path_minimum)
    inv0 = 1.0 / fn if fn > 0.0 else 0.0
    w0, plain0 = _plain_norm(h1 / law.A1, h2 / law.A2)
    phi0 = w0 * inv0
    x_old = 1.0 - F_old / law.Fs
    x_rec = 1.0 - F_rec / law.Fs
    dF0 = law.xi * dt * (x_old if x_old > 0.0 else 0.0)
    dF1 = law.xi * dt * (x_rec if x_rec > 0.0 else 0.0)
    r_0, d_0, plain_0 = _lane_slope(phi0, inv0, -phi0 * inv0, w0, h1, h2, e1, e2, dfn,
                                    law.A1, law.A2, F_old, dF0)  # fmt: skip
    r_1, d_1, plain_1 = _lane_slope(phi_tr, inv, -phi_tr * inv, w_tr, fh1t, fh2t, e1, e2,
                                    dfn, law.A1, law.A2, F_rec, dF1)  # fmt: skip
    forward = d_0 >= 0.0 and d_1 >= 0.0 and r_1 >= r_0
    monotone = forward or (d_0 <= 0.0 and d_1 <= 0.0 and r_1 <= r_0)
    rho = r_0 if forward else r_1
    R_start = rho if rho < R_old else R_old
    r0 = phi_tr - R_start * F_rec
    elastic = w_tr == 0.0 or r0 <= RTOL_RESIDUAL * F_rec
    plain = plain and plain0 and plain_0 and plain_1
    by_point = by_point or not (plain and monotone) or not (elastic or R_start > 0.0)
    kind = BY_POINT if by_point else (ELASTIC if elastic else PLASTIC)
    return kind, f1t, f2t, fn_tr, fh1t, fh2t, w_tr, phi_tr, F_rec, R_start, r0, inv


@njit(cache=True, error_model="numpy")
def _lanes_trial(v, base, law, ca, sa, dt, e_rec, traction, F_old, R_old, gap_old,
                 slip_inc):  # fmt: skip
    """:func:`_lane_trial` for the group of points from ``base``, into the scratch (the
    inputs are copied first, so that the arithmetic reads the scratch alone)."""
    for j in range(LANES):
        i = base + j
        (v[V_T1_OLD + j], v[V_T2_OLD + j], v[V_FN + j], v[V_F_OLD + j], v[V_R_OLD + j],
         v[V_GAP_OLD + j], v[V_SLIP1 + j], v[V_SLIP2 + j], v[V_DUN + j]) = (
            traction[i, 0], traction[i, 1], traction[i, 2], F_old[i], R_old[i], gap_old[i],
            slip_inc[i, 0], slip_inc[i, 1], slip_inc[i, 2])  # fmt: skip
    for j in range(LANES):
        (v[V_KIND + j], v[V_F1T + j], v[V_F2T + j], v[V_FN_TR + j], v[V_FH1T + j],
         v[V_FH2T + j], v[V_W_TR + j], v[V_PHI_TR + j], v[V_F_REC + j], v[V_R_START + j],
         v[V_R0 + j], v[V_PHI_W + j]) = _lane_trial(
            law, ca, sa, dt, e_rec, v[V_T1_OLD + j], v[V_T2_OLD + j], v[V_FN + j],
            v[V_F_OLD + j], v[V_R_OLD + j], v[V_GAP_OLD + j], v[V_SLIP1 + j], v[V_SLIP2 + j],
            v[V_DUN + j])  # fmt: skip


@njit(cache=True, inline="always")
def _lane_start(law, r0, phi_tr, fn_tr, w_tr, fh1t, fh2t, R_start, y0, s0, F_rec):  # fmt: skip
    """The closed-form start of :func:`_start` on the cone as a lane (before the model
    iteration). Returns (q, refine, dR, ddR, dddR, dF, ddF, plain norm)."""
    u = law.u
    dR = u * y0 / s0 if s0 > 0.0 else math.inf
    x = F_rec / law.Fk - 1.0
    dphi_soft = 1.0 / law.Fk  # softening_rate with m = 1
    dF = -law.kappa * (x if x > 0.0 else 0.0)
    A2ref = law.Aref * law.Aref
    W0, plain = _plain_norm(fh1t / (law.A1 * law.A1), fh2t / (law.A2 * law.A2))
    phi_tr_w = 1.0 / fn_tr if fn_tr > 0.0 else 0.0
    dphi = phi_tr_w * W0 * W0 / w_tr * A2ref if w_tr > 0.0 else 0.0
    ddlam = W0 * A2ref / law.alpha_t
    den = dphi + (dR * F_rec + R_start * dF) * ddlam
    q = r0 / den if den > 0.0 and math.isfinite(den) else -1.0
    r_sat = phi_tr - F_rec
    den_sat = dphi + dF * ddlam
    if r_sat > 0.0 and den_sat > 0.0 and math.isfinite(den_sat):
        q = max(q, r_sat / den_sat)
    inside = 0.0 < q < 1.0
    if not inside:  # the tail of _start with r(1) = -inf
        q = r0 / phi_tr if phi_tr > 0.0 else 0.5
        q = q if 0.0 < q < 1.0 else 0.5
    ddR = -0.5 * math.pi * (u * u + dR * dR) * dR / u
    dddR = -0.5 * math.pi * ddR * (3.0 * dR * dR + u * u) / u
    ddF = -law.kappa * dphi_soft * dF
    return q, inside and math.isfinite(dR), dR, ddR, dddR, dF, ddF, plain


@njit(cache=True, inline="always")
def _lane_model(law, q, fh1t, fh2t, phi_w, R0, dR, ddR, dddR, F0, dF, ddF):  # fmt: skip
    """One iteration of :func:`_start`'s model Newton (:func:`_model_at`, cone) as a lane
    (``phi_w = 1/f_n``). Returns (q, stop, plain norm)."""
    A1 = law.A1
    A2 = law.A2
    omq = 1.0 - q
    gamma = law.Aref * law.Aref * q / omq
    i1 = 1.0 / (A1 * A1 + gamma)
    i2 = 1.0 / (A2 * A2 + gamma)
    t1 = fh1t * i1
    t2 = fh2t * i2
    W, plain_W = _plain_norm(t1, t2)
    dlam = gamma * W * (1.0 / law.alpha_t)
    w, plain_w = _plain_norm(A1 * t1, A2 * t2)
    phi = w * phi_w
    R = R0 + dlam * (dR + dlam * (0.5 * ddR + dlam * dddR * (1.0 / 6.0)))
    Rp = dR + dlam * (ddR + 0.5 * dddR * dlam)
    saturated = R > 1.0 or Rp < 0.0
    R = min(R, 1.0) if saturated else R
    Rp = 0.0 if saturated else Rp
    F = F0 + dlam * (dF + 0.5 * ddF * dlam)
    dF = dF + ddF * dlam
    dphi = -phi_w * (A1 * A1 * t1 * t1 * i1 + A2 * A2 * t2 * t2 * i2) / w if w > 0.0 else 0.0
    dW = -(t1 * t1 * i1 + t2 * t2 * i2) / W if W > 0.0 else 0.0
    ddlam = (W + gamma * dW) * (1.0 / law.alpha_t)
    dgamma = law.Aref * law.Aref / (omq * omq)
    mq = phi - R * F
    dmq = dphi * dgamma - (Rp * F + R * dF) * ddlam * dgamma
    stop = not (dmq < 0.0 and math.isfinite(mq) and math.isfinite(dmq))
    q_new = q - mq / dmq if not stop else q
    if q_new <= 0.0:
        q_new = 0.5 * (q + 0.0)
    elif q_new >= 1.0:
        q_new = 0.5 * (1.0 + q)
    done = abs(q_new - q) <= MODEL_RTOL * min(q_new, 1.0 - q_new)
    return (q if stop else q_new), stop or done, plain_W and plain_w


@njit(cache=True, error_model="numpy")
def _lanes_start(v, law):  # fmt: skip
    """Steps 5's start (:func:`_start`, cone) for the plastic lanes: ``V_Q``."""
    for j in range(LANES):  # ratio_start of the cot law, inline (lane_math)
        R_start = v[V_R_START + j]
        v[V_Y0 + j], v[V_S0 + j] = sincos_half_pi(R_start if 0.0 <= R_start <= 1.0 else 0.0)
        v[V_KIND + j] = BY_POINT if not (R_start <= 1.0) else v[V_KIND + j]
    for j in range(LANES):
        q, refine, dR, ddR, dddR, dF, ddF, plain = _lane_start(
            law, v[V_R0 + j], v[V_PHI_TR + j], v[V_FN_TR + j], v[V_W_TR + j], v[V_FH1T + j],
            v[V_FH2T + j], v[V_R_START + j], v[V_Y0 + j], v[V_S0 + j], v[V_F_REC + j])  # fmt: skip
        plastic = v[V_KIND + j] == PLASTIC
        v[V_KIND + j] = BY_POINT if plastic and not plain else v[V_KIND + j]
        v[V_ACTIVE + j] = 1.0 if plastic and plain and refine else 0.0
        (v[V_Q + j], v[V_DR + j], v[V_DDR + j], v[V_DDDR + j], v[V_DF + j],
         v[V_DDF + j]) = q, dR, ddR, dddR, dF, ddF  # fmt: skip
    for _ in range(MODEL_ITERATIONS):
        if _none_active(v):
            break
        for j in range(LANES):
            q, stop, plain = _lane_model(law, v[V_Q + j], v[V_FH1T + j], v[V_FH2T + j],
                                         v[V_PHI_W + j], v[V_R_START + j], v[V_DR + j],
                                         v[V_DDR + j], v[V_DDDR + j], v[V_F_REC + j],
                                         v[V_DF + j], v[V_DDF + j])  # fmt: skip
            active = v[V_ACTIVE + j] == 1.0
            v[V_Q + j] = q if active else v[V_Q + j]
            v[V_KIND + j] = BY_POINT if active and not plain else v[V_KIND + j]
            v[V_ACTIVE + j] = 1.0 if active and plain and not stop else 0.0


@njit(cache=True, inline="always")
def _none_active(v):  # fmt: skip
    """No lane is still iterating."""
    count = 0.0
    for j in range(LANES):
        count += v[V_ACTIVE + j]
    return count == 0.0


@njit(cache=True, inline="always")
def _lane_newton(q, t, t_pos, t_neg, dx, dx_old, flip, r, F, r_gamma, cond, omq, Aref):  # fmt: skip
    """One pass of :func:`_solve`'s loop on the cone as a lane, from the residual at q.

    Returns (finished, converged, t, t_pos, t_neg, dx, dx_old, flip, q, omq).
    """
    scale = max(F, 1e-300)
    done = abs(r) <= RTOL_RESIDUAL * scale
    t_pos = t if r > 0.0 else t_pos
    t_neg = t_neg if r > 0.0 else t
    lo = min(t_pos, t_neg)
    hi = max(t_pos, t_neg)
    collapsed = hi - lo <= 4e-16 * max(hi, 1e-300)
    cond = abs(cond) if math.isfinite(cond) else 0.0
    accepted = abs(r) <= RTOL_ACCEPT * max(scale, cond)
    dqdt = -1.0 if flip else 1.0
    dgdt = Aref * Aref / (omq * omq) * dqdt
    slope = r_gamma * dgdt
    newton = slope != 0.0 and math.isfinite(slope) and math.isfinite(r)
    t_new = t - r / slope if newton else -1.0
    if not (lo < t_new < hi) or abs(t_new - t) > 0.5 * abs(dx_old):
        t_new = 0.5 * (lo + hi)
    dx_old = dx
    dx = t_new - t
    t = t_new
    upper = t > 0.5
    flip = flip != upper
    t = 1.0 - t if upper else t
    t_pos = 1.0 - t_pos if upper else t_pos
    t_neg = 1.0 - t_neg if upper else t_neg
    q = 1.0 - t if flip else t
    omq = t if flip else 1.0 - t
    return (done or collapsed, done or (collapsed and accepted), t, t_pos, t_neg, dx, dx_old,
            flip, q, omq)  # fmt: skip


@njit(cache=True, inline="always")
def _lane_return(law, q, omq, fh1t, fh2t, dt):  # fmt: skip
    """The algebraic start of :func:`_state_at` (cone) as a lane, up to the arguments of
    its transcendental functions. Returns (gamma, i1, i2, t1, t2, W, dlam, w, the
    argument of the ratio's expm1, the size's a, plain norms)."""
    A1 = law.A1
    A2 = law.A2
    gamma = law.Aref * law.Aref * q / omq
    i1 = 1.0 / (A1 * A1 + gamma)
    i2 = 1.0 / (A2 * A2 + gamma)
    t1 = fh1t * i1
    t2 = fh2t * i2
    W, plain_W = _plain_norm(t1, t2)
    dlam = gamma * W * (1.0 / law.alpha_t)
    w, plain_w = _plain_norm(A1 * t1, A2 * t2)
    a = (law.kappa / law.Fk) * dlam + law.xi * dt / law.Fs
    return (gamma, i1, i2, t1, t2, W, dlam, w, -_HALF_PI * law.u * dlam, a,
            plain_W and plain_w and omq > 0.0)  # fmt: skip


@njit(cache=True, inline="always")
def _lane_residual(law, dlam, gamma, i1, i2, t1, t2, W, w, y, s, atan, a, em_f, F0, phi_w,
                   dt):  # fmt: skip
    """The rest of :func:`_state_at` (cone, cot law, exponential size with m = n = 1) as a
    lane, given ``atan2(s, y)``, ``expm1(-a)`` and ``phi_w = 1/f_n``. Returns (r, r_gamma,
    phi_1, phi_2, R, F, phi_fn, hard, cond)."""
    A1 = law.A1
    A2 = law.A2
    kappa = law.kappa
    Fk = law.Fk
    R = atan * _INV_HALF_PI
    dR = law.u * y / s if s > 0.0 else math.inf
    # size_after, closed form of m = n = 1 and the 1 - F/F_s form
    if a == 0.0:
        F = F0
        dF = -kappa * (F0 / Fk - 1.0)
    else:
        ia = 1.0 / a
        F_inf = (kappa * dlam + law.xi * dt) * ia
        e = 1.0 + em_f
        one_minus_e_over_a = -em_f * ia
        F = F_inf + (F0 - F_inf) * e
        dF = (kappa * (1.0 - F_inf * (1.0 / Fk)) * one_minus_e_over_a
              + (F_inf - F0) * e * (kappa / Fk))  # fmt: skip
        F = min(max(F, Fk), law.Fs)
    phi = w * phi_w
    r = phi - R * F
    dfh1 = -A1 * A1 * t1 * i1
    dfh2 = -A2 * A2 * t2 * i2
    phi_per_w = phi_w / w if w > 0.0 else 0.0
    phi_1 = phi_per_w * t1 if w > 0.0 else 0.0
    phi_2 = phi_per_w * t2 if w > 0.0 else 0.0
    dW = -(t1 * t1 * i1 + t2 * t2 * i2) / W if W > 0.0 else 0.0
    ddlam = (W + gamma * dW) * (1.0 / law.alpha_t)
    hard = dR * F + R * dF
    r_gamma = (phi_1 * dfh1 + phi_2 * dfh2) - hard * ddlam
    return r, r_gamma, phi_1, phi_2, R, F, -phi * phi_w, hard, phi_w * w


#: The step from the previous iterate that the transcendental functions may follow by
#: their series (:func:`_lanes_follow`): at most STEP_RTOL of the exponent (and 1; the
#: range of lane_math.expm1_small) ...
STEP_RTOL = 2.0**-17
#: ... and at most ANGLE_STEP_RTOL sin^2(pi R/2) in the ratio's angle variable.
ANGLE_STEP_RTOL = 2.0**-20


@njit(cache=True, inline="always")
def _angle_step(y, s, X):  # fmt: skip
    """Change of the ratio's angle theta = acos(y) when y becomes y e^-X (cot law,
    ``X = pi/2 u d(dlam)``), by its series ``cot X - csc^2 cot X^2/2`` from
    ``(y, s) = (cos theta, sin theta)``.

    d theta/dX = cot theta, d^2/dX^2 = -csc^2 cot, d^3/dX^3 = csc^2 (2 cot^2 + csc^2) cot,
    whose size is at most 3/s^5: for ``|X| <= ANGLE_STEP_RTOL s^2`` the truncation is below
    ``ANGLE_STEP_RTOL^3 s/2 <= 2^-61 theta`` (theta >= s), i.e. rounding.
    """
    cot = y / s
    step = cot * X * (1.0 - (1.0 + cot * cot) * (0.5 * X))
    return step if X != 0.0 else 0.0


@njit(cache=True, error_model="numpy")
def _lanes_residual(v, law, dt, follow):  # fmt: skip
    """:func:`_state_at` at ``V_Q`` for the active lanes (the others keep their values).

    ``follow``: the lanes hold the residual at a previous iterate. When every active lane
    has moved by a small step from it (the last Newton step of a converging solve, ~1e-6
    relative), the ratio's and the size's exponentials follow by the exact product rule
    ``expm1(x + d) = expm1(x) + (1 + expm1(x)) expm1(d)`` with the cubic
    :func:`expm1_small`, and the ratio's angle by :func:`_angle_step`, instead of
    evaluating expm1 twice and atan2 afresh: the same numbers to rounding, and the
    residual itself (and so the convergence test) is still evaluated in full at the new q.
    """
    for j in range(LANES):
        gamma, i1, i2, t1, t2, W, dlam, w, arg_r, a, plain = _lane_return(
            law, v[V_Q + j], v[V_OMQ + j], v[V_FH1T + j], v[V_FH2T + j], dt)  # fmt: skip
        active = v[V_ACTIVE + j] == 1.0
        # expm1_nonpositive's range: both arguments are <= 0 (dlam >= 0)
        plain = plain and arg_r <= 0.0 and a >= 0.0
        v[V_KIND + j] = BY_POINT if active and not plain else v[V_KIND + j]
        v[V_ACTIVE + j] = 1.0 if active and plain else 0.0
        # the steps since the previous iterate (differences of nearby values: exact)
        darg = arg_r - v[V_ARG_R + j]
        da = a - v[V_A + j]
        s_old = v[V_S + j]
        small = (abs(darg) <= STEP_RTOL * min(-arg_r, 1.0)
                 and abs(da) <= STEP_RTOL * min(a, 1.0)
                 and abs(darg) <= ANGLE_STEP_RTOL * (s_old * s_old))  # fmt: skip
        v[V_STEP_OK + j] = 0.0 if active and plain and not small else 1.0
        (v[V_GAMMA + j], v[V_I1 + j], v[V_I2 + j], v[V_T1 + j], v[V_T2 + j], v[V_W + j],
         v[V_DLAM + j], v[V_WN + j], v[V_ARG_R + j], v[V_A + j], v[V_DARG_R + j],
         v[V_DA + j]) = (gamma, i1, i2, t1, t2, W, dlam, w, arg_r, a, darg, da)  # fmt: skip
    if follow and _all_rows(v, V_STEP_OK):
        _lanes_follow(v)
    else:
        _lanes_transcendental(v)
    for j in range(LANES):
        out = _lane_residual(law, v[V_DLAM + j], v[V_GAMMA + j], v[V_I1 + j], v[V_I2 + j],
                             v[V_T1 + j], v[V_T2 + j], v[V_W + j], v[V_WN + j], v[V_Y + j],
                             v[V_S + j], v[V_ATAN + j], v[V_A + j], v[V_EM_F + j],
                             v[V_F_OLD + j], v[V_PHI_W + j], dt)  # fmt: skip
        r, r_gamma, phi_1, phi_2, R, F, phi_fn, hard, cond = out
        active = v[V_ACTIVE + j] == 1.0
        v[V_RES + j] = r if active else v[V_RES + j]
        v[V_R_GAMMA + j] = r_gamma if active else v[V_R_GAMMA + j]
        v[V_PHI_1 + j] = phi_1 if active else v[V_PHI_1 + j]
        v[V_PHI_2 + j] = phi_2 if active else v[V_PHI_2 + j]
        v[V_R + j] = R if active else v[V_R + j]
        v[V_F + j] = F if active else v[V_F + j]
        v[V_PHI_FN + j] = phi_fn if active else v[V_PHI_FN + j]
        v[V_HARD + j] = hard if active else v[V_HARD + j]
        v[V_COND + j] = cond if active else v[V_COND + j]


@njit(cache=True, inline="always")
def _lanes_transcendental(v):  # fmt: skip
    """The ratio's (y, s, angle) and the size's expm1 at ``V_ARG_R``, ``V_A`` afresh."""
    for j in range(LANES):  # inline math (lane_math): every lane, packed
        em_r = expm1_nonpositive(v[V_ARG_R + j])
        v[V_EM_R + j] = em_r
        v[V_EM_F + j] = expm1_nonpositive(-v[V_A + j]) if v[V_A + j] != 0.0 else 0.0
        v[V_Y + j], v[V_S + j] = _lane_sine(v[V_Y0 + j], v[V_S0 + j], em_r)
    for j in range(LANES):  # s >= 0 and y = y0 (1 + em) >= 0
        v[V_ATAN + j] = atan2_first_quadrant(v[V_S + j], v[V_Y + j])


@njit(cache=True, inline="always")
def _lanes_follow(v):  # fmt: skip
    """:func:`_lanes_transcendental` from the previous iterate's values, by the steps
    ``V_DARG_R``, ``V_DA`` (all within the bounds of :func:`_lanes_residual`)."""
    for j in range(LANES):
        em_r = v[V_EM_R + j]
        em_f = v[V_EM_F + j]
        darg = v[V_DARG_R + j]
        em_r = em_r + (1.0 + em_r) * expm1_small(darg)
        v[V_EM_R + j] = em_r
        v[V_EM_F + j] = em_f + (1.0 + em_f) * expm1_small(-v[V_DA + j])
        v[V_ATAN + j] += _angle_step(v[V_Y + j], v[V_S + j], -darg)
        v[V_Y + j], v[V_S + j] = _lane_sine(v[V_Y0 + j], v[V_S0 + j], em_r)


@njit(cache=True, inline="always")
def _lane_sine(y0, s0, em):  # fmt: skip
    """y = cos(pi R/2) = y0 (1 + em) and s = sin(pi R/2) from the ratio's expm1 ``em``."""
    s2 = s0 * s0 - y0 * y0 * (em * (2.0 + em))
    return y0 * (1.0 + em), math.sqrt(s2 if s2 > 0.0 else 0.0)


@njit(cache=True, inline="always")
def _all_rows(v, row):  # fmt: skip
    """Every lane's value in ``row`` is 1."""
    count = 0.0
    for j in range(LANES):
        count += v[row + j]
    return count == LANES


@njit(cache=True, error_model="numpy")
def _lanes_solve(v, law, dt):  # fmt: skip
    """:func:`_solve` (cone) for the plastic lanes from ``V_Q``; a lane that does not
    converge goes BY_POINT (whose solve then fails the same way)."""
    for j in range(LANES):
        q0 = v[V_Q + j]
        flip = q0 > 0.5
        t = 1.0 - q0 if flip else q0
        v[V_FLIP + j] = 1.0 if flip else 0.0
        v[V_T + j] = t
        v[V_T_POS + j] = 1.0 if flip else 0.0
        v[V_T_NEG + j] = 0.0 if flip else 1.0
        v[V_DX + j] = 1.0
        v[V_DX_OLD + j] = 1.0
        v[V_Q + j] = 1.0 - t if flip else t
        v[V_OMQ + j] = t if flip else 1.0 - t
        v[V_ACTIVE + j] = 1.0 if v[V_KIND + j] == PLASTIC else 0.0
        v[V_ITER + j] = 0.0
    _lanes_residual(v, law, dt, False)
    Aref = law.Aref
    for _ in range(MAX_ITERATIONS):
        if _none_active(v):
            break
        for j in range(LANES):
            active = v[V_ACTIVE + j] == 1.0
            (finished, converged, t, t_pos, t_neg, dx, dx_old, flip, q, omq) = _lane_newton(
                v[V_Q + j], v[V_T + j], v[V_T_POS + j], v[V_T_NEG + j], v[V_DX + j],
                v[V_DX_OLD + j], v[V_FLIP + j] > 0.5, v[V_RES + j], v[V_F + j],
                v[V_R_GAMMA + j], v[V_COND + j], v[V_OMQ + j], Aref)  # fmt: skip
            v[V_ITER + j] += 1.0 if active else 0.0
            failed = active and finished and not converged
            v[V_KIND + j] = BY_POINT if failed else v[V_KIND + j]
            going = active and not finished
            v[V_ACTIVE + j] = 1.0 if going else 0.0
            (v[V_T + j], v[V_T_POS + j], v[V_T_NEG + j], v[V_DX + j],
             v[V_DX_OLD + j]) = (t, t_pos, t_neg, dx, dx_old)  # fmt: skip
            # a finished lane keeps its q: _lanes_residual recomputes the same algebra
            v[V_Q + j] = q if going else v[V_Q + j]
            v[V_OMQ + j] = omq if going else v[V_OMQ + j]
            v[V_FLIP + j] = 1.0 if flip else 0.0
        if _none_active(v):  # every lane finished: its values are those at its q already
            break
        _lanes_residual(v, law, dt, True)
    for j in range(LANES):  # still iterating after MAX_ITERATIONS: not converged
        v[V_KIND + j] = BY_POINT if v[V_ACTIVE + j] == 1.0 else v[V_KIND + j]


@njit(cache=True, inline="always")
def _lane_outcome(v, j, law, ca, sa, ext1, ext2, want_tangent):  # fmt: skip
    """Steps 6-7 of an ELASTIC or PLASTIC lane (:func:`_elastic`; :func:`_plastic` after
    the solve), branch-free: both outcomes are computed and one is selected.

    Returns (t1, t2, F, R, dlam, vp1, vp2, diss, k00, k01, k10, k11, k02, k12); the normal
    traction is ``V_FN_TR``, k22 is alpha_n and the tangent is zero without want_tangent.
    """
    elastic = v[V_KIND + j] == ELASTIC
    f1t = v[V_F1T + j]
    f2t = v[V_F2T + j]
    fn_tr = v[V_FN_TR + j]
    fh1t = v[V_FH1T + j]
    fh2t = v[V_FH2T + j]
    W = v[V_W + j]
    dlam = v[V_DLAM + j]
    # elastic: the trial state, R = Phi/F capped at 1
    R_el = v[V_PHI_TR + j] / v[V_F_REC + j]
    R_el = 1.0 if R_el > 1.0 else R_el
    # plastic: the return of the converged gamma, in principal axes
    # _returned, inline (a call compiled with the exception model would keep the loop
    # scalar)
    gamma = v[V_GAMMA + j]
    d1 = law.A1 * law.A1 + gamma
    d2 = law.A2 * law.A2 + gamma
    a1 = law.A1 * law.A1 / d1
    a2 = law.A2 * law.A2 / d2
    fh1 = fh1t * a1
    fh2 = fh2t * a2
    tb1 = (fh1t / d1) / W
    tb2 = (fh2t / d2) / W
    g1 = fn_tr * law.b1 + fh1
    g2 = fn_tr * law.b2 + fh2
    p1 = g1 if not elastic else f1t
    p2 = g2 if not elastic else f2t
    k = Tangent(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    k02_el = 0.0
    k12_el = 0.0
    alpha_t = 0.0
    if want_tangent:
        tr = Trial(fn_tr, f1t, f2t, fh1t, fh2t, v[V_W_TR + j], v[V_PHI_TR + j], 0.0, 0.0,
                   law.alpha_t, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                   ext1, ext2, 0.0, 0.0, 0.0)  # fmt: skip
        res = Residual(v[V_RES + j], v[V_R_GAMMA + j], v[V_PHI_1 + j], v[V_PHI_2 + j], dlam,
                       v[V_R + j], 0.0, v[V_F + j], 0.0, v[V_PHI_FN + j], v[V_GAMMA + j], W,
                       v[V_HARD + j], 0.0, 0.0, 0.0, 0.0, 0.0)  # fmt: skip
        st = Start(v[V_R_START + j], False, 0.0, 0.0, 0.0)
        k = _tangent(law, tr, st, res, v[V_Y0 + j], v[V_S0 + j], d1, d2, a1, a2, fh1, fh2,
                     ca, sa)  # fmt: skip
        k02_el = ca * ext1 - sa * ext2
        k12_el = sa * ext1 + ca * ext2
        alpha_t = law.alpha_t
    return (ca * p1 - sa * p2, sa * p1 + ca * p2,
            v[V_F_REC + j] if elastic else v[V_F + j],
            R_el if elastic else v[V_R + j],
            0.0 if elastic else dlam,
            0.0 if elastic else dlam * (ca * tb1 - sa * tb2),
            0.0 if elastic else dlam * (sa * tb1 + ca * tb2),
            0.0 if elastic else dlam * (g1 * tb1 + g2 * tb2),
            alpha_t if elastic else k.k00, 0.0 if elastic else k.k01,
            0.0 if elastic else k.k10, alpha_t if elastic else k.k11,
            k02_el if elastic else k.k02, k12_el if elastic else k.k12)  # fmt: skip


@njit(cache=True, error_model="numpy")
def _lanes_outcome(v, law, ca, sa, ext1, ext2, want_tangent):  # fmt: skip
    """:func:`_lane_outcome` of every lane into the ``V_OUT_*`` rows (packed; a BY_POINT
    lane's values are not used)."""
    for j in range(LANES):
        (v[V_OUT_T1 + j], v[V_OUT_T2 + j], v[V_OUT_F + j], v[V_OUT_R + j],
         v[V_OUT_DLAM + j], v[V_OUT_VP1 + j], v[V_OUT_VP2 + j], v[V_OUT_DISS + j],
         v[V_OUT_K00 + j], v[V_OUT_K01 + j], v[V_OUT_K10 + j], v[V_OUT_K11 + j],
         v[V_OUT_K02 + j], v[V_OUT_K12 + j]) = _lane_outcome(v, j, law, ca, sa, ext1, ext2,
                                                             want_tangent)  # fmt: skip


@njit(cache=True, inline="always")
def _lane_stored(v, j, law, want_tangent):  # fmt: skip
    """The :data:`Result` of an ELASTIC or PLASTIC lane from its ``V_OUT_*`` rows."""
    elastic = v[V_KIND + j] == ELASTIC
    return Result(STICK if elastic else SLIP, int(v[V_ITER + j]), v[V_OUT_T1 + j],
                  v[V_OUT_T2 + j], v[V_FN_TR + j], v[V_OUT_F + j], v[V_OUT_R + j], 0.0,
                  v[V_OUT_DLAM + j], v[V_OUT_VP1 + j], v[V_OUT_VP2 + j], v[V_OUT_DISS + j],
                  v[V_OUT_K00 + j], v[V_OUT_K01 + j], v[V_OUT_K10 + j], v[V_OUT_K11 + j],
                  v[V_OUT_K02 + j], v[V_OUT_K12 + j],
                  law.alpha_n if want_tangent else 0.0)  # fmt: skip


@njit(cache=True, error_model="numpy")
def _lanes_group(
    base, v, law, p, ca, sa, dt, e_rec, ext1, ext2, traction, F_old, R_old, gap_old,
    slip_inc, surface, tear_k, ulaw, integ, rform, open_frozen, want_tangent,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """Advance the LANES points from ``base`` (shared parameters and time increment)."""
    _lanes_trial(v, base, law, ca, sa, dt, e_rec, traction, F_old, R_old, gap_old,
                 slip_inc)  # fmt: skip
    _lanes_start(v, law)
    _lanes_solve(v, law, dt)
    _lanes_outcome(v, law, ca, sa, ext1, ext2, want_tangent)
    for j in range(LANES):
        i = base + j
        if v[V_KIND + j] == BY_POINT:
            res = _point(dt, ca, sa, p, traction[i, 0], traction[i, 1], traction[i, 2],
                         F_old[i], R_old[i], gap_old[i], slip_inc[i, 0], slip_inc[i, 1],
                         slip_inc[i, 2], surface, tear_k, ulaw, integ, rform, open_frozen,
                         want_tangent)  # fmt: skip
        else:
            res = _lane_stored(v, j, law, want_tangent)
        _store(i, res, want_tangent, out_traction, out_F, out_R, out_gap, out_dlam, out_vp,
               out_diss, out_tangent, out_status, out_iter)  # fmt: skip


@njit(cache=True)
def _in_lanes(P, n_shared_dt, surface, ulaw, integ, rform):  # fmt: skip
    """Whether the call is one the lanes cover (else every point goes through _point)."""
    return (P.shape[0] == 1 and n_shared_dt and surface == COULOMB and ulaw == U_COT
            and integ == EXPONENTIAL and rform == ONE_MINUS and P[0, P_M] == 1.0
            and P[0, P_N] == 1.0)  # fmt: skip


@njit(cache=True, inline="always")
def _call_constants(P, dt, surface, tear_k, ulaw, integ, rform):  # fmt: skip
    """What every lane shares: the law, its parameter row, the axes, the recovery factor
    exp(-xi dt/F_s) (one per call) and the trial's ext = d f_hat^tr/d du_n + alpha_n b."""
    ca, sa = _axes(P, 0)
    p = _row(P, 0)
    law = _law(p, ca, sa, surface, tear_k, ulaw, integ, rform)
    e_rec = math.exp(-law.xi * dt / law.Fs)
    ext1 = 0.0 + -law.alpha_n * law.b1 + law.alpha_n * law.b1
    ext2 = 0.0 + -law.alpha_n * law.b2 + law.alpha_n * law.b2
    return law, p, ca, sa, e_rec, ext1, ext2
