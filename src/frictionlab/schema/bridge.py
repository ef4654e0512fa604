"""The ``frictionlab bridge`` scenario: a roughness scenario, a ``[law]`` and ``[bridge]``.

The roughness part (mu0, [lower], [upper], [sliding], [lattice], [multiscale]) is read as
by ``frictionlab roughness``; ``[law]`` as by simulate, one value per key, without the
fitted keys; ``[bridge]`` says what is fitted and how the fit is checked.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from frictionlab.bridge import FIT_GROUPS, SCALES, steady_coefficient, steady_distance
from frictionlab.errors import InputError, ParameterError
from frictionlab.schema.core import Field, Section, loader
from frictionlab.schema.kinds import INTEGER, NUMBER, STRING, listed
from frictionlab.schema.roughness import _TOP, MULTISCALE, RoughnessScenario, parse_roughness
from frictionlab.schema.scenario import LAW, parse_law_table, per_point
from frictionlab.subloading import SubloadingParams, initial_state

__all__ = ["BRIDGE_FILE", "BridgeOptions", "BridgeScenario", "load_bridge", "parse_bridge"]

#: Roughness tables the bridge does not use (its polar is the single-level kinetic one).
NOT_USED = ("output", "adhesion", "wear", "hierarchy", "contact")
#: [law] keys that a fitted group replaces.
_FITTED_KEYS = {
    "rotation": ("rotation",),
    "orthotropy": ("orthotropy", "orthotropy_angle", "orthotropy_angle_deg"),
}
OPTIONS = Section("bridge", (
    Field("scale", STRING, "where the law's size comes from: the [law] values, or "
          "mu_k from the polar (roughness)", "", "law",
          choices=SCALES),
    Field("fit", listed(str, "string", unique=True), "what is fitted; a group left out is held "
          "at its [law] value", "", list(FIT_GROUPS), choices=FIT_GROUPS),
    Field("step_deg", NUMBER, "full-circle grid of the polar ([sliding].beta_deg added)", "deg",
          10.0, low=0.5, high=45,
          allowed="a step from 0.5 to 45 deg that divides 360"),
    Field("tolerance", NUMBER, "largest relative rms misfit (over the mean |mu|) still called "
          "expressible", "", 0.02,
          low=0, high=1, open="both", allowed="0 < tolerance < 1 (relative rms misfit)"),
    Field("normal_traction", NUMBER, "f_n of the fitted scenario and of the check (closed "
          "surfaces: < F_k)",
          "Pa", 1.0, low=0, open="low", allowed="f_n > 0 Pa"),
    Field("velocity", NUMBER, "speed of the steady-sliding check and of the fitted "
          "scenario's slide", "m/s", 1.0e-3,
          low=0, open="low", allowed="V > 0 m/s"),
    Field("distance", NUMBER, "slide length of the check (default: 25 relaxation "
          "lengths)", "m", None,
          low=0, open="low", allowed="a length > 0 m"),
    Field("steps", INTEGER, "steps of that slide", "", 400, low=1, high=100_000,
          allowed="1 to 100000 steps"),
    Field("check_tolerance", NUMBER, "|simulated - closed form| allowed in f_t/f_n", "",
          1.0e-6, low=0, open="low", allowed="a tolerance > 0"),
    Field("anisotropy_tolerance", NUMBER, "largest share of the polar's anisotropic part "
          "left unexplained", "", 0.1, low=0, high=1, open="both",
          allowed="0 < anisotropy_tolerance < 1"),
), "what is fitted and how the fit is checked", "[bridge]")  # fmt: skip
BRIDGE_FILE = Section("bridge", (
    *_TOP,
    Field("multiscale", table=MULTISCALE),
    Field("law", table=LAW, doc="the law to fit (one value per key, no fitted keys)"),
    Field("bridge", table=OPTIONS),
), "A bridge scenario of `frictionlab bridge`: a roughness scenario whose kinetic polar "
   "mu(beta) is fitted by the subloading-friction [law].", extra={"required": ["mu0", "lower",
   "upper", "sliding", "law"]})  # fmt: skip


#: The longest [bridge].distance, in relaxation lengths of the law (steady_distance).
MAX_DISTANCE_LENGTHS = 1e6


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
    anisotropy_tolerance: float = 0.1


@dataclass(frozen=True)
class BridgeScenario:
    """A parsed bridge scenario: the roughness part, the base law and the options."""

    roughness: RoughnessScenario
    law: SubloadingParams
    law_given: dict[str, Any]
    options: BridgeOptions
    directions_deg: np.ndarray  #: the polar's directions (deg): the circle grid and [sliding]
    title: str = ""


def parse_bridge(
    data: dict[str, Any], *, base_dir: str | os.PathLike[str] = ".", source: str = ""
) -> BridgeScenario:
    """Build a :class:`BridgeScenario`; any problem is one InputError line naming the key."""
    _refuse_not_used(data)
    rest = {k: v for k, v in data.items() if k not in ("law", "bridge")}
    if "law" not in data:
        raise InputError("missing required table [law] (the law to fit, as in simulate)")
    roughness = parse_roughness(rest, base_dir=base_dir)
    options = _options(data.get("bridge", {}))
    law_data = data["law"]
    given = law_data if isinstance(law_data, dict) else {}
    for group, key in [(g, k) for g in options.fit for k in _FITTED_KEYS[g] if k in given]:
        raise InputError(
            f"[law].{key} is fitted by the bridge ([bridge].fit includes '{group}'): leave it "
            f"out, or remove '{group}' from [bridge].fit to hold it"
        )
    law, given = parse_law_table(law_data)
    if varying := per_point(given):
        _, key, value = varying[0]
        raise InputError(f"[law].{key} = {value} gives values per point: the bridge fits one "
                         "law, give one value")  # fmt: skip
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


def load_bridge(path: str | os.PathLike[str], overrides: Sequence[str] = ()) -> BridgeScenario:
    """Read, override (``section.key=value``) and validate a bridge scenario."""
    _refuse_not_used({item.split(".", 1)[0].strip(): None for item in overrides})
    return loader(BRIDGE_FILE, parse_bridge, "a bridge scenario")(path, overrides)


def _refuse_not_used(keys: Any) -> None:
    for key in NOT_USED:
        if key in keys:
            raise InputError(
                f"[{key}] is not used by frictionlab bridge (it fits the single-level kinetic "
                "polar mu(beta)); allowed tables: [lower], [upper], [sliding], [lattice], "
                "[law], [bridge]"
            )


def _options(data: Any) -> BridgeOptions:
    v = OPTIONS.read(data)
    count = 360.0 / v["step_deg"]
    if not math.isclose(count, round(count), rel_tol=0.0, abs_tol=1e-9):
        raise InputError(f"[bridge].step_deg = {v['step_deg']!r} is invalid: allowed "
                         f"{OPTIONS['step_deg'].allowed}")  # fmt: skip
    return BridgeOptions(**{**v, "fit": tuple(v["fit"])})
