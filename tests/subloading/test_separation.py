"""Unloading to the edge of separation (the surface is singular at f_n = 0).

Issue: an unload that left 0 < f_n(trial) <= 1e-8 with tangential traction made the tear
and parabola solves fail (ConvergenceError), and there was no tolerance for "no contact".
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.subloading import Status, initial_state, update

from .support import set_a, set_b, slide


def _g_and_slope(surface: str, chi: float) -> tuple[float, float]:
    """g(chi), g'(chi) of Eqs (51)-(54) (defaults), written out here."""
    if surface == "cam_clay":
        return float(np.exp(chi)), float(np.exp(chi))
    if surface == "modified_cam_clay":
        return 1.0 + chi**2, 2.0 * chi
    if surface == "tear":
        return 3.0 / (3.0 - chi**2), 6.0 * chi / (3.0 - chi**2) ** 2
    return 2.0 / (2.0 - chi), 2.0 / (2.0 - chi) ** 2  # parabola


@pytest.mark.parametrize("surface", ["tear", "parabola", "cam_clay", "modified_cam_clay"])
@pytest.mark.parametrize("fraction", [1e-6, 1e-8, 1e-10, 1e-12])
def test_unloading_to_a_sliver_of_normal_traction_converges(surface: str, fraction: float) -> None:
    params = set_b(surface)
    state = slide(params, initial_state(params, normal_traction=0.4), 0.02, 40).state
    du = np.zeros((1, 3))
    du[0, 2] = -(1.0 - fraction) * state.traction[0, 2] / float(params.alpha_n)
    step = update(params, state, du, 0.0)  # raises ConvergenceError on failure
    fn = step.traction[0, 2]
    assert step.status[0] == Status.SLIP and 0.0 < fn <= 1.01 * fraction * 0.4
    chi = float(np.hypot(*step.traction[0, :2])) / (0.5 * fn)  # M = 0.5, beta = 0
    g, dg = _g_and_slope(surface, chi)
    assert np.isfinite(g)
    phi = fn * g
    F, R = float(step.state.F[0]), float(step.state.R[0])
    # on the surface to the rounding of Phi itself: eps * Phi_w w = eps * f_n g'(chi) chi
    # (the "condition number" of Phi; theory.md, "Accuracy"), and to 1e-12 F where that
    # is smaller
    assert abs(phi - R * F) <= 1e-12 * max(F, fn * dg * chi)


@pytest.mark.parametrize("surface", ["coulomb", "tear", "parabola"])
def test_a_trial_normal_traction_zero_to_rounding_opens_the_contact(surface: str) -> None:
    params = set_a() if surface == "coulomb" else set_b(surface)
    fn0 = 1.0 if surface == "coulomb" else 0.4
    state = slide(params, initial_state(params, normal_traction=fn0), 0.02, 40).state
    du = np.zeros((1, 3))
    du[0, 2] = -(1.0 - 1e-13) * state.traction[0, 2] / float(params.alpha_n)
    step = update(params, state, du, 0.0)
    assert step.status[0] == Status.OPEN
    assert np.all(step.traction == 0.0) and step.state.R[0] == 0.0
