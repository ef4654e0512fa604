"""The driver's compiled loop over slip-controlled steps (driver/compiled_steps.py) gives
the history of the Python steps, its reference (``DriverSettings(compiled=False)``): every
run below is made both ways and compared array by array to 1e-12 relative (equal codes,
counters, step and row layout, segment figures and refined peaks), and the compiled loop
is checked to have run most steps."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import frictionlab.driver as fd
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

from .support import assert_same, set_a

RTOL = 1e-12


_CLOSED = {"alpha_n": 1e12, "alpha_t": 1e12, "F_s": 2e6, "F_k": 1.5e6, "M": 0.5, "u": 1e5,
           "kappa": 1e3, "xi": 1e-3}  # fmt: skip
_TABLE = fd.Table(
    time=np.array([0.0, 1.0, 2.0, 2.5]),
    slip=np.array([[0.0, 0.0], [2e-5, 0.0], [1e-5, 1e-5], [1e-5, 3e-5]]),
    steps_per_row=7,
)
_APPROACH_TABLE = fd.Table(
    time=np.array([0.0, 1.0, 2.0]),
    slip=np.array([[0.0, 0.0], [1e-5, 0.0], [3e-5, 0.0]]),
    approach=np.array([0.0, 1e-7, 5e-8]),
    steps_per_row=5,
)

#: name -> (law, programme, points, initial normal traction, recording, peak accuracy)
CASES: dict[str, tuple[Any, ...]] = {
    "one point: slide, holds with recovery, reverse": (
        set_a(alpha_n=5e11, alpha_t=2e11, u=5e4, kappa=1e3, xi=1e-2),
        (fd.Slide(velocity=1e-4, distance=1e-4, max_step=2e-6), fd.Hold(duration=10.0),
         fd.Slide(velocity=1e-4, distance=3e-5, max_step=2e-6), fd.Hold(duration=100.0, steps=4),
         fd.Reverse(steps=40)),
        1, 1e6, None, 1e-4,
    ),
    "seven points, per-point law (a fit's Jacobian run), no peak refinement": (
        set_a(alpha_n=5e11, alpha_t=np.linspace(1e11, 3e11, 7), u=5e4, kappa=1e3,
              xi=np.geomspace(1e-3, 1e-1, 7)),
        (fd.Slide(velocity=1e-4, distance=5e-5, steps=50), fd.Hold(duration=30.0),
         fd.Slide(velocity=1e-4, distance=2e-5, steps=20)),
        7, 1e6, None, None,
    ),
    "closed surface: cycles, turn, approach, every 3rd row": (
        SubloadingParams(surface="modified_cam_clay", **_CLOSED),
        (fd.Cycle(amplitude=3e-6, velocity=1e-5, steps=40, cycles=2),
         fd.Turn(angle_deg=60.0, distance=2e-6, velocity=1e-5, steps=25),
         fd.NormalStep(approach=1e-7, steps=3), fd.Reverse(steps=17)),
        3, 1e6, fd.Recording(every=3), 1e-4,
    ),
    "tear surface: tables of slip and approach, streamed in small chunks": (
        SubloadingParams(surface="tear", **_CLOSED),
        (_TABLE, _APPROACH_TABLE, fd.Hold(duration=5.0, steps=3)),
        2, 1e6, fd.Recording(sink=lambda chunk: None, chunk_rows=7), 1e-4,
    ),
    "opening and re-closing, then prescribed tractions (Python steps between)": (
        set_a(alpha_n=1e12, alpha_t=1e11, u=1e5, kappa=1e3, xi=1e-2),
        (fd.Slide(velocity=1e-4, distance=2e-5, steps=30), fd.NormalStep(approach=-3e-6, steps=2),
         fd.Slide(velocity=1e-4, distance=1e-5, steps=10), fd.NormalStep(approach=4e-6, steps=3),
         fd.NormalStep(traction=2e6, steps=4), fd.Traction(traction=(1e5, 0.0), steps=10),
         fd.Slide(velocity=1e-4, distance=2e-5, steps=30)),
        2, 1e6, None, 1e-4,
    ),
}  # fmt: skip


def _run(case: str, compiled: bool) -> Any:
    params, program, n, fn, recording, peak = CASES[case]
    return fd.simulate(params, program, fd.InitialConditions(normal_traction=fn), n_points=n,
                    recording=recording, peak_accuracy=peak,
                    settings=fd.DriverSettings(compiled=compiled))  # fmt: skip


@pytest.mark.parametrize("case", list(CASES))
def test_compiled_loop_matches_the_python_steps(case: str, monkeypatch) -> None:
    steps = [0]
    real = fd.compiled_steps.CompiledSteps.run

    def counted(self, runs, k, total_steps, *args, **kwargs):  # type: ignore[no-untyped-def]
        state, after = real(self, runs, k, total_steps, *args, **kwargs)
        steps[0] += after - k
        return state, after

    monkeypatch.setattr(fd.compiled_steps.CompiledSteps, "run", counted)
    fast = _run(case, True)
    python = _run(case, False)
    assert fast.success == python.success
    assert steps[0] >= 0.5 * python.work["steps"]  # the compiled loop ran most steps
    assert_same(fast, python, "history", RTOL)


@pytest.mark.parametrize("case", list(CASES)[:3])
def test_steps_handed_back_to_python_change_nothing(case: str, monkeypatch) -> None:
    """The loop handed steps back in short runs, every third call as if the law had
    raised on its first step (the driver then runs that step in Python, substepping as
    needed, and goes back to the loop): the history is still the Python steps'."""
    calls = [0]
    real_init = fd.compiled_steps.CompiledSteps.__init__

    def flaky_init(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        real_init(self, *args, **kwargs)
        loop = self.loop

        def flaky(k, stop, *rest):  # type: ignore[no-untyped-def]
            calls[0] += 1
            if calls[0] % 3 == 0:
                raise ZeroDivisionError("as the law's kernel on an underflowed divisor")
            return loop(k, min(stop, k + 5), *rest)

        self.loop = flaky

    monkeypatch.setattr(fd.compiled_steps.CompiledSteps, "__init__", flaky_init)
    fast = _run(case, True)
    assert calls[0] > 10
    assert_same(fast, _run(case, False), "history", RTOL)


def test_the_compiled_path_is_off_where_it_does_not_apply(monkeypatch) -> None:
    """Accuracy control, chosen points and ``compiled=False`` run every step in Python."""
    params, program, n, fn, _, _ = CASES["one point: slide, holds with recovery, reverse"]
    with pytest.raises(ParameterError, match="compiled"):
        fd.DriverSettings(compiled=1)  # type: ignore[arg-type]

    def refuse(*args, **kwargs):  # type: ignore[no-untyped-def]
        raise AssertionError("the compiled loop ran")

    monkeypatch.setattr(fd.compiled_steps.CompiledSteps, "run", refuse)
    for settings, recording in (
        (fd.DriverSettings(accuracy=1e-3), None),
        (fd.DriverSettings(), fd.Recording(points=[0])),
        (fd.DriverSettings(compiled=False), None),
    ):
        history = fd.simulate(params, program, fd.InitialConditions(normal_traction=fn),
                           n_points=n, recording=recording, settings=settings)  # fmt: skip
        assert history.success
