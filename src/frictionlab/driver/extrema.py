"""Friction-ratio peaks between recorded steps.

A step grid samples the friction ratio |f_t|/f_n; its largest sample falls short of the
true peak by up to the change over a step (7 % for the starter scenario at 100 steps).
:class:`PeakTracker` keeps, per point, the states on both sides of the largest sample of
each segment (step ``k``: the states after steps ``k - 1`` and ``k``, and the controls of
steps ``k`` and ``k + 1``). Where the sample is a turn (larger than the segment's start and
its last step), :meth:`PeakTracker.refine` maximises the ratio over the bracket
``[k - 1, k + 1]`` by golden-section search; each trial advances from the bracket's kept
state by a fraction of the driver's own step (slip and time scaled, traction targets
interpolated linearly as in :meth:`~frictionlab.driver.program.Control.halves`) with the
driver's step-doubling control at a tenth of the requested accuracy.

The peak is then within ``peak_accuracy`` (relative) of the converged one whenever the
state at step ``k - 1`` is (exact from a segment's start; otherwise to the driver's own
accuracy). Steps that prescribe the tangential traction are not refined: the ratio is
then linear between steps, so its peak is a sample.

Pure computation: no file I/O.
"""

from __future__ import annotations

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
_GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0
#: Golden-section iterations: the bracket (two steps) shrinks to 2 * 0.618**40 ~ 1e-8
#: of a step; the peak's value error is quadratic in that.
_ITERATIONS = 40
_STATE = ("traction", "F", "R", "plastic_slip", "gap", "frame")


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


class PeakTracker:
    """Keeps, per point, what is needed to refine each segment's largest friction ratio."""

    def __init__(self, n_points: int) -> None:
        self.n = n_points

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
    ) -> RefinedPeaks:
        """Refine the turns of the segment just run (``steps`` steps; ``first_step`` its
        first step in the programme, ``index`` its 1-based number)."""
        from frictionlab.driver.stepping import advance

        n = self.n
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

        def ratio_at(x: np.ndarray) -> np.ndarray:
            """The ratio at ``x`` steps past step k - 1 (x in [0, 2]; 0 off the turns)."""
            second = x > 1.0
            frac = np.where(turn, np.where(second, x - 1.0, x), 0.0)
            start = ContactState._trusted(
                **{
                    nm: np.where(
                        second.reshape((n,) + (1,) * (self.before[nm].ndim - 1)),
                        self.after[nm],
                        self.before[nm],
                    )
                    for nm in _STATE
                }
            )
            c = {nm: np.where(second.reshape((n,) + (1,) * (a.ndim - 1)), nxt[nm], a)
                 for nm, a in self.ctl.items()}  # fmt: skip
            fn0 = start.traction[:, 2]
            fn_target = np.where(np.isnan(c["fn"]), np.nan, fn0 + frac * (c["fn"] - fn0))
            prescribed = ~np.isnan(c["fn"])
            ctl = Control(
                frac * c["dt"],
                frac[:, None] * c["du_t"],
                frac * c["du_n"],
                None,
                np.where(prescribed, fn_target, fn0) if prescribed.any() else None,
            )
            out, _ = advance(params, start, ctl, accuracy=tol, max_halvings=max_halvings)
            if not out.ok:  # keep the sample there
                return np.where(turn, -np.inf, 0.0)
            return _ratio(out.state.traction)

        a, b = np.zeros(n), np.full(n, 2.0)
        c = b - _GOLDEN * (b - a)
        d = a + _GOLDEN * (b - a)
        fc, fd = ratio_at(c), ratio_at(d)
        for _ in range(_ITERATIONS):
            left = fc > fd  # the maximum lies in [a, d]
            b = np.where(left, d, b)
            a = np.where(left, a, c)
            new = np.where(left, b - _GOLDEN * (b - a), a + _GOLDEN * (b - a))
            fnew = ratio_at(new)
            c, d, fc, fd = (
                np.where(left, new, d),
                np.where(left, c, new),
                np.where(left, fnew, fd),
                np.where(left, fc, fnew),
            )
        x = np.where(fc > fd, c, d)
        best = np.maximum(fc, fd)
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
