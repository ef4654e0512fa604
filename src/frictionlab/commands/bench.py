"""``frictionlab bench [--json FILE]``: the speed figures, measured in one process.

See :mod:`frictionlab.benchmark`: law update per point against a plain Coulomb return
and against a per-point Python loop, the lattice's springs per second in partial
contact, and the first-call (compilation) cost; warm-up, then the median of >= 5 runs.
"""

from __future__ import annotations

import argparse

HELP = "measure the speed figures (law update, lattice, first-call cost) on this machine"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("bench", help=HELP, description=HELP + ".")
    parser.add_argument("--json", metavar="FILE", help="write every figure to FILE as JSON")
    parser.add_argument("--points", type=int, default=1_000_000,
                        help="contact points of the law benchmark (default 1e6)")  # fmt: skip
    parser.add_argument("--lattice-size", type=int, default=1024,
                        help="grid of the lattice benchmark, N x N (default 1024)")  # fmt: skip
    parser.add_argument("--repeats", type=int, default=5,
                        help="timed runs per figure after a warm-up, >= 5 (default 5)")  # fmt: skip
    parser.add_argument("--no-first-call", action="store_true",
                        help="skip the first-call cost (two child processes)")  # fmt: skip
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab import benchmark
    from frictionlab.errors import ParameterError

    if args.repeats < 5:
        raise ParameterError("--repeats", args.repeats, "at least 5 (median of >= 5 runs)")
    if args.points < 1 or args.lattice_size < 8:
        raise ParameterError("--points/--lattice-size", (args.points, args.lattice_size),
                             "points >= 1 and a lattice of at least 8 x 8")  # fmt: skip
    payload = benchmark.run(
        points=args.points,
        repeats=args.repeats,
        lattice_size=args.lattice_size,
        first_call=not args.no_first_call,
    )
    if args.json:
        benchmark.write(payload, args.json)
        print(f"wrote {args.json}")
    return 0
