"""``frictionlab bridge SCENARIO.toml --out DIR``: from two rough surfaces to a runnable law.

Computes the lattice-spring polar mu(beta) over the full circle, fits the anisotropy of the
subloading-friction law to it (:func:`frictionlab.bridge.fit_anisotropy`), builds the fitted
law, writes it as a scenario that ``frictionlab simulate`` runs as it is, runs that very
scenario (steady sliding in every direction of the polar) and compares the simulated steady
tractions with the law's closed form. Writes ``fitted_law.toml``, ``directions.csv``,
``bridge.png`` and ``bridge.json`` (last) into ``--out``, each atomically and only after
everything is computed.

Exit codes: 2 bad input (one line naming the key; nothing written), 1 failed computation
(no valid law fits, the check simulation fails, or it misses the closed form), 0 success;
a polar the law cannot express is a success with a sentence in ``bridge.json`` and on the
terminal.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from contextlib import AbstractContextManager
from pathlib import Path

import numpy as np

from frictionlab.commands._output import add_run_arguments
from frictionlab.commands._progress import progress_bar

HELP = "fit the law's anisotropy to the roughness polar mu(beta) and write a runnable law"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser(
        "bridge",
        help=HELP,
        description=(
            "Compute mu(beta) of two rough surfaces over the full circle (lattice-spring "
            "model), fit the subloading-friction law's orthotropy and rotation vector to it, "
            "check the fitted law by simulated steady sliding, and write bridge.json, "
            "fitted_law.toml (runnable by `frictionlab simulate`), directions.csv and "
            "bridge.png into --out."
        ),
    )
    add_run_arguments(parser, "bridge scenario file (TOML)", "bridge.scale=roughness", plots=False)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Run the command; returns the exit code (errors propagate to ``cli.main``)."""
    from frictionlab.io.bridge_results import run_bridge, write_bridge
    from frictionlab.io.bridge_scenario import parse_bridge_scenario
    from frictionlab.io.config import apply_overrides, load_toml
    from frictionlab.io.output_set import check_out, output_set

    path: Path = args.scenario
    out = check_out(args.out, args.overwrite)
    scenario = parse_bridge_scenario(apply_overrides(load_toml(path), args.set), path.parent)

    def progress(description: str) -> AbstractContextManager[Callable[[int, int], None]]:
        return progress_bar(description, enabled=not args.quiet)

    with output_set(out, args.overwrite) as oset:
        result = run_bridge(scenario, path, progress)
        written = [oset.shown(p) for p in write_bridge(oset.staging, result)]
    fit = result.fit
    if not args.quiet:
        beta = np.asarray(result.law.params.rotation)
        print(
            f"frictionlab bridge: {fit.beta_deg.size} directions; rotation = "
            f"[{beta[0]:.6g}, {beta[1]:.6g}], orthotropy = [1, {fit.orthotropy[1]:.6g}], "
            f"e*_1 at {fit.orthotropy_angle_deg:.4g} deg; rms misfit {fit.rms_misfit:.3g} "
            f"({fit.relative_rms_misfit:.2%} of the mean friction), max {fit.max_misfit:.3g} "
            f"at beta = {fit.beta_at_max_misfit_deg:g} deg"
        )
        print(
            f"steady sliding at {scenario.options.velocity:g} m/s in {fit.beta_deg.size} "
            f"directions: simulated vs closed form, largest difference "
            f"{result.difference.max():.2e} in f_t/f_n"
        )
        print("wrote " + ", ".join(str(p) for p in written))
    if not fit.expressible:
        print(f"frictionlab bridge: {fit.note}", file=sys.stderr)
    if not result.check_passed:
        print(
            "frictionlab: computation failed: the simulated steady sliding differs from the "
            f"law's closed form by {result.difference.max():.3g} in f_t/f_n (> "
            f"[bridge].check_tolerance = {scenario.options.check_tolerance:g}); increase "
            "[bridge].distance or [bridge].steps",
            file=sys.stderr,
        )
        return 1
    return 0
