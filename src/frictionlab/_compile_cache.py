"""Where numba writes the compiled kernels of frictionlab, and the removal of stale copies.

numba's own default writes the cache next to the sources (``__pycache__``), which fails on
read-only installs, and keys each entry on the time stamp of the function's own file only:
a kernel that calls a function of another module is not recompiled when that module
changes (a stale compiled caller). So frictionlab points numba at a per-user cache
directory *keyed on the package version and a hash of every source file that uses numba*
(kernels call only kernels, and those live in files that import numba, through
:mod:`frictionlab._jit`):

    <user cache>/frictionlab/numba/<version>-<source hash>/

with ``<user cache>`` = ``$XDG_CACHE_HOME`` or ``~/.cache`` (``%LOCALAPPDATA%`` on
Windows), falling back to the system temporary directory when that cannot be created.
Any change of a compiled module gives a fresh directory (and one full recompilation,
about a minute on a 2-core machine), so no stale compiled code is ever loaded; edits
elsewhere (CLI, I/O) keep the cache. ``FRICTIONLAB_CACHE_DIR`` overrides the location
(the key is still appended); a user's own ``NUMBA_CACHE_DIR`` is respected as it is.

Stale directories (other versions or sources) are removed when the first kernel module
is imported (:mod:`frictionlab._jit` calls :func:`configure`; ``import frictionlab`` alone
does not), all but the :data:`KEEP_RECENT` most recently used ones (two checkouts or
installs of different sources used in turn keep their kernels instead of recompiling each
other's), and only when this is certainly safe (POSIX only): the name has the ``<version>-<hash>``
form, every file inside is a numba cache file (``.nbi``/``.nbc``) or frictionlab's own
lock file, and no process is using it. A process holds a shared lock on the lock file of
the directory it uses for as long as it runs (and sets the file's time stamp: the
directory's last use); a directory is removed only under an
exclusive lock, and a directory without a lock file (made before locks existed) only
when it has not changed for a day. Any failure leaves the directory in place: pruning
never stops a run.
"""

from __future__ import annotations

import atexit
import contextlib
import hashlib
import os
import re
import shutil
import sys
import tempfile
import time
from pathlib import Path
from typing import IO

from frictionlab._version import __version__

__all__ = ["cache_dir", "configure", "last_used", "prune", "source_hash"]

_PACKAGE = Path(__file__).resolve().parent
_chosen: Path | None = None
_held: IO[bytes] | None = None

#: The lock file inside every cache directory in use.
LOCK_NAME = ".frictionlab-in-use"
#: Directory names that frictionlab made: ``<version>-<16 hex digits>``.
_KEY = re.compile(r"^[0-9A-Za-z.+!_-]+-[0-9a-f]{16}$")
#: A directory without a lock file is removed only when unchanged for this long (s).
UNLOCKED_GRACE_S = 86400.0
#: Stale directories kept besides the one in use: the most recently used ones.
KEEP_RECENT = 3


def source_hash() -> str:
    """SHA-256 (first 16 hex digits) over the names and bytes of the ``.py`` files using numba
    (directly or through :mod:`frictionlab._jit`)."""
    digest = hashlib.sha256()
    for path in sorted(_PACKAGE.rglob("*.py")):
        data = path.read_bytes()
        if b"numba" not in data and b"frictionlab._jit" not in data:
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


def hold(directory: Path) -> IO[bytes] | None:
    """Take a shared lock on ``directory``'s lock file (kept while the file stays open).

    Returns the open file, or None where locks are unavailable or the directory is gone.
    """
    try:
        import fcntl
    except ImportError:  # not POSIX: no pruning either
        return None
    try:
        handle = open(directory / LOCK_NAME, "ab")  # noqa: SIM115 (held open on purpose)
    except OSError:
        return None
    try:
        fcntl.flock(handle, fcntl.LOCK_SH)
        # A pruner may have renamed the directory away between open and lock.
        if os.fstat(handle.fileno()).st_ino != os.stat(directory / LOCK_NAME).st_ino:
            raise OSError("lock file replaced")
    except OSError:
        handle.close()
        return None
    with contextlib.suppress(OSError):  # the last use, for pruning (a read-only file: none)
        os.utime(handle.fileno())
    return handle


def last_used(directory: Path) -> float:
    """When ``directory`` was last used: its lock file's time stamp, else its own [s]."""
    try:
        return (directory / LOCK_NAME).stat().st_mtime
    except OSError:
        return directory.stat().st_mtime


def _only_cache_files(directory: Path) -> bool:
    for path in directory.rglob("*"):
        if path.is_symlink():
            return False
        if path.is_file() and path.suffix not in (".nbi", ".nbc") and path.name != LOCK_NAME:
            return False
    return True


def _remove_if_unused(directory: Path) -> bool:
    import fcntl

    lock_path = directory / LOCK_NAME
    if not lock_path.exists() and time.time() - directory.stat().st_mtime < UNLOCKED_GRACE_S:
        return False  # made before lock files existed, and may be in use
    with open(lock_path, "ab") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:  # in use
            return False
        if not _only_cache_files(directory):
            return False
        doomed = directory.with_name(f"{directory.name}.removing-{os.getpid()}")
        directory.rename(doomed)  # atomic: a starting process now makes a fresh one
    shutil.rmtree(doomed, ignore_errors=True)
    return True


def prune(root: Path, keep: str, keep_recent: int = KEEP_RECENT) -> list[str]:
    """Remove the stale cache directories in ``root``: all but ``keep`` and the
    ``keep_recent`` most recently used others; never raises.

    Returns the names removed. See the module docstring for what is removed and when.
    """
    removed: list[str] = []
    try:
        import fcntl  # noqa: F401
    except ImportError:
        return removed
    try:
        entries = sorted(root.iterdir())
    except OSError:
        return removed
    stale: list[tuple[float, Path]] = []
    for entry in entries:
        try:
            if entry.name == keep or entry.is_symlink() or not entry.is_dir():
                continue
            if ".removing-" in entry.name and _KEY.match(entry.name.split(".removing-")[0]):
                if _only_cache_files(entry):  # left by an interrupted removal
                    shutil.rmtree(entry, ignore_errors=True)
                continue
            if _KEY.match(entry.name):
                stale.append((last_used(entry), entry))
        except OSError:
            continue
    stale.sort(key=lambda item: item[0], reverse=True)  # the most recently used first
    for _, entry in stale[max(keep_recent, 0) :]:
        try:
            if _remove_if_unused(entry):
                removed.append(entry.name)
        except OSError:
            continue
    return sorted(removed)


def configure() -> str:
    """Point numba's cache at :func:`cache_dir` unless ``NUMBA_CACHE_DIR`` is set.

    Holds the directory's lock for the life of the process and removes stale siblings.
    Returns the directory in use. Must run before the first ``@njit(cache=True)``
    function of frictionlab is defined.
    """
    global _held
    user = os.environ.get("NUMBA_CACHE_DIR")
    if user:
        return user
    import numba.core.config as config

    path = cache_dir()
    for _ in range(2):  # a second try if a pruner removed the directory meanwhile
        if _held is not None:
            break
        _writable(path)
        _held = hold(path)
        if _held is not None:  # closed at exit: no "unclosed file" ResourceWarning
            atexit.register(_held.close)
    if _held is not None:
        prune(path.parent, keep=path.name)
    config.CACHE_DIR = str(path)  # type: ignore[attr-defined]
    return str(path)
