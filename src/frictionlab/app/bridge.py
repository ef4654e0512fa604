"""The bridge run and its files: polar -> fit -> fitted law -> its scenario -> steady sliding.

:func:`run_bridge` computes everything ``frictionlab bridge`` reports, in memory;
:func:`write_bridge` then writes ``fitted_law.toml``, ``directions.csv``, ``bridge.png`` and
``summary.json`` (last, with ``bridge.json`` its deprecated copy), each atomically. The
steady-sliding check runs the very text of ``fitted_law.toml`` (parsed back like
``frictionlab simulate`` does), so a law that the bridge reports has run as written.
:data:`BRIDGE` is the workflow of ``frictionlab bridge``.
"""

from __future__ import annotations

import argparse
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory, no_progress
from frictionlab._version import __version__
from frictionlab.app.outputs import write_outputs
from frictionlab.app.simulate import run_scenario
from frictionlab.bridge import (
    AnisotropyFit,
    FittedLaw,
    fit_anisotropy,
    fitted_law,
    law_polar,
    relative_rotation_of,
    steady_coefficient,
    steady_distance,
)
from frictionlab.driver import History
from frictionlab.errors import FrictionlabError, InputError, ParameterError
from frictionlab.io.atomic import write_contents_atomic
from frictionlab.io.config import format_toml
from frictionlab.io.tables import format_csv
from frictionlab.roughness.lattice import FrictionPolar, friction_polar, merge_polars
from frictionlab.schema.bridge import BridgeScenario
from frictionlab.schema.scenario import law_table, parse_scenario
from frictionlab.subloading import SubloadingParams

__all__ = ["BRIDGE", "FILES", "BridgeRun", "run_bridge", "write_bridge"]

#: The files of a bridge run, in the order they are written (the summary last; bridge.json
#: is its deprecated copy).
FILES = ("fitted_law.toml", "directions.csv", "bridge.png", "summary.json", "bridge.json")
#: Directions per lattice call (progress granularity).
_CHUNK = 6


@dataclass(frozen=True)
class BridgeRun:
    """Everything a bridge run reports (nothing written yet).

    ``closed`` and ``simulated`` are the fitted law's steady ``f_t/f_n`` at the check
    velocity (closed form and driver), ``difference`` their distance per direction;
    ``curve_deg``/``curve_fit`` a 1-degree curve of the fitted kinetic polar in the
    roughness units.
    """

    scenario: BridgeScenario
    source: Path
    polar: FrictionPolar
    fit: AnisotropyFit
    law: FittedLaw
    toml: str
    history: History
    closed: np.ndarray
    simulated: np.ndarray
    kinetic: np.ndarray
    difference: np.ndarray
    curve_deg: np.ndarray
    curve_fit: np.ndarray
    distance: float
    seconds: dict[str, float]

    @property
    def title(self) -> str:
        return self.scenario.title or self.source.name

    @property
    def check_passed(self) -> bool:
        return bool(self.difference.max() <= self.scenario.options.check_tolerance)


def run_bridge(
    scenario: BridgeScenario, source: Path, progress: ProgressFactory | None = None
) -> BridgeRun:
    """Polar, fit, fitted law and its steady-sliding check (module docstring).

    Raises :class:`~frictionlab.errors.FrictionlabError` (exit 1) when no valid law
    results or its check simulation fails; :class:`~frictionlab.errors.InputError` when
    the roughness input leaves mu undefined.
    """
    progress = progress or no_progress
    opts = scenario.options
    base = scenario.law
    fn = opts.normal_traction
    t0 = time.perf_counter()
    polar = _polar(scenario, progress)
    t1 = time.perf_counter()
    fit = fit_anisotropy(
        polar,
        fit=opts.fit,
        orthotropy=np.asarray(base.orthotropy),
        orthotropy_angle=float(base.orthotropy_angle),
        relative_rotation=relative_rotation_of(base, fn),
        tolerance=opts.tolerance,
        anisotropy_tolerance=opts.anisotropy_tolerance,
    )
    t2 = time.perf_counter()
    try:
        law = fitted_law(base, fit, scale=opts.scale, normal_traction=fn)
    except ParameterError as exc:
        raise FrictionlabError(f"the fitted anisotropy is not a valid law ({exc})") from None
    distance = opts.distance or steady_distance(law.params, fn)
    text = _fitted_scenario_text(scenario, source, law.params, fit, distance)
    try:
        runnable = parse_scenario(tomllib.loads(text), source="fitted_law.toml")
    except (InputError, ParameterError) as exc:
        raise FrictionlabError(
            f"the fitted law cannot run with the [bridge] settings: {exc}"
        ) from None
    with progress("bridge: steady sliding") as bar:
        history = run_scenario(runnable, progress=bar)
    if not history.success:
        raise FrictionlabError(f"steady sliding of the fitted law failed: {history.message}")
    t3 = time.perf_counter()
    simulated = history.traction[-1, :, :2] / history.traction[-1, :, 2:3]
    closed = law_polar(law.params, fit.beta_deg, opts.velocity, fn)
    curve_deg = np.arange(0.0, 360.0, 1.0)
    return BridgeRun(
        scenario=scenario,
        source=source,
        polar=polar,
        fit=fit,
        law=law,
        toml=text,
        history=history,
        closed=closed,
        simulated=simulated,
        kinetic=law_polar(law.params, fit.beta_deg, None, fn),
        difference=np.hypot(*(simulated - closed).T),
        curve_deg=curve_deg,
        curve_fit=law_polar(law.params, curve_deg, None, fn) / law.factor,
        distance=float(distance),
        seconds={"polar": t1 - t0, "fit": t2 - t1, "check": t3 - t2},
    )


def _polar(scenario: BridgeScenario, progress: ProgressFactory) -> FrictionPolar:
    """The lattice polar over the scenario's directions, in chunks (for the progress bar)."""
    r = scenario.roughness
    directions = scenario.directions_deg
    parts = []
    with progress("bridge: mu(beta)") as bar:
        for start in range(0, directions.size, _CHUNK):
            chunk = directions[start : start + _CHUNK]
            parts.append(friction_polar(r.lower, r.upper, r.mu0, chunk, settings=r.settings))
            bar(min(start + _CHUNK, directions.size), directions.size)
    polar = merge_polars(*parts)
    if not np.all(polar.in_contact):
        beta = float(polar.beta_deg[int(np.argmin(polar.in_contact))])
        raise InputError(
            f"[sliding].load = {r.settings.load} compresses no spring at beta = {beta:g} deg, "
            "so mu is undefined there: allowed a load that keeps some spring compressed"
        )
    return polar


def _fitted_scenario_text(
    scenario: BridgeScenario,
    source: Path,
    params: SubloadingParams,
    fit: AnisotropyFit,
    distance: float,
) -> str:
    """fitted_law.toml: the fitted [law], f_n and a slide in every direction of the polar."""
    opts = scenario.options
    data = {
        "title": f"{scenario.title or source.stem}: law fitted by frictionlab bridge",
        "description": (
            "Steady sliding of the fitted law in every direction of the roughness polar "
            f"(one point per direction) at {opts.velocity:g} m/s."
        ),
        "law": law_table(params),
        "initial": {"normal_traction": opts.normal_traction},
        "program": [
            {
                "kind": "slide",
                "velocity": opts.velocity,
                "distance": distance,
                "direction_deg": [float(b) for b in fit.beta_deg],
                "steps": opts.steps,
            }
        ],
    }
    header = (
        f"# frictionlab {__version__} bridge: the subloading-friction law fitted to the "
        f"roughness polar of {source.name}\n"
        f"# fitted: {', '.join(fit.fitted_groups) or 'nothing'} (scale = '{opts.scale}'); "
        f"rms misfit {fit.rms_misfit:.6g} ({fit.relative_rms_misfit:.3%} of the mean "
        f"friction), max {fit.max_misfit:.6g}\n"
        "# run it with: frictionlab simulate fitted_law.toml --out DIR\n"
    )
    return header + format_toml(data)


def _xy(name: str, mu: np.ndarray) -> dict[str, np.ndarray]:
    """The columns ``<name>_x`` and ``<name>_y`` of friction vectors ``mu`` (n, 2)."""
    return {f"{name}_x": mu[:, 0], f"{name}_y": mu[:, 1]}


def directions_columns(run: BridgeRun) -> dict[str, np.ndarray]:
    """The columns of directions.csv (one row per direction of the polar)."""
    fit = run.fit
    return {
        "beta_deg": fit.beta_deg,
        **_xy("roughness_mu", fit.data),
        "roughness_mu": np.hypot(fit.data[:, 0], fit.data[:, 1]),
        **_xy("fit_mu", fit.fitted),
        "misfit": fit.misfit,
        **_xy("law_kinetic_mu", run.kinetic),
        **_xy("law_steady_mu", run.closed),
        **_xy("simulated_mu", run.simulated),
        "check_difference": run.difference,
    }


def summary(run: BridgeRun) -> dict[str, Any]:
    """bridge.json: the fitted anisotropy at the top, then the details."""
    sc, fit, law = run.scenario, run.fit, run.law
    opts = sc.options
    params = law.params
    r = sc.roughness
    return {
        "frictionlab_version": __version__,
        "command": "bridge",
        "scenario_file": str(run.source),
        "title": sc.title,
        "rotation": np.asarray(params.rotation).tolist(),
        "orthotropy": np.asarray(params.orthotropy).tolist(),
        "orthotropy_angle_deg": fit.orthotropy_angle_deg,
        "rms_misfit": fit.rms_misfit,
        "max_misfit": fit.max_misfit,
        "relative_rms_misfit": fit.relative_rms_misfit,
        "beta_at_max_misfit_deg": fit.beta_at_max_misfit_deg,
        "expressible": fit.expressible,
        "note": fit.note or None,
        "anisotropic_misfit": fit.anisotropic_misfit,
        "forward_backward_kept": fit.forward_backward_kept,
        "lateral_misfit": fit.lateral_misfit,
        "beta_at_lateral_misfit_deg": fit.beta_at_lateral_misfit_deg,
        "anisotropy_tolerance": fit.anisotropy_tolerance,
        "fit": {
            "fitted": list(fit.fitted_groups),
            "held": _held(sc.law, fit.fitted_groups),
            "matched": "friction vectors (mu_x, mu_y) per sliding direction against the law's "
            "kinetic steady traction ratio f_t/f_n",
            "kinetic_coefficient_roughness": fit.kinetic,
            "rotation_roughness": fit.rotation.tolist(),
            "relative_rotation": fit.relative_rotation.tolist(),
            "misfit_lobes": fit.lobes,
            "tolerance": fit.tolerance,
            "solver": {
                "success": fit.success,
                "message": fit.message,
                "nfev": fit.nfev,
                "cost": fit.cost,
            },
        },
        "law": {
            "scale": law.scale,
            "factor_law_over_roughness": law.factor,
            "kinetic_coefficient": law.kinetic_coefficient,
            "normal_traction_Pa": law.normal_traction,
            **({} if params.is_cone else {"M_1_M_2": _m_i(params)}),
            "table": law_table(params),
        },
        "roughness": {
            "mu0": r.mu0,
            "lower": r.lower.describe(),
            "upper": r.upper.describe(),
            "directions": int(run.polar.beta_deg.size),
            "step_deg": opts.step_deg,
            "lattice": r.settings.as_dict(),
        },
        "check": {
            "velocity_m_per_s": opts.velocity,
            "normal_traction_Pa": opts.normal_traction,
            "distance_m": run.distance,
            "steps": opts.steps,
            "steady_coefficient": steady_coefficient(params, opts.velocity, opts.normal_traction),
            "final_R_min": float(run.history.R[-1].min()),
            "max_abs_difference": float(run.difference.max()),
            "tolerance": opts.check_tolerance,
            "passed": run.check_passed,
        },
        "work": {
            "spring_station_evaluations": int(run.polar.spring_evaluations),
            **{f"seconds_{k}": round(v, 3) for k, v in run.seconds.items()},
            "check_steps": int(run.history.n_rows - 1),
        },
        "files": list(FILES),
    }


def _held(base: SubloadingParams, fitted: tuple[str, ...]) -> dict[str, Any]:
    """The anisotropy taken from [law] rather than fitted."""
    held: dict[str, Any] = {}
    if "orthotropy" not in fitted:
        held["orthotropy"] = np.asarray(base.orthotropy).tolist()
        held["orthotropy_angle_deg"] = float(np.degrees(base.orthotropy_angle))
    if "rotation" not in fitted:
        held["rotation"] = np.asarray(base.rotation).tolist()
    return held


def _m_i(params: SubloadingParams) -> list[float]:
    """(M_1, M_2) = M (C_1, C_2) of a closed surface (Eq 83)."""
    M = float(np.ravel(params.M)[0])
    return [M * float(c) for c in np.asarray(params.orthotropy)]


def _files(out: Path, run: BridgeRun) -> list[Path]:
    """Write the files of ``run`` but the summary into ``out``, each atomically."""
    from frictionlab.plotting.bridge import bridge_figure
    from frictionlab.plotting.roughness import figure_png_bytes

    columns = directions_columns(run)
    units = {k: "deg" if k == "beta_deg" else "-" for k in columns}
    header = (
        f"frictionlab {__version__} bridge: {run.title}\n"
        "roughness_*: the lattice's friction vector per unit normal load; fit_*: the fitted "
        "kinetic polar (roughness units); law_kinetic_*, law_steady_*: the fitted law's f_t/f_n "
        f"(x {run.law.factor:.6g}) kinetic and at V = {run.scenario.options.velocity:g} m/s; "
        "simulated_*: the driver's steady sliding at V; check_difference = |simulated - "
        "law_steady|"
    )
    fig = bridge_figure(
        run.fit, run.curve_deg, run.curve_fit, run.fit.beta_deg, run.closed, run.simulated,
        velocity=run.scenario.options.velocity, factor=run.law.factor, title=run.title,
    )  # fmt: skip
    contents: dict[str, str | bytes] = {
        "fitted_law.toml": run.toml,
        "directions.csv": format_csv(columns, units, header),
        "bridge.png": figure_png_bytes(fig),
    }
    return write_contents_atomic(out, contents)


class Bridge:
    """``frictionlab bridge SCENARIO.toml --out DIR`` (:mod:`frictionlab.commands.bridge`)."""

    name = "bridge"
    #: bridge.json: the summary's name before 0.x; a copy of summary.json for one release.
    aliases: tuple[str, ...] = ("bridge.json",)

    def parse(self, args: argparse.Namespace, out: Path) -> tuple[BridgeScenario, Path]:
        from frictionlab.schema.bridge import load_bridge

        return load_bridge(args.scenario, args.set), Path(args.scenario)

    def run(
        self, job: tuple[BridgeScenario, Path], progress: ProgressFactory, staging: Path
    ) -> BridgeRun:
        return run_bridge(job[0], job[1], progress)

    def files(self, job: Any, result: BridgeRun, out: Path, plots: bool) -> list[Path]:
        return _files(out, result)

    def summary(
        self, job: Any, result: BridgeRun, files: list[str], seconds: float
    ) -> dict[str, Any]:
        return summary(result)

    def inputs(self, job: Any) -> list[Path]:
        return [job[1]]

    def report(self, job: Any, result: BridgeRun, seconds: float, written: list[Path]) -> None:
        fit = result.fit
        beta = np.asarray(result.law.params.rotation)
        print(
            f"frictionlab bridge: {fit.beta_deg.size} directions; rotation = "
            f"[{beta[0]:.6g}, {beta[1]:.6g}], orthotropy = [1, {fit.orthotropy[1]:.6g}], "
            f"e*_1 at {fit.orthotropy_angle_deg:.4g} deg; rms misfit {fit.rms_misfit:.3g} "
            f"({fit.relative_rms_misfit:.2%} of the mean friction), max {fit.max_misfit:.3g} "
            f"at beta = {fit.beta_at_max_misfit_deg:g} deg"
        )
        print(
            f"steady sliding at {result.scenario.options.velocity:g} m/s in {fit.beta_deg.size} "
            f"directions: simulated vs closed form, largest difference "
            f"{result.difference.max():.2e} in f_t/f_n"
        )
        print("wrote " + ", ".join(str(p) for p in written))

    def notes(self, job: Any, result: BridgeRun) -> list[str]:
        return [] if result.fit.expressible else [f"frictionlab bridge: {result.fit.note}"]

    def failure(self, job: Any, result: BridgeRun, out: Path) -> str | None:
        if result.check_passed:
            return None
        return (
            "the simulated steady sliding differs from the law's closed form by "
            f"{result.difference.max():.3g} in f_t/f_n (> [bridge].check_tolerance = "
            f"{result.scenario.options.check_tolerance:g}); increase [bridge].distance or "
            "[bridge].steps"
        )


#: The bridge workflow.
BRIDGE = Bridge()


def write_bridge(out: Path, run: BridgeRun) -> list[Path]:
    """Write the files of ``run`` into ``out`` (summary.json and bridge.json last)."""
    job = (run.scenario, run.source)
    return write_outputs(BRIDGE, job, run, Path(out), plots=True, seconds=0.0)
