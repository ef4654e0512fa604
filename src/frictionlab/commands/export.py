"""``frictionlab export abaqus SCENARIO.toml --out DIR``: the scenario's law for Abaqus.

Writes the user-subroutine source (the law's C core with UINTER and VUINTER), the PROPS
and STATEV tables with units and meaning, ``.inp`` fragments for Abaqus/Standard and
Abaqus/Explicit, a README (how to compile and run) and summary.json. Only ``[law]`` and
the initial size F of ``[initial]`` are used; no compiler is needed to export. The
workflow is :mod:`frictionlab.app.export`.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_run_arguments, workflow_handler

HELP = "write the scenario's law as an Abaqus user interaction (UINTER/VUINTER, C)"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("export", help=HELP, description=HELP)
    parser.add_argument("target", choices=("abaqus",), help="the FE code (abaqus)")
    add_run_arguments(parser, "scenario file (TOML) whose [law] is exported", "law.mu_s=0.6",
                      plots=False, quiet_help="print nothing")  # fmt: skip
    parser.set_defaults(handler=workflow_handler("frictionlab.app.export:EXPORT"))
