"""A validated ``frictionlab simulate`` scenario, ready to run.

The file is read by :mod:`frictionlab.schema.scenario` (every key declared once); its
names are importable from here too.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from frictionlab.app.budget import RunEstimate
from frictionlab.driver import InitialConditions, Program
from frictionlab.schema.scenario import (
    LAW_KEYS,
    MachineRun,
    OutputOptions,
    RunOptions,
    law_table,
    load_scenario,
    parse_initial_table,
    parse_law_table,
    parse_program_tables,
    parse_scenario,
)
from frictionlab.subloading import SubloadingParams

__all__ = [
    "LAW_KEYS",
    "MachineRun",
    "OutputOptions",
    "RunOptions",
    "Scenario",
    "law_table",
    "load_scenario",
    "parse_initial_table",
    "parse_law_table",
    "parse_program_tables",
    "parse_scenario",
]


# --------------------------------------------------------------------------- scenario
@dataclass(frozen=True)
class Scenario:
    """A validated scenario, ready to run (:func:`frictionlab.app.simulate.run_scenario`)."""

    title: str
    description: str
    params: SubloadingParams
    initial: InitialConditions
    run_options: RunOptions
    n_points: int
    program: Program | None = None
    machine: MachineRun | None = None
    inputs: dict[str, Any] = field(default_factory=dict)
    labels: tuple[str, ...] = ()
    source: str = ""
    output: OutputOptions = field(default_factory=OutputOptions)
    #: The work estimate made while parsing (``None`` for a scenario built in Python).
    estimate: RunEstimate | None = None

    @property
    def kind(self) -> str:
        """``"program"`` or ``"spring_slider"``."""
        return "program" if self.program is not None else "spring_slider"
