"""Several load distributions or pressures in one roughness run: the comparison and sweep.

``[contact] model = ["lattice", "elastic"]`` runs both models, ``pressure = [p1, p2, ...]``
each model at every nominal pressure (the lattice through ``stiffness_per_area``, the
elastic half-space warm-started from the previous pressure). The files, named
``comparison.*`` for two models and ``sweep.*`` for one:

* ``<name>.csv``: one row per pressure and requested direction: ``pressure_pa,
  beta_deg`` and per model ``mu_<model>, mu_over_mu0_<model>,
  contact_fraction_<model>`` (mu empty where on_invalid masked it);
* ``<name>.png``: mu/mu0 of every model and pressure on polar axes (full circle) and the
  contact area fraction against the pressure;
* ``pressure_map.png`` with the elastic model (its first pressure).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory
from frictionlab.schema.roughness import RoughnessScenario

__all__ = ["ModelRun", "model_columns", "model_figure", "model_summary", "run_models"]


@dataclass(frozen=True)
class ModelRun:
    """One model at one nominal pressure (Pa): its polar over the requested directions
    (first ``n``) and, for the figure, over the full circle."""

    model: str
    pressure: float
    polar: Any  # FrictionPolar or ElasticPolar
    contact_fraction: float
    plot: Any = None  # the polar over the full circle (None: ``polar``)


def run_models(
    scenario: RoughnessScenario,
    circle: np.ndarray,
    progress: ProgressFactory,
    name: str,
) -> list[ModelRun]:
    """Every model of ``scenario.models`` at every pressure; directions requested first,
    then ``circle`` (extra directions for the figure)."""
    from frictionlab.roughness.elastic import pressure_sweep
    from frictionlab.roughness.lattice import friction_polar, merge_polars

    betas = np.asarray(scenario.beta_deg, dtype=np.float64)
    runs: list[ModelRun] = []
    for model in scenario.models:
        with progress(f"roughness {name} ({model})") as update:
            if model == "elastic":
                assert scenario.contact is not None
                polars = pressure_sweep(
                    scenario.lower, scenario.upper, scenario.mu0,
                    np.concatenate([betas, circle]), scenario.pressures,
                    settings=scenario.contact, progress=update,
                )  # fmt: skip
                runs.extend(
                    ModelRun("elastic", p, polar, polar.contact_fraction_mean)
                    for p, polar in zip(scenario.pressures, polars, strict=True)
                )
                continue
            for k, pressure in enumerate(scenario.pressures):
                settings = replace(scenario.settings, load=scenario.lattice_load(pressure))
                step = _steps(update, k, len(scenario.pressures))
                polar = friction_polar(
                    scenario.lower, scenario.upper, scenario.mu0, betas, settings=settings,
                    progress=step,
                )  # fmt: skip
                if not np.all(polar.in_contact):
                    from frictionlab.errors import InputError

                    raise InputError(
                        f"[contact].pressure = {pressure:g} Pa compresses no spring of the "
                        "lattice: allowed a pressure that keeps some spring compressed"
                    )
                fraction = float(np.mean(polar.contact_fraction_mean))
                plot = polar
                if circle.size:
                    more = friction_polar(
                        scenario.lower, scenario.upper, scenario.mu0, circle,
                        settings=settings,
                    )  # fmt: skip
                    plot = merge_polars(polar, more)
                runs.append(ModelRun("lattice", pressure, polar, fraction, plot))
    return runs


def _steps(update: Callable[[int, int], None], k: int, count: int) -> Callable[[int, int], None]:
    """Progress of pressure ``k`` of ``count`` as a share of the whole sweep."""
    return lambda done, total: update(k * total + done, count * total)


def _mu(run: ModelRun, n: int) -> np.ndarray:
    return np.asarray(run.polar.mu, dtype=np.float64)[:n]


def model_columns(scenario: RoughnessScenario, runs: list[ModelRun]) -> dict[str, np.ndarray]:
    """The long table: one row per pressure and requested direction."""
    betas = np.asarray(scenario.beta_deg, dtype=np.float64)
    n = betas.size
    pressures = np.asarray(scenario.pressures, dtype=np.float64)
    columns: dict[str, np.ndarray] = {
        "pressure_pa": np.repeat(pressures, n),
        "beta_deg": np.tile(betas, pressures.size),
    }
    for model in scenario.models:
        mine = [r for r in runs if r.model == model]
        mu = np.concatenate([_mu(r, n) for r in mine])
        columns[f"mu_{model}"] = np.ma.masked_invalid(mu)
        columns[f"mu_over_mu0_{model}"] = np.ma.masked_invalid(mu / scenario.mu0)
        columns[f"contact_fraction_{model}"] = np.repeat([r.contact_fraction for r in mine], n)
    return columns


def model_units(scenario: RoughnessScenario) -> dict[str, str]:
    """Units of :func:`model_columns`."""
    return {"pressure_pa": "Pa", "beta_deg": "deg"}


def model_summary(scenario: RoughnessScenario, runs: list[ModelRun]) -> dict[str, Any]:
    """The ``contact`` block of summary.json: settings and one entry per model and pressure."""
    n = scenario.beta_deg.size
    rows = []
    for run in runs:
        mu = _mu(run, n)
        row: dict[str, Any] = {
            "model": run.model,
            "pressure_pa": run.pressure,
            "contact_fraction": run.contact_fraction,
            "mu_min": float(np.nanmin(mu)),
            "mu_max": float(np.nanmax(mu)),
            "mu_over_mu0_min": float(np.nanmin(mu)) / scenario.mu0,
            "mu_over_mu0_max": float(np.nanmax(mu)) / scenario.mu0,
        }
        if run.model == "elastic":
            row["mean_gap_m"] = run.polar.mean_gap
            row["plastic_fraction"] = run.polar.plastic_fraction
        else:
            row["load_per_spring_N"] = scenario.lattice_load(run.pressure)
        rows.append(row)
    contact = scenario.contact
    return {
        "models": list(scenario.models),
        "pressures_pa": list(scenario.pressures),
        "stiffness_per_area_pa_per_m": scenario.stiffness_per_area,
        "modulus_pa": None if contact is None else contact.modulus,
        "hardness_pa": None if contact is None else contact.hardness,
        "runs": rows,
    }


_COLORS = {"lattice": "k", "elastic": "C3"}


def model_figure(runs: list[ModelRun], mu0: float, title: str) -> Any:
    """mu/mu0 of every run on polar axes and the contact area against the pressure."""
    from frictionlab.plotting.roughness import new_figure, radial_limits

    fig = new_figure(10.0, 4.8)
    ax = fig.add_subplot(1, 2, 1, projection="polar")
    styles = {"lattice": "-", "elastic": "--"}
    pressures = sorted({r.pressure for r in runs})
    models = list(dict.fromkeys(r.model for r in runs))
    radii = []
    for run in runs:
        polar = run.polar if run.plot is None else run.plot
        beta = np.mod(np.asarray(polar.beta_deg, dtype=np.float64), 360.0)
        order = np.argsort(beta, kind="stable")
        theta = np.radians(np.append(beta[order], beta[order][0] + 360.0))
        r = np.asarray(polar.mu, dtype=np.float64)[order] / mu0
        r = np.append(r, r[0])
        radii.append(r)
        color = (
            _COLORS[run.model] if len(pressures) == 1 else f"C{pressures.index(run.pressure) % 10}"
        )
        label = f"{run.model}, {run.pressure:.3g} Pa" if len(pressures) > 1 else run.model
        ax.plot(theta, r, styles[run.model], color=color, lw=1.4, label=label)
    lo, hi = radial_limits(np.concatenate(radii))
    ax.set_rlim(lo, hi)  # type: ignore[attr-defined]
    origin = f" (radial axis from {lo:.3g})" if lo > 0 else ""
    ax.set_title(f"mu/mu0 vs sliding direction{origin}", fontsize=9)
    ax.legend(fontsize=7, loc="lower left", bbox_to_anchor=(-0.15, -0.15))
    area = fig.add_subplot(1, 2, 2)
    if len(pressures) == 1:  # one pressure: the areas side by side
        values = [100.0 * next(r.contact_fraction for r in runs if r.model == m) for m in models]
        area.bar(models, values, color=[_COLORS[m] for m in models])
        for k, value in enumerate(values):
            area.text(k, value, f"{value:.3g} %", ha="center", va="bottom", fontsize=9)
        area.set_ylabel("contact area [% of the nominal area]")
        area.set_title(f"contact area at {pressures[0]:.3g} Pa", fontsize=9)
        fig.suptitle(title, fontsize=10)
        return fig
    for model in models:
        mine = [r for r in runs if r.model == model]
        area.plot(
            [r.pressure for r in mine], [100.0 * r.contact_fraction for r in mine],
            styles[model], marker="o", color=_COLORS[model], label=model,
        )  # fmt: skip
    if len(pressures) > 1 and max(pressures) / min(pressures) > 10.0:
        area.set_xscale("log")
    area.set_xlabel("nominal pressure [Pa]")
    area.set_ylabel("contact area [% of the nominal area]")
    area.set_title("contact area", fontsize=9)
    area.legend(fontsize=8)
    area.grid(alpha=0.3)
    fig.suptitle(title, fontsize=10)
    return fig
