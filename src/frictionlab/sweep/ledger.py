"""Resume bookkeeping: one ``case.json`` per case directory, written last.

A case counts as done when its ``case.json`` says ``status = "ok"`` for the same inputs
(the sha256 of the base scenario together with the tables or topographies the case's
scenario names) and the same overrides. Outputs are written before the record, each
atomically, so a sweep killed at any moment leaves every case either done (all files and
the record) or not done (no record, or the record of an earlier failed attempt): a re-run
repeats exactly the cases that are not done, failed ones included.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from frictionlab.io.atomic import write_bytes_atomic, write_json_atomic
from frictionlab.sweep.cases import Case

__all__ = [
    "RECORD",
    "file_sha256",
    "inputs_sha256",
    "is_done",
    "make_record",
    "read_record",
    "write_case",
]

#: The per-case record, written after the case's outputs.
RECORD = "case.json"


def file_sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def inputs_sha256(files: Mapping[str, bytes]) -> str:
    """One sha256 for a case's input files (name as written -> content), order-free."""
    digest = hashlib.sha256()
    for name in sorted(files):
        digest.update(json.dumps(name).encode("utf-8"))
        digest.update(hashlib.sha256(files[name]).digest())
    return digest.hexdigest()


def make_record(
    case: Case, command: str, inputs_sha: str, status: str, error: str, seconds: float,
    files: list[str],
) -> dict[str, Any]:  # fmt: skip
    """The content of ``case.json``: parameters, status, error and the files written."""
    return {
        "id": case.id,
        "index": case.index + 1,
        "command": command,
        "overrides": case.overrides,
        "inputs_sha256": inputs_sha,
        "status": status,
        "error": error,
        "seconds": round(seconds, 3),
        "files": sorted(files),
    }


def read_record(case_dir: Path) -> dict[str, Any] | None:
    """The case's record, or None when absent or unreadable (then the case runs again)."""
    try:
        record = json.loads((case_dir / RECORD).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return record if isinstance(record, dict) else None


def is_done(record: Mapping[str, Any] | None, case: Case, inputs_sha: str) -> bool:
    """Whether a record shows ``case`` finished successfully on these inputs."""
    return (
        record is not None
        and record.get("status") == "ok"
        and record.get("id") == case.id
        and record.get("overrides") == case.overrides
        and record.get("inputs_sha256") == inputs_sha
    )


def write_case(case_dir: Path, files: Mapping[str, bytes], record: Mapping[str, Any]) -> None:
    """Write the outputs (each atomically), drop stale ones, then the record."""
    with contextlib.suppress(FileNotFoundError):
        (case_dir / RECORD).unlink()
    for name, data in files.items():
        write_bytes_atomic(case_dir / name, data)
    if case_dir.is_dir():
        for path in case_dir.rglob("*"):
            rel = path.relative_to(case_dir).as_posix()
            if path.is_file() and rel not in files and not rel.startswith("."):
                path.unlink()
    write_json_atomic(case_dir / RECORD, dict(record))
