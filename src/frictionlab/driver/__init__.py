"""Loading programmes and loading systems driving the subloading-friction law.

Public API:

* segments :class:`Slide`, :class:`Hold`, :class:`Reverse`, :class:`Turn`, :class:`Cycle`,
  :class:`NormalStep`, :class:`Traction`, :class:`Table`; a :data:`Program` is a
  tuple of them (:mod:`~frictionlab.driver.program`);
* :func:`simulate` -> :class:`History` (:mod:`~frictionlab.driver.simulate`): N points in
  one vectorised run, automatic substepping, work counters;
* :class:`SpringSlider`, :func:`simulate_spring_slider`, :func:`critical_stiffness`
  (:mod:`~frictionlab.driver.spring_slider`): stick-slip of a compliant loading system.

Pure computation: no file I/O, no printing (progress through a callback).
"""

from typing import Any

from frictionlab.driver import program as _program
from frictionlab.driver.program import (
    SEGMENT_KINDS,
    Control,
    Cycle,
    Hold,
    NormalStep,
    Program,
    Reverse,
    Segment,
    Slide,
    Table,
    Traction,
    Turn,
    plan_program,
    slide_hold_slide,
)
from frictionlab.driver.simulate import (
    DriverSettings,
    History,
    InitialConditions,
    Recording,
    SegmentRecord,
    simulate,
    status_labels,
)
from frictionlab.driver.spring_slider import (
    SpringSlider,
    count_slip_events,
    critical_stiffness,
    friction_oscillation,
    simulate_spring_slider,
    steady_F,
)

__all__ = [
    "SEGMENT_KINDS",
    "Control",
    "Cycle",
    "DriverSettings",
    "History",
    "Hold",
    "InitialConditions",
    "NormalStep",
    "Program",
    "Recording",
    "Reverse",
    "Segment",
    "SegmentRecord",
    "Slide",
    "SpringSlider",
    "Table",
    "Traction",
    "Turn",
    "count_slip_events",
    "critical_stiffness",
    "friction_oscillation",
    "plan_program",
    "simulate",
    "simulate_spring_slider",
    "slide_hold_slide",
    "status_labels",
    "steady_F",
]


def __getattr__(name: str) -> Any:
    """Former names (``TractionControl``), with a DeprecationWarning (PEP 562)."""
    if name in _program.DEPRECATED_NAMES:
        return getattr(_program, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
