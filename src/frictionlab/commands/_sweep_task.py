"""One sweep task, run on a worker (a local process or a Dask worker).

The task runs the scenario command exactly as the command line does (same parser, same
writers) into a private temporary directory and returns the files as bytes: the sweep's
own process writes them, so workers need no shared writable file system (they must see
the base scenario and the files it names at the same path).
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = ["Task", "TaskResult", "run_task"]


@dataclass(frozen=True)
class Task:
    """What a worker needs: the command, the base file, the ``--set`` overrides."""

    case_id: str
    command: str
    base: str
    sets: tuple[str, ...]
    plots: bool


@dataclass(frozen=True)
class TaskResult:
    case_id: str
    ok: bool
    error: str
    seconds: float
    files: dict[str, bytes]


def run_task(task: Task) -> TaskResult:
    """Run one case; never raises (a failure comes back as ``ok = False`` with its error)."""
    import importlib

    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="frictionlab-sweep-") as tmp:
        out = Path(tmp) / "out"
        argv = [task.command, task.base, "--out", str(out), "--quiet"]
        argv += [item for text in task.sets for item in ("--set", text)]
        if not task.plots:
            argv.append("--no-plots")
        error = ""
        try:
            parser = argparse.ArgumentParser(prog="frictionlab")
            sub = parser.add_subparsers(dest="command")
            importlib.import_module(f"frictionlab.commands.{task.command}").add_parser(sub)
            args = parser.parse_args(argv)
            code = int(args.handler(args))
            if code != 0:
                error = _failure_message(out, code)
        except Exception as exc:  # a failed case is recorded, never fatal to the sweep
            error = f"{type(exc).__name__}: {exc}".rstrip(": ")
        files = _collect(out)
    return TaskResult(task.case_id, not error, error, time.perf_counter() - start, files)


def _failure_message(out: Path, code: int) -> str:
    try:
        summary: dict[str, Any] = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        summary = {}
    message = summary.get("message") if isinstance(summary, dict) else None
    return f"computation failed: {message}" if message else f"exit code {code}"


def _collect(out: Path) -> dict[str, bytes]:
    if not out.is_dir():
        return {}
    return {
        p.relative_to(out).as_posix(): p.read_bytes()
        for p in sorted(out.rglob("*"))
        if p.is_file() and not p.name.startswith(".")
    }
