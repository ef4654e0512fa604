"""Arguments shared by the commands that read a TOML file and write an output set."""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Callable
from pathlib import Path
from typing import Any


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


def add_workflow_parser(
    sub: Any,
    name: str,
    help: str,
    workflow: str,
    input_help: str,
    set_example: str,
    *,
    description: str | None = None,
    **options: Any,
) -> argparse.ArgumentParser:
    """Register ``frictionlab NAME`` running ``workflow`` (``"module:ATTRIBUTE"``, imported
    when the command runs) through :func:`frictionlab.commands._pipeline.run_command`;
    ``options`` go to :func:`add_run_arguments`."""
    parser = sub.add_parser(name, help=help, description=description or help)
    add_run_arguments(parser, input_help, set_example, **options)
    parser.set_defaults(handler=workflow_handler(workflow))
    return parser


def workflow_handler(workflow: str) -> Callable[[argparse.Namespace], int]:
    """The ``args.handler`` running the workflow named ``"module:ATTRIBUTE"`` (imported
    only then, so that ``frictionlab --help`` stays fast) through ``run_command``."""

    def handler(args: argparse.Namespace) -> int:
        from frictionlab.commands._pipeline import run_command

        module, attribute = workflow.split(":")
        return run_command(getattr(importlib.import_module(module), attribute), args)

    return handler
