"""Contact scenario files: TOML -> block, law, normal load, tangential programme, solver.

Schema (every key with its default and unit is in docs/contact.md)::

    title = "..."                 # optional
    description = "..."           # optional
    [block]                       # E [Pa], nu, width [m], height [m], element_size [m],
                                  # element; depth [m] for a 3-D block
    [law]                         # the subloading-friction law: the keys of `simulate`
    [normal]                      # pressure [Pa] or displacement [m]; duration [s], steps
    [[program]]                   # kind = slide | reverse | hold | traction
    [solver]                      # optional: tolerance, max_iterations, max_cuts,
                                  # easy_iterations, growth, tangent, drive
    [output]                      # optional: front_ratio

:func:`parse_contact_scenario` validates everything before anything runs; a problem is
one :class:`~frictionlab.errors.InputError` or :class:`~frictionlab.errors.ParameterError`
line naming the key (``[block].nu = 0.7 is invalid: allowed 0 <= nu < 0.5``).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any

from frictionlab.contact.block import ELEMENTS, Block
from frictionlab.contact.interface import TANGENTS
from frictionlab.contact.loading import Hold, NormalLoad, Reverse, Segment, Slide, Traction
from frictionlab.contact.solver import DRIVES, SolverOptions
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import REQUIRED, apply_overrides, load_toml
from frictionlab.io.config import Table as TomlTable
from frictionlab.io.scenario import parse_law_table
from frictionlab.subloading import SubloadingParams, check_normal_capacity, check_snap_back

__all__ = ["ContactScenario", "load_contact_scenario", "parse_contact_scenario"]

_SOLVER_DEFAULTS = {f.name: f.default for f in fields(SolverOptions)}
_SEGMENTS: dict[str, tuple[type, dict[str, Any]]] = {
    # kind -> (class, {key: default}) ; REQUIRED marks required keys
    "slide": (
        Slide,
        {
            "velocity": REQUIRED,
            "distance": None,
            "duration": None,
            "steps": 20,
            "direction_deg": 0.0,
        },
    ),
    "reverse": (Reverse, {"velocity": None, "distance": None, "steps": 20}),
    "hold": (Hold, {"duration": REQUIRED, "steps": 5}),
    "traction": (
        Traction,
        {"target": REQUIRED, "duration": REQUIRED, "steps": 20, "direction_deg": 0.0},
    ),
}


@dataclass(frozen=True)
class ContactScenario:
    """A validated contact scenario and the echo of its inputs with defaults."""

    title: str
    description: str
    block: Block
    params: SubloadingParams
    normal: NormalLoad
    program: tuple[Segment, ...]
    options: SolverOptions
    drive: str
    front_ratio: float
    inputs: dict[str, Any]
    source: str = ""


def _where(where: str, call: Callable[[], Any]) -> Any:
    """Run ``call``; put ``where`` in front of the field of a ParameterError."""
    try:
        return call()
    except ParameterError as exc:
        raise ParameterError(f"{where}.{exc.field}", exc.value, exc.allowed) from None


def _number(t: TomlTable, key: str, default: Any = REQUIRED) -> Any:
    return t.get(key, float, default)


def _steps(t: TomlTable, default: int) -> int:
    return int(t.get("steps", int, default))


def _parse_block(t: TomlTable) -> tuple[Block, dict[str, Any]]:
    values = {
        "E": _number(t, "E"),
        "nu": _number(t, "nu"),
        "width": _number(t, "width"),
        "height": _number(t, "height"),
        "element_size": _number(t, "element_size"),
        "depth": _number(t, "depth", None),
    }
    values["element"] = t.get(
        "element", str, "quad" if values["depth"] is None else "hex", choices=ELEMENTS
    )
    t.finish()
    return _where(t.where, lambda: Block(**values)), values


def _parse_normal(t: TomlTable) -> tuple[NormalLoad, dict[str, Any]]:
    values = {
        "pressure": _number(t, "pressure", None),
        "displacement": _number(t, "displacement", None),
        "duration": _number(t, "duration", 1.0),
        "steps": _steps(t, 5),
    }
    t.finish()
    if values["pressure"] is None and values["displacement"] is None:
        raise InputError(f"missing required key {t.where}.pressure (or {t.where}.displacement)")
    if values["pressure"] is not None and values["displacement"] is not None:
        raise InputError(f"{t.where}: give pressure [Pa] or displacement [m], not both")
    return _where(t.where, lambda: NormalLoad(**values)), values


def _check_load(law: dict[str, Any], block: Block, params: SubloadingParams, normal: Any) -> None:
    """Refuse, naming the key, a per-point law and a normal load no linear block can take."""
    if params.per_point:
        pairs = ("rotation", "orthotropy")  # one pair each, or per-point pairs
        key = next(
            (k for k, v in law.items()
             if isinstance(v, list) and (k not in pairs or (v and isinstance(v[0], list)))),
            "law",
        )  # fmt: skip
        raise InputError(
            f"[law].{key} = {law.get(key)} is invalid: allowed one value (the contact model "
            "has one interface law; per-point lists are for simulate)"
        )
    if normal.control == "pressure" and not normal.value < block.E:
        raise InputError(
            f"[normal].pressure = {normal.value:g} Pa is invalid: allowed a pressure below "
            f"[block].E = {block.E:g} Pa (the linear-elastic block's strain stays below 1)"
        )
    if normal.control != "pressure" and not normal.value < block.height:
        raise InputError(
            f"[normal].displacement = {normal.value:g} m is invalid: allowed less than "
            f"[block].height = {block.height:g} m"
        )


def _parse_segment(t: TomlTable) -> tuple[Segment, dict[str, Any]]:
    kind = t.get("kind", str, choices=tuple(_SEGMENTS))
    cls, keys = _SEGMENTS[kind]
    values: dict[str, Any] = {}
    for key, default in keys.items():
        values[key] = _steps(t, default) if key == "steps" else _number(t, key, default)
    t.finish()
    if kind == "slide" and (values["distance"] is None) == (values["duration"] is None):
        raise InputError(f"{t.where}: a slide needs exactly one of distance [m] or duration [s]")
    segment = _where(t.where, lambda: cls(**values))
    return segment, {"kind": kind, **values}


def _parse_solver(t: TomlTable | None) -> tuple[SolverOptions, str, dict[str, Any]]:
    d = _SOLVER_DEFAULTS
    if t is None:
        t = TomlTable({}, "[solver]")
    values = {
        "tolerance": t.get("tolerance", float, d["tolerance"]),
        "max_iterations": t.get("max_iterations", int, d["max_iterations"]),
        "max_cuts": t.get("max_cuts", int, d["max_cuts"]),
        "easy_iterations": t.get("easy_iterations", int, d["easy_iterations"]),
        "growth": t.get("growth", float, d["growth"]),
        "tangent": t.get("tangent", str, d["tangent"], choices=TANGENTS),
    }
    drive = t.get("drive", str, "top", choices=DRIVES)
    t.finish()
    options = _where(t.where, lambda: SolverOptions(**values))
    return options, drive, {**values, "drive": drive}


def parse_contact_scenario(data: dict[str, Any], source: str = "") -> ContactScenario:
    """Validate a parsed contact scenario mapping (nothing runs, nothing is meshed)."""
    root = TomlTable(data, "")
    title = root.get("title", str, "")
    description = root.get("description", str, "")
    block_t = root.table("block", required=True)
    law_t = root.table("law", required=True)
    normal_t = root.table("normal", required=True)
    program_ts = root.tables("program", required=True)
    solver_t = root.table("solver")
    output_t = root.table("output")
    root.finish()
    assert block_t is not None and law_t is not None and normal_t is not None
    if not program_ts:
        raise InputError("[[program]] must hold at least one segment")
    block, block_echo = _parse_block(block_t)
    params, _ = parse_law_table(law_t.mapping(), law_t.where)
    normal, normal_echo = _parse_normal(normal_t)
    parsed = [_parse_segment(t) for t in program_ts]
    program = tuple(seg for seg, _ in parsed)
    options, drive, solver_echo = _parse_solver(solver_t)
    front_ratio = 0.99
    if output_t is not None:
        front_ratio = output_t.get(
            "front_ratio",
            float,
            0.99,
            check=lambda v: 0.0 < v <= 1.0,
            allowed="0 < front_ratio <= 1",
        )
        output_t.finish()
    # the checks that need several sections, with the key to blame
    from frictionlab.contact.loading import plan_stages

    control, stages = _where("[[program]]", lambda: plan_stages(normal, program))
    if block.dim == 2 and any(abs(s.end[1]) > 0.0 for s in stages[1:]):
        raise InputError(
            "[[program]] direction_deg must be 0 or 180 for a 2-D block (it slides along x); "
            "give [block].depth for a 3-D block"
        )
    if drive == "rigid" and control != "slide":
        raise InputError("[solver].drive = 'rigid' needs a displacement-controlled programme")
    _check_load(law_t.mapping(), block, params, normal)
    nominal = normal.value if normal.control == "pressure" else normal.value * float(params.alpha_n)
    _where("[law]", lambda: check_snap_back(params, nominal))
    if normal.control == "pressure":  # the mean pressure: some points carry more
        _where("[law]", lambda: check_normal_capacity(params, nominal))
    inputs = {
        "title": title,
        "description": description,
        "block": block_echo,
        "law": {
            k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in params.as_dict().items()
        },
        "normal": normal_echo,
        "program": [echo for _, echo in parsed],
        "solver": solver_echo,
        "output": {"front_ratio": front_ratio},
    }
    return ContactScenario(
        title=title,
        description=description,
        block=block,
        params=params,
        normal=normal,
        program=program,
        options=options,
        drive=drive,
        front_ratio=front_ratio,
        inputs=inputs,
        source=source,
    )


def load_contact_scenario(
    path: str | os.PathLike[str], overrides: Sequence[str] = ()
) -> ContactScenario:
    """Read, override (``section.key=value``) and validate a contact scenario file."""
    p = Path(path)
    data = apply_overrides(load_toml(p), overrides)
    return parse_contact_scenario(data, source=str(p))
