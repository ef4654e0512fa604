"""The sweep file: a base scenario plus a ``[grid]`` or ``[[case]]`` list of overrides.

::

    title = "..."                      # optional
    base = "scenario.toml"             # relative to the sweep file
    command = "simulate"               # optional: "simulate" or "roughness" (else detected)
    [grid]                             # cartesian product, the last key varying fastest
    "program.2.duration" = [1.0, 10.0, 100.0]
    "program.1.velocity+program.3.velocity" = [1e-6, 1e-5]   # linked: one value for both
    # or, instead of [grid], one table per case:
    # [[case]]
    # "law.mu_s" = 0.6

Keys are the dotted names of ``--set`` (bare dotted keys work too); ``+`` links keys that
take the same value (in ``[grid]`` and in ``[[case]]``); keys that vary together with
different values are listed as ``[[case]]`` tables. Every key must be present in the base
scenario.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from frictionlab.errors import InputError
from frictionlab.sweep.cases import (
    LINK,
    MAX_CASES,
    Case,
    check_case_count,
    expand_grid,
    make_cases,
)

__all__ = ["COMMANDS", "SweepSpec", "detect_command", "named_files", "parse_sweep"]

#: Scenario commands a sweep can run.
COMMANDS = ("simulate", "roughness")
_TOP_KEYS = ("title", "base", "command", "max_cases", "grid", "case")


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep file (the base scenario itself is not read here)."""

    title: str
    base: Path
    command: str | None
    keys: tuple[str, ...]
    cases: tuple[Case, ...]


def parse_sweep(data: Mapping[str, Any], sweep_dir: Path) -> SweepSpec:
    """Validate a parsed sweep file and expand its cases."""
    for key in data:
        if key not in _TOP_KEYS:
            raise InputError(
                f"unknown key '{key}' in the sweep file; allowed: {', '.join(_TOP_KEYS)}"
            )
    title = data.get("title", "")
    if not isinstance(title, str):
        raise InputError(f"title must be a string, got {title!r}")
    base = data.get("base")
    if not isinstance(base, str) or not base:
        raise InputError('base must name the base scenario file, e.g. base = "scenario.toml"')
    command = data.get("command")
    if command is not None and command not in COMMANDS:
        raise InputError(
            f"command = {command!r} is not allowed; choose one of {', '.join(COMMANDS)}"
        )
    max_cases = data.get("max_cases", MAX_CASES)
    if isinstance(max_cases, bool) or not isinstance(max_cases, int) or max_cases < 1:
        raise InputError(f"max_cases = {max_cases!r} is invalid: allowed an integer >= 1")
    if ("grid" in data) == ("case" in data):
        raise InputError("a sweep file needs exactly one of [grid] or [[case]] tables")
    if "grid" in data:
        grid = _grid(data["grid"])
        keys = tuple(grid)
        overrides = expand_grid(grid, max_cases)
    else:
        if isinstance(data["case"], list):
            check_case_count(len(data["case"]), "[[case]]", max_cases)
        overrides = _case_list(data["case"])
        keys = tuple(dict.fromkeys(k for item in overrides for k in item))
    path = Path(base) if Path(base).is_absolute() else sweep_dir / base
    return SweepSpec(title, path, command, keys, make_cases(overrides))


def detect_command(base: Mapping[str, Any], given: str | None) -> str:
    """The command of a base scenario: ``given``, else simulate for [law], roughness for
    [lower]/[upper]."""
    if given is not None:
        return given
    if "law" in base:
        return "simulate"
    if "lower" in base or "sliding" in base:
        return "roughness"
    raise InputError(
        "command: cannot tell the kind of the base scenario (no [law], [lower] or [sliding]); "
        'give command = "simulate" or "roughness"'
    )


def named_files(command: str, data: Mapping[str, Any]) -> list[str]:
    """The input files a (validated) scenario names, as written (relative to its folder).

    simulate: the ``file`` of every ``kind = "table"`` programme segment; roughness: the
    ``path`` of a ``kind = "file"`` surface.
    """
    names: list[str] = []
    if command == "simulate":
        program = data.get("program")
        for seg in program if isinstance(program, list) else ():
            if isinstance(seg, dict) and seg.get("kind") == "table":
                names.append(str(seg["file"]))
    else:
        for side in ("lower", "upper"):
            table = data.get(side)
            if isinstance(table, dict) and table.get("kind") == "file":
                names.append(str(table["path"]))
    return list(dict.fromkeys(names))


def _flatten(table: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested tables -> dotted keys (bare ``program.2.duration = ...`` nests in TOML)."""
    out: dict[str, Any] = {}
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(_flatten(value, f"{name}."))
        else:
            out[name] = value
    return out


def _check_value(key: str, value: Any) -> None:
    if isinstance(value, float) and not math.isfinite(value):
        raise InputError(f"'{key}' = {value} must be finite")


def _grid(raw: Any) -> dict[str, list[Any]]:
    if not isinstance(raw, dict):
        raise InputError('grid must be a table of "section.key" = [values]')
    grid = _flatten(raw)
    if not grid:
        raise InputError('[grid] is empty: give at least one "section.key" = [values]')
    owner: dict[str, str] = {}
    for key, values in grid.items():
        if not all(key.split(LINK)):
            raise InputError(f"[grid].'{key}' has an empty key around '{LINK}'")
        for part in key.split(LINK):
            if part in owner:
                raise InputError(
                    f"[grid] sets '{part}' twice ('{owner[part]}' and '{key}'): give each "
                    "key one axis"
                )
            owner[part] = key
        if not isinstance(values, list) or not values:
            raise InputError(f"[grid].'{key}' must be a non-empty list of values, got {values!r}")
        for v in values:
            _check_value(f"[grid].{key}", v)
    return grid


def _case_list(raw: Any) -> list[dict[str, Any]]:
    if not isinstance(raw, list) or not all(isinstance(v, dict) for v in raw):
        raise InputError("case must be an array of tables ([[case]])")
    if not raw:
        raise InputError("[[case]] is empty: give at least one case")
    out = []
    for i, item in enumerate(raw, 1):
        flat = _flatten(item)
        if not flat:
            raise InputError(f'[[case]] #{i} is empty: give at least one "section.key" = value')
        linked: dict[str, Any] = {}
        for key, value in flat.items():
            _check_value(f"[[case]] #{i}.{key}", value)
            if not all(key.split(LINK)):
                raise InputError(f"[[case]] #{i}.'{key}' has an empty key around '{LINK}'")
            for part in key.split(LINK):  # "a.x+b.y" = v: the same value for each key
                if part in linked:
                    raise InputError(f"[[case]] #{i} sets '{part}' twice")
                linked[part] = value
        out.append(linked)
    return out
