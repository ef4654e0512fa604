"""Arguments shared by the commands that read a TOML file and write an output set."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_overwrite(parser: argparse.ArgumentParser) -> None:
    """Add ``--overwrite``: replace an --out directory that is not a frictionlab set."""
    parser.add_argument(
        "--overwrite",
        action="store_true",
        help="replace --out as a whole even when it holds files frictionlab did not write "
        "(an earlier frictionlab output set there is always replaced as a whole)",
    )


def add_run_arguments(
    parser: argparse.ArgumentParser,
    input_help: str,
    set_example: str,
    *,
    input_name: str = "scenario",
    plots: bool = True,
    quiet_help: str = "no progress bar, no summary",
) -> None:
    """The input file, ``--out DIR``, repeatable ``--set SECTION.KEY=VALUE``, ``--no-plots``
    (when the command draws plots), ``--quiet`` and ``--overwrite``."""
    parser.add_argument(input_name, type=Path, help=input_help)
    parser.add_argument("--out", type=Path, required=True, metavar="DIR", help="output directory")
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="SECTION.KEY=VALUE",
        help=f"override a value, e.g. --set {set_example} (repeatable)",
    )
    if plots:
        parser.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    parser.add_argument("--quiet", action="store_true", help=quiet_help)
    add_overwrite(parser)
