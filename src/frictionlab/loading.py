"""Loading segments shared by the point driver and the contact model.

:class:`Slide`, :class:`Reverse` and :class:`Hold` are declared once, with one set of
rules, and read by both :func:`frictionlab.driver.program.plan_program` (N points) and
:func:`frictionlab.contact.loading.plan_stages` (one top edge):

* a velocity is > 0 [m/s]; the direction is ``direction_deg`` (counter-clockwise from
  x; ``None``: keep the current direction, initially 0);
* a slide goes for exactly one of ``distance`` [m] or ``duration`` [s]; a reverse goes
  back along the opposite of the current direction, with the last slide's velocity and
  distance unless given;
* ``steps`` (an integer >= 1) or ``max_step`` (the most slip per step [m]); with neither,
  the model's default resolution (``DEFAULT_STEPS`` of :mod:`frictionlab.driver.program`
  and of :mod:`frictionlab.contact.loading`).

Both models also have a ``Traction`` segment (kind ``"traction"``): the tangential
traction is prescribed and the slip solved for. What is loaded differs (a pair
(f_t1, f_t2) at each point in the driver; the mean shear on the top, a scalar ``target``
along ``direction_deg``, in the contact model), so each package declares its own class;
``cycles`` has one meaning and one check here (:func:`_cycles`): the number of full
load cycles, 0 (the default) for a single ramp to the target. The cycle's shape is the
model's: in the driver the traction goes between its start value and the target and
ends at the start (ratcheting); in the contact model it ramps to the target, then
alternates +target -> -target -> +target (fretting) and ends at the target.

Numeric fields are scalars or arrays ``(N,)`` (one value per point; the contact model
takes scalars). Segments are frozen and checked at construction
(:class:`~frictionlab.errors.ParameterError` naming the field).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from frictionlab.errors import ParameterError

__all__ = ["Hold", "Reverse", "Slide"]


# --------------------------------------------------------------------------- value checks
def _array(name: str, value: Any, *, shape_tail: tuple[int, ...] = ()) -> np.ndarray:
    """A read-only float64 array: ``shape_tail`` (shared) or ``(N,) + shape_tail``."""
    try:
        arr = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError(name, value, "a real number or an array of real numbers") from None
    ok_ndim = (len(shape_tail), len(shape_tail) + 1)
    if arr.ndim not in ok_ndim or arr.shape[arr.ndim - len(shape_tail) :] != shape_tail:
        want = f"shape {shape_tail} or (N, {', '.join(map(str, shape_tail))})"
        raise ParameterError(name, value, want if shape_tail else "a scalar or an array (N,)")
    if arr.ndim > len(shape_tail) and arr.shape[0] == 0:
        raise ParameterError(name, value, "at least one value")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(name, value, "finite values (no NaN or infinity)")
    arr.setflags(write=False)
    return arr


def _checked(name: str, value: Any, rule: str | None) -> np.ndarray:
    arr = _array(name, value)
    if rule == ">0" and np.any(arr <= 0):
        raise ParameterError(name, value, f"{name} > 0")
    if rule == ">=0" and np.any(arr < 0):
        raise ParameterError(name, value, f"{name} >= 0")
    return arr


def _optional(name: str, value: Any, rule: str | None) -> np.ndarray | None:
    return None if value is None else _checked(name, value, rule)


def _check_field(seg: Any, name: str, rule: str | None, *, optional: bool = False) -> None:
    """Replace field ``name`` of the frozen ``seg`` by its checked read-only array
    (:func:`_checked`'s ``rule``); an ``optional`` field may stay None."""
    value = getattr(seg, name)
    checked = _optional(name, value, rule) if optional else _checked(name, value, rule)
    object.__setattr__(seg, name, checked)


def _steps(name: str, value: Any) -> int | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 1:
        raise ParameterError(name, value, "an integer >= 1")
    return int(value)


#: The most load cycles of a traction segment.
MAX_CYCLES = 10_000


def _cycles(value: Any) -> int:
    """``cycles`` of a traction segment: an integer 0 <= cycles <= 1e4 (``None``: 0)."""
    if value is None:  # the driver's earlier spelling of "no cycles", kept for one release
        return 0
    if (
        isinstance(value, bool)
        or not isinstance(value, int | np.integer)
        or not 0 <= value <= MAX_CYCLES
    ):
        raise ParameterError("cycles", value, "an integer 0 <= cycles <= 1e4")
    return int(value)


def _max_step(value: Any) -> float | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
        raise ParameterError("max_step", value, "a number > 0")
    if not math.isfinite(value):
        raise ParameterError("max_step", value, "a finite number > 0")
    return float(value)


def _one_of(owner: str, **given: Any) -> str:
    names = [k for k, v in given.items() if v is not None]
    if len(names) != 1:
        options = " or ".join(given)
        got = ", ".join(names) if names else "none"
        raise ParameterError(owner, got, f"exactly one of {options}")
    return names[0]


def _sizes(*arrays: np.ndarray | None, tail: int = 0) -> set[int]:
    return {a.shape[0] for a in arrays if a is not None and a.ndim > tail}


# --------------------------------------------------------------------------- segments
@dataclass(frozen=True)
class Slide:
    """Slide at ``velocity`` [m/s] for a ``distance`` [m] or a ``duration`` [s] (one of them).

    ``direction_deg`` is the sliding direction in the contact plane, counter-clockwise
    from x; when omitted the current direction is kept (initially 0). The normal
    approach is held (no plastic normal sliding, Eq 32).
    """

    velocity: Any
    distance: Any = None
    duration: Any = None
    direction_deg: Any = None
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "slide"

    def __post_init__(self) -> None:
        _one_of("slide length", distance=self.distance, duration=self.duration)
        _check_field(self, "velocity", ">0")
        _check_field(self, "distance", ">0", optional=True)
        _check_field(self, "duration", ">0", optional=True)
        _check_field(self, "direction_deg", None, optional=True)
        _check_steps(self)

    def sizes(self) -> set[int]:
        return _sizes(self.velocity, self.distance, self.duration, self.direction_deg)


@dataclass(frozen=True)
class Reverse:
    """Slide back: along the opposite of the current direction (which it then becomes).

    ``velocity`` and ``distance`` default to those of the preceding sliding segment
    (so ``Slide`` then ``Reverse`` returns to the start); give ``duration`` instead of
    ``distance`` to slide for a time.
    """

    velocity: Any = None
    distance: Any = None
    duration: Any = None
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "reverse"

    def __post_init__(self) -> None:
        _init_inherited(self)

    def sizes(self) -> set[int]:
        return _sizes(self.velocity, self.distance, self.duration)


@dataclass(frozen=True)
class Hold:
    """Stop: zero sliding velocity for ``duration`` [s] (the traction is held, F recovers)."""

    duration: Any
    steps: int | None = None
    max_step: float | None = None
    kind: ClassVar[str] = "hold"

    def __post_init__(self) -> None:
        _check_field(self, "duration", ">=0")
        _check_steps(self)

    def sizes(self) -> set[int]:
        return _sizes(self.duration)


# --------------------------------------------------------------------------- shared checks
def _check_steps(seg: Any) -> None:
    _steps("steps", seg.steps)
    _max_step(seg.max_step)
    if seg.steps is not None and seg.max_step is not None:
        raise ParameterError("steps", seg.steps, "steps or max_step, not both")


def _init_inherited(seg: Any) -> None:
    if seg.distance is not None and seg.duration is not None:
        raise ParameterError(
            seg.kind, "distance and duration", "at most one of distance or duration"
        )
    _check_field(seg, "velocity", ">0", optional=True)
    _check_field(seg, "distance", ">0", optional=True)
    _check_field(seg, "duration", ">0", optional=True)
    _check_steps(seg)
