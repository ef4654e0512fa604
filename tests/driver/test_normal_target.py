"""Prescribed normal tractions: reached exactly after an opening; the no-contact rule.

Expected values are typed from the law's elastic normal response and its re-closing rule
(theory.md: a contact re-forms as a virgin contact; only the tangential slip after the
closure, the fraction c = (f*/alpha_n)/(gap + f*/alpha_n) of the step, loads it).
"""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from frictionlab.app.simulate import run_scenario
from frictionlab.driver.program import Control
from frictionlab.driver.stepping import solve_control
from frictionlab.io.scenario import parse_scenario
from frictionlab.subloading import Status, initial_state, update

from .support import set_a

SCENARIO = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
kappa = 1.0
xi = 0.001
alpha_t = 1000.0
alpha_n = {alpha_n!r}
[initial]
normal_traction = 1.0
[[program]]
kind = "normal"
approach = {opening!r}
[[program]]
kind = "normal"
traction = {target!r}
"""


def _run(alpha_n: float, opening: float, target: float):  # type: ignore[no-untyped-def]
    text = SCENARIO.format(alpha_n=alpha_n, opening=opening, target=target)
    return run_scenario(parse_scenario(tomllib.loads(text)))


@pytest.mark.parametrize("alpha_n", [1e3, 1e9, 1e15, 1e18])
@pytest.mark.parametrize("target", [1.0, 3.7e-3])
def test_a_normal_traction_target_after_an_opening_is_reached_exactly(
    alpha_n: float, target: float
) -> None:
    history = _run(alpha_n, -1e-3, target)  # opens by about 1 mm, then closes onto target
    assert history.success, history.message
    assert history.status[1, 0] == Status.OPEN
    assert pytest.approx(target, rel=1e-12) == float(history.traction[-1, 0, 2])


def test_tangential_slip_while_closing_onto_a_target_loads_only_after_the_closure() -> None:
    params = set_a(alpha_n=1e15)
    state = update(params, initial_state(params, normal_traction=1.0),
                   np.array([[0.0, 0.0, -1e-3]]), 0.0).state  # fmt: skip
    gap = float(state.gap[0])
    assert gap > 9e-4
    target, du_t = 0.8, np.array([3e-4, -2e-4])
    control = Control(np.zeros(1), du_t[None, :], np.zeros(1), fn_target=np.array([target]))
    attempt = solve_control(params, state, control)
    assert attempt.ok
    beyond = target / 1e15
    c = beyond / (gap + beyond)  # about 8e-13: far inside the cone, elastic to ~1e-11
    expected = 1000.0 * du_t * c
    np.testing.assert_allclose(attempt.state.traction[0, :2], expected, rtol=1e-9)
    assert pytest.approx(target, rel=1e-12) == float(attempt.state.traction[0, 2])
    assert attempt.state.gap[0] == 0.0
    np.testing.assert_array_equal(attempt.du[0, :2], du_t)  # the step's own slip is reported


@pytest.mark.parametrize("du_t", [(0.3, -0.2), (3e-4, -2e-4), (0.0, 0.0)])
def test_the_closing_form_is_the_laws_own_reclosing_where_nothing_cancels(du_t) -> None:
    """At a soft contact (f*/alpha_n comparable to the gap) the driver's step equals the law's
    re-closing step with the approach gap + f*/alpha_n, slip and plasticity included."""
    params = set_a()
    state = update(params, initial_state(params, normal_traction=1.0),
                   np.array([[0.0, 0.0, -1e-3]]), 0.0).state  # fmt: skip
    gap, target = float(state.gap[0]), 0.8
    control = Control(np.full(1, 2.0), np.array([du_t]), np.zeros(1), fn_target=np.array([target]))
    attempt = solve_control(params, state, control)
    direct = update(params, state, np.array([[*du_t, gap + target / 1000.0]]), 2.0)
    np.testing.assert_allclose(
        attempt.state.traction, direct.state.traction, rtol=1e-12, atol=1e-15
    )
    np.testing.assert_allclose(attempt.state.R, direct.state.R, rtol=1e-12)
    np.testing.assert_allclose(attempt.state.F, direct.state.F, rtol=1e-14)
    np.testing.assert_allclose(attempt.dissipation, direct.dissipation, rtol=1e-9, atol=1e-18)
    np.testing.assert_array_equal(attempt.status, direct.status)


@pytest.mark.parametrize("target", [1e-200, 1e-20])
def test_a_target_that_cannot_be_told_from_zero_stops_in_one_line(target: float) -> None:
    text = SCENARIO.format(alpha_n=1e3, opening=1e-4, target=target)  # closes first: f_n = 1.1
    history = run_scenario(parse_scenario(tomllib.loads(text)))
    assert not history.success
    assert "cannot be told from zero" in history.message and "\n" not in history.message
    assert not np.any(history.status[1:, 0] == Status.OPEN)  # never a silent opening


@pytest.mark.parametrize("target", [1e-9, 1e-13])
def test_a_small_target_above_the_rule_is_a_contact(target: float) -> None:
    """1e-13 Pa from 1.1 Pa is below the rule in one step; halved steps reach it."""
    text = SCENARIO.format(alpha_n=1e3, opening=1e-4, target=target)
    history = run_scenario(parse_scenario(tomllib.loads(text)))
    assert history.success, history.message
    fn = float(history.traction[-1, 0, 2])
    assert history.status[-1, 0] != Status.OPEN
    # reached to the rounding of its terms, about 1e-16 of the 1.1 Pa it changes from
    assert abs(fn - target) <= 1e-15
