"""The 3-D block (hexahedra): sliding at an angle to the orthotropy axes turns the
traction away from the sliding direction, to the closed form of the orthotropic cone.

For the cone with orthotropy (C_1, C_2) (spec scenario A8) steady sliding along a
direction at angle theta from e*_1 gives the traction direction tan(phi) = (C_2/C_1)^2
tan(theta) and the magnitude mu_k f_n sqrt(C_1^4 cos^2 + C_2^4 sin^2) / sqrt(C_1^2 cos^2
+ C_2^2 sin^2) (associated flow: the surface normal along the slip). Before sliding the
traction follows the elastic (isotropic) penalty: parallel to the slip.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.contact import Block, NormalLoad, Slide, run_contact
from frictionlab.subloading import SubloadingParams

MU, C2, P = 0.5, 0.6, 1.0e6


def _law() -> SubloadingParams:
    return SubloadingParams(
        alpha_n=5e11, alpha_t=5e11, mu_s=MU, mu_k=MU, u=1e8, kappa=0.0, xi=0.0,
        orthotropy=(1.0, C2),
    )  # fmt: skip


def _steady(theta: float) -> tuple[float, float]:
    """Closed-form steady traction: its angle [rad] and |f_t|/f_n."""
    c, s = math.cos(theta), math.sin(theta)
    phi = math.atan2(C2**2 * s, c)
    ratio = MU * math.hypot(c, C2**2 * s) / math.hypot(c, C2 * s)
    return phi, ratio


@pytest.mark.parametrize("drive", ["rigid", "top"])
def test_oblique_sliding_turns_the_traction_to_the_orthotropic_closed_form(drive: str) -> None:
    theta = math.radians(45.0)
    block = Block(E=3e9, nu=0.0 if drive == "rigid" else 0.3, width=0.02, height=0.01,
                  depth=0.02, element_size=0.005, element="hex")  # fmt: skip
    history = run_contact(
        block, _law(), NormalLoad(pressure=P, steps=2),
        [Slide(velocity=1e-5, distance=0.5e-6, steps=2, direction_deg=45.0),
         Slide(velocity=1e-5, distance=120e-6, steps=20, direction_deg=45.0)], drive=drive,
    )  # fmt: skip
    assert history.success, history.message
    rows = history.stage > 0
    qx, qy = history.tangential_force[rows], history.tangential_force_y[rows]
    angle = np.arctan2(qy, qx)
    # first step (0.25 um, half the elastic slip at sliding): the traction along the slip
    assert angle[0] == pytest.approx(theta, abs=2e-3)
    phi, ratio = _steady(theta)
    assert math.degrees(phi) == pytest.approx(19.8, abs=0.05)
    assert angle[-1] == pytest.approx(phi, abs=2e-4)
    magnitude = np.hypot(qx, qy) / history.normal_force[rows]
    assert magnitude[-1] == pytest.approx(ratio, rel=1e-3)
    # the path turns monotonically from the slip direction to the steady direction
    assert np.all(np.diff(angle) <= 1e-9)


def test_dimension_mismatches_are_rejected_with_the_field() -> None:
    from frictionlab.errors import ParameterError

    with pytest.raises(ParameterError, match="element"):
        Block(E=3e9, nu=0.3, width=0.02, height=0.01, element_size=0.005, element="hex")
    with pytest.raises(ParameterError, match="element"):
        Block(E=3e9, nu=0.3, width=0.02, height=0.01, depth=0.02, element_size=0.005)
    flat = Block(E=3e9, nu=0.3, width=0.02, height=0.01, element_size=0.005)
    with pytest.raises(ParameterError, match="direction_deg"):
        run_contact(flat, _law(), NormalLoad(pressure=P),
                    [Slide(velocity=1e-5, distance=1e-6, direction_deg=30.0)])  # fmt: skip
