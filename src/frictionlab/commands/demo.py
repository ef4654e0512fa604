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
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.demo import run_demo
    from frictionlab.errors import InputError

    out: Path = args.out
    if out.exists() and not out.is_dir():
        raise InputError(f"--out {out} exists and is not a directory")
    start = time.perf_counter()

    def log(message: str) -> None:
        if not args.quiet:
            print(message, flush=True)

    def progress(description: str) -> AbstractContextManager[Callable[[int, int], None]]:
        return progress_bar(description, enabled=not args.quiet)

    report = run_demo(out, progress=progress, log=log)
    print(f"demo finished in {time.perf_counter() - start:.1f} s")
    print(f"report: {report.resolve()}")
    print(f"data and plots of each scenario: {out.resolve()}/<scenario>/")
    return 0
