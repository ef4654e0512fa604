"""Slip-controlled segments through the driver's compiled loop (one call per many steps).

:func:`~frictionlab.driver.simulate.simulate` hands a segment that prescribes no
traction (:meth:`~frictionlab.driver.program.SegmentPlan.slip_runs`: slide, hold,
reverse, turn, cycle, an approach, a table of slip) to :meth:`CompiledSteps.run` when the
run qualifies (:func:`compiled_steps`): no ``accuracy`` control, the law's own update,
fewer than ``PARALLEL_MIN_POINTS`` points, every point recorded and every recorded row
kept in memory (a sink may stream them). The compiled loop
(:func:`~frictionlab.driver._step_loop.run_slip_steps`) makes the very calls of the
Python steps (the law's kernel, the recorder's passes), so the history, its figures and
peaks are the same numbers; where a point fails it returns, and the driver substeps
that step in Python (:func:`~frictionlab.driver.stepping.advance`) and carries on.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from frictionlab.driver._running import slip_lengths
from frictionlab.driver.extrema import PeakTracker
from frictionlab.driver.program import SlipRuns
from frictionlab.driver.recorder import Recorder
from frictionlab.driver.stepping import SlipSteps
from frictionlab.subloading import ContactState
from frictionlab.subloading.return_map import OUTPUT_KEYS, PARALLEL_MIN_POINTS

__all__ = ["PROGRESS_STEPS", "CompiledSteps", "compiled_steps"]

#: Steps between progress reports when a progress callback is given.
PROGRESS_STEPS = 1000
#: The output set's arrays in the loop's order (the state's first).
_SET_KEYS = ("traction", "F", "R", "gap", "plastic_slip", *OUTPUT_KEYS[4:])
_STATE_KEYS = ("traction", "F", "R", "gap", "plastic_slip")
_ROW_KEYS = ("time", "slip", "approach", "plastic_work", "traction", "F", "R", "plastic_slip",
             "status", "iterations", "step", "segment", "substeps", "solves", "_index",
             "_end")  # fmt: skip


def compiled_steps(direct: SlipSteps | None, rec: Recorder, n_points: int) -> CompiledSteps | None:
    """The compiled loop for a run that qualifies (see the module docstring), else None."""
    if direct is None or n_points >= PARALLEL_MIN_POINTS:
        return None
    if not rec.store_all or rec.selected is not None:
        return None
    return CompiledSteps(direct, n_points)


def _tracker_arrays(tracker: PeakTracker | None, n: int) -> tuple[np.ndarray, ...]:
    """The tracker's arrays in the loop's order (empty stand-ins without a tracker)."""
    if tracker is None:
        z1, z2, i1 = np.zeros(0), np.zeros((0, 3)), np.zeros(0, dtype=np.int64)
        return (z1, i1, z2, z1, z1, z1, z1, z2, z1, z1, z1, z1, z1, np.zeros((0, 2)), z1, z1,
                z1, np.zeros((0, 2)), z1)  # fmt: skip
    b, a, c = tracker.before, tracker.after, tracker.ctl
    return (tracker.best, tracker.k, *(b[k] for k in _STATE_KEYS[:3]), b["plastic_slip"],
            b["gap"], *(a[k] for k in _STATE_KEYS[:3]), a["plastic_slip"], a["gap"], c["dt"],
            c["du_t"], c["du_n"], c["fn"], tracker.time, tracker.slip, tracker.path)  # fmt: skip


class CompiledSteps:
    """Runs the steps of slip-controlled segments in the compiled loop."""

    def __init__(self, direct: SlipSteps, n_points: int) -> None:
        from frictionlab.driver._step_loop import run_slip_steps  # numba: on first use

        self.loop: Callable[..., bool] = run_slip_steps
        self.direct = direct
        self.n = n_points
        self.sets = tuple(tuple(s[k] for k in _SET_KEYS) for s in direct.pool.sets)
        self.law = direct.settings[n_points == 1][:8]  # the shared-dt flag as the Python step's

    def tables(self, runs: SlipRuns) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(C, N, 3) increments, (C, N) time increments and (C, N) |du_t| of the controls."""
        n, count = self.n, len(runs.controls)
        du, dt, dpath = np.empty((count, n, 3)), np.empty((count, n)), np.empty((count, n))
        for c, control in enumerate(runs.controls):
            du[c] = control._slip_increment(n)[0]
            dt[c] = control.dt
        slip_lengths(du.reshape(count * n, 3), dpath.reshape(count * n))
        return du, dt, dpath

    def _holding(self, state: ContactState) -> int:
        """The set holding ``state``; a state in neither is copied into set 1 (the Python
        step's first output then goes to set 0, as :meth:`OutputPool.free_for` gives)."""
        sets = self.direct.pool.sets
        for j in (0, 1):
            if state.traction is sets[j]["traction"]:
                return j
        for key in _STATE_KEYS:
            sets[1][key][...] = getattr(state, key)
        return 1

    def run(
        self,
        runs: SlipRuns,
        k: int,
        steps: int,
        state: ContactState,
        rec: Recorder,
        tracker: PeakTracker | None,
        work: dict[str, int],
        progress: Any = None,
        total: int = 0,
    ) -> tuple[ContactState, int]:
        """Steps ``k`` .. of the segment (``steps`` in all) from ``state``; the state after
        the last step done and the next step: below ``steps`` when a point fails in it (the
        caller substeps it)."""
        from frictionlab.driver._step_loop import (
            C_FILL,
            C_ITERATIONS,
            C_LAST_RECORDED,
            C_RECORDED,
            C_SET,
            C_STEP,
            C_STEPS,
        )

        du, dt, dpath = self.tables(runs)
        s, seg = rec.stats, rec._seg
        assert seg is not None
        figures = (s.time, s.slip, s.approach, s.plastic_work, s.path_length,
                   s.peak_friction_ratio, s.peak_step, s.peak_time, s.peak_path_length,
                   seg.peak_friction_ratio, seg.peak_time, seg.max_normal_traction)  # fmt: skip
        tracked = _tracker_arrays(tracker, self.n)
        j = self._holding(state)
        counters = np.array([k, j, rec.fill, rec.recorded, s.steps, 0, 0], dtype=np.int64)
        before = s.steps
        ok = True
        while ok and k < steps:
            stop = steps if progress is None else min(steps, k + PROGRESS_STEPS)
            capacity = rec.buf["step"].shape[0]
            stop_fill = capacity if rec.sink is None else min(capacity, rec.sent + rec.chunk)
            rows = tuple(rec.buf[key] for key in _ROW_KEYS)
            ratio = np.empty(self.n)
            counters[C_ITERATIONS] = 0
            try:
                ok = self.loop(k, stop, steps - 1, rec.every, rec._seg_index, runs.bounds,
                               runs.which, du, dt, dpath, self.law, *self.sets, figures, ratio,
                               rows, stop_fill, tracker is not None, tracked,
                               counters)  # fmt: skip
            except ArithmeticError:  # as SlipSteps.step: the step is substepped in Python
                ok = False
            done = int(counters[C_STEP]) - k
            k += done
            for key in ("steps", "substeps", "solves"):
                work[key] += done
            work["iterations"] += int(counters[C_ITERATIONS])
            if done:
                s.friction_ratio = ratio
            rec.fill, rec.recorded = int(counters[C_FILL]), int(counters[C_RECORDED])
            if rec.sink is not None and rec.fill - rec.sent >= rec.chunk:
                rec._send()
            if rec.fill == capacity:
                rec._grow(2 * rec.fill)
            if progress is not None and done:
                progress(work["steps"], total)
        if int(counters[C_STEPS]) == before:  # not one step done
            return state, k
        j = int(counters[C_SET])
        state = self.direct.view(j, state.frame)
        s.steps = int(counters[C_STEPS])
        seg.last_step = s.steps
        rec._seg_k = k
        rec.state = state
        rec._last_recorded = bool(counters[C_LAST_RECORDED])
        if not rec._last_recorded:
            out = self.direct.pool.sets[j]
            rec._last = (out["status"], out["iterations"].astype(np.int64), 0, 1, 1)
        return state, k
