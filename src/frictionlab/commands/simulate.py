"""``frictionlab simulate SCENARIO.toml --out DIR``: run one scenario file.

Writes ``DIR/history.csv`` (streamed to disk chunk by chunk while a programme runs, so
memory stays bounded whatever the number of steps; ``[output] every`` and ``points``
choose the rows), ``DIR/points.csv``, ``DIR/summary.json``, ``DIR/friction.png`` and,
for 2-D programmes, ``DIR/traction_path.png``. Bad input (a wrong key or
type, a missing value, an unknown surface or segment kind, a physically invalid
parameter, an unreadable file) is reported on one line with exit code 2 before
anything is written; a failed computation exits 1 and keeps the history computed so far.
The files are written as one set (:mod:`frictionlab.io.output_set`): ``DIR`` holds either
the complete earlier set or the complete new one, never a mixture.
"""

from __future__ import annotations

import argparse
import sys
import time

from frictionlab.commands._output import add_run_arguments
from frictionlab.commands._progress import progress_bar

HELP = "run a scenario file (TOML) and write history.csv, summary.json and plots"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("simulate", help=HELP, description=HELP)
    add_run_arguments(parser, "scenario file (TOML)", "law.mu_s=0.6 or --set program.2.steps=50")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.io.budget import check_output_space
    from frictionlab.io.output_set import check_out, output_set
    from frictionlab.io.results import PLOT_ROWS, HistoryStream, write_results
    from frictionlab.io.scenario import load_scenario
    from frictionlab.plotting.law import shown_points

    out = check_out(args.out, args.overwrite)
    scenario = load_scenario(args.scenario, args.set)  # every input check happens here
    if scenario.estimate is not None:  # and the output's size against the free disk space
        check_output_space(scenario.estimate, out, scenario.run_options.allow_large)
    with output_set(out, args.overwrite) as oset:
        start = time.perf_counter()
        stream = None
        with progress_bar(f"simulate {args.scenario.name}", enabled=not args.quiet) as progress:
            if scenario.kind == "program":
                path = oset.staging / "history.csv"
                shown = shown_points(scenario.output.recorded_points(scenario.n_points))
                with HistoryStream(path, cone=scenario.params.is_cone) as stream:
                    history = scenario.run(progress, stream, PLOT_ROWS, shown.tolist())
            else:
                history = scenario.run(progress=progress)
        elapsed = time.perf_counter() - start
        paths = write_results(
            oset.staging, scenario, history, elapsed, plots=not args.no_plots, streamed=stream
        )
        paths = [oset.shown(p) for p in paths]
    if not args.quiet:
        _report(scenario.labels, history, elapsed)
        print("wrote " + ", ".join(str(p) for p in paths))
    for warning in history.warnings:
        print(f"frictionlab: warning: {warning}", file=sys.stderr)
    if not history.success:
        print(
            f"frictionlab: computation failed: {history.message}; the history up to the "
            f"failure is in {out / 'history.csv'}",
            file=sys.stderr,
        )
        return 1
    return 0


def _report(labels: tuple[str, ...], history: object, elapsed: float) -> None:
    from frictionlab.driver import History
    from frictionlab.io.results import point_figures

    assert isinstance(history, History)
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
    from frictionlab.driver.healing import healing_analysis

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
