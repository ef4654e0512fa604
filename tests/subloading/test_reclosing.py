"""Re-closing after separation (theory.md, "Re-closing").

Issue: with a rotation vector beta, re-closing set R = 0 and the contact then slid
plastically under pure normal approach. A contact that re-forms is a virgin contact:
f_t = 0 and R = Phi(f_t = 0, f_n)/F (|beta|/F for the cone, as ``initial_state``).
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from frictionlab.subloading import Status, SubloadingParams, initial_state, update
from frictionlab.subloading.reference import yield_value

from .support import set_a, set_b, slide


def _opened(params, fn0):  # type: ignore[no-untyped-def]
    state = slide(params, initial_state(params, normal_traction=fn0), 0.5, 100).state
    du = np.array([[0.0, 0.0, -fn0 / float(params.alpha_n) - 2e-3]])
    step = update(params, state, du, 5.0)
    assert step.status[0] == Status.OPEN
    return step.state


@pytest.mark.parametrize("surface", ["coulomb", "modified_cam_clay", "tear"])
def test_pure_normal_reclosing_is_elastic_with_the_virgin_ratio(surface: str) -> None:
    beta = np.array([0.06, -0.02])
    if surface == "coulomb":
        params, fn0 = set_a(rotation=tuple(beta)), 1.0
    else:
        params, fn0 = set_b(surface, rotation=tuple(beta)), 0.3
    opened = _opened(params, fn0)
    fn_new = 0.8 * fn0
    step = update(params, opened, np.array([[0.0, 0.0, 2e-3 + fn_new / 1000.0]]), 0.0)
    assert step.status[0] == Status.STICK
    np.testing.assert_allclose(step.traction[0], [0.0, 0.0, fn_new], rtol=1e-9, atol=1e-15)
    virgin = initial_state(params, normal_traction=fn_new)
    F = float(step.state.F[0])
    # the virgin ratio at the reached normal traction, with the current size F
    assert step.state.R[0] == pytest.approx(float(virgin.R[0]) * float(virgin.F[0]) / F,
                                            rel=1e-12)  # fmt: skip
    if surface == "coulomb":
        assert step.state.R[0] == pytest.approx(float(np.hypot(*beta)) / F, rel=1e-12)
        # the cone's ratio does not depend on f_n: further pure approach stays elastic
        # (a closed surface with beta != 0 flows under normal loading, as from
        # initial_state: test_contact.py)
        again = update(params, step.state, np.array([[0.0, 0.0, 1e-4]]), 0.0)
        assert again.status[0] == Status.STICK and np.all(again.traction[0, :2] == 0.0)


def test_reclosing_is_continuous_in_the_approach() -> None:
    """Tangential slip during a closing step loads only the part after the closure."""
    params = set_a(rotation=(0.06, -0.02))
    opened = _opened(params, 1.0)  # gap 2e-3
    tangential = np.array([2e-5, 1e-5])
    ft = []
    approaches = 2e-3 + np.array([0.0, 1e-12, 1e-9, 1e-6, 1e-4])
    for dun in approaches:
        step = update(params, opened, np.array([[*tangential, dun]]), 0.0)
        ft.append(step.traction[0, :2])
    ft = np.array(ft)
    # closing exactly at the end of the step: no tangential traction (continuity with OPEN)
    assert np.all(np.abs(ft[0]) <= 1e-300)
    # then f_t = alpha_t (1 - s_c) du_t while elastic, s_c = gap/du_n
    s_c = 2e-3 / approaches[1:]
    np.testing.assert_allclose(ft[1:], 1000.0 * (1 - s_c)[:, None] * tangential, rtol=1e-9)


def test_tangent_of_a_closing_step_matches_central_differences() -> None:
    params = set_a(rotation=(0.06, -0.02))
    opened = _opened(params, 1.0)
    for du in (np.array([[4e-4, 1e-4, 2.5e-3]]), np.array([[2e-6, -1e-6, 2.5e-3]])):
        step = update(params, opened, du, 0.0)
        fd = np.zeros((3, 3))
        for j in range(3):
            h = 1e-7 * max(abs(du[0, j]), 1e-4)
            up, dn = du.copy(), du.copy()
            up[0, j] += h
            dn[0, j] -= h
            fd[:, j] = (update(params, opened, up, 0.0).traction[0]
                        - update(params, opened, dn, 0.0).traction[0]) / (2 * h)  # fmt: skip
        np.testing.assert_allclose(step.tangent[0], fd, rtol=1e-5, atol=1e-6 * np.abs(fd).max())


# Issue 27 item 1: a contact that re-closes while the opening has recovered its size (xi > 0)
# must end on or inside its sliding-yield surface. Scales of the issue's reproducer: F_k = 1e4,
# F_s = 2e4, one second of recovery takes F from 1e4 to ~1.14e4; targets below, near and
# above the size before the step.
CLOSED = ["cam_clay", "modified_cam_clay", "tear", "parabola"]
ROTATIONS = [(0.0, 0.0), (0.4, 0.0), (0.15, -0.25)]
TARGETS = [0.5e4, 0.95e4, 1.1e4]  # [Pa]
SLIPS = [0.0, -5e-9, -5e-5]  # [m]: none, elastic-sized (5e3 Pa), far beyond the surface


def _recovering(surface: str, rotation: tuple[float, float]):  # type: ignore[no-untyped-def]
    return SubloadingParams(surface=surface, F_s=2e4, F_k=1e4, M=1.0, rotation=rotation,
                            alpha_n=2e7, alpha_t=1e12, u=1e4, kappa=0.0, xi=3000.0)  # fmt: skip


def _surface_error(params, step) -> float:  # type: ignore[no-untyped-def]
    """|f - R F| / F of a step's end state, f from the reference yield function."""
    f = yield_value(params, step.traction[0])
    return abs(f - float(step.state.R[0]) * float(step.state.F[0])) / float(step.state.F[0])


@pytest.mark.parametrize("surface", CLOSED)
def test_a_reclosing_step_ends_on_or_inside_the_surface(surface: str) -> None:
    """Every re-closing step ends with R <= 1 on its subloading surface to the accuracy of a
    step from a closed contact, or FAILED where the same step from a closed contact fails."""
    for rotation, target, slip in itertools.product(ROTATIONS, TARGETS, SLIPS):
        params = _recovering(surface, rotation)
        closed = initial_state(params, normal_traction=2e3, F=1e4)
        opened = update(params, closed, np.array([[0.0, 0.0, -1e-3]]), 0.0).state
        case = f"{surface} rotation={rotation} target={target} slip={slip}"
        assert opened.traction[0, 2] == 0.0, case
        du = np.array([[0.0, slip, float(opened.gap[0]) + target / 2e7]])
        step = update(params, opened, du, 1.0, raise_on_failure=False)
        direct = update(params, closed, np.array([[0.0, slip, (target - 2e3) / 2e7]]), 1.0,
                        raise_on_failure=False)  # fmt: skip
        assert direct.status[0] != Status.FAILED, case  # the grid stays carriable
        assert step.status[0] in (Status.STICK, Status.SLIP), case
        assert step.traction[0, 2] == pytest.approx(target, rel=1e-12), case
        assert 0.0 <= step.state.R[0] <= 1.0, case
        assert _surface_error(params, step) <= 1e-12, case
        assert _surface_error(params, direct) <= 1e-12, case


def test_the_issue_reproducer_stays_inside() -> None:
    """The issue's case: R was 1.0716 with SLIP (outside the recovered surface)."""
    params = _recovering("modified_cam_clay", (0.0, 0.0))
    state = update(params, initial_state(params, 5e3, F=1e4), [[0, 0, -1e-3]], 0.0).state
    step = update(params, state, [[0, -5e-5, state.gap[0] + 1.1e4 / 2e7]], 1.0)
    assert step.status[0] == Status.SLIP
    assert step.state.R[0] <= 1.0 and _surface_error(params, step) <= 1e-12
    # the contact forms at f_n = 1.1e4 with the size recovered over the step (exact for
    # n = 1, kappa = 0): F_s - (F_s - F) exp(-xi dt / F_s)
    assert step.state.F[0] == pytest.approx(2e4 - 1e4 * np.exp(-3000.0 / 2e4), rel=1e-14)


@pytest.mark.parametrize("surface", CLOSED)
def test_tangent_of_a_recovering_reclosing_step_matches_central_differences(surface) -> None:  # type: ignore[no-untyped-def]
    params = _recovering(surface, (0.15, -0.25))
    closed = initial_state(params, normal_traction=2e3, F=1e4)
    opened = update(params, closed, np.array([[0.0, 0.0, -1e-3]]), 0.0).state
    gap = float(opened.gap[0])
    # an elastic closing, and a plastic one whose starting ratio is the virgin ratio of the
    # end-of-step normal traction (it depends on du_n)
    for du in (np.array([[2e-9, -4e-9, gap + 0.9e4 / 2e7]]),
               np.array([[1e-6, 2e-6, gap + 1.0e4 / 2e7]])):  # fmt: skip
        step = update(params, opened, du, 1.0)
        fd = np.zeros((3, 3))
        for j in range(3):
            h = 1e-6 * (abs(du[0, j]) if j < 2 else 1.1e4 / 2e7)
            up, dn = du.copy(), du.copy()
            up[0, j] += h
            dn[0, j] -= h
            fd[:, j] = (update(params, opened, up, 1.0).traction[0]
                        - update(params, opened, dn, 1.0).traction[0]) / (2 * h)  # fmt: skip
        np.testing.assert_allclose(step.tangent[0], fd, rtol=1e-5, atol=1e-6 * np.abs(fd).max())
