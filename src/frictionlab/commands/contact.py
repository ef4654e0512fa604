"""``frictionlab contact SCENARIO.toml --out DIR``: the finite-element contact model.

Writes ``DIR/global.csv``, ``DIR/interface.csv``, ``DIR/friction.png``,
``DIR/interface_map.png``, ``DIR/deformed_mesh.png`` and ``DIR/summary.json`` (each
atomically). Bad input is one line and exit code 2 before anything is written; a step
that Newton cannot solve even after cutting it exits 1 and keeps the rows before it.
"""

from __future__ import annotations

import argparse
import sys
import time

from frictionlab.commands._output import add_run_arguments

HELP = "run the finite-element contact model (a block on a rigid base) from a TOML file"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("contact", help=HELP, description=HELP)
    add_run_arguments(parser, "contact scenario file (TOML)", "block.element_size=0.005")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.commands._progress import progress_bar
    from frictionlab.contact import front_arrival, run_contact
    from frictionlab.contact._fem import require_skfem
    from frictionlab.io.contact_results import write_contact_results
    from frictionlab.io.contact_scenario import load_contact_scenario
    from frictionlab.io.output_set import check_out, output_set

    out = check_out(args.out, args.overwrite)
    scenario = load_contact_scenario(args.scenario, args.set)  # every input check is here
    require_skfem()
    with output_set(out, args.overwrite) as oset:
        from frictionlab.contact import discretise

        start = time.perf_counter()
        disc = discretise(scenario.block)
        with progress_bar(f"contact {args.scenario.name}", enabled=not args.quiet) as progress:
            history = run_contact(
                scenario.block,
                scenario.params,
                scenario.normal,
                scenario.program,
                options=scenario.options,
                drive=scenario.drive,
                base=scenario.base,
                discretisation=disc,
                record_displacement=scenario.fields,
                progress=(lambda fraction: progress(round(1000 * fraction), 1000)),
            )
        elapsed = time.perf_counter() - start
        paths = write_contact_results(
            oset.staging, scenario, history, elapsed, plots=not args.no_plots
        )
        if scenario.fields:  # [output] fields: .vtu per step + .pvd for ParaView
            from frictionlab.contact.fields import field_frames
            from frictionlab.io.mesh_files import write_field_series

            frames = field_frames(history, disc)
            folder = oset.staging / "fields"
            paths.append(write_field_series(folder, "block", [(f.time, f.block) for f in frames]))
            paths.append(
                write_field_series(folder, "interface", [(f.time, f.interface) for f in frames])
            )
        paths = [oset.shown(p) for p in paths]
    if not args.quiet:
        peak = history.peak_index
        steps = history.iterations[1:]
        print(
            f"{history.n_rows - 1} steps in {elapsed:.2f} s, {int(steps.sum())} Newton "
            f"iterations (at most {int(steps.max(initial=0))} in a step)"
        )
        print(
            f"peak Q/P = {history.friction_ratio[peak]:.4f} at a top travel of "
            f"{history.travel[peak] * 1e6:.3g} um; final Q/P = "
            f"{history.friction_ratio[-1]:.4f}"
        )
        arrival = front_arrival(history, scenario.front_ratio)
        if arrival is not None:
            print(
                f"the sliding zone spans the interface at {100 * arrival['fraction_of_peak']:.1f}"
                f" % of the peak force (t = {arrival['time']:.4g} s)"
            )
        print("wrote " + ", ".join(str(p) for p in paths))
    if not history.success:
        print(
            f"frictionlab: computation failed: {history.message}; the rows up to the failure "
            f"are in {out / 'global.csv'}",
            file=sys.stderr,
        )
        return 1
    return 0
