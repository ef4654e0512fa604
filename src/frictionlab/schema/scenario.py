"""The ``frictionlab simulate`` scenario: declarations and the parser.

``[law]`` (-> SubloadingParams), ``[initial]``, optional ``[run]`` and ``[output]``, then
``[[program]]`` segments or a ``[machine]`` (the stick-slip spring-slider). Numbers may be
lists, one value per contact point; vectors as ``[a, b]`` or a list of pairs.
:func:`parse_scenario` validates everything before anything runs; every problem is one
line naming the key.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.app.budget import (
    HISTORY_BYTES_PER_ROW,
    RunEstimate,
    check_points,
    machine_steps,
    scenario_estimate,
    steps_key,
)
from frictionlab.driver import (
    SEGMENT_KINDS,
    InitialConditions,
    Program,
    SpringSlider,
    Table,
    Traction,
    plan_program,
)
from frictionlab.driver.program import segment_fields
from frictionlab.driver.recorder import Recording, RowSink
from frictionlab.driver.simulate import MAX_HALVINGS, count_points
from frictionlab.errors import InputError
from frictionlab.io.config import Table as TomlTable
from frictionlab.io.tables import read_csv
from frictionlab.plotting.legends import point_labels
from frictionlab.schema.core import REQUIRED, Field, Section, loader, reraise, run_file
from frictionlab.schema.kinds import BOOL, INTEGER, NUMBER, NUMBERS, PAIRS, STRING, listed
from frictionlab.subloading import SURFACES, SubloadingParams
from frictionlab.subloading.params import (
    F_INTEGRATORS,
    OPEN_RECOVERY,
    ORTHOTROPY_CONVENTIONS,
    RECOVERY_FORMS,
    U_LAWS,
)

__all__ = [
    "INITIAL", "LAW", "LAW_KEYS", "MACHINE", "OUTPUT", "RUN", "SCENARIO_FILE", "SEGMENT",
    "MachineRun", "OutputOptions", "RunOptions", "Scenario", "law_table", "load_scenario",
    "parse_initial_table", "parse_law_table", "parse_program_tables", "parse_scenario",
]  # fmt: skip

P = SubloadingParams


def _law(name: str, doc: str, unit: str = "", kind: Any = NUMBERS, **kw: Any) -> Field:
    return Field(name, kind, doc, unit, by=P, per_point=kind in (NUMBERS, PAIRS), **kw)


LAW = Section("law", (
    _law("surface", "sliding-yield surface", kind=STRING, choices=SURFACES),
    _law("alpha_n", "normal contact stiffness", "Pa/m"),
    _law("alpha_t", "tangential contact stiffness", "Pa/m"),
    _law("mu_s", "static friction coefficient (surface coulomb)", "-"),
    _law("mu_k", "kinetic friction coefficient (surface coulomb)", "-"),
    _law("F_s", "static size of a closed surface", "Pa"),
    _law("F_k", "kinetic size of a closed surface", "Pa"),
    _law("M", "slope of a closed surface's critical state line", "-"),
    _law("u", "evolution of the normal sliding-yield ratio R", "1/m"),
    _law("kappa", "softening with plastic slip", "1/m"),
    _law("xi", "recovery (healing) rate", "1/s"),
    _law("m", "exponent of the recovery", "-"),
    _law("n", "exponent of the softening", "-"),
    _law("rotation", "rotation of the friction cone (pair)", "-", PAIRS),
    _law("orthotropy", "orthotropy factors (pair)", "-", PAIRS),
    _law("orthotropy_angle", "angle of the orthotropy axes", "rad"),
    _law("orthotropy_angle_deg", "the same angle in degrees (give one of the two)", "deg"),
    _law("orthotropy_convention", "how orthotropy factors act", kind=STRING,
         choices=ORTHOTROPY_CONVENTIONS),
    _law("tear_k", "shape of the tear surface", "-", NUMBER),
    _law("U_law", "form of the softening function U", kind=STRING, choices=U_LAWS),
    _law("F_integrator", "integration of the size F", kind=STRING, choices=F_INTEGRATORS),
    _law("recovery_form", "form of the recovery term", kind=STRING, choices=RECOVERY_FORMS),
    _law("open_recovery", "recovery while the contact is open", kind=STRING,
         choices=OPEN_RECOVERY),
), "the subloading-friction law (SubloadingParams)", "[law]",
   exclusive=(("orthotropy_angle", "orthotropy_angle_deg"),))  # fmt: skip
#: ``[law]`` keys (declaration order).
LAW_KEYS = LAW.keys()
_NEEDED = {"coulomb": ("mu_s", "mu_k")}
_CLOSED_KEYS = ("F_s", "F_k", "M")

INITIAL = Section("initial", (
    Field("normal_traction", NUMBERS, "initial normal traction, compression positive", "Pa",
          REQUIRED, by=InitialConditions, per_point=True),
    Field("tangential_traction", PAIRS, "initial tangential traction (pair)", "Pa",
          [0.0, 0.0], by=InitialConditions, per_point=True),
    Field("F", NUMBERS, "initial size of the surface (default: the static value)", "",
          None, by=InitialConditions, per_point=True),
), "the contact before the programme starts", "[initial]", by=InitialConditions)  # fmt: skip


@dataclass(frozen=True)
class RunOptions:
    """``[run]``: number of points, accuracy control, deepest substepping."""

    n_points: int | None = None
    accuracy: float | None = None
    max_halvings: int = 10
    peak_accuracy: float = 1e-4
    allow_large: bool = False


RUN = Section("run", (
    Field("n_points", INTEGER, "number of contact points (default: from the lists)", "", None,
          low=1),
    Field("accuracy", NUMBER, "error per step that the adaptive substepping keeps", "", None,
          low=0, open="low"),
    Field("max_halvings", INTEGER, "deepest substepping (halvings of a step)", "", 10, low=0,
          high=MAX_HALVINGS),
    Field("peak_accuracy", NUMBER, "relative accuracy of the reported peaks, refined between "
          "steps (0: the largest recorded step)", "", 1e-4, low=0, high=0.1),
    Field("allow_large", BOOL, "run past the memory/time estimate", "", False),
), "how the run is made", "[run]", by=RunOptions)  # fmt: skip

#: The file formats of the history (``[output] format``).
HISTORY_FORMATS = tuple(HISTORY_BYTES_PER_ROW)

OUTPUT = Section("output", (
    Field("every", INTEGER, "record every k-th step (default: every step while the history "
          "stays under 1 GB, else the smallest k that keeps it under, with a warning)", "",
          None, low=1),
    Field("points", listed(int, "integer", unique=True, count=(1, None)), "the points recorded "
          "(1-based; default all)", "", None, low=1, allowed="point numbers >= 1 (the first "
          "point is 1)"),
    Field("format", STRING, "file format of the history: csv (history.csv, text) or parquet "
          "(history.parquet, binary columns with their units)", "", "csv",
          choices=HISTORY_FORMATS),
), "what is recorded", "[output]")  # fmt: skip

_SEG: dict[str, Any] = {"by": SEGMENT_KINDS["slide"], "per_point": True}
SEGMENT = Section("segment", (
    Field("kind", STRING, "segment kind", "", REQUIRED, choices=tuple(SEGMENT_KINDS)),
    Field("velocity", NUMBERS, "sliding velocity", "m/s", **_SEG),
    Field("distance", NUMBERS, "slide length", "m", **_SEG),
    Field("duration", NUMBERS, "duration", "s", **_SEG),
    Field("direction_deg", NUMBERS, "sliding direction from e_1", "deg", **_SEG),
    Field("angle_deg", NUMBERS, "turn angle", "deg", **_SEG),
    Field("amplitude", NUMBERS, "cycle amplitude", "m", **_SEG),
    Field("cycles", INTEGER, "number of cycles", "", low=1),
    Field("approach", NUMBERS, "normal approach", "m", **_SEG),
    Field("traction", NUMBERS, "normal traction target", "Pa", **_SEG),
    Field("traction_change", NUMBERS, "normal traction change", "Pa", **_SEG),
    Field("magnitude", NUMBERS, "traction target's size (with direction_deg)", "Pa", **_SEG),
    Field("file", STRING, "table file (CSV: time, slip_1, slip_2, ...)", ""),
    Field("steps_per_row", INTEGER, "steps between table rows", "", low=1),
    Field("steps", INTEGER, "number of steps", "", low=1),
    Field("max_step", NUMBER, "largest step (instead of steps)", "", low=0, open="low"),
), "one loading segment", "[[program]]", variants={
    "slide": ("steps", "max_step", "velocity", "distance", "duration", "direction_deg"),
    "hold": ("steps", "max_step", "duration"),
    "reverse": ("steps", "max_step", "velocity", "distance", "duration"),
    "turn": ("steps", "max_step", "angle_deg", "velocity", "distance", "duration"),
    "cycle": ("steps", "max_step", "amplitude", "velocity", "cycles", "direction_deg"),
    "normal": ("steps", "max_step", "approach", "traction", "traction_change", "duration"),
    "traction": ("steps", "max_step", Field("traction", PAIRS, "tangential traction target "
                 "(pair)", "Pa", **_SEG), "duration", Field("cycles", INTEGER, "full load cycles "
                 "start -> target -> start (0: one ramp to the target)", "", 0, by=Traction),
                 "magnitude", "direction_deg"),
    "table": ("file", "steps_per_row", "max_step"),
}, required_by={
    "slide": ("velocity",), "hold": ("duration",), "turn": ("angle_deg",),
    "cycle": ("amplitude", "velocity"), "table": ("file",),
}, ref=True, by=SEGMENT_KINDS, one_of=(("traction", "magnitude"),))  # fmt: skip

_M: dict[str, Any] = {"by": SpringSlider, "per_point": True}
MACHINE = Section("machine", (
    Field("stiffness", NUMBERS, "machine spring k", "Pa/m", REQUIRED, **_M),
    Field("velocity", NUMBERS, "load-point velocity V", "m/s", REQUIRED, **_M),
    Field("mass", NUMBERS, "slider mass (0: quasi-static)", "kg/m^2", 0.0, **_M),
    Field("damping", NUMBERS, "dashpot parallel to the spring", "Pa s/m", 0.0, **_M),
    Field("direction_deg", NUMBERS, "rail direction from e_1", "deg", 0.0, **_M),
    Field("spectral_radius", NUMBER, "rho_inf of the generalized-alpha scheme", "", 0.5,
          by=SpringSlider),
    Field("duration", NUMBERS, "how long the load point moves", "s", REQUIRED, low=0,
          open="low", per_point=True),
    Field("steps", INTEGER, "number of steps (default 1000)", "", None, low=1),
    Field("max_step", NUMBER, "largest step (instead of steps)", "s", None, low=0, open="low"),
), "the stick-slip spring-slider (instead of [[program]])", "[machine]",
   exclusive=(("steps", "max_step"),), by=SpringSlider)  # fmt: skip

SCENARIO_FILE = run_file("scenario", (
    Field("law", table=LAW, default=REQUIRED),
    Field("initial", table=INITIAL, default=REQUIRED),
    Field("run", table=RUN),
    Field("output", table=OUTPUT),
    Field("program", table=SEGMENT, many=True),
    Field("machine", table=MACHINE),
), "A scenario file of `frictionlab simulate`: [law], [initial], optional [run] and [output], "
   "then [[program]] segments or a [machine]. Numbers may be lists, one value per contact "
   "point. SI units.", "", one_of=(("program", "machine"),))  # fmt: skip


# --------------------------------------------------------------------------- sections
def parse_law_table(data: Any, where: str = "[law]") -> tuple[SubloadingParams, dict[str, Any]]:
    """Validate a ``[law]`` mapping -> (params, the keys given with their values)."""
    given = LAW.read(data, where, only_given=True)
    surface = given.get("surface", "coulomb")
    needed = _NEEDED.get(surface, _CLOSED_KEYS)
    for key in needed:
        if key not in given:
            raise InputError(f"missing required key {where}.{key} (surface '{surface}' needs "
                             f"{', '.join(needed)})")  # fmt: skip
    values = radians(given)
    given.pop("surface", None)
    return reraise(where, lambda: SubloadingParams(**values)), given


def radians(values: dict[str, Any]) -> dict[str, Any]:
    """``values`` with ``orthotropy_angle_deg`` given as ``orthotropy_angle`` (rad)."""
    if "orthotropy_angle_deg" not in values:
        return dict(values)
    deg = {k: v for k, v in values.items() if k != "orthotropy_angle_deg"}
    return {**deg, "orthotropy_angle": np.radians(values["orthotropy_angle_deg"]).tolist()}


def law_table(params: SubloadingParams) -> dict[str, Any]:
    """The ``[law]`` table that :func:`parse_scenario` reads back as ``params``.

    Every parameter is written (defaults included), per-point values as lists, the
    orthotropy angle in degrees and the orthotropy in the stored "divide" convention.
    """
    table: dict[str, Any] = {}
    for key in LAW_KEYS:
        value = getattr(params, key.removesuffix("_deg"))
        if key.startswith("orthotropy_angle"):
            angle = np.degrees(np.asarray(value, dtype=float))
            key, value = "orthotropy_angle_deg", angle.tolist()
        if value is not None:
            table[key] = np.asarray(value).tolist() if isinstance(value, np.ndarray) else value
    return {**table, "orthotropy_convention": "divide"}


def parse_initial_table(
    data: Any, where: str = "[initial]"
) -> tuple[InitialConditions, dict[str, Any]]:
    """Validate an ``[initial]`` mapping -> (initial conditions, the values as given)."""
    return INITIAL.build(data, where)


def parse_program_tables(
    tables: Sequence[dict[str, Any]],
    base_dir: str | os.PathLike[str] = ".",
    where: str = "[[program]]",
) -> Program:
    """Validate ``[[program]]`` mappings (segments, in order) -> a :data:`Program`."""
    if not tables:
        raise InputError(f"{where} must hold at least one segment")
    return tuple(
        _parse_segment(TomlTable(t, f"{where} #{i + 1}"), Path(base_dir))
        for i, t in enumerate(tables)
    )


@dataclass(frozen=True)
class OutputOptions:
    """``[output]``: record every k-th step (``every``) and only some ``points`` (1-based),
    the history in ``format`` (``"csv"`` or ``"parquet"``). ``every_given``: whether the
    file set ``every`` (otherwise it was chosen to bound the history's size)."""

    every: int = 1
    points: tuple[int, ...] | None = None
    format: str = "csv"
    every_given: bool = True

    @property
    def history_name(self) -> str:
        """``history.csv`` or ``history.parquet``."""
        return f"history.{self.format}"

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
    values = OUTPUT.read({} if t is None else t, "[output]")
    points = values["points"] and tuple(sorted(values["points"]))
    every = values["every"]
    return OutputOptions(every or 1, points, values["format"], every is not None)


def _parse_segment(t: TomlTable, base_dir: Path) -> Any:
    kwargs = SEGMENT.read(t, only_given=True)
    kind = kwargs.pop("kind")
    if kind == "table":
        return _parse_table_segment(t, kwargs, base_dir)
    if kind == "traction" and "magnitude" in kwargs:
        magnitude = np.asarray(kwargs.pop("magnitude"))
        angle = np.radians(np.asarray(kwargs.pop("direction_deg", 0.0)))
        vec = np.stack(
            np.broadcast_arrays(magnitude * np.cos(angle), magnitude * np.sin(angle)), axis=-1
        )
        kwargs["traction"] = vec.tolist()
    cls = SEGMENT_KINDS[kind]
    return reraise(t.where, lambda: cls(**{"steps": None, "max_step": None, **kwargs}))


#: SI units of the columns of a ``kind = "table"`` file (titles may carry them: ``time [s]``).
TABLE_UNITS = {"time": "s", "slip_1": "m", "slip_2": "m", "normal_traction": "Pa", "approach": "m"}


def _parse_table_segment(t: TomlTable, values: dict[str, Any], base_dir: Path) -> Table:
    name = values["file"]
    path = Path(name) if Path(name).is_absolute() else base_dir / name
    cols = read_csv(path)
    where = f"{t.where}.file '{name}'"
    for required in ("time", "slip_1"):
        if required not in cols:
            raise InputError(f"{where}: missing column '{required}' (columns: time, slip_1, "
                             "slip_2, and optionally normal_traction or approach)")  # fmt: skip
    extra = sorted(set(cols) - set(TABLE_UNITS))
    if extra:
        raise InputError(
            f"{where}: unknown column '{extra[0]}'; allowed: {', '.join(sorted(TABLE_UNITS))}"
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
    return reraise(
        where,
        lambda: Table(
            time=cols["time"], slip=slip, normal_traction=cols.get("normal_traction"),
            approach=cols.get("approach"), steps_per_row=values.get("steps_per_row"),
            max_step=values.get("max_step"), source=str(name),
        ),
    )  # fmt: skip


def _is_float(v: str) -> bool:
    try:
        float(v)
    except ValueError:
        return False
    return True


@dataclass(frozen=True)
class MachineRun:
    """``[machine]``: the spring-slider and how long to pull it."""

    machine: SpringSlider
    duration: Any
    steps: int | None = None
    max_step: float | None = None


def _parse_machine(t: TomlTable) -> tuple[MachineRun, dict[str, Any]]:
    machine, echo = MACHINE.build(t, drop=("duration", "steps", "max_step"))
    duration, steps, max_step = echo["duration"], echo["steps"], echo["max_step"]
    if np.any(np.asarray(duration, dtype=np.float64) <= 0):
        raise InputError(f"{t.where}.duration = {duration} is invalid: allowed a duration > 0 [s]")
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
    #: Warnings about the inputs, made while parsing (printed before the run, and in
    #: summary.json's warnings).
    warnings: tuple[str, ...] = ()

    @property
    def kind(self) -> str:
        """``"program"`` or ``"spring_slider"``."""
        return "program" if self.program is not None else "spring_slider"


_PAIR_KEYS = ("rotation", "orthotropy", "tangential_traction", "traction")


def per_point(values: dict[str, Any], prefix: str = "") -> list[tuple[str, str, list[Any]]]:
    """The inputs given per point, (prefix, key, values): lists of numbers, or lists of
    pairs for vector keys."""
    listed = ((k, v) for k, v in values.items() if isinstance(v, list) and v)
    return [(prefix, k, v) for k, v in listed if isinstance(v[0], list) or k not in _PAIR_KEYS]


def _segment_echo(seg: Any) -> dict[str, Any]:
    if isinstance(seg, Table):
        return {
            "kind": "table", "source": seg.source, "rows": int(seg.time.size),
            "columns": ["time", "slip_1", "slip_2"]
            + [c for c in ("normal_traction", "approach") if getattr(seg, c) is not None],
            "steps_per_row": seg.steps_per_row, "max_step": seg.max_step,
        }  # fmt: skip
    return {"kind": seg.kind, **_jsonable(segment_fields(seg))}


def parse_scenario(
    data: dict[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> Scenario:
    """Validate a parsed scenario mapping and build a :class:`Scenario` (nothing runs)."""
    top, tables = SCENARIO_FILE.read_top(data)
    params, law_given = parse_law_table(tables["law"])
    init, init_echo = parse_initial_table(tables["initial"])
    opts, _ = RUN.build(tables["run"] or {})
    output = _parse_output(tables["output"])
    varying = per_point(law_given) + per_point(init_echo)
    program: Program | None = None
    machine: MachineRun | None = None
    if tables["program"] is not None:
        program = tuple(_parse_segment(t, Path(base_dir)) for t in tables["program"])
        for t, seg in zip(tables["program"], program, strict=True):
            raw = {k: v for k, v in t.mapping().items() if k != "kind"}
            varying += per_point(raw, "hold " if seg.kind == "hold" else "")
    else:
        machine, machine_echo = _parse_machine(tables["machine"])
        varying += per_point(machine_echo)
    sizes = machine.machine.sizes() if machine is not None else set()
    if machine is not None and np.ndim(machine.duration) == 1:
        sizes = sizes | {len(machine.duration)}
    n = reraise("scenario", lambda: count_points(params, program or (), init, opts.n_points, sizes))
    if output.points is not None and output.points[-1] > n:
        raise InputError(f"[output].points has {output.points[-1]}: allowed point numbers "
                         f"1..{n} (the scenario has {n} point(s))")  # fmt: skip
    check_points(n, output, program is not None, opts.allow_large)  # before size-N arrays
    # the snap-back check names a [law] field
    reraise(
        lambda k: f"[law].{k}" if k in LAW_KEYS else f"[initial].{k}", lambda: init.state(params, n)
    )
    if program is not None:
        plans = reraise("[[program]]", lambda: plan_program(program, n))
        counts = [(p.estimated_steps, f"[[program]] #{i}.{steps_key(seg)}")
                  for i, (p, seg) in enumerate(zip(plans, program, strict=True), 1)]  # fmt: skip
    else:
        assert machine is not None
        counts = [(machine_steps(machine), f"[machine].{steps_key(machine)}")]
    estimate, output, warnings = scenario_estimate(counts, n, output, program is not None,
                                                   opts.allow_large)  # fmt: skip
    inputs: dict[str, Any] = _jsonable({
        "title": top["title"], "description": top["description"], "law": params.as_dict(),
        "initial": {**init_echo, "F": _or(init_echo["F"], "static value")},
        "run": {"n_points": n, **{k: getattr(opts, k) for k in (
            "accuracy", "max_halvings", "peak_accuracy")}},
        "output": {"every": output.every, "points": _or(output.points, "all"),
                   "format": output.format},
        **({"program": [_segment_echo(s) for s in program]} if program is not None
           else {"machine": machine_echo}),
    })  # fmt: skip
    return Scenario(
        title=top["title"], description=top["description"], params=params, initial=init,
        run_options=opts, n_points=n, program=program, machine=machine, inputs=inputs,
        labels=point_labels(n, varying), source=source, output=output, estimate=estimate,
        warnings=warnings,
    )  # fmt: skip


def _or(value: Any, default: Any) -> Any:
    return default if value is None else value


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


load_scenario = loader(SCENARIO_FILE, parse_scenario, "a scenario file")
