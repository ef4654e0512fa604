"""The provenance block of every ``summary.json``: what produced the file, where and from what.

:func:`stamp` adds to a summary the keys common to every command:

* ``schema_version`` -- the version of the summary layout (:data:`SCHEMA_VERSION`; the JSON
  Schema is ``docs/schemas/summary.schema.json``);
* ``frictionlab_version`` and ``files`` (the output files) -- the same names in every
  command. The older ``frictionlab`` and ``outputs`` keys of some commands are kept for
  one release (see CHANGELOG.md);
* ``provenance`` -- frictionlab and dependency versions, Python and platform, the UTC
  time, the command line and the sha256 of every input file.
"""

from __future__ import annotations

import contextlib
import datetime as _dt
import hashlib
import os
import platform
import sys
from collections.abc import Iterable, Iterator, Sequence
from contextvars import ContextVar
from importlib import metadata
from pathlib import Path
from typing import Any

from frictionlab._version import __version__

__all__ = ["SCHEMA_VERSION", "command_line", "file_sha256", "provenance", "stamp"]

#: Version of the summary.json layout; raised when a key changes meaning or goes away.
SCHEMA_VERSION = 1

#: Distributions whose versions are recorded (those not installed are left out).
DEPENDENCIES = (
    "numpy",
    "scipy",
    "numba",
    "matplotlib",
    "pandas",
    "SurfaceTopography",
    "ContactMechanics",
    "scikit-fem",
    "meshio",
    "pyamg",
    "pymetis",
    "cvxopt",
    "pint",
    "pyarrow",
    "orjson",
)

_COMMAND: ContextVar[tuple[str, ...] | None] = ContextVar("frictionlab_command", default=None)


@contextlib.contextmanager
def command_line(argv: Sequence[str]) -> Iterator[None]:
    """Record ``argv`` as the command line of the summaries written inside the block."""
    token = _COMMAND.set(tuple(str(a) for a in argv))
    try:
        yield
    finally:
        _COMMAND.reset(token)


def file_sha256(path: str | os.PathLike[str]) -> str:
    """Hex sha256 of a file's bytes."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _versions() -> dict[str, str]:
    out = {}
    for name in DEPENDENCIES:
        with contextlib.suppress(metadata.PackageNotFoundError):
            out[name] = metadata.version(name)
    return out


def provenance(inputs: Iterable[str | os.PathLike[str]] = ()) -> dict[str, Any]:
    """The provenance block: versions, platform, UTC time, command line, input checksums.

    ``inputs`` are the files read (scenario, tables, topography); each is given as
    written by the user with its sha256 (a file that cannot be read is listed with
    ``sha256 = null``).
    """
    files = []
    seen = set()
    for item in inputs:
        path = Path(item)
        if str(path) in seen:
            continue
        seen.add(str(path))
        try:
            digest: str | None = file_sha256(path)
        except OSError:
            digest = None
        files.append({"path": str(path), "sha256": digest})
    command = _COMMAND.get()
    return {
        "frictionlab_version": __version__,
        "dependencies": _versions(),
        "python": platform.python_version(),
        "platform": platform.platform(),
        "timestamp": _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        "command": list(command) if command is not None else list(sys.argv),
        "inputs": files,
    }


def stamp(
    summary: dict[str, Any],
    files: Sequence[str],
    inputs: Iterable[str | os.PathLike[str]] = (),
) -> dict[str, Any]:
    """A copy of ``summary`` with the common keys and the provenance block added.

    ``files`` are the names of the output files (summary.json included). Keys already in
    ``summary`` keep their values; nothing is renamed.
    """
    out = {"schema_version": SCHEMA_VERSION, "frictionlab_version": __version__}
    out.update(summary)
    out.setdefault("files", list(files))
    out["provenance"] = {**summary.get("provenance", {}), **provenance(inputs)}
    return out
