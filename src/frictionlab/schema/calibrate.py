"""The ``frictionlab calibrate`` file: declarations and the parser.

``[law]`` (the starting values, as in a simulate scenario), ``[fit]`` (what to fit) and
one or more ``[[data]]`` curves, each with its ``[data.initial]`` and
``[[data.program]]``. Everything is validated (data files read) before any fit starts.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.calibration.fit import make_space
from frictionlab.calibration.model import FITTABLE, Curve, program_duration
from frictionlab.driver.simulate import count_points
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import Table
from frictionlab.io.tribometer import ROLES, read_tribometer
from frictionlab.schema.core import REQUIRED, Field, Section, loader, reraise, run_file
from frictionlab.schema.kinds import BOOL, INTEGER, NUMBER, STRING, Kind, listed
from frictionlab.schema.scenario import (
    INITIAL,
    LAW,
    SEGMENT,
    parse_initial_table,
    parse_law_table,
    parse_program_tables,
)
from frictionlab.subloading import SubloadingParams

__all__ = [
    "CALIBRATE_FILE",
    "END_TOLERANCE",
    "CalibrationConfig",
    "load_calibrate",
    "parse_calibrate",
]

#: Data may run past the programme's end by this fraction of its duration (round-off of
#: the lab's clock), and are then clipped to the end.
END_TOLERANCE = 1e-6

_PAIR = listed(float, "number", 2)
#: The most grid values of one likelihood profile (each is a fit of the other parameters).
MAX_PROFILE_POINTS = 1001
FIT = Section("fit", (
    Field("parameters", listed(str, "string"), "the [law] keys to fit (the rest stay fixed)",
          default=REQUIRED, choices=tuple(FITTABLE)),
    Field("bounds", table=Section("bounds", ()), doc="name = [low, high] (physical units)",
          json={"type": "object", "additionalProperties": _PAIR.json}),
    Field("max_evaluations", INTEGER, "least-squares function evaluations", "", 100, low=1),
    Field("profile", BOOL, "profile likelihood of poorly identified parameters", "", True),
    Field("profile_points", INTEGER, "grid values per profile", "", 9, low=3,
          high=MAX_PROFILE_POINTS),
    Field("profile_max", INTEGER, "profile at most this many (worst first)", "", 2, low=0),
    Field("starts", INTEGER, "starting points (the [law] one, then scrambled Halton)", "", 1,
          low=1, high=1000),
    Field("seed", INTEGER, "seed of the quasi-random starts", "", 0, low=0),
    Field("band_level", NUMBER, "level of the confidence and prediction bands", "", 0.95,
          low=0, high=1, open="both"),
), "what to fit", "[fit]")  # fmt: skip
COLUMNS = Section(
    "columns",
    tuple(Field(k, STRING, f"title of the {k} column (default: found by name)") for k in ROLES),
    "column titles of the data file",
)
UNITS = Section(
    "units",
    tuple(Field(k, STRING, f"unit of the {k} column (any unit pint reads; default: the "
                "title's or the units row's, else SI)") for k in ROLES),
    "units of the data file's columns",
)  # fmt: skip


def _read_offset(t: Table, f: Field) -> float | str:
    raw = t.raw(f.name)
    if isinstance(raw, str):
        if raw != "fit":
            raise InputError(
                f"{t.where}.{f.name} = {raw!r} is invalid: allowed a number (s) or 'fit'"
            )
        return "fit"
    return float(t.get(f.name, float))


_OFFSET = Kind("number or 'fit'", _read_offset,
               {"oneOf": [{"type": "number"}, {"type": "string", "enum": ["fit"]}]})  # fmt: skip
DATA = Section("data", (
    Field("file", STRING, "the measured curve (CSV, relative to this file)", "", REQUIRED),
    Field("columns", table=COLUMNS),
    Field("units", table=UNITS),
    Field("weight", NUMBER, "weight of this curve in the fit", "", 1.0, low=0, open="low"),
    Field("sep", STRING, "delimiter (default: sniffed among tab ; , |)", "", None),
    Field("decimal", STRING, "decimal mark (default: sniffed)", "", None, choices=(".", ",")),
    Field("encoding", STRING, "text encoding (default: by BOM, else UTF-16 by its NUL "
          "bytes, else UTF-8, else cp1252)", "",
          None),
    Field("reciprocating", BOOL, "the friction ratio changes sign with each stroke", "", False),
    Field("segment_weights", listed(float, "number"), "weight of each [[data.program]] "
          "segment's samples", "", None),
    Field("time_offset", _OFFSET, "when the data's t = 0 falls in the programme, or 'fit' "
          "to estimate it within time_offset_bounds", "s", 0.0),
    Field("time_offset_bounds", listed(float, "number", 2), "[low, high] of a fitted "
          "time_offset", "s", None),
    Field("initial", table=INITIAL, default=REQUIRED),
    Field("program", table=SEGMENT, many=True, default=REQUIRED),
), "one measured curve", "[[data]]")  # fmt: skip
CALIBRATE_FILE = run_file("calibrate", (
    Field("law", table=LAW, default=REQUIRED),
    Field("fit", table=FIT, default=REQUIRED),
    Field("data", table=DATA, many=True, default=REQUIRED),
), "A calibration file of `frictionlab calibrate`: the starting [law], what to [fit] and "
   "the measured [[data]] curves.")  # fmt: skip


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
    starts: int = 1
    seed: int = 0
    band_level: float = 0.95


def _parse_fit(t: Table) -> tuple[dict[str, Any], dict[str, tuple[float, float]]]:
    values = FIT.read(t)
    bounds: dict[str, tuple[float, float]] = {}
    bt = t.table("bounds")
    for key in [] if bt is None else bt.keys():
        pair = bt.get_list(key, float, length=2)  # type: ignore[union-attr]
        if not pair[0] < pair[1]:
            raise InputError(f"[fit].bounds.{key} = {pair} must be [low, high] with low < high")
        bounds[key] = (pair[0], pair[1])
    if values["profile_max"] == 0:
        values["profile"] = False
    return values, bounds


def _parse_data(t: Table, base: Path) -> tuple[Curve, dict[str, Any]]:
    values = DATA.read(t)
    name = values["file"]
    columns = COLUMNS.read(t.raw("columns", {}), f"{t.where}.columns", only_given=True)
    units = UNITS.read(t.raw("units", {}), f"{t.where}.units", only_given=True)
    initial, programs = t.raw("initial"), t.raw("program")
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
    where = f"{t.where}.file '{name}'"
    measured = read_tribometer(
        base / name, columns, units, where, sep=values["sep"], decimal=values["decimal"],
        encoding=values["encoding"], reciprocating=values["reciprocating"],
    )  # fmt: skip
    end = program_duration(program)
    offset, bounds = values["time_offset"], values["time_offset_bounds"]
    fitted = offset == "fit"
    if fitted != (bounds is not None):
        raise InputError(
            f"{t.where}.time_offset_bounds = {bounds} is invalid: allowed [low, high] (s) "
            "exactly when time_offset = 'fit'"
        )
    if fitted:
        lo, hi = bounds
        t0, t1 = float(measured.time[0]), float(measured.time[-1])
        if not (
            lo < hi and t0 + lo >= -END_TOLERANCE * end and t1 + hi <= end * (1.0 + END_TOLERANCE)
        ):
            raise InputError(
                f"{t.where}.time_offset_bounds = {bounds} is invalid: allowed low < high "
                f"with every offset keeping the data (t = {t0:g} to {t1:g} s) inside "
                f"{t.where}.program (0 to {end:g} s): low >= {0.0 - t0 + 0.0:g}, "
                f"high <= {end - t1:g}"
            )
        offset = 0.5 * (lo + hi)  # unused: the fit estimates it
    t_last = float(measured.time[-1]) + offset
    if not fitted and t_last > end * (1.0 + END_TOLERANCE):
        raise InputError(
            f"{where}: the data run to t = {t_last:g} s, past the end of "
            f"{t.where}.program at {end:g} s (extend the programme or trim the data)"
        )
    weights = values["segment_weights"]
    curve = reraise(t.where, lambda: Curve(
        name=Path(name).name,
        time=measured.time if fitted else np.minimum(measured.time, end - offset),
        friction_ratio=measured.friction_ratio, program=program, initial=init,
        weight=values["weight"], slip=measured.slip, time_offset=offset,
        segment_weights=None if weights is None else tuple(weights),
        offset_bounds=None if bounds is None else (bounds[0], bounds[1]),
    ))  # fmt: skip
    echo = {
        "file": name, "columns": measured.columns, "units": measured.units,
        "weight": values["weight"], "segment_weights": weights,
        "time_offset": "fit" if fitted else offset, "time_offset_bounds": bounds,
        "samples": curve.n_samples, "duration": end, "initial": initial, "program": programs,
    }  # fmt: skip
    return curve, echo


def parse_calibrate(
    data: dict[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> CalibrationConfig:
    """Validate a parsed calibration mapping (reads the data files; nothing is fitted)."""
    top, tables = CALIBRATE_FILE.read_top(data)
    params, given = parse_law_table(tables["law"])
    fit_values, bounds = _parse_fit(tables["fit"])
    names = fit_values["parameters"]
    try:
        make_space(params, names, bounds)
    except ParameterError as exc:
        field = exc.field if exc.field.startswith(("fit.", "law.")) else f"fit.{exc.field}"
        section, _, key = field.partition(".")
        raise ParameterError(f"[{section}].{key}", exc.value, exc.allowed) from None
    curves, echoes = zip(*(_parse_data(t, Path(base_dir)) for t in tables["data"]), strict=True)
    n_samples = sum(c.n_samples for c in curves)
    if n_samples <= len(names):
        raise InputError(f"[[data]]: {n_samples} samples in all, fewer than needed to fit "
                         f"{len(names)} parameters")  # fmt: skip
    return CalibrationConfig(
        title=top["title"], params=params, law_given=given, names=tuple(names), bounds=bounds,
        curves=curves, data_echo=echoes, source=source,
        **{k: v for k, v in fit_values.items() if k != "parameters"},
    )  # fmt: skip


load_calibrate = loader(CALIBRATE_FILE, parse_calibrate, "a calibration file")
