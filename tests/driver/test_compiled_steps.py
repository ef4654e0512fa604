"""The driver's compiled loop over slip-controlled steps (driver/compiled_steps.py) gives
the history of the Python steps, its reference (``DriverSettings(compiled=False)``): every
run below is made both ways and compared array by array to 1e-12 relative (equal codes,
counters, step and row layout, segment figures and refined peaks), and the compiled loop
is checked to have run most steps."""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
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
    Table,
    Traction,
    Turn,
    compiled_steps,
    simulate,
)
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

from .support import set_a

RTOL = 1e-12


def _close(a: Any, b: Any, where: str) -> None:
    """Arrays to RTOL relative (integers and codes exactly), dataclasses, dicts and
    sequences field by field, everything else equal."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        assert a.dtype == b.dtype and a.shape == b.shape, where
        if a.dtype.kind == "f":
            scale = np.maximum(np.abs(a), np.abs(b))
            bad = ~((a == b) | (np.abs(a - b) <= RTOL * scale) | (np.isnan(a) & np.isnan(b)))
            assert not bad.any(), f"{where}: {a[bad][:3]} != {b[bad][:3]}"
        else:
            assert np.array_equal(a, b), where
    elif dataclasses.is_dataclass(a) and not isinstance(a, type):
        assert type(a) is type(b), where
        for f in dataclasses.fields(a):
            _close(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}")
    elif isinstance(a, dict):
        assert a.keys() == b.keys(), where
        for key in a:
            _close(a[key], b[key], f"{where}[{key!r}]")
    elif isinstance(a, list | tuple):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _close(x, y, f"{where}[{i}]")
    else:
        assert a == b or (a != a and b != b), f"{where}: {a!r} != {b!r}"


_CLOSED = {"alpha_n": 1e12, "alpha_t": 1e12, "F_s": 2e6, "F_k": 1.5e6, "M": 0.5, "u": 1e5,
           "kappa": 1e3, "xi": 1e-3}  # fmt: skip
_TABLE = Table(
    time=np.array([0.0, 1.0, 2.0, 2.5]),
    slip=np.array([[0.0, 0.0], [2e-5, 0.0], [1e-5, 1e-5], [1e-5, 3e-5]]),
    steps_per_row=7,
)
_APPROACH_TABLE = Table(
    time=np.array([0.0, 1.0, 2.0]),
    slip=np.array([[0.0, 0.0], [1e-5, 0.0], [3e-5, 0.0]]),
    approach=np.array([0.0, 1e-7, 5e-8]),
    steps_per_row=5,
)

#: name -> (law, programme, points, initial normal traction, recording, peak accuracy)
CASES: dict[str, tuple[Any, ...]] = {
    "one point: slide, holds with recovery, reverse": (
        set_a(alpha_n=5e11, alpha_t=2e11, u=5e4, kappa=1e3, xi=1e-2),
        (Slide(velocity=1e-4, distance=1e-4, max_step=2e-6), Hold(duration=10.0),
         Slide(velocity=1e-4, distance=3e-5, max_step=2e-6), Hold(duration=100.0, steps=4),
         Reverse(steps=40)),
        1, 1e6, None, 1e-4,
    ),
    "seven points, per-point law (a fit's Jacobian run), no peak refinement": (
        set_a(alpha_n=5e11, alpha_t=np.linspace(1e11, 3e11, 7), u=5e4, kappa=1e3,
              xi=np.geomspace(1e-3, 1e-1, 7)),
        (Slide(velocity=1e-4, distance=5e-5, steps=50), Hold(duration=30.0),
         Slide(velocity=1e-4, distance=2e-5, steps=20)),
        7, 1e6, None, None,
    ),
    "closed surface: cycles, turn, approach, every 3rd row": (
        SubloadingParams(surface="modified_cam_clay", **_CLOSED),
        (Cycle(amplitude=3e-6, velocity=1e-5, steps=40, cycles=2),
         Turn(angle_deg=60.0, distance=2e-6, velocity=1e-5, steps=25),
         NormalStep(approach=1e-7, steps=3), Reverse(steps=17)),
        3, 1e6, Recording(every=3), 1e-4,
    ),
    "tear surface: tables of slip and approach, streamed in small chunks": (
        SubloadingParams(surface="tear", **_CLOSED),
        (_TABLE, _APPROACH_TABLE, Hold(duration=5.0, steps=3)),
        2, 1e6, Recording(sink=lambda chunk: None, chunk_rows=7), 1e-4,
    ),
    "opening and re-closing, then prescribed tractions (Python steps between)": (
        set_a(alpha_n=1e12, alpha_t=1e11, u=1e5, kappa=1e3, xi=1e-2),
        (Slide(velocity=1e-4, distance=2e-5, steps=30), NormalStep(approach=-3e-6, steps=2),
         Slide(velocity=1e-4, distance=1e-5, steps=10), NormalStep(approach=4e-6, steps=3),
         NormalStep(traction=2e6, steps=4), Traction(traction=(1e5, 0.0), steps=10),
         Slide(velocity=1e-4, distance=2e-5, steps=30)),
        2, 1e6, None, 1e-4,
    ),
}  # fmt: skip


def _run(case: str, compiled: bool) -> Any:
    params, program, n, fn, recording, peak = CASES[case]
    return simulate(params, program, InitialConditions(normal_traction=fn), n_points=n,
                    recording=recording, peak_accuracy=peak,
                    settings=DriverSettings(compiled=compiled))  # fmt: skip


@pytest.mark.parametrize("case", list(CASES))
def test_compiled_loop_matches_the_python_steps(case: str, monkeypatch) -> None:
    steps = [0]
    real = compiled_steps.CompiledSteps.run

    def counted(self, runs, k, total_steps, *args, **kwargs):  # type: ignore[no-untyped-def]
        state, after = real(self, runs, k, total_steps, *args, **kwargs)
        steps[0] += after - k
        return state, after

    monkeypatch.setattr(compiled_steps.CompiledSteps, "run", counted)
    fast = _run(case, True)
    python = _run(case, False)
    assert fast.success == python.success
    assert steps[0] >= 0.5 * python.work["steps"]  # the compiled loop ran most steps
    _close(fast, python, "history")


@pytest.mark.parametrize("case", list(CASES)[:3])
def test_steps_handed_back_to_python_change_nothing(case: str, monkeypatch) -> None:
    """The loop handed steps back in short runs, every third call as if the law had
    raised on its first step (the driver then runs that step in Python, substepping as
    needed, and goes back to the loop): the history is still the Python steps'."""
    calls = [0]
    real_init = compiled_steps.CompiledSteps.__init__

    def flaky_init(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        real_init(self, *args, **kwargs)
        loop = self.loop

        def flaky(k, stop, *rest):  # type: ignore[no-untyped-def]
            calls[0] += 1
            if calls[0] % 3 == 0:
                raise ZeroDivisionError("as the law's kernel on an underflowed divisor")
            return loop(k, min(stop, k + 5), *rest)

        self.loop = flaky

    monkeypatch.setattr(compiled_steps.CompiledSteps, "__init__", flaky_init)
    fast = _run(case, True)
    assert calls[0] > 10
    _close(fast, _run(case, False), "history")


def test_the_compiled_path_is_off_where_it_does_not_apply(monkeypatch) -> None:
    """Accuracy control, chosen points and ``compiled=False`` run every step in Python."""
    params, program, n, fn, _, _ = CASES["one point: slide, holds with recovery, reverse"]
    with pytest.raises(ParameterError, match="compiled"):
        DriverSettings(compiled=1)  # type: ignore[arg-type]

    def refuse(*args, **kwargs):  # type: ignore[no-untyped-def]
        raise AssertionError("the compiled loop ran")

    monkeypatch.setattr(compiled_steps.CompiledSteps, "run", refuse)
    for settings, recording in (
        (DriverSettings(accuracy=1e-3), None),
        (DriverSettings(), Recording(points=[0])),
        (DriverSettings(compiled=False), None),
    ):
        history = simulate(params, program, InitialConditions(normal_traction=fn),
                           n_points=n, recording=recording, settings=settings)  # fmt: skip
        assert history.success
