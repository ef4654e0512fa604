"""The export workflow: a scenario's law -> an Abaqus user interaction (no computation).

:data:`EXPORT` is what ``frictionlab export abaqus`` runs
(:func:`frictionlab.commands._pipeline.run_command`): the scenario's ``[law]`` and the
initial size F of ``[initial]`` become the files of :mod:`frictionlab.export.abaqus`,
and summary.json lists them with the 22 PROPS.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory
from frictionlab.app.outputs import WorkflowBase
from frictionlab.io.scenario import Scenario

__all__ = ["EXPORT", "ExportJob"]


@dataclass(frozen=True)
class ExportJob:
    """A checked export: the scenario, the target code, the PROPS and the initial F."""

    scenario: Scenario
    target: str
    props: np.ndarray
    F_initial: float | None


class Export(WorkflowBase):
    """``frictionlab export abaqus SCENARIO.toml --out DIR`` (frictionlab.commands.export)."""

    name = "export"

    def parse(self, args: argparse.Namespace, out: Path) -> ExportJob:
        from frictionlab.errors import ParameterError
        from frictionlab.export.abaqus import props_vector
        from frictionlab.io.scenario import load_scenario

        scenario = load_scenario(args.scenario, args.set)
        F0 = scenario.initial.F
        if F0 is not None and np.unique(np.asarray(F0, dtype=float)).size > 1:
            raise ParameterError("initial.F", F0, "one value: an Abaqus interaction has one set")
        F_initial = None if F0 is None else float(np.asarray(F0, dtype=float).ravel()[0])
        # refuses a law whose values differ per point, naming the key
        return ExportJob(scenario, args.target, props_vector(scenario.params, F_initial), F_initial)

    def run(self, job: ExportJob, progress: ProgressFactory, staging: Path) -> None:
        return None  # the files are text made from the law: nothing to compute

    def files(self, job: ExportJob, result: None, out: Path, plots: bool) -> list[Path]:
        from frictionlab.export.abaqus import write_files

        s = job.scenario
        return write_files(out, s.params, s.title, job.F_initial)

    def summary(
        self, job: ExportJob, result: None, names: list[str], seconds: float
    ) -> dict[str, Any]:
        from frictionlab.export.abaqus import PROPS

        return {
            "title": job.scenario.title,
            "success": True,
            "export": {
                "target": job.target,
                "props": {name: float(v) for (name, _, _), v in zip(PROPS, job.props, strict=True)},
            },
        }

    def inputs(self, job: ExportJob) -> list[Path]:
        return [Path(job.scenario.source)] if job.scenario.source else []


#: The export workflow.
EXPORT = Export()
