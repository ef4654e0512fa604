"""Outputs of ``frictionlab contact``: global.csv, interface.csv, plots, summary.json.

Every file is written atomically; summary.json is written last, so its presence means
the others are complete. A failed run writes the rows computed before the failure.
"""

from __future__ import annotations

import datetime as _dt
import os
import platform
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._version import __version__
from frictionlab.contact.history import ContactHistory, front_arrival, slip_front
from frictionlab.driver.simulate import status_labels
from frictionlab.io.atomic import write_json_atomic
from frictionlab.io.contact_scenario import ContactScenario
from frictionlab.io.tables import write_csv_atomic

__all__ = ["contact_summary", "write_contact_results"]


def _global_columns(
    history: ContactHistory, ratio: float
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    cols = {
        "time": history.time,
        "stage": history.stage,
        "top_displacement": history.top_displacement,
        "top_shear": history.top_shear,
        "tangential_force": history.tangential_force,
        "normal_force": history.normal_force,
        "friction_ratio": history.friction_ratio,
        "slip_front": slip_front(history, ratio),
        "iterations": history.iterations,
        "cuts": history.cuts,
    }
    units = {
        "time": "s", "top_displacement": "m", "top_shear": "Pa", "tangential_force": "N/m",
        "normal_force": "N/m", "slip_front": "m",
    }  # fmt: skip
    return cols, units


def _interface_columns(
    history: ContactHistory, cone: bool
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    S, P = history.R.shape
    cols = {
        "row": np.repeat(np.arange(S), P),
        "time": np.repeat(history.time, P),
        "x": np.tile(history.x, S),
        "slip": history.slip.ravel(),
        "approach": history.approach.ravel(),
        "plastic_slip": history.plastic_slip.ravel(),
        "traction_t": history.traction_t.ravel(),
        "traction_n": history.traction_n.ravel(),
        "R": history.R.ravel(),
        "F": history.F.ravel(),
        "status": status_labels(history.status.ravel()),
    }
    units = {
        "time": "s", "x": "m", "slip": "m", "approach": "m", "plastic_slip": "m",
        "traction_t": "Pa", "traction_n": "Pa", "F": "1" if cone else "Pa",
    }  # fmt: skip
    return cols, units


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
            "cells": list(scenario.block.cells),
            "element": scenario.block.element,
            "dofs": int(2 * history.nodes.shape[1]),
            "contact_points": int(history.x.shape[0]),
        },
        "results": {
            "rows": history.n_rows,
            "peak_tangential_force": float(history.tangential_force[peak]),
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
            "final_relative_residuals": [r[-1] if r else 0.0 for r in history.residuals],
        },
        "units": {"forces": "N/m (per unit depth of the plane-strain block)", "lengths": "m"},
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


def write_contact_results(
    out_dir: str | os.PathLike[str],
    scenario: ContactScenario,
    history: ContactHistory,
    elapsed: float,
    plots: bool = True,
) -> list[Path]:
    """Write the CSV tables, the plots and summary.json (last); return the paths."""
    out = Path(out_dir)
    cone = scenario.params.is_cone
    head = (
        f"frictionlab {__version__} contact run of '{scenario.title or scenario.source}'\n"
        f"forces per unit depth; success = {str(history.success).lower()}"
    )
    written = []
    cols, units = _global_columns(history, scenario.front_ratio)
    written.append(write_csv_atomic(out / "global.csv", cols, units, head))
    cols, units = _interface_columns(history, cone)
    written.append(write_csv_atomic(out / "interface.csv", cols, units, head))
    if plots and history.n_rows > 1:
        written.extend(_plots(out, scenario, history))
    names = [p.name for p in written] + ["summary.json"]
    summary = contact_summary(scenario, history, elapsed, names)
    written.append(write_json_atomic(out / "summary.json", summary))
    return written


def _plots(out: Path, scenario: ContactScenario, history: ContactHistory) -> list[Path]:
    from frictionlab.plotting.contact import (
        plot_contact_friction,
        plot_deformed_mesh,
        plot_interface_map,
    )
    from frictionlab.plotting.law import save_figure

    return [
        save_figure(plot_contact_friction(history, scenario.title), out / "friction.png"),
        save_figure(
            plot_interface_map(history, scenario.front_ratio, scenario.title),
            out / "interface_map.png",
        ),
        save_figure(plot_deformed_mesh(history), out / "deformed_mesh.png"),
    ]
