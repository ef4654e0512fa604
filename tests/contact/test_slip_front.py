"""The sliding-zone front: found by interpolation on R, robust to the lift-off edge."""

from __future__ import annotations

import numpy as np
import pytest
from tests.contact.support import NORMAL, SLIDE, law, pmma_block

from frictionlab.contact import ContactHistory, run_contact, slip_front

WIDTH = 0.1  # m


def _history(R: np.ndarray, status: np.ndarray, x: np.ndarray) -> ContactHistory:
    """A 2-D history holding only what the front reads (R, status, x, weights, width)."""
    S, P = R.shape
    zeros, grid = np.zeros(S), np.zeros((S, P))
    return ContactHistory(
        time=np.arange(S, dtype=float), stage=np.ones(S, dtype=int),
        top_displacement=1e-6 * np.arange(S), top_displacement_y=zeros, top_shear=zeros,
        top_shear_y=zeros, tangential_force=zeros, tangential_force_y=zeros,
        normal_force=zeros, iterations=np.zeros(S, dtype=int), cuts=np.zeros(S, dtype=int),
        residuals=[[] for _ in range(S)], x=x, y=np.zeros(P), weight=np.full(P, WIDTH / P),
        slip=grid, slip_y=grid, approach=grid, plastic_slip=grid, traction_t=grid,
        traction_t_y=grid, traction_n=grid, R=R, F=grid, status=status,
        nodes=np.array([[0.0, WIDTH], [0.0, 0.02]]), cells=np.zeros((3, 0), dtype=int),
        dof_x=np.zeros(0, dtype=int), dof_y=np.zeros(0, dtype=int),
    )  # fmt: skip


def test_front_of_a_linear_ratio_field_is_the_exact_crossing() -> None:
    # R falls linearly along x from a front moving at a constant speed: R = ratio exactly
    # at x_f(t) = 0.004 + 0.0031 t, so linear interpolation between points is exact
    P, ratio = 40, 0.9
    x = (np.arange(P) + 0.5) * WIDTH / P
    t = np.arange(20.0)
    expected = 0.004 + 0.0031 * t
    R = np.clip(ratio - 5.0 * (x[None, :] - expected[:, None]), 0.0, 1.0)
    front = slip_front(_history(R, np.ones_like(R, dtype=np.int8), x), ratio)
    np.testing.assert_allclose(front, expected, rtol=0, atol=1e-12)
    assert np.all(np.diff(front) > 0)  # monotonic, not a staircase on the points


def test_a_point_reclosing_at_the_lift_off_edge_does_not_pull_the_front_back() -> None:
    # trailing points open (status 2), the next one just re-closed with a low R, then a
    # released zone up to 60 mm and a stuck rest: the front is at 60 mm, not at the edge
    P = 20
    x = (np.arange(P) + 0.5) * WIDTH / P
    status = np.ones((1, P), dtype=np.int8)
    status[0, :3] = 2
    R = np.where(x < 0.06, 1.0, 0.5)[None, :].copy()
    R[0, :3] = 0.0
    R[0, 3] = 0.9  # re-closed, below the ratio
    front = slip_front(_history(R, status, x), 0.99)
    crossing = x[11] + (1.0 - 0.99) / (1.0 - 0.5) * (x[12] - x[11])
    assert front[0] == pytest.approx(crossing, abs=1e-12)


def test_no_release_gives_zero_and_full_release_the_width() -> None:
    x = (np.arange(10) + 0.5) * WIDTH / 10
    R = np.array([np.full(10, 0.2), np.full(10, 1.0)])
    front = slip_front(_history(R, np.ones((2, 10), dtype=np.int8), x), 0.99)
    assert front.tolist() == [0.0, WIDTH]


def test_a_3d_block_measures_the_front_on_the_mid_depth_line() -> None:
    # three lines of points at y = 0, 5, 10 mm, listed out of x order; only the middle
    # line has a released zone (up to between x = 30 and 50 mm)
    xs = np.array([0.05, 0.01, 0.03, 0.07, 0.09])
    x = np.tile(xs, 3)
    y = np.repeat([0.0, 0.005, 0.01], xs.size)
    R = np.full((1, x.size), 0.5)
    middle = y == 0.005
    R[0, middle & (x < 0.04)] = 1.0
    h = _history(R, np.ones((1, x.size), dtype=np.int8), x)
    h.y = y
    h.nodes = np.array([[0.0, WIDTH], [0.0, 0.01], [0.0, 0.02]])
    assert h.dim == 3
    expected = 0.03 + (1.0 - 0.99) / (1.0 - 0.5) * (0.05 - 0.03)
    assert slip_front(h, 0.99)[0] == pytest.approx(expected, abs=1e-15)


def test_front_of_a_first_slide_grows_monotonically() -> None:
    history = run_contact(pmma_block(element_size=0.005), law(), NORMAL, SLIDE)
    assert history.success
    front = slip_front(history, 0.99)[history.stage == 1]
    assert front[-1] == pytest.approx(WIDTH)  # the zone spans the interface by the end
    assert np.all(np.diff(front) >= 0.0)
