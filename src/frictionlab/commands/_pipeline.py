"""The one command pipeline: a :class:`Command` declaration and :func:`run_command`.

``run_command`` does, for every command that writes an output set: check ``--out``,
parse (every input check: bad input is one line and exit 2, nothing written), open the
output set, time the run, show progress (``progress(done, total)``), write the files and
the stamped ``summary.json`` last (:func:`frictionlab.app.outputs.write_outputs`), print
the terminal lines and return the exit code: 0 success, 1 failed computation (what was
computed is kept), 2 bad input. Exceptions map to exit codes in :func:`exit_code`.
"""

from __future__ import annotations

import argparse
import sys

from frictionlab.app.outputs import Workflow, write_outputs
from frictionlab.errors import FrictionlabError, InputError, ParameterError, ValidityError

__all__ = ["EXIT_BAD_INPUT", "EXIT_FAILED", "EXIT_OK", "Command", "exit_code", "run_command"]

EXIT_OK = 0
EXIT_FAILED = 1
EXIT_BAD_INPUT = 2

#: A command is a workflow (:class:`frictionlab.app.outputs.Workflow`) run by the CLI.
Command = Workflow


def run_command(command: Command, args: argparse.Namespace) -> int:
    """Run ``command`` with the parsed arguments; return the exit code."""
    import time

    from frictionlab.commands._progress import progress_bar
    from frictionlab.io.output_set import check_out, output_set

    out = check_out(args.out, args.overwrite)
    job = command.parse(args, out)
    quiet = bool(getattr(args, "quiet", False))
    with output_set(out, args.overwrite) as oset:
        start = time.perf_counter()
        result = command.run(job, lambda text: progress_bar(text, enabled=not quiet), oset.staging)
        seconds = time.perf_counter() - start
        plots = not getattr(args, "no_plots", False)
        written = write_outputs(command, job, result, oset.staging, plots=plots, seconds=seconds)
        shown = [oset.shown(p) for p in written]
    if not quiet:
        command.report(job, result, seconds, shown)
    for line in command.notes(job, result):
        print(line, file=sys.stderr)
    failure = command.failure(job, result, out)
    if failure is not None:
        print(f"frictionlab: computation failed: {failure}", file=sys.stderr)
        return EXIT_FAILED
    return EXIT_OK


def exit_code(exc: BaseException, command: str) -> tuple[int, str | None]:
    """The exit code of an exception leaving a command and its one-line message."""
    if isinstance(exc, InputError | ParameterError | ValidityError):
        return EXIT_BAD_INPUT, f"frictionlab: error: {exc}"
    if isinstance(exc, FrictionlabError):
        return EXIT_FAILED, f"frictionlab: computation failed: {exc}"
    if isinstance(exc, MemoryError):
        return EXIT_FAILED, (
            f"frictionlab: computation failed: out of memory in `{command}`: reduce the "
            "number of points, steps or the grid size"
        )
    if isinstance(exc, OSError):  # a read or write the commands did not anticipate
        where = f" ({exc.filename})" if exc.filename else ""
        return EXIT_FAILED, f"frictionlab: computation failed: {exc.strerror or exc}{where}"
    if isinstance(exc, KeyboardInterrupt):
        return EXIT_FAILED, "frictionlab: interrupted"
    raise exc
