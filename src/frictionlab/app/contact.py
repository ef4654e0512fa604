"""The contact workflow (``frictionlab contact``): global.csv, interface.csv, plots, summary.

Every file is written atomically; summary.json is written last, so its presence means
the others are complete. A failed run writes the rows computed before the failure.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import os
import platform
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory
from frictionlab._version import __version__
from frictionlab.app.outputs import WorkflowBase, write_outputs
from frictionlab.contact.history import ContactHistory, front_arrival
from frictionlab.contact.mesh import Discretisation
from frictionlab.driver.simulate import status_labels
from frictionlab.io.tables import write_csv_atomic
from frictionlab.schema.contact import ContactScenario

__all__ = [
    "CONTACT", "contact_summary", "discretise_scenario", "run_contact_scenario", "scenario_law",
    "write_contact_results",
]  # fmt: skip


def _global_columns(
    history: ContactHistory, ratio: float
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    return history.columns(ratio), history.units()


def _interface_columns(
    history: ContactHistory, cone: bool
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    S, P = history.R.shape
    three = history.dim == 3
    cols: dict[str, np.ndarray] = {
        "row": np.repeat(np.arange(S), P),
        "time": np.repeat(history.time, P),
        "x": np.tile(history.x, S),
    }
    if three:
        cols["y"] = np.tile(history.y, S)
    cols["slip"] = history.slip.ravel()
    if three:
        cols["slip_y"] = history.slip_y.ravel()
    cols["approach"] = history.approach.ravel()
    cols["plastic_slip"] = history.plastic_slip.ravel()
    cols["traction_t"] = history.traction_t.ravel()
    if three:
        cols["traction_t_y"] = history.traction_t_y.ravel()
    cols["traction_n"] = history.traction_n.ravel()
    cols["R"] = history.R.ravel()
    cols["F"] = history.F.ravel()
    cols["status"] = status_labels(history.status.ravel())
    units = {
        "time": "s", "x": "m", "y": "m", "slip": "m", "slip_y": "m", "approach": "m",
        "plastic_slip": "m", "traction_t": "Pa", "traction_t_y": "Pa", "traction_n": "Pa",
        "F": "1" if cone else "Pa",
    }  # fmt: skip
    return cols, {k: v for k, v in units.items() if k in cols}


def contact_summary(
    scenario: ContactScenario, history: ContactHistory, elapsed: float, files: list[str]
) -> dict[str, Any]:
    """The summary.json content: inputs with defaults, results, solver work, provenance."""
    import scipy

    try:
        import skfem

        skfem_version = str(skfem.__version__)
    except ImportError:  # pragma: no cover
        skfem_version = "missing"
    peak = history.peak_index
    sliding = history.stage > 0
    steps = history.iterations[1:]
    return {
        "inputs": scenario.inputs,
        "source": scenario.source,
        "success": history.success,
        "message": history.message,
        "mesh": {
            "cells": list(scenario.block.cells)
            if scenario.mesh is None
            else [int(history.cells.shape[1])],
            "element": scenario.block.element,
            "dofs": int(history.dim * history.nodes.shape[1]),
            "contact_points": int(history.x.shape[0]),
        },
        "results": {
            "rows": history.n_rows,
            "peak_tangential_force": float(history.tangential_force[peak]),
            "peak_tangential_force_y": float(history.tangential_force_y[peak]),
            "peak_friction_ratio": float(history.friction_ratio[peak]),
            "peak_top_displacement": float(history.top_displacement[peak]),
            "peak_time": float(history.time[peak]),
            "final_friction_ratio": float(history.friction_ratio[-1]),
            "front_arrival": front_arrival(history, scenario.front_ratio),
        },
        "solver": {
            "steps": int(steps.size),
            "iterations_per_step": history.iterations.tolist(),
            "cuts_per_step": history.cuts.tolist(),
            "total_iterations": int(steps.sum()),
            "max_iterations_in_a_step": int(steps.max(initial=0)),
            "mean_iterations_sliding": float(history.iterations[sliding].mean())
            if sliding.any()
            else 0.0,
            "relative_residuals_per_step": history.residuals,
        },
        "units": {
            "forces": "N/m (per unit depth of the plane-strain block)" if history.dim == 2 else "N",
            "lengths": "m",
        },
        "provenance": {
            "frictionlab": __version__,
            "python": platform.python_version(),
            "numpy": np.__version__,
            "scipy": scipy.__version__,
            "scikit-fem": skfem_version,
            "created_utc": _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
            "wall_time_s": elapsed,
        },
        "files": files,
    }


def _files(
    out: Path, scenario: ContactScenario, history: ContactHistory, plots: bool
) -> list[Path]:
    """Write the CSV tables and the plots; return the paths (the summary comes after)."""
    head = (
        f"frictionlab {__version__} contact run of '{scenario.title or scenario.source}'\n"
        f"forces per unit depth; success = {str(history.success).lower()}"
    )
    written = []
    cols, units = _global_columns(history, scenario.front_ratio)
    written.append(write_csv_atomic(out / "global.csv", cols, units, head))
    cols, units = _interface_columns(history, getattr(scenario.params, "is_cone", False))
    written.append(write_csv_atomic(out / "interface.csv", cols, units, head))
    if plots and history.n_rows > 1:
        written.extend(_plots(out, scenario, history))
    return written


def discretise_scenario(scenario: ContactScenario) -> Discretisation:
    """The scenario's mesh: its [mesh] file assembled, or its [block] meshed."""
    if scenario.mesh is not None:
        from frictionlab.schema.contact import mesh_keys

        mesh = scenario.mesh
        return mesh_keys(lambda: mesh.discretise(scenario.block))
    from frictionlab.contact import discretise

    return discretise(scenario.block)


def scenario_law(scenario: ContactScenario, disc: Discretisation) -> Any:
    """The law at the contact points of ``disc`` ([law_table] and [[law_region]] resolved)."""
    if not scenario.law_field:
        return scenario.params
    from frictionlab.errors import InputError, ParameterError

    try:
        mesh = scenario.mesh
        groups = {
            r.group: mesh.points_in(r.group, disc)
            for r in scenario.law_field.regions
            if r.group is not None and mesh is not None
        }
        return scenario.law_field.resolve(scenario.params, disc.contact_xy, groups)  # type: ignore[arg-type]
    except ParameterError as exc:  # a table short of the face, a mix no point can take
        if exc.field.startswith("["):
            raise InputError(str(exc)) from None
        raise InputError(
            f"[law] with [law_table]/[[law_region]] at the contact points: {exc}"
        ) from None


def run_contact_scenario(
    scenario: ContactScenario,
    progress: Callable[[int, int], None] | None = None,
    discretisation: Discretisation | None = None,
) -> ContactHistory:
    """Run a parsed contact scenario (a failed step is a history with success False).

    With ``scenario.fields`` the nodal displacement of every row is kept (field output).
    """
    from frictionlab.contact import run_contact

    disc = discretisation
    if disc is None and (scenario.mesh is not None or scenario.law_field):
        disc = discretise_scenario(scenario)
    params = scenario.params if disc is None else scenario_law(scenario, disc)
    return run_contact(
        scenario.block, params, scenario.normal, scenario.program,
        settings=scenario.options, drive=scenario.drive, progress=progress,
        discretisation=disc, base=scenario.base,
        record_displacement=scenario.fields,
    )  # fmt: skip


def _field_files(out: Path, history: ContactHistory, disc: Discretisation) -> list[Path]:
    """[output] fields: fields/block.pvd and fields/interface.pvd (a .vtu per row)."""
    from frictionlab.contact.fields import field_frames
    from frictionlab.io.mesh_files import write_field_series

    frames = field_frames(history, disc)
    folder = out / "fields"
    return [
        write_field_series(folder, "block", [(f.time, f.block) for f in frames]),
        write_field_series(folder, "interface", [(f.time, f.interface) for f in frames]),
    ]


class Contact(WorkflowBase):
    """``frictionlab contact SCENARIO.toml --out DIR`` (:mod:`frictionlab.commands.contact`)."""

    name = "contact"

    def __init__(self) -> None:
        self._meshes: dict[int, Discretisation] = {}  # a run's mesh, for its field files

    def parse(self, args: argparse.Namespace, out: Path) -> ContactScenario:
        from frictionlab.app.budget import check_contact
        from frictionlab.contact._fem import require_skfem
        from frictionlab.schema.contact import load_contact

        scenario = load_contact(args.scenario, args.set)  # every input check is here
        check_contact(scenario)  # the solver's memory and time, before meshing
        require_skfem()
        return scenario

    def run(self, job: ContactScenario, progress: ProgressFactory, staging: Path) -> ContactHistory:
        name = Path(job.source).name if job.source else "scenario"
        disc = None
        if job.fields or job.mesh is not None or job.law_field:
            disc = discretise_scenario(job)
            self._meshes[id(job)] = disc  # again for the field files
        with progress(f"contact {name}") as update:
            return run_contact_scenario(job, update, disc)

    def files(
        self, job: ContactScenario, result: ContactHistory, out: Path, plots: bool
    ) -> list[Path]:
        written = _files(out, job, result, plots)
        disc = self._meshes.pop(id(job), None)
        if job.fields:
            if disc is None:  # written without run() (write_contact_results)
                disc = discretise_scenario(job)
            written.extend(_field_files(out, result, disc))
        return written

    def summary(
        self, job: ContactScenario, result: ContactHistory, files: list[str], seconds: float
    ) -> dict[str, Any]:
        return contact_summary(job, result, seconds, files)

    def inputs(self, job: ContactScenario) -> list[Path]:
        return [Path(job.source)] if job.source else []

    def report(
        self, job: ContactScenario, history: ContactHistory, seconds: float, written: list[Path]
    ) -> None:
        peak = history.peak_index
        steps = history.iterations[1:]
        print(
            f"{history.n_rows - 1} steps in {seconds:.2f} s, {int(steps.sum())} Newton "
            f"iterations (at most {int(steps.max(initial=0))} in a step)"
        )
        print(
            f"peak Q/P = {history.friction_ratio[peak]:.4f} at a top travel of "
            f"{history.travel[peak] * 1e6:.3g} um; final Q/P = "
            f"{history.friction_ratio[-1]:.4f}"
        )
        arrival = front_arrival(history, job.front_ratio)
        if arrival is not None:
            print(
                f"the sliding zone spans the interface at {100 * arrival['fraction_of_peak']:.1f}"
                f" % of the peak force (t = {arrival['time']:.4g} s)"
            )
        super().report(job, history, seconds, written)

    def failure(self, job: ContactScenario, history: ContactHistory, out: Path) -> str | None:
        if history.success:
            return None
        return f"{history.message}; the rows up to the failure are in {out / 'global.csv'}"


#: The contact workflow.
CONTACT = Contact()


def write_contact_results(
    out_dir: str | os.PathLike[str],
    scenario: ContactScenario,
    history: ContactHistory,
    elapsed: float,
    plots: bool = True,
) -> list[Path]:
    """Write the CSV tables, the plots and summary.json (last); return the paths."""
    return write_outputs(CONTACT, scenario, history, Path(out_dir), plots=plots, seconds=elapsed)


def _plots(out: Path, scenario: ContactScenario, history: ContactHistory) -> list[Path]:
    from frictionlab.plotting.contact import (
        plot_contact_friction,
        plot_deformed_mesh,
        plot_interface_map,
        plot_traction_path,
    )
    from frictionlab.plotting.law import save_figure

    paths = [
        save_figure(plot_contact_friction(history, scenario.title), out / "friction.png"),
        save_figure(
            plot_interface_map(history, scenario.front_ratio, scenario.title),
            out / "interface_map.png",
        ),
    ]
    if history.dim == 2:
        paths.append(save_figure(plot_deformed_mesh(history), out / "deformed_mesh.png"))
    else:
        paths.append(save_figure(plot_traction_path(history), out / "traction_path.png"))
    return paths
