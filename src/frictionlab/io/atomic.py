"""Atomic file output: a file is either absent, its previous version, or complete.

Every writer goes through :func:`atomic_path`: the content is written to a temporary
file in the same directory and moved into place with :func:`os.replace`, which is
atomic on POSIX and Windows. An interrupted or failed write leaves no partial file.
"""

from __future__ import annotations

import contextlib
import json
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

__all__ = [
    "atomic_path",
    "write_bytes_atomic",
    "write_contents_atomic",
    "write_json_atomic",
    "write_text_atomic",
]


def _file_mode() -> int:
    """The mode a plain ``open(path, "w")`` would give: 0o666 minus the process umask."""
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


_FILE_MODE = _file_mode()


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path next to ``path``; move it onto ``path`` on success.

    The parent directory is created if needed. On an exception (including
    ``KeyboardInterrupt``) the temporary file is removed and ``path`` is untouched.
    The temporary name keeps the suffix of ``path`` so that writers that infer the
    format from the suffix (e.g. ``matplotlib.savefig``) still work.
    """
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(
        prefix=f".{target.name}.", suffix=f".tmp{target.suffix}", dir=target.parent
    )
    os.close(fd)
    tmp = Path(tmp_name)
    try:
        yield tmp
        os.chmod(tmp, _FILE_MODE)  # mkstemp creates 0600; give the usual umask-based mode
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()
        raise


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically and return the path."""
    with atomic_path(path) as tmp, open(tmp, "wb") as handle:
        handle.write(data)
        handle.flush()
        os.fsync(handle.fileno())
    return Path(path)


def write_text_atomic(path: str | os.PathLike[str], text: str) -> Path:
    """Write UTF-8 ``text`` to ``path`` atomically and return the path."""
    return write_bytes_atomic(path, text.encode("utf-8"))


def write_contents_atomic(
    folder: str | os.PathLike[str], contents: dict[str, str | bytes]
) -> list[Path]:
    """Write each ``name -> text or bytes`` of ``contents`` atomically into ``folder``, in
    order; return the paths."""
    out = Path(folder)
    return [
        write_bytes_atomic(out / name, data)
        if isinstance(data, bytes)
        else write_text_atomic(out / name, data)
        for name, data in contents.items()
    ]


def write_json_atomic(path: str | os.PathLike[str], obj: Any) -> Path:
    """Write ``obj`` as indented JSON (NaN and infinities refused) atomically."""
    text = json.dumps(obj, indent=2, sort_keys=False, allow_nan=False, default=_to_builtin)
    return write_text_atomic(path, text + "\n")


def _to_builtin(obj: Any) -> Any:
    """Convert NumPy scalars and arrays for JSON."""
    import numpy as np

    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, Path):
        return str(obj)
    raise TypeError(f"cannot serialise {type(obj).__name__} to JSON")
