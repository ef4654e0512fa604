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
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

from frictionlab.contact.block import ELEMENTS, INTEGRATIONS, Block, Refinement
from frictionlab.contact.interface import TANGENTS
from frictionlab.contact.linear import LINEAR_SOLVERS
from frictionlab.contact.loading import Hold, NormalLoad, Reverse, Segment, Slide, Traction
from frictionlab.contact.shapes import SHAPES, Base
from frictionlab.contact.solver import DRIVES, SolverOptions
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import REQUIRED, apply_overrides, load_toml
from frictionlab.io.config import Table as TomlTable
from frictionlab.io.scenario import parse_law_table
from frictionlab.subloading import SubloadingParams, check_snap_back

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
        {"target": REQUIRED, "duration": REQUIRED, "steps": 20, "direction_deg": 0.0, "cycles": 0},
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
    base: Base = field(default_factory=Base)
    fields: bool = False


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
    values["integration"] = t.get("integration", str, "full", choices=INTEGRATIONS)
    ref_t = t.table("refinement")
    t.finish()
    echo = dict(values)
    if ref_t is not None:
        ref = {
            "size": _number(ref_t, "size"),
            "extent": _number(ref_t, "extent"),
            "center": ref_t.get_list("center", float, None, length=(1, 2)),
            "growth": _number(ref_t, "growth", 1.2),
        }
        ref_t.finish()
        values["refinement"] = _where(ref_t.where, lambda: Refinement(**ref))
        echo["refinement"] = ref
    return _where(t.where, lambda: Block(**values)), echo


def _parse_base(t: TomlTable | None) -> tuple[Base, dict[str, Any]]:
    if t is None:
        return Base(), {"shape": "flat"}
    values = {
        "shape": t.get("shape", str, "flat", choices=SHAPES),
        "radius": _number(t, "radius", None),
        "center": t.get_list("center", float, None, length=(1, 2)),
    }
    t.finish()
    if values["shape"] == "profile":
        raise InputError(f"{t.where}.shape = 'profile' is available from Python only (Base)")
    return _where(t.where, lambda: Base(**values)), values


def _parse_normal(t: TomlTable) -> tuple[NormalLoad, dict[str, Any]]:
    values = {
        "pressure": _number(t, "pressure", None),
        "displacement": _number(t, "displacement", None),
        "force": _number(t, "force", None),
        "duration": _number(t, "duration", 1.0),
        "steps": _steps(t, 5),
    }
    t.finish()
    given = [k for k in ("pressure", "displacement", "force") if values[k] is not None]
    if not given:
        raise InputError(
            f"missing required key {t.where}.pressure (or {t.where}.displacement, {t.where}.force)"
        )
    if len(given) > 1:
        raise InputError(
            f"{t.where}: give exactly one of pressure [Pa], displacement [m] or force "
            f"[N/m in 2-D, N in 3-D], not {' and '.join(given)}"
        )
    return _where(t.where, lambda: NormalLoad(**values)), values


def _parse_segment(t: TomlTable) -> tuple[Segment, dict[str, Any]]:
    kind = t.get("kind", str, choices=tuple(_SEGMENTS))
    cls, keys = _SEGMENTS[kind]
    values: dict[str, Any] = {}
    for key, default in keys.items():
        if key in ("steps", "cycles"):
            values[key] = int(t.get(key, int, default))
        else:
            values[key] = _number(t, key, default)
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
        "linear_solver": t.get("linear_solver", str, d["linear_solver"], choices=LINEAR_SOLVERS),
        "memory_limit": t.get("memory_limit", float, d["memory_limit"]),
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
    base_t = root.table("base")
    root.finish()
    assert block_t is not None and law_t is not None and normal_t is not None
    if not program_ts:
        raise InputError("[[program]] must hold at least one segment")
    block, block_echo = _parse_block(block_t)
    base, base_echo = _parse_base(base_t)
    _where("[base]", lambda: base.check_dim(block.dim))
    params, _ = parse_law_table(law_t.mapping(), law_t.where)
    normal, normal_echo = _parse_normal(normal_t)
    parsed = [_parse_segment(t) for t in program_ts]
    program = tuple(seg for seg, _ in parsed)
    options, drive, solver_echo = _parse_solver(solver_t)
    front_ratio = 0.99
    write_fields = False
    if output_t is not None:
        write_fields = output_t.get("fields", bool, False)
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
    if normal.control == "pressure":
        nominal = normal.value
    elif normal.control == "force":
        area = block.width * (block.depth or 1.0)
        nominal = normal.value / area
    else:
        nominal = normal.value * float(params.alpha_n)
    _where("[law]", lambda: check_snap_back(params, nominal))
    inputs = {
        "title": title,
        "description": description,
        "block": block_echo,
        "base": base_echo,
        "law": {
            k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in params.as_dict().items()
        },
        "normal": normal_echo,
        "program": [echo for _, echo in parsed],
        "solver": solver_echo,
        "output": {"front_ratio": front_ratio, "fields": write_fields},
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
        base=base,
        fields=write_fields,
    )


def load_contact_scenario(
    path: str | os.PathLike[str], overrides: Sequence[str] = ()
) -> ContactScenario:
    """Read, override (``section.key=value``) and validate a contact scenario file."""
    p = Path(path)
    data = apply_overrides(load_toml(p), overrides)
    return parse_contact_scenario(data, source=str(p))
