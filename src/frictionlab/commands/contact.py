"""``frictionlab contact SCENARIO.toml --out DIR``: the finite-element contact model.

Writes ``DIR/global.csv``, ``DIR/interface.csv``, ``DIR/friction.png``,
``DIR/interface_map.png``, ``DIR/deformed_mesh.png`` and ``DIR/summary.json`` (each
atomically). Bad input is one line and exit code 2 before anything is written; a step
that Newton cannot solve even after cutting it exits 1 and keeps the rows before it.
The workflow is :mod:`frictionlab.app.contact`.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_workflow_parser

HELP = "run the finite-element contact model (a block on a rigid base) from a TOML file"


def add_parser(sub: argparse._SubParsersAction) -> None:
    add_workflow_parser(sub, "contact", HELP, "frictionlab.app.contact:CONTACT",
                        "contact scenario file (TOML)", "block.element_size=0.005")  # fmt: skip
