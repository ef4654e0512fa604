"""The implicit update against fine-step explicit integration of the rate equations.

The explicit scheme converges to the implicit map at first order.
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.subloading import update
from frictionlab.subloading.reference import explicit_increment, yield_value

from .support import fresh, set_a, set_b

CASES = {
    "cone": (set_a, {}, 1.0),
    "cone rotated orthotropic turned": (
        set_a, {"rotation": (0.05, 0.02), "orthotropy": (1.0, 0.7), "orthotropy_angle": 0.3}, 1.0
    ),
    "cone exponents": (set_a, {"m": 2.0, "n": 0.5}, 1.0),
    "cam_clay": (lambda **k: set_b("cam_clay", **k), {}, 0.2),
    "modified_cam_clay rotated": (
        lambda **k: set_b("modified_cam_clay", **k), {"rotation": (0.1, 0.0)}, 0.2
    ),
    "tear orthotropic": (lambda **k: set_b("tear", **k), {"orthotropy": (1.0, 0.8)}, 0.2),
    "parabola": (lambda **k: set_b("parabola", **k), {}, 0.2),
}  # fmt: skip


@pytest.mark.slow
@pytest.mark.parametrize("name", list(CASES))
def test_explicit_integration_converges_to_the_implicit_update_at_first_order(name: str) -> None:
    factory, changes, fn = CASES[name]
    params = factory(**changes)
    start = fresh(params, fn=fn)
    # leave the singular start R = 0 / g'(0) = 0 behind with one small implicit step
    start = update(params, start, np.array([[1e-4, 5e-5, 0.0]]), 1e-3).state
    du = np.array([0.02, 0.01, 1e-5])
    dt = 0.2
    fine = 4000
    state = start
    for _ in range(fine):
        state = update(params, state, (du / fine)[None, :], dt / fine).state
    reference = state.traction[0]
    errors = []
    for substeps in (1000, 2000, 4000, 8000):
        x, F, R, _ = explicit_increment(
            params, start.traction[0], float(start.F[0]), float(start.R[0]), du, dt, substeps
        )
        errors.append(np.max(np.abs(x - reference)))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    np.testing.assert_allclose(ratios, 2.0, rtol=0.2)  # error proportional to the substep
    assert ratios[-1] == pytest.approx(2.0, rel=0.08)  # asymptotically first order
    assert errors[-1] < 1e-3 * np.max(np.abs(reference))
    # the explicit scheme drifts off the sliding-subloading surface; the implicit one does not
    drift = abs(yield_value(params, x) - R * F)
    assert drift > 1e-9
    implicit_gap = abs(yield_value(params, state.traction[0]) - state.R[0] * state.F[0])
    assert implicit_gap <= 1e-12 * state.F[0]


def test_implicit_update_converges_under_step_refinement() -> None:
    params = set_a(orthotropy=(1.0, 0.6))
    start = update(params, fresh(params), np.array([[1e-4, 5e-5, 0.0]]), 1e-3).state
    du = np.array([0.02, 0.01, 0.0])
    finals = {}
    for steps in (25, 50, 100, 200, 3200):
        state = start
        for _ in range(steps):
            state = update(params, state, (du / steps)[None, :], 0.2 / steps).state
        finals[steps] = state.traction[0]
    errors = [np.max(np.abs(finals[n] - finals[3200])) for n in (25, 50, 100, 200)]
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all(ratios > 1.8)  # at least first order
