"""The ``frictionlab`` command line.

Exit codes: 0 success, 1 a computation failed, 2 bad input. Each subcommand lives in
``frictionlab.commands.<name>`` and provides ``add_parser(subparsers)`` and ``run(args)``.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Sequence

from frictionlab._version import __version__
from frictionlab.errors import FrictionlabError, InputError, ParameterError, ValidityError

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
    "export",
)

EXIT_OK = 0
EXIT_FAILED = 1
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
    from frictionlab.io.provenance import command_line

    try:
        with command_line(["frictionlab", *(sys.argv[1:] if argv is None else argv)]):
            return int(args.handler(args))
    except (InputError, ParameterError, ValidityError) as exc:
        print(f"frictionlab: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except FrictionlabError as exc:
        print(f"frictionlab: computation failed: {exc}", file=sys.stderr)
        return EXIT_FAILED
    except MemoryError:
        print(
            f"frictionlab: computation failed: out of memory in `{args.command}`: reduce the "
            "number of points, steps or the grid size",
            file=sys.stderr,
        )
        return EXIT_FAILED
    except OSError as exc:  # a read or write the commands did not anticipate (disk, device)
        where = f" ({exc.filename})" if exc.filename else ""
        print(f"frictionlab: computation failed: {exc.strerror or exc}{where}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        print("frictionlab: interrupted", file=sys.stderr)
        return EXIT_FAILED
    except BrokenPipeError:  # e.g. `frictionlab demo | head -1`: the reader went away
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
