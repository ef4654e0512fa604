"""Profile likelihood of one fitted parameter (for the poorly identified ones).

The parameter is fixed on a grid around its optimum and every other fitted parameter is
fitted again; the profile is ``delta chi^2 = 2 (cost - cost_min) / s^2`` with the
residual variance s^2 of the full fit. Where the linearised stderr is trustworthy the
profile is the parabola ``((x - x_hat)/stderr)^2`` in the fitted space; where it is not,
the profile shows how far the data really constrain the parameter. The 95 % interval is
where delta chi^2 <= 3.84 (chi^2 with one degree of freedom), open where the grid ends
below that level.

Pure computation: progress goes to an optional callback.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from frictionlab.calibration.fit import FitResult, Objective, ProgressCallback
from frictionlab.calibration.model import Curve, FitSpace, with_values

__all__ = ["CHI2_95", "Profile", "profile_likelihood"]

#: 95 % quantile of chi^2 with one degree of freedom.
CHI2_95 = 3.841458820694124


@dataclass(frozen=True)
class Profile:
    """The profile of one parameter: grid values (physical units), costs, delta chi^2.

    ``interval`` is the 95 % range (low, high); an end is None when the profile stays
    below 3.84 up to the end of the grid (the data do not bound it there).
    """

    name: str
    values: np.ndarray
    cost: np.ndarray
    delta_chi2: np.ndarray
    interval: tuple[float | None, float | None]


def _crossing(x: np.ndarray, d: np.ndarray, centre: int, step: int) -> float | None:
    """Where delta chi^2 first reaches CHI2_95 walking from ``centre`` by ``step``."""
    i = centre
    while 0 <= i + step < x.size:
        j = i + step
        if d[i] < CHI2_95 <= d[j]:
            t = (CHI2_95 - d[i]) / (d[j] - d[i])
            return float(x[i] + t * (x[j] - x[i]))
        i = j
    return None


def profile_likelihood(
    fit: FitResult,
    curves: list[Curve] | tuple[Curve, ...],
    name: str,
    *,
    points: int = 9,
    span: float = 3.0,
    max_nfev: int = 30,
    accuracy: float | None = None,
    max_halvings: int = 10,
    progress: ProgressCallback | None = None,
) -> Profile:
    """Profile of ``name``: ``points`` grid values over +-``span`` stderr (fitted space).

    The grid is clipped to the parameter's bounds; where the stderr is infinite it spans
    +-``span`` in the fitted space (e-folds for log parameters) or +-``span`` times the
    value for the others.
    """
    space = fit.space
    j = fit.names.index(name)
    theta_hat = space.to_theta(fit.values)
    se_theta = fit.stderr[j] / space.jacobian_factor(fit.values)[j]
    half = span * se_theta
    if not np.isfinite(half) or half <= 0:
        half = span if space.log[j] else span * max(abs(theta_hat[j]), 1e-12)
    lo, hi = space.theta_bounds()
    margin = 1e-9 * max(1.0, abs(theta_hat[j]))
    a = max(theta_hat[j] - half, lo[j] + margin)
    b = min(theta_hat[j] + half, hi[j] - margin)
    grid = np.unique(np.concatenate([np.linspace(a, b, max(points, 3)), [theta_hat[j]]]))
    centre = int(np.flatnonzero(grid == theta_hat[j])[0])
    others = [k for k in range(len(fit.names)) if k != j]
    sub = FitSpace(tuple(fit.names[k] for k in others), space.lower[others], space.upper[others])
    costs = np.full(grid.size, np.nan)
    costs[centre] = fit.cost
    x_fixed = np.exp(grid) if space.log[j] else grid
    for direction in (-1, 1):
        start = theta_hat[others]
        i = centre + direction
        while 0 <= i < grid.size:
            base = with_values(fit.params, (name,), np.array([x_fixed[i]]))
            obj = Objective(
                base, curves, sub, accuracy=accuracy, max_halvings=max_halvings,
                progress=progress,
            )  # fmt: skip
            if others:
                slo, shi = sub.theta_bounds()
                res = least_squares(
                    obj.residuals, np.clip(start, slo + 1e-12, shi - 1e-12), jac=obj.jac,
                    bounds=(slo, shi), method="trf", x_scale="jac", max_nfev=max_nfev,
                )  # fmt: skip
                start = res.x
                costs[i] = float(res.cost)
            else:
                r = obj.residuals(np.zeros(0))
                costs[i] = 0.5 * float(r @ r)
            i += direction
    s2 = fit.residual_variance
    delta = (
        2.0 * (costs - fit.cost) / s2 if np.isfinite(s2) and s2 > 0 else np.full_like(costs, np.nan)
    )
    delta = np.maximum(delta, 0.0)
    low = _crossing(x_fixed, delta, centre, -1)
    high = _crossing(x_fixed, delta, centre, +1)
    return Profile(name, x_fixed, costs, delta, (low, high))
