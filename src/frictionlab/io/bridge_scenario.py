"""Scenario files of ``frictionlab bridge``: a roughness scenario, a ``[law]`` and ``[bridge]``.

Layout (every unknown key is an error; docs/bridge.md has every key with its default)::

    title = "..."                 # optional
    mu0 = 0.3                     # the roughness scenario, as `frictionlab roughness`:
    [lower] ...                   #   mu0, [lower], [upper], [sliding], [lattice]
    [upper] ...                   #   ([sliding].beta_deg: extra directions for the polar)
    [sliding] ...
    [lattice] ...                 # optional
    [law]                         # as in `frictionlab simulate`, one value per key; the
    surface = "coulomb"           # fitted keys (rotation; orthotropy, orthotropy_angle)
    mu_s = 0.5                    # are left out
    mu_k = 0.3
    [bridge]                      # optional
    scale = "law"                 # or "roughness": the size from mu(beta)
    fit = ["orthotropy", "rotation"]
    step_deg = 10.0               # full-circle grid of the polar (deg)
    tolerance = 0.02              # relative rms misfit still called expressible
    normal_traction = 1.0         # Pa: f_n of the fitted scenario (closed surfaces: < F_k)
    velocity = 1.0e-3             # m/s: steady-sliding check and fitted scenario
    distance = 1.0                # m: slide length (default: 25 relaxation lengths)
    steps = 400                   # steps of that slide
    check_tolerance = 1.0e-6      # |simulated - closed form| allowed in f_t/f_n

:func:`parse_bridge_scenario` validates everything before anything is computed; each
problem is one :class:`~frictionlab.errors.InputError` line naming the key.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.bridge import FIT_GROUPS, SCALES, steady_coefficient, steady_distance
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import Table
from frictionlab.io.roughness_scenario import RoughnessScenario, parse_roughness_scenario
from frictionlab.io.scenario import parse_law_table
from frictionlab.subloading import SubloadingParams, initial_state

__all__ = ["BridgeOptions", "BridgeScenario", "parse_bridge_scenario"]

#: Roughness tables the bridge does not use (its polar is the single-level kinetic one).
_NOT_USED = ("output", "adhesion", "wear", "hierarchy")
#: The longest [bridge].distance, in relaxation lengths of the law (steady_distance).
MAX_DISTANCE_LENGTHS = 1e6
#: [law] keys that a fitted group replaces.
_FITTED_KEYS = {
    "rotation": ("rotation",),
    "orthotropy": ("orthotropy", "orthotropy_angle", "orthotropy_angle_deg"),
}


@dataclass(frozen=True)
class BridgeOptions:
    """The ``[bridge]`` table (defaults as documented in docs/bridge.md)."""

    scale: str = "law"
    fit: tuple[str, ...] = FIT_GROUPS
    step_deg: float = 10.0
    tolerance: float = 0.02
    normal_traction: float = 1.0
    velocity: float = 1.0e-3
    distance: float | None = None
    steps: int = 400
    check_tolerance: float = 1.0e-6


@dataclass(frozen=True)
class BridgeScenario:
    """A parsed bridge scenario: the roughness part, the base law and the options."""

    roughness: RoughnessScenario
    law: SubloadingParams
    law_given: dict[str, Any]
    options: BridgeOptions
    directions_deg: np.ndarray  #: the polar's directions (deg): the circle grid and [sliding]
    title: str = ""


def parse_bridge_scenario(data: dict[str, Any], base_dir: Path) -> BridgeScenario:
    """Build a :class:`BridgeScenario`; any problem is one InputError line naming the key."""
    for key in _NOT_USED:
        if key in data:
            raise InputError(
                f"[{key}] is not used by frictionlab bridge (it fits the single-level kinetic "
                "polar mu(beta)); allowed tables: [lower], [upper], [sliding], [lattice], "
                "[law], [bridge]"
            )
    rest = {k: v for k, v in data.items() if k not in ("law", "bridge")}
    if "law" not in data:
        raise InputError("missing required table [law] (the law to fit, as in simulate)")
    roughness = parse_roughness_scenario(rest, base_dir)
    options = _options(Table(data.get("bridge", {}), "[bridge]"))
    law_data = data["law"]
    if isinstance(law_data, dict):
        for group in options.fit:
            for key in _FITTED_KEYS[group]:
                if key in law_data:
                    raise InputError(
                        f"[law].{key} is fitted by the bridge ([bridge].fit includes "
                        f"'{group}'): leave it out, or remove '{group}' from [bridge].fit "
                        "to hold it"
                    )
    law, given = parse_law_table(law_data)
    for key, value in given.items():
        pair = key in ("rotation", "orthotropy")
        if isinstance(value, list) and (not pair or isinstance(value[0], list)):
            raise InputError(
                f"[law].{key} = {value} gives values per point: the bridge fits one law, "
                "give one value"
            )
    try:
        steady_coefficient(law, None, options.normal_traction)
    except ParameterError as exc:
        raise InputError(
            f"[bridge].normal_traction = {options.normal_traction:g} is invalid: allowed "
            f"{exc.allowed}"
        ) from None
    # The law must hold at f_n before any fit: inside the domain of a closed surface, and
    # no snap-back (the elastic stiffness must exceed the softening slope).
    try:
        initial_state(law, options.normal_traction)
    except ParameterError as exc:
        if exc.field == "normal_traction":
            raise InputError(f"[bridge].{exc}") from None
        raise InputError(
            f"[law].{exc} (at [bridge].normal_traction = {options.normal_traction:g} Pa)"
        ) from None
    if options.distance is not None:
        # steady after ~25 relaxation lengths (steady_distance); far beyond, one step's
        # slip makes a trial traction the law's solve rejects, blaming the traction
        longest = steady_distance(law, options.normal_traction, lengths=MAX_DISTANCE_LENGTHS)
        if options.distance > longest:
            raise InputError(
                f"[bridge].distance = {options.distance:g} m is invalid: allowed at most "
                f"{longest:.3g} m ({MAX_DISTANCE_LENGTHS:g} relaxation lengths of [law] at "
                "[bridge].normal_traction; steady sliding needs about 25)"
            )
    circle = np.arange(0.0, 360.0 - 1e-9, options.step_deg)
    extra = np.mod(roughness.beta_deg, 360.0)
    directions = np.unique(np.round(np.concatenate([circle, extra]), 9))
    return BridgeScenario(roughness, law, given, options, directions, roughness.title)


def _options(t: Table) -> BridgeOptions:
    scale = t.get("scale", str, "law", choices=SCALES)
    fit = t.get_list("fit", str, list(FIT_GROUPS))
    for i, group in enumerate(fit):
        if group not in FIT_GROUPS:
            raise InputError(
                f"[bridge].fit[{i}] = {group!r} is not allowed; choose among "
                + ", ".join(repr(g) for g in FIT_GROUPS)
            )
    if len(set(fit)) != len(fit):
        raise InputError(f"[bridge].fit = {fit} names a group twice")
    step = t.get(
        "step_deg", float, 10.0, check=lambda v: 0.5 <= v <= 45.0 and _divides_circle(v),
        allowed="a step from 0.5 to 45 deg that divides 360",
    )  # fmt: skip
    tolerance = t.get(
        "tolerance", float, 0.02, check=lambda v: 0.0 < v < 1.0,
        allowed="0 < tolerance < 1 (relative rms misfit)",
    )  # fmt: skip
    fn = t.get("normal_traction", float, 1.0, check=lambda v: v > 0.0, allowed="f_n > 0 Pa")
    velocity = t.get("velocity", float, 1.0e-3, check=lambda v: v > 0.0, allowed="V > 0 m/s")
    distance = t.get("distance", float, None, check=lambda v: v > 0.0, allowed="a length > 0 m")
    steps = t.get("steps", int, 400, check=lambda v: 1 <= v <= 100_000, allowed="1 to 100000 steps")
    check = t.get(
        "check_tolerance", float, 1.0e-6, check=lambda v: v > 0.0, allowed="a tolerance > 0"
    )
    t.finish()
    return BridgeOptions(scale, tuple(fit), step, tolerance, fn, velocity, distance, steps, check)


def _divides_circle(step: float) -> bool:
    count = 360.0 / step
    return math.isclose(count, round(count), rel_tol=0.0, abs_tol=1e-9)
