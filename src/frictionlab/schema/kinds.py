"""Value kinds of the input declarations: :class:`Kind` and the shared kinds.

A kind says how a key's value is read from TOML (typed, one-line errors naming the key)
and how it is written in JSON Schema. :mod:`frictionlab.schema.core` declares the keys.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from frictionlab.errors import InputError
from frictionlab.io.config import Table, coerce

if TYPE_CHECKING:
    from frictionlab.schema.core import Field

__all__ = [
    "BOOL", "DEFS", "INTEGER", "NUMBER", "NUMBERS", "PAIRS", "STRING", "Kind", "choice", "either",
    "listed",
]  # fmt: skip


@dataclass(frozen=True)
class Kind:
    """A value kind: how a value is read from TOML and how it is written in JSON Schema.

    ``read(table, field)`` returns the typed value of a present key; ``json`` is the
    JSON Schema of a value (``$defs`` names are resolved by the generator). ``entries``:
    the field's choices and range apply to each entry of a list.
    """

    name: str
    read: Callable[[Table, Field], Any]
    json: Mapping[str, Any]
    entries: bool = False


def _scalar(kind: type) -> Callable[[Table, Field], Any]:
    def read(t: Table, f: Field) -> Any:
        return t.get(f.name, kind, choices=f.choices, check=f.check(), allowed=f.allowed_text())

    return read


def _numbers(t: Table, f: Field) -> Any:
    """A number or a non-empty list of numbers (one per point)."""
    value, name = t.raw(f.name), f"{t.where}.{f.name}"
    if isinstance(value, list):
        if not value:
            raise InputError(f"{name} must be a number or a non-empty list of numbers, got []")
        return [coerce(v, float, f"{name}[{i}]") for i, v in enumerate(value)]
    return coerce(value, float, name)


def _pairs(t: Table, f: Field) -> Any:
    """A pair ``[a, b]`` or a list of pairs (one per point)."""
    value, name = t.raw(f.name), f"{t.where}.{f.name}"
    if isinstance(value, list) and len(value) == 2 and not any(isinstance(v, list) for v in value):
        return [coerce(v, float, f"{name}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, list) and value and all(isinstance(v, list) for v in value):
        out = []
        for i, pair in enumerate(value):
            if len(pair) != 2:
                raise InputError(f"{name}[{i}] must have 2 entries, got {len(pair)}")
            out.append([coerce(v, float, f"{name}[{i}][{j}]") for j, v in enumerate(pair)])
        return out
    raise InputError(f"{name} must be a pair [a, b] or a list of pairs, got {value!r}")


def listed(
    items: type, json_items: str, length: int | tuple[int, ...] | None = None, *,
    scalar: bool = False, unique: bool = False, count: tuple[int, int | None] | None = None,
) -> Kind:  # fmt: skip
    """A list of ``items`` (float, int or str), optionally of a given length (or lengths).

    Each entry is checked against the field's choices and range. ``scalar``: one value
    reads as a list of one; ``unique``: no value twice; ``count``: (least, most) entries.
    """
    lengths = (length,) if isinstance(length, int) else length
    schema: dict[str, Any] = {"type": "array", "items": {"type": json_items}}
    low, high = (min(lengths), max(lengths)) if lengths else count or (None, None)
    schema.update({k: v for k, v in (("minItems", low), ("maxItems", high)) if v is not None})
    if unique:
        schema["uniqueItems"] = True

    def read(t: Table, f: Field) -> Any:
        raw, name = t.raw(f.name), f"{t.where}.{f.name}"
        values = t.get_list(f.name, items, length=length) if not scalar or isinstance(
            raw, list) else [t.get(f.name, items)]  # fmt: skip
        if count is not None and not count[0] <= len(values) <= (count[1] or len(values)):
            most = f"{count[0]} to {count[1]}" if count[1] else f"{count[0]} or more"
            what = "is empty" if not values else f"= {raw!r} is invalid"
            raise InputError(f"{name} {what}: allowed {most} entries")
        ok = f.check()
        for i, v in enumerate(values):
            at = f"{name}[{i}]" if isinstance(raw, list) else name
            if f.choices is not None and v not in f.choices:
                options = ", ".join(repr(c) for c in f.choices)
                raise InputError(f"{at} = {v!r} is not allowed; choose one of {options}")
            if ok is not None and not ok(v):
                raise InputError(f"{at} = {v!r} is invalid: allowed {f.allowed_text()}")
            if unique and v in values[:i]:
                raise InputError(f"{name} has {v!r} twice: allowed distinct values")
        return values

    kind = Kind(f"list of {json_items}s", read, schema, entries=True)
    return Kind(f"{json_items} or {kind.name}", read, {"oneOf": [{"type": json_items}, schema]},
                entries=True) if scalar else kind  # fmt: skip


def either(*kinds: Kind) -> Kind:
    """A value of one of ``kinds``: the one whose JSON type is the value's (else the last)."""

    def read(t: Table, f: Field) -> Any:
        raw = t.raw(f.name)
        kind = "string" if isinstance(raw, str) else "array" if isinstance(raw, list) else None
        chosen = next((k for k in kinds if k.json.get("type") == kind), kinds[-1])
        try:
            return chosen.read(t, f)
        except InputError:
            if kind != "string" or chosen is kinds[-1]:  # a string not among the choices
                raise
        unit = f" ({f.unit})" if f.unit else ""
        raise InputError(f"{t.where}.{f.name} = {raw!r} is invalid: allowed {name}{unit}")

    name = " or ".join(k.name for k in kinds)
    return Kind(name, read, {"oneOf": [dict(k.json) for k in kinds]})


def choice(*values: str) -> Kind:
    """One of the strings ``values``."""
    read = lambda t, f: t.get(f.name, str, choices=values)  # noqa: E731
    return Kind(" | ".join(map(repr, values)), read, {"type": "string", "enum": list(values)})


NUMBER = Kind("number", _scalar(float), {"type": "number"})
INTEGER = Kind("integer", _scalar(int), {"type": "integer"})
STRING = Kind("string", _scalar(str), {"type": "string"})
BOOL = Kind("bool", _scalar(bool), {"type": "boolean"})
#: A number, or a list of numbers (one per contact point).
NUMBERS = Kind("number(s)", _numbers, {"$ref": "#/$defs/numbers"})
#: A pair [a, b], or a list of pairs (one per contact point).
PAIRS = Kind("pair(s)", _pairs, {"$ref": "#/$defs/pairs"})
#: Schemas of the shared value kinds (``$defs`` of each generated schema that uses them).
DEFS: dict[str, Any] = {
    "numbers": {"anyOf": [{"type": "number"},
                          {"type": "array", "items": {"type": "number"}, "minItems": 1}]},
    "pairs": {"anyOf": [{"$ref": "#/$defs/pair"},
                        {"type": "array", "items": {"$ref": "#/$defs/pair"}, "minItems": 1}]},
    "pair": {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2},
}  # fmt: skip
