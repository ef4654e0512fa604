"""Compiled (numba) implicit return map of the subloading-friction law, spec §4.

One call of :func:`step_points` advances N independent contact points by one
increment. Per point (spec §4.2):

0. rotate the contact-frame components into the principal axes of orthotropy;
1. elastic predictor ``f_t^tr = f_t + alpha_t du_t``, ``f_n^tr = f_n + alpha_n (du_n - gap)``;
   ``f_n^tr <= 0`` opens the contact (zero traction, R = 0, the opening kept in ``gap``);
2. recovery-only size ``F^tr = F(dlam = 0)``;
3. partial-unloading correction of the starting ratio when the straight trial path
   passes its point of smallest |fhat| inside the step (T. Chang's correction);
4. loading test on the trial state (never on the sign of lambda, pitfall 5);
5. plastic corrector with ONE scalar unknown ``q`` in [0, 1): the backward-Euler flow
   ``fhat_i = fhat_i^tr A_i^2/(A_i^2 + gamma)``, ``gamma = A_ref^2 q/(1 - q)``, gives
   ``dlam = gamma W(gamma)/alpha_t``; for isotropic surfaces this is the radial return
   with ``q = alpha_t dlam / |fhat^tr|`` — the unknown is the plastic increment itself,
   never R (pitfall 1). Safeguarded Newton inside a sign bracket.
6. update; 7. algorithmic consistent tangent by implicit differentiation of the scalar
   residual (exact for isotropic, rotated and orthotropic surfaces).

The normal traction never changes plastically (no plastic normal sliding, Eq 32).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from frictionlab.subloading.evolution import ratio_after, size_after
from frictionlab.subloading.surfaces import COULOMB, potential

# status codes
STICK, SLIP, OPEN, FAILED = 0, 1, 2, 3

# columns of the parameter table (one row shared by all points, or one row per point)
P_ALPHA_N, P_ALPHA_T, P_FS, P_FK, P_U, P_KAPPA, P_XI, P_M, P_N = range(9)
P_BETA1, P_BETA2, P_A1, P_A2, P_ANGLE = range(9, 14)
N_PARAMS = 14

#: Relative tolerance of the scalar residual |f - R F| <= RTOL_RESIDUAL * F.
RTOL_RESIDUAL = 1e-13
#: Accepted residual when the bracket has collapsed to round-off (documented invariant).
RTOL_ACCEPT = 1e-10
MAX_ITERATIONS = 100


@njit(cache=True)
def _state_at(
    q: float,
    fh1t: float, fh2t: float, fn: float, A1: float, A2: float, Aref: float,
    alpha_t: float, surface: int, tear_k: float,
    R0: float, u: float, ulaw: int,
    F0: float, Fs: float, Fk: float, kappa: float, xi: float, m: float, n: float,
    dt: float, integ: int, rform: int,
):  # fmt: skip
    """Residual r(q) = Phi(fhat(q), f_n) - R(dlam) F(dlam) and everything derived from it."""
    if q >= 1.0:  # limit gamma -> infinity: fhat -> 0, dlam -> |fhat^tr|/alpha_t
        dlam = math.hypot(fh1t, fh2t) / alpha_t
        R, dR = ratio_after(ulaw, u, R0, dlam)
        F, dF = size_after(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, integ, rform)
        phi = 0.0 if surface == COULOMB else fn * 1.0
        return phi - R * F, 0.0, 0.0, 0.0, dlam, R, dR, F, dF, 0.0, 0.0, 0.0, 0.0, math.inf
    gamma = Aref * Aref * q / (1.0 - q)
    d1 = A1 * A1 + gamma
    d2 = A2 * A2 + gamma
    a1 = A1 * A1 / d1
    a2 = A2 * A2 / d2
    fh1 = fh1t * a1
    fh2 = fh2t * a2
    t1 = fh1t / d1  # = fh1 / A1^2
    t2 = fh2t / d2
    W = math.hypot(t1, t2)
    dlam = gamma * W / alpha_t
    w = math.hypot(fh1 / A1, fh2 / A2)
    phi, phi_w, phi_fn = potential(surface, tear_k, w, fn)
    R, dR = ratio_after(ulaw, u, R0, dlam)
    F, dF = size_after(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, integ, rform)
    r = phi - R * F
    # derivatives with respect to gamma
    dfh1 = -fh1 / d1
    dfh2 = -fh2 / d2
    if w > 0.0:
        phi_1 = phi_w * fh1 / (A1 * A1 * w)
        phi_2 = phi_w * fh2 / (A2 * A2 * w)
    else:
        phi_1 = 0.0
        phi_2 = 0.0
    dW = -(fh1t * fh1t / (d1 * d1 * d1) + fh2t * fh2t / (d2 * d2 * d2)) / W if W > 0.0 else 0.0
    ddlam = (W + gamma * dW) / alpha_t
    hard = dR * F + R * dF
    r_gamma = phi_1 * dfh1 + phi_2 * dfh2 - hard * ddlam
    return r, r_gamma, phi_1, phi_2, dlam, R, dR, F, dF, phi_fn, gamma, W, hard, phi


@njit(cache=True)
def step_points(
    traction, F_old, R_old, gap_old, slip_inc, dt_arr, P, n_shared_dt,
    surface, tear_k, ulaw, integ, rform, open_frozen,
    out_traction, out_F, out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent,
    out_status, out_iter,
):  # fmt: skip
    """Advance every point by one increment; results go to the ``out_*`` arrays.

    ``P`` is the parameter table (1 or N rows, columns ``P_*``); ``dt_arr`` has 1 or N
    entries. Failed points keep their old state, get the elastic tangent and status
    FAILED; no NaN is ever written.
    """
    npts = traction.shape[0]
    shared_p = P.shape[0] == 1
    for i in range(npts):
        row = 0 if shared_p else i
        dt = dt_arr[0] if n_shared_dt else dt_arr[i]
        alpha_n = P[row, P_ALPHA_N]
        alpha_t = P[row, P_ALPHA_T]
        Fs = P[row, P_FS]
        Fk = P[row, P_FK]
        u = P[row, P_U]
        kappa = P[row, P_KAPPA]
        xi = P[row, P_XI]
        m = P[row, P_M]
        n = P[row, P_N]
        A1 = P[row, P_A1]
        A2 = P[row, P_A2]
        Aref = max(A1, A2)
        ca = math.cos(P[row, P_ANGLE])
        sa = math.sin(P[row, P_ANGLE])
        # 0. into principal axes (contact frame -> (e*_1, e*_2))
        b1 = ca * P[row, P_BETA1] + sa * P[row, P_BETA2]
        b2 = -sa * P[row, P_BETA1] + ca * P[row, P_BETA2]
        f1 = ca * traction[i, 0] + sa * traction[i, 1]
        f2 = -sa * traction[i, 0] + ca * traction[i, 1]
        fn = traction[i, 2]
        du1 = ca * slip_inc[i, 0] + sa * slip_inc[i, 1]
        du2 = -sa * slip_inc[i, 0] + ca * slip_inc[i, 1]
        dun = slip_inc[i, 2]

        for a in range(3):
            for b in range(3):
                out_tangent[i, a, b] = 0.0
        out_dlam[i] = 0.0
        out_diss[i] = 0.0
        out_vp[i, 0] = 0.0
        out_vp[i, 1] = 0.0
        out_vp[i, 2] = 0.0
        out_iter[i] = 0

        # 2. recovery-only size
        F_rec = size_after(F_old[i], Fs, Fk, kappa, xi, m, n, 0.0, dt, integ, rform)[0]
        # 1. elastic predictor and separation
        fn_tr = fn + alpha_n * (dun - gap_old[i])
        if fn_tr <= 0.0:
            out_traction[i, 0] = 0.0
            out_traction[i, 1] = 0.0
            out_traction[i, 2] = 0.0
            out_F[i] = F_old[i] if open_frozen else F_rec
            out_R[i] = 0.0
            out_gap[i] = -fn_tr / alpha_n
            out_status[i] = OPEN
            continue
        f1t = f1 + alpha_t * du1
        f2t = f2 + alpha_t * du2
        fh1t = f1t - fn_tr * b1
        fh2t = f2t - fn_tr * b2
        w_tr = math.hypot(fh1t / A1, fh2t / A2)
        phi_tr = potential(surface, tear_k, w_tr, fn_tr)[0]

        # 3. starting ratio with the partial-unloading correction
        R_start = R_old[i]
        if fn > 0.0:
            h1 = f1 - fn * b1
            h2 = f2 - fn * b2
            e1 = fh1t - h1
            e2 = fh2t - h2
            den = (e1 * e1) / (A1 * A1) + (e2 * e2) / (A2 * A2)
            if den > 0.0:
                s = -((h1 * e1) / (A1 * A1) + (h2 * e2) / (A2 * A2)) / den
                if 0.0 < s < 1.0:
                    ws = math.hypot((h1 + s * e1) / A1, (h2 + s * e2) / A2)
                    fns = fn + s * (fn_tr - fn)
                    R_min = potential(surface, tear_k, ws, fns)[0] / F_rec
                    if R_min < R_start:
                        R_start = R_min

        # 4. loading test on the trial state
        r0 = phi_tr - R_start * F_rec
        if w_tr == 0.0 or r0 <= RTOL_RESIDUAL * F_rec:
            R_new = phi_tr / F_rec
            if surface != COULOMB and R_new > 1.0 + RTOL_ACCEPT:
                # normal traction pushed the state outside a closed surface (pitfall 3)
                _keep_old(i, traction, F_old, R_old, gap_old, alpha_t, alpha_n,
                          out_traction, out_F, out_R, out_gap, out_tangent)  # fmt: skip
                out_status[i] = FAILED
                continue
            if R_new > 1.0:
                R_new = 1.0
            out_traction[i, 0] = ca * f1t - sa * f2t
            out_traction[i, 1] = sa * f1t + ca * f2t
            out_traction[i, 2] = fn_tr
            out_F[i] = F_rec
            out_R[i] = R_new
            out_gap[i] = 0.0
            out_tangent[i, 0, 0] = alpha_t
            out_tangent[i, 1, 1] = alpha_t
            out_tangent[i, 2, 2] = alpha_n
            out_status[i] = STICK
            continue

        # 5. plastic corrector: bracket [0, 1] in q
        r1 = _state_at(1.0, fh1t, fh2t, fn_tr, A1, A2, Aref, alpha_t, surface, tear_k,
                       R_start, u, ulaw, F_old[i], Fs, Fk, kappa, xi, m, n, dt, integ,
                       rform)[0]  # fmt: skip
        if not r1 < 0.0:
            _keep_old(i, traction, F_old, R_old, gap_old, alpha_t, alpha_n,
                      out_traction, out_F, out_R, out_gap, out_tangent)  # fmt: skip
            out_status[i] = FAILED
            continue
        lo, hi = 0.0, 1.0
        q = r0 / (r0 - r1) if math.isfinite(r0) else 0.5
        if not 0.0 < q < 1.0:
            q = 0.5
        converged = False
        it = 0
        r_prev = math.inf
        res = _state_at(q, fh1t, fh2t, fn_tr, A1, A2, Aref, alpha_t, surface, tear_k,
                        R_start, u, ulaw, F_old[i], Fs, Fk, kappa, xi, m, n, dt, integ,
                        rform)  # fmt: skip
        while it < MAX_ITERATIONS:
            it += 1
            r = res[0]
            scale = max(res[7], 1e-300)
            if abs(r) <= RTOL_RESIDUAL * scale:
                converged = True
                break
            if r > 0.0:
                lo = q
            else:
                hi = q
            drdq = res[1] * Aref * Aref / ((1.0 - q) * (1.0 - q))
            q_new = q - r / drdq if (drdq < 0.0 and math.isfinite(drdq)) else -1.0
            if not (lo < q_new < hi) or abs(r) > 0.5 * r_prev:
                q_new = 0.5 * (lo + hi)
            r_prev = abs(r)
            if hi - lo <= 4e-16 * max(hi, 1e-300):
                converged = abs(r) <= RTOL_ACCEPT * scale
                break
            q = q_new
            res = _state_at(q, fh1t, fh2t, fn_tr, A1, A2, Aref, alpha_t, surface, tear_k,
                            R_start, u, ulaw, F_old[i], Fs, Fk, kappa, xi, m, n, dt, integ,
                            rform)  # fmt: skip
        out_iter[i] = it
        if not converged:
            _keep_old(i, traction, F_old, R_old, gap_old, alpha_t, alpha_n,
                      out_traction, out_F, out_R, out_gap, out_tangent)  # fmt: skip
            out_status[i] = FAILED
            continue
        (r, r_gamma, phi_1, phi_2, dlam, R, dR, F, dF, phi_fn, gamma, W, hard, phi) = res
        d1 = A1 * A1 + gamma
        d2 = A2 * A2 + gamma
        a1 = A1 * A1 / d1
        a2 = A2 * A2 / d2
        fh1 = fh1t * a1
        fh2 = fh2t * a2
        # 6. update (principal axes)
        g1 = fn_tr * b1 + fh1
        g2 = fn_tr * b2 + fh2
        tb1 = (fh1t / d1) / W  # flow direction t-bar at t_{n+1}, Eqs (87), (99)
        tb2 = (fh2t / d2) / W
        out_dlam[i] = dlam
        out_diss[i] = dlam * (g1 * tb1 + g2 * tb2)
        out_vp[i, 0] = dlam * (ca * tb1 - sa * tb2)
        out_vp[i, 1] = dlam * (sa * tb1 + ca * tb2)
        out_traction[i, 0] = ca * g1 - sa * g2
        out_traction[i, 1] = sa * g1 + ca * g2
        out_traction[i, 2] = fn_tr
        out_F[i] = F
        out_R[i] = R
        out_gap[i] = 0.0
        out_status[i] = SLIP
        # 7. consistent tangent: r(gamma; fhat^tr, f_n) = 0
        #    r_fhtr_j = Phi_j a_j - hard * d(dlam)/d(fhat^tr_j)
        ddl1 = gamma * (fh1t / (d1 * d1)) / (W * alpha_t)
        ddl2 = gamma * (fh2t / (d2 * d2)) / (W * alpha_t)
        c1 = (phi_1 * a1 - hard * ddl1) / r_gamma
        c2 = (phi_2 * a2 - hard * ddl2) / r_gamma
        cn = phi_fn / r_gamma
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
        T11 = alpha_t * j11
        T12 = alpha_t * j12
        T21 = alpha_t * j21
        T22 = alpha_t * j22
        T1n = alpha_n * (jn1 - j11 * b1 - j12 * b2)
        T2n = alpha_n * (jn2 - j21 * b1 - j22 * b2)
        # back to the contact frame: T_c = Q^T T_p Q, Q = [[ca, sa], [-sa, ca]]
        p11 = ca * T11 - sa * T21
        p12 = ca * T12 - sa * T22
        p21 = sa * T11 + ca * T21
        p22 = sa * T12 + ca * T22
        out_tangent[i, 0, 0] = p11 * ca - p12 * sa
        out_tangent[i, 0, 1] = p11 * sa + p12 * ca
        out_tangent[i, 1, 0] = p21 * ca - p22 * sa
        out_tangent[i, 1, 1] = p21 * sa + p22 * ca
        out_tangent[i, 0, 2] = ca * T1n - sa * T2n
        out_tangent[i, 1, 2] = sa * T1n + ca * T2n
        out_tangent[i, 2, 2] = alpha_n


@njit(cache=True)
def _keep_old(i, traction, F_old, R_old, gap_old, alpha_t, alpha_n,
              out_traction, out_F, out_R, out_gap, out_tangent):  # fmt: skip
    """A failed point keeps its old state and gets the elastic tangent (never NaN)."""
    for a in range(3):
        out_traction[i, a] = traction[i, a]
    out_F[i] = F_old[i]
    out_R[i] = R_old[i]
    out_gap[i] = gap_old[i]
    out_tangent[i, 0, 0] = alpha_t
    out_tangent[i, 1, 1] = alpha_t
    out_tangent[i, 2, 2] = alpha_n


def empty_outputs(n_points: int) -> dict[str, np.ndarray]:
    """Allocate the output arrays of :func:`step_points`."""
    return {
        "traction": np.empty((n_points, 3)),
        "F": np.empty(n_points),
        "R": np.empty(n_points),
        "gap": np.empty(n_points),
        "dlam": np.empty(n_points),
        "vp": np.empty((n_points, 3)),
        "diss": np.empty(n_points),
        "tangent": np.empty((n_points, 3, 3)),
        "status": np.empty(n_points, dtype=np.int8),
        "iterations": np.empty(n_points, dtype=np.int32),
    }
