"""Consistent tangent against central finite differences."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.subloading import Status, update

from .support import fresh, set_a, set_b, slide

CASES = [
    ("coulomb isotropic", set_a, {}),
    ("coulomb rotated", set_a, {"rotation": (0.05, -0.03)}),
    ("coulomb orthotropic", set_a, {"orthotropy": (1.0, 0.6), "orthotropy_angle": 0.5}),
    (
        "coulomb all",
        set_a,
        {"rotation": (0.04, 0.02), "orthotropy": (0.8, 1.2), "m": 2.0, "n": 0.5},
    ),
    ("coulomb ln law", set_a, {"U_law": "ln"}),
    ("coulomb backward euler", set_a, {"F_integrator": "backward_euler"}),
    ("cam_clay", lambda **k: set_b("cam_clay", **k), {}),
    (
        "modified_cam_clay rotated",
        lambda **k: set_b("modified_cam_clay", **k),
        {"rotation": (0.1, 0.05)},
    ),
    (
        "tear orthotropic",
        lambda **k: set_b("tear", **k),
        {"orthotropy": (1.0, 0.7), "orthotropy_angle": -0.3},
    ),
    ("parabola", lambda **k: set_b("parabola", **k), {"rotation": (0.0, 0.1)}),
    ("tear k=2", lambda **k: set_b("tear", **k), {"tear_k": 2.0}),
]


@pytest.mark.parametrize(("name", "factory", "changes"), CASES, ids=[c[0] for c in CASES])
def test_tangent_matches_central_differences(name, factory, changes) -> None:  # type: ignore[no-untyped-def]
    params = factory(**changes)
    fn = 1.0 if params.is_cone else 0.2
    rng = np.random.default_rng(7)
    # states at several points of a 2-D loading path: transition, peak, softening
    base = slide(params, fresh(params, fn=fn), 0.03, 60, direction=(0.9, 0.45)).state
    states = [base, slide(params, base, 0.3, 30, direction=(0.6, 0.8)).state]
    checked = 0
    for state in states:
        for _ in range(4):
            du = np.zeros((1, 3))
            du[0, :2] = rng.normal(size=2) * 4e-4 + 3e-4 * np.array([0.6, 0.8])
            du[0, 2] = rng.normal() * 2e-5
            dt = 0.01
            step = update(params, state, du, dt)
            if step.status[0] != Status.SLIP:
                continue
            numeric = np.empty((3, 3))
            for j in range(3):
                h = 2e-8  # [m]; increments are ~1e-4 m
                plus, minus = du.copy(), du.copy()
                plus[0, j] += h
                minus[0, j] -= h
                sp = update(params, state, plus, dt)
                sm = update(params, state, minus, dt)
                assert sp.status[0] == sm.status[0] == Status.SLIP
                numeric[:, j] = (sp.traction[0] - sm.traction[0]) / (2 * h)
            analytic = step.tangent[0]
            err = np.linalg.norm(analytic - numeric) / np.linalg.norm(analytic)
            assert err < 1e-6, (name, err, analytic, numeric)
            checked += 1
    assert checked >= 4


def test_tangent_is_non_symmetric_in_plastic_sliding() -> None:
    params = set_b("modified_cam_clay", rotation=(0.1, 0.0))
    state = slide(params, fresh(params, fn=0.2), 0.05, 50).state
    step = update(params, state, np.array([[1e-4, 0.0, 1e-5]]), 0.01)
    T = step.tangent[0]
    assert step.status[0] == Status.SLIP
    assert abs(T[0, 2] - T[2, 0]) > 1e-3 * np.abs(T).max()


def test_elastic_and_open_tangents() -> None:
    params = set_a(alpha_n=2000.0, alpha_t=700.0)
    state = fresh(params)
    rest = update(params, state, np.zeros((1, 3)), 1.0)
    np.testing.assert_array_equal(rest.tangent[0], np.diag([700.0, 700.0, 2000.0]))
    opened = update(params, state, np.array([[0.0, 0.0, -1.0]]), 0.0)
    assert opened.status[0] == Status.OPEN
    np.testing.assert_array_equal(opened.tangent[0], np.zeros((3, 3)))


@pytest.mark.parametrize("factory", [set_a, lambda **k: set_b("tear", **k)])
def test_tangent_of_a_reversal_inside_one_step(factory) -> None:  # type: ignore[no-untyped-def]
    """The partial-unloading correction makes R_start depend on du; the tangent includes it."""
    params = factory(rotation=(0.03, 0.01), orthotropy=(1.0, 0.8))
    fn = 1.0 if params.is_cone else 0.2
    state = slide(params, fresh(params, fn=fn), 0.2, 100).state
    f_t = state.traction[0, :2]
    du = np.zeros((1, 3))
    du[0, :2] = -1.6 * f_t / 1000.0 + np.array([0.0, 2e-5])  # through the axis and beyond
    du[0, 2] = 1e-5
    step = update(params, state, du, 0.01)
    assert step.status[0] == Status.SLIP
    numeric = np.empty((3, 3))
    for j in range(3):
        plus, minus = du.copy(), du.copy()
        plus[0, j] += 2e-8
        minus[0, j] -= 2e-8
        numeric[:, j] = (update(params, state, plus, 0.01).traction[0]
                         - update(params, state, minus, 0.01).traction[0]) / 4e-8  # fmt: skip
    err = np.linalg.norm(step.tangent[0] - numeric) / np.linalg.norm(numeric)
    assert err < 1e-6
