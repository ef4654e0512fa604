"""The calibration's view of a programme: its duration, the model at the samples."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.calibration import evaluate_columns
from frictionlab.calibration.model import program_duration
from frictionlab.driver import (
    Cycle,
    Hold,
    InitialConditions,
    NormalStep,
    Reverse,
    Slide,
    Traction,
    Turn,
    simulate,
)

from .support import make_curve, true_params


def test_program_duration_is_the_time_the_driver_runs() -> None:
    program = (
        Slide(velocity=1e-4, distance=2e-4, steps=20),
        Hold(duration=12.5),
        Reverse(velocity=2e-4, duration=0.5, steps=10),
        Turn(angle_deg=90.0, steps=10),
        Cycle(amplitude=1e-5, velocity=1e-5, cycles=2, steps=40),
        NormalStep(traction=1.5e6, duration=3.0),
        Traction(traction=[1e5, 0.0], duration=4.0, steps=10),
    )
    history = simulate(true_params(), program, InitialConditions(normal_traction=1e6))
    assert history.success, history.message
    assert program_duration(program) == pytest.approx(history.time[-1, 0], rel=1e-12)


def test_columns_of_one_run_equal_separate_runs() -> None:
    curve = make_curve(0.0)
    names = ("mu_s", "xi")
    columns = np.array([[0.5, 0.52, 0.5], [5e-3, 5e-3, 6e-3]])
    together = evaluate_columns(true_params(), names, columns, curve)
    for k in range(3):
        alone = evaluate_columns(true_params(), names, columns[:, [k]], curve)[0]
        np.testing.assert_allclose(together[k], alone, rtol=0, atol=1e-14)
    # Column 0 is the true law: its model is the (noise-free) data.
    np.testing.assert_allclose(together[0], curve.friction_ratio, rtol=0, atol=1e-14)
