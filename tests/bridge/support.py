"""Helpers of the bridge tests: the driver's steady sliding and a slow reference fit.

Both are independent of :mod:`frictionlab.bridge`: the steady tractions come from the
driver (the return map verified against the spec), and the reference fit minimises the
same sum of squares with Nelder-Mead from a grid of starts, with the steady polar written
from the support point of an ellipse (maximum dissipation, derived by a Lagrange multiplier:
the point of the ellipse |A^-1 x| <= 1 with the largest d . x is A^2 d / |A d|).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from scipy.optimize import minimize

from frictionlab.driver import InitialConditions, Slide, simulate
from frictionlab.subloading import SubloadingParams

DIRECTIONS = np.arange(0.0, 360.0, 10.0)


def simulated_steady(
    params: SubloadingParams,
    directions: np.ndarray = DIRECTIONS,
    velocity: float = 0.1,
    normal_traction: float = 1.0,
    distance: float = 10.0,
    steps: int = 400,
) -> np.ndarray:
    """(N, 2) f_t/f_n after sliding ``distance`` along each direction (one point each)."""
    history = simulate(
        params,
        (Slide(velocity=velocity, distance=distance, direction_deg=directions, steps=steps),),
        InitialConditions(normal_traction=normal_traction),
    )
    assert history.success, history.message
    assert np.all(history.R[-1] > 1.0 - 1e-9)  # on the sliding-yield surface: steady
    return history.traction[-1, :, :2] / history.traction[-1, :, 2:3]


def support_polar(
    directions_deg: np.ndarray, k: float, ratio: float, angle: float, beta: np.ndarray
) -> np.ndarray:
    """beta + k x (support point of the ellipse with semi-axes (1, ratio) at ``angle``)."""
    t = np.radians(directions_deg)
    c, s = math.cos(angle), math.sin(angle)
    d1 = c * np.cos(t) + s * np.sin(t)  # sliding direction in the ellipse's axes
    d2 = -s * np.cos(t) + c * np.sin(t)
    A = np.array([1.0, ratio])
    norm = np.sqrt((A[0] * d1) ** 2 + (A[1] * d2) ** 2)
    x1, x2 = A[0] ** 2 * d1 / norm, A[1] ** 2 * d2 / norm
    return np.asarray(beta) + k * np.column_stack([c * x1 - s * x2, s * x1 + c * x2])


def reference_fit(directions_deg: np.ndarray, data: np.ndarray) -> tuple[float, np.ndarray]:
    """Smallest rms misfit over (k, C_2/C_1, angle, beta) and its parameters (Nelder-Mead)."""

    def rms(x: np.ndarray) -> float:
        k, ratio, angle, b1, b2 = x
        if k <= 0 or ratio <= 0:
            return 1e9
        diff = support_polar(directions_deg, k, ratio, angle, np.array([b1, b2])) - data
        return float(np.sqrt(np.mean(np.sum(diff**2, axis=1))))

    scale = float(np.mean(np.hypot(data[:, 0], data[:, 1])))
    b0 = data.mean(axis=0)
    best = None
    for angle, ratio in itertools.product(np.radians(np.arange(0.0, 180.0, 30.0)), (0.5, 0.9)):
        res = minimize(
            rms, [scale, ratio, angle, *b0], method="Nelder-Mead",
            options={"xatol": 1e-12, "fatol": 1e-15, "maxiter": 20000, "maxfev": 20000},
        )  # fmt: skip
        if best is None or res.fun < best.fun:
            best = res
    assert best is not None
    return float(best.fun), np.asarray(best.x)
