"""Patch test: a block pressed uniformly and translated rigidly reproduces the
single-point driver (frictionlab.simulate) at every contact point.

With nu = 0 a uniform pressure gives a uniform uniaxial strain, so every contact point
carries f_n = p exactly; with the tangential displacement imposed on every node
(drive="rigid") every point slips by the top displacement. Each point is then the
driver's single point with the same increments, and the friction ratio Q/P of the
block must equal the driver's f_t/f_n to the Newton tolerance.
"""

from __future__ import annotations

import numpy as np
from tests.contact.support import PRESSURE, SLIDE_HOLD_SLIDE, law, pmma_block

from frictionlab.contact import NormalLoad, run_contact
from frictionlab.driver import Hold as DHold
from frictionlab.driver import InitialConditions, simulate
from frictionlab.driver import Slide as DSlide


def test_rigid_translation_reproduces_the_single_point_driver() -> None:
    params = law()
    normal = NormalLoad(pressure=PRESSURE, duration=1.0, steps=2)
    history = run_contact(pmma_block(nu=0.0), params, normal, SLIDE_HOLD_SLIDE, drive="rigid")
    assert history.success, history.message
    assert np.all(history.cuts == 0)  # nominal steps, as the driver takes them
    # the driver: the same slide/hold/slide from the pressed, virgin contact; the base
    # slips along -x relative to the block (direction 180 deg in the contact frame)
    reference = simulate(
        params,
        [
            DSlide(velocity=1e-5, distance=30e-6, steps=15, direction_deg=180.0),
            DHold(duration=10.0, steps=2),
            DSlide(velocity=1e-5, distance=10e-6, steps=5),
        ],
        InitialConditions(normal_traction=PRESSURE),
    )
    assert reference.success
    tangential = history.stage > 0
    ratio_fe = history.friction_ratio[tangential]
    ratio_point = -reference.traction[1:, 0, 0] / reference.traction[1:, 0, 2]
    assert ratio_fe.shape == ratio_point.shape
    np.testing.assert_allclose(ratio_fe, ratio_point, rtol=1e-8, atol=1e-10)
    # uniform interface: every point carries the same traction and plastic slip
    f_t = history.traction_t[tangential]
    np.testing.assert_allclose(f_t, f_t[:, :1] * np.ones_like(f_t), rtol=1e-8, atol=1e-3)
    np.testing.assert_allclose(history.traction_n[tangential], PRESSURE, rtol=1e-9)
    np.testing.assert_allclose(
        history.plastic_slip[-1], reference.plastic_slip[-1, 0], rtol=1e-8, atol=1e-15
    )
