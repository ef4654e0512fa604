"""Outputs of a simulated scenario: ``history.csv``, ``points.csv``, ``summary.json``, plots.

``history.csv`` is long format, one row per recorded step and point (step-major), with
units in the column titles (``time [s]``); ``frictionlab simulate`` streams it to disk
chunk by chunk while the programme runs (:class:`HistoryStream`), so the history never
has to fit in memory. ``points.csv`` holds one row per point: peak, final and per-segment
figures over every step (not only the recorded ones). ``summary.json`` stays small
whatever the number of points: the inputs with defaults filled, aggregate figures (min,
mean, max over points), the per-point entries of the first :data:`SUMMARY_POINTS`
points, per-segment values, work counters, success, the version and the file list.
Every other file is written atomically.
"""

from __future__ import annotations

import os
from dataclasses import replace
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
from frictionlab.driver.table import (
    HISTORY_UNITS,
    chunk_columns,
    history_columns,
    history_units,
)
from frictionlab.errors import FrictionlabError
from frictionlab.io.closing import Closing
from frictionlab.io.parquet import ParquetStream, write_parquet_atomic
from frictionlab.io.tables import write_csv, write_csv_atomic
from frictionlab.schema.scenario import OutputOptions, Scenario

__all__ = [
    "HISTORY_UNITS",
    "PLOT_ROWS",
    "SUMMARY_POINTS",
    "HistoryStream",
    "history_columns",
    "point_figures",
    "print_report",
    "scenario_inputs",
    "summarise",
    "write_files",
]

#: Points listed one by one in summary.json (every point is in points.csv).
SUMMARY_POINTS = 100
#: Rows a streamed run keeps in memory for the plots and the console report (the
#: recorded rows are thinned evenly beyond it; history.csv has every recorded row).
PLOT_ROWS = 4000

#: Units of the points.csv columns (per-segment columns ``segment_<i>_...`` are added).
POINT_UNITS: dict[str, str] = {
    "point": "-",
    "peak_friction_ratio": "-",
    "peak_step": "-",
    "peak_time": "s",
    "peak_slip_distance": "m",
    "final_time": "s",
    "final_slip_1": "m",
    "final_slip_2": "m",
    "final_approach": "m",
    "final_traction_1": "Pa",
    "final_traction_2": "Pa",
    "final_traction_n": "Pa",
    "final_friction_ratio": "-",
    "final_F": "-",
    "final_R": "-",
    "final_plastic_slip": "m",
    "final_plastic_work": "J/m^2",
    "path_length": "m",
}


#: Lines of CSV formatted at a time (bounds the text and string lists held in memory).
CSV_BLOCK = 65536
_ROW_KEYS = ("step", "segment", "kind", "substeps", "solves")


def _sub_chunk(chunk: dict[str, np.ndarray], rows: slice, points: slice) -> dict[str, np.ndarray]:
    """Some rows and points of a chunk of recorded rows."""
    out = {}
    for key, value in chunk.items():
        if key in _ROW_KEYS:
            out[key] = value[rows]
        elif key == "point":
            out[key] = value[points]
        else:
            out[key] = value[rows, points]
    return out


class HistoryStream(Closing):
    """A recording sink that appends the recorded rows to the history file as they come.

    Use as a context manager around the run; ``rows`` counts the data rows written. The
    file is plain CSV (see :mod:`frictionlab.io.tables`), or Parquet when ``path`` ends
    in ``.parquet`` (one row group per chunk, :mod:`frictionlab.io.parquet`): it is not
    replaced atomically itself, so write it into an output set's staging directory.
    """

    def __init__(
        self, path: str | os.PathLike[str], cone: bool = True, extra: dict[str, str] | None = None
    ) -> None:
        self.path = Path(path)
        self.units = history_units(None, cone)
        self.extra = tuple(extra or ())
        self.units.update(extra or {})
        self.rows = 0
        self._parquet = (
            ParquetStream(self.path, self.units) if self.path.suffix == ".parquet" else None
        )
        self._file = open(self.path, "wb") if self._parquet is None else None  # noqa: SIM115

    def __call__(self, chunk: dict[str, np.ndarray]) -> None:
        rows, m = chunk["time"].shape
        per = max(1, CSV_BLOCK // m)  # format at most about CSV_BLOCK lines at a time
        for r0 in range(0, rows, per):
            for p0 in range(0, m, CSV_BLOCK):
                self._write(_sub_chunk(chunk, slice(r0, r0 + per), slice(p0, p0 + CSV_BLOCK)))

    def _write(self, chunk: dict[str, np.ndarray]) -> None:
        cols = chunk_columns(chunk, self.extra)
        if self._parquet is not None:
            self._parquet.write(cols)
        else:
            assert self._file is not None
            write_csv(self._file, cols, self.units, header=not self.rows)
        self.rows += len(cols["step"])

    def close(self) -> None:
        if self._parquet is not None:
            self._parquet.close()
        else:
            assert self._file is not None
            self._file.close()


def point_figures(history: History) -> dict[str, np.ndarray]:
    """(N,) per-point figures over every step: peaks, final values, path length.

    From the run's running figures when the history has them (every step and every
    point, whatever was recorded), otherwise from its rows.
    """
    st = history.stats
    if st is not None:
        fs = history.final_state
        n = st.time.shape[0]
        return {
            "point": np.arange(1, n + 1),
            "peak_friction_ratio": st.peak_friction_ratio,
            "peak_step": st.peak_step,
            "peak_time": st.peak_time,
            "peak_slip_distance": st.peak_path_length,
            "final_time": st.time,
            **_parts("final_slip", st.slip, "12"),
            "final_approach": st.approach,
            **_parts("final_traction", fs.traction, "12n"),
            "final_friction_ratio": st.friction_ratio,
            "final_F": fs.F,
            "final_R": fs.R,
            "final_plastic_slip": fs.plastic_slip,
            "final_plastic_work": st.plastic_work,
            "path_length": st.path_length,
        }
    ratios, paths = history.friction_ratio, history.path_length
    k = np.argmax(ratios, axis=0)
    cols = np.arange(history.n_points)
    return {
        "point": history.point_numbers,
        "peak_friction_ratio": ratios[k, cols],
        "peak_step": history.steps[k],
        "peak_time": history.time[k, cols],
        "peak_slip_distance": paths[k, cols],
        "final_time": history.time[-1],
        **_parts("final_slip", history.slip[-1], "12"),
        "final_approach": history.approach[-1],
        **_parts("final_traction", history.traction[-1], "12n"),
        "final_friction_ratio": ratios[-1],
        "final_F": history.F[-1],
        "final_R": history.R[-1],
        "final_plastic_slip": history.plastic_slip[-1],
        "final_plastic_work": history.plastic_work[-1],
        "path_length": paths[-1],
    }


def _parts(name: str, values: np.ndarray, suffixes: str) -> dict[str, np.ndarray]:
    """The columns ``name_<suffix>`` of the (N, k) ``values``, one per suffix."""
    return {f"{name}_{s}": values[:, k] for k, s in enumerate(suffixes)}


def _point_summary(fig: dict[str, np.ndarray], i: int, label: str) -> dict[str, Any]:
    """Peak and final values of point ``i`` (0-based row of ``fig``)."""
    return {
        "point": int(fig["point"][i]),
        "label": label,
        "peak": {
            "friction_ratio": float(fig["peak_friction_ratio"][i]),
            "step": int(fig["peak_step"][i]),
            "time": float(fig["peak_time"][i]),
            "slip_distance": float(fig["peak_slip_distance"][i]),
        },
        "final": {
            "time": float(fig["final_time"][i]),
            "slip": [float(fig["final_slip_1"][i]), float(fig["final_slip_2"][i])],
            "approach": float(fig["final_approach"][i]),
            "traction": [
                float(fig["final_traction_1"][i]),
                float(fig["final_traction_2"][i]),
                float(fig["final_traction_n"][i]),
            ],
            "friction_ratio": float(fig["final_friction_ratio"][i]),
            "F": float(fig["final_F"][i]),
            "R": float(fig["final_R"][i]),
            "plastic_slip": float(fig["final_plastic_slip"][i]),
            "plastic_work": float(fig["final_plastic_work"][i]),
            "dissipation": float(fig["final_plastic_work"][i]),
            "path_length": float(fig["path_length"][i]),
        },
    }


def _compact(value: Any) -> Any:
    """JSON for a per-point value: the list up to SUMMARY_POINTS entries, else min/mean/max."""
    if isinstance(value, np.ndarray):
        if value.shape and value.shape[0] > SUMMARY_POINTS and value.dtype.kind in "fiub":
            return _aggregate(value)
        return value.tolist()
    return value


def _aggregate(values: np.ndarray) -> dict[str, Any]:
    v = np.asarray(values, dtype=np.float64)
    return {
        "min": float(v.min()),
        "mean": float(v.mean()),
        "max": float(v.max()),
        "per_point": "points.csv",
    }


def _segment_figures(history: History, seg: Any) -> dict[str, np.ndarray]:
    """(N,) start, peak (start included) and final friction ratio, final F and R."""
    st = seg.stats
    if st is not None and st.final_F is not None:
        return {
            "start_friction_ratio": st.start_friction_ratio,
            "peak_friction_ratio": np.maximum(st.start_friction_ratio, st.peak_friction_ratio),
            "final_friction_ratio": st.final_friction_ratio,
            "final_F": st.final_F,
            "final_R": st.final_R,
        }
    ratio = history.friction_ratio[seg.rows]
    return {
        "start_friction_ratio": ratio[0],
        "peak_friction_ratio": ratio.max(axis=0),
        "final_friction_ratio": ratio[-1],
        "final_F": history.F[seg.last_row],
        "final_R": history.R[seg.last_row],
    }


def _segment_summary(history: History, seg: Any) -> dict[str, Any]:
    fig = _segment_figures(history, seg)
    steps = history.steps
    first, last = (
        (seg.stats.first_step, seg.stats.last_step)
        if seg.stats is not None
        else (int(steps[seg.first_row]), int(steps[seg.last_row]))
    )
    return {
        "index": seg.index,
        "kind": seg.kind,
        "first_step": int(first),
        "last_step": int(last),
        "resolved": {k: _compact(v) for k, v in seg.resolved.items()},
        **{k: _compact(np.asarray(v)) for k, v in fig.items()},
    }


def summarise(
    scenario: Scenario,
    history: History,
    elapsed: float,
    outputs: list[str],
    healing: Healing | None = None,
    recorded_rows: int | None = None,
) -> dict[str, Any]:
    """The content of ``summary.json`` (bounded size: per-point values beyond
    :data:`SUMMARY_POINTS` points are given as min/mean/max, every point is in points.csv).
    """
    fig = point_figures(history)
    n = int(fig["point"].size)
    labels = list(scenario.labels) + [""] * n
    listed = min(n, SUMMARY_POINTS)
    steps = history.stats.steps if history.stats is not None else int(history.steps[-1])
    out: dict[str, Any] = {
        "frictionlab": __version__,
        "scenario": scenario.source,
        "title": scenario.title,
        "success": history.success,
        "message": history.message,
        "warnings": list(scenario.warnings) + list(history.warnings),
        "n_points": n,
        "steps": steps,
        "recorded": {
            "every": scenario.output.every,
            "points": "all" if scenario.output.points is None else list(scenario.output.points),
            "rows": history.n_rows if recorded_rows is None else recorded_rows,
        },
        "inputs": scenario.inputs,
        "aggregate": {
            key: _aggregate(fig[key])
            for key in (
                "peak_friction_ratio",
                "final_friction_ratio",
                "path_length",
                "final_plastic_work",
            )
        },
        "points_listed": listed,
        "points": [_point_summary(fig, i, labels[i]) for i in range(listed)],
        "segments": [_segment_summary(history, seg) for seg in history.segments],
        "work": dict(history.work),
        "elapsed_seconds": round(elapsed, 3),
        "outputs": outputs,
    }
    if healing is not None:
        out["healing"] = healing.as_dict()
        records = out["healing"]["records"]
        out["healing"]["records"] = [r for r in records if r["point"] <= SUMMARY_POINTS]
        out["healing"]["records_file"] = "healing.csv"
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


def take_rows(history: History, rows: np.ndarray, points: np.ndarray | None = None) -> History:
    """A history of some rows (ascending indices) and points (0-based) of ``history``."""
    pts = np.arange(history.n_points) if points is None else points

    def sel(a: np.ndarray) -> np.ndarray:
        return a[rows][:, pts]

    segments = tuple(
        replace(
            seg,
            first_row=int(np.searchsorted(rows, seg.first_row)),
            last_row=max(int(np.searchsorted(rows, seg.last_row, side="right")) - 1, 0),
        )
        for seg in history.segments
    )
    base = history.points
    return History(
        time=sel(history.time), slip=sel(history.slip), approach=sel(history.approach),
        traction=sel(history.traction), F=sel(history.F), R=sel(history.R),
        plastic_slip=sel(history.plastic_slip), dissipation=sel(history.dissipation),
        status=sel(history.status), segment=history.segment[rows],
        substeps=history.substeps[rows], solves=history.solves[rows],
        iterations=sel(history.iterations), segments=segments, final_state=history.final_state,
        success=history.success, message=history.message, work=history.work,
        extra={k: sel(v) for k, v in history.extra.items()}, extra_units=history.extra_units,
        warnings=history.warnings, step=history.steps[rows],
        points=None if points is None else (pts if base is None else base[pts]),
        stats=history.stats, thinned=history.thinned or rows.size < history.n_rows,
    )  # fmt: skip


def select_rows(history: History, output: OutputOptions) -> History:
    """The rows and points ``[output]`` asks for, from a history that recorded everything.

    Used for the spring-slider (which records every step in memory): every k-th step
    and the last one, the chosen points.
    """
    if output.every == 1 and output.points is None:
        return history
    rows = np.arange(history.n_rows)
    keep = rows[(rows % output.every == 0) | (rows == history.n_rows - 1)]
    pts = None if output.points is None else np.asarray(output.points, dtype=np.int64) - 1
    out = take_rows(history, keep, pts)
    return replace(out, thinned=False)


def plot_rows(history: History, limit: int = PLOT_ROWS) -> History:
    """At most about ``limit`` evenly spread rows of ``history`` (segment ends kept)."""
    if history.n_rows <= limit:
        return history
    spread = np.linspace(0, history.n_rows - 1, limit).round().astype(np.int64)
    ends = [r for seg in history.segments for r in (seg.first_row - 1, seg.last_row)]
    return take_rows(history, np.unique(np.concatenate([spread, np.asarray(ends, np.int64)])))


def write_files(
    out: Path,
    scenario: Scenario,
    history: History,
    plots: bool,
    streamed: HistoryStream | None,
    healing: Healing | None,
) -> list[Path]:
    """Write history.csv (unless ``streamed`` wrote it during the run), points.csv,
    healing.csv and the plots; return the paths (summary.json is written after them).

    ``streamed``: the :class:`HistoryStream` that already wrote history.csv during the
    run (``history`` then holds the rows kept in memory, for the plots).
    """
    written: list[Path] = []
    if streamed is not None:
        written.append(streamed.path)
    else:
        chosen = select_rows(history, scenario.output)
        cols, units = history_columns(chosen, cone=scenario.params.is_cone)
        path = out / scenario.output.history_name
        write = write_parquet_atomic if path.suffix == ".parquet" else write_csv_atomic
        written.append(write(path, cols, units))
    written.append(_write_points(out, history, scenario.params.is_cone))
    if len(history.peaks):
        written.append(_write_peaks(out, history))
    if healing is not None:
        written.append(_write_healing(out, healing))
    if plots and history.n_rows > 1:
        written.extend(_plots(out, scenario, history))
        if healing is not None:
            written.append(_plot_healing(out, scenario, healing))
    return written


def _write_points(out: Path, history: History, cone: bool) -> Path:
    """points.csv: one row per point, the figures over every step (and per segment)."""
    cols = dict(point_figures(history))
    units = dict(POINT_UNITS)
    f_unit = "-" if cone else "Pa"
    units["final_F"] = f_unit
    for seg in history.segments:
        for key, values in _segment_figures(history, seg).items():
            name = f"segment_{seg.index}_{key}"
            cols[name] = np.asarray(values)
            units[name] = f_unit if key == "final_F" else "-"
    return write_csv_atomic(out / "points.csv", cols, units)  # in blocks: bounded memory


def _write_peaks(out: Path, history: History) -> Path:
    """peaks.csv: each segment peak located between steps (``[run] peak_accuracy``)."""
    pk = history.peaks
    cols = {
        "segment": pk.segment, "point": pk.point, "step": pk.step, "offset": pk.offset,
        "time": pk.time, "slip_1": pk.slip[:, 0], "slip_2": pk.slip[:, 1],
        "path_length": pk.path_length, "friction_ratio": pk.friction_ratio,
        "sampled_friction_ratio": pk.sampled_friction_ratio,
    }  # fmt: skip
    units = {"segment": "-", "point": "-", "step": "-", "offset": "steps", "time": "s",
             "slip_1": "m", "slip_2": "m", "path_length": "m", "friction_ratio": "-",
             "sampled_friction_ratio": "-"}  # fmt: skip
    comment = (
        "segment peaks of the friction ratio located between steps: offset is the position "
        "in steps after step - 1;\nsampled_friction_ratio is the largest recorded step it "
        "replaces (history.csv keeps the step grid)"
    )
    return write_csv_atomic(out / "peaks.csv", cols, units, comment)


def scenario_inputs(scenario: Scenario) -> list[Path]:
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
    rec = healing.recovery
    if rec is not None:
        comment += (f"\nthe law's recovery form: restart peak = A - (A - mu_0) exp(-t_h/tau) with "
                    f"A = {rec.A!r}, mu_0 = {rec.mu_0!r}, tau = {rec.tau!r} s")  # fmt: skip
    comment += "\n" + healing.comparison()
    return write_csv_atomic(out / "healing.csv", cols, units, comment)


def _recovery_curve(healing: Healing) -> tuple[float, float, float, float] | None:
    """The recovery form for healing.png when every hold starts from one friction ratio."""
    rec = healing.recovery
    before = {r.friction_before for r in healing.records}
    if rec is None or len(before) != 1:
        return None
    return rec.A, rec.mu_0, rec.tau, before.pop()


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
        recovery=_recovery_curve(healing),
    )
    ax.set_title(scenario.title, fontsize=9)
    return save_figure(ax.figure, out / "healing.png")  # type: ignore[arg-type]


def _plot_note(history: History, scenario: Scenario) -> str:
    """What the plotted rows and points are, for the figure title."""
    notes = []
    if history.thinned:
        notes.append(f"{history.n_rows} evenly spread rows of {history.steps[-1]} steps")
    elif scenario.output.every > 1:
        notes.append(f"every {scenario.output.every}th step")
    recorded = scenario.output.recorded_points(scenario.n_points)
    if history.n_points < recorded:
        notes.append(f"{history.n_points} of {recorded} points")
    return f"\n(plotted: {'; '.join(notes)})" if notes else ""


def _plots(out: Path, scenario: Scenario, full: History) -> list[Path]:
    from frictionlab.plotting.law import (
        plot_friction,
        plot_spring_slider,
        plot_traction_path,
        save_figure,
    )

    history = plot_rows(full)
    paths = []
    labels = tuple(
        scenario.labels[p - 1] if p - 1 < len(scenario.labels) else f"point {p}"
        for p in history.point_numbers
    )
    title = scenario.title + _plot_note(history, scenario)
    if scenario.kind == "spring_slider":
        fig = plot_spring_slider(history, labels)
        fig.suptitle(title)
        paths.append(save_figure(fig, out / "friction.png"))
    else:
        paths.append(save_figure(plot_friction(history, labels, title), out / "friction.png"))
    if not history.is_planar:
        ax = plot_traction_path(history, scenario.params, labels)
        ax.set_title(title, fontsize=9)
        paths.append(save_figure(ax.figure, out / "traction_path.png"))  # type: ignore[arg-type]
    return paths


def print_report(
    labels: tuple[str, ...], history: History, elapsed: float, mu_s: float | None = None
) -> None:
    """The terminal lines of a run: peak and final friction per point, restart peaks (and,
    with the law's ``mu_s``, what it is and is not)."""
    fig = point_figures(history)
    peak, final = fig["peak_friction_ratio"], fig["final_friction_ratio"]
    n = peak.size
    steps = history.stats.steps if history.stats is not None else history.n_rows - 1
    print(f"{n} point(s), {steps} steps in {elapsed:.2f} s "
          f"({history.work['substeps']} substeps, {history.work['solves']} solves)")  # fmt: skip
    print(f"{'point':>5} {'peak |f_t|/f_n':>15} {'final |f_t|/f_n':>16}  label")
    for i in range(min(n, 12)):
        label = labels[i] if i < len(labels) else ""
        print(f"{i + 1:>5} {peak[i]:>15.5f} {final[i]:>16.5f}  {label}")
    if n > 12:
        print(f"  ... {n - 12} more points in points.csv")
    healing = healing_analysis(history)
    if healing is None:
        return
    print(f"restart peaks after holds ({len(healing.records)}; all in healing.csv):")
    print(f"{'point':>5} {'hold [s]':>10} {'before':>9} {'peak':>9} {'delta mu':>9}")
    for r in healing.records[:12]:
        print(f"{r.point:>5} {r.hold_time:>10.4g} {r.friction_before:>9.5f} "
              f"{r.restart_peak:>9.5f} {r.delta_mu:>9.5f}")  # fmt: skip
    if healing.rate_per_decade is not None:
        print(f"healing rate d(delta mu)/d log10(t_h) = {healing.rate_per_decade:.5g} per decade")
    rec = healing.recovery
    if rec is not None:
        print(f"the law's recovery form: A = {rec.A:.5g}, mu_0 = {rec.mu_0:.5g}, "
              f"tau = {rec.tau:.4g} s")  # fmt: skip
    print(healing.comparison())
    if mu_s is not None:
        print(healing.static_note(mu_s))
