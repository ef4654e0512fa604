"""The scalar local solve: few residual evaluations from its model start, full precision.

The iteration counts are properties of the algorithm, not timings: the start solved on
the model residual (Phi exact, R and F Taylor polynomials in dlam) leaves an error of the
order of the truncated series, so one Newton step reaches the 1e-13 tolerance.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.subloading import SubloadingParams, initial_state, kernels, update
from frictionlab.subloading.kernels import _norm

FULL = dict(
    surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
    rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
)  # fmt: skip


def _steady(params: SubloadingParams, fn: float, n: int = 64):
    rng = np.random.default_rng(3)
    state = initial_state(params, normal_traction=np.full(n, fn))
    du = np.zeros((n, 3))
    du[:, 0] = 1e-3 * rng.uniform(0.5, 1.5, n)
    du[:, 1] = 3e-4 * rng.uniform(-1.0, 1.0, n)
    for _ in range(20):
        state = update(params, state, du, 0.01).state
    return state, du


@pytest.mark.parametrize("U_law, most", [("cot", 2), ("ln", 3)])
def test_steady_sliding_needs_few_residual_evaluations(U_law: str, most: int) -> None:
    params = SubloadingParams(**FULL, U_law=U_law)  # type: ignore[arg-type]
    state, du = _steady(params, 1.0)
    step = update(params, state, du, 0.01)
    assert np.all(step.status == kernels.SLIP)
    # The bracket-end evaluation is skipped (r(1) < 0 is known for the cone). For the cot
    # law the model start is within ~1e-6 of the root and one Newton step converges; the
    # implicit-Euler ln law's Taylor series converges more slowly (radius ~ R/u), ~1e-5.
    assert step.iterations.max() <= most


def test_the_solve_reaches_the_yield_surface_to_the_tolerance() -> None:
    params = SubloadingParams(**FULL)  # type: ignore[arg-type]
    state, du = _steady(params, 1.0)
    step = update(params, state, du, 0.01)
    # Phi = w / f_n in the principal axes, recomputed here from the returned traction
    c, s = math.cos(0.3), math.sin(0.3)
    f = step.traction
    fhat = f[:, :2] - f[:, 2:] * np.array([0.05, 0.02])
    p1 = c * fhat[:, 0] + s * fhat[:, 1]
    p2 = -s * fhat[:, 0] + c * fhat[:, 1]
    phi = np.hypot(p1 / 1.0, p2 / 0.6) / f[:, 2]
    RF = step.state.R * step.state.F
    np.testing.assert_allclose(phi, RF, rtol=1e-12)


@pytest.mark.parametrize("x, y", [(3.0, 4.0), (1e-200, 3e-200), (1e200, -2e200), (0.0, 0.0)])
def test_norm_equals_hypot_without_overflow_or_underflow(x: float, y: float) -> None:
    assert pytest.approx(math.hypot(x, y), rel=4e-16, abs=0.0) == _norm(x, y)


@pytest.mark.parametrize("surface", ["tear", "parabola", "cam_clay"])
@pytest.mark.parametrize("scale", [1e-3, 1e-2])
def test_closed_surfaces_converge_in_few_evaluations_from_large_steps(
    surface: str, scale: float
) -> None:
    # Steps large enough that the elastic trial leaves the domain of g (tear, parabola:
    # Phi infinite at q = 0). The start then comes from the domain's edge, found in closed
    # form for an isotropic surface; bisecting the infinite region instead cost 7-15
    # evaluations per point. Cam-clay's exponential g is nearly linear in the log.
    params = SubloadingParams(surface=surface, F_s=1.0, F_k=0.6, M=0.5, u=100.0, kappa=1.0,
                              xi=1e-3)  # fmt: skip
    rng = np.random.default_rng(1)
    n = 64
    state = initial_state(params, normal_traction=np.full(n, 0.2))
    du = np.zeros((n, 3))
    du[:, 0] = scale * rng.uniform(0.2, 1.5, n)
    du[:, 1] = scale * rng.uniform(-1.0, 1.0, n)
    for _ in range(8):
        step = update(params, state, du, 0.01)
        assert np.all(step.status == kernels.SLIP)
        state = step.state
    assert step.iterations.max() <= 3
    # and the result is on the yield surface: Phi = f_n g(w / f_n) = R F
    w = np.hypot(step.traction[:, 0], step.traction[:, 1]) / params.M
    fn = step.traction[:, 2]
    chi = w / fn
    g = {
        "tear": (1.0 - chi**2 / 3.0) ** -1.0,
        "parabola": 2.0 / (2.0 - chi),
        "cam_clay": np.exp(chi),
    }[surface]
    np.testing.assert_allclose(fn * g, state.R * state.F, rtol=1e-11)
