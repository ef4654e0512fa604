"""``frictionlab contact SCENARIO.toml --out DIR``: the finite-element contact model.

Writes ``DIR/global.csv``, ``DIR/interface.csv``, ``DIR/friction.png``,
``DIR/interface_map.png``, ``DIR/deformed_mesh.png`` and ``DIR/summary.json`` (each
atomically). Bad input is one line and exit code 2 before anything is written; a step
that Newton cannot solve even after cutting it exits 1 and keeps the rows before it.
The workflow is :mod:`frictionlab.app.contact`.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_run_arguments

HELP = "run the finite-element contact model (a block on a rigid base) from a TOML file"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("contact", help=HELP, description=HELP)
    add_run_arguments(parser, "contact scenario file (TOML)", "block.element_size=0.005")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.app.contact import CONTACT
    from frictionlab.commands._pipeline import run_command

    return run_command(CONTACT, args)
