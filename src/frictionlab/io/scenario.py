"""A validated ``frictionlab simulate`` scenario, ready to run.

The file is read by :mod:`frictionlab.schema.scenario` (every key declared once); its
names are importable from here too.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from frictionlab.driver import (
    History,
    InitialConditions,
    Program,
    simulate,
    simulate_spring_slider,
)
from frictionlab.driver.recorder import RowSink
from frictionlab.driver.simulate import ProgressCallback
from frictionlab.io.budget import RunEstimate
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
    """A validated scenario, ready to run (:meth:`run`)."""

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

    def run(
        self,
        progress: ProgressCallback | None = None,
        sink: RowSink | None = None,
        keep_rows: int | None = None,
        keep_points: Sequence[int] | None = None,
    ) -> History:
        """Simulate the scenario (never raises for a failed computation: see History.success).

        A programme records as ``[output]`` says; ``sink`` receives the recorded rows in
        chunks as they are computed; ``keep_rows`` and ``keep_points`` then bound what
        stays in memory (see :class:`~frictionlab.driver.recorder.Recording`). The
        spring-slider records every step in memory (``[output]`` is applied when its
        history is written).
        """
        opts = self.run_options
        if self.program is not None:
            return simulate(
                self.params, self.program, self.initial, n_points=self.n_points,
                accuracy=opts.accuracy, max_halvings=opts.max_halvings, progress=progress,
                recording=self.output.recording(sink, keep_rows, keep_points),
            )  # fmt: skip
        assert self.machine is not None
        m = self.machine
        return simulate_spring_slider(
            self.params, m.machine, m.duration, steps=m.steps, max_step=m.max_step,
            initial=self.initial, n_points=self.n_points, accuracy=opts.accuracy,
            max_halvings=opts.max_halvings, progress=progress,
        )  # fmt: skip
