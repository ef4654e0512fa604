"""The driver's direct path for slip-controlled steps (SlipSteps) gives exactly the history
of the general path (advance: solve_control, substepping, attempts), which is its reference:
each run is repeated with the direct path switched off and compared bit for bit."""

from __future__ import annotations

from typing import Any

import pytest

from frictionlab.driver import (
    Cycle,
    DriverSettings,
    Hold,
    InitialConditions,
    NormalStep,
    Recording,
    Reverse,
    Slide,
    simulate,
    stepping,
)
from frictionlab.subloading import SubloadingParams

from .support import assert_same, set_a

CASES = {
    "one point, slide-hold-slide-reverse": (
        set_a(alpha_n=1e12, alpha_t=1e11, u=1e5, kappa=1e3, xi=1e-2),
        (Slide(velocity=1e-4, distance=2e-4, steps=60), Hold(duration=30.0, steps=20),
         Slide(velocity=1e-4, distance=1e-4, steps=40), Reverse(steps=30)),
        1, None,
    ),
    "three points, cycles and a normal step, every 3rd row": (
        SubloadingParams(surface="modified_cam_clay", alpha_n=1e12, alpha_t=1e12, F_s=2e6,
                         F_k=1.5e6, M=0.5, u=1e5, kappa=1e3, xi=1e-3),
        (Cycle(amplitude=3e-6, velocity=1e-5, steps=40), NormalStep(traction_change=2e5, steps=3),
         Slide(velocity=1e-5, distance=2e-6, direction_deg=30.0, steps=25)),
        3, Recording(every=3),
    ),
}  # fmt: skip


def _run(params: SubloadingParams, program: Any, n: int, recording: Any) -> Any:
    # the Python steps (the compiled loop has its own test: test_compiled_steps.py)
    return simulate(params, program, InitialConditions(normal_traction=1e6), n_points=n,
                    recording=recording, settings=DriverSettings(compiled=False))  # fmt: skip


@pytest.mark.parametrize("case", list(CASES))
def test_direct_slip_steps_match_the_general_path(case: str, monkeypatch) -> None:
    params, program, n, recording = CASES[case]
    calls = {"direct": 0}
    real = stepping.SlipSteps.step

    def counted(self, state, control):  # type: ignore[no-untyped-def]
        calls["direct"] += 1
        return real(self, state, control)

    monkeypatch.setattr(stepping.SlipSteps, "step", counted)
    fast = _run(params, program, n, recording)
    assert fast.success and calls["direct"] >= 0.9 * fast.work["steps"]  # the path was taken
    monkeypatch.setattr(stepping.SlipSteps, "step", lambda self, state, control: None)
    general = _run(params, program, n, recording)
    assert_same(fast, general)


def test_a_failed_direct_step_falls_back_to_the_general_path(monkeypatch) -> None:
    """Every 4th direct step is reported failed after its kernel call wrote the free
    buffers: the general path then repeats the step from the same state (as it does when
    the law fails) and the history is unchanged."""
    params, program, n, recording = CASES["one point, slide-hold-slide-reverse"]
    monkeypatch.setattr(stepping.SlipSteps, "step", lambda self, state, control: None)
    general = _run(params, program, n, recording)
    real = stepping.SlipSteps.step
    count = [0]

    def flaky(self, state, control):  # type: ignore[no-untyped-def]
        out = real(self, state, control)
        count[0] += 1
        return None if count[0] % 4 == 0 else out

    monkeypatch.setattr(stepping.SlipSteps, "step", flaky)
    assert_same(_run(params, program, n, recording), general)
    assert count[0] > 100
