"""The ``frictionlab contact`` scenario: declarations and the parser.

``[block]`` (the elastic block), ``[law]`` (as in simulate), ``[normal]`` (the normal
stage), ``[[program]]`` (kind = slide | reverse | hold | traction), optional
``[solver]`` and ``[output]``. Everything is validated before anything is meshed.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from frictionlab.contact.block import ELEMENTS, Block
from frictionlab.contact.interface import TANGENTS
from frictionlab.contact.loading import Hold, NormalLoad, Reverse, Segment, Slide, Traction
from frictionlab.contact.solver import DRIVES, SolverOptions
from frictionlab.errors import InputError
from frictionlab.schema.core import (
    INTEGER,
    NUMBER,
    REQUIRED,
    STRING,
    Field,
    Section,
    load,
    reraise,
)
from frictionlab.schema.scenario import LAW, parse_law_table
from frictionlab.subloading import SubloadingParams, check_snap_back

__all__ = ["CONTACT", "ContactScenario", "load_contact", "parse_contact"]

_B: dict[str, Any] = {"by": Block}
BLOCK = Section("block", (
    Field("E", NUMBER, "Young's modulus", "Pa", REQUIRED, **_B),
    Field("nu", NUMBER, "Poisson's ratio", "-", REQUIRED, **_B),
    Field("width", NUMBER, "block width (x)", "m", REQUIRED, **_B),
    Field("height", NUMBER, "block height (y)", "m", REQUIRED, **_B),
    Field("element_size", NUMBER, "element edge length", "m", REQUIRED, **_B),
    Field("depth", NUMBER, "block depth (z): gives a 3-D block", "m", None, **_B),
    Field("element", STRING, "element (default quad in 2-D, hex in 3-D)", choices=ELEMENTS, **_B),
), "the elastic block", "[block]")  # fmt: skip
_N: dict[str, Any] = {"by": NormalLoad}
NORMAL = Section("normal", (
    Field("pressure", NUMBER, "normal pressure on the top (or displacement)", "Pa", None, **_N),
    Field("displacement", NUMBER, "normal displacement of the top (or pressure)", "m", None,
          **_N),
    Field("duration", NUMBER, "duration of the normal stage", "s", 1.0, **_N),
    Field("steps", INTEGER, "steps of the normal stage", "", 5, **_N),
), "the normal stage", "[normal]")  # fmt: skip
_SEG_CLASSES = {"slide": Slide, "reverse": Reverse, "hold": Hold, "traction": Traction}
SEGMENT = Section("contact_segment", (
    Field("kind", STRING, "segment kind", "", REQUIRED, choices=tuple(_SEG_CLASSES)),
    Field("velocity", NUMBER, "sliding velocity of the drive", "m/s", None, by=Slide),
    Field("distance", NUMBER, "slide length (or duration)", "m", None, by=Slide),
    Field("duration", NUMBER, "duration", "s", None, by=Slide),
    Field("target", NUMBER, "tangential traction target (ratio to the pressure)", "", None,
          by=Traction),
    Field("steps", INTEGER, "number of steps", "", 20, by=Slide),
    Field("direction_deg", NUMBER, "sliding direction from x", "deg", 0.0, by=Slide),
), "one tangential segment", "[[program]]", variants={
    "slide": ("velocity", "distance", "duration", "steps", "direction_deg"),
    "reverse": ("velocity", "distance", "steps"),
    "hold": ("duration", Field("steps", INTEGER, "number of steps", "", 5, by=Hold)),
    "traction": ("target", "duration", "steps", "direction_deg"),
}, required_by={"slide": ("velocity",), "hold": ("duration",),
                "traction": ("target", "duration")}, ref=True)  # fmt: skip
_S: dict[str, Any] = {"by": SolverOptions}
SOLVER = Section("solver", (
    Field("tolerance", NUMBER, "relative residual norm for convergence", "", 1e-10, **_S),
    Field("max_iterations", INTEGER, "Newton iterations per step attempt", "", 25, **_S),
    Field("max_cuts", INTEGER, "halvings of a step before the run stops", "", 12, **_S),
    Field("easy_iterations", INTEGER, "a step converged within these lets the next grow", "",
          4, **_S),
    Field("growth", NUMBER, "growth factor of the next step after an easy one", "", 2.0, **_S),
    Field("tangent", STRING, "stiffness of the Newton iteration", "", "consistent",
          choices=TANGENTS, **_S),
    Field("drive", STRING, "what the tangential programme moves", "", "top", choices=DRIVES),
), "Newton and step control", "[solver]")  # fmt: skip
OUTPUT = Section("output", (
    Field("front_ratio", NUMBER, "|f_t| / F ratio that counts as slipping (the front)", "",
          0.99, low=0, high=1, open="low"),
), "what is reported", "[output]")  # fmt: skip
CONTACT = Section("contact", (
    Field("title", STRING, "title of the run", "", ""),
    Field("description", STRING, "free text", "", ""),
    Field("block", table=BLOCK, default=REQUIRED),
    Field("law", table=LAW, default=REQUIRED),
    Field("normal", table=NORMAL, default=REQUIRED),
    Field("program", table=SEGMENT, many=True, default=REQUIRED),
    Field("solver", table=SOLVER),
    Field("output", table=OUTPUT),
), "A contact scenario of `frictionlab contact`: an elastic [block] pressed and slid on a "
   "rigid base through the subloading-friction [law]. SI units.")  # fmt: skip


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


def _segment(data: Any) -> tuple[Segment, dict[str, Any]]:
    values = SEGMENT.read(data)
    kind = values.pop("kind")
    if kind == "slide" and (values["distance"] is None) == (values["duration"] is None):
        raise InputError(f"{data.where}: a slide needs exactly one of distance [m] or duration [s]")
    return reraise(data.where, lambda: _SEG_CLASSES[kind](**values)), {"kind": kind, **values}


def parse_contact(
    data: dict[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> ContactScenario:
    """Validate a parsed contact scenario mapping (nothing runs, nothing is meshed)."""
    root = CONTACT.table(data, "")
    top = CONTACT.read(root)
    block_t, law_t = root.table("block", required=True), root.table("law", required=True)
    normal_t = root.table("normal", required=True)
    program_ts = root.tables("program", required=True)
    assert block_t is not None and law_t is not None and normal_t is not None
    if not program_ts:
        raise InputError("[[program]] must hold at least one segment")
    block_echo = BLOCK.read(block_t)
    if block_echo["element"] is None:
        block_echo["element"] = "quad" if block_echo["depth"] is None else "hex"
    block = reraise("[block]", lambda: Block(**block_echo))
    params, _ = parse_law_table(law_t.mapping(), law_t.where)
    normal_echo = NORMAL.read(normal_t)
    if normal_echo["pressure"] is None and normal_echo["displacement"] is None:
        raise InputError("missing required key [normal].pressure (or [normal].displacement)")
    if normal_echo["pressure"] is not None and normal_echo["displacement"] is not None:
        raise InputError("[normal]: give pressure [Pa] or displacement [m], not both")
    normal = reraise("[normal]", lambda: NormalLoad(**normal_echo))
    parsed = [_segment(t) for t in program_ts]
    program = tuple(seg for seg, _ in parsed)
    solver_echo = SOLVER.read(root.raw("solver", {}), "[solver]")
    solver_values = {k: v for k, v in solver_echo.items() if k != "drive"}
    options = reraise("[solver]", lambda: SolverOptions(**solver_values))
    drive = solver_echo["drive"]
    front_ratio = OUTPUT.read(root.raw("output", {}), "[output]")["front_ratio"]
    # the checks that need several sections, with the key to blame
    from frictionlab.contact.loading import plan_stages

    control, stages = reraise("[[program]]", lambda: plan_stages(normal, program))
    if block.dim == 2 and any(abs(s.end[1]) > 0.0 for s in stages[1:]):
        raise InputError(
            "[[program]] direction_deg must be 0 or 180 for a 2-D block (it slides along x); "
            "give [block].depth for a 3-D block"
        )
    if drive == "rigid" and control != "slide":
        raise InputError("[solver].drive = 'rigid' needs a displacement-controlled programme")
    nominal = normal.value if normal.control == "pressure" else normal.value * float(params.alpha_n)
    reraise("[law]", lambda: check_snap_back(params, nominal))
    inputs = {
        "title": top["title"], "description": top["description"], "block": block_echo,
        "law": {k: (v.tolist() if hasattr(v, "tolist") else v)
                for k, v in params.as_dict().items()},
        "normal": normal_echo, "program": [echo for _, echo in parsed], "solver": solver_echo,
        "output": {"front_ratio": front_ratio},
    }  # fmt: skip
    return ContactScenario(
        title=top["title"], description=top["description"], block=block, params=params,
        normal=normal, program=program, options=options, drive=drive, front_ratio=front_ratio,
        inputs=inputs, source=source,
    )  # fmt: skip


def load_contact(path: str | os.PathLike[str], overrides: Sequence[str] = ()) -> ContactScenario:
    """Read, override (``section.key=value``) and validate a contact scenario file."""
    return load(CONTACT, parse_contact, path, overrides)
