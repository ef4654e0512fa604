"""``frictionlab roughness SCENARIO.toml --out DIR``: mu(beta) of two rough surfaces.

Writes polar.csv, summary.json and polar.png, plus the files of the scenario's optional
tables ([adhesion], [wear], [hierarchy], [multiscale]); the workflow and the files are
described in :mod:`frictionlab.app.roughness`. Bad input is one line and exit code 2
before anything is written.
"""

from __future__ import annotations

import argparse
from typing import Any

from frictionlab.commands._output import add_overwrite, workflow_handler

__all__ = ["add_parser"]


def add_parser(subparsers: Any) -> argparse.ArgumentParser:
    """Register the ``roughness`` subcommand."""
    parser = subparsers.add_parser(
        "roughness",
        help="anisotropic friction mu(beta) of two rough surfaces (lattice-spring model)",
        description=(
            "Compute mu_x, mu_y and mu(beta) of two rough surfaces with the lattice-spring "
            "model and write polar.csv, summary.json and polar.png into --out."
        ),
    )
    parser.add_argument("scenario", help="scenario TOML file")
    parser.add_argument("--out", required=True, metavar="DIR", help="output directory")
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="SECTION.KEY=VALUE",
        help="override a scenario value, e.g. --set lattice.time_samples=100 (repeatable)",
    )
    parser.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    parser.add_argument(
        "--quiet", action="store_true", help="no progress bar, warnings or summary line"
    )
    add_overwrite(parser)
    parser.set_defaults(handler=workflow_handler("frictionlab.app.roughness:ROUGHNESS"))
    return parser
