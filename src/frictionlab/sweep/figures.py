"""The summary figures of one case, read from its ``summary.json``.

The single place that knows the summary layout of each command: if a summary key is
renamed, only this module changes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

__all__ = ["figure_unit", "summary_figures"]

_ROUGHNESS = (
    "mu_min",
    "mu_max",
    "beta_at_mu_min_deg",
    "beta_at_mu_max_deg",
    "mu_over_mu0_min",
    "mu_over_mu0_max",
    "anisotropy_max_over_min",
)


def summary_figures(command: str, summary: Mapping[str, Any]) -> dict[str, float | None]:
    """Scalar figures of a case: peak/final friction ratio (and the healing rate) for
    simulate (suffix ``_p<i>`` per point when there are several), mu extremes and the
    anisotropy for roughness. Missing values come back as None."""
    if command == "roughness":
        results = summary.get("results", {})
        return {key: _number(results.get(key)) for key in _ROUGHNESS}
    out: dict[str, float | None] = {}
    points = summary.get("points", [])
    for i, point in enumerate(points):
        suffix = "" if len(points) == 1 else f"_p{i + 1}"
        out[f"peak_friction_ratio{suffix}"] = _number(point.get("peak", {}).get("friction_ratio"))
        out[f"final_friction_ratio{suffix}"] = _number(point.get("final", {}).get("friction_ratio"))
    healing = summary.get("healing")
    if isinstance(healing, Mapping):
        records = healing.get("records", [])
        if len(records) == 1:
            out["delta_mu"] = _number(records[0].get("delta_mu"))
        if healing.get("rate_per_decade") is not None:
            out["healing_rate_per_decade"] = _number(healing.get("rate_per_decade"))
    return out


def figure_unit(name: str) -> str:
    """The unit of a summary figure: angles (``*_deg``) in degrees, the rest (friction
    ratios, mu, anisotropy, delta mu, the healing rate per decade) dimensionless."""
    return "deg" if name.endswith("_deg") else "-"


def _number(value: Any) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    return float(value) if math.isfinite(value) else None
