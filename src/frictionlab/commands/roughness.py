"""``frictionlab roughness SCENARIO.toml --out DIR``: mu(beta) of two rough surfaces.

Reads a scenario (see :mod:`frictionlab.io.roughness_scenario`), runs the lattice-spring
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

Bad input (unknown kind, missing key, angle outside (0, 90), unreadable file, NaN
heights, mu0 <= 0 or beyond the validity bound of Eq 1) ends with one line on stderr and
exit code 2; nothing is written.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._version import __version__
from frictionlab.errors import InputError
from frictionlab.io.atomic import write_bytes_atomic, write_json_atomic, write_text_atomic
from frictionlab.io.config import apply_overrides, load_toml
from frictionlab.io.roughness_scenario import RoughnessScenario, parse_roughness_scenario
from frictionlab.io.tables import format_csv
from frictionlab.roughness.closed_forms import wedge_friction
from frictionlab.roughness.generators import FlatProfile, WedgeProfile
from frictionlab.roughness.lattice import FrictionPolar, friction_polar, merge_polars

__all__ = ["add_parser", "run"]


def add_parser(subparsers: Any) -> argparse.ArgumentParser:
    """Register the ``roughness`` subcommand."""
    parser = subparsers.add_parser(
        "roughness",
        help="anisotropic friction mu(beta) of two rough surfaces (lattice-spring model)",
        description=(
            "Compute mu_x, mu_y and mu(beta) of two rough surfaces with the lattice-spring "
            "model and write polar.csv, summary.json and polar.png into --out."
        ),
    )
    parser.add_argument("scenario", help="scenario TOML file")
    parser.add_argument("--out", required=True, metavar="DIR", help="output directory")
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="SECTION.KEY=VALUE",
        help="override a scenario value, e.g. --set lattice.time_samples=100 (repeatable)",
    )
    parser.set_defaults(handler=run)
    return parser


def run(args: argparse.Namespace) -> int:
    """Run the command; returns the exit code (errors propagate to ``cli.main``)."""
    scenario_path = Path(args.scenario)
    out_dir = Path(args.out)
    if out_dir.exists() and not out_dir.is_dir():
        raise InputError(f"--out '{out_dir}' exists and is not a directory")
    data = apply_overrides(load_toml(scenario_path), args.set)
    scenario = parse_roughness_scenario(data, scenario_path.parent)
    started = time.perf_counter()
    polar = friction_polar(
        scenario.lower, scenario.upper, scenario.mu0, scenario.beta_deg, settings=scenario.settings
    )
    plot_polar = _full_circle(scenario, polar)
    seconds = time.perf_counter() - started

    csv_text = _csv_text(scenario, polar, scenario_path)
    summary = _summary(scenario, polar, plot_polar, scenario_path, seconds)
    png = _png(scenario, plot_polar)
    write_text_atomic(out_dir / "polar.csv", csv_text)
    write_json_atomic(out_dir / "summary.json", summary)
    write_bytes_atomic(out_dir / "polar.png", png)
    ratio = polar.mu_over_mu0
    print(
        f"frictionlab roughness: {polar.beta_deg.size} directions, mu/mu0 from "
        f"{ratio.min():.6g} (beta = {polar.beta_deg[int(np.argmin(ratio))]:g} deg) to "
        f"{ratio.max():.6g} (beta = {polar.beta_deg[int(np.argmax(ratio))]:g} deg); "
        f"wrote {out_dir / 'polar.csv'}, {out_dir / 'summary.json'}, {out_dir / 'polar.png'}"
    )
    return 0


def _full_circle(scenario: RoughnessScenario, polar: FrictionPolar) -> FrictionPolar:
    """The polar for the plot: requested directions plus the full circle at plot_step_deg."""
    if not scenario.plot_full_circle:
        return polar
    have = np.round(np.mod(polar.beta_deg, 360.0), 9)
    circle = np.arange(0.0, 360.0 - 1e-9, scenario.plot_step_deg)
    extra = circle[~np.isin(np.round(circle, 9), have)]
    if extra.size == 0:
        return polar
    more = friction_polar(
        scenario.lower, scenario.upper, scenario.mu0, extra, settings=scenario.settings
    )
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
        "frictionlab_version": __version__,
        "command": "roughness",
        "scenario_file": str(path),
        "title": scenario.title,
        "mu0": scenario.mu0,
        "mu_definition": s.mu_definition,
        "lower": scenario.lower.describe(),
        "upper": scenario.upper.describe(),
        "sliding": {
            "beta_deg": [float(polar.beta_deg[0]), float(polar.beta_deg[-1])],
            "directions": int(polar.beta_deg.size),
            "load_per_spring_N": s.load,
            "control": s.control,
            "separation_m": s.separation,
            "phase_m": list(s.phase),
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
        "work": {
            "spring_station_evaluations": int(polar.spring_evaluations),
            "plot_directions": int(plot_polar.beta_deg.size),
            "seconds": round(seconds, 3),
        },
        "files": ["polar.csv", "summary.json", "polar.png"],
    }


def _png(scenario: RoughnessScenario, plot_polar: FrictionPolar) -> bytes:
    from frictionlab.plotting.roughness import figure_png_bytes, scenario_figure

    fig = scenario_figure(
        plot_polar,
        scenario.lower,
        scenario.upper,
        requested=scenario.beta_deg,
        title=scenario.title or None,
    )
    return figure_png_bytes(fig)
