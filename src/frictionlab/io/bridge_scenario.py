"""Bridge scenario files: the parser is :mod:`frictionlab.schema.bridge` (names kept here)."""

from __future__ import annotations

import os
from typing import Any

from frictionlab.schema.bridge import NOT_USED, BridgeOptions, BridgeScenario, parse_bridge

__all__ = ["BridgeOptions", "BridgeScenario", "parse_bridge_scenario"]

_NOT_USED = NOT_USED


def parse_bridge_scenario(data: dict[str, Any], base_dir: str | os.PathLike[str]) -> BridgeScenario:
    """:func:`frictionlab.schema.bridge.parse_bridge` (the older signature)."""
    return parse_bridge(data, base_dir=base_dir)
