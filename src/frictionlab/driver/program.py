"""Loading programmes: what a tribometer does to a contact, as data.

A :data:`Program` is a tuple of segments, run one after the other:

* :class:`Slide` — slide at a velocity for a distance or a duration, along a direction
  in the contact plane;
* :class:`Hold` — stop (sliding velocity zero) for a duration;
* :class:`Reverse` — slide back along the opposite of the current direction;
* :class:`Turn` — slide along a direction turned by an angle from the current one;
* :class:`Cycle` — displacement-controlled cycles ``0 -> +A -> -A -> 0`` about the
  current position;
* :class:`NormalStep` — a prescribed normal approach or normal-traction change;
* :class:`Traction` — tangential traction-controlled loading (the driver solves for
  the slip, so ratcheting can be simulated); ``TractionControl`` is its deprecated name;
* :class:`Table` — time, slip and normal traction (or approach) read from a table.

Numeric fields are scalars shared by every point or arrays of shape ``(N,)`` (one value
per point), so that, for example, a sweep of hold times runs as one vectorised
programme. Step counts are shared by all points (the points advance in lockstep).

Segments are frozen and validated at construction (:class:`~frictionlab.errors.ParameterError`
naming the field). :func:`plan_program` resolves the defaults that depend on the
preceding segments (the current sliding direction, the velocity and distance a
:class:`Reverse` or :class:`Turn` inherits) and turns every segment into a plan that
hands out one :class:`Control` per step.

Units (SI): velocity [m/s], distance, amplitude, approach and slip [m], duration and
time [s], tractions [Pa], angles in degrees (``*_deg``).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, fields
from typing import Any, ClassVar

import numpy as np

from frictionlab.errors import ParameterError
from frictionlab.loading import (
    Hold,
    Reverse,
    Slide,
    _array,
    _check_field,
    _check_steps,
    _cycles,
    _init_inherited,
    _max_step,
    _one_of,
    _sizes,
    _steps,
)

__all__ = [
    "DEFAULT_STEPS",
    "SEGMENT_KINDS",
    "Control",
    "Cycle",
    "Hold",
    "NormalStep",
    "PlanContext",
    "Program",
    "Reverse",
    "Segment",
    "SegmentPlan",
    "Slide",
    "SlipRuns",
    "Table",
    "Traction",
    "Turn",
    "plan_program",
    "program_points",
    "segment_fields",
    "slide_hold_slide",
]


# --------------------------------------------------------------------------- value checks
def _count(extent: np.ndarray, max_step: float) -> int:
    """Steps needed so that no point moves more than ``max_step`` per step."""
    return max(1, math.ceil(float(np.max(np.abs(extent))) / max_step * (1.0 - 1e-12)))


#: Most steps a traction target's ``max_step`` may ask for (its count is known only when the
#: segment starts, after the size checks of the input).
MAX_TARGET_STEPS = 10**7


def _lerp(a: np.ndarray, b: np.ndarray, s: float) -> np.ndarray:
    """``(1 - s) a + s b``: exactly ``b`` at ``s = 1`` (a target is never lost to
    ``a + s (b - a)``'s cancellation, e.g. 1e-200 Pa from 1 Pa)."""
    return (1.0 - s) * a + s * b


def _vec(value: np.ndarray, n: int) -> np.ndarray:
    return np.broadcast_to(value, (n,)).astype(np.float64)


# --------------------------------------------------------------------------- controls
@dataclass(frozen=True)
class Control:
    """What one step prescribes for N points (mixed control, as in MTest).

    Attributes
    ----------
    dt:
        (N,) time increment [s].
    du_t:
        (N, 2) prescribed tangential slip increment [m] (contact frame); ignored where
        ``ft_target`` is given.
    du_n:
        (N,) prescribed normal approach increment [m]; ignored where ``fn_target`` is given.
    ft_target:
        (N, 2) tangential traction [Pa] to reach at the end of the step, or None.
    fn_target:
        (N,) normal traction [Pa] to reach at the end of the step, or None.
    """

    dt: np.ndarray
    du_t: np.ndarray
    du_n: np.ndarray
    ft_target: np.ndarray | None = None
    fn_target: np.ndarray | None = None

    def halves(self, start: np.ndarray) -> tuple[Control, Control]:
        """Two half steps from the traction ``start`` (N, 3) at the beginning of this step.

        Slip and time are split equally; traction targets are interpolated linearly.
        """
        ft_mid = None if self.ft_target is None else 0.5 * (start[:, :2] + self.ft_target)
        fn_mid = None if self.fn_target is None else 0.5 * (start[:, 2] + self.fn_target)
        first = Control(0.5 * self.dt, 0.5 * self.du_t, 0.5 * self.du_n, ft_mid, fn_mid)
        second = Control(
            0.5 * self.dt, 0.5 * self.du_t, 0.5 * self.du_n, self.ft_target, self.fn_target
        )
        return first, second

    def _slip_increment(self, n: int) -> tuple[np.ndarray, np.ndarray]:
        """(N, 3) slip increment ``(du_t, du_n)`` [m] of a step that prescribes no traction,
        built once per control (a plan repeats its control): the array for the law's kernel
        (never written: the kernel's compiled form for writeable inputs serves it) and a
        read-only view of it for everything else."""
        cached = self.__dict__.get("_du")
        if cached is None or cached[0].shape[0] != n:
            du = np.empty((n, 3))
            du[:, :2] = self.du_t
            du[:, 2] = self.du_n
            view = du.view()
            view.setflags(write=False)
            cached = (du, view)
            object.__setattr__(self, "_du", cached)
        return cached


@dataclass(frozen=True)
class SlipRuns:
    """A segment that prescribes no traction, as runs of steps with one control each:
    steps ``bounds[r] <= k < bounds[r + 1]`` apply ``controls[which[r]]`` (the driver's
    compiled loop, :mod:`~frictionlab.driver.compiled_steps`, runs them)."""

    controls: tuple[Control, ...]
    bounds: np.ndarray  #: (R + 1,) int64, first step of each run, then the step count
    which: np.ndarray  #: (R,) int64, index into ``controls`` of each run

    @classmethod
    def constant(cls, control: Control, steps: int) -> SlipRuns:
        """Every step the same ``control``."""
        return cls((control,), np.array([0, steps], dtype=np.int64), np.zeros(1, np.int64))


# --------------------------------------------------------------------------- plans
@dataclass
class PlanContext:
    """What a segment may inherit from the ones before it (arrays (N,))."""

    n_points: int
    direction: np.ndarray  #: current sliding direction [rad] from e_1, counter-clockwise
    velocity: np.ndarray | None = None  #: velocity of the last sliding segment [m/s]
    distance: np.ndarray | None = None  #: distance of the last slide/reverse/turn [m]


class SegmentPlan:
    """A segment resolved for N points: a step count and one :class:`Control` per step.

    ``begin(start)`` is called with the traction (N, 3) at the start of the segment and
    returns the number of steps (it can depend on the start for traction targets);
    ``control(k)`` then gives step ``k`` (0-based).
    """

    kind: str
    resolved: dict[str, Any]

    def __init__(self, kind: str, n_points: int, resolved: dict[str, Any]) -> None:
        self.kind = kind
        self.n_points = n_points
        self.resolved = resolved
        self.start = np.zeros((n_points, 3))

    @property
    def estimated_steps(self) -> int:
        """Step count known before the run (exact except for traction targets with max_step)."""
        raise NotImplementedError

    def begin(self, start: np.ndarray) -> int:
        self.start = np.array(start, dtype=np.float64)
        return self.estimated_steps

    def control(self, k: int) -> Control:
        raise NotImplementedError

    def slip_runs(self) -> SlipRuns | None:
        """After :meth:`begin`: the controls of every step as :class:`SlipRuns` (the very
        objects or values :meth:`control` gives) when no step prescribes a traction; None
        otherwise."""
        return None

    @property
    def is_hold(self) -> bool:
        """True when nothing slides during the segment (for marking holds in plots)."""
        return False


class _ConstantPlan(SegmentPlan):
    """Equal steps with the same prescribed increments."""

    def __init__(
        self,
        kind: str,
        n: int,
        steps: int,
        dt: np.ndarray,
        du_t: np.ndarray,
        du_n: np.ndarray,
        resolved: dict[str, Any],
        hold: bool = False,
    ) -> None:
        super().__init__(kind, n, resolved)
        self.steps = steps
        self._control = Control(dt, du_t, du_n)
        self._hold = hold

    @property
    def estimated_steps(self) -> int:
        return self.steps

    def control(self, k: int) -> Control:
        return self._control

    def slip_runs(self) -> SlipRuns:
        return SlipRuns.constant(self._control, self.steps)

    @property
    def is_hold(self) -> bool:
        return self._hold


def _direction_vector(theta: np.ndarray) -> np.ndarray:
    """Unit vectors (N, 2); components below 1e-15 (round-off of pi) are set to 0."""
    unit = np.column_stack([np.cos(theta), np.sin(theta)])
    unit[np.abs(unit) < 1e-15] = 0.0
    return unit


def _slide_plan(
    kind: str,
    ctx: PlanContext,
    theta: np.ndarray,
    velocity: np.ndarray,
    distance: np.ndarray,
    steps: int,
    extra: dict[str, Any],
) -> tuple[SegmentPlan, PlanContext]:
    n = ctx.n_points
    step_len = distance / steps
    du_t = _direction_vector(theta) * step_len[:, None]
    resolved = {
        "kind": kind,
        **extra,
        "velocity": velocity,
        "distance": distance,
        "duration": distance / velocity,
        "direction_deg": np.degrees(theta),
        "steps": steps,
    }
    plan = _ConstantPlan(kind, n, steps, step_len / velocity, du_t, np.zeros(n), resolved)
    return plan, PlanContext(n, theta, velocity, distance)


#: Steps of a shared segment that gives neither ``steps`` nor ``max_step``. A hold's
#: recovery is integrated exactly (no stability limit): one step is exact at its end.
DEFAULT_STEPS = {"slide": 100, "reverse": 100, "hold": 1}


def _plan_slide(seg: Slide, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
    n = ctx.n_points
    theta = ctx.direction if seg.direction_deg is None else np.radians(_vec(seg.direction_deg, n))
    velocity = _vec(seg.velocity, n)
    distance = (
        _vec(seg.distance, n) if seg.distance is not None else velocity * _vec(seg.duration, n)
    )
    steps = _resolve_steps(seg, distance)
    return _slide_plan(seg.kind, ctx, _vec(theta, n), velocity, distance, steps, {})


def _plan_reverse(seg: Reverse, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
    velocity, distance = _inherit(seg, ctx)
    steps = _resolve_steps(seg, distance)
    return _slide_plan(seg.kind, ctx, ctx.direction + math.pi, velocity, distance, steps, {})


def _plan_hold(seg: Hold, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
    n = ctx.n_points
    duration = _vec(seg.duration, n)
    steps = _resolve_steps(seg, duration)
    resolved = {"kind": seg.kind, "duration": duration, "steps": steps}
    zeros = np.zeros((n, 2))
    plan = _ConstantPlan(
        seg.kind, n, steps, duration / steps, zeros, np.zeros(n), resolved, hold=True
    )
    return plan, ctx


# --------------------------------------------------------------------------- segments
@dataclass(frozen=True)
class Turn:
    """Turn the sliding direction by ``angle_deg`` (counter-clockwise) and slide on.

    ``velocity`` and ``distance`` default to those of the preceding sliding segment.
    """

    angle_deg: Any
    velocity: Any = None
    distance: Any = None
    duration: Any = None
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "turn"
    default_steps: ClassVar[int] = 100

    def __post_init__(self) -> None:
        _check_field(self, "angle_deg", None)
        _init_inherited(self)

    def sizes(self) -> set[int]:
        return _sizes(self.angle_deg, self.velocity, self.distance, self.duration)

    def plan(self, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
        velocity, distance = _inherit(self, ctx)
        theta = ctx.direction + np.radians(_vec(self.angle_deg, ctx.n_points))
        steps = _resolve_steps(self, distance)
        extra = {"angle_deg": _vec(self.angle_deg, ctx.n_points)}
        return _slide_plan(self.kind, ctx, theta, velocity, distance, steps, extra)


@dataclass(frozen=True)
class Cycle:
    """Displacement cycles ``0 -> +amplitude -> -amplitude -> 0`` about the current position.

    Triangular wave at constant ``velocity`` along ``direction_deg`` (default: the
    current direction). ``steps`` counts the steps of one cycle (rounded up to a
    multiple of 4, default 400); ``max_step`` [m] bounds the slip per step instead.
    """

    amplitude: Any
    velocity: Any
    cycles: int = 1
    direction_deg: Any = None
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "cycle"
    default_steps: ClassVar[int] = 400

    def __post_init__(self) -> None:
        _check_field(self, "amplitude", ">0")
        _check_field(self, "velocity", ">0")
        _check_field(self, "direction_deg", None, optional=True)
        _steps("cycles", self.cycles)
        _check_steps(self)
        if self.steps is not None and self.steps < 4:
            raise ParameterError("steps", self.steps, "at least 4 steps per cycle")

    def sizes(self) -> set[int]:
        return _sizes(self.amplitude, self.velocity, self.direction_deg)

    def plan(self, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
        n = ctx.n_points
        theta = (
            ctx.direction if self.direction_deg is None else np.radians(_vec(self.direction_deg, n))
        )
        theta = _vec(theta, n)
        amplitude = _vec(self.amplitude, n)
        velocity = _vec(self.velocity, n)
        if self.max_step is not None:
            quarter = _count(amplitude, self.max_step)
        else:
            quarter = math.ceil((self.steps or self.default_steps) / 4)
        step_len = amplitude / quarter
        resolved = {
            "kind": self.kind,
            "amplitude": amplitude,
            "velocity": velocity,
            "cycles": self.cycles,
            "direction_deg": np.degrees(theta),
            "steps": 4 * quarter,
        }
        plan = _CyclePlan(n, quarter, self.cycles, theta, step_len, velocity, resolved)
        return plan, PlanContext(n, theta, velocity, ctx.distance)


class _CyclePlan(SegmentPlan):
    def __init__(
        self,
        n: int,
        quarter: int,
        cycles: int,
        theta: np.ndarray,
        step_len: np.ndarray,
        velocity: np.ndarray,
        resolved: dict[str, Any],
    ) -> None:
        super().__init__("cycle", n, resolved)
        self.quarter = quarter
        self.cycles = cycles
        du = _direction_vector(theta) * step_len[:, None]
        dt = step_len / velocity
        self._forward = Control(dt, du, np.zeros(n))
        self._backward = Control(dt, -du, np.zeros(n))

    @property
    def estimated_steps(self) -> int:
        return 4 * self.quarter * self.cycles

    def control(self, k: int) -> Control:
        q = (k // self.quarter) % 4  # quarters of a cycle: +, -, -, +
        return self._forward if q in (0, 3) else self._backward

    def slip_runs(self) -> SlipRuns:
        quarters = 4 * self.cycles
        bounds = np.arange(quarters + 1, dtype=np.int64) * self.quarter
        which = np.isin(np.arange(quarters) % 4, (1, 2)).astype(np.int64)
        return SlipRuns((self._forward, self._backward), bounds, which)


@dataclass(frozen=True)
class NormalStep:
    """Change the normal loading; the tangential slip is held.

    Exactly one of ``approach`` [m] (an increment of the normal approach, positive
    closes; it may open the contact), ``traction`` [Pa] (the normal traction to reach,
    > 0) or ``traction_change`` [Pa] (added to the current normal traction). The normal
    traction is controlled exactly, since there is no plastic normal sliding (Eq 32).
    ``duration`` [s] (default 0) is the time the change takes. Default 1 step;
    ``max_step`` is in m (approach) or Pa (traction).
    """

    approach: Any = None
    traction: Any = None
    traction_change: Any = None
    duration: Any = 0.0
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "normal"
    default_steps: ClassVar[int] = 1

    def __post_init__(self) -> None:
        _one_of(
            "normal",
            approach=self.approach,
            traction=self.traction,
            traction_change=self.traction_change,
        )
        _check_field(self, "approach", None, optional=True)
        _check_field(self, "traction", ">0", optional=True)
        _check_field(self, "traction_change", None, optional=True)
        _check_field(self, "duration", ">=0")
        _check_steps(self)

    def sizes(self) -> set[int]:
        return _sizes(self.approach, self.traction, self.traction_change, self.duration)

    def plan(self, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
        return _NormalPlan(self, ctx.n_points), ctx


class _NormalPlan(SegmentPlan):
    def __init__(self, seg: NormalStep, n: int) -> None:
        resolved: dict[str, Any] = {"kind": seg.kind}
        for name in ("approach", "traction", "traction_change"):
            if getattr(seg, name) is not None:
                resolved[name] = _vec(getattr(seg, name), n)
        resolved["duration"] = _vec(seg.duration, n)
        super().__init__(seg.kind, n, resolved)
        self.seg = seg
        self.steps = seg.steps or seg.default_steps
        if seg.max_step is not None and seg.traction is None:
            extent = seg.approach if seg.approach is not None else seg.traction_change
            self.steps = _count(np.asarray(extent), seg.max_step)
        self.resolved["steps"] = self.steps
        self.target: np.ndarray | None = None

    @property
    def estimated_steps(self) -> int:
        return self.steps

    def begin(self, start: np.ndarray) -> int:
        super().begin(start)
        n, seg = self.n_points, self.seg
        if seg.traction is not None:
            self.target = _vec(seg.traction, n)
            if seg.max_step is not None:
                self.steps = _count(self.target - self.start[:, 2], seg.max_step)
                if self.steps > MAX_TARGET_STEPS:
                    change = float(np.max(np.abs(self.target - self.start[:, 2])))
                    raise ParameterError(
                        "max_step",
                        seg.max_step,
                        f"a step that reaches the traction change {change:.6g} Pa in at most "
                        f"{MAX_TARGET_STEPS} steps (it asks {self.steps:.3g})",
                    )
                self.resolved["steps"] = self.steps
        elif seg.traction_change is not None:
            self.target = self.start[:, 2] + _vec(seg.traction_change, n)
            if np.any(self.target <= 0.0):
                raise ParameterError(
                    "traction_change",
                    seg.traction_change,
                    "a change that leaves the normal traction > 0 (to open the contact, "
                    "prescribe an approach)",
                )
        return self.steps

    def control(self, k: int) -> Control:
        n = self.n_points
        dt = self.resolved["duration"] / self.steps
        zeros = np.zeros((n, 2))
        if self.target is None:
            return Control(dt, zeros, self.resolved["approach"] / self.steps)
        target = _lerp(self.start[:, 2], self.target, (k + 1) / self.steps)
        return Control(dt, zeros, np.zeros(n), fn_target=target)

    def slip_runs(self) -> SlipRuns | None:
        return None if self.target is not None else SlipRuns.constant(self.control(0), self.steps)


@dataclass(frozen=True)
class Traction:
    """Tangential traction-controlled loading: reach the traction ``traction`` = (f_t1, f_t2) [Pa].

    The traction goes linearly from its value at the start of the segment to the
    target in ``steps`` equal increments (default 100; or ``max_step`` [Pa] of traction
    per step); the driver solves for the slip of each step with Newton's method on the
    consistent tangent. ``cycles`` counts full load cycles (0, the default: one ramp;
    ``None`` is accepted as 0 for one release): with ``cycles = n`` the segment goes to
    the target and back to the start traction n times (ratcheting: the residual slip
    grows each cycle). The contact model's :class:`frictionlab.contact.loading.Traction`
    is the same kind of segment for a whole top face: a mean shear ``target`` along
    ``direction_deg`` instead of a pair per point.
    ``duration`` [s] is the time of one leg (default 0: rate-independent). The normal
    approach is held. A target the contact cannot carry (gross sliding) makes the
    computation fail.
    """

    traction: Any
    duration: Any = 0.0
    cycles: int = 0
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "traction"
    default_steps: ClassVar[int] = 100

    def __post_init__(self) -> None:
        object.__setattr__(self, "traction", _array("traction", self.traction, shape_tail=(2,)))
        _check_field(self, "duration", ">=0")
        object.__setattr__(self, "cycles", _cycles(self.cycles))
        _check_steps(self)

    def sizes(self) -> set[int]:
        return _sizes(self.traction, tail=1) | _sizes(self.duration)

    def plan(self, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
        return _TractionPlan(self, ctx.n_points), ctx


class _TractionPlan(SegmentPlan):
    def __init__(self, seg: Traction, n: int) -> None:
        target = np.broadcast_to(seg.traction, (n, 2)).astype(np.float64)
        resolved = {
            "kind": seg.kind,
            "traction": target,
            "duration": _vec(seg.duration, n),
            "cycles": seg.cycles,
        }
        super().__init__(seg.kind, n, resolved)
        self.seg = seg
        self.target = target
        self.legs = 2 * seg.cycles if seg.cycles else 1
        self.per_leg = seg.steps or seg.default_steps
        self.resolved["steps"] = self.per_leg * self.legs

    @property
    def estimated_steps(self) -> int:
        return self.per_leg * self.legs

    def begin(self, start: np.ndarray) -> int:
        super().begin(start)
        if self.seg.max_step is not None:
            self.per_leg = _count(self.target - self.start[:, :2], self.seg.max_step)
            self.resolved["steps"] = self.per_leg * self.legs
        return self.estimated_steps

    def control(self, k: int) -> Control:
        n = self.n_points
        leg, j = divmod(k, self.per_leg)
        a, b = self.start[:, :2], self.target
        if leg % 2 == 1:
            a, b = b, a
        target = _lerp(a, b, (j + 1) / self.per_leg)
        dt = self.resolved["duration"] / self.per_leg
        return Control(dt, np.zeros((n, 2)), np.zeros(n), ft_target=target)


@dataclass(frozen=True)
class Table:
    """Table-driven loading: rows of time [s], tangential slip (slip_1, slip_2) [m] and
    optionally normal traction [Pa] or normal approach [m].

    Slip and approach are cumulative and taken relative to the first row (so only
    their changes matter); each interval between rows is one step, or
    ``steps_per_row`` equal steps, or as many as needed for ``max_step`` [m] of slip per
    step. The normal traction of row ``i > 0`` is reached at the end of interval ``i``,
    from the traction at the start of the segment for the first interval. The table is
    shared by all points. ``source`` names where the table came from (for messages).
    """

    time: Any
    slip: Any
    normal_traction: Any = None
    approach: Any = None
    steps_per_row: int | None = None
    max_step: float | None = None
    source: str = "table"
    kind: ClassVar[str] = "table"

    def __post_init__(self) -> None:
        time = _array("time", self.time, shape_tail=())
        if time.ndim != 1 or time.size < 2:
            raise ParameterError("time", self.time, "a column of at least 2 rows")
        if np.any(np.diff(time) < 0):
            raise ParameterError("time", self.time, "non-decreasing times")
        rows = time.size
        slip = _array("slip", self.slip, shape_tail=(2,))
        if slip.shape != (rows, 2):
            raise ParameterError("slip", slip.shape, f"shape ({rows}, 2), one row per time")
        object.__setattr__(self, "time", time)
        object.__setattr__(self, "slip", slip)
        if self.normal_traction is not None and self.approach is not None:
            raise ParameterError("normal", "normal_traction and approach", "at most one of them")
        for name in ("normal_traction", "approach"):
            value = getattr(self, name)
            if value is None:
                continue
            arr = _array(name, value)
            if arr.shape != (rows,):
                raise ParameterError(name, arr.shape, f"shape ({rows},), one value per row")
            if name == "normal_traction" and np.any(arr[1:] <= 0):
                raise ParameterError(name, value, "normal traction > 0 (compression)")
            object.__setattr__(self, name, arr)
        if self.steps_per_row is not None and self.max_step is not None:
            raise ParameterError(
                "steps_per_row", self.steps_per_row, "steps_per_row or max_step, not both"
            )
        _steps("steps_per_row", self.steps_per_row)
        _max_step(self.max_step)

    def sizes(self) -> set[int]:
        return set()

    def plan(self, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
        return _TablePlan(self, ctx.n_points), ctx


class _TablePlan(SegmentPlan):
    def __init__(self, seg: Table, n: int) -> None:
        dslip = np.diff(seg.slip, axis=0)
        if seg.max_step is not None:
            counts = [_count(np.hypot(*d), seg.max_step) for d in dslip]
        else:
            counts = [seg.steps_per_row or 1] * len(dslip)
        resolved = {
            "kind": seg.kind,
            "source": seg.source,
            "rows": int(seg.time.size),
            "steps": int(sum(counts)),
        }
        super().__init__(seg.kind, n, resolved)
        self.seg = seg
        self.counts = np.array(counts)
        self.first = np.concatenate([[0], np.cumsum(counts)])  # first step of each interval
        self.dslip = dslip
        self.dtime = np.diff(seg.time)

    @property
    def estimated_steps(self) -> int:
        return int(self.first[-1])

    def control(self, k: int) -> Control:
        n = self.n_points
        i = int(np.searchsorted(self.first, k, side="right") - 1)
        c = int(self.counts[i])
        j = k - int(self.first[i])
        dt = np.full(n, self.dtime[i] / c)
        du_t = np.broadcast_to(self.dslip[i] / c, (n, 2)).copy()
        if self.seg.approach is not None:
            dun = (self.seg.approach[i + 1] - self.seg.approach[i]) / c
            return Control(dt, du_t, np.full(n, dun))
        if self.seg.normal_traction is not None:
            a = self.start[:, 2] if i == 0 else np.full(n, self.seg.normal_traction[i])
            b = np.full(n, self.seg.normal_traction[i + 1])
            return Control(dt, du_t, np.zeros(n), fn_target=_lerp(a, b, (j + 1) / c))
        return Control(dt, du_t, np.zeros(n))

    def slip_runs(self) -> SlipRuns | None:
        if self.seg.normal_traction is not None:
            return None
        controls = tuple(self.control(int(k)) for k in self.first[:-1])
        return SlipRuns(
            controls, self.first.astype(np.int64), np.arange(len(controls), dtype=np.int64)
        )


# --------------------------------------------------------------------------- shared helpers
def _resolve_steps(seg: Any, extent: np.ndarray) -> int:
    if seg.max_step is not None:
        return _count(extent, seg.max_step)
    default = DEFAULT_STEPS.get(seg.kind) or seg.default_steps
    return int(seg.steps or default)


def _inherit(seg: Any, ctx: PlanContext) -> tuple[np.ndarray, np.ndarray]:
    n = ctx.n_points
    if seg.velocity is not None:
        velocity = _vec(seg.velocity, n)
    elif ctx.velocity is not None:
        velocity = ctx.velocity
    else:
        raise ParameterError(
            "velocity", None, f"a velocity for '{seg.kind}' (no sliding segment precedes it)"
        )
    if seg.distance is not None:
        distance = _vec(seg.distance, n)
    elif seg.duration is not None:
        distance = velocity * _vec(seg.duration, n)
    elif ctx.distance is not None:
        distance = ctx.distance
    else:
        raise ParameterError(
            "distance", None, f"a distance or duration for '{seg.kind}' (no slide precedes it)"
        )
    return velocity, distance


# --------------------------------------------------------------------------- programmes
Segment = Slide | Hold | Reverse | Turn | Cycle | NormalStep | Traction | Table
#: A loading programme: segments run one after the other.
Program = tuple[Segment, ...]

#: Segment classes by their ``kind`` (the ``kind`` key of a scenario's ``[[program]]``).
SEGMENT_KINDS: dict[str, type] = {
    cls.kind: cls for cls in (Slide, Hold, Reverse, Turn, Cycle, NormalStep, Traction, Table)
}


def program_points(program: Sequence[Segment]) -> set[int]:
    """The per-point sizes N used by the segments' arrays (empty when all are shared)."""
    out: set[int] = set()
    for seg in program:
        out |= seg.sizes()
    return out


def plan_program(program: Sequence[Segment], n_points: int) -> list[SegmentPlan]:
    """Resolve every segment for ``n_points`` points (inherited defaults, step counts).

    Raises :class:`~frictionlab.errors.ParameterError` naming the segment (1-based,
    ``segment #2 (reverse): ...``) when a value is missing or has the wrong number of
    points.
    """
    if len(program) == 0:
        raise ParameterError("program", "()", "at least one segment")
    ctx = PlanContext(n_points, np.zeros(n_points))
    plans = []
    for i, seg in enumerate(program, start=1):
        if not isinstance(seg, tuple(SEGMENT_KINDS.values())):
            raise ParameterError(
                f"segment #{i}",
                type(seg).__name__,
                "one of " + ", ".join(c.__name__ for c in SEGMENT_KINDS.values()),
            )
        bad = seg.sizes() - {n_points}
        if bad:
            raise ParameterError(
                f"segment #{i} ({seg.kind})",
                f"{sorted(bad)[0]} values",
                f"{n_points} (one per point) or a scalar",
            )
        try:
            plan, ctx = _plan(seg, ctx)
        except ParameterError as exc:
            raise ParameterError(
                f"segment #{i} ({seg.kind}) {exc.field}", exc.value, exc.allowed
            ) from None
        plans.append(plan)
    return plans


def _plan(seg: Segment, ctx: PlanContext) -> tuple[SegmentPlan, PlanContext]:
    if isinstance(seg, Slide):
        return _plan_slide(seg, ctx)
    if isinstance(seg, Reverse):
        return _plan_reverse(seg, ctx)
    if isinstance(seg, Hold):
        return _plan_hold(seg, ctx)
    return seg.plan(ctx)


def segment_fields(seg: Segment) -> dict[str, Any]:
    """The constructor fields of a segment with their values (for summaries)."""
    return {f.name: getattr(seg, f.name) for f in fields(seg)}


def slide_hold_slide(
    velocity: float,
    distance: float,
    hold_time: Any,
    reslide_distance: float | None = None,
    *,
    steps: int = 1000,
    hold_steps: int = 1,
    reslide_steps: int | None = None,
) -> Program:
    """Slide, hold for ``hold_time`` [s] (scalar or one per point), slide again.

    ``reslide_distance`` defaults to 0.3 of ``distance``; the re-slide keeps the step
    length of the first slide unless ``reslide_steps`` is given.
    """
    again = 0.3 * distance if reslide_distance is None else reslide_distance
    n_again = reslide_steps or max(1, round(steps * again / distance))
    return (
        Slide(velocity=velocity, distance=distance, steps=steps),
        Hold(duration=hold_time, steps=hold_steps),
        Slide(velocity=velocity, distance=again, steps=n_again),
    )


#: Former names, accepted for one release with a DeprecationWarning: {old: new}.
DEPRECATED_NAMES = {"TractionControl": "Traction"}


def __getattr__(name: str) -> Any:
    """The deprecated names of :data:`DEPRECATED_NAMES` (PEP 562)."""
    new = DEPRECATED_NAMES.get(name)
    if new is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    warnings.warn(
        f"{name} is deprecated and will be removed in the next release: use {new} (the same class)",
        DeprecationWarning,
        stacklevel=2,
    )
    return globals()[new]
