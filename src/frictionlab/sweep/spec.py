"""The sweep file: parsed by :mod:`frictionlab.schema.sweep` (names kept here); what the
base scenario of a sweep is and which files it names.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from frictionlab.errors import InputError
from frictionlab.schema.sweep import COMMANDS, SweepSpec
from frictionlab.schema.sweep import parse_sweep as _parse_sweep

__all__ = ["COMMANDS", "SweepSpec", "detect_command", "named_files", "parse_sweep"]


def parse_sweep(data: Mapping[str, Any], sweep_dir: Path) -> SweepSpec:
    """:func:`frictionlab.schema.sweep.parse_sweep` (the older signature)."""
    return _parse_sweep(data, base_dir=sweep_dir)


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
