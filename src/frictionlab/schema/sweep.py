"""The ``frictionlab sweep`` file: declarations and the parser.

A base scenario plus a ``[grid]`` (cartesian product, the last key varying fastest) or a
``[[case]]`` list of overrides. Keys are the dotted names of ``--set``; ``+`` links keys
that take the same value. Every key must be present in the base scenario.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from frictionlab.errors import InputError
from frictionlab.schema.core import REQUIRED, Field, Section, loader
from frictionlab.schema.kinds import INTEGER, STRING

if TYPE_CHECKING:
    from frictionlab.sweep.cases import Case

__all__ = ["COMMANDS", "SWEEP_FILE", "SweepSpec", "load_sweep", "parse_sweep"]

#: The default most cases of a sweep (``max_cases``).
MAX_CASES = 100_000
#: Scenario commands a sweep can run.
COMMANDS = ("simulate", "roughness")
_FREE = Section("overrides", ())
SWEEP_FILE = Section("sweep", (
    Field("title", STRING, "names the sweep in the plot", "", ""),
    Field("base", STRING, "the base scenario file (relative to the sweep file)", "", REQUIRED),
    Field("max_cases", INTEGER, "the most cases the sweep may hold (counted before a grid is "
          "expanded)", "", MAX_CASES, low=1),
    Field("command", STRING, "when absent: simulate for a base with [law], roughness for one with "
          "[lower] or [sliding]", "", None, choices=COMMANDS),
    Field("grid", table=_FREE, doc='"section.key" = [values]: every combination is a case; '
          '"a.x+b.y" = [values] links keys (one axis, one column of sweep.csv)',
          json={"type": "object", "minProperties": 1}),
    Field("case", table=_FREE, many=True, doc='one table per case: "section.key" = value '
          '("a.x+b.y" links keys as in [grid])',
          json={"type": "array", "minItems": 1, "items": {"type": "object", "minProperties": 1}}),
), "A sweep file of `frictionlab sweep`: a base scenario and a [grid] or [[case]] tables "
   "of overrides.", one_of=(("grid", "case"),))  # fmt: skip


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep file (the base scenario itself is not read here)."""

    title: str
    base: Path
    command: str | None
    keys: tuple[str, ...]
    cases: tuple[Case, ...]


def parse_sweep(
    data: Mapping[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> SweepSpec:
    """Validate a parsed sweep file and expand its cases."""
    from frictionlab.sweep.cases import check_case_count, expand_grid, make_cases  # a cycle

    if not isinstance(data.get("base", ""), str) or not data.get("base"):
        SWEEP_FILE.table(dict(data), "")  # an unknown key first
        raise InputError('base must name the base scenario file, e.g. base = "scenario.toml"')
    values = SWEEP_FILE.read(dict(data), "")
    if "grid" in data:
        grid = _grid(data["grid"])
        keys = tuple(grid)
        overrides = expand_grid(grid, values["max_cases"])
    else:
        if isinstance(data["case"], list):
            check_case_count(len(data["case"]), "[[case]]", values["max_cases"])
        overrides = _case_list(data["case"])
        keys = tuple(dict.fromkeys(k for item in overrides for k in item))
    path = Path(base_dir) / values["base"]
    return SweepSpec(values["title"], path, values["command"], keys, make_cases(overrides))


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


LINK = "+"  # links keys that take the same value (frictionlab.sweep.cases.LINK)


def _links(where: str, key: str, values: list[Any], owner: dict[str, str]) -> list[str]:
    """The keys that ``key`` links ("a.x+b.y"), each set once across ``owner``; its
    ``values`` must be finite."""
    for v in values:
        if isinstance(v, float) and not math.isfinite(v):
            raise InputError(f"'{where}.{key}' = {v} must be finite")
    parts = key.split(LINK)
    if not all(parts):
        raise InputError(f"{where}.'{key}' has an empty key around '{LINK}'")
    for part in parts:
        if part in owner:
            raise InputError(f"{where} sets '{part}' twice ('{owner[part]}' and '{key}')")
        owner[part] = key
    return parts


def _grid(raw: Any) -> dict[str, list[Any]]:
    if not isinstance(raw, dict):
        raise InputError('grid must be a table of "section.key" = [values]')
    grid = _flatten(raw)
    if not grid:
        raise InputError('[grid] is empty: give at least one "section.key" = [values]')
    owner: dict[str, str] = {}
    for key, values in grid.items():
        if not isinstance(values, list) or not values:
            raise InputError(f"[grid].'{key}' must be a non-empty list of values, got {values!r}")
        _links("[grid]", key, values, owner)
    return grid


def _case_list(raw: Any) -> list[dict[str, Any]]:
    if not isinstance(raw, list) or not all(isinstance(v, dict) for v in raw):
        raise InputError("case must be an array of tables ([[case]])")
    if not raw:
        raise InputError("[[case]] is empty: give at least one case")
    out = []
    for i, item in enumerate(raw, 1):
        flat = _flatten(item)
        owner: dict[str, str] = {}
        if not flat:
            raise InputError(f'[[case]] #{i} is empty: give at least one "section.key" = value')
        where = f"[[case]] #{i}"  # "a.x+b.y" = v: the same value for each key
        out.append({p: v for k, v in flat.items() for p in _links(where, k, [v], owner)})
    return out


load_sweep = loader(SWEEP_FILE, parse_sweep, "a sweep file")
