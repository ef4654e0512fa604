"""Loading of the contact model: a normal phase, then a tangential programme.

The normal load acts on the top of the block: a uniform pressure [Pa], a total force
(N per metre of depth in 2-D, N in 3-D; applied as the uniform pressure force / top
area) or a prescribed downward displacement [m] of the top edge, ramped linearly over
``duration`` and then held. The tangential programme uses the segment vocabulary of
``frictionlab simulate`` where it applies:

* :class:`~frictionlab.loading.Slide` — move the top edge at ``velocity`` > 0 [m/s] for a
  ``distance`` [m] or a ``duration`` [s] along ``direction_deg`` (default: the current
  direction, initially x; 180: -x) (displacement control);
* :class:`~frictionlab.loading.Reverse` — slide back, opposite to the last slide, with its
  speed and distance unless given;
* :class:`~frictionlab.loading.Hold` — keep the last tangential control value for
  ``duration`` [s];
* :class:`Traction` — ramp the mean shear traction on the top edge to ``target`` [Pa]
  over ``duration`` [s] (force control; the top edge is then free in x), along x or
  ``direction_deg``; with ``cycles = k`` it then cycles k times between ``-target``
  and ``+target`` (each ramp over ``duration``: fretting loops).

Slide, Reverse and Hold are the driver's segments (:mod:`frictionlab.loading`, one set of
rules); this model takes scalar values. A programme is displacement- or force-controlled
as a whole (Hold fits both). ``steps`` is the nominal number of load steps of a segment
(or ``max_step`` [m], the most slip per step; default :data:`DEFAULT_STEPS`); the solver
cuts a step on non-convergence and grows it back after easy steps, never beyond the
nominal size.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from frictionlab.errors import ParameterError
from frictionlab.loading import Hold, Reverse, Slide, _cycles

__all__ = [
    "DEFAULT_STEPS",
    "Hold",
    "NormalLoad",
    "Reverse",
    "Segment",
    "Slide",
    "Stage",
    "Traction",
    "plan_stages",
]


def _real(name: str, value: Any, rule: str, ok: bool) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise ParameterError(name, value, f"a finite number ({rule})")
    if not ok:
        raise ParameterError(name, value, rule)
    return float(value)


def _steps(value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < 1 or value > 1_000_000:
        raise ParameterError("steps", value, "an integer 1 <= steps <= 1e6")
    return int(value)


@dataclass(frozen=True)
class NormalLoad:
    """Normal phase: ``pressure`` [Pa], ``force`` [N/m in 2-D, N in 3-D] or top
    ``displacement`` [m, downward], exactly one of them."""

    pressure: float | None = None
    displacement: float | None = None
    duration: float = 1.0
    steps: int = 5
    force: float | None = None

    def __post_init__(self) -> None:
        given = [k for k in ("pressure", "displacement", "force") if getattr(self, k) is not None]
        if len(given) != 1:
            raise ParameterError(
                "normal",
                ", ".join(given) or "none",
                "exactly one of pressure, displacement or force",
            )
        if self.pressure is not None:
            _real("pressure", self.pressure, "pressure > 0 [Pa]", self.pressure > 0)
        if self.force is not None:
            _real("force", self.force, "force > 0 [N/m in 2-D, N in 3-D]", self.force > 0)
        if self.displacement is not None:
            d = self.displacement
            _real("displacement", d, "displacement > 0 [m] (downward)", d > 0)
        _real("duration", self.duration, "duration > 0 [s]", self.duration > 0)
        _steps(self.steps)

    @property
    def control(self) -> str:
        """``"pressure"``, ``"force"`` or ``"displacement"``."""
        if self.pressure is not None:
            return "pressure"
        return "force" if self.force is not None else "displacement"

    @property
    def value(self) -> float:
        """The final pressure [Pa], force [N/m or N] or displacement [m]."""
        for v in (self.pressure, self.force, self.displacement):
            if v is not None:
                return float(v)
        raise AssertionError("unreachable")  # pragma: no cover


@dataclass(frozen=True)
class Traction:
    """Ramp the mean shear traction on the top to ``target`` [Pa] over ``duration`` [s].

    ``target`` is a scalar along ``direction_deg`` (counter-clockwise from x): the
    contact model loads one top face, where the driver's
    :class:`frictionlab.driver.program.Traction` prescribes a pair (f_t1, f_t2) per
    point. ``cycles`` counts full load cycles as there (0, the default: one ramp); here
    each cycle, after the ramp, goes +target -> -target -> +target (fretting), each leg
    in ``duration`` and ``steps``.
    """

    target: float
    duration: float
    steps: int = 20
    direction_deg: float = 0.0
    cycles: int = 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "cycles", _cycles(self.cycles))
        _real("target", self.target, "a finite target [Pa]", True)
        _real("direction_deg", self.direction_deg, "a finite angle [deg]", True)
        _real("duration", self.duration, "duration > 0 [s]", self.duration > 0)
        _steps(self.steps)


Segment = Slide | Reverse | Hold | Traction

#: Load steps of a Slide, Reverse or Hold that gives neither ``steps`` nor ``max_step`` (a
#: finite-element step costs far more than a point's, so fewer than the driver's).
DEFAULT_STEPS = {"slide": 20, "reverse": 20, "hold": 5}


def _scalar(seg: Slide | Reverse | Hold, name: str) -> float | None:
    value = getattr(seg, name, None)
    if value is None:
        return None
    if np.ndim(value) != 0:
        raise ParameterError(name, value, "a scalar (the contact model drives one top edge)")
    return float(value)


def _step_count(seg: Slide | Reverse | Hold, extent: float) -> int:
    if seg.max_step is not None:
        return max(1, math.ceil(abs(extent) / seg.max_step * (1.0 - 1e-12)))
    return int(seg.steps or DEFAULT_STEPS[seg.kind])


@dataclass(frozen=True)
class Stage:
    """One segment resolved to a linear ramp of its control value over time.

    ``kind`` is ``"normal"`` or the segment name; ``control`` is ``"pressure"``,
    ``"displacement"`` (normal: scalar values), ``"slide"`` (top displacement [m], a
    vector (x, y)) or ``"force"`` (mean top shear traction [Pa], a vector (x, y)); the
    value goes from ``start`` to ``end``.
    """

    kind: str
    control: str
    start: np.ndarray
    end: np.ndarray
    duration: float
    steps: int

    def value(self, fraction: float) -> np.ndarray:
        """The control value at a fraction in [0, 1] of the stage."""
        return self.start + (self.end - self.start) * fraction


def _unit(angle_deg: float) -> np.ndarray:
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    return np.array([0.0 if abs(c) < 1e-15 else c, 0.0 if abs(s) < 1e-15 else s])


def plan_stages(normal: NormalLoad, program: Sequence[Segment]) -> tuple[str, list[Stage]]:
    """Resolve the programme: (tangential control ``"slide"`` or ``"force"``, stages)."""
    kinds = {type(seg) for seg in program}
    if Traction in kinds and kinds & {Slide, Reverse}:
        raise ParameterError(
            "program",
            "slide/reverse and traction segments",
            "one kind of tangential control per run (displacement: slide, reverse, hold; "
            "force: traction, hold)",
        )
    control = "force" if Traction in kinds else "slide"
    zero = np.zeros(2)
    stages = [
        Stage(
            "normal",
            normal.control,
            np.array([0.0]),
            np.array([normal.value]),
            normal.duration,
            normal.steps,
        )
    ]
    value = zero.copy()
    last_step: np.ndarray | None = None  # the last slide's displacement vector
    last_speed = 0.0
    direction = 0.0  # the current sliding direction [deg]
    for i, seg in enumerate(program):
        if isinstance(seg, Slide | Reverse):
            if isinstance(seg, Slide):
                speed = _scalar(seg, "velocity") or 0.0
                distance = _scalar(seg, "distance") or speed * (_scalar(seg, "duration") or 0.0)
                given = _scalar(seg, "direction_deg")
                direction = direction if given is None else given
                step = distance * _unit(direction)
            else:
                if last_step is None:
                    raise ParameterError(
                        f"program[{i + 1}].kind", "reverse", "a reverse after at least one slide"
                    )
                speed = _scalar(seg, "velocity") or last_speed
                length = float(np.hypot(*last_step))
                duration = _scalar(seg, "duration")
                distance = _scalar(seg, "distance") or (
                    length if duration is None else speed * duration
                )
                step = -last_step * (distance / length)
                direction += 180.0
            end = value + step
            steps = _step_count(seg, distance)
            stages.append(Stage(seg.kind, control, value, end, distance / speed, steps))
            value, last_step, last_speed = end, step, speed
        elif isinstance(seg, Hold):
            duration = _scalar(seg, "duration") or 0.0
            stages.append(
                Stage("hold", control, value, value, duration, _step_count(seg, duration))
            )
        else:
            target = seg.target * _unit(seg.direction_deg)
            stages.append(Stage("traction", control, value, target, seg.duration, seg.steps))
            value = target
            for _ in range(seg.cycles):
                for end in (-target, target):
                    stages.append(Stage("traction", control, value, end, seg.duration, seg.steps))
                    value = end
    return control, stages
