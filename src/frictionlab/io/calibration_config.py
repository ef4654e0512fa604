"""Calibration files: TOML -> the starting law, what to fit, the measured curves.

The schema (docs/calibration.md has every key)::

    title = "..."                     # optional
    [law]                             # the starting values, as in a simulate scenario
    [fit]
    parameters = ["mu_s", "mu_k", "kappa", "xi"]   # the rest of [law] stays fixed
    max_evaluations = 100             # optional: least-squares function evaluations
    profile = true                    # optional: profile likelihood of poorly identified ones
    profile_points = 9                # optional: grid values per profile
    profile_max = 2                   # optional: profile at most this many (worst first)
    [fit.bounds]                      # optional: name = [low, high] (physical units)
    [[data]]                          # one or more measured curves
    file = "run.csv"
    columns = { time = "Time", slip = "Displacement", friction_ratio = "COF" }  # optional
    units = { time = "min", slip = "mm" }                                        # optional
    weight = 1.0                      # optional
    [data.initial]                    # as [initial] of a simulate scenario
    [[data.program]]                  # as [[program]] of a simulate scenario

Everything is validated before any fit starts; every problem is one
:class:`~frictionlab.errors.InputError` or :class:`~frictionlab.errors.ParameterError`
line naming the key (``[[data]] #2.units.time``) or the file.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.calibration.fit import make_space
from frictionlab.calibration.model import FITTABLE, Curve, program_duration
from frictionlab.driver.simulate import count_points
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import Table, apply_overrides, load_toml, unknown_key
from frictionlab.io.scenario import parse_initial_table, parse_law_table, parse_program_tables
from frictionlab.io.tribometer import SLIP_UNITS, TIME_UNITS, read_tribometer
from frictionlab.subloading import SubloadingParams

__all__ = ["END_TOLERANCE", "CalibrationConfig", "load_calibration", "parse_calibration"]

#: Data may run past the programme's end by this fraction of its duration (round-off of
#: the lab's clock), and are then clipped to the end.
END_TOLERANCE = 1e-6


#: The most grid values of one likelihood profile (each is a fit of the other parameters).
MAX_PROFILE_POINTS = 1001


@dataclass(frozen=True)
class CalibrationConfig:
    """A validated calibration file."""

    title: str
    params: SubloadingParams
    law_given: dict[str, Any]
    names: tuple[str, ...]
    bounds: dict[str, tuple[float, float]]
    curves: tuple[Curve, ...]
    data_echo: tuple[dict[str, Any], ...]
    max_evaluations: int = 100
    profile: bool = True
    profile_points: int = 9
    profile_max: int = 2
    source: str = ""


def _parse_fit(
    t: Table,
) -> tuple[list[str], dict[str, tuple[float, float]], int, bool, int, int]:
    names = t.get_list("parameters", str)
    for name in names:
        if name not in FITTABLE:
            raise InputError(
                f"[fit].parameters: '{name}' cannot be fitted; choose from {', '.join(FITTABLE)}"
            )
    bounds: dict[str, tuple[float, float]] = {}
    bt = t.table("bounds")
    if bt is not None:
        for key in bt.mapping():
            pair = bt.get_list(key, float, length=2)
            if not pair[0] < pair[1]:
                raise InputError(f"[fit].bounds.{key} = {pair} must be [low, high] with low < high")
            bounds[key] = (pair[0], pair[1])
        bt.finish()
    max_eval = t.get("max_evaluations", int, 100, check=lambda v: v >= 1, allowed="an integer >= 1")
    profile = t.get("profile", bool, True)
    points = t.get(
        "profile_points", int, 9, check=lambda v: 3 <= v <= MAX_PROFILE_POINTS,
        allowed=f"an integer from 3 to {MAX_PROFILE_POINTS}",
    )  # fmt: skip
    most = t.get("profile_max", int, 2, check=lambda v: v >= 0, allowed="an integer >= 0")
    t.finish()
    return names, bounds, max_eval, profile if most > 0 else False, points, most


def _mapping(t: Table, key: str, allowed: dict[str, Any]) -> dict[str, str]:
    """An inline table of strings whose keys are in ``allowed`` (values checked if a dict)."""
    sub = t.table(key)
    if sub is None:
        return {}
    out = {}
    for k in sub.mapping():
        if k not in allowed:
            raise InputError(unknown_key(f"{sub.where}.{k}", k, allowed))
        choices = allowed[k]
        out[k] = sub.get(k, str, choices=tuple(choices) if choices else None)
    sub.finish()
    return out


def _parse_data(t: Table, base: Path) -> tuple[Curve, dict[str, Any]]:
    name = t.get("file", str)
    columns = _mapping(t, "columns", {"time": None, "slip": None, "friction_ratio": None})
    units = _mapping(t, "units", {"time": TIME_UNITS, "slip": SLIP_UNITS})
    weight = t.get(
        "weight", float, 1.0, check=lambda v: v > 0 and math.isfinite(v), allowed="a number > 0"
    )
    initial = t.raw("initial")
    programs = t.raw("program")
    t.finish()
    if not isinstance(programs, list) or not all(isinstance(p, dict) for p in programs):
        raise InputError(f"{t.where}.program must be an array of tables ([[data.program]])")
    init, _ = parse_initial_table(initial, f"{t.where}.initial")
    program = parse_program_tables(programs, base, f"{t.where}.program")
    try:
        n = count_points(SubloadingParams(mu_s=1.0, mu_k=1.0), program, init)
    except ParameterError:
        n = 2
    if n != 1:
        raise InputError(
            f"{t.where}: per-point lists in [data.initial] or [[data.program]] are not allowed "
            "(one curve is one contact point; give each curve its own [[data]])"
        )
    path = Path(name) if Path(name).is_absolute() else base / name
    where = f"{t.where}.file '{name}'"
    measured = read_tribometer(path, columns, units, where)
    end = program_duration(program)
    t_last = float(measured.time[-1])
    if t_last > end * (1.0 + END_TOLERANCE):
        raise InputError(
            f"{where}: the data run to t = {t_last:g} s, past the end of "
            f"{t.where}.program at {end:g} s (extend the programme or trim the data)"
        )
    time = np.minimum(measured.time, end)
    curve = Curve(
        name=Path(name).name, time=time, friction_ratio=measured.friction_ratio,
        program=program, initial=init, weight=weight, slip=measured.slip,
    )  # fmt: skip
    echo = {
        "file": name, "columns": columns, "units": measured.units, "weight": weight,
        "samples": curve.n_samples, "duration": end, "initial": initial, "program": programs,
    }  # fmt: skip
    return curve, echo


def parse_calibration(
    data: dict[str, Any], base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> CalibrationConfig:
    """Validate a parsed calibration mapping (reads the data files; nothing is fitted)."""
    root = Table(data, "")
    title = root.get("title", str, "")
    root.get("description", str, "")
    law = root.raw("law")
    fit = root.table("fit", required=True)
    data_tables = root.tables("data", required=True)
    root.finish()
    assert fit is not None
    if not data_tables:
        raise InputError("[[data]] must hold at least one measured curve")
    params, given = parse_law_table(law)
    names, bounds, max_eval, profile, points, most = _parse_fit(fit)
    try:
        make_space(params, names, bounds)
    except ParameterError as exc:
        field = exc.field if exc.field.startswith(("fit.", "law.")) else f"fit.{exc.field}"
        section, _, key = field.partition(".")
        raise ParameterError(f"[{section}].{key}", exc.value, exc.allowed) from None
    curves, echoes = [], []
    for t in data_tables:
        curve, echo = _parse_data(t, Path(base_dir))
        curves.append(curve)
        echoes.append(echo)
    n_samples = sum(c.n_samples for c in curves)
    if n_samples <= len(names):
        raise InputError(f"[[data]]: {n_samples} samples in all, fewer than needed to fit "
                         f"{len(names)} parameters")  # fmt: skip
    return CalibrationConfig(
        title=title, params=params, law_given=given, names=tuple(names), bounds=bounds,
        curves=tuple(curves), data_echo=tuple(echoes), max_evaluations=max_eval,
        profile=profile, profile_points=points, profile_max=most, source=source,
    )  # fmt: skip


def load_calibration(
    path: str | os.PathLike[str], overrides: tuple[str, ...] | list[str] = ()
) -> CalibrationConfig:
    """Read, override (``section.key=value``) and validate a calibration file."""
    p = Path(path)
    data = apply_overrides(load_toml(p), overrides)
    return parse_calibration(data, base_dir=p.parent, source=str(p))
