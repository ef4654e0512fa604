"""Scenario files of ``frictionlab roughness``: TOML -> surfaces and lattice settings.

Layout (every unknown key is an error; lengths in m, angles in degrees)::

    mu0 = 0.3                      # local Coulomb coefficient, > 0
    title = "..."                  # optional
    [lower]                        # surface 1, fixed
    kind = "wedge"                 # flat | wedge | smooth_wedge | sinusoid | self_affine | file
    angles_deg = [30.0, 15.0]      # wedge, smooth_wedge: rising, falling (one value: symmetric)
    wavelength = 1.0e-3            # wedge, smooth_wedge
    [upper]                        # surface 2, sliding
    kind = "sinusoid"
    amplitude = 1.0e-4             # sinusoid
    wavelengths = [1.0e-3, 2.0e-3] # sinusoid: one value 1-D, two values 2-D
    [sliding]
    beta_deg = { start = 0.0, stop = 90.0, step = 5.0 }   # or a list, or one number
    load = "full"                  # or the mean normal force per spring (N)
    control = "load"               # or "separation" (then separation = c in m)
    phase = [0.0, 0.0]             # initial offset of the upper surface (m)
    on_invalid = "error"           # or "mask": drop contacts violating Eq 1, report their fraction
    [lattice]                      # optional: fields of LatticeSettings
    stations = 2000                # or [nx, ny]
    time_samples = 400
    k_c = 1.0                      # N/m
    k_t = 0.0                      # N/m
    travel = "auto"                # auto | return | ergodic | a length in m
    max_return_periods = 8
    mu_definition = "magnitude"    # or "projection"
    engine = "numba"               # or "numpy"
    full_contact = "average"       # load = "full": direct area average, or "lattice"
    snap_time_samples = true       # time samples moved to whole-station shifts
    [output]                       # optional
    plot_full_circle = true        # compute extra directions for the full-circle plot
    plot_step_deg = 5.0
    [adhesion]                     # optional: load sweep with tensile springs (Eqs 21-22)
    loads = [2.0, 1.0, 0.5, 0.0, -0.1]   # N per spring; or { start, stop, count }
    k_t = 0.5                      # N/m, default k_c / 2
    detachment = 0.1               # m, cut-off elongation; default: never detach
    beta_deg = [0.0, 90.0]         # default: [sliding].beta_deg
    compare_without_adhesion = true
    [wear]                         # optional: Archard wear, mu(t) (Eqs 23-28w)
    wear_coefficient = 1.0e-4      # K (dimensionless), > 0
    hardness = 2.0e9               # Pa, > 0
    normal_load = 10.0             # N on the nominal area (not the lattice load)
    velocity = 0.1                 # m/s
    nominal_area = 1.0e-4          # m^2 (1-D: depth along the ridges x length)
    surfaces = "both"              # both | lower | upper
    samples = 21                   # times from 0 to T_w
    method = "auto"                # auto | lattice | closed_form
    beta_deg = [0.0, 45.0, 90.0]   # default: [sliding].beta_deg
    [hierarchy]                    # optional: [lower]/[upper] are the outermost level n
    levels = 3                     # self-similar levels (Eq 28) with
    ratio = 10.0                   # the scale factor between levels, or instead:
    # [[hierarchy.inner]]          # inner levels, innermost first, strictly nested
    # lower = { kind = "sinusoid", amplitude = 1.0e-6, wavelengths = [1.0e-5] }
    # upper = { kind = "flat" }
    mu_passed = "magnitude"        # or "projection"
    on_invalid = "raise"           # or "mask"
    samples_per_level = 11         # hierarchy with [wear]: times per level window
    beta_deg = [0.0, 45.0, 90.0]   # default: [sliding].beta_deg
    [multiscale]                   # optional: scale-resolved friction (sampled surfaces)
    cutoffs = [1.0e-4, 3.0e-5]     # band edges, wavelengths in m (any order, distinct)
    mu_passed = "magnitude"        # or "projection"
    beta_deg = [0.0, 45.0, 90.0]   # default: [sliding].beta_deg

Surface kinds and their keys:

* ``flat``: none.
* ``self_affine``: ``hurst``, ``physical_sizes`` (1 or 2 values), ``points`` (same count;
  grids beyond half the machine's memory are refused unless ``allow_large = true``),
  ``seed`` (integer), exactly one of ``rms_height`` (m) or ``rms_slope``; optional
  ``short_cutoff``, ``long_cutoff`` (m).
* ``file``: ``path`` (relative to the scenario file), ``periodicity`` (require | assume |
  mirror) and ``detrend`` (none | center | height | curvature), both required; optional
  ``fill_missing`` (false), ``gradient`` (fd | spectral), ``format``, ``channel``,
  ``unit`` and ``physical_sizes`` (only for files without them: the length unit of the
  heights and sizes, and the scan size along x, y *in that unit*), ``crop = [x0, x1, y0,
  y1]`` (m), ``window`` (e.g. "hann"), ``short_cutoff`` and ``long_cutoff`` (m).
  Array axes: the first is x (see :mod:`frictionlab.roughness.topography`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.app.budget import check_grid_size
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import Table
from frictionlab.roughness import generators
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
from frictionlab.roughness.topography import DETREND_MODES, PERIODICITY_MODES, read_prepared
from frictionlab.roughness.wear import WEAR_METHODS, WEAR_SURFACES, WearSettings

__all__ = [
    "SURFACE_KINDS",
    "AdhesionOptions",
    "HierarchyOptions",
    "RoughnessScenario",
    "WearOptions",
    "parse_roughness_scenario",
]

SURFACE_KINDS = ("flat", "wedge", "smooth_wedge", "sinusoid", "self_affine", "file")
MAX_DIRECTIONS = 3601

_SLIDING_FIELDS = {"load", "control", "separation", "phase", "on_invalid"}
#: [sliding].on_invalid in the TOML -> LatticeSettings.on_invalid
ON_INVALID_KEYS = {"error": "raise", "mask": "drop"}


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


def parse_roughness_scenario(data: dict[str, Any], base_dir: Path) -> RoughnessScenario:
    """Build a :class:`RoughnessScenario`; any problem is one :class:`InputError` line."""
    top = Table(data, "")
    mu0 = top.get(
        "mu0", float, check=lambda v: v > 0.0, allowed="a local friction coefficient mu0 > 0"
    )
    title = top.get("title", str, "")
    lower_table = top.table("lower", required=True)
    upper_table = top.table("upper", required=True)
    assert lower_table is not None and upper_table is not None
    notes: dict[str, Any] = {}
    lower = _surface(lower_table, base_dir, notes, "lower")
    upper = _surface(upper_table, base_dir, notes, "upper")
    _check_cell(lower, upper, notes)
    sliding = top.table("sliding", required=True)
    assert sliding is not None
    betas = _directions(sliding)
    options: dict[str, Any] = {}
    load = sliding.raw("load", "full")
    if isinstance(load, str):
        if load != "full":
            raise InputError(
                f"[sliding].load = {load!r} is invalid: allowed 'full' or a number (N)"
            )
        options["load"] = "full"
    else:
        options["load"] = sliding.get("load", float)
    options["control"] = sliding.get("control", str, "load", choices=CONTROLS)
    if "separation" in sliding:
        options["separation"] = sliding.get("separation", float)
    if "phase" in sliding:
        options["phase"] = tuple(sliding.get_list("phase", float, length=2))
    on_invalid = sliding.get("on_invalid", str, "error", choices=tuple(ON_INVALID_KEYS))
    options["on_invalid"] = ON_INVALID_KEYS[on_invalid]
    sliding.finish(allowed=("separation", "phase"))
    lattice = top.table("lattice")
    if lattice is not None:
        if "stations" in lattice:
            raw = lattice.raw("stations")
            if isinstance(raw, list):
                options["stations"] = tuple(lattice.get_list("stations", int, length=(1, 2)))
            else:
                options["stations"] = lattice.get("stations", int)
        for key, kind in (("time_samples", int), ("max_return_periods", int)):
            if key in lattice:
                options[key] = lattice.get(key, kind)
        for key in ("k_c", "k_t"):
            if key in lattice:
                options[key] = lattice.get(key, float)
        if "travel" in lattice:
            raw = lattice.raw("travel")
            options["travel"] = (
                lattice.get("travel", str, choices=TRAVEL_MODES)
                if isinstance(raw, str)
                else lattice.get("travel", float)
            )
        if "mu_definition" in lattice:
            options["mu_definition"] = lattice.get("mu_definition", str, choices=MU_DEFINITIONS)
        if "engine" in lattice:
            options["engine"] = lattice.get("engine", str, choices=ENGINES)
        if "full_contact" in lattice:
            options["full_contact"] = lattice.get("full_contact", str, choices=FULL_CONTACT_METHODS)
        if "snap_time_samples" in lattice:
            options["snap_time_samples"] = lattice.get("snap_time_samples", bool)
        lattice.finish(allowed=_LATTICE_KEYS)
    try:
        settings = LatticeSettings(**options)
    except ParameterError as exc:
        section = "[sliding]" if exc.field in _SLIDING_FIELDS else "[lattice]"
        raise InputError(f"{section}.{exc}") from None
    output = top.table("output")
    full_circle, step = True, 5.0
    if output is not None:
        full_circle = output.get("plot_full_circle", bool, True)
        step = output.get(
            "plot_step_deg", float, 5.0, check=lambda v: 0.0 < v <= 90.0, allowed="0 < step <= 90"
        )
        output.finish()
    adhesion_table = top.table("adhesion")
    adhesion = None if adhesion_table is None else _adhesion(adhesion_table, betas, settings)
    wear_table = top.table("wear")
    wear = None if wear_table is None else _wear(wear_table, betas)
    hierarchy_table = top.table("hierarchy")
    hierarchy = (
        None
        if hierarchy_table is None
        else _hierarchy(hierarchy_table, lower, upper, betas, base_dir)
    )
    multiscale_table = top.table("multiscale")
    multiscale = None
    if multiscale_table is not None:
        multiscale = _multiscale(multiscale_table, lower, upper, betas)
    top.finish()
    try:  # the station count is checked against the surfaces now, not mid-computation
        lattice_geometry(lower, upper, settings.stations)
    except ParameterError as exc:
        if exc.field == "stations":
            raise InputError(f"[lattice].{exc}") from None
    return RoughnessScenario(
        mu0=mu0,
        lower=lower,
        upper=upper,
        beta_deg=betas,
        settings=settings,
        title=title,
        plot_full_circle=full_circle,
        plot_step_deg=step,
        adhesion=adhesion,
        wear=wear,
        hierarchy=hierarchy,
        sources={k: v for k, v in notes.items() if k in ("lower", "upper")},
        warnings=tuple(notes.get("warnings", ())),
        multiscale=multiscale,
    )


#: Every key of [lattice] (listed when an unknown one is given).
#: Optional keys of a surface table that are read only when given, by kind.
_OPTIONAL_SURFACE_KEYS = {
    "self_affine": ("rms_height", "rms_slope", "short_cutoff", "long_cutoff"),
    "file": ("short_cutoff", "long_cutoff"),
}
_LATTICE_KEYS = (
    "stations", "time_samples", "max_return_periods", "k_c", "k_t", "travel",
    "mu_definition", "engine", "full_contact", "snap_time_samples",
)  # fmt: skip


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


def _multiscale(
    table: Table, lower: Surface, upper: Surface, betas: np.ndarray
) -> MultiscaleOptions:
    cutoffs = table.get_list("cutoffs", float)
    if not cutoffs or any(not (v > 0.0 and math.isfinite(v)) for v in cutoffs):
        raise InputError(
            f"{table.where}.cutoffs = {cutoffs} is invalid: allowed a non-empty list of "
            "wavelengths > 0 m"
        )
    ordered = tuple(sorted(cutoffs, reverse=True))
    if len(set(ordered)) != len(ordered):
        raise InputError(f"{table.where}.cutoffs = {cutoffs} is invalid: allowed distinct values")
    mu_passed = table.get("mu_passed", str, "magnitude", choices=MU_PASSED)
    directions = _own_directions(table, betas)
    table.finish(allowed=("beta_deg",))
    return MultiscaleOptions(ordered, directions, mu_passed)


def _own_directions(table: Table, default: np.ndarray) -> np.ndarray:
    """``beta_deg`` of an optional table (same forms as [sliding]), else the default."""
    return _directions(table) if "beta_deg" in table else default


def _adhesion(table: Table, betas: np.ndarray, settings: LatticeSettings) -> AdhesionOptions:
    name = f"{table.where}.loads"
    raw = table.raw("loads")
    if isinstance(raw, dict):
        rng = Table(raw, name)
        start = rng.get("start", float)
        stop = rng.get("stop", float)
        count = rng.get("count", int, check=lambda v: v >= 1, allowed="count >= 1 load")
        rng.finish()
        if count == 1 and start != stop:
            raise InputError(f"{name}: count = 1 needs start == stop")
        loads = np.linspace(start, stop, count)
    else:
        loads = np.array(table.get_list("loads", float), dtype=np.float64)
        if loads.size == 0:
            raise InputError(
                f"{name} is empty: allowed a sweep of at least one load (N per spring)"
            )
    if loads.size > MAX_DIRECTIONS:
        raise InputError(f"{name} has {loads.size} loads: allowed at most {MAX_DIRECTIONS}")
    k_t = None
    if "k_t" in table:
        k_t = table.get(
            "k_t",
            float,
            check=lambda v: 0.0 <= v <= settings.k_c,
            allowed=f"0 <= k_t <= k_c = {settings.k_c:g} N/m",
        )
    kt_value = 0.5 * settings.k_c if k_t is None else k_t
    if kt_value == 0.0 and np.any(loads <= 0.0):
        raise InputError(f"{name}: loads <= 0 need tensile springs (k_t > 0)")
    if settings.control != "load":
        raise InputError(f"{table.where} needs [sliding].control = 'load' (a load sweep)")
    compare = table.get("compare_without_adhesion", bool, True)
    detachment = None
    if "detachment" in table:
        detachment = table.get(
            "detachment", float, check=lambda v: v > 0.0, allowed="a cut-off elongation > 0 m"
        )
        if kt_value == 0.0:
            raise InputError(f"{table.where}.detachment needs tensile springs (k_t > 0)")
    directions = _own_directions(table, betas)
    table.finish(allowed=("k_t", "detachment", "beta_deg"))
    return AdhesionOptions(loads, k_t, directions, compare, detachment)


def _wear(table: Table, betas: np.ndarray) -> WearOptions:
    values: dict[str, Any] = {}
    units = {
        "wear_coefficient": "dimensionless",
        "hardness": "Pa",
        "normal_load": "N",
        "velocity": "m/s",
        "nominal_area": "m^2",
    }
    for key, unit in units.items():
        values[key] = table.get(
            key, float, check=lambda v: v > 0.0, allowed=f"a positive number ({unit})"
        )
    values["surfaces"] = table.get("surfaces", str, "both", choices=WEAR_SURFACES)
    samples = table.get("samples", int, 21, check=lambda v: v >= 2, allowed="an integer >= 2")
    method = table.get("method", str, "auto", choices=WEAR_METHODS)
    directions = _own_directions(table, betas)
    table.finish(allowed=("beta_deg",))
    try:
        settings = WearSettings(**values)
    except ParameterError as exc:
        raise InputError(f"{table.where}.{exc}") from None
    return WearOptions(settings, samples, method, directions)


def _hierarchy(
    table: Table, lower: Surface, upper: Surface, betas: np.ndarray, base_dir: Path
) -> HierarchyOptions:
    has_inner = "inner" in table
    has_self_similar = "levels" in table or "ratio" in table
    if has_inner == has_self_similar:
        raise InputError(
            f"{table.where} needs either levels and ratio (self-similar, Eq 28) or "
            "[[hierarchy.inner]] tables, not both"
        )
    try:
        if has_self_similar:
            n = table.get("levels", int, check=lambda v: v >= 1, allowed="an integer >= 1")
            ratio = table.get("ratio", float, check=lambda v: v > 1.0, allowed="a scale factor > 1")
            levels = self_similar_levels(lower, upper, n, ratio)
        else:
            raw = table.raw("inner")
            if not isinstance(raw, list) or not all(isinstance(v, dict) for v in raw):
                raise InputError(f"{table.where}.inner must be an array of tables")
            inner = []
            for i, item in enumerate(raw, 1):
                level = Table(item, f"{table.where}.inner #{i}")
                pair = []
                for side in ("lower", "upper"):
                    sub = level.table(side, required=True)
                    assert sub is not None
                    pair.append(_surface(sub, base_dir, {}, side))
                level.finish()
                inner.append(HierarchyLevel(pair[0], pair[1]))
            levels = (*inner, HierarchyLevel(lower, upper))
            check_nested(levels)
    except ParameterError as exc:
        raise InputError(f"{table.where}: {exc}") from None
    mu_passed = table.get("mu_passed", str, "magnitude", choices=MU_PASSED)
    on_invalid = table.get("on_invalid", str, "raise", choices=ON_INVALID)
    samples = table.get(
        "samples_per_level", int, 11, check=lambda v: v >= 2, allowed="an integer >= 2"
    )
    directions = _own_directions(table, betas)
    table.finish(allowed=("levels", "ratio", "inner", "beta_deg"))
    return HierarchyOptions(levels, mu_passed, on_invalid, samples, directions)


def _directions(sliding: Table) -> np.ndarray:
    raw = sliding.raw("beta_deg")
    name = f"{sliding.where}.beta_deg"
    if isinstance(raw, dict):
        rng = Table(raw, name)
        start = rng.get("start", float)
        stop = rng.get("stop", float)
        step = rng.get("step", float, check=lambda v: v > 0.0, allowed="step > 0")
        rng.finish()
        if stop < start:
            raise InputError(f"{name}: stop = {stop:g} is below start = {start:g}")
        count = math.floor((stop - start) / step * (1.0 + 1e-12) + 1e-9) + 1
        if count > MAX_DIRECTIONS:
            raise InputError(f"{name} has {count} directions: allowed at most {MAX_DIRECTIONS}")
        return start + step * np.arange(count)
    if isinstance(raw, list):
        values = sliding.get_list("beta_deg", float)
        if not values or len(values) > MAX_DIRECTIONS:
            raise InputError(f"{name} must list 1 to {MAX_DIRECTIONS} directions")
        return np.array(values, dtype=np.float64)
    return np.array([sliding.get("beta_deg", float)], dtype=np.float64)


def _surface(table: Table, base_dir: Path, notes: dict[str, Any], side: str) -> Surface:
    """Build one surface; its provenance goes to ``notes[side]``, warnings to
    ``notes["warnings"]``."""
    kind = table.get("kind", str, choices=SURFACE_KINDS)
    info: dict[str, Any] = {"kind": kind}
    try:
        surface = _build(kind, table, base_dir, info)
    except ParameterError as exc:
        raise InputError(f"{table.where}.{exc}") from None
    table.finish(allowed=_OPTIONAL_SURFACE_KEYS.get(kind, ()))
    for text in info.pop("warnings", ()):
        notes.setdefault("warnings", []).append(f"{table.where}: {text}")
    notes[side] = info
    return surface


def _positive(table: Table, key: str) -> float:
    return float(
        table.get(key, float, check=lambda v: v > 0.0, allowed="a positive value (SI units)")
    )


def _build(kind: str, table: Table, base_dir: Path, info: dict[str, Any]) -> Surface:
    if kind == "flat":
        return generators.flat()
    if kind in ("wedge", "smooth_wedge"):
        angles = table.get_list("angles_deg", float, length=(1, 2))
        for a in angles:
            if not 0.0 < a < 90.0:
                raise InputError(
                    f"{table.where}.angles_deg = {angles} is invalid: "
                    "allowed 0 < angle < 90 degrees"
                )
        wavelength = _positive(table, "wavelength")
        make = generators.wedge if kind == "wedge" else generators.smooth_wedge
        return make(angles, wavelength)
    if kind == "sinusoid":
        amplitude = _positive(table, "amplitude")
        wavelengths = table.get_list("wavelengths", float, length=(1, 2))
        return generators.sinusoid(amplitude, wavelengths)
    if kind == "self_affine":
        hurst = table.get("hurst", float, check=lambda v: 0.0 < v <= 1.0, allowed="0 < hurst <= 1")
        sizes = table.get_list("physical_sizes", float, length=(1, 2))
        points = table.get_list("points", int, length=len(sizes))
        allow_large = table.get("allow_large", bool, False)
        check_grid_size(f"{table.where}.points", points, allow_large)
        seed = table.get("seed", int, check=lambda v: v >= 0, allowed="an integer >= 0")
        rms_height = _positive(table, "rms_height") if "rms_height" in table else None
        rms_slope = _positive(table, "rms_slope") if "rms_slope" in table else None
        short = _positive(table, "short_cutoff") if "short_cutoff" in table else None
        long = _positive(table, "long_cutoff") if "long_cutoff" in table else None
        info.update(hurst=hurst, seed=seed, physical_sizes_m=sizes, points=points)
        return generators.self_affine(
            hurst,
            sizes,
            points,
            rng=np.random.default_rng(seed),
            rms_height=rms_height,
            rms_slope=rms_slope,
            short_cutoff=short,
            long_cutoff=long,
        )
    # kind == "file"
    path = Path(table.get("path", str))
    if not path.is_absolute():
        path = base_dir / path
    periodicity = table.get("periodicity", str, choices=PERIODICITY_MODES)
    detrend = table.get("detrend", str, choices=DETREND_MODES)
    fill = table.get("fill_missing", bool, False)
    gradient = table.get("gradient", str, "fd", choices=("fd", "spectral"))
    fmt = table.get("format", str, None)
    channel = table.get("channel", int, None)
    unit = table.get("unit", str, None)
    sizes = table.get_list("physical_sizes", float, None, length=(1, 2))
    crop = table.get_list("crop", float, None, length=(2, 4))
    window = table.get("window", str, None)
    short = _positive(table, "short_cutoff") if "short_cutoff" in table else None
    long = _positive(table, "long_cutoff") if "long_cutoff" in table else None
    if sizes is not None and any(not (v > 0.0 and math.isfinite(v)) for v in sizes):
        raise InputError(
            f"{table.where}.physical_sizes = {sizes} is invalid: allowed sizes > 0 in `unit`"
        )
    prepared = read_prepared(
        path,
        periodicity=periodicity,
        detrend=detrend,
        fill_missing=fill,
        gradient=gradient,
        format=fmt,
        channel=channel,
        unit=unit,
        physical_sizes=None if sizes is None else (sizes[0] if len(sizes) == 1 else tuple(sizes)),
        crop=None if crop is None else tuple(crop),
        window=window,
        short_cutoff=short,
        long_cutoff=long,
    )
    info.update(prepared.info)
    info["warnings"] = list(prepared.warnings)
    return prepared.surface
