"""The demo's bridge section: two rough surfaces -> a fitted, runnable law.

Runs the bundled bridge scenario ``frictionlab/data/bridge/ratchet.toml`` through the same
code path as ``frictionlab bridge`` (outputs in ``OUT/bridge/``), then the fitted law it
wrote through the same code path as ``frictionlab simulate`` (``OUT/bridge/fitted_law/``,
four of its sliding directions), and returns a report section.
"""

from __future__ import annotations

import contextlib
import json
import os
import time
from pathlib import Path

import numpy as np

from frictionlab.app.bridge import run_bridge, write_bridge
from frictionlab.app.simulate import run_scenario, write_results
from frictionlab.demo import DemoContext, bundled_scenario, law_rows
from frictionlab.errors import FrictionlabError
from frictionlab.io.atomic import write_json_atomic, write_text_atomic
from frictionlab.io.report import Section, format_value
from frictionlab.schema.bridge import load_bridge
from frictionlab.schema.scenario import load_scenario

__all__ = ["BRIDGE_SECTIONS", "bridge_section", "bundled_bridge_scenario"]

#: Sliding directions (deg) of the fitted law's friction curves in the report.
CURVE_DIRECTIONS = (0.0, 90.0, 180.0, 270.0)


def bundled_bridge_scenario(name: str) -> contextlib.AbstractContextManager[Path]:
    """A filesystem path to the bundled bridge scenario ``name`` (e.g. ``"ratchet"``)."""
    return bundled_scenario(name, "bridge")


#: The fitted law's rows of the report: (key, unit).
_LAW_KEYS = (("mu_s", "-"), ("mu_k", "-"), ("alpha_t", "Pa/m"), ("u", "1/m"), ("kappa", "1/m"),
             ("xi", "1/s"))  # fmt: skip


def _relative_source(summary_path: Path, source: Path) -> None:
    """Record ``source`` in a summary relative to the summary's folder.

    The demo writes into the output set's staging directory, which is renamed when the set
    is published: an absolute path recorded there would name a directory that no longer
    exists. ``../fitted_law.toml`` stays true wherever the output set is moved.
    """
    summary = json.loads(summary_path.read_text(encoding="utf-8"))
    relative = os.path.relpath(source, summary_path.parent)
    if summary.get("scenario") == str(source):
        summary["scenario"] = relative
    for item in summary.get("provenance", {}).get("inputs", []):
        if item.get("path") == str(source):
            item["path"] = relative
    write_json_atomic(summary_path, summary)


def bridge_section(ctx: DemoContext) -> Section:
    """From roughness to a runnable law: the bridge"""
    rel = "bridge"
    out = ctx.out_dir / rel
    with bundled_bridge_scenario("ratchet") as path:
        text = path.read_text(encoding="utf-8")
        scenario = load_bridge(path)
        run = run_bridge(scenario, path, ctx.progress)
    if not run.check_passed:
        raise FrictionlabError(
            f"demo bridge: simulated steady sliding misses the closed form by "
            f"{run.difference.max():.3g}"
        )
    write_bridge(out, run)
    write_text_atomic(out / "bridge_scenario.toml", text)
    directions = "[" + ", ".join(f"{d:g}" for d in CURVE_DIRECTIONS) + "]"
    override = f"program.1.direction_deg={directions}"
    fitted = load_scenario(out / "fitted_law.toml", [override])
    start = time.perf_counter()
    with ctx.progress("bridge: fitted law") as progress:
        history = run_scenario(fitted, progress=progress)
    if not history.success:
        raise FrictionlabError(f"demo bridge: the fitted law failed: {history.message}")
    write_results(out / "fitted_law", fitted, history, time.perf_counter() - start)
    _relative_source(out / "fitted_law" / "summary.json", out / "fitted_law.toml")
    write_text_atomic(
        out / "fitted_law" / "scenario.toml",
        f"# The demo ran ../fitted_law.toml with: --set {override}\n"
        + (out / "fitted_law.toml").read_text(encoding="utf-8"),
    )

    fit, law = run.fit, run.law
    params = law.params
    mu_k = float(np.ravel(params.mu_k)[0])
    # values at the solver's round-off level are shown as 0
    beta = np.asarray(params.rotation)
    beta = np.where(np.abs(beta) < 1e-9 * mu_k, 0.0, beta)
    angle = fit.orthotropy_angle_deg if abs(fit.orthotropy_angle_deg) > 1e-5 else 0.0
    sec = Section(
        "From roughness to a runnable law: the bridge",
        "frictionlab bridge computes the lattice-spring polar mu(beta) of two rough surfaces "
        "over the full circle, fits the subloading-friction law's anisotropy to it "
        "(orthotropy axes and C_1/C_2, rotation vector beta) by least squares on the friction "
        "vectors, and writes the fitted law as a scenario that frictionlab simulate runs as "
        "it is. Here a flat slider on a saw-tooth with steep rising faces (45 deg) and "
        "gentle falling faces (15 deg): a ratchet, which resists sliding along +x more than "
        "along -x, and a ridged surface, which resists across the ridges more than along "
        "them. The law takes its kinetic friction from the roughness (scale = roughness) and "
        "its static friction, healing and slip scales from the [law] table.",
        law=law_rows(params, _LAW_KEYS),  # the report compares them with the first law table
        parameters=_parameters(run),
    )
    sec.add_figure(
        f"{rel}/bridge.png",
        "The roughness polar (points) and the fitted law's kinetic polar (line): |mu| "
        "against the sliding direction (left), the friction component along the sliding "
        "direction minus its mean (middle: larger at 0 than at 180 deg, the ratchet, fitted "
        "by a rotation vector beta along +x) and the lateral component (right), with the "
        "fitted law's steady polar at 1 mm/s in closed form (dashed) and the driver's "
        "simulated steady sliding (crosses) on it.",
    )
    sec.add_figure(
        f"{rel}/fitted_law/friction.png",
        "The fitted law run by the simulate code path in four sliding directions: a static "
        "peak, then softening to a kinetic value that is highest along +x (0 deg), lower "
        "along -x (180 deg) and lowest along the ridges (90 and 270 deg).",
    )
    sec.notes.append(
        f"Fitted: rotation beta = ({beta[0]:.5f}, {beta[1]:.5f}), orthotropy C = (1, "
        f"{fit.orthotropy[1]:.5f}) with e*_1 at {angle:.4g} deg, mu_k = {mu_k:.5f}; rms "
        f"misfit {fit.rms_misfit:.2g} "
        f"({fit.relative_rms_misfit:.2%} of the mean friction), largest "
        f"{fit.max_misfit:.2g} at beta = {fit.beta_at_max_misfit_deg:g} deg. Steady sliding "
        f"of the fitted law in {fit.beta_deg.size} directions: simulated against the closed "
        f"form, largest difference {run.difference.max():.1e} in f_t/f_n. "
        + (fit.note or "The law expresses this polar within the tolerance.")
    )
    return sec


def _parameters(run: object) -> list[tuple[str, str, str]]:
    from frictionlab.app.bridge import BridgeRun

    assert isinstance(run, BridgeRun)
    sc = run.scenario
    r = sc.roughness
    opts = sc.options
    rows = [
        ("mu0 (local Coulomb coefficient)", format_value(r.mu0), "-"),
        ("lower surface", f"{r.lower.kind} {r.lower.describe().get('angles_deg', '')}", "deg"),
        ("upper surface", r.upper.kind, ""),
        ("directions of the polar", f"{run.fit.beta_deg.size} (every {opts.step_deg:g} deg)", ""),
        ("scale", opts.scale, ""),
        ("fitted", ", ".join(run.fit.fitted_groups), ""),
    ]
    rows += [
        ("check velocity", format_value(opts.velocity), "m/s"),
        ("normal traction f_n", format_value(opts.normal_traction), "Pa"),
    ]
    return rows


#: The bridge's demo sections, in report order.
BRIDGE_SECTIONS = (bridge_section,)
