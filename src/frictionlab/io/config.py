"""Reading TOML configuration files with clear, one-line errors.

:class:`Table` wraps one TOML table and hands out typed values; every problem is an
:class:`~frictionlab.errors.InputError` that names the key (``[law].mu_s``), the value
and what is allowed. :meth:`Table.finish` rejects keys nobody asked for, so a typo is
never silently ignored.
"""

from __future__ import annotations

import difflib
import math
import os
import tomllib
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any

import tomli_w

from frictionlab.errors import InputError
from frictionlab.io.inputs import read_input_text

__all__ = [
    "REQUIRED", "Table", "apply_overrides", "coerce", "format_toml", "load_toml", "unknown_key",
]  # fmt: skip


class _Required:
    def __repr__(self) -> str:
        return "REQUIRED"


#: Sentinel default meaning "the key must be present".
REQUIRED: Any = _Required()

_TYPE_NAMES = {float: "a number", int: "an integer", str: "a string", bool: "true or false"}


def load_toml(path: str | os.PathLike[str]) -> dict[str, Any]:
    """Read a TOML file; unreadable or malformed files raise :class:`InputError`.

    A FIFO, device or directory is refused by type; a byte-order mark is allowed
    (:func:`frictionlab.io.inputs.decode_text`).
    """
    p = Path(path)
    text = read_input_text(p)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"file '{p}' is not valid TOML: {exc}") from None


def format_toml(data: dict[str, Any]) -> str:
    """TOML text of ``data`` (nested mappings, lists, numbers, strings, booleans).

    ``None`` values are left out (TOML has no null). Floats keep their exact repr, so a
    file written here and read back with :func:`load_toml` gives the same numbers.
    """
    return tomli_w.dumps(_drop_none(data))


def _drop_none(obj: Any) -> Any:
    if isinstance(obj, dict):
        return {k: _drop_none(v) for k, v in obj.items() if v is not None}
    if isinstance(obj, list | tuple):
        return [_drop_none(v) for v in obj]
    return obj


def apply_overrides(data: dict[str, Any], overrides: Iterable[str]) -> dict[str, Any]:
    """Return a copy of ``data`` with ``section.key=value`` overrides applied.

    The value is parsed as a TOML value (``0.6``, ``"tear"``, ``[1.0, 0.5]``); a bare
    word that is not valid TOML is taken as a string. A numeric part selects an entry
    of an array of tables, counted from 1 as in the messages (``program.2.steps=50``).
    """
    result = _deep_copy(data)
    for item in overrides:
        if "=" not in item:
            raise InputError(f"override '{item}' must look like section.key=value")
        dotted, text = item.split("=", 1)
        parts = [part.strip() for part in dotted.strip().split(".")]
        if not all(parts):
            raise InputError(f"override '{item}' has an empty key")
        try:
            value = tomllib.loads(f"v = {text.strip()}")["v"]
        except tomllib.TOMLDecodeError:
            value = text.strip()
        node: Any = result
        for part in parts[:-1]:
            if isinstance(node, list):
                node = _list_entry(node, part, item)
                continue
            child = node.setdefault(part, {})
            if not isinstance(child, dict | list):
                raise InputError(f"override '{item}': '{part}' is not a table")
            node = child
        if isinstance(node, list):
            raise InputError(f"override '{item}': '{parts[-2]}' is an array; name an entry")
        node[parts[-1]] = value
    return result


def _list_entry(node: list[Any], part: str, item: str) -> dict[str, Any]:
    """Entry ``part`` (1-based) of an array of tables."""
    if not part.isdigit() or not 1 <= int(part) <= len(node):
        raise InputError(
            f"override '{item}': '{part}' must be an entry number from 1 to {len(node)}"
        )
    entry = node[int(part) - 1]
    if not isinstance(entry, dict):
        raise InputError(f"override '{item}': entry {part} is not a table")
    return entry


def _deep_copy(obj: Any) -> Any:
    if isinstance(obj, dict):
        return {k: _deep_copy(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_deep_copy(v) for v in obj]
    return obj


class Table:
    """One TOML table with typed, checked access.

    Parameters
    ----------
    data:
        The parsed table.
    where:
        How the table is named in messages, e.g. ``"[law]"`` or ``"[[program]] #2"``.
    """

    def __init__(self, data: Any, where: str) -> None:
        if not isinstance(data, dict):
            raise InputError(f"{where} must be a table, got {type(data).__name__}")
        self._data = data
        self.where = where
        self._used: set[str] = set()

    def __contains__(self, key: str) -> bool:
        return key in self._data

    def keys(self) -> list[str]:
        return list(self._data)

    def mapping(self) -> dict[str, Any]:
        """A shallow copy of the table (does not mark any key as used)."""
        return dict(self._data)

    def _name(self, key: str) -> str:
        return f"{self.where}.{key}" if self.where else key

    def raw(self, key: str, default: Any = REQUIRED) -> Any:
        """The untyped value (marks the key as used)."""
        self._used.add(key)
        if key not in self._data:
            if default is REQUIRED:
                raise InputError(f"missing required key {self._name(key)}")
            return default
        return self._data[key]

    def get(
        self,
        key: str,
        kind: type,
        default: Any = REQUIRED,
        *,
        choices: Sequence[Any] | None = None,
        check: Callable[[Any], bool] | None = None,
        allowed: str = "",
    ) -> Any:
        """A scalar value of type ``kind`` (float accepts integers; bool is never a number).

        ``choices`` restricts the value to a set; ``check`` is a predicate whose failure is
        reported with ``allowed`` as the description of the allowed range.
        """
        value = self.raw(key, default)
        if value is default and key not in self._data:
            return value
        value = coerce(value, kind, self._name(key))
        if choices is not None and value not in choices:
            options = ", ".join(repr(c) for c in choices)
            raise InputError(
                f"{self._name(key)} = {value!r} is not allowed; choose one of {options}"
            )
        if check is not None and not check(value):
            raise InputError(f"{self._name(key)} = {value!r} is invalid: allowed {allowed}")
        return value

    def get_list(
        self,
        key: str,
        kind: type = float,
        default: Any = REQUIRED,
        *,
        length: int | tuple[int, ...] | None = None,
    ) -> Any:
        """A list of values of type ``kind``, optionally of a given length (or lengths)."""
        value = self.raw(key, default)
        if value is default and key not in self._data:
            return value
        name = self._name(key)
        if not isinstance(value, list):
            raise InputError(f"{name} must be a list, got {_describe(value)}")
        lengths = (length,) if isinstance(length, int) else length
        if lengths is not None and len(value) not in lengths:
            want = " or ".join(str(n) for n in lengths)
            raise InputError(f"{name} must have {want} entries, got {len(value)}")
        return [coerce(v, kind, f"{name}[{i}]") for i, v in enumerate(value)]

    def table(self, key: str, required: bool = False) -> Table | None:
        """A sub-table, or ``None`` when absent and not required."""
        value = self.raw(key, REQUIRED if required else None)
        if value is None:
            return None
        return Table(value, f"[{key}]" if not self.where else f"{self.where}.{key}")

    def tables(self, key: str, required: bool = False) -> list[Table]:
        """An array of tables (``[[key]]``)."""
        value = self.raw(key, REQUIRED if required else [])
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise InputError(f"{self._name(key)} must be an array of tables ([[{key}]])")
        return [Table(v, f"[[{key}]] #{i + 1}") for i, v in enumerate(value)]

    def finish(self, allowed: Sequence[str] = ()) -> None:
        """Reject keys that were never read; the message lists those read and ``allowed``."""
        unknown = [k for k in self._data if k not in self._used]
        if unknown:
            raise InputError(
                unknown_key(self._name(unknown[0]), unknown[0], self._used | set(allowed))
            )


def unknown_key(name: str, key: str, allowed: Iterable[str]) -> str:
    """The message for an unknown key ``name``, with the nearest allowed key when one is close."""
    keys = sorted(allowed)
    near = difflib.get_close_matches(str(key), keys, n=1)
    hint = f" (did you mean '{near[0]}'?)" if near else ""
    return f"unknown key {name}{hint}; allowed keys here: {', '.join(keys) or 'none'}"


def _describe(value: Any) -> str:
    return f"{type(value).__name__} {value!r}"


def coerce(value: Any, kind: type, name: str) -> Any:
    """``value`` as ``kind`` (float accepts integers, bool is never a number); else one line."""
    if kind is float:
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise InputError(f"{name} must be {_TYPE_NAMES[float]}, got {_describe(value)}")
        value = float(value)
        if not math.isfinite(value):
            raise InputError(f"{name} = {value} must be finite")
        return value
    if kind is int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise InputError(f"{name} must be {_TYPE_NAMES[int]}, got {_describe(value)}")
        return value
    if not isinstance(value, kind) or (kind is not bool and isinstance(value, bool)):
        want = _TYPE_NAMES.get(kind, kind.__name__)
        raise InputError(f"{name} must be {want}, got {_describe(value)}")
    return value
