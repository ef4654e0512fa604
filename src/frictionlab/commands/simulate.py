"""``frictionlab simulate SCENARIO.toml --out DIR``: run one scenario file.

Writes ``DIR/history.csv`` (streamed to disk chunk by chunk while a programme runs, so
memory stays bounded whatever the number of steps; ``[output] every`` and ``points``
choose the rows), ``DIR/points.csv``, ``DIR/summary.json``, ``DIR/friction.png`` and,
for 2-D programmes, ``DIR/traction_path.png``. Bad input (a wrong key or
type, a missing value, an unknown surface or segment kind, a physically invalid
parameter, an unreadable file) is reported on one line with exit code 2 before
anything is written; a failed computation exits 1 and keeps the history computed so far.
The files are written as one set (:mod:`frictionlab.io.output_set`): ``DIR`` holds either
the complete earlier set or the complete new one, never a mixture. The workflow is
:mod:`frictionlab.app.simulate`.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_workflow_parser

HELP = "run a scenario file (TOML) and write history.csv, summary.json and plots"


def add_parser(sub: argparse._SubParsersAction) -> None:
    add_workflow_parser(
        sub, "simulate", HELP, "frictionlab.app.simulate:SIMULATE", "scenario file (TOML)",
        "law.mu_s=0.6 or --set program.2.steps=50",
    )  # fmt: skip
