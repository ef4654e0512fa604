"""The driver's cheaper steps give the same numbers as the plain paths.

References: numpy written here (running figures, hypot), the public ``update`` with fresh
outputs, the list form of the no-snap-back check; compared bit for bit.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from frictionlab.driver._running import accumulate, accumulate_row, slip_lengths
from frictionlab.driver.program import Control
from frictionlab.driver.recorder import Recorder
from frictionlab.driver.stepping import OutputPool, advance
from frictionlab.subloading import initial_state, kernels, snap_back_violations, update
from frictionlab.subloading.return_map import _update_into
from frictionlab.subloading.state import _snap_back_failures

from .support import set_a


def _inputs(n: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    traction = rng.normal(size=(n, 3))
    traction[::3, 1] = 0.0  # planar points (the exact |f_1| shortcut) ...
    traction[1::6, 1] = -0.0  # ... with either zero
    traction[::5, 2] = -np.abs(traction[::5, 2])  # open points: ratio 0
    du = rng.normal(size=(n, 3)) * 1e-3
    du[::4, 1] = 0.0
    return {"traction": traction, "du": du, "work": rng.random(n), "dt": rng.random(n)}


def _reference(step, dt, du, work, traction, run):  # type: ignore[no-untyped-def]
    """The running figures by numpy, point by point formulas written out."""
    time = run["time"] + dt
    path = run["path"] + np.hypot(du[:, 0], du[:, 1])
    fn = traction[:, 2]
    ratio = np.zeros_like(fn)
    closed = fn > 0.0
    ratio[closed] = np.hypot(traction[closed, 0], traction[closed, 1]) / fn[closed]
    new_peak = ratio > run["peak"]
    return {
        "time": time,
        "slip": run["slip"] + du[:, :2],
        "approach": run["approach"] + du[:, 2],
        "work": run["work"] + work,
        "path": path,
        "ratio": ratio,
        "peak": np.where(new_peak, ratio, run["peak"]),
        "peak_step": np.where(new_peak, step, run["peak_step"]),
        "peak_time": np.where(new_peak, time, run["peak_time"]),
        "peak_path": np.where(new_peak, path, run["peak_path"]),
        "seg_max_fn": np.maximum(run["seg_max_fn"], fn),
    }


@pytest.mark.parametrize("shared_dt", [True, False])
def test_running_figures_equal_a_numpy_reference(shared_dt: bool) -> None:
    n = 600
    x = _inputs(n, 3)
    dt = x["dt"][:1] if shared_dt else x["dt"]
    rng = np.random.default_rng(4)
    run = {
        "time": rng.random(n), "slip": rng.random((n, 2)), "approach": rng.random(n),
        "work": rng.random(n), "path": rng.random(n), "peak": rng.random(n) * 0.5,
        "peak_step": np.arange(n, dtype=np.int64), "peak_time": rng.random(n),
        "peak_path": rng.random(n), "seg_max_fn": rng.normal(size=n),
    }  # fmt: skip
    want = _reference(7, dt, x["du"], x["work"], x["traction"], run)
    dpath = slip_lengths(x["du"], np.empty(n))
    np.testing.assert_array_equal(dpath, np.hypot(x["du"][:, 0], x["du"][:, 1]))
    for with_row in (False, True):
        got = {k: v.copy() for k, v in run.items()}
        ratio = np.empty(n)
        seg_peak, seg_time = np.full(n, -np.inf), np.zeros(n)
        common = (got["time"], got["slip"], got["approach"], got["work"], got["path"], ratio,
                  got["peak"], got["peak_step"], got["peak_time"], got["peak_path"],
                  seg_peak, seg_time, got["seg_max_fn"])  # fmt: skip
        if with_row:
            state = [rng.random(n), rng.random(n), rng.random(n)]
            status, iters = np.ones(n, np.int8), np.arange(n, dtype=np.int64)
            row = [np.empty(n), np.empty((n, 2)), np.empty(n), np.empty(n), np.empty((n, 3)),
                   np.empty(n), np.empty(n), np.empty(n), np.empty(n, np.int8),
                   np.empty(n, np.int64)]  # fmt: skip
            accumulate_row(7, dt, x["du"], dpath, x["work"], x["traction"], *state, status,
                           iters, *common, *row)  # fmt: skip
            for a, b in zip(row, (got["time"], got["slip"], got["approach"], got["work"],
                                  x["traction"], *state, status, iters), strict=True):  # fmt: skip
                np.testing.assert_array_equal(a, b)
        else:
            accumulate(7, dt, x["du"], dpath, x["work"], x["traction"], *common)
        got["ratio"] = ratio
        for key, value in want.items():
            np.testing.assert_array_equal(got[key], value, key)
        np.testing.assert_array_equal(seg_peak, want["ratio"])  # first step of a segment
        np.testing.assert_array_equal(seg_time, want["time"])


def test_hypot_of_a_zero_component_is_the_absolute_value() -> None:
    """The planar shortcut relies on C's hypot(x, +-0) = |x| (exactly, Annex F)."""
    values = [0.0, -0.0, 5e-324, -2.5e-310, 1e-300, -3.7, 1e300, -1.7e308, math.inf]
    for x, zero in itertools.product(values, (0.0, -0.0)):
        assert math.hypot(x, zero) == abs(x)
        assert math.copysign(1.0, math.hypot(x, zero)) == 1.0


def test_the_driver_law_call_equals_the_public_update() -> None:
    params = set_a()
    n = 7
    state = initial_state(params, 1.0, (0.2, -0.1), n_points=n)
    du = np.random.default_rng(5).normal(size=(n, 3)) * 2e-4
    dt = np.full(n, 1e-3)
    want = update(params, state, du, dt, raise_on_failure=False)
    got = _update_into(params, state, du, dt, kernels.empty_outputs(n, tangent=False))
    for name in ("traction", "F", "R", "plastic_slip", "gap"):
        np.testing.assert_array_equal(getattr(got.state, name), getattr(want.state, name))
    for name in ("plastic_multiplier", "dissipation", "status", "iterations"):
        np.testing.assert_array_equal(getattr(got, name), getattr(want, name))


def test_a_plans_increment_is_built_once_read_only_and_never_written() -> None:
    n = 5
    du_t = np.tile([1e-3, -2e-3], (n, 1))
    control = Control(np.full(n, 0.01), du_t, np.full(n, 1e-4))
    kernel_du, du = control._slip_increment(n)
    assert control._slip_increment(n)[1] is du  # the same arrays on every step
    assert not du.flags.writeable and np.shares_memory(du, kernel_du)
    np.testing.assert_array_equal(du, np.column_stack([du_t, np.full(n, 1e-4)]))
    params = set_a()
    state = initial_state(params, 1.0, n_points=n)
    pool = OutputPool(n)
    for _ in range(3):
        outcome, _ = advance(params, state, control, pool=pool)
        assert outcome.du is du and not outcome.du.flags.writeable
        state = outcome.state
    np.testing.assert_array_equal(kernel_du, np.column_stack([du_t, np.full(n, 1e-4)]))


def test_recorder_rows_are_separate_aligned_fields_of_one_block() -> None:
    rec = Recorder(initial_state(set_a(), 1.0, n_points=11))
    fields = list(rec.buf.items())
    for (a, x), (b, y) in itertools.combinations(fields, 2):
        assert not np.shares_memory(x, y), (a, b)
    for name, x in fields:
        assert x.flags.c_contiguous and x.flags.writeable, name
        assert x.ctypes.data % 64 == (fields[0][1].ctypes.data % 64), name


def test_the_failing_points_of_the_snap_back_check_are_the_list_entries() -> None:
    n = 9
    alpha_t = np.linspace(0.01, 3.0, n)  # the smallest stiffnesses snap back at f_n = 2
    params = set_a(alpha_t=alpha_t, alpha_n=np.full(n, 1e3))
    fn = np.full(n, 2.0)
    listed = snap_back_violations(params, fn)
    failures = _snap_back_failures(params, fn)
    assert 0 < len(failures) < n
    assert list(failures) == [i for i, r in enumerate(listed) if r]
    for i, reason in failures.items():
        assert listed[i] == reason
    # the cone's closed form: alpha_t > f_n kappa (mu_s/mu_k - 1)^m (m = 1, unit axes)
    slope = 2.0 * 1.0 * (0.5 / 0.3 - 1.0)
    assert list(failures) == [i for i in range(n) if not alpha_t[i] > slope]
    with pytest.raises(ValueError):
        snap_back_violations(params, np.full(n - 1, 2.0))
