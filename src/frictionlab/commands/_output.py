"""The ``--overwrite`` flag shared by the commands that write an output set."""

from __future__ import annotations

import argparse


def add_overwrite(parser: argparse.ArgumentParser) -> None:
    """Add ``--overwrite``: replace an --out directory that is not a frictionlab set."""
    parser.add_argument(
        "--overwrite",
        action="store_true",
        help="replace --out as a whole even when it holds files frictionlab did not write "
        "(an earlier frictionlab output set there is always replaced as a whole)",
    )
