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
    [lattice]                      # optional: fields of LatticeSettings
    stations = 2000                # or [nx, ny]
    time_samples = 400
    k_c = 1.0                      # N/m
    k_t = 0.0                      # N/m
    travel = "auto"                # auto | return | ergodic | a length in m
    max_return_periods = 8
    mu_definition = "magnitude"    # or "projection"
    engine = "numba"               # or "numpy"
    [output]                       # optional
    plot_full_circle = true        # compute extra directions for the full-circle plot
    plot_step_deg = 5.0

Surface kinds and their keys:

* ``flat``: none.
* ``self_affine``: ``hurst``, ``physical_sizes`` (1 or 2 values), ``points`` (same count),
  ``seed`` (integer), exactly one of ``rms_height`` (m) or ``rms_slope``; optional
  ``short_cutoff``, ``long_cutoff`` (m).
* ``file``: ``path`` (relative to the scenario file), ``periodicity`` (require | assume |
  mirror) and ``detrend`` (none | center | height | curvature), both required; optional
  ``fill_missing`` (false), ``gradient`` (fd | spectral), ``format``, ``channel``, ``unit``,
  ``physical_sizes``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import Table
from frictionlab.roughness import generators
from frictionlab.roughness.lattice import (
    CONTROLS,
    ENGINES,
    MU_DEFINITIONS,
    TRAVEL_MODES,
    LatticeSettings,
)
from frictionlab.roughness.surface import Surface
from frictionlab.roughness.topography import DETREND_MODES, PERIODICITY_MODES, read_surface

__all__ = ["SURFACE_KINDS", "RoughnessScenario", "parse_roughness_scenario"]

SURFACE_KINDS = ("flat", "wedge", "smooth_wedge", "sinusoid", "self_affine", "file")
MAX_DIRECTIONS = 3601

_SLIDING_FIELDS = {"load", "control", "separation", "phase"}


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
    lower = _surface(lower_table, base_dir)
    upper = _surface(upper_table, base_dir)
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
    sliding.finish()
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
        lattice.finish()
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
    top.finish()
    return RoughnessScenario(
        mu0=mu0,
        lower=lower,
        upper=upper,
        beta_deg=betas,
        settings=settings,
        title=title,
        plot_full_circle=full_circle,
        plot_step_deg=step,
    )


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


def _surface(table: Table, base_dir: Path) -> Surface:
    kind = table.get("kind", str, choices=SURFACE_KINDS)
    try:
        surface = _build(kind, table, base_dir)
    except ParameterError as exc:
        raise InputError(f"{table.where}: {exc}") from None
    table.finish()
    return surface


def _positive(table: Table, key: str) -> float:
    return float(
        table.get(key, float, check=lambda v: v > 0.0, allowed="a positive value (SI units)")
    )


def _build(kind: str, table: Table, base_dir: Path) -> Surface:
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
        seed = table.get("seed", int, check=lambda v: v >= 0, allowed="an integer >= 0")
        rms_height = _positive(table, "rms_height") if "rms_height" in table else None
        rms_slope = _positive(table, "rms_slope") if "rms_slope" in table else None
        short = _positive(table, "short_cutoff") if "short_cutoff" in table else None
        long = _positive(table, "long_cutoff") if "long_cutoff" in table else None
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
    return read_surface(
        path,
        periodicity=periodicity,
        detrend=detrend,
        fill_missing=fill,
        gradient=gradient,
        format=fmt,
        channel=channel,
        unit=unit,
        physical_sizes=None if sizes is None else (sizes[0] if len(sizes) == 1 else tuple(sizes)),
    )
