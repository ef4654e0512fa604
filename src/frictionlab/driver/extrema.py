"""Friction-ratio peaks between recorded steps.

A step grid samples the friction ratio |f_t|/f_n; its largest sample falls short of the
true peak by up to the change over a step (7 % for the starter scenario at 100 steps).
:class:`PeakTracker` keeps, per point, the states on both sides of the largest sample of
each segment (step ``k``: the states after steps ``k - 1`` and ``k``, and the controls of
steps ``k`` and ``k + 1``). Where the sample is a turn (larger than the segment's start and
its last step), :meth:`PeakTracker.refine` maximises the ratio over the bracket
``[k - 1, k + 1]``:

1. one pass from the kept state at ``k - 1`` over the bracket in ``_NODES`` equal
   sub-intervals (slip and time scaled, traction targets interpolated linearly as in
   :meth:`~frictionlab.driver.program.Control.halves`), each with the driver's
   step-doubling control at a tenth of the requested accuracy, keeping the state at every
   node;
2. Chandrupatla's bracketing search (:func:`scipy.optimize.elementwise.find_minimum`,
   superlinear) between the neighbours of the largest node, each trial one advance from
   the node before it (at most one sub-interval), until the bracket's values agree to that
   tenth.

The cost is about one accurate integration over the two steps (a search re-integrating
from ``k - 1`` for every trial would cost one per trial). The peak is then within
``peak_accuracy`` (relative) of the converged one whenever the state at step ``k - 1`` is
(exact from a segment's start; otherwise to the driver's own accuracy). Steps that
prescribe the tangential traction are not refined: the ratio is then linear between
steps, so its peak is a sample.

Pure computation: no file I/O.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from frictionlab.driver.program import Control
from frictionlab.subloading import ContactState, SubloadingParams

if TYPE_CHECKING:
    from frictionlab.driver.program import SegmentPlan

__all__ = ["DEFAULT_PEAK_ACCURACY", "PeakTracker", "RefinedPeaks", "check_peak_accuracy"]

#: Default relative accuracy of reported peaks (``[run] peak_accuracy``).
DEFAULT_PEAK_ACCURACY = 1e-4
#: Sub-intervals of the bracket (two steps) integrated in one pass; even, so that step
#: ``k`` ends on a node.
_NODES = 16
_SPACING = 2.0 / _NODES
#: Iterations of the bracketing search between the largest node's neighbours (each halves
#: the bracket at worst; it stops at the value tolerance long before).
_MAX_ITERATIONS = 60
_STATE = ("traction", "F", "R", "plastic_slip", "gap", "frame")
#: A set of the law's outputs in the compiled loop's order (the state's first).
_SET_KEYS = ("traction", "F", "R", "gap", "plastic_slip", "dlam", "vp", "diss", "tangent",
             "status", "iterations")  # fmt: skip


def check_peak_accuracy(value: object) -> float | None:
    """``peak_accuracy`` as a float in (0, 0.1], or None (no refinement); ParameterError else."""
    from frictionlab.errors import ParameterError

    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not 0 < value <= 0.1:
        raise ParameterError(
            "peak_accuracy", value, "a number in (0, 0.1], or None (no refinement)"
        )
    return float(value)


@dataclass(frozen=True)
class RefinedPeaks:
    """Refined segment peaks, one row per (segment, point) whose largest sample was a turn.

    ``segment``, ``point`` are 1-based; ``step`` is the sampled peak's step; ``offset`` the
    refined position in steps from step ``k - 1`` (in [0, 2]); ``time`` [s], ``slip``
    (rows, 2) [m], ``path_length`` [m] and ``friction_ratio`` [-] at the refined peak;
    ``sampled_friction_ratio`` the largest sample it replaces.
    """

    segment: np.ndarray
    point: np.ndarray
    step: np.ndarray
    offset: np.ndarray
    time: np.ndarray
    slip: np.ndarray
    path_length: np.ndarray
    friction_ratio: np.ndarray
    sampled_friction_ratio: np.ndarray

    @classmethod
    def empty(cls) -> RefinedPeaks:
        z = np.zeros(0)
        i = np.zeros(0, dtype=np.int64)
        return cls(i, i, i, z, z, np.zeros((0, 2)), z, z, z)

    @classmethod
    def join(cls, parts: list[RefinedPeaks]) -> RefinedPeaks:
        if not parts:
            return cls.empty()
        return cls(
            *(np.concatenate([getattr(p, f) for p in parts]) for f in cls.__dataclass_fields__)
        )

    def __len__(self) -> int:
        return int(self.segment.size)


def _ratio(traction: np.ndarray) -> np.ndarray:
    fn = traction[:, 2]
    ft = np.hypot(traction[:, 0], traction[:, 1])
    return np.where(fn > 0.0, ft / np.where(fn > 0.0, fn, 1.0), 0.0)


def _control_arrays(control: Control, n: int) -> dict[str, np.ndarray]:
    """A control's values as (N, ...) arrays (NaN where a target is not prescribed)."""
    nan = np.full(n, np.nan)
    return {
        "dt": np.array(np.broadcast_to(np.asarray(control.dt, dtype=np.float64), (n,))),
        "du_t": np.array(np.broadcast_to(np.asarray(control.du_t, dtype=np.float64), (n, 2))),
        "du_n": np.array(np.broadcast_to(np.asarray(control.du_n, dtype=np.float64), (n,))),
        "fn": nan.copy() if control.fn_target is None else
        np.array(np.broadcast_to(np.asarray(control.fn_target, dtype=np.float64), (n,))),
    }  # fmt: skip


class _CompiledDoubling:
    """The step doubling of a slip-controlled advance in one compiled call
    (:func:`~frictionlab.driver._doubling_loop.double_steps`: the Python advance's law
    calls, so its state)."""

    def __init__(
        self, params: SubloadingParams, n: int, tol: float, max_halvings: int, owner: _Bracket
    ) -> None:
        from frictionlab.subloading import kernels
        from frictionlab.subloading.return_map import kernel_settings

        self.law = kernel_settings(params, n == 1, False)[:8]  # as update() for (N,) dt
        self.static = np.ascontiguousarray(np.broadcast_to(params.static, (n,)), dtype=np.float64)
        self.sets = tuple(
            tuple(kernels.empty_outputs(n, tangent=False)[key] for key in _SET_KEYS)
            for _ in range(3)
        )
        self.du, self.dt = np.empty((n, 3)), np.empty(n)
        self.tol, self.max_halvings, self.owner = tol, max_halvings, owner

    @classmethod
    def make(
        cls, params: SubloadingParams, n: int, tol: float, max_halvings: int, owner: _Bracket
    ) -> _CompiledDoubling | None:
        """The compiled advance where it gives the Python one's: the law's own update, a
        serial number of points; else None."""
        from frictionlab.driver import stepping
        from frictionlab.subloading.return_map import PARALLEL_MIN_POINTS

        if stepping.update is not stepping._LAW_UPDATE or n >= PARALLEL_MIN_POINTS:
            return None
        return cls(params, n, tol, max_halvings, owner)

    def __call__(self, start: ContactState, control: Control) -> ContactState | None:
        """The state after ``control`` (no traction target) from ``start``; None where a
        point failed or the law raised (the caller then runs the Python advance)."""
        from frictionlab.driver._doubling_loop import (
            D_SOLVES,
            D_SUBSTEPS,
            D_UNMET,
            double_steps,
        )

        double: Callable[..., bool] = double_steps  # compiled on first use
        n = start.n_points
        state = tuple(np.array(getattr(start, key), dtype=np.float64) for key in _SET_KEYS[:5])
        du = np.empty((n, 3))
        du[:, :2] = control.du_t
        du[:, 2] = control.du_n
        dt = np.ascontiguousarray(control.dt, dtype=np.float64)
        counters = np.zeros(3, dtype=np.int64)
        try:
            ok = double(state, du, dt, self.tol, self.max_halvings, self.static, self.law,
                              *self.sets, self.du, self.dt, counters)  # fmt: skip
        except ArithmeticError:
            return None
        finally:
            self.owner.solves += int(counters[D_SOLVES])
            self.owner.substeps += int(counters[D_SUBSTEPS])
            self.owner.unmet += int(counters[D_UNMET])
        if not ok:
            return None
        traction, F, R, gap, plastic_slip = state
        return ContactState._trusted(
            traction=traction, F=F, R=R, gap=gap, plastic_slip=plastic_slip, frame=start.frame
        )


class _Bracket:
    """The friction ratio over the bracket ``[k - 1, k + 1]`` of each point (in steps from
    step ``k - 1``): one pass of ``_NODES`` sub-intervals from the state at ``k - 1``, each
    advanced with the driver's step doubling to ``tol``, keeps the state at every node;
    the ratio between nodes is one advance from the node before.

    ``before``: the states at ``k - 1``; ``ctl``, ``nxt``: the controls of steps ``k`` and
    ``k + 1`` (:func:`_control_arrays`); ``turn``: the points refined (the others stay at
    their node 0).
    """

    def __init__(
        self,
        params: SubloadingParams,
        before: dict[str, np.ndarray],
        ctl: dict[str, np.ndarray],
        nxt: dict[str, np.ndarray],
        turn: np.ndarray,
        tol: float,
        max_halvings: int,
        compiled: bool = True,
    ) -> None:
        self.params, self.ctl, self.nxt, self.turn = params, ctl, nxt, turn
        self.tol, self.max_halvings = tol, max_halvings
        n = turn.shape[0]
        self.rows = np.arange(n)
        self.nodes = {
            name: np.empty((_NODES + 1, *arr.shape), dtype=arr.dtype)
            for name, arr in before.items()
        }
        self.ratio = np.empty((_NODES + 1, n))
        self.ok = True
        # law calls, accepted substeps, substeps left inaccurate at the deepest halving
        self.solves = self.substeps = self.unmet = 0
        self.compiled = (
            _CompiledDoubling.make(params, n, tol, max_halvings, self) if compiled else None
        )
        node = np.zeros(n, dtype=np.int64)
        self._keep(0, ContactState._trusted(**before))
        for i in range(_NODES):
            node[:] = i
            state = self._advance(node, np.where(turn, (i + 1) * _SPACING, i * _SPACING))
            if state is None:
                self.ok = False
                return
            self._keep(i + 1, state)

    def _keep(self, i: int, state: ContactState) -> None:
        for name, arr in self.nodes.items():
            arr[i] = getattr(state, name)
        self.ratio[i] = _ratio(state.traction)

    def _advance(self, node: np.ndarray, x: np.ndarray) -> ContactState | None:
        """The states at ``x`` (per point, in [node, node + 1] spacings) advanced from the
        kept ``node`` (per point); None where the step failed even substepped."""
        from frictionlab.driver.stepping import advance

        n = x.shape[0]
        start = ContactState._trusted(
            **{name: arr[node, self.rows] for name, arr in self.nodes.items()}
        )
        x0 = node * _SPACING
        second = node >= _NODES // 2  # in step k + 1
        frac = np.where(self.turn, x - x0, 0.0)  # of a step
        a1 = np.where(second, x - 1.0, x)  # the end, as a fraction of its step
        c = {name: np.where(second.reshape((n,) + (1,) * (a.ndim - 1)), self.nxt[name], a)
             for name, a in self.ctl.items()}  # fmt: skip
        prescribed = self.turn & ~np.isnan(c["fn"])  # the other points keep theirs
        fn_target = None
        if prescribed.any():  # reached linearly over the step, from its start
            fn_start = np.where(
                second, self.nodes["traction"][_NODES // 2, :, 2], self.nodes["traction"][0, :, 2]
            )
            fn_target = np.where(
                prescribed, fn_start + a1 * (c["fn"] - fn_start), start.traction[:, 2]
            )
        control = Control(
            frac * c["dt"], frac[:, None] * c["du_t"], frac * c["du_n"], None, fn_target
        )
        if fn_target is None and self.compiled is not None:
            state = self.compiled(start, control)
            if state is not None:
                return state
        out, work = advance(
            self.params, start, control, accuracy=self.tol, max_halvings=self.max_halvings
        )
        self.solves += work.solves
        self.substeps += work.substeps
        self.unmet += int(work.accuracy_unmet)
        return out.state if out.ok else None

    def _negative_ratio(self, x: np.ndarray, rows: np.ndarray) -> np.ndarray:
        """-ratio at ``x`` for the points ``rows`` (the others stay at node 0: no cost)."""
        n = self.turn.shape[0]
        node = np.zeros(n, dtype=np.int64)
        xs = np.zeros(n)
        node[rows] = np.minimum(np.floor(x / _SPACING), _NODES).astype(np.int64)
        xs[rows] = x
        state = self._advance(node, xs)
        if state is None:
            return np.full(rows.shape, np.inf)
        return -_ratio(state.traction)[rows]

    def peak(self) -> tuple[np.ndarray, np.ndarray]:
        """Position (steps from ``k - 1``) and value of each point's largest ratio: the
        largest node, then Chandrupatla's bracketing search
        (:func:`scipy.optimize.elementwise.find_minimum`) between its neighbours, to
        ``(f_l - 2 f_m + f_r)/2 <= tol/2``: a concave peak is then at most ``tol`` above
        the best point found."""
        j = np.argmax(self.ratio, axis=0)
        cols = np.arange(j.shape[0])
        best = self.ratio[j, cols]
        x = j * _SPACING
        inner = self.turn & (j > 0) & (j < _NODES)
        rows = np.flatnonzero(inner)
        if rows.size:
            from scipy.optimize.elementwise import find_minimum  # ~0.5 s: only when refining

            jr = j[rows]
            res = find_minimum(
                self._negative_ratio,
                ((jr - 1) * _SPACING, jr * _SPACING, (jr + 1) * _SPACING),
                args=(rows,),
                tolerances={"fatol": 0.5 * self.tol, "xatol": 1e-12},
                maxiter=_MAX_ITERATIONS,
            )
            found = -res.f_bracket[1]
            up = np.isfinite(found) & (found > best[rows])
            best[rows[up]] = found[up]
            x[rows[up]] = res.bracket[1][up]
        return x, np.where(self.turn, best, -np.inf)


class PeakTracker:
    """Keeps, per point, what is needed to refine each segment's largest friction ratio."""

    def __init__(self, n_points: int) -> None:
        self.n = n_points
        #: Law calls of every refinement so far, and of the last one, the trial steps left
        #: short of its accuracy at the deepest halving.
        self.solves = 0
        self.unmet = 0
        #: Whether the last refinement failed (its segment keeps the largest samples).
        self.failed = False

    def begin_segment(
        self, state: ContactState, time: np.ndarray, slip: np.ndarray, path: np.ndarray
    ) -> None:
        """Start a segment from ``state`` with running time, slip (N, 2) and path length."""
        n = self.n
        self.start_ratio = _ratio(state.traction)
        self.best = np.full(n, -np.inf)
        self.k = np.full(n, -1, dtype=np.int64)
        self.before = {name: np.array(getattr(state, name), order="C") for name in _STATE}
        self.after = {name: np.array(getattr(state, name), order="C") for name in _STATE}
        self.ctl = _control_arrays(Control(np.zeros(n), np.zeros((n, 2)), np.zeros(n)), n)
        self.time = np.array(time)  # after step k
        self.slip = np.array(slip)
        self.path = np.array(path)
        self.prescribed_traction = False

    def observe(
        self,
        k: int,
        before: ContactState,
        after: ContactState,
        control: Control,
        time: np.ndarray,
        slip: np.ndarray,
        path: np.ndarray,
    ) -> None:
        """Step ``k`` (0-based in the segment) took ``before`` to ``after``: keep both where
        the ratio rose above the segment's largest so far."""
        if control.ft_target is not None:
            self.prescribed_traction = True
        r = _ratio(after.traction)
        rose = r > self.best
        if not rose.any():
            return
        self.best[rose] = r[rose]
        self.k[rose] = k
        for name in _STATE:
            self.before[name][rose] = getattr(before, name)[rose]
            self.after[name][rose] = getattr(after, name)[rose]
        for name, arr in _control_arrays(control, self.n).items():
            self.ctl[name][rose] = arr[rose]
        self.time[rose] = time[rose]
        self.slip[rose] = slip[rose]
        self.path[rose] = path[rose]

    def refine(
        self,
        params: SubloadingParams,
        plan: SegmentPlan,
        steps: int,
        accuracy: float,
        *,
        max_halvings: int,
        first_step: int,
        index: int,
        compiled: bool = True,
    ) -> RefinedPeaks:
        """Refine the turns of the segment just run (``steps`` steps; ``first_step`` its
        first step in the programme, ``index`` its 1-based number; ``compiled``: the step
        doubling in one compiled call where it qualifies, else in Python)."""
        n = self.n
        self.unmet, self.failed = 0, False
        turn = (self.k >= 0) & (self.k < steps - 1) & (self.best > self.start_ratio)
        if self.prescribed_traction or not turn.any():
            return RefinedPeaks.empty()
        # the control of step k + 1, per point
        nxt = {name: arr.copy() for name, arr in self.ctl.items()}
        for k in np.unique(self.k[turn]):
            sel = turn & (self.k == k)
            for name, arr in _control_arrays(plan.control(int(k) + 1), n).items():
                nxt[name][sel] = arr[sel]
        tol = 0.1 * accuracy * float(np.min(self.best[turn]))
        bracket = _Bracket(params, self.before, self.ctl, nxt, turn, tol, max_halvings, compiled)
        if not bracket.ok:  # a sub-interval failed even substepped: keep the samples
            self.solves += bracket.solves
            self.failed = True
            return RefinedPeaks.empty()
        x, best = bracket.peak()
        self.solves += bracket.solves
        self.unmet = bracket.unmet
        better = turn & np.isfinite(best)
        rows = np.flatnonzero(better)
        if not rows.size:
            return RefinedPeaks.empty()
        k = self.k[rows]
        second = x[rows] > 1.0
        dt1, dt2 = self.ctl["dt"][rows], nxt["dt"][rows]
        ds1, ds2 = self.ctl["du_t"][rows], nxt["du_t"][rows]
        xr = x[rows]
        time = np.where(
            second, self.time[rows] + (xr - 1.0) * dt2, self.time[rows] - (1.0 - xr) * dt1
        )
        slip = np.where(
            second[:, None],
            self.slip[rows] + (xr - 1.0)[:, None] * ds2,
            self.slip[rows] - (1.0 - xr)[:, None] * ds1,
        )
        dp1, dp2 = np.hypot(*ds1.T), np.hypot(*ds2.T)
        path = np.where(
            second, self.path[rows] + (xr - 1.0) * dp2, self.path[rows] - (1.0 - xr) * dp1
        )
        return RefinedPeaks(
            segment=np.full(rows.size, index, dtype=np.int64),
            point=rows + 1,
            step=first_step + k,
            offset=xr,
            time=time,
            slip=slip,
            path_length=path,
            friction_ratio=best[rows],
            sampled_friction_ratio=self.best[rows],
        )
