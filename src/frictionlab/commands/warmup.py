"""``frictionlab warmup``: compile the kernels once, so that a first run does not wait.

See :mod:`frictionlab.warmup`. ``make venv`` and ``make demo`` call it after installing.
"""

from __future__ import annotations

import argparse
import sys

HELP = "compile the numba kernels into the cache now (a first run then starts at once)"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("warmup", help=HELP, description=HELP + ".")
    parser.add_argument("--quiet", action="store_true", help="print only the cache directory")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab import _compile_cache
    from frictionlab.warmup import warmup

    report = None if args.quiet else (lambda line: print(line, file=sys.stderr, flush=True))
    times = warmup(report)
    total = sum(seconds for _, seconds in times)
    print(f"compiled kernels ready in {_compile_cache.cache_dir()} ({total:.1f} s)")
    return 0
