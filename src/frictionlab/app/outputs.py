"""What every workflow provides, and the one place its files and summary.json are written."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any, Protocol

from frictionlab._progress import ProgressFactory
from frictionlab.io.atomic import write_json_atomic
from frictionlab.io.provenance import stamp

__all__ = ["SUMMARY", "Workflow", "WorkflowBase", "write_outputs"]

#: The summary every workflow writes (last), with the provenance block.
SUMMARY = "summary.json"


class Workflow(Protocol):
    """A workflow: ``parse`` (every input check) -> ``run`` -> ``files`` + ``summary``."""

    #: The command's name (``frictionlab <name>``) and its input's argument name.
    name: str
    #: Deprecated names written as copies of summary.json (for one release).
    aliases: tuple[str, ...]

    def parse(self, args: Any, out: Path) -> Any:
        """Read and check every input (one line naming the key on bad input)."""

    def run(self, job: Any, progress: ProgressFactory, staging: Path) -> Any:
        """Compute; a failed computation is a result (see :meth:`failure`), not an error."""

    def files(self, job: Any, result: Any, out: Path, plots: bool) -> list[Path]:
        """Write every output but the summary into ``out``; return the paths."""

    def summary(self, job: Any, result: Any, files: list[str], seconds: float) -> dict[str, Any]:
        """The summary, before the provenance stamp (``files``: every output's name)."""

    def inputs(self, job: Any) -> Sequence[Path]:
        """The files read (their sha256 goes into the provenance block)."""

    def report(self, job: Any, result: Any, seconds: float, written: list[Path]) -> None:
        """Print the terminal lines of a successful or failed run."""

    def notes(self, job: Any, result: Any) -> list[str]:
        """Lines for stderr, printed even with ``--quiet`` (warnings, caveats)."""

    def failure(self, job: Any, result: Any, out: Path) -> str | None:
        """Why the computation failed (exit code 1), or ``None``."""


class WorkflowBase:
    """The defaults of a :class:`Workflow`: no deprecated copies, the files written as
    the terminal line, no notes, no failure."""

    aliases: tuple[str, ...] = ()

    def report(self, job: Any, result: Any, seconds: float, written: list[Path]) -> None:
        print("wrote " + ", ".join(str(p) for p in written))

    def notes(self, job: Any, result: Any) -> list[str]:
        return []

    def failure(self, job: Any, result: Any, out: Path) -> str | None:
        return None


def write_outputs(
    workflow: Workflow, job: Any, result: Any, out: Path, *, plots: bool, seconds: float
) -> list[Path]:
    """Write the workflow's files, then summary.json (stamped) and its deprecated copies."""
    written = workflow.files(job, result, out, plots)
    names = [p.name for p in written] + [SUMMARY, *workflow.aliases]
    summary = stamp(workflow.summary(job, result, names, seconds), names, workflow.inputs(job))
    for name in (SUMMARY, *workflow.aliases):
        written.append(write_json_atomic(out / name, summary))
    return written
