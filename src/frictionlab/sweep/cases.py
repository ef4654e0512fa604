"""Cases of a sweep: cartesian grids, deterministic ids, overrides as ``--set`` text."""

from __future__ import annotations

import hashlib
import itertools
import json
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import tomli_w

from frictionlab.errors import InputError
from frictionlab.schema.sweep import MAX_CASES

__all__ = [
    "LINK",
    "MAX_CASES",
    "Case",
    "case_id",
    "check_case_count",
    "check_key",
    "expand_grid",
    "override_strings",
]


@dataclass(frozen=True)
class Case:
    """One scenario of a sweep: its id, its position and its overrides (dotted key -> value)."""

    id: str
    index: int
    overrides: dict[str, Any]


def case_id(overrides: Mapping[str, Any]) -> str:
    """A 12-hex-digit id that depends only on the overrides (not on their order)."""
    text = json.dumps(sorted(overrides.items()), separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:12]


#: Joins keys that take the same value together in a grid (``"a.x+b.y" = [1, 2]``).
LINK = "+"


def check_case_count(count: int, where: str, max_cases: int = MAX_CASES) -> None:
    """Raise :class:`InputError` when ``count`` cases exceed ``max_cases`` (before expanding)."""
    if count > max_cases:
        raise InputError(
            f"{where} makes {count:.6g} cases, more than max_cases = {max_cases}: allowed "
            "fewer values, or a larger max_cases at the top of the sweep file"
        )


def expand_grid(
    grid: Mapping[str, Sequence[Any]], max_cases: int = MAX_CASES
) -> list[dict[str, Any]]:
    """Cartesian product of ``{key: [values]}``; the last key varies fastest.

    A key ``"a.x+b.y"`` links keys: each value is given to all of them (one axis). More
    than ``max_cases`` cases raise :class:`InputError` before any is made.
    """
    count = 1
    for values in grid.values():
        count *= len(values)
    check_case_count(count, "[grid]", max_cases)
    keys = [key.split(LINK) for key in grid]
    return [
        {path: value for paths, value in zip(keys, combo, strict=True) for path in paths}
        for combo in itertools.product(*grid.values())
    ]


def make_cases(overrides: Sequence[dict[str, Any]]) -> tuple[Case, ...]:
    """Number and name the cases; a repeated case is an :class:`InputError`."""
    seen: dict[str, int] = {}
    cases = []
    for i, item in enumerate(overrides):
        cid = case_id(item)
        if cid in seen:
            raise InputError(
                f"sweep case {i + 1} repeats case {seen[cid] + 1} ({format_overrides(item)})"
            )
        seen[cid] = i
        cases.append(Case(cid, i, dict(item)))
    return tuple(cases)


def format_value(value: Any) -> str:
    """``value`` as inline TOML text (what ``--set key=TEXT`` parses back to the same value).

    Tables, also inside arrays, are written inline (``{ a = 1 }``), so every value of a
    sweep file has a ``--set`` form; the scenario's parser then judges it.
    """
    if isinstance(value, dict):
        items = ", ".join(f"{_key(k)} = {format_value(v)}" for k, v in value.items())
        return f"{{ {items} }}" if items else "{}"
    if isinstance(value, list):
        return "[" + ", ".join(format_value(v) for v in value) + "]"
    text = tomli_w.dumps({"v": value}).strip()
    text = text.removeprefix("v =").strip()
    if tomllib.loads(f"v = {text}")["v"] != value:  # pragma: no cover - a tomli_w guarantee
        raise InputError(f"cannot write {value!r} as a TOML value")
    return text


def _key(key: str) -> str:
    """A table key as TOML text (bare when it can be, else quoted)."""
    return tomli_w.dumps({key: 0}).split("=", 1)[0].strip()


def override_strings(overrides: Mapping[str, Any]) -> list[str]:
    """The overrides as ``section.key=value`` strings (the form of ``--set``)."""
    return [f"{key}={format_value(value)}" for key, value in overrides.items()]


def format_overrides(overrides: Mapping[str, Any]) -> str:
    return ", ".join(f"{k} = {format_value(v)}" for k, v in overrides.items()) or "no overrides"


def check_key(data: Mapping[str, Any], dotted: str, where: str) -> None:
    """Raise :class:`InputError` unless ``dotted`` names a value of ``data``.

    The parts are table keys; a number selects an entry of an array of tables, counted
    from 1 (``program.2.duration``), as in ``--set``.
    """
    node: Any = data
    for depth, part in enumerate(dotted.split(".")):
        here = ".".join(dotted.split(".")[: depth + 1])
        if isinstance(node, list):
            if not part.isdigit() or not 1 <= int(part) <= len(node):
                raise InputError(
                    f"{where}: '{dotted}': '{here}' must be an entry number from 1 to {len(node)}"
                )
            node = node[int(part) - 1]
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            raise InputError(
                f"{where}: the base scenario has no '{here}' (key '{dotted}'); a swept key "
                "must be present in the base scenario"
            )
