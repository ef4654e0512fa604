"""The ``frictionlab contact`` scenario: declarations and the parser.

``[block]`` (the elastic block), ``[law]`` (as in simulate), ``[normal]`` (the normal
stage), ``[[program]]`` (kind = slide | reverse | hold | traction), optional
``[solver]`` and ``[output]``. Everything is validated before anything is meshed.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from frictionlab.contact.block import ELEMENTS, INTEGRATIONS, Block, Refinement
from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.interface import TANGENTS
from frictionlab.contact.linear import LINEAR_SOLVERS
from frictionlab.contact.loading import Hold, NormalLoad, Reverse, Segment, Slide, Traction
from frictionlab.contact.shapes import Base
from frictionlab.contact.solver import DRIVES, SolverOptions, check_memory
from frictionlab.errors import InputError
from frictionlab.schema.core import (
    BOOL,
    INTEGER,
    NUMBER,
    REQUIRED,
    STRING,
    Field,
    Section,
    listed,
    load,
    reraise,
)
from frictionlab.schema.scenario import LAW, parse_law_table
from frictionlab.subloading import SubloadingParams, check_normal_capacity, check_snap_back

__all__ = ["CONTACT_FILE", "ContactScenario", "load_contact", "parse_contact"]

_R: dict[str, Any] = {"by": Refinement}
REFINEMENT = Section("refinement", (
    Field("size", NUMBER, "element size near the contact", "m", REQUIRED, **_R),
    Field("extent", NUMBER, "half-width (and depth) of the fine zone", "m", REQUIRED, **_R),
    Field("center", listed(float, "number", (1, 2)), "in-plane centre of the fine zone: x "
          "(2-D) or [x, y] (3-D); default the middle of the bottom", "m", None, **_R),
    Field("growth", NUMBER, "size ratio of neighbouring elements outside it", "", 1.2, **_R),
), "a graded mesh, fine near the contact", "[block.refinement]")  # fmt: skip
_B: dict[str, Any] = {"by": Block}
BLOCK = Section("block", (
    Field("E", NUMBER, "Young's modulus", "Pa", REQUIRED, **_B),
    Field("nu", NUMBER, "Poisson's ratio", "-", REQUIRED, **_B),
    Field("width", NUMBER, "block width (x)", "m", REQUIRED, **_B),
    Field("height", NUMBER, "block height (y)", "m", REQUIRED, **_B),
    Field("element_size", NUMBER, "element edge length", "m", REQUIRED, **_B),
    Field("depth", NUMBER, "block depth (z): gives a 3-D block", "m", None, **_B),
    Field("element", STRING, "element (default quad in 2-D, hex in 3-D)", choices=ELEMENTS, **_B),
    Field("integration", STRING, "full, or selective (one-point volumetric part: no locking as nu "
          "-> 1/2)", "", "full", choices=INTEGRATIONS, **_B),
    Field("refinement", table=REFINEMENT),
), "the elastic block", "[block]")  # fmt: skip
BASE = Section("base", (
    Field("shape", STRING, "the rigid base: flat, cylinder (2-D) or sphere (3-D)", "", "flat",
          choices=("flat", "cylinder", "sphere"), by=Base),
    Field("radius", NUMBER, "radius of a cylinder or sphere", "m", None, by=Base),
    Field("center", listed(float, "number", (1, 2)), "in-plane apex position: x (2-D) or "
          "[x, y] (3-D); default the middle of the bottom", "m", None, by=Base),
), "the rigid base's shape (a profile base is Python only: contact.shapes.Base)",
   "[base]")  # fmt: skip
_N: dict[str, Any] = {"by": NormalLoad}
NORMAL = Section("normal", (
    Field("pressure", NUMBER, "normal pressure on the top (or displacement, force)", "Pa", None,
          **_N),
    Field("displacement", NUMBER, "normal displacement of the top (or pressure, force)", "m",
          None, **_N),
    Field("force", NUMBER, "normal force through a rigid top plate (or pressure, "
          "displacement); N/m in 2-D, N in 3-D", "N/m or N", None, **_N),
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
    Field("cycles", INTEGER, "fretting: after the ramp, this many full cycles +target -> "
          "-target -> +target", "", 0, by=Traction),
), "one tangential segment", "[[program]]", variants={
    "slide": ("velocity", "distance", "duration", "steps", "direction_deg"),
    "reverse": ("velocity", "distance", "steps"),
    "hold": ("duration", Field("steps", INTEGER, "number of steps", "", 5, by=Hold)),
    "traction": ("target", "duration", "steps", "direction_deg", "cycles"),
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
    Field("linear_solver", STRING, "direct (SuperLU) or iterative (GMRES + AMG, pyamg)", "",
          "direct", choices=LINEAR_SOLVERS, **_S),
    Field("memory_limit", NUMBER, "refuse a mesh whose estimated solver storage exceeds it",
          "bytes", None, **_S),
    Field("drive", STRING, "what the tangential programme moves", "", "top", choices=DRIVES),
), "Newton and step control", "[solver]")  # fmt: skip
OUTPUT = Section("output", (
    Field("front_ratio", NUMBER, "|f_t| / F ratio that counts as slipping (the front)", "",
          0.99, low=0, high=1, open="low"),
    Field("fields", BOOL, "write fields/: a ParaView .pvd series of .vtu files (block "
          "displacement and stress, interface tractions) per recorded step", "", False),
), "what is reported", "[output]")  # fmt: skip
CONTACT_FILE = Section("contact", (
    Field("title", STRING, "title of the run", "", ""),
    Field("description", STRING, "free text", "", ""),
    Field("block", table=BLOCK, default=REQUIRED),
    Field("law", table=LAW, default=REQUIRED),
    Field("base", table=BASE),
    Field("normal", table=NORMAL, default=REQUIRED),
    Field("program", table=SEGMENT, many=True, default=REQUIRED),
    Field("solver", table=SOLVER),
    Field("output", table=OUTPUT),
), "A contact scenario of `frictionlab contact`: an elastic [block] pressed and slid on a "
   "rigid [base] through the subloading-friction [law] (mu_s = mu_k = 0: frictionless, "
   "alpha_n only). SI units.")  # fmt: skip


@dataclass(frozen=True)
class ContactScenario:
    """A validated contact scenario and the echo of its inputs with defaults."""

    title: str
    description: str
    block: Block
    params: SubloadingParams | Frictionless
    normal: NormalLoad
    program: tuple[Segment, ...]
    options: SolverOptions
    drive: str
    front_ratio: float
    inputs: dict[str, Any]
    source: str = ""
    base: Base = field(default_factory=Base)
    fields: bool = False


def _segment(data: Any) -> tuple[Segment, dict[str, Any]]:
    values = SEGMENT.read(data)
    kind = values.pop("kind")
    if kind == "slide" and (values["distance"] is None) == (values["duration"] is None):
        raise InputError(f"{data.where}: a slide needs exactly one of distance [m] or duration [s]")
    return reraise(data.where, lambda: _SEG_CLASSES[kind](**values)), {"kind": kind, **values}


def _block(t: Any) -> tuple[Block, dict[str, Any]]:
    echo = BLOCK.read(t)
    if echo["element"] is None:
        echo["element"] = "quad" if echo["depth"] is None else "hex"
    values = dict(echo)
    ref_t = t.table("refinement")
    if ref_t is not None:
        ref = REFINEMENT.read(ref_t)
        values["refinement"] = reraise(ref_t.where, lambda: Refinement(**ref))
        echo["refinement"] = ref
    return reraise("[block]", lambda: Block(**values)), echo


def _law(data: Any) -> tuple[SubloadingParams | Frictionless, dict[str, Any]]:
    """The [law]: mu_s = mu_k = 0 is the frictionless interface (alpha_n only)."""
    given = LAW.read(data, "[law]", only_given=True)
    if given.get("mu_s") == 0 and given.get("mu_k") == 0:
        extra = sorted(set(given) - {"mu_s", "mu_k", "alpha_n"})
        if extra:
            raise InputError(
                f"[law] with mu_s = mu_k = 0 is frictionless: it reads alpha_n only, "
                f"not {', '.join(extra)}"
            )
        if "alpha_n" not in given:
            raise InputError("missing required key [law].alpha_n (frictionless interface)")
        return reraise("[law]", lambda: Frictionless(alpha_n=given["alpha_n"])), given
    params, _ = parse_law_table(data, "[law]")
    echo = {k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in params.as_dict().items()}
    return params, echo


def _normal(t: Any) -> tuple[NormalLoad, dict[str, Any]]:
    echo = NORMAL.read(t)
    given = [k for k in ("pressure", "displacement", "force") if echo[k] is not None]
    if not given:
        raise InputError(
            "missing required key [normal].pressure (or [normal].displacement, [normal].force)"
        )
    if len(given) > 1:
        raise InputError(
            "[normal]: give exactly one of pressure [Pa], displacement [m] or force "
            f"[N/m in 2-D, N in 3-D], not {' and '.join(given)}"
        )
    return reraise("[normal]", lambda: NormalLoad(**echo)), echo


def _check_load(
    law: dict[str, Any], block: Block, params: SubloadingParams | Frictionless, normal: Any
) -> None:
    """Refuse, naming the key, a per-point law and a normal load no linear block can take."""
    if isinstance(params, SubloadingParams) and params.per_point:
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
    if normal.control == "force" and not normal.value / _top_area(block) < block.E:
        raise InputError(
            f"[normal].force = {normal.value:g} N is invalid: allowed a mean pressure below "
            f"[block].E = {block.E:g} Pa over the top face (the block's strain stays below 1)"
        )
    if normal.control == "displacement" and not normal.value < block.height:
        raise InputError(
            f"[normal].displacement = {normal.value:g} m is invalid: allowed less than "
            f"[block].height = {block.height:g} m"
        )


def _top_area(block: Block) -> float:
    """The loaded top face: m^2 in 3-D, m (per metre of depth) in 2-D."""
    return block.width * (block.depth or 1.0)


def parse_contact(
    data: dict[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> ContactScenario:
    """Validate a parsed contact scenario mapping (nothing runs, nothing is meshed)."""
    root = CONTACT_FILE.table(data, "")
    top = CONTACT_FILE.read(root)
    block_t, law_t = root.table("block", required=True), root.table("law", required=True)
    normal_t = root.table("normal", required=True)
    program_ts = root.tables("program", required=True)
    assert block_t is not None and law_t is not None and normal_t is not None
    if not program_ts:
        raise InputError("[[program]] must hold at least one segment")
    block, block_echo = _block(block_t)
    base_echo = BASE.read(root.raw("base", {}), "[base]")
    base = reraise("[base]", lambda: Base(**base_echo))
    reraise("[base]", lambda: base.check_dim(block.dim))
    params, law_echo = _law(law_t.mapping())
    normal, normal_echo = _normal(normal_t)
    parsed = [_segment(t) for t in program_ts]
    program = tuple(seg for seg, _ in parsed)
    solver_echo = SOLVER.read(root.raw("solver", {}), "[solver]")
    solver_values = {k: v for k, v in solver_echo.items() if k != "drive"}
    options = reraise("[solver]", lambda: SolverOptions(**solver_values))
    drive = solver_echo["drive"]
    output_echo = OUTPUT.read(root.raw("output", {}), "[output]")
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
    _check_load(law_t.mapping(), block, params, normal)
    if isinstance(params, SubloadingParams):
        if normal.control == "pressure":
            nominal = normal.value
        elif normal.control == "force":  # over the top face
            nominal = normal.value / _top_area(block)
        else:
            nominal = normal.value * float(params.alpha_n)
        reraise("[law]", lambda: check_snap_back(params, nominal))
        if normal.control != "displacement":  # the mean pressure: some points carry more
            reraise("[law]", lambda: check_normal_capacity(params, nominal))
    reraise("[block]", lambda: check_memory(block, options))
    inputs = {
        "title": top["title"], "description": top["description"], "block": block_echo,
        "base": base_echo, "law": law_echo, "normal": normal_echo,
        "program": [echo for _, echo in parsed], "solver": solver_echo, "output": output_echo,
    }  # fmt: skip
    return ContactScenario(
        title=top["title"], description=top["description"], block=block, params=params,
        normal=normal, program=program, options=options, drive=drive,
        front_ratio=output_echo["front_ratio"], inputs=inputs, source=source, base=base,
        fields=output_echo["fields"],
    )  # fmt: skip


def load_contact(path: str | os.PathLike[str], overrides: Sequence[str] = ()) -> ContactScenario:
    """Read, override (``section.key=value``) and validate a contact scenario file."""
    return load(CONTACT_FILE, parse_contact, path, overrides)
