"""The bundled reversal scenario resolves the elastic unloading after a reversal.

Its step once exceeded the elastic unloading range, so the demo never showed it. After a
reversal from kinetic sliding the traction returns elastically from mu f_n to zero over the
slip mu f_n / alpha_t (then R = 0 and smooth re-yielding starts): 0.3 um here.
"""

from __future__ import annotations

import numpy as np

from frictionlab.demo import bundled_scenario
from frictionlab.driver import simulate
from frictionlab.io.scenario import load_scenario
from frictionlab.subloading import Status


def test_reversal_scenario_shows_an_elastic_branch_of_slope_alpha_t() -> None:
    with bundled_scenario("reversal_cycles") as path:
        scenario = load_scenario(path, ())
    assert scenario.program is not None
    segments = tuple(scenario.program)[:2]  # the slide and the reversal
    h = simulate(scenario.params, segments, scenario.initial)
    rev = h.segments[1]
    rows = np.arange(rev.first_row, rev.last_row + 1)
    n_stick = int(np.argmax(h.status[rows, 0] != int(Status.STICK)))
    alpha_t = float(scenario.params.alpha_t)
    mu_fn = abs(float(h.traction[rev.first_row - 1, 0, 0]))
    # at least three steps inside the elastic range mu f_n / alpha_t
    assert n_stick >= 3
    assert n_stick * abs(np.diff(h.slip[rows[:2], 0, 0])[0]) <= mu_fn / alpha_t * (1 + 1e-9)
    stick = rows[:n_stick]
    slope = np.diff(h.traction[stick, 0, 0]) / np.diff(h.slip[stick, 0, 0])
    np.testing.assert_allclose(slope, alpha_t, rtol=1e-9)
