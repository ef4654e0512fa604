"""Scenario files: TOML -> law parameters, initial contact, loading programme (or machine).

The schema (public contract, docs/driver.md has every key with its default and unit)::

    title = "..."                 # optional
    description = "..."           # optional
    [law]                         # -> SubloadingParams (same names)
    [initial]                     # normal_traction (required), tangential_traction, F
    [run]                         # optional: n_points, accuracy, max_halvings, allow_large
    [output]                      # optional: every (record every k-th step), points (1-based)
    [[program]]                   # segments, in order; kind = slide | hold | reverse |
                                  # turn | cycle | normal | traction | table
    [machine]                     # instead of [[program]]: the stick-slip spring-slider

Numbers may be given per point as lists (``duration = [10.0, 100.0]``); vectors
(``rotation``, ``orthotropy``, ``tangential_traction``, a traction target) as ``[a, b]``
or as a list of pairs. :func:`parse_scenario` validates everything (keys, types,
physical ranges, the programme's inherited values, table files, the initial state)
before anything runs; every problem is one :class:`~frictionlab.errors.InputError` or
:class:`~frictionlab.errors.ParameterError` line naming the key.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.app.budget import RunEstimate, check_run_size, largest
from frictionlab.driver import (
    SEGMENT_KINDS,
    InitialConditions,
    Program,
    SpringSlider,
    Table,
    plan_program,
)
from frictionlab.driver.program import segment_fields
from frictionlab.driver.recorder import Recording, RowSink
from frictionlab.driver.simulate import count_points
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import REQUIRED, apply_overrides, load_toml, unknown_key
from frictionlab.io.config import Table as TomlTable
from frictionlab.io.tables import read_csv
from frictionlab.subloading import SURFACES, SubloadingParams
from frictionlab.subloading.params import (
    F_INTEGRATORS,
    OPEN_RECOVERY,
    ORTHOTROPY_CONVENTIONS,
    RECOVERY_FORMS,
    U_LAWS,
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

_PARAM_DEFAULTS = {f.name: f.default for f in fields(SubloadingParams) if f.init}

#: ``[law]`` keys: name -> (value kind, choices). Kinds: "num" (number or per-point
#: list), "vec2" (pair or list of pairs), "float", a tuple of choices for strings.
LAW_KEYS: dict[str, Any] = {
    "surface": SURFACES,
    "alpha_n": "num",
    "alpha_t": "num",
    "mu_s": "num",
    "mu_k": "num",
    "F_s": "num",
    "F_k": "num",
    "M": "num",
    "u": "num",
    "kappa": "num",
    "xi": "num",
    "m": "num",
    "n": "num",
    "rotation": "vec2",
    "orthotropy": "vec2",
    "orthotropy_angle": "num",  # rad, as in the Python API
    "orthotropy_angle_deg": "num",  # the same angle in degrees (give one of the two)
    "orthotropy_convention": ORTHOTROPY_CONVENTIONS,
    "tear_k": "float",
    "U_law": U_LAWS,
    "F_integrator": F_INTEGRATORS,
    "recovery_form": RECOVERY_FORMS,
    "open_recovery": OPEN_RECOVERY,
}

_CONE_KEYS = ("mu_s", "mu_k")
_CLOSED_KEYS = ("F_s", "F_k", "M")


# --------------------------------------------------------------------------- typed values
def _numbers(t: TomlTable, key: str, default: Any = REQUIRED) -> Any:
    """A number or a non-empty list of numbers (one per point); None if absent and optional."""
    value = t.raw(key, default)
    if key not in t:
        return value
    name = f"{t.where}.{key}"
    if isinstance(value, list):
        if not value:
            raise InputError(f"{name} must be a number or a non-empty list of numbers, got []")
        return [_number(v, f"{name}[{i}]") for i, v in enumerate(value)]
    return _number(value, name)


def _number(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise InputError(f"{name} must be a number, got {type(value).__name__} {value!r}")
    if not math.isfinite(value):
        raise InputError(f"{name} = {value} must be finite")
    return float(value)


def _pairs(t: TomlTable, key: str, default: Any = REQUIRED) -> Any:
    """A pair ``[a, b]`` or a list of pairs (one per point)."""
    value = t.raw(key, default)
    if key not in t:
        return value
    name = f"{t.where}.{key}"
    if isinstance(value, list) and len(value) == 2 and not any(isinstance(v, list) for v in value):
        return [_number(v, f"{name}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, list) and value and all(isinstance(v, list) for v in value):
        out = []
        for i, pair in enumerate(value):
            if len(pair) != 2:
                raise InputError(f"{name}[{i}] must have 2 entries, got {len(pair)}")
            out.append([_number(v, f"{name}[{i}][{j}]") for j, v in enumerate(pair)])
        return out
    raise InputError(f"{name} must be a pair [a, b] or a list of pairs, got {value!r}")


def _int(t: TomlTable, key: str, default: Any, minimum: int) -> Any:
    return t.get(
        key, int, default, check=lambda v: v >= minimum, allowed=f"an integer >= {minimum}"
    )


def _positive(t: TomlTable, key: str, default: Any = None) -> Any:
    return t.get(key, float, default, check=lambda v: v > 0, allowed="a number > 0")


def _reject_unknown(t: TomlTable, allowed: Sequence[str]) -> None:
    """Report a misspelt key before any missing-key error it would cause."""
    for key in t.mapping():
        if key not in allowed:
            raise InputError(unknown_key(f"{t.where}.{key}", key, allowed))


def _reraise(where: str, call: Callable[[], Any]) -> Any:
    """Run ``call``; re-raise a ParameterError with ``where`` in front of its field."""
    try:
        return call()
    except ParameterError as exc:
        raise ParameterError(f"{where}.{exc.field}", exc.value, exc.allowed) from None


# --------------------------------------------------------------------------- sections
def _parse_law(t: TomlTable) -> tuple[SubloadingParams, dict[str, Any]]:
    _reject_unknown(t, tuple(LAW_KEYS))
    surface = t.get("surface", str, _PARAM_DEFAULTS["surface"], choices=SURFACES)
    needed = _CONE_KEYS if surface == "coulomb" else _CLOSED_KEYS
    for key in needed:
        if key not in t:
            raise InputError(
                f"missing required key {t.where}.{key} (surface '{surface}' needs "
                f"{', '.join(needed)})"
            )
    values: dict[str, Any] = {"surface": surface}
    given: dict[str, Any] = {}
    for key, kind in LAW_KEYS.items():
        if key == "surface" or key not in t:
            continue
        if kind == "num":
            values[key] = _numbers(t, key)
        elif kind == "vec2":
            values[key] = _pairs(t, key)
        elif kind == "float":
            values[key] = t.get(key, float)
        else:
            values[key] = t.get(key, str, choices=kind)
        given[key] = values[key]
    t.finish()
    if "orthotropy_angle_deg" in values:
        if "orthotropy_angle" in values:
            raise InputError(
                f"{t.where}: give orthotropy_angle (rad) or orthotropy_angle_deg (deg), not both"
            )
        deg = values.pop("orthotropy_angle_deg")
        values["orthotropy_angle"] = np.radians(deg).tolist()
    params = _reraise(t.where, lambda: SubloadingParams(**values))
    return params, given


def parse_law_table(
    data: dict[str, Any], where: str = "[law]"
) -> tuple[SubloadingParams, dict[str, Any]]:
    """Validate a ``[law]`` mapping -> (params, the keys given with their values).

    The public form of the scenario's ``[law]`` parser, for commands that read a law
    from a table of their own (bridge, calibration). Errors name ``where.key``.
    """
    return _parse_law(TomlTable(data, where))


def law_table(params: SubloadingParams) -> dict[str, Any]:
    """The ``[law]`` table that :func:`parse_scenario` reads back as ``params``.

    Every parameter is written explicitly (defaults included), per-point values as
    lists; the orthotropy angle in degrees (``orthotropy_angle_deg``) and the orthotropy
    in the stored "divide" convention. Used by commands that write a runnable scenario
    (fitted laws). Round trip: ``_parse_law(law_table(p))`` equals ``p`` to round-off of
    the degree conversion.
    """
    table: dict[str, Any] = {}
    for key in LAW_KEYS:
        if key in ("orthotropy_angle", "orthotropy_angle_deg"):
            angle = np.degrees(np.asarray(params.orthotropy_angle, dtype=float))
            table["orthotropy_angle_deg"] = angle.tolist()
            continue
        value = getattr(params, key)
        if value is None:
            continue
        table[key] = np.asarray(value).tolist() if isinstance(value, np.ndarray) else value
    table["orthotropy_convention"] = "divide"
    return table


def _parse_initial(t: TomlTable) -> tuple[InitialConditions, dict[str, Any]]:
    _reject_unknown(t, ("normal_traction", "tangential_traction", "F"))
    fn = _numbers(t, "normal_traction")
    ft = _pairs(t, "tangential_traction", [0.0, 0.0])
    F = _numbers(t, "F", None)
    t.finish()
    init = InitialConditions(normal_traction=fn, tangential_traction=ft, F=F)
    return init, {"normal_traction": fn, "tangential_traction": ft, "F": F}


def parse_initial_table(
    data: dict[str, Any], where: str = "[initial]"
) -> tuple[InitialConditions, dict[str, Any]]:
    """Validate an ``[initial]`` mapping -> (initial conditions, the values as given).

    The public form of the scenario's ``[initial]`` parser (used by the calibration's
    ``[data.initial]``). Errors name ``where.key``.
    """
    return _parse_initial(TomlTable(data, where))


def parse_program_tables(
    tables: Sequence[dict[str, Any]],
    base_dir: str | os.PathLike[str] = ".",
    where: str = "[[program]]",
) -> Program:
    """Validate ``[[program]]`` mappings (segments, in order) -> a :data:`Program`.

    The public form of the scenario's segment parser (used by the calibration's
    ``[[data.program]]``). Errors name ``where #i.key``; table files are read relative to
    ``base_dir``.
    """
    if not tables:
        raise InputError(f"{where} must hold at least one segment")
    return tuple(
        _parse_segment(TomlTable(t, f"{where} #{i + 1}"), Path(base_dir))
        for i, t in enumerate(tables)
    )


@dataclass(frozen=True)
class RunOptions:
    """``[run]``: number of points, accuracy control, deepest substepping."""

    n_points: int | None = None
    accuracy: float | None = None
    max_halvings: int = 10
    allow_large: bool = False


def _parse_run(t: TomlTable | None) -> RunOptions:
    if t is None:
        return RunOptions()
    opts = RunOptions(
        n_points=_int(t, "n_points", None, 1),
        accuracy=_positive(t, "accuracy"),
        max_halvings=_int(t, "max_halvings", 10, 0),
        allow_large=t.get("allow_large", bool, False),
    )
    t.finish()
    return opts


@dataclass(frozen=True)
class OutputOptions:
    """``[output]``: record every k-th step (``every``) and only some ``points`` (1-based)."""

    every: int = 1
    points: tuple[int, ...] | None = None

    def recording(
        self,
        sink: RowSink | None = None,
        keep_rows: int | None = None,
        keep_points: Sequence[int] | None = None,
    ) -> Recording:
        """The driver's :class:`~frictionlab.driver.recorder.Recording` (0-based points)."""
        pts = None if self.points is None else tuple(p - 1 for p in self.points)
        return Recording(
            every=self.every, points=pts, sink=sink, keep_rows=keep_rows, keep_points=keep_points
        )

    def recorded_points(self, n: int) -> int:
        """How many points are recorded out of ``n``."""
        return n if self.points is None else len(self.points)


def _parse_output(t: TomlTable | None) -> OutputOptions:
    if t is None:
        return OutputOptions()
    every = _int(t, "every", 1, 1)
    points = t.get_list("points", int, None)
    t.finish()
    if points is not None:
        if not points:
            raise InputError("[output].points = [] is invalid: allowed at least one point number")
        seen: set[int] = set()
        for v in points:
            if v < 1:
                raise InputError(
                    f"[output].points has {v}: allowed point numbers >= 1 (the first point is 1)"
                )
            if v in seen:
                raise InputError(f"[output].points has {v} twice: allowed each point once")
            seen.add(v)
        points = sorted(points)
    return OutputOptions(every, None if points is None else tuple(points))


def _check_output_points(out: OutputOptions, n: int) -> None:
    if out.points is not None and out.points[-1] > n:
        raise InputError(
            f"[output].points has {out.points[-1]}: allowed point numbers 1..{n} "
            f"(the scenario has {n} point(s))"
        )


# --------------------------------------------------------------------------- segments
_SEGMENT_KEYS: dict[str, dict[str, str]] = {
    "slide": {"velocity": "num", "distance": "num", "duration": "num", "direction_deg": "num"},
    "hold": {"duration": "num"},
    "reverse": {"velocity": "num", "distance": "num", "duration": "num"},
    "turn": {"angle_deg": "num", "velocity": "num", "distance": "num", "duration": "num"},
    "cycle": {"amplitude": "num", "velocity": "num", "cycles": "int", "direction_deg": "num"},
    "normal": {"approach": "num", "traction": "num", "traction_change": "num", "duration": "num"},
    "traction": {"traction": "vec2", "duration": "num", "cycles": "int"},
}
_REQUIRED_KEYS = {
    "slide": ("velocity",),
    "hold": ("duration",),
    "turn": ("angle_deg",),
    "cycle": ("amplitude", "velocity"),
}


def _parse_segment(t: TomlTable, base_dir: Path) -> Any:
    kind = t.get("kind", str, choices=tuple(SEGMENT_KINDS))
    if kind == "table":
        _reject_unknown(t, ("kind", "file", "steps_per_row", "max_step"))
        return _parse_table_segment(t, base_dir)
    extra = ("magnitude", "direction_deg") if kind == "traction" else ()
    _reject_unknown(t, ("kind", "steps", "max_step", *_SEGMENT_KEYS[kind], *extra))
    kwargs: dict[str, Any] = {}
    for key in _REQUIRED_KEYS.get(kind, ()):
        if key not in t:
            raise InputError(f"missing required key {t.where}.{key} (needed by kind = '{kind}')")
    if kind == "traction":
        if ("traction" in t) == ("magnitude" in t):
            raise InputError(
                f"{t.where} (kind = 'traction') needs exactly one of traction = [f_t1, f_t2] "
                "or magnitude (with direction_deg)"
            )
        if "magnitude" in t:
            magnitude = np.asarray(_numbers(t, "magnitude"))
            angle = np.radians(np.asarray(_numbers(t, "direction_deg", 0.0)))
            vec = np.stack(
                np.broadcast_arrays(magnitude * np.cos(angle), magnitude * np.sin(angle)), axis=-1
            )
            kwargs["traction"] = vec.tolist()
    for key, kind_of in _SEGMENT_KEYS[kind].items():
        if key not in t:
            continue
        if kind_of == "num":
            kwargs[key] = _numbers(t, key)
        elif kind_of == "vec2":
            kwargs[key] = _pairs(t, key)
        else:
            kwargs[key] = _int(t, key, None, 1)
    kwargs["steps"] = _int(t, "steps", None, 1)
    kwargs["max_step"] = _positive(t, "max_step")
    t.finish()
    cls = SEGMENT_KINDS[kind]
    return _reraise(t.where, lambda: cls(**kwargs))


#: SI units of the columns of a ``kind = "table"`` file (titles may carry them: ``time [s]``).
TABLE_UNITS = {"time": "s", "slip_1": "m", "slip_2": "m", "normal_traction": "Pa", "approach": "m"}


def _parse_table_segment(t: TomlTable, base_dir: Path) -> Table:
    name = t.get("file", str)
    path = Path(name) if Path(name).is_absolute() else base_dir / name
    steps_per_row = _int(t, "steps_per_row", None, 1)
    max_step = _positive(t, "max_step")
    t.finish()
    cols = read_csv(path)
    where = f"{t.where}.file '{name}'"
    for required in ("time", "slip_1"):
        if required not in cols:
            raise InputError(f"{where}: missing column '{required}' (columns: time, slip_1, "
                             "slip_2, and optionally normal_traction or approach)")  # fmt: skip
    allowed = {"time", "slip_1", "slip_2", "normal_traction", "approach"}
    extra = sorted(set(cols) - allowed)
    if extra:
        raise InputError(
            f"{where}: unknown column '{extra[0]}'; allowed: {', '.join(sorted(allowed))}"
        )
    for key in cols:
        unit = cols.units.get(key)
        if unit is not None and unit != TABLE_UNITS[key]:
            raise InputError(
                f"{where}: column '{key}' is in [{unit}]; allowed: [{TABLE_UNITS[key]}] (SI)"
            )
    for key, arr in cols.items():
        if arr.dtype != np.float64:
            bad = next(v for v in arr if not _is_float(v))
            raise InputError(f"{where}: column '{key}' must hold numbers, found {bad!r}")
    slip = np.column_stack([cols["slip_1"], cols.get("slip_2", np.zeros_like(cols["slip_1"]))])
    return _reraise(
        where,
        lambda: Table(
            time=cols["time"], slip=slip, normal_traction=cols.get("normal_traction"),
            approach=cols.get("approach"), steps_per_row=steps_per_row, max_step=max_step,
            source=str(name),
        ),
    )  # fmt: skip


def _is_float(v: str) -> bool:
    try:
        float(v)
    except ValueError:
        return False
    return True


# --------------------------------------------------------------------------- machine
@dataclass(frozen=True)
class MachineRun:
    """``[machine]``: the spring-slider and how long to pull it."""

    machine: SpringSlider
    duration: Any
    steps: int | None = None
    max_step: float | None = None


def _parse_machine(t: TomlTable) -> tuple[MachineRun, dict[str, Any]]:
    kw = {
        "stiffness": _numbers(t, "stiffness"),
        "velocity": _numbers(t, "velocity"),
        "mass": _numbers(t, "mass", 0.0),
        "damping": _numbers(t, "damping", 0.0),
        "direction_deg": _numbers(t, "direction_deg", 0.0),
        "spectral_radius": t.get("spectral_radius", float, 0.5),
    }
    duration = _numbers(t, "duration")
    steps = _int(t, "steps", None, 1)
    max_step = _positive(t, "max_step")
    t.finish()
    if steps is not None and max_step is not None:
        raise InputError(f"{t.where}: give steps or max_step, not both")
    machine = _reraise(t.where, lambda: SpringSlider(**kw))
    dur = np.asarray(duration, dtype=np.float64)
    if np.any(dur <= 0):
        raise InputError(f"{t.where}.duration = {duration} is invalid: allowed a duration > 0 [s]")
    echo = {**kw, "duration": duration, "steps": steps if max_step is None else None,
            "max_step": max_step}  # fmt: skip
    if steps is None and max_step is None:
        echo["steps"] = 1000
    return MachineRun(machine, duration, steps, max_step), echo


# --------------------------------------------------------------------------- scenario
@dataclass(frozen=True)
class Scenario:
    """A validated scenario, ready to run (:func:`frictionlab.app.simulate.run_scenario`)."""

    title: str
    description: str
    params: SubloadingParams
    initial: InitialConditions
    run_options: RunOptions
    n_points: int
    program: Program | None = None
    machine: MachineRun | None = None
    inputs: dict[str, Any] = field(default_factory=dict)
    labels: tuple[str, ...] = ()
    source: str = ""
    output: OutputOptions = field(default_factory=OutputOptions)
    #: The work estimate made while parsing (``None`` for a scenario built in Python).
    estimate: RunEstimate | None = None

    @property
    def kind(self) -> str:
        """``"program"`` or ``"spring_slider"``."""
        return "program" if self.program is not None else "spring_slider"


#: How per-point inputs are named in legends: key -> (symbol, unit).
_LABEL_NAMES: dict[str, tuple[str, str]] = {
    "velocity": ("V", "m/s"),
    "distance": ("distance", "m"),
    "duration": ("t", "s"),
    "direction_deg": ("direction", "deg"),
    "angle_deg": ("turn", "deg"),
    "amplitude": ("amplitude", "m"),
    "approach": ("approach", "m"),
    "traction": ("f_t", "Pa"),
    "traction_change": ("change", "Pa"),
    "normal_traction": ("f_n", "Pa"),
    "tangential_traction": ("f_t", "Pa"),
    "stiffness": ("k", "Pa/m"),
    "mass": ("m", "kg/m^2"),
    "damping": ("c", "Pa s/m"),
    "alpha_n": ("alpha_n", "Pa/m"),
    "alpha_t": ("alpha_t", "Pa/m"),
    "u": ("u", "1/m"),
    "F_s": ("F_s", "Pa"),
    "F_k": ("F_k", "Pa"),
}


def _labels(n: int, varying: list[tuple[str, str, list[Any]]]) -> tuple[str, ...]:
    """Legend labels from the inputs given per point (``V = 0.1 m/s`` style)."""
    if n == 1:
        return ("",)
    if not varying:
        return tuple(f"point {i + 1}" for i in range(n))
    out = []
    for i in range(n):
        parts = []
        for prefix, key, values in varying[:2]:
            symbol, unit = _LABEL_NAMES.get(key, (key, ""))
            v = values[i]
            text = f"({v[0]:g}, {v[1]:g})" if isinstance(v, list) else f"{v:g}"
            parts.append(f"{prefix}{symbol} = {text}{' ' + unit if unit else ''}")
        out.append(", ".join(parts))
    return tuple(out)


def _per_point(prefix: str, values: dict[str, Any]) -> list[tuple[str, str, list[Any]]]:
    """The inputs given per point: lists of numbers, or lists of pairs for vector keys."""
    found = []
    for key, v in values.items():
        if not isinstance(v, list) or not v:
            continue
        nested = isinstance(v[0], list)
        if nested or key not in _PAIR_KEYS:
            found.append((prefix, key, v))
    return found


_PAIR_KEYS = ("rotation", "orthotropy", "tangential_traction", "traction")


def _segment_echo(seg: Any) -> dict[str, Any]:
    if isinstance(seg, Table):
        return {
            "kind": "table",
            "source": seg.source,
            "rows": int(seg.time.size),
            "columns": ["time", "slip_1", "slip_2"]
            + [c for c in ("normal_traction", "approach") if getattr(seg, c) is not None],
            "steps_per_row": seg.steps_per_row,
            "max_step": seg.max_step,
        }
    return {"kind": seg.kind, **_jsonable(segment_fields(seg))}


def parse_scenario(
    data: dict[str, Any], base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> Scenario:
    """Validate a parsed scenario mapping and build a :class:`Scenario` (nothing runs)."""
    root = TomlTable(data, "")
    title = root.get("title", str, "")
    description = root.get("description", str, "")
    law = root.table("law", required=True)
    initial = root.table("initial", required=True)
    run = root.table("run")
    output_table = root.table("output")
    has_program = "program" in root
    machine_table = root.table("machine")
    program_tables = root.tables("program") if has_program else []
    root.finish()
    assert law is not None and initial is not None
    if has_program == (machine_table is not None):
        raise InputError(
            "a scenario needs exactly one of [[program]] (segments) or [machine] (spring-slider)"
        )
    if has_program and not program_tables:
        raise InputError("[[program]] must hold at least one segment")
    params, law_given = _parse_law(law)
    init, init_echo = _parse_initial(initial)
    opts = _parse_run(run)
    output = _parse_output(output_table)
    varying = _per_point("", law_given) + _per_point("", init_echo)
    program: Program | None = None
    machine: MachineRun | None = None
    program_echo: list[dict[str, Any]] = []
    machine_echo: dict[str, Any] = {}
    base = Path(base_dir)
    if has_program:
        segments = []
        for t in program_tables:
            raw = t.mapping()
            seg = _parse_segment(t, base)
            segments.append(seg)
            raw.pop("kind", None)
            varying += _per_point("hold " if seg.kind == "hold" else "", raw)
        program = tuple(segments)
        program_echo = [_segment_echo(s) for s in program]
    else:
        assert machine_table is not None
        machine, machine_echo = _parse_machine(machine_table)
        varying += _per_point("", machine_echo)
    sizes = machine.machine.sizes() if machine is not None else set()
    if machine is not None and np.ndim(machine.duration) == 1:
        sizes = sizes | {len(machine.duration)}
    n = _reraise(
        "scenario", lambda: count_points(params, program or (), init, opts.n_points, sizes)
    )
    _check_output_points(output, n)
    # points alone (one step) before anything of size N is built, then with the steps
    streamed = program is not None  # frictionlab simulate streams a programme's rows
    recorded = output.recorded_points(n)
    check_run_size(
        RunEstimate(2, n, "[run].n_points", output.every, recorded, streamed), opts.allow_large
    )
    try:
        init.state(params, n)
    except ParameterError as exc:  # the snap-back check names a [law] field
        section = "[law]" if exc.field in LAW_KEYS else "[initial]"
        raise ParameterError(f"{section}.{exc.field}", exc.value, exc.allowed) from None
    if program is not None:
        plans = _reraise("[[program]]", lambda: plan_program(program, n))
        counts = [
            (p.estimated_steps, f"[[program]] #{i}.{_steps_key(seg)}")
            for i, (p, seg) in enumerate(zip(plans, program, strict=True), start=1)
        ]
    else:
        assert machine is not None
        counts = [(_machine_steps(machine), f"[machine].{_steps_key(machine)}")]
    estimate = largest(counts, n, "[run].n_points", output.every, recorded, streamed)
    check_run_size(estimate, opts.allow_large)
    inputs: dict[str, Any] = {
        "title": title,
        "description": description,
        "law": _jsonable(params.as_dict()),
        "initial": _jsonable(
            {**init_echo, "F": init_echo["F"] if init_echo["F"] is not None else "static value"}
        ),
        "run": {"n_points": n, "accuracy": opts.accuracy, "max_halvings": opts.max_halvings},
        "output": {
            "every": output.every,
            "points": "all" if output.points is None else list(output.points),
        },
    }
    if program is not None:
        inputs["program"] = program_echo
    else:
        inputs["machine"] = _jsonable(machine_echo)
    return Scenario(
        title=title, description=description, params=params, initial=init, run_options=opts,
        n_points=n, program=program, machine=machine, inputs=inputs,
        labels=_labels(n, varying), source=source, output=output, estimate=estimate,
    )  # fmt: skip


def _steps_key(seg: Any) -> str:
    """The key that sets a segment's step count: max_step when given, else steps."""
    return "max_step" if getattr(seg, "max_step", None) is not None else "steps"


def _machine_steps(m: MachineRun) -> int:
    if m.max_step is not None:
        longest = float(np.max(np.asarray(m.duration, dtype=np.float64)))
        return max(1, math.ceil(longest / m.max_step))
    return m.steps or 1000


def load_scenario(path: str | os.PathLike[str], overrides: Sequence[str] = ()) -> Scenario:
    """Read, override (``section.key=value``) and validate a scenario file."""
    p = Path(path)
    data = apply_overrides(load_toml(p), overrides)
    return parse_scenario(data, base_dir=p.parent, source=str(p))


def _jsonable(obj: Any) -> Any:
    """Plain JSON values (lists for arrays, None kept)."""
    if isinstance(obj, dict):
        return {k: _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    return obj
