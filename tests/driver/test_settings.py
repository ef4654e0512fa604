"""Solver settings go one way, ``settings=``; the old keywords are deprecated aliases that
give the same run (one release)."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.driver import (
    DriverSettings,
    Slide,
    SpringSlider,
    simulate,
    simulate_spring_slider,
)
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

PARAMS = SubloadingParams(alpha_n=1e12, alpha_t=1e12, mu_s=0.5, mu_k=0.3, u=1e6, kappa=1e4, xi=1e-2)
PROGRAM = (Slide(velocity=1e-4, distance=2e-5, steps=8),)


def test_old_keywords_warn_and_give_the_same_history() -> None:
    new = simulate(PARAMS, PROGRAM, settings=DriverSettings(accuracy=1e-5, max_halvings=4))
    with pytest.warns(DeprecationWarning, match=r"settings=DriverSettings\(accuracy=...,"):
        old = simulate(PARAMS, PROGRAM, accuracy=1e-5, max_halvings=4)
    np.testing.assert_array_equal(old.traction, new.traction)
    np.testing.assert_array_equal(old.time, new.time)
    assert old.work == new.work


def test_the_spring_slider_takes_the_same_settings() -> None:
    machine = SpringSlider(stiffness=1e9, velocity=1e-5)
    new = simulate_spring_slider(PARAMS, machine, 0.5, steps=50,
                                 settings=DriverSettings(max_halvings=3))  # fmt: skip
    with pytest.warns(DeprecationWarning, match="simulate_spring_slider"):
        old = simulate_spring_slider(PARAMS, machine, 0.5, steps=50, max_halvings=3)
    np.testing.assert_array_equal(old.traction, new.traction)


def test_settings_are_checked_and_not_mixed_with_the_old_keywords() -> None:
    with pytest.raises(ParameterError, match="max_halvings"):
        DriverSettings(max_halvings=-1)
    with pytest.raises(ParameterError, match="settings= alone"):
        simulate(PARAMS, PROGRAM, settings=DriverSettings(), accuracy=1e-5)
