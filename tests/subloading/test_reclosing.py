"""Re-closing after separation (theory.md, "Re-closing").

Issue: with a rotation vector beta, re-closing set R = 0 and the contact then slid
plastically under pure normal approach. A contact that re-forms is a virgin contact:
f_t = 0 and R = Phi(f_t = 0, f_n)/F (|beta|/F for the cone, as ``initial_state``).
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.subloading import Status, initial_state, update

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
