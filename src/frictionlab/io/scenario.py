"""Simulate scenarios: the parser is :mod:`frictionlab.schema.scenario` (names kept here)."""

from __future__ import annotations

from frictionlab.schema.scenario import (
    LAW_KEYS,
    MachineRun,
    OutputOptions,
    RunOptions,
    Scenario,
    law_table,
    load_scenario,
    parse_initial_table,
    parse_law_table,
    parse_program_tables,
    parse_scenario,
)

__all__ = [
    "LAW_KEYS",
    "MachineRun",
    "OutputOptions",
    "RunOptions",
    "Scenario",
    "law_table",
    "load_scenario",
    "parse_initial_table",
    "parse_law_table",
    "parse_program_tables",
    "parse_scenario",
]
