"""Reading input files: refused by type before opening, decoded by one rule.

Every reader of a user's file (TOML scenarios, tables, tribometer exports, topography
files, the files a sweep names) goes through :func:`check_input_file` before it opens
the file: a directory, a FIFO, a socket or a device (``/dev/zero``, a terminal) is
refused with one line, since opening or reading it could block or never end.

Text is decoded by :func:`decode_text`, the same rule everywhere: UTF-8, where a leading
byte-order mark (as some editors and spreadsheet programs write) is dropped.
"""

from __future__ import annotations

import codecs
import os
import stat
from pathlib import Path

from frictionlab.errors import InputError

__all__ = ["check_input_file", "decode_text", "read_input_bytes", "read_input_text"]

#: Byte-order marks of the encodings other than UTF-8 (refused with their name).
_OTHER_BOMS: tuple[tuple[bytes, str], ...] = (
    (codecs.BOM_UTF32_LE, "UTF-32"),
    (codecs.BOM_UTF32_BE, "UTF-32"),
    (codecs.BOM_UTF16_LE, "UTF-16"),
    (codecs.BOM_UTF16_BE, "UTF-16"),
)


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "not a regular file"


def check_input_file(path: str | os.PathLike[str], what: str = "file") -> Path:
    """Raise :class:`InputError` unless ``path`` is an existing regular file (links followed).

    ``what`` names the file in the message (``"table"``, ``"surface file"``). Nothing is
    opened: a FIFO or a device is refused by its type alone.
    """
    p = Path(path)
    try:
        mode = os.stat(p).st_mode
    except FileNotFoundError:
        raise InputError(f"cannot read {what} '{p}': no such file") from None
    except OSError as exc:
        raise InputError(f"cannot read {what} '{p}': {exc.strerror or exc}") from None
    if not stat.S_ISREG(mode):
        raise InputError(f"cannot read {what} '{p}': it is {_kind(mode)}, not a regular file")
    return p


def read_input_bytes(path: str | os.PathLike[str], what: str = "file") -> bytes:
    """The bytes of a regular file (see :func:`check_input_file`); errors are one line."""
    p = check_input_file(path, what)
    try:
        return p.read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read {what} '{p}': {exc.strerror or exc}") from None


def decode_text(raw: bytes, where: str) -> str:
    """Text of ``raw``: UTF-8, with or without a byte-order mark (``where`` names it).

    A UTF-16 or UTF-32 byte-order mark, or bytes that are not UTF-8, raise
    :class:`InputError` asking for UTF-8.
    """
    if raw.startswith(codecs.BOM_UTF8):
        raw = raw[len(codecs.BOM_UTF8) :]
    else:
        for bom, name in _OTHER_BOMS:
            if raw.startswith(bom):
                raise InputError(f"{where} is not UTF-8 text ({name}): save it as UTF-8")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(
            f"{where} is not UTF-8 text (byte {exc.start + 1}): save it as UTF-8"
        ) from None


def read_input_text(path: str | os.PathLike[str], what: str = "file") -> str:
    """The text of a regular file, decoded by :func:`decode_text`."""
    return decode_text(read_input_bytes(path, what), f"{what} '{Path(path)}'")
