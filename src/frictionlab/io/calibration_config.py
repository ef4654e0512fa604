"""Calibration files: the parser is :mod:`frictionlab.schema.calibrate` (names kept here)."""

from __future__ import annotations

import os
from typing import Any

from frictionlab.schema.calibrate import END_TOLERANCE, CalibrationConfig, parse_calibrate
from frictionlab.schema.calibrate import load_calibrate as load_calibration

__all__ = ["END_TOLERANCE", "CalibrationConfig", "load_calibration", "parse_calibration"]


def parse_calibration(
    data: dict[str, Any], base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> CalibrationConfig:
    """:func:`frictionlab.schema.calibrate.parse_calibrate` (the older name)."""
    return parse_calibrate(data, base_dir=base_dir, source=source)
