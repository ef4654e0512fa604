"""The ``frictionlab roughness`` scenario: declarations and the parser.

``mu0``, two surfaces ``[lower]`` (fixed) and ``[upper]`` (sliding), ``[sliding]`` and
optional ``[lattice]``, ``[output]``, ``[adhesion]`` (Eqs 21-22), ``[wear]`` (Eqs
23-28w), ``[hierarchy]`` (Eq 28) and ``[multiscale]``. Lengths in m, angles in degrees.
Surface kinds: flat, wedge, smooth_wedge, sinusoid, self_affine, file (a measured map
read through SurfaceTopography; its array's first axis is x).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.app.budget import check_grid_size
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import Table
from frictionlab.roughness import generators
from frictionlab.roughness.elastic import ElasticSettings
from frictionlab.roughness.hierarchy import (
    MU_PASSED,
    ON_INVALID,
    HierarchyLevel,
    check_nested,
    self_similar_levels,
)
from frictionlab.roughness.lattice import (
    CONTROLS,
    ENGINES,
    FULL_CONTACT_METHODS,
    MU_DEFINITIONS,
    TRAVEL_MODES,
    LatticeSettings,
    lattice_geometry,
)
from frictionlab.roughness.surface import HeightMap, Surface
from frictionlab.roughness.topography import (
    DETREND_MODES,
    PERIODICITY_MODES,
    RESAMPLE_MODES,
    read_prepared,
)
from frictionlab.roughness.wear import WEAR_METHODS, WEAR_SURFACES, WearSettings
from frictionlab.schema.core import REQUIRED, TITLE, Field, Section, loader, reraise
from frictionlab.schema.kinds import BOOL, INTEGER, NUMBER, STRING, Kind, choice, either, listed

__all__ = [
    "ROUGHNESS_FILE", "SURFACE", "SURFACE_KINDS", "AdhesionOptions", "HierarchyOptions",
    "MultiscaleOptions", "RoughnessScenario", "WearOptions", "load_roughness",
    "parse_roughness",
]  # fmt: skip

SURFACE_KINDS = ("flat", "wedge", "smooth_wedge", "sinusoid", "self_affine", "file")
MAX_DIRECTIONS = 3601
#: [sliding].on_invalid in the TOML -> LatticeSettings.on_invalid ("mask": deprecated)
ON_INVALID_KEYS = {"error": "error", "drop": "drop", "mask": "drop"}
#: Old spellings accepted for one release: (section, value) -> (meaning, terminal note)
_OLD_ON_INVALID = {
    ("sliding", "mask"): ("drop", '[sliding].on_invalid = "mask" is deprecated: it drops the '
                          'contacts violating Eq 1, as before; write "drop" ("mask" will mark '
                          "the direction invalid, as in Python)"),
    ("hierarchy", "raise"): ("error", '[hierarchy].on_invalid = "raise" is deprecated: write '
                             '"error" (the same meaning)'),
}  # fmt: skip


def _on_invalid(section: str, value: str, notes: dict[str, Any]) -> str:
    """The meaning of a TOML ``on_invalid``; an old spelling adds a terminal note."""
    if (section, value) in _OLD_ON_INVALID:
        value, note = _OLD_ON_INVALID[section, value]
        notes.setdefault("warnings", []).append(note)
    return value


def _spread(end: Field, what: str) -> Kind:
    """Values as a list (directions: or one number) or as a table {start, stop, ``last``}
    (``step`` or ``count``), at most MAX_DIRECTIONS of them."""
    last = end.name
    many = listed(float, "number", scalar=last == "step", count=(1, MAX_DIRECTIONS))
    ends = (Field("start", NUMBER, default=REQUIRED), Field("stop", NUMBER, default=REQUIRED))
    rng = Section("range", (*ends, end))

    def read(t: Table, f: Field) -> np.ndarray:
        name = f"{t.where}.{f.name}"
        if not isinstance(t.raw(f.name), dict):
            return np.array(many.read(t, f), dtype=np.float64)
        v = rng.read(t.raw(f.name), name)
        start, stop, by = v["start"], v["stop"], v[last]
        if last == "count" and by == 1 and start != stop:
            raise InputError(f"{name}: count = 1 needs start == stop")
        if last == "count":
            return np.linspace(start, stop, by)
        if stop < start:
            raise InputError(f"{name}: stop = {stop:g} is below start = {start:g}")
        count = math.floor((stop - start) / by * (1.0 + 1e-12) + 1e-9) + 1
        if count > MAX_DIRECTIONS:
            raise InputError(f"{name} has {count} {what}: allowed at most {MAX_DIRECTIONS}")
        return start + by * np.arange(count)

    return Kind(what, read, {"oneOf": [*many.json.get("oneOf", [many.json]), rng.schema()]})


DIRECTIONS = _spread(Field("step", NUMBER, default=REQUIRED, low=0, open="low"), "directions")
LOADS = _spread(Field("count", INTEGER, default=REQUIRED, low=1), "loads")
_BETA = Field("beta_deg", DIRECTIONS, "directions (default: [sliding].beta_deg)", "deg")
_POS: dict[str, Any] = {"low": 0.0, "open": "low", "allowed": "a positive value (SI units)"}
CONTACT_MODELS = ("lattice", "elastic")
SIDES = ("lower", "upper")


_SIZES = Field("physical_sizes", listed(float, "number", (1, 2)), "period along x (and y)", "m")
SURFACE = Section("surface", (
    Field("kind", STRING, "surface kind", "", REQUIRED, choices=SURFACE_KINDS),
    Field("angles_deg", listed(float, "number", (1, 2)), "rising, falling flank angles", "deg",
          low=0, high=90, open="both", allowed="0 < angle < 90 degrees"),
    Field("wavelength", NUMBER, "period of the wedges", "m", **_POS),
    Field("amplitude", NUMBER, "amplitude of the sinusoid", "m", **_POS),
    Field("wavelengths", listed(float, "number", (1, 2)), "one (1-D) or two (2-D) periods", "m"),
    Field("hurst", NUMBER, "Hurst exponent", "", low=0, high=1, open="low",
          allowed="0 < hurst <= 1"),
    _SIZES,
    Field("points", listed(int, "integer", (1, 2)), "grid points (same count as sizes)"),
    Field("allow_large", BOOL, "allow grids beyond half the machine's memory", "", False),
    Field("seed", INTEGER, "random seed", "", low=0),
    Field("rms_height", NUMBER, "rms height (or rms_slope)", "m", **_POS),
    Field("rms_slope", NUMBER, "rms slope (or rms_height)", "", **_POS),
    Field("short_cutoff", NUMBER, "shortest wavelength kept", "m", **_POS),
    Field("long_cutoff", NUMBER, "longest wavelength kept", "m", **_POS),
    Field("path", STRING, "the topography file (relative to the scenario)"),
    Field("periodicity", STRING, "how the map is made periodic", choices=PERIODICITY_MODES),
    Field("detrend", STRING, "trend removed from the map", choices=DETREND_MODES),
    Field("fill_missing", BOOL, "fill missing points", "", False),
    Field("gradient", STRING, "slope computation", "", "fd", choices=("fd", "spectral")),
    Field("format", STRING, "file format (default: detected)", "", None),
    Field("channel", INTEGER, "data channel of the file", "", None),
    Field("unit", STRING, "length unit of files without one", "", None),
    Field("crop", listed(float, "number", (2, 4)), "[x0, x1, y0, y1]", "m", None),
    Field("window", STRING, "window applied before filtering (e.g. hann)", "", None),
    Field("allow_flattening", BOOL, "accept a preparation keeping < 1 % of the rms height or "
          "slope", "", False),
    Field("resample", either(choice(*RESAMPLE_MODES), INTEGER),
          "non-uniform line scans: median | finest | a number of points", "", None),
), "one rough surface", variants={
    "flat": (),
    "wedge": ("angles_deg", "wavelength"),
    "smooth_wedge": ("angles_deg", "wavelength"),
    "sinusoid": ("amplitude", "wavelengths"),
    "self_affine": ("hurst", "physical_sizes", "points", "allow_large", "seed", "rms_height",
                    "rms_slope", "short_cutoff", "long_cutoff"),
    "file": ("path", "periodicity", "detrend", "fill_missing", "gradient", "format", "channel",
             "unit", Field("physical_sizes", _SIZES.kind, "scan size along x (and y), in "
             "`unit` (files without sizes)", "unit", low=0, open="low",
             allowed="sizes > 0 in `unit`"), "crop", "window",
             "short_cutoff", "long_cutoff", "allow_flattening", "resample"),
}, required_by={
    "wedge": ("angles_deg", "wavelength"), "smooth_wedge": ("angles_deg", "wavelength"),
    "sinusoid": ("amplitude", "wavelengths"),
    "self_affine": ("hurst", "physical_sizes", "points", "seed"),
    "file": ("path", "periodicity", "detrend"),
}, ref=True)  # fmt: skip
_L: dict[str, Any] = {"by": LatticeSettings}
SLIDING = Section("sliding", (
    Field("beta_deg", DIRECTIONS, "sliding directions: one value, a list or {start, stop, "
          "step}", "deg", REQUIRED),
    Field("load", either(choice("full"), NUMBER), "'full' contact or the mean force per "
          "spring", "N", "full", **_L),
    Field("control", STRING, "what is held: the load or the separation", "", "load",
          choices=CONTROLS, **_L),
    Field("separation", NUMBER, "separation c (control = separation)", "m", **_L),
    Field("phase", listed(float, "number", 2), "initial offset of the upper surface", "m", **_L),
    Field("on_invalid", STRING, "contacts violating Eq 1: error, or drop them (report their "
          'fraction); "mask" is a deprecated spelling of "drop" here', "", "error",
          choices=tuple(ON_INVALID_KEYS)),
), "how the upper surface slides", "[sliding]")  # fmt: skip
LATTICE = Section("lattice", (
    Field("stations", either(listed(int, "integer", (1, 2)), INTEGER), "lattice stations "
          "(or [nx, ny])", **_L),
    Field("time_samples", INTEGER, "time samples of the travel", **_L),
    Field("max_return_periods", INTEGER, "most periods travelled before the return", **_L),
    Field("k_c", NUMBER, "spring stiffness in compression", "N/m", **_L),
    Field("k_t", NUMBER, "spring stiffness in tension", "N/m", **_L),
    Field("travel", either(choice(*TRAVEL_MODES), NUMBER),
          "auto | return | ergodic | a length", "m", **_L),
    Field("mu_definition", STRING, "mu as magnitude or projection", choices=MU_DEFINITIONS, **_L),
    Field("engine", STRING, "kernel engine", choices=ENGINES, **_L),
    Field("full_contact", STRING, "load = full: area average or lattice",
          choices=FULL_CONTACT_METHODS, **_L),
    Field("snap_time_samples", BOOL, "time samples moved to whole-station shifts", **_L),
    Field("shift_invariance", BOOL, "a flat counter-face takes one time sample", **_L),
), "lattice settings (LatticeSettings)", "[lattice]")  # fmt: skip
OUTPUT = Section("output", (
    Field("plot_full_circle", BOOL, "compute extra directions for the full-circle plot", "",
          True),
    Field("plot_step_deg", NUMBER, "step of those directions", "deg", 5.0, low=0, high=90,
          open="low", allowed="0 < step <= 90"),
    Field("statistics", BOOL, "write the sampled surfaces' statistics (CSV, PNG)", "", False),
), "figures", "[output]")  # fmt: skip
_E: dict[str, Any] = {"by": ElasticSettings}  # > 0 (hardness > pressure): ElasticSettings checks
CONTACT = Section("contact", (
    Field("model", listed(str, "string", scalar=True, unique=True, count=(1, 2)), "load "
          "distribution: 'lattice' (the paper's springs), 'elastic' (half-space, BEM) or both "
          "as a list (a comparison)", "", ("lattice",), choices=CONTACT_MODELS),
    Field("pressure", listed(float, "number", scalar=True, unique=True, count=(1, MAX_DIRECTIONS)),
          "nominal mean pressure; a list gives a load sweep", "Pa", None,
          **{**_POS, "allowed": "a positive value (Pa)"}),
    Field("modulus", NUMBER, "effective contact modulus E* (elastic)", "Pa", None, **_E),
    Field("hardness", NUMBER, "optional cap on the local pressure (elastic)", "Pa", None, **_E),
    Field("stiffness_per_area", NUMBER, "the lattice at a pressure: spring stiffness per "
          "nominal area, k_c / station area; load per spring = pressure k_c / "
          "stiffness_per_area", "Pa/m", None, **_POS),
), "the load distribution (roughness.elastic)", "[contact]")  # fmt: skip
ADHESION = Section("adhesion", (
    Field("loads", LOADS, "loads per spring: a list or {start, stop, count}", "N", REQUIRED),
    Field("k_t", NUMBER, "tensile spring stiffness, 0 <= k_t <= k_c (default k_c / 2)", "N/m",
          None),
    Field("detachment", NUMBER, "cut-off elongation (default: never detach)", "m", None,
          low=0, open="low", allowed="a cut-off elongation > 0 m"),
    _BETA,
    Field("compare_without_adhesion", BOOL, "also run without tensile springs", "", True),
), "load sweep with tensile springs (Eqs 21-22)", "[adhesion]")  # fmt: skip
_W: dict[str, Any] = {"default": REQUIRED, "by": WearSettings}  # > 0: WearSettings checks
WEAR = Section("wear", (
    Field("wear_coefficient", NUMBER, "Archard K", "-", **_W),
    Field("hardness", NUMBER, "hardness", "Pa", **_W),
    Field("normal_load", NUMBER, "force on the nominal area", "N", **_W),
    Field("velocity", NUMBER, "sliding velocity", "m/s", **_W),
    Field("nominal_area", NUMBER, "nominal contact area", "m^2", **_W),
    Field("surfaces", STRING, "which surfaces wear", "", "both", choices=WEAR_SURFACES),
    Field("samples", INTEGER, "times from 0 to T_w", "", 21, low=2),
    Field("method", STRING, "how the worn polar is computed", "", "auto", choices=WEAR_METHODS),
    _BETA,
), "Archard wear, mu(t) (Eqs 23-28w)", "[wear]", by=WearSettings)  # fmt: skip
LEVEL = Section("level", (
    Field("lower", table=SURFACE, default=REQUIRED),
    Field("upper", table=SURFACE, default=REQUIRED),
), "one inner level (innermost first)")  # fmt: skip
HIERARCHY = Section("hierarchy", (
    Field("levels", INTEGER, "self-similar levels (Eq 28; with ratio)", "", None, low=1),
    Field("ratio", NUMBER, "scale factor between levels", "", None, low=1, open="low",
          allowed="a scale factor > 1"),
    Field("inner", table=LEVEL, many=True, doc="inner levels (instead of levels, ratio)"),
    Field("mu_passed", STRING, "mu passed between levels", "", "magnitude", choices=MU_PASSED),
    Field("on_invalid", STRING, "contacts violating Eq 1: error, or mask the level and those "
          'above ("raise": deprecated)', "", "error", choices=(*ON_INVALID, "raise")),
    Field("samples_per_level", INTEGER, "hierarchy with [wear]: times per level window", "",
          11, low=2),
    _BETA,
), "hierarchical roughness: [lower]/[upper] are the outermost level", "[hierarchy]",
   one_of=(("levels", "inner"), ("ratio", "inner")))  # fmt: skip
MULTISCALE = Section("multiscale", (
    Field("cutoffs", listed(float, "number", unique=True, count=(1, None)), "band edges: "
          "wavelengths (any order, distinct)", "m", REQUIRED, low=0, open="low"),
    Field("mu_passed", STRING, "mu passed between bands", "", "magnitude", choices=MU_PASSED),
    _BETA,
), "scale-resolved friction (sampled surfaces)", "[multiscale]")  # fmt: skip
_TOP = (
    Field("mu0", NUMBER, "local Coulomb coefficient", "-", REQUIRED, low=0, open="low",
          allowed="a local friction coefficient mu0 > 0"),
    TITLE,
    Field("lower", table=SURFACE, default=REQUIRED, doc="surface 1, fixed"),
    Field("upper", table=SURFACE, default=REQUIRED, doc="surface 2, sliding"),
    Field("sliding", table=SLIDING, default=REQUIRED),
    Field("lattice", table=LATTICE),
)  # fmt: skip
ROUGHNESS_FILE = Section("roughness", (
    *_TOP,
    Field("output", table=OUTPUT),
    Field("adhesion", table=ADHESION),
    Field("wear", table=WEAR),
    Field("hierarchy", table=HIERARCHY),
    Field("multiscale", table=MULTISCALE),
    Field("contact", table=CONTACT),
), "A roughness scenario of `frictionlab roughness`: two surfaces slid over each other on the "
   "lattice-spring model. Lengths in m, angles in degrees.")  # fmt: skip


@dataclass(frozen=True)
class AdhesionOptions:
    """The ``[adhesion]`` table: loads per spring (N), k_t (N/m; None: k_c / 2), directions."""

    loads: np.ndarray
    k_t: float | None
    beta_deg: np.ndarray
    compare_without_adhesion: bool
    detachment: float | None = None


@dataclass(frozen=True)
class WearOptions:
    """The ``[wear]`` table: Archard inputs, number of times, method, directions."""

    settings: WearSettings
    samples: int
    method: str
    beta_deg: np.ndarray


@dataclass(frozen=True)
class HierarchyOptions:
    """The ``[hierarchy]`` table: levels (innermost first), options, directions."""

    levels: tuple[HierarchyLevel, ...]
    mu_passed: str
    on_invalid: str
    samples_per_level: int
    beta_deg: np.ndarray


@dataclass(frozen=True)
class MultiscaleOptions:
    """The ``[multiscale]`` table: band edges (wavelengths, m, descending), directions."""

    cutoffs: tuple[float, ...]
    beta_deg: np.ndarray
    mu_passed: str


@dataclass(frozen=True)
class RoughnessScenario:
    """A parsed scenario: surfaces, directions (deg), lattice settings, output options."""

    mu0: float
    lower: Surface
    upper: Surface
    beta_deg: np.ndarray
    settings: LatticeSettings
    title: str = ""
    plot_full_circle: bool = True
    plot_step_deg: float = 5.0
    adhesion: AdhesionOptions | None = None
    wear: WearOptions | None = None
    hierarchy: HierarchyOptions | None = None
    sources: dict[str, dict[str, Any]] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    multiscale: MultiscaleOptions | None = None
    contact: ElasticSettings | None = None
    statistics: bool = False
    models: tuple[str, ...] = ("lattice",)
    pressures: tuple[float, ...] = ()
    stiffness_per_area: float | None = None

    @property
    def compares(self) -> bool:
        """Several models or several pressures (the comparison and sweep files)."""
        return len(self.models) > 1 or len(self.pressures) > 1

    def lattice_load(self, pressure: float) -> float:
        """The lattice's mean force per spring (N) at a nominal pressure (Pa).

        A spring of stiffness k_c stands for the station area A, so the foundation's
        stiffness per area is k = k_c / A and the mean force per spring L = p A =
        p k_c / k: the mean spring compression L / k_c = p / k does not depend on the
        station grid.
        """
        assert self.stiffness_per_area is not None
        return pressure * self.settings.k_c / self.stiffness_per_area

    def elastic(self, pressure: float) -> ElasticSettings:
        """The elastic settings at a nominal pressure (Pa)."""
        assert self.contact is not None
        return replace(self.contact, pressure=pressure)


def parse_roughness(
    data: dict[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> RoughnessScenario:
    """Build a :class:`RoughnessScenario`; any problem is one :class:`InputError` line."""
    base = Path(base_dir)
    values, top = ROUGHNESS_FILE.read_top(data)
    notes: dict[str, Any] = {}
    lower, upper = (_surface(top[side], f"[{side}]", base, notes, side) for side in SIDES)
    _check_cell(lower, upper, notes)
    sliding = SLIDING.read(top["sliding"], only_given=True)
    load_given, betas = "load" in sliding, sliding.pop("beta_deg")
    sliding["on_invalid"] = _on_invalid("sliding", sliding.get("on_invalid", "error"), notes)
    options = {"load": "full", "control": "load", **sliding,
               **LATTICE.read(top["lattice"] or {}, only_given=True)}  # fmt: skip
    options.update({k: tuple(options[k]) for k in ("phase", "stations")
                    if isinstance(options.get(k), list)})  # fmt: skip
    name = lambda k: f"[sliding].{k}" if k in SLIDING.keys() else f"[lattice].{k}"  # noqa: E731, SIM118
    settings = reraise(name, lambda: LatticeSettings(**options), InputError)
    output = OUTPUT.read(top["output"] or {})
    makers: dict[str, Callable[[Any], Any]] = {
        "adhesion": lambda t: _adhesion(t, betas, settings),
        "wear": lambda t: _wear(t, betas),
        "hierarchy": lambda t: _hierarchy(t, lower, upper, betas, base, notes),
        "multiscale": lambda t: _multiscale(t, betas),
    }
    extra = {k: None if top[k] is None else make(top[k]) for k, make in makers.items()}
    given = CONTACT.read(top["contact"] or {})
    contact = _contact(given, settings)
    settings = _lattice_pressure(given, settings, load_given)
    used = [k for k, v in extra.items() if v is not None]
    if used and (len(given["model"]) > 1 or len(given["pressure"] or ()) > 1):
        raise InputError(
            f"[{used[0]}] is invalid with a list in [contact].model or [contact].pressure:"
            " allowed only for one model at one load"
        )
    try:  # the station count is checked against the surfaces now, not mid-computation
        lattice_geometry(lower, upper, settings.stations)
    except ParameterError as exc:
        if exc.field == "stations":
            raise InputError(f"[lattice].{exc}") from None
    return RoughnessScenario(
        mu0=values["mu0"], lower=lower, upper=upper, beta_deg=betas, settings=settings,
        title=values["title"], plot_full_circle=output["plot_full_circle"],
        plot_step_deg=output["plot_step_deg"], **extra, contact=contact,
        sources={k: v for k, v in notes.items() if k in SIDES},
        warnings=tuple(notes.get("warnings", ())), statistics=output["statistics"],
        models=tuple(given["model"]), pressures=tuple(given["pressure"] or ()),
        stiffness_per_area=given["stiffness_per_area"],
    )  # fmt: skip


def _contact(v: dict[str, Any], settings: LatticeSettings) -> ElasticSettings | None:
    """``[contact]``: the BEM settings (at the first pressure) when ``model`` lists
    ``"elastic"``; None for the lattice alone."""
    if "elastic" not in v["model"]:
        given = [k for k in ("modulus", "hardness") if v[k] is not None]
        if given:
            raise InputError(
                f"[contact].{given[0]} is invalid with model = 'lattice': allowed only with "
                "model = 'elastic' (the lattice's load is [sliding].load, N per spring, or "
                "[contact].pressure with stiffness_per_area)"
            )
        return None
    for key in ("pressure", "modulus"):
        if v[key] is None:
            raise InputError(f"[contact].{key} is missing: required with model = 'elastic'")
    return reraise("[contact]", lambda: ElasticSettings(
        pressure=v["pressure"][0], modulus=v["modulus"], hardness=v["hardness"],
        stations=settings.stations, mu_definition=settings.mu_definition,
        on_invalid=settings.on_invalid,
    ), InputError)  # fmt: skip


def _lattice_pressure(
    v: dict[str, Any], settings: LatticeSettings, load_given: bool
) -> LatticeSettings:
    """The lattice at ``[contact].pressure``: its load per spring from stiffness_per_area."""
    kappa = v["stiffness_per_area"]
    at_pressure = "lattice" in v["model"] and v["pressure"] is not None
    if not at_pressure:
        if kappa is not None:
            raise InputError(
                f"[contact].stiffness_per_area = {kappa!r} is invalid here: allowed only with "
                "model 'lattice' and a [contact].pressure"
            )
        return settings
    if kappa is None:
        raise InputError(
            "[contact].stiffness_per_area is missing: required for model 'lattice' at a "
            "[contact].pressure (Pa/m, the springs' stiffness per nominal area; the load "
            "per spring is pressure * k_c / stiffness_per_area)"
        )
    if load_given or settings.control != "load":
        key = "load" if load_given else "control"
        raise InputError(
            f"[sliding].{key} is invalid with [contact].pressure: allowed one way to load "
            "the lattice (remove [sliding].load or [contact].pressure)"
        )
    load = v["pressure"][0] * settings.k_c / kappa
    return reraise("[contact].pressure", lambda: replace(settings, load=load), InputError, ": ")


def _check_cell(lower: Surface, upper: Surface, notes: dict[str, Any]) -> None:
    """Two sampled surfaces need commensurate sizes: say so with the files' own sizes."""
    try:
        lattice_geometry(lower, upper, (1, 1) if isinstance(lower, HeightMap) else 1)
    except ParameterError as exc:
        sizes = []
        for side in ("lower", "upper"):
            info = notes.get(side, {})
            if "source_physical_sizes_m" in info:
                size = [f"{v:.6g}" for v in info["source_physical_sizes_m"]]
                extra = " (mirrored: doubled)" if info.get("periodicity") == "mirror" else ""
                crop = " after crop" if "crop_m" in info else ""
                sizes.append(
                    f"[{side}] file {info.get('file')} is {' x '.join(size)} m{crop}{extra}"
                )
        if not sizes:
            raise InputError(f"[lower]/[upper]: {exc}") from None
        raise InputError(
            "[upper].physical_sizes: the two surfaces must share a period cell (sizes in an "
            f"integer ratio up to 64) but {'; '.join(sizes)}: crop them to a common size "
            "(crop = [x0, x1, y0, y1] in m)"
        ) from None


def _multiscale(data: Any, betas: np.ndarray) -> MultiscaleOptions:
    v = MULTISCALE.read(data, beta_deg=betas)
    return MultiscaleOptions(
        tuple(sorted(v["cutoffs"], reverse=True)), v["beta_deg"], v["mu_passed"]
    )


def _adhesion(data: Any, betas: np.ndarray, settings: LatticeSettings) -> AdhesionOptions:
    v = ADHESION.read(data, beta_deg=betas)
    loads, k_t = v["loads"], v["k_t"]
    if k_t is not None and not 0.0 <= k_t <= settings.k_c:
        raise InputError(f"[adhesion].k_t = {k_t!r} is invalid: allowed 0 <= k_t <= k_c = "
                         f"{settings.k_c:g} N/m")  # fmt: skip
    kt_value = 0.5 * settings.k_c if k_t is None else k_t
    if kt_value == 0.0 and np.any(loads <= 0.0):
        raise InputError("[adhesion].loads: loads <= 0 need tensile springs (k_t > 0)")
    if settings.control != "load":
        raise InputError("[adhesion] needs [sliding].control = 'load' (a load sweep)")
    if v["detachment"] is not None and kt_value == 0.0:
        raise InputError("[adhesion].detachment needs tensile springs (k_t > 0)")
    return AdhesionOptions(**v)


def _wear(data: Any, betas: np.ndarray) -> WearOptions:
    drop = ("samples", "method", "beta_deg")
    settings, v = WEAR.build(data, drop=drop, error=InputError, beta_deg=betas)
    return WearOptions(settings, v["samples"], v["method"], v["beta_deg"])


def _hierarchy(
    table: Table,
    lower: Surface,
    upper: Surface,
    betas: np.ndarray,
    base_dir: Path,
    notes: dict[str, Any],
) -> HierarchyOptions:
    v = HIERARCHY.read(table, beta_deg=betas)
    v["on_invalid"] = _on_invalid("hierarchy", v["on_invalid"], notes)
    try:
        if "inner" not in table:
            levels = self_similar_levels(lower, upper, v["levels"], v["ratio"])
        else:
            raw = table.raw("inner")
            if not isinstance(raw, list) or not all(isinstance(item, dict) for item in raw):
                raise InputError(f"{table.where}.inner must be an array of tables")
            inner = []
            for i, item in enumerate(raw, 1):
                where = f"{table.where}.inner #{i}"
                level = LEVEL.table(item, where)
                pair = (_surface(level.raw(s), f"{where}.{s}", base_dir, {}, s) for s in SIDES)
                inner.append(HierarchyLevel(*pair))
            levels = (*inner, HierarchyLevel(lower, upper))
            check_nested(levels)
    except ParameterError as exc:
        raise InputError(f"{table.where}: {exc}") from None
    return HierarchyOptions(levels, v["mu_passed"], v["on_invalid"], v["samples_per_level"],
                            v["beta_deg"])  # fmt: skip


def _surface(data: Any, where: str, base_dir: Path, notes: dict[str, Any], side: str) -> Surface:
    """Build one surface; its provenance goes to ``notes[side]``, warnings to
    ``notes["warnings"]``."""
    v = SURFACE.read(data, where)
    info: dict[str, Any] = {"kind": v["kind"]}
    surface = reraise(where, lambda: _build(v, where, base_dir, info), InputError)
    for text in info.pop("warnings", ()):
        notes.setdefault("warnings", []).append(f"{where}: {text}")
    notes[side] = info
    return surface


_MAKE = {k: getattr(generators, k) for k in ("flat", "wedge", "smooth_wedge", "sinusoid")}


def _build(v: dict[str, Any], where: str, base_dir: Path, info: dict[str, Any]) -> Surface:
    kind, keys = v["kind"], SURFACE.keys(v["kind"])[1:]
    if kind in _MAKE:
        return _MAKE[kind](**{k: v[k] for k in keys})
    if kind == "self_affine":
        sizes, points = v["physical_sizes"], v["points"]
        if len(points) != len(sizes):
            raise InputError(f"{where}.points must have {len(sizes)} entries, got {len(points)}")
        check_grid_size(f"{where}.points", points, v["allow_large"])
        info.update(hurst=v["hurst"], seed=v["seed"], physical_sizes_m=sizes, points=points)
        rng = np.random.default_rng(v["seed"])
        return generators.self_affine(
            **{k: v[k] for k in keys if k not in ("allow_large", "seed")}, rng=rng
        )
    sizes, crop = v["physical_sizes"], v["crop"]
    options = {k: v[k] for k in keys if k not in ("path", "physical_sizes", "crop")}
    prepared = read_prepared(
        base_dir / v["path"], **options,
        physical_sizes=None if sizes is None else (sizes[0] if len(sizes) == 1 else tuple(sizes)),
        crop=None if crop is None else tuple(crop),
    )  # fmt: skip
    info.update(prepared.info)
    info["warnings"] = list(prepared.warnings)
    return prepared.surface


load_roughness = loader(ROUGHNESS_FILE, parse_roughness, "a roughness scenario")
