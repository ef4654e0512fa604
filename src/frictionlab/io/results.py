"""Outputs of a simulated scenario: ``history.csv``, ``summary.json`` and the plots.

``history.csv`` is long format, one row per point and recorded step (point-major),
with units in the column titles (``time [s]``). ``summary.json`` echoes the inputs with defaults
filled, and gives peaks, final values, per-segment values, work counters, success and
the version. Every file is written atomically.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._version import __version__
from frictionlab.driver import History, Table
from frictionlab.driver.healing import Healing, healing_analysis
from frictionlab.driver.spring_slider import (
    count_slip_events,
    critical_stiffness,
    friction_oscillation,
)
from frictionlab.driver.table import HISTORY_UNITS, history_columns
from frictionlab.errors import FrictionlabError
from frictionlab.io.atomic import write_json_atomic
from frictionlab.io.provenance import stamp
from frictionlab.io.scenario import Scenario
from frictionlab.io.tables import write_csv_atomic

__all__ = ["HISTORY_UNITS", "history_columns", "summarise", "write_results"]


def _point_summary(
    history: History, i: int, label: str, ratios: np.ndarray, paths: np.ndarray
) -> dict[str, Any]:
    """Peak and final values of point ``i`` (``ratios``, ``paths``: (rows, N), computed once)."""
    ratio = ratios[:, i]
    k = int(np.argmax(ratio))
    path = paths[:, i]
    return {
        "point": i + 1,
        "label": label,
        "peak": {
            "friction_ratio": float(ratio[k]),
            "step": k,
            "time": float(history.time[k, i]),
            "slip_distance": float(path[k]),
        },
        "final": {
            "time": float(history.time[-1, i]),
            "slip": history.slip[-1, i].tolist(),
            "approach": float(history.approach[-1, i]),
            "traction": history.traction[-1, i].tolist(),
            "friction_ratio": float(ratio[-1]),
            "F": float(history.F[-1, i]),
            "R": float(history.R[-1, i]),
            "plastic_slip": float(history.plastic_slip[-1, i]),
            "dissipation": float(history.dissipation[-1, i]),
        },
    }


def _segment_summary(history: History, seg: Any, ratios: np.ndarray) -> dict[str, Any]:
    ratio = ratios[seg.rows]
    resolved = {
        k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in seg.resolved.items()
    }
    return {
        "index": seg.index,
        "kind": seg.kind,
        "first_step": seg.first_row,
        "last_step": seg.last_row,
        "resolved": resolved,
        "start_friction_ratio": ratio[0].tolist(),
        "peak_friction_ratio": ratio.max(axis=0).tolist(),
        "final_friction_ratio": ratio[-1].tolist(),
        "final_F": history.F[seg.last_row].tolist(),
        "final_R": history.R[seg.last_row].tolist(),
    }


def summarise(
    scenario: Scenario,
    history: History,
    elapsed: float,
    outputs: list[str],
    healing: Healing | None = None,
) -> dict[str, Any]:
    """The content of ``summary.json``.

    Linear in the number of points and rows: the friction ratio and the path length
    are computed once for the whole history, not once per point or segment.
    """
    labels = list(scenario.labels) + [""] * history.n_points
    ratios, paths = history.friction_ratio, history.path_length
    out: dict[str, Any] = {
        "frictionlab": __version__,
        "scenario": scenario.source,
        "title": scenario.title,
        "success": history.success,
        "message": history.message,
        "warnings": list(history.warnings),
        "n_points": history.n_points,
        "steps": history.n_rows - 1,
        "inputs": scenario.inputs,
        "points": [
            _point_summary(history, i, labels[i], ratios, paths) for i in range(history.n_points)
        ],
        "segments": [_segment_summary(history, seg, ratios) for seg in history.segments],
        "work": dict(history.work),
        "elapsed_seconds": round(elapsed, 3),
        "outputs": outputs,
    }
    if healing is not None:
        out["healing"] = healing.as_dict()
    if scenario.kind == "spring_slider" and history.n_rows > 1:
        machine = history.segments[0].resolved
        out["stick_slip"] = {
            "friction_oscillation_last_quarter": friction_oscillation(history, 0.25).tolist(),
            "slip_events": count_slip_events(history).tolist(),
            "critical_stiffness": _critical(scenario, machine),
        }
    return out


def _critical(scenario: Scenario, machine: dict[str, Any]) -> list[float] | str:
    params = scenario.params
    if np.any(np.asarray(params.orthotropy_angle) != 0) or np.any(machine["direction_deg"] != 0):
        return "not evaluated: the closed form holds for sliding along e*_1 = e_1"
    try:
        fn = np.broadcast_to(
            np.asarray(scenario.initial.normal_traction, float), (scenario.n_points,)
        )
        return critical_stiffness(params, machine["velocity"], fn).tolist()
    except FrictionlabError as exc:
        return f"not evaluated: {exc}"


def write_results(
    out_dir: str | os.PathLike[str],
    scenario: Scenario,
    history: History,
    elapsed: float,
    plots: bool = True,
) -> list[Path]:
    """Write history.csv, the plots and summary.json (last) into ``out_dir``; return the paths."""
    out = Path(out_dir)
    written: list[Path] = []
    cols, units = history_columns(history, cone=scenario.params.is_cone)
    comment = (
        f"frictionlab {__version__} history of '{scenario.title or scenario.source}'\n"
        f"{history.n_points} points x {history.n_rows} rows (row 0 = initial state); "
        f"success = {str(history.success).lower()}"
    )
    written.append(write_csv_atomic(out / "history.csv", cols, units, comment))
    healing = healing_analysis(history) if scenario.kind == "program" else None
    if healing is not None:
        written.append(_write_healing(out, healing))
    if plots and history.n_rows > 1:
        written.extend(_plots(out, scenario, history))
        if healing is not None:
            written.append(_plot_healing(out, scenario, healing))
    names = [p.name for p in written] + ["summary.json"]
    summary = stamp(summarise(scenario, history, elapsed, names, healing), names, _inputs(scenario))
    written.append(write_json_atomic(out / "summary.json", summary))
    return written


def _inputs(scenario: Scenario) -> list[Path]:
    """The scenario file and the table files its programme reads."""
    if not scenario.source:
        return []
    source = Path(scenario.source)
    tables = [seg.source for seg in scenario.program or () if isinstance(seg, Table) and seg.source]
    return [source, *(source.parent / name for name in tables)]


def _write_healing(out: Path, healing: Healing) -> Path:
    """healing.csv: one row per hold and point."""
    r = healing.records
    cols = {
        "point": np.array([x.point for x in r]),
        "hold_segment": np.array([x.hold_segment for x in r]),
        "hold_time": np.array([x.hold_time for x in r]),
        "friction_before": np.array([x.friction_before for x in r]),
        "restart_peak": np.array([x.restart_peak for x in r]),
        "delta_mu": np.array([x.delta_mu for x in r]),
        "peak_time": np.array([x.peak_time for x in r]),
    }
    units = {"point": "-", "hold_segment": "-", "hold_time": "s", "friction_before": "-",
             "restart_peak": "-", "delta_mu": "-", "peak_time": "s"}  # fmt: skip
    rate = healing.rate_per_decade
    comment = "slide-hold-slide analysis: restart peak after each hold\n" + (
        f"healing rate d(delta_mu)/d log10(t_h) = {rate!r} per decade (least squares)"
        if rate is not None
        else "healing rate: needs at least two distinct hold times"
    )
    return write_csv_atomic(out / "healing.csv", cols, units, comment)


def _plot_healing(out: Path, scenario: Scenario, healing: Healing) -> Path:
    from frictionlab.plotting.law import plot_healing, save_figure

    r = healing.records
    ax = plot_healing(
        np.array([x.hold_time for x in r]),
        np.array([x.delta_mu for x in r]),
        np.array([x.point for x in r]),
        healing.rate_per_decade,
        healing.intercept,
        scenario.labels,
    )
    ax.set_title(scenario.title, fontsize=9)
    return save_figure(ax.figure, out / "healing.png")  # type: ignore[arg-type]


def _plots(out: Path, scenario: Scenario, history: History) -> list[Path]:
    from frictionlab.plotting.law import (
        plot_friction,
        plot_spring_slider,
        plot_traction_path,
        save_figure,
    )

    paths = []
    labels = scenario.labels
    if scenario.kind == "spring_slider":
        fig = plot_spring_slider(history, labels)
        fig.suptitle(scenario.title)
        paths.append(save_figure(fig, out / "friction.png"))
    else:
        paths.append(
            save_figure(plot_friction(history, labels, scenario.title), out / "friction.png")
        )
    if not history.is_planar:
        ax = plot_traction_path(history, scenario.params, labels)
        ax.set_title(scenario.title, fontsize=9)
        paths.append(save_figure(ax.figure, out / "traction_path.png"))  # type: ignore[arg-type]
    return paths
