"""``frictionlab demo --out DIR``: run the bundled scenarios and write DIR/report.html.

The report shows every figure with a sentence saying what it shows and the parameters
used; each scenario's history.csv, summary.json, plots and a copy of its scenario file
sit in a subdirectory. Progress is shown on the terminal.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from contextlib import AbstractContextManager
from pathlib import Path

from frictionlab.commands._output import add_overwrite
from frictionlab.commands._progress import progress_bar


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser(
        "demo",
        help="run the bundled scenarios and write an HTML report (OUT/report.html)",
        description=(
            "Run the bundled scenarios (the subloading-friction law, the lattice-spring "
            "roughness model, the bridge between them and the finite-element contact model) "
            "and write OUT/report.html: each figure with what it shows and the parameters "
            "used. The data (CSV, JSON) and a copy of each scenario file sit in "
            "OUT/<section>/. Takes a few minutes."
        ),
    )
    parser.add_argument("--out", type=Path, default=Path("out/demo"), help="output directory")
    parser.add_argument("--quiet", action="store_true", help="no progress output")
    add_overwrite(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.demo import run_demo
    from frictionlab.io.output_set import check_out, output_set

    out = check_out(args.out, args.overwrite)
    start = time.perf_counter()

    def log(message: str) -> None:
        if not args.quiet:
            print(message, flush=True)

    def progress(description: str) -> AbstractContextManager[Callable[[int, int], None]]:
        return progress_bar(description, enabled=not args.quiet)

    with output_set(out, args.overwrite) as oset:
        report = oset.shown(run_demo(oset.staging, progress=progress, log=log))
    print(f"demo finished in {time.perf_counter() - start:.1f} s")
    print(f"report: {report.resolve()}")
    print(f"data and plots of each scenario: {out.resolve()}/<scenario>/")
    return 0
