"""One compiled pass over N points for the recorder's running figures (numba).

Kept apart from :mod:`frictionlab.driver.recorder` so that edits there do not invalidate
the compile cache (keyed on the files that use numba).

The passes stay serial: on numba's threads they were faster on an idle machine but, on
a machine shared with other work, every extra threaded region waited for a descheduled
thread (measured 2-3x slower steps at N = 1e4).
"""

from __future__ import annotations

import math

from frictionlab._jit import njit

__all__ = ["accumulate", "accumulate_row", "slip_lengths"]


@njit(cache=True, inline="always")
def _length(x, y):
    """hypot(x, y), with the exact shortcut |x| of C's hypot(x, +-0) (Annex F) for the
    planar case (libm's hypot was most of the passes' time)."""
    return abs(x) if y == 0.0 else math.hypot(x, y)


@njit(cache=True)
def slip_lengths(du, out):
    """``out[i] = |du_t|`` = hypot(du[i, 0], du[i, 1]) [m] of the (N, 3) increments ``du``:
    apart from the running figures, so that a plan's repeated increment is measured once."""
    for i in range(du.shape[0]):
        out[i] = math.hypot(du[i, 0], du[i, 1])
    return out


@njit(cache=True, inline="always")
def _extremes(step, t, p, r, fn, peak, peak_step, peak_time, peak_path,
              seg_peak, seg_peak_time, seg_max_fn):  # fmt: skip
    """One point's figures after a step with friction ratio ``r`` at time ``t`` and path
    ``p``: a new overall or segment peak (with its step, time and path) and the segment's
    largest normal traction ``fn``. Scalars in and out: arrays passed to a helper inside
    the loop are reference-counted on every point, which cost more than the loop."""
    if r > peak:
        peak = r
        peak_step = step
        peak_time = t
        peak_path = p
    if r > seg_peak:
        seg_peak = r
        seg_peak_time = t
    if fn > seg_max_fn:
        seg_max_fn = fn
    return peak, peak_step, peak_time, peak_path, seg_peak, seg_peak_time, seg_max_fn


@njit(cache=True)
def accumulate(step, dt, du, dpath, work, traction, time, slip, approach, plastic_work, path,
               ratio, peak, peak_step, peak_time, peak_path,
               seg_peak, seg_peak_time, seg_max_fn):  # fmt: skip
    """Update the running figures of N points by one step, in place.

    ``dt`` (1 or N,) [s]; ``du`` (N, 3) [m]; ``dpath`` (N,) its |du_t| [m]
    (:func:`slip_lengths`); ``work`` (N,) [J/m^2]; ``traction`` (N, 3) [Pa] after the step.
    Adds to ``time``, ``slip`` (N, 2), ``approach``, ``plastic_work`` and ``path``
    (``dpath``); writes ``ratio`` = |f_t|/f_n (0 where open); where it exceeds ``peak``
    (or ``seg_peak``) records it with the step, time and path (time); raises
    ``seg_max_fn`` to f_n. Returns the number of points whose segment peak rose.
    """
    return accumulate_row(step, dt, du, dpath, work, traction, None, None, None, None, None,
                          time, slip, approach, plastic_work, path,
                          ratio, peak, peak_step, peak_time, peak_path,
                          seg_peak, seg_peak_time, seg_max_fn,
                          None, None, None, None, None, None, None, None, None,
                          None)  # fmt: skip


@njit(cache=True)
def accumulate_row(step, dt, du, dpath, work, traction, F, R, plastic_slip, status, iterations,
                   time, slip, approach, plastic_work, path,
                   ratio, peak, peak_step, peak_time, peak_path,
                   seg_peak, seg_peak_time, seg_max_fn,
                   row_time, row_slip, row_approach, row_work, row_traction,
                   row_F, row_R, row_plastic_slip, row_status, row_iterations):  # fmt: skip
    """:func:`accumulate` and, in the same pass, the recorded row of every point.

    ``F``, ``R``, ``plastic_slip``, ``status``, ``iterations`` (N,) are the step's new
    values; the ``row_*`` arrays (one row of the history, shapes as the running figures
    and ``traction``) receive the figures after the step and the new state. With
    ``row_time`` None (:func:`accumulate`) no row is written: numba compiles that
    signature without the row branch (a branch on an argument typed None is pruned).
    """
    n = traction.shape[0]
    shared = dt.shape[0] == 1
    rose = 0
    for i in range(n):
        t = time[i] + (dt[0] if shared else dt[i])
        time[i] = t
        s0 = slip[i, 0] + du[i, 0]
        s1 = slip[i, 1] + du[i, 1]
        slip[i, 0] = s0
        slip[i, 1] = s1
        a = approach[i] + du[i, 2]
        approach[i] = a
        w = plastic_work[i] + work[i]
        plastic_work[i] = w
        p = path[i] + dpath[i]
        path[i] = p
        f0 = traction[i, 0]
        f1 = traction[i, 1]
        fn = traction[i, 2]
        if row_time is not None:
            row_time[i] = t
            row_slip[i, 0] = s0
            row_slip[i, 1] = s1
            row_approach[i] = a
            row_work[i] = w
            row_traction[i, 0] = f0
            row_traction[i, 1] = f1
            row_traction[i, 2] = fn
            row_F[i] = F[i]
            row_R[i] = R[i]
            row_plastic_slip[i] = plastic_slip[i]
            row_status[i] = status[i]
            row_iterations[i] = iterations[i]
        r = _length(f0, f1) / fn if fn > 0.0 else 0.0
        ratio[i] = r
        # the arrays stay in the loop (a helper taking them would be reference-counted
        # per point); the shared part, _extremes, takes scalars
        if r > seg_peak[i]:
            rose += 1
        if r > peak[i] or r > seg_peak[i] or fn > seg_max_fn[i]:  # stores only on a change
            (peak[i], peak_step[i], peak_time[i], peak_path[i], seg_peak[i], seg_peak_time[i],
             seg_max_fn[i]) = _extremes(step, t, p, r, fn, peak[i], peak_step[i], peak_time[i],
                                        peak_path[i], seg_peak[i], seg_peak_time[i],
                                        seg_max_fn[i])  # fmt: skip
    return rose
