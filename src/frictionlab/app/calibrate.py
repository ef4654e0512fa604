"""The calibration workflow: fit, profiles, then ``fitted.toml``, ``summary.json``, figures.

``fitted.toml`` is a simulate scenario (the fitted law with the first curve's initial
contact and programme) that ``frictionlab simulate`` runs as it is; further curves get
``fitted_2.toml``, ... ``summary.json`` (``fit.json``: its deprecated copy) holds
``parameters`` (name -> value, stderr, ...), the ``correlation`` matrix, ``cost``,
``n_points``, the identifiability in words and the profiles. Every file is written
atomically, the summary last. :data:`CALIBRATE` is the workflow of ``frictionlab calibrate``.
"""

from __future__ import annotations

import argparse
import os
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory
from frictionlab._version import __version__
from frictionlab.app.outputs import WorkflowBase, write_outputs
from frictionlab.calibration import (
    CORRELATION_LIMIT,
    RELATIVE_STDERR_LIMIT,
    FitResult,
    Profile,
)
from frictionlab.calibration.fit import parameter_unit
from frictionlab.io.atomic import write_text_atomic
from frictionlab.io.config import format_toml
from frictionlab.io.report import Report, Section, format_value
from frictionlab.io.tables import write_csv_atomic
from frictionlab.schema.calibrate import CalibrationConfig
from frictionlab.schema.scenario import law_table

__all__ = ["CALIBRATE", "CalibrationRun", "identifiability", "parameter_unit", "write_calibration"]


@dataclass(frozen=True)
class CalibrationRun:
    """What ``frictionlab calibrate`` computed: the fit, the profiles and the start's model."""

    config: CalibrationConfig
    fit: FitResult
    start_models: tuple[np.ndarray, ...]
    profiles: dict[str, Profile] = field(default_factory=dict)


def _finite(v: float) -> float | None:
    return float(v) if np.isfinite(v) else None


def identifiability(fit: FitResult, profiles: dict[str, Profile]) -> list[str]:
    """Sentences on which parameters the data pin down and which they do not."""
    out = []
    for a, b, c in fit.strong_correlations():
        way = "raising" if c > 0 else "lowering"
        rel_a = fit.relative_stderr[fit.names.index(a)]
        rel_b = fit.relative_stderr[fit.names.index(b)]
        still = (
            f" Both are still determined to {rel_a:.1%} and {rel_b:.1%} by these data."
            if max(rel_a, rel_b) <= RELATIVE_STDERR_LIMIT
            else ""
        )
        out.append(
            f"{a} and {b} are strongly correlated (r = {c:+.2f}): the data fix a combination "
            f"of the two better than either one, so raising one can be compensated by {way} "
            f"the other.{still}"
        )
    missing = fit.not_identified()
    for j, name in enumerate(fit.names):
        rel = fit.relative_stderr[j]
        if name in missing:
            if not np.isfinite(fit.stderr[j]):
                why = "the Jacobian has no component along it"
            elif name in profiles and None in profiles[name].interval:
                why = "its 95 % profile interval is open"
            else:
                why = "it ran to an end of its bounds"
            lo, hi = fit.space.lower[j], fit.space.upper[j]
            out.append(
                f"{name} is not identified by these data ({why}): its value "
                f"{fit.values[j]:.4g} is arbitrary within what they allow (bounds "
                f"[{lo:.3g}, {hi:.3g}]); fix it in [law] or add data that depend on it."
            )
        elif rel > RELATIVE_STDERR_LIMIT:
            out.append(
                f"{name} is poorly identified: its standard error is {rel:.0%} of its value."
            )
        if name in profiles:
            low, high = profiles[name].interval
            lo = f"{low:.4g}" if low is not None else "open (below the profiled range)"
            hi = f"{high:.4g}" if high is not None else "open (above the profiled range)"
            out.append(f"Profile likelihood of {name}: 95 % range from {lo} to {hi} "
                       f"(fitted {fit.values[j]:.4g}).")  # fmt: skip
    if not out:
        out.append(
            f"Every fitted parameter is well identified: relative standard errors below "
            f"{RELATIVE_STDERR_LIMIT:.0%} and correlations below {CORRELATION_LIMIT} in magnitude."
        )
    return out


def fit_summary(run: CalibrationRun, outputs: list[str]) -> dict[str, Any]:
    """The content of ``fit.json``."""
    fit, cfg = run.fit, run.config
    cone = fit.params.is_cone
    missing = fit.not_identified()
    params = {}
    for j, name in enumerate(fit.names):
        params[name] = {
            "value": float(fit.values[j]),
            "stderr": _finite(fit.stderr[j]),
            "relative_stderr": _finite(fit.relative_stderr[j]),
            "start": float(fit.start[j]),
            "bounds": [_finite(fit.space.lower[j]), _finite(fit.space.upper[j])],
            "fitted_as": "ln" if fit.space.log[j] else "linear",
            "unit": parameter_unit(name, cone),
            "identified": name not in missing,
        }
    corr = [[_finite(v) for v in row] for row in fit.correlation]
    curves = []
    for k, (c, r, echo) in enumerate(zip(cfg.curves, fit.residuals, cfg.data_echo, strict=True)):
        offset = fit.offsets[k] if fit.offsets else None
        offset_se = fit.offset_stderr[k] if fit.offset_stderr else None
        curves.append({
            "file": echo["file"], "samples": c.n_samples, "weight": c.weight,
            "units": echo["units"], "rms_residual": float(np.sqrt(np.mean(r**2))),
            "max_abs_residual": float(np.max(np.abs(r))), "time_offset": c.time_offset,
            "time_offset_fitted": offset is not None,
            "time_offset_stderr": None if offset_se is None else _finite(offset_se),
            "time_offset_bounds": echo.get("time_offset_bounds"),
        })  # fmt: skip
    profiles = {
        name: {
            "values": p.values.tolist(),
            "delta_chi2": [_finite(v) for v in p.delta_chi2],
            "interval_95": [p.interval[0], p.interval[1]],
        }
        for name, p in run.profiles.items()
    }
    return {
        "frictionlab": __version__,
        "config": cfg.source,
        "title": cfg.title,
        "success": fit.success,
        "message": fit.message,
        "parameters": params,
        "correlation": {"names": list(fit.names), "matrix": corr},
        "cost": fit.cost,
        "n_points": fit.n_points,
        "dof": fit.dof,
        "residual_std": _finite(np.sqrt(fit.residual_variance)),
        "poorly_identified": fit.poorly_identified(),
        "not_identified": missing,
        "identifiability": identifiability(fit, run.profiles),
        "profiles": profiles,
        "curves": curves,
        "work": {
            "nfev": fit.nfev,
            "njev": fit.njev,
            "driver_runs": fit.runs,
            "seconds": round(fit.seconds, 3),
        },
        "outputs": outputs,
    }


def _program_tables(echo: dict[str, Any], base: Path) -> list[dict[str, Any]]:
    """The curve's programme tables with table files made absolute (run from anywhere)."""
    out = []
    for seg in echo["program"]:
        seg = dict(seg)
        if seg.get("kind") == "table" and not Path(seg["file"]).is_absolute():
            seg["file"] = str((base / seg["file"]).resolve())
        out.append(seg)
    return out


def fitted_scenario(run: CalibrationRun, k: int, base: Path) -> str:
    """The TOML text of the simulate scenario of curve ``k`` with the fitted law."""
    echo = run.config.data_echo[k]
    data = {
        "title": f"Fitted law: {echo['file']}",
        "description": (
            f"The law fitted by frictionlab calibrate ({', '.join(run.fit.names)}) run "
            f"through the loading programme of {echo['file']}."
        ),
        "law": law_table(run.fit.params),
        "initial": echo["initial"],
        "program": _program_tables(echo, base),
    }
    return format_toml(data)


def _curve_columns(run: CalibrationRun) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    names: tuple[str, ...] = (
        "curve",
        "time",
        "data",
        "model",
        "residual",
        "weight",
        "confidence",
        "prediction",
    )
    cols: dict[str, list[Any]] = {k: [] for k in names}
    bands = run.fit.bands(run.config.band_level)
    for i, (c, m, (conf, pred)) in enumerate(
        zip(run.config.curves, run.fit.models, bands, strict=True)
    ):
        cols["curve"].append(np.full(c.n_samples, i + 1))
        cols["time"].append(c.time)
        cols["data"].append(c.friction_ratio)
        cols["model"].append(m)
        cols["residual"].append(m - c.friction_ratio)
        cols["weight"].append(run.fit.weights[i])
        # half-widths of the bands at [fit] band_level; none (0) where the weight is 0
        cols["confidence"].append(np.nan_to_num(conf, nan=0.0))
        cols["prediction"].append(np.nan_to_num(pred, nan=0.0))
    arrays = {k: np.concatenate(v) for k, v in cols.items()}
    if not np.all(np.isfinite(run.fit.stderr)):  # no band: a direction is not determined
        del arrays["confidence"], arrays["prediction"]
        names = names[:-2]
    units = dict.fromkeys(names, "-") | {"time": "s"}
    return arrays, units


def _files(out_dir: str | os.PathLike[str], run: CalibrationRun, base: Path) -> list[Path]:
    """Write every output but the summary into ``out_dir``; returns the paths written."""
    from frictionlab.plotting.calibration import plot_correlation, plot_curve_fit, plot_profile
    from frictionlab.plotting.law import save_figure

    out = Path(out_dir)
    fit, cfg = run.fit, run.config
    written: list[Path] = []
    for k in range(len(cfg.curves)):
        name = "fitted.toml" if k == 0 else f"fitted_{k + 1}.toml"
        written.append(write_text_atomic(out / name, fitted_scenario(run, k, base)))
    cols, units = _curve_columns(run)
    comment = (
        "frictionlab calibrate: data and fitted model per curve; confidence and prediction: "
        f"half-widths of the {cfg.band_level:.0%} bands of the model and of a new measurement "
        "(0 where the sample's weight is 0: no band there)"
    )
    if "confidence" not in cols:
        comment = (f"frictionlab calibrate: data and fitted model per curve; no bands: "
                   f"{', '.join(fit.not_identified())} not determined by the data")  # fmt: skip
    written.append(write_csv_atomic(out / "curves.csv", cols, units, comment))
    report = Report(
        cfg.title or "Calibration of the subloading-friction law",
        f"{len(cfg.curves)} curve(s), {fit.n_points} samples; fitted "
        f"{', '.join(fit.names)} by bounded least squares with the driver in the loop.",
    )
    sec = report.add_section(Section("Fitted parameters", anchor="parameters"))
    cone = fit.params.is_cone
    for j, name in enumerate(fit.names):
        se = fit.stderr[j]
        text = f"{fit.values[j]:.6g} ± {se:.3g}" if np.isfinite(se) else f"{fit.values[j]:.6g} ± ∞"
        sec.parameters.append(
            (name, f"{text} (start {fit.start[j]:.4g})", parameter_unit(name, cone))
        )
    fixed = [
        f"{k} = {format_value(v)}"
        for k, v in cfg.law_given.items()
        if k not in fit.names and k != "surface"
    ]
    if fixed:
        sec.notes.append("Fixed at their [law] values: " + ", ".join(fixed) + ".")
    sec.notes.append(
        f"Cost {fit.cost:.6g} (half the weighted sum of squared residuals), residual standard "
        f"deviation {np.sqrt(fit.residual_variance):.3g} in friction ratio, {fit.nfev} "
        f"evaluations, {fit.runs} driver runs, {fit.seconds:.2f} s. Optimiser: {fit.message}"
    )
    data_sec = report.add_section(Section("Data and model", anchor="curves"))
    for k, (c, m) in enumerate(zip(cfg.curves, fit.models, strict=True)):
        rel = f"curve_{k + 1}.png"
        band = fit.bands(cfg.band_level)[k][0]
        written.append(save_figure(plot_curve_fit(c, m, run.start_models[k], band), out / rel))
        rms = float(np.sqrt(np.mean((m - c.friction_ratio) ** 2)))
        data_sec.add_figure(
            rel,
            f"{c.name}: measured friction ratio (dots), the start law (dashed) and the fitted "
            f"law (line) with its {cfg.band_level:.0%} confidence band, one panel per sliding "
            f"segment (holds left out); residuals below (rms {rms:.3g}).",
        )
    unc = report.add_section(Section("Uncertainty and identifiability", anchor="uncertainty"))
    unc.intro = (
        "Standard errors from the linearisation at the optimum, cov = s^2 (J^T J)^-1 with the "
        "residual variance s^2, mapped from the fitted space (ln x for u, kappa, xi, alpha) by "
        "the delta method. They assume independent residuals of equal variance."
    )
    unc.notes.extend(identifiability(fit, run.profiles))
    if len(fit.names) > 1:
        ax = plot_correlation(fit.names, fit.correlation)
        written.append(save_figure(ax.figure, out / "correlation.png"))  # type: ignore[arg-type]
        unc.add_figure("correlation.png", "Correlation matrix of the fitted parameters.")
    for name, prof in run.profiles.items():
        j = fit.names.index(name)
        ax = plot_profile(prof, float(fit.values[j]), float(fit.stderr[j]), bool(fit.space.log[j]))
        rel = f"profile_{name}.png"
        written.append(save_figure(ax.figure, out / rel))  # type: ignore[arg-type]
        unc.add_figure(
            rel,
            f"Profile likelihood of {name}: delta chi^2 with every other parameter re-fitted "
            "(dots) and the linearised parabola (dashed).",
        )
    written.append(report.write(out / "report.html"))
    return written


def _inputs(cfg: CalibrationConfig) -> list[Path]:
    """The config file, then the data files it names (relative to it)."""
    if not cfg.source:
        return []
    return [Path(cfg.source)] + [Path(cfg.source).parent / e["file"] for e in cfg.data_echo]


class Calibrate(WorkflowBase):
    """``frictionlab calibrate CONFIG.toml --out DIR`` (:mod:`frictionlab.commands.calibrate`)."""

    name = "calibrate"
    #: fit.json: the summary's name before; a copy of summary.json for one release.
    aliases: tuple[str, ...] = ("fit.json",)

    def parse(self, args: argparse.Namespace, out: Path) -> tuple[CalibrationConfig, Path]:
        from frictionlab.app.budget import check_calibration
        from frictionlab.schema.calibrate import load_calibrate

        cfg = load_calibrate(args.config, args.set)
        check_calibration(cfg)  # memory and time, before the fit starts
        return cfg, Path(args.config)

    def run(self, job: Any, progress: ProgressFactory, staging: Path) -> CalibrationRun:
        from frictionlab.calibration import evaluate_columns, fit_law, profile_likelihood

        cfg, path = job
        x0 = np.array([[float(getattr(cfg.params, n))] for n in cfg.names])
        start_models = tuple(evaluate_columns(cfg.params, cfg.names, x0, c)[0] for c in cfg.curves)
        with progress(f"calibrate {path.name}") as update:
            fit = fit_law(
                cfg.params, cfg.curves, cfg.names, cfg.bounds,
                max_nfev=cfg.max_evaluations, progress=update, starts=cfg.starts, seed=cfg.seed,
            )  # fmt: skip
        profiles = {}
        if cfg.profile:
            for name in fit.worst_identified(cfg.profile_max):
                with progress(f"profile {name}") as update:
                    profiles[name] = profile_likelihood(
                        fit, cfg.curves, name, points=cfg.profile_points, progress=update
                    )
        fit = replace(fit, profiles=profiles)  # not_identified() reads the profiles
        # the outputs show each curve at its fitted offset, now fixed
        curves = tuple(
            c if o is None else replace(c, time_offset=o, offset_bounds=None)
            for c, o in zip(cfg.curves, fit.offsets, strict=True)
        )
        return CalibrationRun(replace(cfg, curves=curves), fit, start_models, profiles)

    def files(self, job: Any, result: CalibrationRun, out: Path, plots: bool) -> list[Path]:
        return _files(out, result, job[1].parent)

    def summary(
        self, job: Any, result: CalibrationRun, files: list[str], seconds: float
    ) -> dict[str, Any]:
        return fit_summary(result, files)

    def inputs(self, job: Any) -> list[Path]:
        return _inputs(job[0])

    def report(self, job: Any, result: CalibrationRun, seconds: float, written: list[Path]) -> None:
        fit, cfg = result.fit, result.config
        print(f"frictionlab calibrate: {len(cfg.curves)} curve(s), {fit.n_points} samples, "
              f"{fit.nfev} evaluations ({fit.runs} driver runs) in {seconds:.2f} s; "
              f"{fit.message}")  # fmt: skip
        print(f"{'parameter':>10} {'start':>12} {'fitted':>12} {'stderr':>10} {'rel':>7}")
        missing = fit.not_identified()
        for j, name in enumerate(fit.names):
            se, rel = fit.stderr[j], fit.relative_stderr[j]
            flag = "  not identified" if name in missing else ""
            print(f"{name:>10} {fit.start[j]:>12.5g} {fit.values[j]:>12.6g} {se:>10.3g} "
                  f"{rel:>7.1%}{flag}")  # fmt: skip
        for c, offset, se in zip(cfg.curves, fit.offsets, fit.offset_stderr, strict=True):
            if offset is not None:
                print(f"{c.name}: time offset fitted {offset:.6g} s ± {se:.3g} s")
        print(f"residual std {np.sqrt(fit.residual_variance):.3g} (friction ratio)")
        for line in identifiability(fit, result.profiles):
            print("  " + line)
        super().report(job, result, seconds, written)


#: The calibration workflow.
CALIBRATE = Calibrate()


def write_calibration(
    out_dir: str | os.PathLike[str], run: CalibrationRun, base: Path
) -> list[Path]:
    """Write every output into ``out_dir`` (summary.json and fit.json last)."""
    job = (run.config, base / "config.toml")
    return write_outputs(CALIBRATE, job, run, Path(out_dir), plots=True, seconds=0.0)
