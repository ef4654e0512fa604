"""The ``frictionlab`` command line.

Exit codes: 0 success, 1 a computation failed, 2 bad input. Each subcommand lives in
``frictionlab.commands.<name>`` and provides ``add_parser(subparsers)``, which sets the
``handler(args)`` that runs it.
"""

from __future__ import annotations

import argparse
import atexit
import contextlib
import importlib
import os
import sys
import threading
from collections.abc import Sequence

from frictionlab._version import __version__
from frictionlab.errors import FrictionlabError

#: Subcommand modules under ``frictionlab.commands`` (one job each).
COMMANDS: tuple[str, ...] = (
    "demo",
    "simulate",
    "roughness",
    "bridge",
    "calibrate",
    "contact",
    "sweep",
    "example",
    "bench",
    "warmup",
    "export",
)

EXIT_BAD_INPUT = 2


def build_parser() -> argparse.ArgumentParser:
    """Build the argument parser with every registered subcommand."""
    from importlib import resources

    scenarios = resources.files("frictionlab") / "data" / "scenarios"
    parser = argparse.ArgumentParser(
        prog="frictionlab",
        description="Anisotropic friction: subloading-friction law and lattice-spring roughness.",
        epilog=(
            "getting started:\n"
            "  frictionlab demo --out out/demo     run everything, open out/demo/report.html\n"
            "  frictionlab example                 list the commented starter scenarios\n"
            "  frictionlab example simulate > my.toml && "
            "frictionlab simulate my.toml --out out/my\n"
            f"bundled scenarios (used by the demo): {scenarios}\n"
            "documentation: README.md and docs/ in the source tree "
            "(`make docs` builds the site into site/)\n"
            "exit codes: 0 success, 1 a computation failed, 2 bad input"
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"frictionlab {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in COMMANDS:
        module = importlib.import_module(f"frictionlab.commands.{name}")
        module.add_parser(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI and return the exit code."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on bad usage, 0 on --help
        return int(exc.code) if isinstance(exc.code, int) else EXIT_BAD_INPUT
    if args.command is None:
        parser.print_help()
        return EXIT_BAD_INPUT
    from frictionlab.commands._pipeline import exit_code
    from frictionlab.io.provenance import command_line

    try:
        with command_line(["frictionlab", *(sys.argv[1:] if argv is None else argv)]):
            return int(args.handler(args))
    except (FrictionlabError, MemoryError, OSError, KeyboardInterrupt) as exc:
        code, message = exit_code(exc, args.command)
        print(message, file=sys.stderr)
        return code


def run() -> None:
    """The ``frictionlab`` console command: :func:`main`, then a quick exit.

    Tearing the interpreter down frees every module's objects one by one: ~0.4 s after
    numba has loaded a kernel, ~0.15 s each for SciPy and matplotlib, ~0.5 s of a warm
    ``frictionlab calibrate``. So once :func:`main` has returned (every output written and
    closed), the exit handlers run (``atexit``: logging, temporary folders, pools), the
    standard streams are flushed and the process ends with the exit code, skipping the
    teardown; while another non-daemon thread runs, the interpreter exits as usual.
    """
    code = main()
    if threading.active_count() > 1:
        sys.exit(code)
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):  # closed, or a broken pipe
            stream.flush()
    os._exit(code)
