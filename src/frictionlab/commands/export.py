"""``frictionlab export abaqus SCENARIO.toml --out DIR``: the scenario's law for Abaqus.

Writes the user-subroutine source (the law's C core with UINTER and VUINTER), the PROPS
and STATEV tables with units and meaning, ``.inp`` fragments for Abaqus/Standard and
Abaqus/Explicit and a README (how to compile and run). Only ``[law]`` and the initial
size F of ``[initial]`` are used. No compiler is needed to export.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_run_arguments

HELP = "write the scenario's law as an Abaqus user interaction (UINTER/VUINTER, C)"
TARGETS = ("abaqus",)


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("export", help=HELP, description=HELP)
    parser.add_argument("target", choices=TARGETS, help="the FE code (abaqus)")
    add_run_arguments(parser, "scenario file (TOML) whose [law] is exported", "law.mu_s=0.6",
                      plots=False, quiet_help="print nothing")  # fmt: skip
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    import numpy as np

    from frictionlab.errors import ParameterError
    from frictionlab.export.abaqus import props_vector, write_files
    from frictionlab.io.output_set import check_out, output_set
    from frictionlab.io.scenario import load_scenario

    out = check_out(args.out, args.overwrite)
    scenario = load_scenario(args.scenario, args.set)
    F0 = scenario.initial.F
    if F0 is not None and np.unique(np.asarray(F0, dtype=float)).size > 1:
        raise ParameterError("initial.F", F0, "one value: an Abaqus interaction has one PROPS set")
    F0 = None if F0 is None else float(np.asarray(F0, dtype=float).ravel()[0])
    props_vector(scenario.params, F0)  # refuses per-point values before anything is written
    with output_set(out, args.overwrite) as oset:
        paths = write_files(oset.staging, scenario.params, scenario.title, F0)
        paths = [oset.shown(p) for p in paths]
    if not args.quiet:
        print("wrote " + ", ".join(str(p) for p in paths))
    return 0
