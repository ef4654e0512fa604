"""One call for N points equals N separate calls (per-point parameters and time steps)."""

from __future__ import annotations

import numpy as np

from frictionlab.subloading import SubloadingParams, initial_state, update


def test_per_point_parameters_equal_separate_runs() -> None:
    rng = np.random.default_rng(11)
    n = 5
    per_point = dict(
        alpha_t=rng.uniform(500, 2000, n),
        mu_s=rng.uniform(0.45, 0.6, n),
        mu_k=rng.uniform(0.25, 0.35, n),
        u=rng.uniform(50, 500, n),
        kappa=rng.uniform(0.5, 2.0, n),
        xi=rng.uniform(0, 1e-2, n),
        rotation=rng.uniform(-0.05, 0.05, (n, 2)),
        orthotropy=rng.uniform(0.7, 1.3, (n, 2)),
        orthotropy_angle=rng.uniform(-1, 1, n),
    )
    params = SubloadingParams(surface="coulomb", **per_point)
    fn = rng.uniform(0.5, 2.0, n)
    increments = rng.normal(size=(40, n, 3)) * np.array([1e-3, 1e-3, 1e-5])
    dts = rng.uniform(0.0, 0.05, (40, n))
    together = initial_state(params, normal_traction=fn)
    for du, dt in zip(increments, dts, strict=True):
        together = update(params, together, du, dt).state
    for i in range(n):
        single = SubloadingParams(surface="coulomb", **{k: v[i] for k, v in per_point.items()})
        state = initial_state(single, normal_traction=fn[i])
        for du, dt in zip(increments, dts, strict=True):
            state = update(single, state, du[i : i + 1], dt[i]).state
        np.testing.assert_array_equal(state.traction[0], together.traction[i])
        np.testing.assert_array_equal(state.F[0], together.F[i])
        np.testing.assert_array_equal(state.R[0], together.R[i])


def test_update_does_not_mutate_its_inputs() -> None:
    params = SubloadingParams(surface="coulomb", mu_s=0.5, mu_k=0.3)
    state = initial_state(params, normal_traction=np.ones(3))
    du = np.tile([1e-3, 0.0, 0.0], (3, 1))
    du_copy = du.copy()
    before = state.traction.copy()
    step = update(params, state, du, 0.01)
    np.testing.assert_array_equal(du, du_copy)
    np.testing.assert_array_equal(state.traction, before)
    assert not step.traction.flags.writeable and not step.state.F.flags.writeable
