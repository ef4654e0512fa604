"""``frictionlab sweep SWEEP.toml --out DIR``: run a grid or list of scenarios.

The sweep file names a base scenario (simulate or roughness) and a ``[grid]`` or
``[[case]]`` list of ``section.key`` overrides; each case is written to
``DIR/cases/<id>/`` by the base command's own pipeline, and ``DIR/sweep.csv`` and
``DIR/sweep.png`` collect them. Resumable; exit 1 if any case failed. The workflow is
:mod:`frictionlab.app.sweep` (it keeps its own resumable folder instead of one output set).
"""

from __future__ import annotations

import argparse
from pathlib import Path

HELP = "run a grid or list of scenarios (local processes or a Dask cluster), resumable"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("sweep", help=HELP, description=HELP)
    parser.add_argument("sweep", type=Path, help="sweep file (TOML): base scenario + [grid]")
    parser.add_argument("--out", type=Path, required=True, help="output directory")
    parser.add_argument(
        "--workers", type=int, default=None, metavar="N",
        help="local worker processes (default: the number of cores)",
    )  # fmt: skip
    parser.add_argument(
        "--scheduler", default=None, metavar="ADDRESS",
        help="run on this Dask scheduler (e.g. tcp://host:8786) instead of local processes",
    )  # fmt: skip
    parser.add_argument("--no-plots", action="store_true", help="skip every PNG plot")
    parser.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.app.sweep import run_sweep
    from frictionlab.commands._progress import progress_bar

    return run_sweep(args, lambda text: progress_bar(text, enabled=not args.quiet))
