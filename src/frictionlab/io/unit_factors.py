"""Factors from a unit's name to an SI unit, by pint, remembered on disk.

:func:`si_factor` asks pint's default registry, once per unit and pint version: each
answer is kept in ``factors-<pint version>.json`` in the folder of pint's own definition
cache (``pint`` beside the compiled kernels' folders), so a later process reads it there
without importing pint (~0.4 CPU s, most of a small calibration's input reading). Only
pint's answers are stored, as ``repr`` of the float (exact round trip); a memo that cannot
be read or written is ignored and pint asked instead.
"""

from __future__ import annotations

import contextlib
import json
import math
from functools import cache
from pathlib import Path
from typing import Any

__all__ = ["memo_path", "registry", "si_factor"]


@cache
def registry() -> Any:
    """pint's default registry; its parsed definitions are cached on disk (pint's own
    ``cache_folder``, which the compile cache's pruning leaves alone), ~0.3 CPU s less
    per process. A cache that cannot be read or written (another process writing it, a
    read-only folder) gives the registry built from pint's definition files instead."""
    import pint

    try:
        return pint.UnitRegistry(cache_folder=_folder())
    except Exception:  # pint/flexcache raise OSError or pickle's errors
        return pint.UnitRegistry()


def _folder() -> Path:
    from frictionlab._compile_cache import cache_dir

    return cache_dir().parent / "pint"


@cache
def memo_path() -> Path | None:
    """The memo file of the installed pint version (None without pint's metadata)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return _folder() / f"factors-{version('pint')}.json"
    except PackageNotFoundError:
        return None


@cache
def _memo() -> dict[str, float]:
    path = memo_path()
    try:
        data = json.loads(path.read_text(encoding="utf-8")) if path is not None else {}
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict):
        return {}
    return {
        k: float(v)
        for k, v in data.items()
        if isinstance(k, str) and isinstance(v, float) and math.isfinite(v) and v > 0.0
    }


def si_factor(unit: str, si: str, dimension: str) -> float:
    """The factor from ``unit`` to ``si`` (pint's names, e.g. ``"min"``, ``"s"``), whose
    pint dimensionality must be ``dimension`` (e.g. ``"[time]"``).

    Raises pint's errors for an unknown unit and ValueError for another dimension.
    """
    key = f"{unit}|{dimension}|{si}"
    memo = _memo()
    if key in memo:
        return memo[key]
    q = registry().Quantity(1.0, unit)
    if not q.check(dimension):
        raise ValueError(f"{unit} is not {dimension}")
    factor = float(q.to(si).magnitude)
    if math.isfinite(factor) and factor > 0.0:
        memo[key] = factor
        _store(memo)
    return factor


def _store(memo: dict[str, float]) -> None:
    from frictionlab.io.atomic import write_text_atomic

    path = memo_path()
    if path is None:
        return
    with contextlib.suppress(OSError):  # a read-only cache: pint is asked next time
        write_text_atomic(path, json.dumps(memo, sort_keys=True, indent=0))
