"""The roughness workflow (``frictionlab roughness SCENARIO.toml --out DIR``): mu(beta).

Reads a scenario (see :mod:`frictionlab.schema.roughness`), runs the lattice-spring
model over the requested sliding directions and writes, each file atomically and only
after everything has been computed and rendered:

* ``DIR/polar.csv``: one row per requested direction (``beta_deg, mu_x, mu_y, mu,
  mu_over_mu0, mu_magnitude, mu_projection, contact_fraction_min, contact_fraction_mean,
  time_samples``; ``mu_apparent`` too when k_t > 0), units in a header line;
* ``DIR/summary.json``: inputs, lattice geometry, extremes of mu, the closed-form check
  (Eqs 15-16) when both surfaces are wedges or flat, the work done;
* ``DIR/polar.png``: mu/mu0 on polar axes over the full circle (extra directions every
  ``plot_step_deg`` are computed for it unless ``plot_full_circle = false``), and both
  surfaces.

Optional tables of the scenario add (see :mod:`frictionlab.schema.roughness`):

* ``[adhesion]``: ``adhesion.csv`` (one row per load and direction: tangential force,
  mu_compressed, mu_apparent (Eq 22; an empty field at L = 0 with
  ``mu_apparent_defined = false``), fractions of compressed and stretched springs) and
  ``adhesion.png``;
* ``[wear]``: ``wear.csv`` (mu(t) from 0 to T_w per direction) and ``wear.png``;
* ``[hierarchy]``: ``hierarchy.csv`` (mu_i of every level per direction; invalid levels
  as empty fields with ``valid = false``) and ``hierarchy.png``;
* ``[hierarchy]`` with ``[wear]``: also ``hierarchy_wear.csv`` (B_i and mu_i of every
  level over the whole life) and ``hierarchy_wear.png``.
* ``[multiscale]``: ``multiscale.csv`` (mu(beta) against the shortest wavelength
  retained: ``cutoff_m, beta_deg, mu, mu_over_mu0, valid``) and ``multiscale.png``.

``--quiet`` hides the progress bar (one step per direction), warnings and the summary
line; ``--no-plots`` skips every PNG. With ``[sliding] on_invalid = "drop"`` contacts
violating Eq 1 are dropped and ``polar.csv`` gains ``invalid_fraction``. summary.json
records the provenance of each surface (file name, sha256, preparation, rms height and
slope after filtering; Hurst exponent and seed of generated ones), every direction
computed, the invalid fraction per direction and the warnings (e.g. the edge step of
``periodicity = "assume"``, also printed on stderr).

Bad input (unknown kind, missing key, angle outside (0, 90), unreadable file, NaN
heights, mu0 <= 0 or beyond the validity bound of Eq 1, a negative wear coefficient, a
zero hardness, levels that are not strictly nested, an empty load sweep) ends with one
line on stderr and exit code 2; nothing is written. A validity failure comes within
seconds (full contact checks all directions in one pass, partial contact stops at the
first offending sample) and says where, how much, and what to do.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory
from frictionlab._version import __version__
from frictionlab.app.budget import check_roughness
from frictionlab.errors import InputError, ParameterError, ValidityError
from frictionlab.io.atomic import write_contents_atomic
from frictionlab.io.config import load_toml
from frictionlab.io.tables import format_csv
from frictionlab.roughness import (
    AdhesionSweep,
    FlatProfile,
    FrictionPolar,
    HierarchyResult,
    HierarchyWearHistory,
    LatticeGeometry,
    LatticeSettings,
    Surface,
    WearHistory,
    WedgeProfile,
    adhesion_sweep,
    friction_polar,
    hierarchy_friction,
    hierarchy_wear,
    lattice_geometry,
    merge_polars,
    wear_history,
    wedge_friction,
)
from frictionlab.roughness.full_contact import full_contact_sums
from frictionlab.roughness.multiscale import MultiscaleResult, multiscale_friction
from frictionlab.schema.core import override
from frictionlab.schema.roughness import ROUGHNESS_FILE, RoughnessScenario, parse_roughness

__all__ = ["ROUGHNESS", "RoughnessJob", "RoughnessRun"]


@dataclass(frozen=True)
class RoughnessJob:
    """A parsed roughness scenario, the file it came from and its TOML data."""

    scenario: RoughnessScenario
    path: Path
    data: dict[str, Any]
    plots: bool
    quiet: bool = False


@dataclass(frozen=True)
class RoughnessRun:
    """The requested polar, the polar drawn (full circle) and the extension results."""

    polar: FrictionPolar
    plot_polar: FrictionPolar
    extensions: dict[str, Any]
    elastic: Any = None  # ElasticPolar of [contact] model = "elastic" (all directions)
    runs: Any = None  # list of roughness_models.ModelRun: a comparison or a pressure sweep

    @property
    def model(self) -> str:
        """Which run this is: "models" (comparison or sweep), "elastic" or "lattice"."""
        if self.runs is not None:
            return "models"
        return "lattice" if self.elastic is None else "elastic"


class Roughness:
    """``frictionlab roughness SCENARIO.toml --out DIR`` (:mod:`frictionlab.commands.roughness`)."""

    name = "roughness"
    aliases: tuple[str, ...] = ()

    def parse(self, args: argparse.Namespace, out: Path) -> RoughnessJob:
        path = Path(args.scenario)
        data = override(ROUGHNESS_FILE, load_toml(path), args.set)
        scenario = parse_roughness(data, base_dir=path.parent, source=str(path))
        check_roughness(scenario)  # the lattice's memory and time, before the run
        if not args.quiet:
            for text in scenario.warnings:
                print(f"frictionlab roughness: warning: {text}", file=sys.stderr)
        return RoughnessJob(scenario, path, data, not args.no_plots, bool(args.quiet))

    def run(self, job: RoughnessJob, progress: ProgressFactory, staging: Path) -> RoughnessRun:
        scenario = job.scenario
        if scenario.compares:
            return _run_models(job, progress)
        if scenario.contact is not None:
            return _run_elastic(job, progress)
        try:
            with progress(f"roughness {job.path.name}") as update:
                polar = friction_polar(
                    scenario.lower, scenario.upper, scenario.mu0, scenario.beta_deg,
                    settings=scenario.settings, progress=update,
                )  # fmt: skip
                if not np.all(polar.in_contact):
                    beta = float(polar.beta_deg[int(np.argmin(polar.in_contact))])
                    raise InputError(
                        f"[sliding].load = {scenario.settings.load} compresses no spring at "
                        f"beta = {beta:g} deg, so mu is undefined there: allowed a load that "
                        "keeps some spring compressed (sweeps through zero and tension belong "
                        "in [adhesion])"
                    )
                plot_polar = _full_circle(scenario, polar, update) if job.plots else polar
            extensions = _extensions(scenario)
        except ValidityError as exc:
            # Full contact fails in its one pass over all directions, partial contact at the
            # first offending time sample: either way within seconds, before the rest.
            raise ValidityError(f"{exc}.{_diagnose(scenario)} {_ways_forward(scenario)}") from None
        return RoughnessRun(polar, plot_polar, extensions)

    def files(self, job: RoughnessJob, result: RoughnessRun, out: Path, plots: bool) -> list[Path]:
        files = _OUTPUTS[result.model].files(job, result, plots)
        files.update(_statistics_outputs(job.scenario, plots)[0])
        return write_contents_atomic(out, files)

    def summary(
        self, job: RoughnessJob, result: RoughnessRun, files: list[str], seconds: float
    ) -> dict[str, Any]:
        summary = _OUTPUTS[result.model].summary(job, result, seconds)
        stats = _statistics_outputs(job.scenario, False)[1]
        if stats:
            summary["statistics"] = stats
        summary["files"] = _names(files)
        return summary

    def inputs(self, job: RoughnessJob) -> list[Path]:
        return _input_files(job.path, job.data)

    def report(
        self, job: RoughnessJob, result: RoughnessRun, seconds: float, written: list[Path]
    ) -> None:
        n = job.scenario.beta_deg.size
        ratio = result.polar.mu_over_mu0[:n]
        folder = written[0].parent
        names = ", ".join(str(folder / name) for name in _names([p.name for p in written]))
        model = (
            ""
            if result.elastic is None
            else (
                f"elastic contact ({100 * result.elastic.contact_fraction_mean:.3g} % in contact), "
            )
        )
        if result.runs is not None:
            areas = ", ".join(
                f"{r.model} at {r.pressure:.3g} Pa: {100 * r.contact_fraction:.3g} %"
                for r in result.runs
            )
            model = f"contact area {areas}; {result.runs[0].model} at the first pressure: "
        print(
            f"frictionlab roughness: {model}{n} directions in "
            f"{seconds:.3g} s, mu/mu0 from {np.nanmin(ratio):.6g} to {np.nanmax(ratio):.6g}; "
            f"wrote {names}"
        )

    def notes(self, job: RoughnessJob, result: RoughnessRun) -> list[str]:
        if job.quiet or result.elastic is not None or result.runs is not None:
            return []
        return [f"frictionlab roughness: note: {text}" for text in result.polar.notes]

    def failure(self, job: RoughnessJob, result: RoughnessRun, out: Path) -> str | None:
        return None


#: The roughness workflow.
ROUGHNESS = Roughness()


def _names(files: list[str]) -> list[str]:
    """The output names in summary order: polar.csv, summary.json, polar.png, the rest."""
    fixed = ("polar.csv", "summary.json", "polar.png")
    extra = sorted(name for name in files if name not in fixed)
    return [*(name for name in fixed if name in files or name == "summary.json"), *extra]


def _station_gradients(
    lower: Surface, upper: Surface, settings: LatticeSettings
) -> tuple[LatticeGeometry, tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]:
    geometry = lattice_geometry(lower, upper, settings.stations)
    xs, ys = geometry.station_coordinates()
    px, py = settings.phase
    n = geometry.n_stations
    _, g1x, g1y = (np.broadcast_to(a, geometry.shape).ravel() for a in lower.evaluate(xs, ys))
    _, g2x, g2y = (
        np.broadcast_to(a, geometry.shape).ravel() for a in upper.evaluate(xs - px, ys - py)
    )
    assert g1x.size == n
    return geometry, (g1x, g1y), (g2x, g2y)


def _diagnose(scenario: RoughnessScenario) -> str:
    """Where full contact violates Eq 1 (one pass over every direction): the fraction of
    contacts, and whether the worst lies on an edge step made by periodicity='assume'."""
    s = scenario.settings
    geometry, g1, g2 = _station_gradients(scenario.lower, scenario.upper, s)
    beta = scenario.beta_deg
    sums = full_contact_sums(
        scenario.mu0, g1, g2, np.cos(np.radians(beta)), np.sin(np.radians(beta)),
        engine=s.engine,
    )  # fmt: skip
    if not np.any(sums.invalid):
        return ""
    d = int(np.argmax(sums.invalid_fraction))
    station = int(sums.worst_station[d])
    family = int(sums.worst_family[d])
    side = "lower" if family == 1 else "upper"
    surface = scenario.lower if family == 1 else scenario.upper
    xs, ys = geometry.station_coordinates()
    idx = np.unravel_index(station, geometry.shape)
    x = float(np.ravel(xs)[idx[0]])
    y = float(np.ravel(ys)[idx[1]]) if geometry.dimension == 2 else 0.0
    if family == 2:
        x, y = x - s.phase[0], y - s.phase[1]
    _, gx, gy = surface.evaluate(np.array([x]), np.array([y]))
    phi = math.degrees(math.atan(math.hypot(float(gx[0]), float(gy[0]))))
    where = f"x = {x:.6g} m" + (f", y = {y:.6g} m" if geometry.dimension == 2 else "")
    text = (
        f" In full contact {100 * sums.invalid_fraction[d]:.3g}% of the contacts violate "
        f"Eq 1 at beta = {beta[d]:g} deg; the steepest is on the {side} surface at {where} "
        f"(phi = {phi:.4g} deg)."
    )
    if _on_assumed_edge(scenario, side, surface, x, y):
        text += (
            f" It lies on the artificial edge step that periodicity = 'assume' creates in "
            f"[{side}] (use 'mirror', window = 'hann' or detrend = 'height')."
        )
    return text


def _on_assumed_edge(
    scenario: RoughnessScenario, side: str, surface: Surface, x: float, y: float
) -> bool:
    """Whether (x, y) lies within one pixel of the wrap of a surface read with 'assume'."""
    if scenario.sources.get(side, {}).get("periodicity") != "assume":
        return False
    grid = surface.grid_shape
    periods = [p for p in surface.periods if p is not None]
    if grid is None:
        return False
    for value, period, n in zip((x, y), periods, grid, strict=False):
        u = (value % period) / (period / n)  # position in pixels from the origin
        if u < 1.0 or u > n - 1.0:
            return True
    return False


def _ways_forward(scenario: RoughnessScenario) -> str:
    pixel = [
        info["physical_sizes_m"][0] / info["points"][0]
        for info in scenario.sources.values()
        if "physical_sizes_m" in info and "points" in info
    ]
    cutoff = f" (e.g. short_cutoff = {4 * min(pixel):.3g} m, four pixels)" if pixel else ""
    return (
        "Ways forward: remove the pixel-scale slopes with short_cutoff in [lower]/[upper]"
        f'{cutoff}, use a smaller mu0, or set on_invalid = "drop" in [sliding] to drop '
        "the invalid contacts and report their area fraction"
    )


def _extensions(scenario: RoughnessScenario) -> dict[str, Any]:
    """Adhesion, wear, hierarchy and hierarchy-with-wear results (only those requested)."""
    out: dict[str, Any] = {}
    s = scenario.settings
    if scenario.adhesion is not None:
        a = scenario.adhesion
        kt = 0.5 * s.k_c if a.k_t is None else a.k_t
        out["adhesion"] = adhesion_sweep(
            scenario.lower, scenario.upper, scenario.mu0, a.loads, a.beta_deg, k_t=a.k_t,
            compare_without_adhesion=a.compare_without_adhesion,
            settings=replace(s, k_t=kt, detachment=a.detachment),
        )  # fmt: skip
    if scenario.wear is not None:
        w = scenario.wear
        out["wear"] = wear_history(
            scenario.lower, scenario.upper, scenario.mu0, w.beta_deg, w.settings,
            samples=w.samples, method=w.method, settings=s,
        )  # fmt: skip
    if scenario.hierarchy is not None:
        h = scenario.hierarchy
        out["hierarchy"] = hierarchy_friction(
            h.levels, scenario.mu0, h.beta_deg, mu_passed=h.mu_passed, on_invalid=h.on_invalid,
            settings=s,
        )  # fmt: skip
        if scenario.wear is not None:
            out["hierarchy_wear"] = hierarchy_wear(
                h.levels, scenario.mu0, h.beta_deg, scenario.wear.settings,
                samples_per_level=h.samples_per_level, mu_passed=h.mu_passed, settings=s,
            )  # fmt: skip
    if scenario.multiscale is not None:
        m = scenario.multiscale
        try:
            out["multiscale"] = multiscale_friction(
                scenario.lower, scenario.upper, scenario.mu0, m.beta_deg, m.cutoffs,
                mu_passed=m.mu_passed, drop=s.on_invalid == "drop", engine=s.engine,
            )  # fmt: skip
        except ParameterError as exc:
            raise InputError(
                f"[multiscale] needs sampled surfaces (kind = 'file' or 'self_affine') or flat "
                f"ones: {exc}"
            ) from None
    return out


def _adhesion_entry(sweep: AdhesionSweep, scenario: RoughnessScenario) -> dict[str, Any]:
    return {
        "k_c_N_per_m": sweep.k_c,
        "k_t_N_per_m": sweep.k_t,
        "loads_per_spring_N": sweep.load.tolist(),
        "beta_deg": sweep.beta_deg.tolist(),
        "mu_apparent": [
            [None if v is np.ma.masked else float(v) for v in row] for row in sweep.mu_apparent
        ],
        "detachment_m": scenario.adhesion.detachment if scenario.adhesion else None,
    }


def _wear_entry(history: WearHistory, scenario: RoughnessScenario) -> dict[str, Any]:
    return {
        **history.wear.as_dict(),
        "wear_time_s": history.wear_time,
        "roughness_volume_m3": history.volume,
        "method": history.method,
        "mu_initial": history.mu[0].tolist(),
        "mu_final": history.mu[-1].tolist(),
    }


def _hierarchy_entry(result: HierarchyResult, scenario: RoughnessScenario) -> dict[str, Any]:
    return {
        "levels": result.n_levels,
        "mu_passed": result.mu_passed,
        "beta_deg": result.beta_deg.tolist(),
        "mu_outermost": [None if v is np.ma.masked else float(v) for v in result.mu[-1]],
        "first_invalid_level": result.first_invalid_level.tolist(),
        "messages": list(result.messages),
    }


def _hierarchy_wear_entry(
    life: HierarchyWearHistory, scenario: RoughnessScenario
) -> dict[str, Any]:
    return {
        "wear_time_per_level_s": life.wear_time.tolist(),
        "dropout_time_per_level_s": life.dropout_time.tolist(),
        "volume_per_level_m3": life.volume.tolist(),
    }


def _multiscale_entry(ms: MultiscaleResult, scenario: RoughnessScenario) -> dict[str, Any]:
    mu = np.where(ms.valid, ms.mu, np.nan)
    with np.errstate(invalid="ignore"):
        anisotropy = np.nanmax(mu, axis=1) / np.nanmin(mu, axis=1)
    return {
        "cutoffs_m": list(scenario.multiscale.cutoffs) if scenario.multiscale else [],
        "shortest_wavelength_retained_m": ms.cutoff_m.tolist(),
        "beta_deg": ms.beta_deg.tolist(),
        "band_rms_slope": ms.band_rms_slope.tolist(),
        "anisotropy_max_over_min": [None if not np.isfinite(v) else float(v) for v in anisotropy],
        "all_valid": bool(ms.valid.all()),
    }


@dataclass(frozen=True)
class _Extension:
    """How one extension result is written: CSV header, figure and summary.json entry."""

    header: Callable[[Any], str]  # what follows "frictionlab V roughness: TITLE\nmu0 = MU0"
    figure: str  # "module.function" in frictionlab.plotting (imported only to draw)
    caption: str  # the figure's title before ": TITLE"
    entry: Callable[[Any, RoughnessScenario], dict[str, Any]]


#: The extension results by file stem and summary key, in writing order.
_EXTENSIONS = {
    "adhesion": _Extension(
        lambda sweep: (
            f", k_c = {sweep.k_c:g} N/m, k_t = {sweep.k_t:g} N/m; loads and forces per "
            "spring (N); mu_apparent = R/L (Eq 22), empty where undefined (L = 0)"
        ),
        "roughness_life.adhesion_figure",
        "adhesion",
        _adhesion_entry,
    ),
    "wear": _Extension(
        lambda history: (
            f", wear time T_w = {history.wear_time:.9g} s, volume {history.volume:.9g} m^3, "
            f"surfaces = {history.wear.surfaces}, method = {history.method}"
        ),
        "roughness_life.wear_figure",
        "wear",
        _wear_entry,
    ),
    "hierarchy": _Extension(
        lambda result: (
            f", {result.n_levels} levels (level 0: the local mu0), mu passed upward: "
            f"{result.mu_passed}; invalid levels empty with valid = false"
        ),
        "roughness_life.hierarchy_figure",
        "hierarchy",
        _hierarchy_entry,
    ),
    "hierarchy_wear": _Extension(
        lambda life: (
            ", levels flat (drop out) at t = "
            + ", ".join(f"{t:.6g}" for t in life.dropout_time)
            + " s (Eq 35 windows)"
        ),
        "roughness_life.hierarchy_wear_figure",
        "hierarchy with wear",
        _hierarchy_wear_entry,
    ),
    "multiscale": _Extension(
        lambda ms: (
            "; bands split at the cutoffs (wavelengths, m) by SurfaceTopography's "
            "shortcut filter, innermost band = shortest wavelengths, mu passed upward: "
            f"{ms.mu_passed}; cutoff_m = shortest wavelength retained (last: Nyquist); "
            "invalid values empty with valid = false"
        ),
        "multiscale.multiscale_figure",
        "scale-resolved friction",
        _multiscale_entry,
    ),
}


def _extension_files(
    scenario: RoughnessScenario, results: dict[str, Any], path: Path, plots: bool = True
) -> dict[str, str | bytes]:
    """CSV text and PNG bytes of every extension result, rendered before anything is written."""
    from importlib import import_module

    from frictionlab.plotting.roughness import figure_png_bytes

    title = scenario.title or path.name
    head = f"frictionlab {__version__} roughness: {title}\nmu0 = {scenario.mu0:g}"
    files: dict[str, str | bytes] = {}
    for stem, how in _EXTENSIONS.items():
        if stem not in results:
            continue
        res = results[stem]
        files[f"{stem}.csv"] = format_csv(res.columns(), res.units(), head + how.header(res))
        if plots:  # figures are rendered only when written
            module, name = how.figure.split(".")
            figure = getattr(import_module(f"frictionlab.plotting.{module}"), name)
            files[f"{stem}.png"] = figure_png_bytes(figure(res, f"{how.caption}: {title}"))
    return files


def _extension_summary(scenario: RoughnessScenario, results: dict[str, Any]) -> dict[str, Any]:
    return {
        key: how.entry(results[key], scenario) for key, how in _EXTENSIONS.items() if key in results
    }


def _full_circle(
    scenario: RoughnessScenario,
    polar: FrictionPolar,
    progress: Callable[[int, int], None] | None = None,
) -> FrictionPolar:
    """The polar for the plot: requested directions plus the full circle at plot_step_deg."""
    if not scenario.plot_full_circle:
        return polar
    have = np.round(np.mod(polar.beta_deg, 360.0), 9)
    circle = np.arange(0.0, 360.0 - 1e-9, scenario.plot_step_deg)
    extra = circle[~np.isin(np.round(circle, 9), have)]
    if extra.size == 0:
        return polar
    more = friction_polar(
        scenario.lower, scenario.upper, scenario.mu0, extra, settings=scenario.settings,
        progress=progress,
    )  # fmt: skip
    return merge_polars(polar, more)


def _csv_text(scenario: RoughnessScenario, polar: FrictionPolar, path: Path) -> str:
    columns = polar.columns()
    if scenario.settings.k_t == 0.0:
        columns.pop("mu_apparent", None)
    units = {"beta_deg": "deg"}
    s = scenario.settings
    header = (
        f"frictionlab {__version__} roughness: {scenario.title or path.name}\n"
        f"lower = {scenario.lower.kind}, upper = {scenario.upper.kind}, mu0 = {scenario.mu0:g}, "
        f"mu = {s.mu_definition}, load = {s.load} (N per spring), control = {s.control}\n"
        f"stations = {list(polar.geometry.shape)} over cell {_cell(polar)} m, time samples per "
        "direction in column time_samples"
    )
    return format_csv(columns, units, header)


def _cell(polar: FrictionPolar) -> list[float]:
    return [c for c in polar.geometry.cell if c is not None]


def _closed_form_check(scenario: RoughnessScenario, polar: FrictionPolar) -> dict[str, Any] | None:
    """Eqs 15-16 against the lattice when both surfaces are wedges or flat profiles.

    A diagnostic: exact in the dense limit for any beta with time averaging; at beta = 90
    deg (static 1-D configuration) only when each face sees a uniform height distribution
    (in-phase identical wedges, or a flat counter-face).
    """
    angles: list[float] = []
    for surface in (scenario.lower, scenario.upper):
        if isinstance(surface, WedgeProfile):
            angles.extend(surface.angles_deg)
        elif isinstance(surface, FlatProfile):
            angles.extend((0.0, 0.0))
        else:
            return None
    mu_x, mu_y = wedge_friction(scenario.mu0, angles, polar.beta_deg)
    return {
        "equations": "Eqs 15-16 (wedge closed forms)",
        "angles_deg": angles,
        "max_abs_diff_mu_x": float(np.max(np.abs(polar.mu_x - mu_x))),
        "max_abs_diff_mu_y": float(np.max(np.abs(polar.mu_y - mu_y))),
    }


def _summary(
    scenario: RoughnessScenario,
    polar: FrictionPolar,
    plot_polar: FrictionPolar,
    path: Path,
    seconds: float,
) -> dict[str, Any]:
    ratio = polar.mu_over_mu0
    i_min, i_max = int(np.argmin(polar.mu)), int(np.argmax(polar.mu))
    modes: dict[str, int] = {}
    for mode in polar.travel_mode:
        modes[mode] = modes.get(mode, 0) + 1
    s = scenario.settings
    return {
        **_summary_head(scenario, path, s.mu_definition),
        "sliding": {
            "beta_deg": [float(polar.beta_deg[0]), float(polar.beta_deg[-1])],
            "directions": int(polar.beta_deg.size),
            "load_per_spring_N": s.load,
            "control": s.control,
            "separation_m": s.separation,
            "phase_m": list(s.phase),
            "directions_deg": polar.beta_deg.tolist(),
            "on_invalid": s.on_invalid,
            "invalid_fraction": polar.invalid_fraction.tolist(),
        },
        "lattice": {
            **s.as_dict(),
            "dimension": polar.geometry.dimension,
            "cell_m": _cell(polar),
            "stations_shape": list(polar.geometry.shape),
            "travel_modes": modes,
        },
        "results": {
            "mu_min": float(polar.mu[i_min]),
            "beta_at_mu_min_deg": float(polar.beta_deg[i_min]),
            "mu_max": float(polar.mu[i_max]),
            "beta_at_mu_max_deg": float(polar.beta_deg[i_max]),
            "mu_over_mu0_min": float(ratio.min()),
            "mu_over_mu0_max": float(ratio.max()),
            "anisotropy_max_over_min": float(polar.mu.max() / polar.mu.min()),
            "contact_fraction_min": float(polar.contact_fraction_min.min()),
        },
        "closed_form_check": _closed_form_check(scenario, polar),
        **(
            {}
            if not scenario.pressures
            else {
                "contact": {
                    "model": "lattice",
                    "pressure_pa": scenario.pressures[0],
                    "stiffness_per_area_pa_per_m": scenario.stiffness_per_area,
                    "load_per_spring_N": s.load,
                    "contact_fraction": float(np.mean(polar.contact_fraction_mean)),
                }
            }
        ),
        "work": {
            "spring_station_evaluations": int(polar.spring_evaluations),
            "plot_directions": int(plot_polar.beta_deg.size),
            "seconds": round(seconds, 3),
        },
        "files": ["polar.csv", "summary.json", "polar.png"],
    }


def _lattice_files(job: RoughnessJob, result: RoughnessRun, plots: bool) -> dict[str, str | bytes]:
    scenario = job.scenario
    files: dict[str, str | bytes] = {"polar.csv": _csv_text(scenario, result.polar, job.path)}
    files.update(_extension_files(scenario, result.extensions, job.path, plots))
    if plots:
        files["polar.png"] = _png(scenario, result.plot_polar)
    return files


def _lattice_summary(job: RoughnessJob, result: RoughnessRun, seconds: float) -> dict[str, Any]:
    scenario = job.scenario
    summary = _summary(scenario, result.polar, result.plot_polar, job.path, seconds)
    summary["warnings"] = [*summary["warnings"], *result.polar.notes]
    summary.update(_extension_summary(scenario, result.extensions))
    return summary


def _summary_head(scenario: RoughnessScenario, path: Path, mu_definition: str) -> dict[str, Any]:
    """The leading entries of every roughness summary.json: version, inputs, warnings."""
    return {
        "frictionlab_version": __version__,
        "command": "roughness",
        "scenario_file": str(path),
        "title": scenario.title,
        "mu0": scenario.mu0,
        "mu_definition": mu_definition,
        "lower": scenario.lower.describe(),
        "upper": scenario.upper.describe(),
        "sources": scenario.sources,
        "warnings": list(scenario.warnings),
    }


def _input_files(scenario_path: Path, data: dict[str, Any]) -> list[Path]:
    """The scenario file and the topography files it reads (for the provenance block)."""
    out = [scenario_path]
    for side in ("lower", "upper"):
        table = data.get(side)
        if isinstance(table, dict) and table.get("kind") == "file":
            out.append(scenario_path.parent / str(table["path"]))  # absolute paths stay
    return out


def _png(scenario: RoughnessScenario, plot_polar: FrictionPolar) -> bytes:
    from frictionlab.plotting.roughness import figure_png_bytes, mirrored_scans, scenario_figure

    fig = scenario_figure(
        plot_polar,
        scenario.lower,
        scenario.upper,
        requested=scenario.beta_deg,
        title=scenario.title or None,
        scans=mirrored_scans(scenario.sources),
    )
    return figure_png_bytes(fig)


def _run_elastic(job: RoughnessJob, progress: ProgressFactory) -> RoughnessRun:
    """``[contact] model = "elastic"`` (roughness.elastic): one BEM solve gives every
    direction, so the plot's full circle costs nothing extra."""
    from frictionlab.roughness.elastic import elastic_polar

    scenario = job.scenario
    settings = scenario.contact
    assert settings is not None
    if scenario.adhesion or scenario.wear or scenario.hierarchy or scenario.multiscale:
        raise InputError(
            "[contact].model = 'elastic' is invalid with [adhesion], [wear], [hierarchy] or "
            "[multiscale]: allowed only with model = 'lattice'"
        )
    requested = np.asarray(scenario.beta_deg, dtype=np.float64)
    circle = np.arange(0.0, 360.0 - 1e-9, scenario.plot_step_deg) if job.plots else np.empty(0)
    extra = circle[~np.isin(np.round(circle, 9), np.round(np.mod(requested, 360.0), 9))]
    with progress(f"roughness {job.path.name}") as update:
        whole = elastic_polar(
            scenario.lower, scenario.upper, scenario.mu0, np.concatenate([requested, extra]),
            settings=settings, progress=update,
        )  # fmt: skip
    return RoughnessRun(whole, whole, {}, whole)  # type: ignore[arg-type]


def _run_models(job: RoughnessJob, progress: ProgressFactory) -> RoughnessRun:
    """Two models or several pressures (app.roughness_models)."""
    from frictionlab.app.roughness_models import run_models

    scenario = job.scenario
    requested = np.mod(np.asarray(scenario.beta_deg, dtype=np.float64), 360.0)
    circle = (
        np.arange(0.0, 360.0 - 1e-9, scenario.plot_step_deg)
        if job.plots and scenario.plot_full_circle
        else np.empty(0)
    )
    extra = circle[~np.isin(np.round(circle, 9), np.round(requested, 9))]
    runs = run_models(scenario, extra, progress, job.path.name)
    first = runs[0].polar
    return RoughnessRun(first, first, {}, None, runs)


def _model_name(scenario: RoughnessScenario) -> str:
    return "comparison" if len(scenario.models) > 1 else "sweep"


def _model_files(job: RoughnessJob, result: RoughnessRun, plots: bool) -> dict[str, str | bytes]:
    from frictionlab.app.roughness_models import model_columns, model_figure, model_units

    scenario, runs = job.scenario, result.runs
    name = _model_name(scenario)
    files: dict[str, str | bytes] = {
        f"{name}.csv": format_csv(model_columns(scenario, runs), model_units(scenario))
    }
    if plots:
        from frictionlab.plotting.roughness import figure_png_bytes

        title = scenario.title or job.path.name
        files[f"{name}.png"] = figure_png_bytes(model_figure(runs, scenario.mu0, title))
        elastic = [r for r in runs if r.model == "elastic"]
        if elastic:
            files["pressure_map.png"] = _pressure_png(elastic[0].polar)
    return files


def _model_summary(job: RoughnessJob, result: RoughnessRun, seconds: float) -> dict[str, Any]:
    from frictionlab.app.roughness_models import model_summary

    scenario = job.scenario
    contact = model_summary(scenario, result.runs)
    rows = contact["runs"]
    return {
        **_summary_head(scenario, job.path, scenario.settings.mu_definition),
        "contact": contact,
        "results": {
            "directions_deg": scenario.beta_deg.tolist(),
            "mu_over_mu0_min": min(r["mu_over_mu0_min"] for r in rows),
            "mu_over_mu0_max": max(r["mu_over_mu0_max"] for r in rows),
        },
        "work": {"seconds": round(seconds, 3)},
    }


def _elastic_files(job: RoughnessJob, result: RoughnessRun, plots: bool) -> dict[str, str | bytes]:
    scenario, settings, whole = job.scenario, job.scenario.contact, result.elastic
    assert settings is not None
    n = scenario.beta_deg.size
    columns = {k: v[:n] for k, v in whole.columns().items()}
    header = (
        f"frictionlab {__version__} roughness: {scenario.title or job.path.name}\n"
        f"lower = {scenario.lower.kind}, upper = {scenario.upper.kind}, mu0 = "
        f"{scenario.mu0:g}, mu = {settings.mu_definition}, elastic contact: pressure = "
        f"{settings.pressure:g} Pa, E* = {settings.modulus:g} Pa\n"
        f"grid = {list(whole.geometry.shape)}, contact fraction "
        f"{whole.contact_fraction_mean:.6g} in columns contact_fraction_*"
    )
    files: dict[str, str | bytes] = {"polar.csv": format_csv(columns, {"beta_deg": "deg"}, header)}
    if plots:
        files["polar.png"] = _png(scenario, whole)
        files["pressure_map.png"] = _pressure_png(whole, _pressure_scan(scenario))
    return files


def _elastic_summary(job: RoughnessJob, result: RoughnessRun, seconds: float) -> dict[str, Any]:
    scenario, settings, whole = job.scenario, job.scenario.contact, result.elastic
    assert settings is not None
    n = scenario.beta_deg.size
    mu = whole.mu[:n]
    ratio = mu / scenario.mu0
    return {
        **_summary_head(scenario, job.path, settings.mu_definition),
        "contact": {**whole.summary(), "settings": settings.as_dict()},
        "results": {
            "mu_min": float(np.nanmin(mu)),
            "mu_max": float(np.nanmax(mu)),
            "mu_over_mu0_min": float(np.nanmin(ratio)),
            "mu_over_mu0_max": float(np.nanmax(ratio)),
            "directions_deg": scenario.beta_deg.tolist(),
            "invalid_fraction": whole.invalid_fraction[:n].tolist(),
        },
        "work": {"seconds": round(seconds, 3), "plot_directions": int(whole.beta_deg.size)},
    }


def _pressure_scan(scenario: RoughnessScenario) -> list[float] | None:
    """The scan sizes (m) to which the pressure map is cut: a mirrored measured map against
    a flat face (the grid is then the map's); None otherwise."""
    from frictionlab.plotting.roughness import mirrored_scans

    scans = mirrored_scans(scenario.sources)
    other = {"lower": scenario.upper, "upper": scenario.lower}
    mine = [side for side in scans if other[side].kind == "flat"]
    return scans[mine[0]] if len(scans) == 1 and mine else None


def _pressure_png(polar: Any, scan: list[float] | None = None) -> bytes:
    """The contact pressure of the first shift (a map, or a profile's line); ``scan`` (m):
    only that part from the origin (the measured scan of a mirrored map)."""
    from frictionlab.plotting.roughness import figure_png_bytes, new_figure

    fig = new_figure(5.5, 4.5)
    ax = fig.add_subplot()
    state = polar.states[0]
    cell = [c for c in polar.geometry.cell if c is not None]
    pressure = np.asarray(state.pressure)
    if scan is not None:
        keep = [max(1, round(n * min(s / c, 1.0))) for n, s, c in
                zip(pressure.shape, scan, cell, strict=False)]  # fmt: skip
        cell = [c * k / n for c, k, n in zip(cell, keep, pressure.shape, strict=False)]
        pressure = pressure[tuple(slice(0, k) for k in keep)]
    if pressure.ndim == 2 and polar.geometry.dimension == 2:
        image = ax.imshow(
            pressure.T / 1e6, origin="lower", cmap="magma",
            extent=(0.0, cell[0] * 1e6, 0.0, cell[1] * 1e6),
        )  # fmt: skip
        fig.colorbar(image, ax=ax, label="contact pressure [MPa]")
        ax.set_ylabel("y [um]")
    else:
        p = np.ravel(pressure)
        x = (np.arange(p.size) + 0.5) * cell[0] / p.size
        ax.plot(x * 1e6, p / 1e6, lw=1.0)
        ax.set_ylabel("contact pressure [MPa]")
    ax.set_xlabel("x [um]")
    ax.set_title(
        f"elastic contact: {polar.settings.pressure:g} Pa nominal, "
        f"{100 * polar.contact_fraction_mean:.3g} % in contact"
        + ("\nthe scan (mirrored for the model)" if scan is not None else ""),
        fontsize=9,
    )
    return figure_png_bytes(fig)


def _statistics_outputs(
    scenario: RoughnessScenario, plots: bool
) -> tuple[dict[str, str | bytes], dict[str, Any]]:
    """``[output] statistics = true``: per sampled surface, its statistics as CSV tables
    (``statistics_<side>_<table>.csv``) and one figure (``statistics_<side>.png``)."""
    from frictionlab.roughness.statistics import surface_statistics
    from frictionlab.roughness.surface import SampledHeightMap, SampledProfile

    files: dict[str, str | bytes] = {}
    summary: dict[str, Any] = {}
    if not scenario.statistics:
        return files, summary
    for side, surface in (("lower", scenario.lower), ("upper", scenario.upper)):
        if not isinstance(surface, SampledProfile | SampledHeightMap):
            continue
        stats = surface_statistics(surface)
        summary[side] = stats.summary()
        for name, columns in stats.tables().items():
            files[f"statistics_{side}_{name}.csv"] = format_csv(
                columns, {}, f"frictionlab {__version__} surface statistics: {side}, {name}"
            )
        if plots:
            from frictionlab.plotting.roughness import figure_png_bytes, plot_statistics

            files[f"statistics_{side}.png"] = figure_png_bytes(
                plot_statistics(stats, title=f"{side} surface ({surface.kind})")
            )
    return files, summary


@dataclass(frozen=True)
class _Outputs:
    """The files (name -> content) and the summary.json entries of one kind of run."""

    files: Callable[[RoughnessJob, RoughnessRun, bool], dict[str, str | bytes]]
    summary: Callable[[RoughnessJob, RoughnessRun, float], dict[str, Any]]


#: The outputs of each kind of run, by :attr:`RoughnessRun.model`.
_OUTPUTS = {
    "models": _Outputs(_model_files, _model_summary),
    "elastic": _Outputs(_elastic_files, _elastic_summary),
    "lattice": _Outputs(_lattice_files, _lattice_summary),
}
