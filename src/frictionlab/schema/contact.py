"""The ``frictionlab contact`` scenario: declarations and the parser.

``[block]`` (the elastic block), ``[law]`` (as in simulate), ``[normal]`` (the normal
stage), ``[[program]]`` (kind = slide | reverse | hold | traction), optional
``[solver]`` and ``[output]``. Everything is validated before anything is meshed.
"""

from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.contact.block import ELEMENTS, INTEGRATIONS, Block, Refinement
from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.imported import MeshSource, mesh_block
from frictionlab.contact.interface import TANGENTS
from frictionlab.contact.law_field import FIELD_KEYS, PAIR_KEYS, LawField, LawRegion, LawTable
from frictionlab.contact.linear import LINEAR_SOLVERS
from frictionlab.contact.loading import Hold, NormalLoad, Reverse, Segment, Slide, Traction
from frictionlab.contact.shapes import Base
from frictionlab.contact.solver import DRIVES, SolverOptions, check_memory
from frictionlab.errors import InputError
from frictionlab.io.config import load_toml
from frictionlab.io.mesh_files import read_mesh
from frictionlab.io.tables import read_csv
from frictionlab.schema.core import REQUIRED, Field, Section, loader, reraise, run_file
from frictionlab.schema.kinds import BOOL, INTEGER, NUMBER, PAIRS, STRING, listed
from frictionlab.schema.scenario import LAW, parse_law_table, per_point, radians
from frictionlab.subloading import SubloadingParams, check_normal_capacity, check_snap_back

__all__ = [
    "CONTACT_FILE", "ContactScenario", "load_contact", "mesh_keys", "parse_contact",
]  # fmt: skip

_R: dict[str, Any] = {"by": Refinement}
REFINEMENT = Section("refinement", (
    Field("size", NUMBER, "element size near the contact", "m", REQUIRED, **_R),
    Field("extent", NUMBER, "half-width (and depth) of the fine zone", "m", REQUIRED, **_R),
    Field("center", listed(float, "number", (1, 2)), "in-plane centre of the fine zone: x "
          "(2-D) or [x, y] (3-D); default the middle of the bottom", "m", None, **_R),
    Field("growth", NUMBER, "size ratio of neighbouring elements outside it", "", 1.2, **_R),
), "a graded mesh, fine near the contact", "[block.refinement]", by=Refinement)  # fmt: skip
_B: dict[str, Any] = {"by": Block}
BLOCK = Section("block", (
    Field("E", NUMBER, "Young's modulus", "Pa", REQUIRED, **_B),
    Field("nu", NUMBER, "Poisson's ratio", "-", REQUIRED, **_B),
    Field("width", NUMBER, "block width (x); required unless [mesh]", "m", None, **_B),
    Field("height", NUMBER, "block height (y); required unless [mesh]", "m", None, **_B),
    Field("element_size", NUMBER, "element edge length; required unless [mesh]", "m", None,
          **_B),
    Field("depth", NUMBER, "block depth (z): gives a 3-D block", "m", None, **_B),
    Field("element", STRING, "element (default quad in 2-D, hex in 3-D)", choices=ELEMENTS, **_B),
    Field("integration", STRING, "full, or selective (one-point volumetric part: no locking as nu "
          "-> 1/2)", "", "full", choices=INTEGRATIONS, **_B),
    Field("refinement", table=REFINEMENT),
), "the elastic block", "[block]", by=Block)  # fmt: skip
BASE = Section("base", (
    Field("shape", STRING, "the rigid base: flat, cylinder (2-D) or sphere (3-D)", "", "flat",
          choices=("flat", "cylinder", "sphere"), by=Base),
    Field("radius", NUMBER, "radius of a cylinder or sphere", "m", None, by=Base),
    Field("center", listed(float, "number", (1, 2)), "in-plane apex position: x (2-D) or "
          "[x, y] (3-D); default the middle of the bottom", "m", None, by=Base),
), "the rigid base's shape (a profile base is Python only: contact.shapes.Base)",
   "[base]", by=Base)  # fmt: skip
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
), "the normal stage", "[normal]", by=NormalLoad,
   one_of=(("pressure", "displacement", "force"),))  # fmt: skip
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
    Field("cycles", INTEGER, "full load cycles after the ramp, +target -> -target -> "
          "+target (0: one ramp to the target)", "", 0, by=Traction),
), "one tangential segment", "[[program]]", variants={
    "slide": ("velocity", "distance", "duration", "steps", "direction_deg"),
    "reverse": ("velocity", "distance", "steps"),
    "hold": ("duration", Field("steps", INTEGER, "number of steps", "", 5, by=Hold)),
    "traction": ("target", "duration", "steps", "direction_deg", "cycles"),
}, required_by={"slide": ("velocity",), "hold": ("duration",),
                "traction": ("target", "duration")}, ref=True, by=_SEG_CLASSES,
   one_of=(("distance", "duration"),))  # fmt: skip
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
), "Newton and step control", "[solver]", by=SolverOptions)  # fmt: skip
OUTPUT = Section("output", (
    Field("front_ratio", NUMBER, "|f_t| / F ratio that counts as slipping (the front)", "",
          0.99, low=0, high=1, open="low"),
    Field("fields", BOOL, "write fields/: a ParaView .pvd series of .vtu files (block "
          "displacement and stress, interface tractions) per recorded step", "", False),
), "what is reported", "[output]")  # fmt: skip
MESH = Section("mesh", (
    Field("file", STRING, "mesh file read by meshio: gmsh .msh (2.2, 4.1), Abaqus .inp, ...; "
          "one family of linear quads, triangles (2-D) or hexahedra (3-D)", "", REQUIRED),
    Field("contact", STRING, "named group (gmsh physical group, Abaqus set) of the flat "
          "face on the rigid base, at the lowest y (2-D) or z (3-D)", "", REQUIRED),
    Field("loaded", STRING, "named group of the faces that carry the normal load and the "
          "tangential programme", "", REQUIRED),
    Field("fixed", listed(str, "string"), "named groups held at zero displacement", "", []),
), "an imported mesh instead of the box of [block] ([block] then gives E, nu and "
   "integration only)", "[mesh]")  # fmt: skip
_PAIR = listed(float, "number", 2)
LAW_TABLE = Section("law_table", tuple(
    Field(key, STRING, f"CSV file of {key} along the interface: columns x [m] (2-D) or x, y "
          f"[m] (3-D) and {key}; linearly interpolated onto the contact points", LAW[key].unit)
    for key in (*FIELD_KEYS, "orthotropy_angle_deg")
), "law parameters varying along the interface, from tables (applied before the "
   "regions)", "[law_table]", exclusive=LAW.exclusive)  # fmt: skip
LAW_REGION = Section("law_region", (
    Field("x", _PAIR, "x range [from, to] of the region (closed; default all)", "m", None),
    Field("y", _PAIR, "y range [from, to] of the region, 3-D (closed; default all)", "m",
          None),
    Field("group", STRING, "a named group of the [mesh]: the contact points whose facet "
          "lies in it (with x, y: the intersection)", "", None),
    Field("bridge", STRING, "a `frictionlab bridge` fitted_law.toml: its anisotropy "
          "(rotation, orthotropy, orthotropy angle) in this region", "", None),
    *(dataclasses.replace(LAW[key], kind=_PAIR if LAW[key].kind is PAIRS else NUMBER,
                          per_point=False, default=None)  # default: the [law]'s value
      for key in (*FIELD_KEYS, "orthotropy_angle_deg", *PAIR_KEYS)),
), "a part of the interface with its own law values (later regions override earlier "
   "ones; keys given here override the bridge's)", "[[law_region]]", ref=True,
   exclusive=LAW.exclusive)  # fmt: skip
CONTACT_FILE = run_file("contact", (
    Field("block", table=BLOCK, default=REQUIRED),
    Field("mesh", table=MESH),
    Field("law", table=LAW, default=REQUIRED),
    Field("law_table", table=LAW_TABLE),
    Field("law_region", table=LAW_REGION, many=True),
    Field("base", table=BASE),
    Field("normal", table=NORMAL, default=REQUIRED),
    Field("program", table=SEGMENT, many=True, default=REQUIRED),
    Field("solver", table=SOLVER),
    Field("output", table=OUTPUT),
), "A contact scenario of `frictionlab contact`: an elastic [block] pressed and slid on a "
   "rigid [base] through the subloading-friction [law] (mu_s = mu_k = 0: frictionless, "
   "alpha_n only). SI units.", extra={
       "if": {"not": {"required": ["mesh"]}},
       "then": {"properties": {"block": {"required": ["width", "height", "element_size"]}}},
   })  # fmt: skip


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
    mesh: MeshSource | None = None
    law_field: LawField = field(default_factory=LawField)


_BOX_KEYS = ("width", "height", "element_size")


def _block(t: Any, mesh: MeshSource | None = None) -> tuple[Block, dict[str, Any]]:
    echo = BLOCK.read(t)
    if mesh is not None:  # the box comes from the mesh file
        given = [k for k in (*_BOX_KEYS, "depth", "element") if echo[k] is not None]
        given += ["refinement"] if t.table("refinement") is not None else []
        if given:
            raise InputError(
                f"[block].{given[0]} is set by [mesh].file: with [mesh], [block] reads E, nu "
                "and integration only"
            )
        block = mesh_keys(lambda: mesh_block(
            mesh.mesh, E=echo["E"], nu=echo["nu"], integration=echo["integration"]))  # fmt: skip
        return block, {k: echo[k] for k in ("E", "nu", "integration")}
    for key in _BOX_KEYS:
        if echo[key] is None:
            raise InputError(f"missing required key [block].{key} (or give a [mesh])")
    if echo["element"] is None:
        echo["element"] = "quad" if echo["depth"] is None else "hex"
    values = dict(echo)
    ref_t = t.table("refinement")
    if ref_t is not None:
        values["refinement"], echo["refinement"] = REFINEMENT.build(ref_t)
    return reraise("[block]", lambda: Block(**values)), echo


def mesh_keys(call: Any) -> Any:
    """Run ``call``; name a ParameterError's key as [mesh].key (mesh.*) or [block].key."""
    return reraise(lambda k: f"[mesh].{k[5:]}" if k.startswith("mesh.") else f"[block].{k}", call)


def _mesh(data: Any, base_dir: Path) -> tuple[MeshSource, dict[str, Any]]:
    """[mesh]: read the file and check its cells and named groups (nothing assembled)."""
    echo = MESH.read(data, "[mesh]")
    path = base_dir / echo["file"]
    try:
        mesh = read_mesh(path)
    except InputError as exc:
        raise InputError(f"[mesh].file = {echo['file']!r}: {exc}") from None
    source = mesh_keys(lambda: MeshSource.of(
        str(path), mesh, echo["contact"], echo["loaded"], echo["fixed"]))  # fmt: skip
    return source, echo


def _check_field(where: str, params: SubloadingParams, values: dict[str, Any]) -> None:
    """The law with ``values`` (a region's or a table's samples) must be a valid law."""
    call = lambda: params.replace(**values, orthotropy_convention="divide")  # noqa: E731
    reraise(where, call, InputError, ": with the [law] values, ")


def _law_tables(
    data: Any, params: SubloadingParams, dim: int, base_dir: Path
) -> tuple[list[LawTable], dict[str, Any]]:
    """[law_table]: the CSV tables read and checked, and the keys given."""
    given = LAW_TABLE.read(data, "[law_table]", only_given=True)
    axes = ("x",) if dim == 2 else ("x", "y")
    out = []
    for key, name in given.items():
        where = f"[law_table].{key} = {name!r}"
        try:
            table = read_csv(base_dir / name)
        except InputError as exc:
            raise InputError(f"{where}: {exc}") from None
        wanted = (*axes, key)
        missing = [c for c in wanted if c not in table]
        if missing or (dim == 2 and "y" in table):
            raise InputError(
                f"{where}: allowed a table with the columns {', '.join(wanted)} "
                f"(this one has {', '.join(table)}) for a {dim}-D block"
            )
        for column in wanted:
            values = table[column]
            if np.ma.isMaskedArray(values) or values.dtype == object:
                raise InputError(f"{where}: column {column} has empty or non-numeric cells")
            unit = table.units.get(column)
            if column in axes and unit not in (None, "m"):
                raise InputError(f"{where}: column {column} is in [{unit}]; allowed [m]")
        values = np.asarray(table[key], dtype=np.float64)
        stored = key
        if key == "orthotropy_angle_deg":
            stored, values = "orthotropy_angle", np.radians(values)
        if getattr(params, stored) is None:
            raise InputError(f"{where}: {key} is not a parameter of surface '{params.surface}'")
        points = np.column_stack([table[c] for c in axes])
        law_table = LawTable(stored, points, values, source=f"[law_table].{key} ({name!r})")
        _check_field(where, params, {stored: law_table.values})
        out.append(law_table)
    return out, given


def _bridge_anisotropy(where: str, name: str, params: SubloadingParams,
                       base_dir: Path) -> dict[str, Any]:  # fmt: skip
    """rotation, orthotropy and orthotropy_angle of a bridge run's fitted_law.toml."""
    data = load_toml(base_dir / name)
    if not isinstance(data.get("law"), dict):
        raise InputError(f"{where}.bridge = {name!r}: no [law] table (a fitted_law.toml "
                         "written by `frictionlab bridge`)")  # fmt: skip
    fitted, _ = parse_law_table(data["law"], f"{where}.bridge [law]")
    if fitted.surface != params.surface or fitted.per_point:
        raise InputError(
            f"{where}.bridge = {name!r}: its law has surface '{fitted.surface}'"
            f"{' and per-point values' if fitted.per_point else ''}; allowed one law of "
            f"the [law]'s surface '{params.surface}'"
        )
    return {
        "rotation": np.asarray(fitted.rotation).tolist(),
        "orthotropy": np.asarray(fitted.orthotropy).tolist(),
        "orthotropy_angle": float(fitted.orthotropy_angle),
    }


def _law_regions(
    tables: list[Any],
    params: SubloadingParams,
    dim: int,
    base_dir: Path,
    multiply: bool,
    mesh: MeshSource | None,
) -> tuple[list[LawRegion], list[dict[str, Any]]]:
    regions, echoes = [], []
    for t in tables:
        where = t.where
        echo = LAW_REGION.read(t, where, only_given=True)
        values = {k: v for k, v in echo.items() if k not in ("x", "y", "bridge", "group")}
        if "group" in echo:
            if mesh is None:
                raise InputError(f"{where}.group needs a [mesh] (its named groups)")
            reraise(where, partial(mesh.check_group, echo["group"]))  # names .group
        if "bridge" in echo:
            values = {**_bridge_anisotropy(where, echo["bridge"], params, base_dir), **values}
        values = radians(values)
        if multiply and "orthotropy" in echo:  # the [law]'s convention, stored as "divide"
            values["orthotropy"] = [c**-0.5 for c in echo["orthotropy"]]
        if not values:
            raise InputError(f"{where}: give at least one law value (or bridge)")
        if dim == 2 and "y" in echo:
            raise InputError(f"{where}.y is for a 3-D block; a 2-D region is an x range")
        for key in values:
            if getattr(params, key) is None:
                raise InputError(f"{where}.{key} is not a parameter of surface "
                                 f"'{params.surface}'")  # fmt: skip
        region = LawRegion(values, x=echo.get("x"), y=echo.get("y"), group=echo.get("group"),
                           name=where)  # fmt: skip
        _check_field(where, params, dict(values))
        regions.append(region)
        echoes.append({**echo, **{k: v for k, v in values.items() if k not in echo}})
    return regions, echoes


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


def _law_field(
    tables: dict[str, Any],
    params: SubloadingParams | Frictionless,
    dim: int,
    base_dir: Path,
    law_t: Any,
    mesh: MeshSource | None = None,
) -> tuple[LawField, dict[str, Any]]:
    """[law_table] and [[law_region]]: the law's values along the interface."""
    table_data, region_ts = tables["law_table"], tables["law_region"] or []
    if table_data is None and not region_ts:
        return LawField(), {}
    if not isinstance(params, SubloadingParams):
        key = "[law_table]" if table_data is not None else "[[law_region]]"
        raise InputError(f"{key} needs a law with friction; the [law] is frictionless")
    if params.per_point:
        raise InputError("[law] takes one value per key when [law_table] or [[law_region]] "
                         "vary it along the interface")  # fmt: skip
    multiply = law_t.mapping().get("orthotropy_convention") == "multiply"
    law_tables, table_echo = _law_tables(table_data or {}, params, dim, base_dir)
    regions, region_echo = _law_regions(region_ts, params, dim, base_dir, multiply, mesh)
    echo: dict[str, Any] = {"law_table": table_echo} if table_data is not None else {}
    if regions:
        echo["law_region"] = region_echo
    return LawField(tuple(law_tables), tuple(regions)), echo


def _check_load(
    law: dict[str, Any], block: Block, params: SubloadingParams | Frictionless, normal: Any
) -> None:
    """Refuse, naming the key, a per-point law and a normal load no linear block can take."""
    if isinstance(params, SubloadingParams) and params.per_point:
        key = next((k for _, k, _ in per_point(law)), "law")
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
    top, tables = CONTACT_FILE.read_top(data)
    law_t = tables["law"]
    mesh, mesh_echo = None, None
    if tables["mesh"] is not None:
        mesh, mesh_echo = _mesh(tables["mesh"], Path(base_dir))
    block, block_echo = _block(tables["block"], mesh)
    base, base_echo = BASE.build(tables["base"] or {})
    reraise("[base]", lambda: base.check_dim(block.dim))
    params, law_echo = _law(law_t.mapping())
    law_field, field_echo = _law_field(tables, params, block.dim, Path(base_dir), law_t, mesh)
    normal, normal_echo = NORMAL.build(tables["normal"])
    parsed = [SEGMENT.build(t) for t in tables["program"]]
    program = tuple(seg for seg, _ in parsed)
    options, solver_echo = SOLVER.build(tables["solver"] or {}, drop=("drive",))
    drive = solver_echo["drive"]
    output_echo = OUTPUT.read(tables["output"] or {})
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
            for region in law_field.regions:  # a region's own F_k, named with its key
                if "F_k" in region.values:
                    local = params.replace(F_k=region.values["F_k"])
                    reraise(region.name, partial(check_normal_capacity, local, nominal))
    reraise("[block]", lambda: check_memory(block, options))
    inputs = {
        "title": top["title"], "description": top["description"], "block": block_echo,
        "base": base_echo, "law": law_echo, "normal": normal_echo,
        "program": [echo for _, echo in parsed], "solver": solver_echo, "output": output_echo,
        **({"mesh": mesh_echo} if mesh_echo is not None else {}), **field_echo,
    }  # fmt: skip
    return ContactScenario(
        title=top["title"], description=top["description"], block=block, params=params,
        normal=normal, program=program, options=options, drive=drive,
        front_ratio=output_echo["front_ratio"], inputs=inputs, source=source, base=base,
        fields=output_echo["fields"], mesh=mesh, law_field=law_field,
    )  # fmt: skip


load_contact = loader(CONTACT_FILE, parse_contact, "a contact scenario file")
