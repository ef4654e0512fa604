"""Slow explicit reference integrator of the rate equations, for verification only.

This is an independent second implementation of the law, written from the rate form
of Hashiguchi & Ozaki (2008) rather than from the return map: forward Euler on

* the loading factor, Eq (39) multiplied through by ``|df/df|``:
  ``Lambda = (grad f . C^e v - R xi psi(F)) / (U(R) F - R kappa phi(F) + grad f . C^e t_bar)``,
  with plastic sliding iff the numerator is positive (Eq 47);
* the traction rate, Eq (40): ``f' = C^e (v - <Lambda> t_bar)``;
* Eq (25)/(69) for F and Eq (26) for R (in elastic states R = f/F).

The gradient of f is taken by central finite differences of the yield function itself,
so none of the kernel's analytic derivatives are reused. The explicit scheme drifts off
the sliding-subloading surface with an error proportional to the substep.
Single point, pure NumPy, slow by design.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from frictionlab.subloading.params import SubloadingParams

__all__ = ["explicit_increment", "yield_value"]


def _g(surface: str, chi: float, tear_k: float) -> float:
    if surface == "cam_clay":
        return math.exp(chi)
    if surface == "modified_cam_clay":
        return 1.0 + chi * chi
    if surface == "tear":
        a = 1.0 / (2.0 * tear_k + 1.0)
        base = 1.0 - a * chi * chi
        return math.inf if base <= 0 else base**-tear_k
    if surface == "parabola":
        return math.inf if chi >= 2.0 else 2.0 / (2.0 - chi)
    raise ValueError(surface)


def yield_value(params: SubloadingParams, traction: np.ndarray, point: int = 0) -> float:
    """f(f, beta) for one traction (f_t1, f_t2, f_n) in the contact frame (Eqs 48, 67, 83, 95)."""
    p = _point_params(params, point)
    ft = np.asarray(traction[:2], dtype=float)
    fn = float(traction[2])
    if fn <= 0.0:
        return 0.0
    fhat = ft - fn * p.beta
    c, s = math.cos(p.angle), math.sin(p.angle)
    principal = np.array([c * fhat[0] + s * fhat[1], -s * fhat[0] + c * fhat[1]])
    w = float(np.sqrt(np.sum((principal / p.axes) ** 2)))
    if params.is_cone:
        return w / fn
    return fn * _g(params.surface, w / fn, params.tear_k)


@dataclass(frozen=True)
class _Point:
    """Parameters of one point as plain floats."""

    alpha_n: float
    alpha_t: float
    Fs: float
    Fk: float
    u: float
    kappa: float
    xi: float
    m: float
    n: float
    beta: np.ndarray
    axes: np.ndarray
    angle: float


def _point_params(params: SubloadingParams, i: int) -> _Point:
    def at(value: object) -> float:
        arr = np.asarray(value, dtype=float)
        return float(arr if arr.ndim == 0 else arr[i])

    rot = np.asarray(params.rotation, dtype=float)
    axes = np.asarray(params.axis_factors, dtype=float)
    return _Point(
        alpha_n=at(params.alpha_n),
        alpha_t=at(params.alpha_t),
        Fs=at(params.static),
        Fk=at(params.kinetic),
        u=at(params.u),
        kappa=at(params.kappa),
        xi=at(params.xi),
        m=at(params.m),
        n=at(params.n),
        beta=rot if rot.ndim == 1 else rot[i],
        axes=axes if axes.ndim == 1 else axes[i],
        angle=at(params.orthotropy_angle),
    )


def explicit_increment(
    params: SubloadingParams,
    traction: np.ndarray,
    F: float,
    R: float,
    slip_increment: np.ndarray,
    time_increment: float,
    substeps: int,
    point: int = 0,
) -> tuple[np.ndarray, float, float, float]:
    """Integrate one increment with ``substeps`` forward-Euler substeps.

    Returns the traction (3,), F, R and the accumulated plastic sliding. The contact must
    stay closed; U(R) = u cot(pi R/2) and the recovery form (1 - F/F_s)^n are used.
    """
    p = _point_params(params, point)
    x = np.array(traction, dtype=float)
    du = np.asarray(slip_increment, dtype=float) / substeps
    h = time_increment / substeps
    C = np.array([p.alpha_t, p.alpha_t, p.alpha_n])
    Fs, Fk, kappa, xi, u = p.Fs, p.Fk, p.kappa, p.xi, p.u
    up = 0.0
    for _ in range(substeps):
        grad = _gradient(params, x, point)
        gt = grad[:2]
        norm_t = float(np.hypot(gt[0], gt[1]))
        lam = 0.0
        if norm_t > 0.0 and R > 0.0:
            tbar = np.array([gt[0] / norm_t, gt[1] / norm_t, 0.0])
            phi = max(F / Fk - 1.0, 0.0) ** p.m
            psi = max(1.0 - F / Fs, 0.0) ** p.n
            U = u * math.cos(0.5 * math.pi * R) / math.sin(0.5 * math.pi * R)
            numerator = float(grad @ (C * du)) - R * xi * psi * h
            denominator = U * F - R * kappa * phi + float(grad @ (C * tbar))
            if numerator > 0.0 and denominator > 0.0:
                lam = numerator / denominator
        else:
            tbar = np.zeros(3)
            phi = max(F / Fk - 1.0, 0.0) ** p.m
            psi = max(1.0 - F / Fs, 0.0) ** p.n
            U = 0.0
        x = x + C * (du - lam * tbar)
        F = F - kappa * phi * lam + xi * psi * h
        if lam > 0.0:
            R = R + U * lam
        else:
            R = yield_value(params, x, point) / F
        up += lam
    return x, F, R, up


def _gradient(params: SubloadingParams, x: np.ndarray, point: int) -> np.ndarray:
    grad = np.empty(3)
    for k in range(3):
        step = 1e-6 * max(abs(x[k]), abs(x[2]), 1e-12)
        xp = x.copy()
        xm = x.copy()
        xp[k] += step
        xm[k] -= step
        grad[k] = (yield_value(params, xp, point) - yield_value(params, xm, point)) / (2 * step)
    return grad
