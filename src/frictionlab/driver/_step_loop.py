"""The driver's steps of a slip-controlled segment in one compiled loop (numba).

For a few points and many steps (a calibration's runs: 1 to ~10 points, thousands of
steps) the Python around each step of :func:`~frictionlab.driver.simulate.simulate` cost
~30 us against ~1 us in the law. :func:`run_slip_steps` does, step after step, what the
driver's single-solve path does (:class:`~frictionlab.driver.stepping.SlipSteps` and
:meth:`~frictionlab.driver.recorder.Recorder.add`, with the peak tracker's bookkeeping):
the law's own :func:`~frictionlab.subloading.kernels.step_points` into the two output
sets used in turn, the plastic slip, the recorder's running figures and rows
(:mod:`~frictionlab.driver._running`), so its numbers are the Python loop's. It stops
at the first step a point fails (the caller substeps that step in Python), when the row
store is full or a chunk is due to the sink, or at ``stop``.

Kept apart from the Python glue (:mod:`~frictionlab.driver.compiled_steps`) so that edits
there do not invalidate the compile cache.
"""

from __future__ import annotations

import numpy as np

from frictionlab._jit import njit
from frictionlab.driver._running import accumulate, accumulate_row
from frictionlab.subloading.kernels import FAILED, step_points

__all__ = ["run_slip_steps"]

#: Slots of ``counters``: next step, set holding the state, rows filled, rows recorded,
#: steps done in the run, Newton iterations summed, whether the last step was recorded.
C_STEP, C_SET, C_FILL, C_RECORDED, C_STEPS, C_ITERATIONS, C_LAST_RECORDED = range(7)


@njit(cache=True, inline="always")
def _solve(src, dst, du, dt, law):  # fmt: skip
    """One call of the law from the state in ``src`` into ``dst``; True when no point
    failed (then ``dst``'s plastic slip is ``src``'s plus the increment)."""
    P, shared_dt, surface, tear_k, ulaw, integ, rform, open_frozen = law
    tr, F, R, gap, ps = src[0], src[1], src[2], src[3], src[4]
    o_tr, o_F, o_R, o_gap, o_ps, o_dlam, o_vp, o_diss, o_tan, o_status, o_iter = dst
    step_points(tr, F, R, gap, du, dt, P, shared_dt, surface, tear_k, ulaw, integ, rform,
                open_frozen, False, o_tr, o_F, o_R, o_gap, o_dlam, o_vp, o_diss, o_tan,
                o_status, o_iter)  # fmt: skip
    for i in range(o_status.shape[0]):
        if o_status[i] >= FAILED:
            return False
    for i in range(o_ps.shape[0]):
        o_ps[i] = ps[i] + o_dlam[i]
    return True


@njit(cache=True)
def _track(k, src, dst, c, du_tab, dt_tab, ratio, figures, tracker):  # fmt: skip
    """:meth:`~frictionlab.driver.extrema.PeakTracker.observe` of step ``k`` (control ``c``)
    from the state in ``src`` to the one in ``dst``."""
    best, at, b_tr, b_F, b_R, b_ps, b_gap, a_tr, a_F, a_R, a_ps, a_gap = tracker[:12]
    c_dt, c_du_t, c_du_n, c_fn, t_time, t_slip, t_path = tracker[12:]
    time, slip, path = figures[0], figures[1], figures[4]
    for i in range(best.shape[0]):
        r = ratio[i]
        if not r > best[i]:
            continue
        best[i] = r
        at[i] = k
        for d in range(3):
            b_tr[i, d] = src[0][i, d]
            a_tr[i, d] = dst[0][i, d]
        b_F[i], b_R[i], b_gap[i], b_ps[i] = src[1][i], src[2][i], src[3][i], src[4][i]
        a_F[i], a_R[i], a_gap[i], a_ps[i] = dst[1][i], dst[2][i], dst[3][i], dst[4][i]
        c_dt[i] = dt_tab[c, i]
        c_du_t[i, 0] = du_tab[c, i, 0]
        c_du_t[i, 1] = du_tab[c, i, 1]
        c_du_n[i] = du_tab[c, i, 2]
        c_fn[i] = np.nan  # no normal traction prescribed
        t_time[i] = time[i]
        t_slip[i, 0] = slip[i, 0]
        t_slip[i, 1] = slip[i, 1]
        t_path[i] = path[i]


@njit(cache=True, inline="always")
def _advance(k, src, dst, c, last, every, segment, du_tab, dt_tab, dpath_tab, law, figures,
             ratio, rows, track, tracker, counters):  # fmt: skip
    """Step ``k`` from ``src`` into ``dst``, recorded as the recorder does; False when a
    point failed (nothing recorded)."""
    du, dt, dpath = du_tab[c], dt_tab[c], dpath_tab[c]
    if not _solve(src, dst, du, dt, law):
        return False
    o_tr, o_F, o_R, o_ps, o_diss = dst[0], dst[1], dst[2], dst[4], dst[7]
    o_status, o_iter = dst[9], dst[10]
    time, slip, approach, work, path, peak, peak_step, peak_time, peak_path = figures[:9]
    seg_peak, seg_peak_time, seg_max_fn = figures[9:]
    steps = counters[C_STEPS] + 1
    counters[C_STEPS] = steps
    total = 0
    for i in range(o_iter.shape[0]):
        total += o_iter[i]
    counters[C_ITERATIONS] += total
    if k == 0 or k == last or (k + 1) % every == 0:
        (r_time, r_slip, r_approach, r_work, r_traction, r_F, r_R, r_ps, r_status, r_iter,
         r_step, r_segment, r_substeps, r_solves, r_index, r_end) = rows  # fmt: skip
        j = counters[C_FILL]
        rose = accumulate_row(
            steps, dt, du, dpath, o_diss, o_tr, o_F, o_R, o_ps, o_status, o_iter,
            time, slip, approach, work, path, ratio, peak, peak_step, peak_time, peak_path,
            seg_peak, seg_peak_time, seg_max_fn, r_time[j], r_slip[j], r_approach[j],
            r_work[j], r_traction[j], r_F[j], r_R[j], r_ps[j], r_status[j], r_iter[j],
        )  # fmt: skip
        r_step[j] = steps
        r_segment[j] = segment
        r_substeps[j] = 1
        r_solves[j] = 1
        r_index[j] = counters[C_RECORDED]
        r_end[j] = 1 if (k == 0 or k == last) else 0
        counters[C_RECORDED] += 1
        counters[C_FILL] = j + 1
        counters[C_LAST_RECORDED] = 1
    else:
        rose = accumulate(
            steps, dt, du, dpath, o_diss, o_tr, time, slip, approach, work, path, ratio,
            peak, peak_step, peak_time, peak_path, seg_peak, seg_peak_time, seg_max_fn,
        )  # fmt: skip
        counters[C_LAST_RECORDED] = 0
    if track and rose:
        _track(k, src, dst, c, du_tab, dt_tab, ratio, figures, tracker)
    return True


@njit(cache=True)
def run_slip_steps(k, stop, last, every, segment, bounds, which, du_tab, dt_tab, dpath_tab,
                   law, set0, set1, figures, ratio, rows, stop_fill, track, tracker,
                   counters):  # fmt: skip
    """Steps ``k`` .. ``stop - 1`` of a segment whose last step is ``last``; False when a
    point failed at step ``counters[C_STEP]`` (nothing of it kept), True otherwise (it
    also stops early, at ``counters[C_STEP]``, once ``stop_fill`` rows are filled).

    Step ``s`` applies control ``which[r]`` for ``bounds[r] <= s < bounds[r + 1]``: the
    (N, 3) increment ``du_tab[c]``, time increment ``dt_tab[c]`` (N,) and ``dpath_tab[c]``
    = |du_t|. ``law``: the kernel's settings (parameter table to the open-recovery flag).
    ``set0``, ``set1``: the two output sets (traction, F, R, gap, plastic_slip, dlam, vp,
    diss, tangent, status, iterations); the state is in ``set0`` when ``counters[C_SET]``
    is 0. ``figures``: the recorder's running figures (time, slip, approach, plastic
    work, path, peak, peak step, peak time, peak path, the segment's peak, its time and
    largest f_n), ``ratio`` its friction ratio after the step; ``rows``: the store's
    fields (time .. iterations, step, segment, substeps, solves, index, end), filled up to
    ``stop_fill``. ``tracker``: the peak tracker's arrays (best, step, the states before
    and after, the control, time, slip and path), updated when ``track``. ``counters``
    (:data:`C_STEP` ...) are read at the start and kept current after every step, so
    they are right even when the law raises.
    """
    r = 0
    while bounds[r + 1] <= k:
        r += 1
    while k < stop:
        while bounds[r + 1] <= k:
            r += 1
        c = which[r]
        if counters[C_SET] == 0:
            ok = _advance(k, set0, set1, c, last, every, segment, du_tab, dt_tab, dpath_tab,
                          law, figures, ratio, rows, track, tracker, counters)  # fmt: skip
        else:
            ok = _advance(k, set1, set0, c, last, every, segment, du_tab, dt_tab, dpath_tab,
                          law, figures, ratio, rows, track, tracker, counters)  # fmt: skip
        if not ok:
            return False
        counters[C_SET] = 1 - counters[C_SET]
        k += 1
        counters[C_STEP] = k
        if counters[C_FILL] >= stop_fill:
            return True
    return True
