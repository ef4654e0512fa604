"""Whole output sets: a command's ``--out`` directory holds its complete old set or its new one.

Each command writes all of its files into a hidden staging directory beside ``--out``
(``.NAME.new-XXXX``) and, once everything is written, moves it into place:

* on Linux the staging directory and an existing ``--out`` are swapped in one atomic
  ``renameat2(RENAME_EXCHANGE)``, so at every instant ``--out`` is either the complete
  old set or the complete new one, even under ``kill -9``; elsewhere the old set is
  first renamed to ``.NAME.old-XXXX`` and put back by the next run if a kill falls
  between the two renames;
* a lock file ``.NAME.lock`` (``flock``, released by the kernel when the process dies)
  stops a second run from writing the same ``--out`` at the same time;
* the leftovers of killed runs (``.NAME.new-*``, ``.NAME.old-*``) are removed by the
  next run on the same ``--out``;
* an existing ``--out`` is replaced as a whole (older files that the new set does not
  have disappear) when it is empty or holds a frictionlab set (one of
  :data:`SET_MARKERS` at its top level); any other directory is refused unless the user
  passes ``--overwrite``. The current directory, its ancestors and the home directory
  are always refused (``--out ""`` means the current directory).

Bad ``--out`` values raise :class:`~frictionlab.errors.InputError` (exit 2) before
anything is computed or written; an ``OSError`` while writing (a full disk) removes the
staging directory and raises :class:`OutputError` (exit 1): nothing partial is left.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import os
import shutil
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from frictionlab.errors import FrictionlabError, InputError

__all__ = ["SET_MARKERS", "OutputError", "OutputSet", "check_out", "lock_out", "output_set"]

#: Top-level files by which an existing directory is recognised as a frictionlab set
#: (summary of simulate/roughness/contact, bridge, calibrate, the demo's report, sweep).
SET_MARKERS: tuple[str, ...] = (
    "summary.json", "bridge.json", "fit.json", "report.html", "sweep.csv",
)  # fmt: skip

_AT_FDCWD = -100
_RENAME_EXCHANGE = 2


class OutputError(FrictionlabError):
    """The output set could not be written (e.g. no space left); nothing was changed."""


@dataclass(frozen=True)
class OutputSet:
    """Where a command writes (``staging``) and where the set will live (``final``)."""

    final: Path
    staging: Path

    def shown(self, path: str | os.PathLike[str]) -> Path:
        """The final location of a path written under ``staging`` (for messages)."""
        p = Path(path)
        try:
            return self.final / p.relative_to(self.staging)
        except ValueError:
            return p


def _dir_mode() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return 0o777 & ~umask


def check_out(
    out: str | os.PathLike[str], overwrite: bool = False, markers: tuple[str, ...] = SET_MARKERS
) -> Path:
    """Refuse an unusable ``--out`` with one line (InputError); return the path to write.

    A non-empty directory is accepted when it holds one of ``markers`` at its top level
    (or with ``overwrite``). A symbolic link is followed: the set is written where it
    points (a link to nothing is refused).
    """
    text = os.fspath(out)
    target = Path(text)
    shown = f"--out '{text}'"
    if target.is_symlink():
        if not target.exists():
            raise InputError(
                f"{shown} is a symbolic link to '{os.readlink(target)}', which does not "
                "exist: allowed a directory or a link to one"
            )
        target = target.resolve()
    resolved = target.resolve()
    cwd = Path.cwd().resolve()
    if text.strip() == "" or resolved == cwd or resolved in cwd.parents:
        raise InputError(
            f"{shown} is the current directory or one of its parents: allowed a new "
            "directory or one that holds an earlier frictionlab output set"
        )
    if resolved == Path.home().resolve() or resolved == Path(resolved.anchor):
        raise InputError(f"{shown} is the home or root directory: allowed a new directory")
    if target.exists() and not target.is_dir():
        raise InputError(f"{shown} exists and is not a directory")
    if target.is_dir() and not overwrite:
        try:
            names = sorted(p.name for p in target.iterdir())
        except OSError as exc:
            raise InputError(f"cannot read {shown}: {exc.strerror or exc}") from None
        if names and not any((target / m).is_file() for m in markers):
            raise InputError(
                f"{shown} holds files that are not a frictionlab output set (e.g. "
                f"'{names[0]}'): allowed a new or empty directory, or pass --overwrite to "
                "replace it as a whole"
            )
    return target


@contextlib.contextmanager
def lock_out(target: Path) -> Iterator[None]:
    """Hold ``.NAME.lock`` beside ``target`` (flock; Unix only, a no-op elsewhere).

    A second holder is refused with :class:`InputError`; the kernel releases the lock
    when the process dies.
    """
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows
        yield
        return
    path = target.parent / f".{target.name}.lock"
    while True:
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise InputError(
                f"--out '{target}' is being written by another frictionlab run: wait for "
                "it to finish or choose another directory"
            ) from None
        try:  # the file may have been unlinked by the run that held it: retry then
            if os.stat(path).st_ino == os.fstat(fd).st_ino:
                break
        except FileNotFoundError:
            pass
        os.close(fd)
    try:
        yield
    finally:
        with contextlib.suppress(OSError):
            path.unlink()
        os.close(fd)


def _clean_leftovers(target: Path) -> None:
    """Remove staging directories of killed runs; restore an old set moved aside."""
    parent, name = target.parent, target.name
    olds = sorted(parent.glob(f".{name}.old-*"), key=lambda p: p.stat().st_mtime)
    if olds and not target.exists():
        os.rename(olds.pop(), target)
    for leftover in [*parent.glob(f".{name}.new-*"), *olds]:
        shutil.rmtree(leftover, ignore_errors=True)


def _exchange(a: Path, b: Path) -> bool:
    """Swap two directories atomically (Linux ``renameat2``); False where unsupported."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        fn = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return False
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    fn.restype = ctypes.c_int
    if fn(_AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), _RENAME_EXCHANGE) == 0:
        return True
    code = ctypes.get_errno()
    if code in (errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP, errno.EPERM):
        return False
    raise OSError(code, os.strerror(code), str(b))


def _publish(staging: Path, target: Path) -> None:
    """Move the complete set ``staging`` onto ``target`` (replacing an old set whole)."""
    if not target.exists():
        os.rename(staging, target)
        return
    if _exchange(staging, target):
        shutil.rmtree(staging, ignore_errors=True)  # now the old set
        return
    aside = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=target.parent))
    os.rmdir(aside)
    os.rename(target, aside)
    os.rename(staging, target)
    shutil.rmtree(aside, ignore_errors=True)


@contextlib.contextmanager
def output_set(out: str | os.PathLike[str], overwrite: bool = False) -> Iterator[OutputSet]:
    """Yield an :class:`OutputSet` whose ``staging`` directory receives every file.

    On normal exit of the ``with`` block the set replaces ``out`` as a whole; on an
    exception nothing under ``out`` changes and the staging directory is removed. An
    ``OSError`` raised while writing becomes :class:`OutputError`.
    """
    target = check_out(out, overwrite)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        lock = lock_out(target)
        lock.__enter__()
    except OSError as exc:
        raise InputError(f"cannot write to --out '{out}': {exc.strerror or exc}") from None
    try:
        _clean_leftovers(target)
        try:
            staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.new-", dir=target.parent))
            os.chmod(staging, _dir_mode())
        except OSError as exc:
            raise InputError(f"cannot write to --out '{out}': {exc.strerror or exc}") from None
        try:
            yield OutputSet(final=target, staging=staging)
            _publish(staging, target)
        except OSError as exc:
            raise OutputError(
                f"cannot write the output set into '{target}': {exc.strerror or exc}; "
                "nothing was changed there"
            ) from None
        finally:
            if staging.exists():
                shutil.rmtree(staging, ignore_errors=True)
    finally:
        lock.__exit__(None, None, None)
