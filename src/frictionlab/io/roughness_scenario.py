"""Roughness scenario files: the parser is :mod:`frictionlab.schema.roughness` (names kept)."""

from __future__ import annotations

import os
from typing import Any

from frictionlab.schema.roughness import (
    ON_INVALID_KEYS,
    SURFACE_KINDS,
    AdhesionOptions,
    HierarchyOptions,
    MultiscaleOptions,
    RoughnessScenario,
    WearOptions,
    parse_roughness,
)

__all__ = [
    "ON_INVALID_KEYS",
    "SURFACE_KINDS",
    "AdhesionOptions",
    "HierarchyOptions",
    "MultiscaleOptions",
    "RoughnessScenario",
    "WearOptions",
    "parse_roughness_scenario",
]


def parse_roughness_scenario(
    data: dict[str, Any], base_dir: str | os.PathLike[str] = "."
) -> RoughnessScenario:
    """:func:`frictionlab.schema.roughness.parse_roughness` (the older signature)."""
    return parse_roughness(data, base_dir=base_dir)
