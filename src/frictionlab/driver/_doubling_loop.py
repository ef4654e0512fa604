"""Step doubling of one slip-controlled step in one compiled call (numba).

The peak refinement (:mod:`~frictionlab.driver.extrema`) integrates fractions of a step
to a tenth of ``peak_accuracy``: hundreds of substeps of a few points, where the Python of
:func:`~frictionlab.driver.stepping.substep` costs ~100 us per law call against ~1 us in
the law. :func:`double_steps` makes the same law calls in the same order (depth first,
the failed or inaccurate step halved, at most ``max_halvings`` times) with the same
step-doubling error (:func:`~frictionlab.driver.stepping.step_error`, whose slip term is
zero when the slip is prescribed), so its state is the Python one's.

Kept apart from the Python glue so that edits there do not invalidate the compile cache.
"""

from __future__ import annotations

import numpy as np

from frictionlab._jit import njit
from frictionlab.driver._step_loop import _solve

__all__ = ["double_steps"]

#: Slots of ``counters``: law calls, accepted substeps, steps left inaccurate at the
#: deepest halving.
D_SOLVES, D_SUBSTEPS, D_UNMET = range(3)


@njit(cache=True)
def _scaled(du, dt, depth, du_out, dt_out):  # fmt: skip
    """``du``, ``dt`` times 2**-depth (exact: a power of two)."""
    scale = 0.5**depth
    for i in range(dt.shape[0]):
        dt_out[i] = dt[i] * scale
        for d in range(3):
            du_out[i, d] = du[i, d] * scale


@njit(cache=True)
def _copy_state(src, dst):  # fmt: skip
    """The state arrays (traction, F, R, gap, plastic slip) of ``src`` into ``dst``."""
    dst[0][...] = src[0]
    dst[1][...] = src[1]
    dst[2][...] = src[2]
    dst[3][...] = src[3]
    dst[4][...] = src[4]


@njit(cache=True)
def _error(a, b, static):  # fmt: skip
    """Step-doubling error of a full step ``a`` and two halves ``b`` (same slip): the
    largest over points of |f_t,a - f_t,b|/f_n, |R_a - R_b| and |F_a - F_b|/F_s; infinite
    where a value is not a number."""
    worst = 0.0
    ta, tb = a[0], b[0]
    for i in range(ta.shape[0]):
        fn = max(ta[i, 2], tb[i, 2])
        ratio = 0.0
        if fn > 0.0:
            ratio = np.hypot(ta[i, 0] - tb[i, 0], ta[i, 1] - tb[i, 1]) / fn
        v = max(ratio, abs(a[2][i] - b[2][i]), abs(a[1][i] - b[1][i]) / static[i])
        if v != v:
            return np.inf
        worst = max(worst, v)
    return worst


@njit(cache=True)
def double_steps(state, du, dt, accuracy, max_halvings, static, law, full, half1, half2,
                 du_d, dt_d, counters):  # fmt: skip
    """Advance ``state`` (traction, F, R, gap, plastic slip; written in place) by the slip
    ``du`` (N, 3) [m] over ``dt`` (N,) [s] with step doubling to ``accuracy``; False when a
    point failed at the deepest halving (``state`` then holds a partial advance).

    ``static``: (N,) F_s (mu_s for the cone) [Pa]; ``law``: the kernel's settings
    (parameter table to the open-recovery flag); ``full``, ``half1``, ``half2``: three
    output sets (``kernels.empty_outputs`` in the driver's order, with plastic slip);
    ``du_d``, ``dt_d``: scratch of ``du``'s and ``dt``'s shapes; ``counters``
    (:data:`D_SOLVES` ...) summed.
    """
    pending = np.empty(max_halvings + 2, dtype=np.int64)  # depths of right halves to do
    top = 0
    depth = 0
    have_full = False  # ``full`` holds this interval's full step (a left half's trial)
    full_ok = False
    while True:
        if not have_full:
            _scaled(du, dt, depth, du_d, dt_d)
            full_ok = _solve(state, full, du_d, dt_d, law)
            counters[D_SOLVES] += 1
        have_full = False
        accepted = False
        if not full_ok:
            if depth >= max_halvings:
                return False
            pending[top] = depth + 1  # the right half, after the left one
            top += 1
            depth += 1
            continue
        if depth >= max_halvings:
            _copy_state(full, state)
            counters[D_SUBSTEPS] += 1
            counters[D_UNMET] += 1
            accepted = True
        else:
            _scaled(du, dt, depth + 1, du_d, dt_d)
            ok1 = _solve(state, half1, du_d, dt_d, law)
            counters[D_SOLVES] += 1
            ok2 = False
            if ok1:
                ok2 = _solve(half1, half2, du_d, dt_d, law)
                counters[D_SOLVES] += 1
            if ok2 and _error(full, half2, static) <= accuracy:
                _copy_state(half2, state)
                counters[D_SUBSTEPS] += 2
                accepted = True
            elif ok1 and depth + 1 >= max_halvings:  # the left half stays as tried,
                _copy_state(half1, state)  # the right half is the second trial
                counters[D_SUBSTEPS] += 1
                counters[D_UNMET] += 1
                _copy_state(half2, full)
                full_ok = ok2
                have_full = True
                depth += 1
            else:  # refine: the left half, its trial kept as its full step
                _copy_state(half1, full)
                full_ok = ok1
                have_full = True
                pending[top] = depth + 1
                top += 1
                depth += 1
        if accepted:
            if top == 0:
                return True
            top -= 1
            depth = pending[top]
