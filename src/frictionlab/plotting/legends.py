"""Legend labels of the contact points from the inputs given per point (``V = 0.1 m/s``)."""

from __future__ import annotations

from typing import Any

__all__ = ["point_labels"]

#: How per-point inputs are named in legends: key -> (symbol, unit).
_LABEL_NAMES: dict[str, tuple[str, str]] = {
    "velocity": ("V", "m/s"), "distance": ("distance", "m"), "duration": ("t", "s"),
    "direction_deg": ("direction", "deg"), "angle_deg": ("turn", "deg"),
    "amplitude": ("amplitude", "m"), "approach": ("approach", "m"), "traction": ("f_t", "Pa"),
    "traction_change": ("change", "Pa"), "normal_traction": ("f_n", "Pa"),
    "tangential_traction": ("f_t", "Pa"), "stiffness": ("k", "Pa/m"), "mass": ("m", "kg/m^2"),
    "damping": ("c", "Pa s/m"), "alpha_n": ("alpha_n", "Pa/m"), "alpha_t": ("alpha_t", "Pa/m"),
    "u": ("u", "1/m"), "F_s": ("F_s", "Pa"), "F_k": ("F_k", "Pa"),
}  # fmt: skip


def point_labels(n: int, varying: list[tuple[str, str, list[Any]]]) -> tuple[str, ...]:
    """Legend labels from the inputs given per point (``V = 0.1 m/s`` style)."""
    if n == 1:
        return ("",)
    if not varying:
        return tuple(f"point {i + 1}" for i in range(n))
    out = []
    for i in range(n):
        parts = []
        for prefix, key, values in varying[:2]:
            symbol, unit = _LABEL_NAMES.get(key, (key, ""))
            v = values[i]
            text = f"({v[0]:g}, {v[1]:g})" if isinstance(v, list) else f"{v:g}"
            parts.append(f"{prefix}{symbol} = {text}{' ' + unit if unit else ''}")
        out.append(", ".join(parts))
    return tuple(out)
