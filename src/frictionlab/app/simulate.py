"""The simulate workflow: a scenario file -> the driver -> history.csv, points.csv, plots.

:func:`run_scenario` runs a parsed :class:`~frictionlab.schema.scenario.Scenario`;
:data:`SIMULATE` is the workflow ``frictionlab simulate`` runs
(:func:`frictionlab.commands._pipeline.run_command`); :func:`write_results` writes a run's
files and summary.json the same way for the demo.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory
from frictionlab.app import simulate_files as files
from frictionlab.app.outputs import write_outputs
from frictionlab.driver import DriverSettings, History, simulate, simulate_spring_slider
from frictionlab.driver.healing import Healing, healing_analysis
from frictionlab.driver.recorder import RowSink
from frictionlab.driver.simulate import ProgressCallback
from frictionlab.schema.scenario import Scenario

__all__ = ["SIMULATE", "SimulateRun", "run_scenario", "write_results"]


def run_scenario(
    scenario: Scenario,
    progress: ProgressCallback | None = None,
    sink: RowSink | None = None,
    keep_rows: int | None = None,
    keep_points: Sequence[int] | None = None,
) -> History:
    """Simulate ``scenario`` (never raises for a failed computation: see History.success).

    A programme records as ``[output]`` says; ``sink`` receives the recorded rows in
    chunks as they are computed; ``keep_rows`` and ``keep_points`` then bound what
    stays in memory (see :class:`~frictionlab.driver.recorder.Recording`). The
    spring-slider records every step in memory (``[output]`` is applied when its
    history is written).
    """
    opts = scenario.run_options
    settings = DriverSettings(accuracy=opts.accuracy, max_halvings=opts.max_halvings)
    if scenario.program is not None:
        return simulate(
            scenario.params, scenario.program, scenario.initial, n_points=scenario.n_points,
            settings=settings, progress=progress,
            recording=scenario.output.recording(sink, keep_rows, keep_points),
            peak_accuracy=opts.peak_accuracy or None,
        )  # fmt: skip
    assert scenario.machine is not None
    m = scenario.machine
    return simulate_spring_slider(
        scenario.params, m.machine, m.duration, steps=m.steps, max_step=m.max_step,
        initial=scenario.initial, n_points=scenario.n_points, settings=settings,
        progress=progress,
    )  # fmt: skip


@dataclass(frozen=True)
class SimulateRun:
    """A finished run: the history (rows kept in memory), the stream that wrote
    history.csv during the run (if any) and the healing analysis of its holds."""

    history: History
    stream: files.HistoryStream | None = None
    healing: Healing | None = None


class Simulate:
    """``frictionlab simulate SCENARIO.toml --out DIR`` (:mod:`frictionlab.commands.simulate`)."""

    name = "simulate"
    aliases: tuple[str, ...] = ()

    def parse(self, args: argparse.Namespace, out: Path) -> Scenario:
        from frictionlab.app.budget import check_output_space
        from frictionlab.schema.scenario import load_scenario

        scenario = load_scenario(args.scenario, args.set)  # every input check happens here
        if scenario.estimate is not None:  # and the output's size against the free disk space
            check_output_space(scenario.estimate, out, scenario.run_options.allow_large)
        for text in scenario.warnings:  # before the run: the user may stop it
            print(f"frictionlab: warning: {text}", file=sys.stderr)
        return scenario

    def run(self, job: Scenario, progress: ProgressFactory, staging: Path) -> SimulateRun:
        from frictionlab.plotting.law import shown_points

        name = Path(job.source).name if job.source else "scenario"
        stream = None
        with progress(f"simulate {name}") as update:
            if job.kind == "program":
                shown = shown_points(job.output.recorded_points(job.n_points))
                with files.HistoryStream(
                    staging / job.output.history_name, cone=job.params.is_cone
                ) as stream:
                    history = run_scenario(job, update, stream, files.PLOT_ROWS, shown.tolist())
            else:
                history = run_scenario(job, progress=update)
        return self.finished(job, history, stream)

    @staticmethod
    def finished(job: Scenario, history: History, stream: Any = None) -> SimulateRun:
        healing = healing_analysis(history) if job.kind == "program" else None
        return SimulateRun(history, stream, healing)

    def files(self, job: Scenario, result: SimulateRun, out: Path, plots: bool) -> list[Path]:
        return files.write_files(out, job, result.history, plots, result.stream, result.healing)

    def summary(
        self, job: Scenario, result: SimulateRun, names: list[str], seconds: float
    ) -> dict[str, Any]:
        history, stream = result.history, result.stream
        if stream is not None:
            recorded_rows = stream.rows // job.output.recorded_points(job.n_points)
        else:
            recorded_rows = files.select_rows(history, job.output).n_rows
        return files.summarise(job, history, seconds, names, result.healing, recorded_rows)

    def inputs(self, job: Scenario) -> list[Path]:
        return files.scenario_inputs(job)

    def report(
        self, job: Scenario, result: SimulateRun, seconds: float, written: list[Path]
    ) -> None:
        mu_s = job.params.mu_s if job.params.is_cone and np.ndim(job.params.mu_s) == 0 else None
        files.print_report(job.labels, result.history, seconds, mu_s)
        print("wrote " + ", ".join(str(p) for p in written))

    def notes(self, job: Scenario, result: SimulateRun) -> list[str]:
        return [f"frictionlab: warning: {text}" for text in result.history.warnings]

    def failure(self, job: Scenario, result: SimulateRun, out: Path) -> str | None:
        history = result.history
        if history.success:
            return None
        name = job.output.history_name
        return f"{history.message}; the history up to the failure is in {out / name}"


#: The simulate workflow.
SIMULATE = Simulate()


def write_results(
    out_dir: str | Path, scenario: Scenario, history: History, elapsed: float, plots: bool = True
) -> list[Path]:
    """Write history.csv, points.csv, the plots and summary.json (last); return the paths."""
    result = Simulate.finished(scenario, history)
    return write_outputs(SIMULATE, scenario, result, Path(out_dir), plots=plots, seconds=elapsed)
