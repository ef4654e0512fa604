"""The FE model's loose ends (issue 27, item 5): nearly frictionless force control,
mu = 0, and the travel along the sliding direction of a 3-D run."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.contact import Block, NormalLoad, Slide, Traction, run_contact
from frictionlab.contact.frictionless import Frictionless, frictionless_update
from frictionlab.contact.interface import open_state
from frictionlab.errors import ParameterError

from .support import PRESSURE, law, pmma_block


@pytest.mark.parametrize("mu", [1e-3, 1e-6])
def test_nearly_frictionless_force_control_passes_the_normal_stage(mu: float) -> None:
    """Under tangential force control only friction holds the block in-plane while the
    Poisson expansion slides its bottom; the normal stage is now pinned (the reported
    "Newton failed in stage 0 (normal)" did not reproduce on this block with the code
    before the pins: a regression test, not a proof of the fix)."""
    params = law(mu_s=mu, mu_k=mu, kappa=0.0)
    history = run_contact(
        pmma_block(), params, NormalLoad(pressure=PRESSURE, steps=2),
        [Traction(target=0.5 * mu * PRESSURE, duration=1.0, steps=4)],
    )  # fmt: skip
    assert history.success, history.message
    assert history.normal_force[-1] == pytest.approx(PRESSURE * 0.1, rel=1e-9)
    # the applied shear is carried by friction: Q = 0.5 mu P at the end (to the Newton
    # tolerance 1e-10 of the largest force, P)
    Q = history.tangential_force[-1]
    assert abs(Q - 0.5 * mu * PRESSURE * 0.1) <= 1e-9 * PRESSURE * 0.1
    # the pins of the normal stage carried nothing (symmetric block): no jump after
    assert abs(history.tangential_force[2]) <= 1e-9 * PRESSURE * 0.1


def test_mu_zero_slides_without_resistance() -> None:
    block = pmma_block()
    history = run_contact(
        block, Frictionless(alpha_n=5e11), NormalLoad(pressure=PRESSURE, steps=2),
        [Slide(velocity=1e-5, distance=10e-6, steps=4)],
    )  # fmt: skip
    assert history.success, history.message
    assert np.all(np.abs(history.tangential_force) <= 1e-9 * PRESSURE * block.width)
    assert history.normal_force[-1] == pytest.approx(PRESSURE * block.width, rel=1e-9)
    closed = history.status[-1] != 2
    assert np.all(history.R[-1][closed] == 1.0)
    # a frictionless block slides as a whole: every closed point slipped the full 10 um
    assert np.allclose(history.slip[-1][closed] - history.slip[2][closed], 10e-6, rtol=1e-6)


def test_frictionless_update_opens_and_recloses_like_the_law() -> None:
    p = Frictionless(alpha_n=1e9)
    s = open_state(p, 3, gap=np.array([0.0, 1e-6, 2e-6]))  # type: ignore[arg-type]
    r = frictionless_update(p, s, np.array([[1e-7, 0, 1.5e-6]] * 3))
    assert r.traction[:, 2] == pytest.approx([1.5e3, 0.5e3, 0.0])
    assert r.state.gap == pytest.approx([0.0, 0.0, 0.5e-6])
    assert list(r.status) == [1, 1, 2]
    assert r.traction[:, :2].tolist() == [[0.0, 0.0]] * 3
    with pytest.raises(ParameterError, match="alpha_n"):
        Frictionless(alpha_n=0.0)


def test_3d_travel_is_along_the_sliding_direction() -> None:
    block = Block(E=3e9, nu=0.35, width=0.05, depth=0.05, height=0.0125,
                  element_size=0.0125, element="hex")  # fmt: skip
    history = run_contact(
        block, law(kappa=0.0), NormalLoad(pressure=PRESSURE, steps=2),
        [Slide(velocity=1e-5, distance=4e-6, steps=2, direction_deg=60.0)],
    )  # fmt: skip
    assert history.success, history.message
    ux, uy = history.top_displacement[-1], history.top_displacement_y[-1]
    assert history.travel[-1] == pytest.approx(4e-6, rel=1e-9)
    assert ux == pytest.approx(4e-6 * 0.5, rel=1e-9)  # x alone is half of it
    assert np.hypot(ux, uy) == pytest.approx(history.travel[-1], rel=1e-9)
