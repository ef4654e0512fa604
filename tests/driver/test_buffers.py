"""Reused output buffers and the one-pass row writer give the results of fresh arrays.

References: the same steps with fresh outputs (no buffer pool) and the recorder's
plain numpy path (chosen points, here all of them), compared bit for bit.
"""

from __future__ import annotations

import numpy as np

from frictionlab.driver import Hold, Recording, Slide, Traction, simulate
from frictionlab.driver.program import plan_program
from frictionlab.driver.stepping import OutputPool, advance
from frictionlab.subloading import initial_state

from .support import set_a

FIELDS = ("time", "slip", "approach", "traction", "F", "R", "plastic_slip", "dissipation",
          "status", "iterations", "substeps", "solves")  # fmt: skip


def test_pool_steps_equal_fresh_steps_and_earlier_states_stay_valid() -> None:
    params = set_a()
    n = 5
    plan = plan_program((Slide(velocity=0.1, distance=0.02, steps=6),), n)[0]
    steps = plan.begin(initial_state(params, 1.0, n_points=n).traction)
    pool = OutputPool(n)
    fresh = pooled = initial_state(params, 1.0, n_points=n)
    kept = []
    for k in range(steps):
        a, _ = advance(params, fresh, plan.control(k))
        b, _ = advance(params, pooled, plan.control(k), pool=pool)
        assert pool.holds(b.state) and b.state.traction is not pooled.traction
        for name in ("traction", "F", "R", "plastic_slip", "gap"):
            np.testing.assert_array_equal(getattr(b.state, name), getattr(a.state, name))
        np.testing.assert_array_equal(b.status, a.status)
        if kept:  # the state of the step before is untouched by this step
            np.testing.assert_array_equal(pooled.traction, kept[-1])
        kept.append(b.state.traction.copy())
        fresh, pooled = a.state, b.state


def test_history_is_the_same_with_the_one_pass_writer_and_the_plain_path() -> None:
    params = set_a()
    n = 4
    program = (
        Slide(velocity=np.array([0.1, 0.2, 0.05, 0.1]), distance=0.03, steps=9),
        Hold(duration=10.0, steps=3),
        Slide(velocity=0.1, distance=0.02, direction_deg=180.0, steps=4),
        Slide(velocity=0.1, distance=0.01, steps=5),
    )
    one_pass = simulate(params, program, n_points=n)  # every point: the compiled writer
    plain = simulate(params, program, n_points=n, recording=Recording(points=range(n)))
    assert one_pass.success and plain.success
    for name in FIELDS:
        np.testing.assert_array_equal(getattr(one_pass, name), getattr(plain, name), name)
    for name in ("peak_friction_ratio", "peak_time", "path_length", "time"):
        np.testing.assert_array_equal(getattr(one_pass.stats, name), getattr(plain.stats, name))


def test_final_state_is_a_read_only_copy_apart_from_the_buffers() -> None:
    h = simulate(set_a(), (Slide(velocity=0.1, distance=0.02, steps=4),), n_points=3)
    final = h.final_state
    assert not final.traction.flags.writeable and not final.F.flags.writeable
    np.testing.assert_array_equal(final.traction, h.traction[-1])
    again = simulate(set_a(), (Slide(velocity=0.1, distance=0.04, steps=4),), initial=final)
    assert again.success
    np.testing.assert_array_equal(final.traction, h.traction[-1])  # untouched by the new run


def test_traction_control_of_many_points_is_not_checked_as_a_normal_traction() -> None:
    """A tangential traction target (N, 2) reached after a slide (it was once passed to the
    normal-traction check and failed to broadcast)."""
    program = (
        Slide(velocity=0.1, distance=0.03, steps=3),
        Traction(traction=(0.2, 0.0), steps=4),
    )
    h = simulate(set_a(), program, n_points=4)
    assert h.success, h.message
    np.testing.assert_allclose(h.traction[-1, :, 0], 0.2, rtol=1e-10)
    np.testing.assert_array_equal(h.traction[-1, :, 1], 0.0)
