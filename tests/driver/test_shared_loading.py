"""Slide, Reverse and Hold are one definition for the point driver and the contact model.

The contact model's stages are checked against hand-computed displacement vectors; the
rules (velocity > 0, a missing direction keeps the current one, steps or max_step) are
checked through both public names.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab import contact, driver, loading
from frictionlab.contact.loading import NormalLoad, plan_stages
from frictionlab.driver.program import plan_program
from frictionlab.errors import ParameterError

NORMAL = NormalLoad(pressure=1e6)


def test_one_definition_behind_both_names() -> None:
    for name in ("Slide", "Reverse", "Hold"):
        assert getattr(contact, name) is getattr(driver, name) is getattr(loading, name)


@pytest.mark.parametrize("velocity", [0.0, -1e-5])
def test_velocity_must_be_positive(velocity) -> None:
    with pytest.raises(ParameterError, match="velocity > 0"):
        contact.Slide(velocity=velocity, distance=1e-6)
    with pytest.raises(ParameterError, match="velocity > 0"):
        contact.Reverse(velocity=velocity)


def test_contact_direction_is_kept_unless_given() -> None:
    d = 1e-6
    program = [
        contact.Slide(velocity=1e-5, distance=d, direction_deg=90.0),
        contact.Slide(velocity=1e-5, distance=d),  # keeps 90 deg
        contact.Reverse(duration=0.05),  # back along -y for 1e-5 * 0.05 m
        contact.Slide(velocity=1e-5, distance=d, direction_deg=0.0),  # explicit 0: along x
    ]
    _, stages = plan_stages(NORMAL, program)
    ends = [s.end for s in stages[1:]]
    np.testing.assert_allclose(ends[0], [0.0, d], atol=1e-20)
    np.testing.assert_allclose(ends[1], [0.0, 2 * d], atol=1e-20)
    np.testing.assert_allclose(ends[2], [0.0, 2 * d - 5e-7], atol=1e-20)
    np.testing.assert_allclose(ends[3], [d, 2 * d - 5e-7], atol=1e-20)
    assert [s.duration for s in stages[1:]] == pytest.approx([0.1, 0.1, 0.05, 0.1])


def test_step_defaults_are_per_model_and_max_step_is_shared() -> None:
    slide, hold = contact.Slide(velocity=1.0, distance=1.0), contact.Hold(duration=1.0)
    _, stages = plan_stages(NORMAL, [slide, hold])
    assert [s.steps for s in stages[1:]] == [20, 5]  # the contact model's defaults
    plans = plan_program((slide, hold), 1)
    assert [p.estimated_steps for p in plans] == [100, 1]  # the driver's
    fine = contact.Slide(velocity=1.0, distance=1.0, max_step=0.3)
    _, stages = plan_stages(NORMAL, [fine])
    assert stages[1].steps == math.ceil(1.0 / 0.3) == plan_program((fine,), 1)[0].estimated_steps


def test_contact_takes_scalars_only() -> None:
    program = [contact.Slide(velocity=[1e-5, 2e-5], distance=1e-6)]
    with pytest.raises(ParameterError, match=r"velocity .*a scalar"):
        plan_stages(NORMAL, program)
