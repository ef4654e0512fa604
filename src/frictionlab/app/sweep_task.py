"""One sweep task, run on a worker (a local process or a Dask worker).

The task runs the scenario command exactly as the command line does (same parser, same
writers) into a private temporary directory and returns the files as bytes: the sweep's
own process writes them, so workers need no shared file system: the task carries the base
scenario and the files it names by relative path, rebuilt beside a copy of the base in the
worker's temporary directory (a file named by an absolute path must exist on the worker).
Paths of that copy in the text outputs are written back as the original base's folder.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = ["Task", "TaskResult", "run_task"]


@dataclass(frozen=True)
class Task:
    """What a worker needs: the command, the base file, the ``--set`` overrides, the inputs.

    ``inputs`` are (name, content) pairs: the base scenario under its file name first, then
    the files it names by relative path, as written; ``inputs_sha256`` identifies them.
    """

    case_id: str
    command: str
    base: str
    sets: tuple[str, ...]
    plots: bool
    inputs: tuple[tuple[str, bytes], ...] = ()
    inputs_sha256: str = ""


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
        error = ""
        try:
            base = _unpack(task.inputs, Path(tmp) / "in") if task.inputs else Path(task.base)
        except (OSError, ValueError) as exc:
            base = Path(task.base)
            error = f"cannot copy the inputs onto the worker: {exc}"
        argv = [task.command, str(base), "--out", str(out), "--quiet"]
        argv += [item for text in task.sets for item in ("--set", text)]
        if not task.plots:
            argv.append("--no-plots")
        try:
            if not error:
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
        if base != Path(task.base):
            files = _restore_paths(files, str(base.parent), str(Path(task.base).parent))
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


def _unpack(inputs: tuple[tuple[str, bytes], ...], root: Path) -> Path:
    """Write the base and the files it names under ``root``; returns the base's copy.

    The base goes deep enough that names climbing out of its folder (``../x.csv``) stay
    under ``root``.
    """
    (base_name, base_bytes), named = inputs[0], inputs[1:]
    climb = max((_climb(name) for name, _ in named), default=0)
    folder = root.joinpath(*(["up"] * climb))
    folder.mkdir(parents=True)
    base = folder / base_name
    base.write_bytes(base_bytes)
    for name, data in named:
        path = Path(os.path.normpath(folder / name))
        if not path.is_relative_to(root):
            raise ValueError(f"'{name}' leaves the base scenario's folder")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    return base


def _climb(name: str) -> int:
    """How many folders a relative name climbs above its start (``../../a`` -> 2)."""
    depth = low = 0
    for part in Path(name).parts:
        depth += -1 if part == ".." else 0 if part == "." else 1
        low = min(low, depth)
    return -low


#: Text outputs in which the worker's copy of the inputs is named.
_TEXT_SUFFIXES = (".json", ".csv", ".toml", ".txt", ".html")


def _restore_paths(files: dict[str, bytes], local: str, original: str) -> dict[str, bytes]:
    """Replace the folder of the worker's copy by the original base's folder in text files."""
    old, new = local.encode("utf-8"), original.encode("utf-8")
    return {
        name: data.replace(old, new) if name.endswith(_TEXT_SUFFIXES) else data
        for name, data in files.items()
    }
