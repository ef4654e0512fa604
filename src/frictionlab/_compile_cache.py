"""Where numba writes the compiled kernels of frictionlab (issue 14, item 4).

numba's own default writes the cache next to the sources (``__pycache__``), which fails on
read-only installs, and keys each entry on the time stamp of the function's own file only:
a kernel that calls a function of another module is not recompiled when that module
changes (a stale compiled caller). So frictionlab points numba at a per-user cache
directory *keyed on the package version and a hash of every source file that uses numba*
(kernels call only kernels, and those live in files that import numba):

    <user cache>/frictionlab/numba/<version>-<source hash>/

with ``<user cache>`` = ``$XDG_CACHE_HOME`` or ``~/.cache`` (``%LOCALAPPDATA%`` on
Windows), falling back to the system temporary directory when that cannot be created.
Any change of a compiled module gives a fresh directory (and one full recompilation,
about a minute on a 2-core machine), so no stale compiled code is ever loaded; edits
elsewhere (CLI, I/O) keep the cache. ``FRICTIONLAB_CACHE_DIR`` overrides the location
(the key is still appended); a user's own ``NUMBA_CACHE_DIR`` is respected as it is.
Directories of earlier versions are not removed (a few MB each).

:func:`configure` runs when :mod:`frictionlab` is imported, before any kernel is
decorated (numba reads ``config.CACHE_DIR`` when a ``cache=True`` function is defined).
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
from pathlib import Path

from frictionlab._version import __version__

__all__ = ["cache_dir", "configure", "source_hash"]

_PACKAGE = Path(__file__).resolve().parent
_chosen: Path | None = None


def source_hash() -> str:
    """SHA-256 (first 16 hex digits) over the names and bytes of the ``.py`` files using numba."""
    digest = hashlib.sha256()
    for path in sorted(_PACKAGE.rglob("*.py")):
        data = path.read_bytes()
        if b"numba" not in data:
            continue
        digest.update(path.relative_to(_PACKAGE).as_posix().encode())
        digest.update(b"\0")
        digest.update(data)
    return digest.hexdigest()[:16]


def _user_cache_root() -> Path:
    if sys.platform == "win32":
        base = os.environ.get("LOCALAPPDATA") or str(Path.home() / "AppData" / "Local")
    elif sys.platform == "darwin":
        base = str(Path.home() / "Library" / "Caches")
    else:
        base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "frictionlab" / "numba"


def _writable(path: Path) -> bool:
    try:
        path.mkdir(parents=True, exist_ok=True)
        probe = path / f".probe-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError:
        return False
    return True


def cache_dir() -> Path:
    """The directory frictionlab's kernels are cached in (created when needed)."""
    global _chosen
    if _chosen is not None:
        return _chosen
    key = f"{__version__}-{source_hash()}"
    override = os.environ.get("FRICTIONLAB_CACHE_DIR")
    candidates = [Path(override)] if override else [_user_cache_root()]
    user_tag = str(os.getuid()) if hasattr(os, "getuid") else "user"
    candidates.append(Path(tempfile.gettempdir()) / f"frictionlab-numba-{user_tag}")
    for root in candidates:
        if _writable(root / key):
            _chosen = root / key
            return _chosen
    _chosen = candidates[-1] / key  # numba then warns and compiles in memory only
    return _chosen


def configure() -> str:
    """Point numba's cache at :func:`cache_dir` unless ``NUMBA_CACHE_DIR`` is set.

    Returns the directory in use. Must run before the first ``@njit(cache=True)``
    function of frictionlab is defined.
    """
    user = os.environ.get("NUMBA_CACHE_DIR")
    if user:
        return user
    import numba.core.config as config

    path = str(cache_dir())
    config.CACHE_DIR = path  # type: ignore[attr-defined]
    return path
