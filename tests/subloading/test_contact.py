"""3-D contact: normal approach, separation and re-closing, objectivity."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.subloading import (
    Status,
    global_traction,
    hold_recovery,
    initial_state,
    local_increment,
    rotate_frame,
    update,
)

from .support import fresh, set_a, set_b, slide


def rotation_matrix(axis: np.ndarray, angle: float) -> np.ndarray:
    """Rodrigues' formula, written here independently of the library."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def test_normal_approach_is_elastic_and_exact() -> None:
    params = set_a(alpha_n=2500.0)
    state = slide(params, fresh(params), 0.2, 100).state
    for dun in (1e-4, -2e-4, 3e-5):
        step = update(params, state, np.array([[1e-4, 0.0, dun]]), 0.01)
        assert step.traction[0, 2] == state.traction[0, 2] + 2500.0 * dun  # exact (linear)
        assert step.plastic_slip_increment[0, 2] == 0.0
        state = step.state


@pytest.mark.parametrize("mode", ["continue", "frozen"])
def test_separation_opens_and_reclosing_remembers_the_gap(mode: str) -> None:
    params = set_a(open_recovery=mode)
    state = slide(params, fresh(params), 1.0, 200).state
    F_stop = float(state.F[0])
    fn0 = float(state.traction[0, 2])
    # separate by 3e-3 beyond zero traction
    step = update(params, state, np.array([[5e-4, 0.0, -fn0 / 1000.0 - 3e-3]]), 10.0)
    assert step.status[0] == Status.OPEN
    np.testing.assert_array_equal(step.traction[0], [0.0, 0.0, 0.0])
    assert step.state.R[0] == 0.0 and step.state.is_open[0]
    assert step.state.gap[0] == pytest.approx(3e-3, rel=1e-12)
    expected_F = hold_recovery(F_stop, 0.5, 1e-3, 10.0) if mode == "continue" else F_stop
    assert step.state.F[0] == pytest.approx(expected_F, rel=1e-14)
    state = step.state
    # tangential slip while open: no traction
    step = update(params, state, np.array([[1e-2, 3e-3, 1e-3]]), 1.0)
    assert step.status[0] == Status.OPEN and step.state.gap[0] == pytest.approx(2e-3, rel=1e-12)
    state = step.state
    # approach by 1.5e-3 < gap: still open
    step = update(params, state, np.array([[0.0, 0.0, 1.5e-3]]), 0.0)
    assert step.status[0] == Status.OPEN and step.state.gap[0] == pytest.approx(5e-4, rel=1e-9)
    # re-close: approach 1e-3 more -> 0.5e-3 of elastic approach, tangential traction from zero
    step = update(params, step.state, np.array([[0.0, 0.0, 1e-3]]), 0.0)
    assert step.status[0] == Status.STICK
    np.testing.assert_allclose(step.traction[0], [0.0, 0.0, 1000.0 * 0.5e-3], rtol=1e-9)
    assert step.state.gap[0] == 0.0 and step.state.R[0] == 0.0
    # from R = 0 any tangential loading starts the smooth (subloading) transition
    step = update(params, step.state, np.array([[2e-6, 0.0, 0.0]]), 0.0)
    assert 0.0 < step.traction[0, 0] < 1000.0 * 2e-6


def test_reclosed_contact_slides_again_with_recovered_friction() -> None:
    params = set_a()
    state = slide(params, fresh(params), 1.0, 200).state
    opened = update(params, state, np.array([[0.0, 0.0, -0.01]]), 1e5).state  # long separation
    closed = update(params, opened, np.array([[0.0, 0.0, 0.01]]), 0.0).state  # gap 9e-3 + 1e-3
    assert closed.traction[0, 2] == pytest.approx(1.0, rel=1e-10)
    again = slide(params, closed, 0.2, 200)
    assert again.traction[:, 0, 0].max() > state.traction[0, 0] + 0.1  # static friction back


def test_closed_surface_tracks_pressure_changes_plastically() -> None:
    """Raising f_n on the dense side of a closed surface during sliding is admissible."""
    params = set_b("modified_cam_clay")
    state = slide(params, fresh(params, fn=0.2), 0.5, 100).state
    step = update(params, state, np.array([[1e-4, 0.0, 1e-4]]), 0.01)  # f_n 0.2 -> 0.3
    assert step.success and step.traction[0, 2] == pytest.approx(0.3, rel=1e-12)


def test_rigid_rotation_without_sliding_is_objective() -> None:
    params = set_a(rotation=(0.04, 0.01), orthotropy=(1.0, 0.7))
    state = slide(params, fresh(params, n=3), 0.3, 60, direction=(0.8, 0.6)).state
    before_global = global_traction(state)
    rng = np.random.default_rng(3)
    Q = np.array([rotation_matrix(rng.normal(size=3), rng.uniform(-3, 3)) for _ in range(3)])
    rotated = rotate_frame(state, Q)
    np.testing.assert_array_equal(rotated.traction, state.traction)  # co-rotating components
    np.testing.assert_allclose(global_traction(rotated), np.einsum("nij,nj->ni", Q, before_global),
                               atol=1e-15)  # fmt: skip
    # the pair moves rigidly: the global relative slip is zero -> no plastic sliding
    step = update(params, rotated, local_increment(rotated, np.zeros((3, 3))), 0.0)
    assert np.all(step.plastic_multiplier == 0.0)
    np.testing.assert_allclose(step.traction, state.traction, rtol=1e-15)


def test_sliding_in_a_rotated_frame_gives_the_rotated_response() -> None:
    """beta and the orthotropy axes ride with the frame (Eqs 19, 81)."""
    params = set_a(rotation=(0.05, 0.0), orthotropy=(1.0, 0.6))
    Q = rotation_matrix(np.array([1.0, 2.0, 0.5]), 1.1)
    a = fresh(params)
    b = rotate_frame(fresh(params), Q)
    slip_dir_global = np.array([0.6, 0.8, 0.0])
    for _ in range(300):
        du_a = local_increment(a, 1e-3 * slip_dir_global)
        du_b = local_increment(b, 1e-3 * (Q @ slip_dir_global))
        np.testing.assert_allclose(du_b, du_a, atol=1e-16)
        a = update(params, a, du_a, 0.01).state
        b = update(params, b, du_b, 0.01).state
    np.testing.assert_allclose(global_traction(b)[0], Q @ global_traction(a)[0], atol=1e-14)


def test_local_increment_and_global_traction_conventions() -> None:
    params = set_a()
    state = initial_state(params, normal_traction=2.0, tangential_traction=(0.3, -0.1))
    # the body's outward normal is +z; compression means the traction points along -n
    np.testing.assert_allclose(global_traction(state)[0], [0.3, -0.1, -2.0])
    # the counter body moving along -n approaches: positive normal slip
    np.testing.assert_allclose(local_increment(state, [1e-3, 0.0, -2e-3])[0], [1e-3, 0.0, 2e-3])


def test_rotate_frame_rejects_non_rotations() -> None:
    state = fresh(set_a())
    with pytest.raises(ParameterError, match="rotation"):
        rotate_frame(state, np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ParameterError, match="rotation"):
        rotate_frame(state, 2.0 * np.eye(3))
