"""Interface law parameters that vary along the contact face: tables and regions.

A :class:`LawField` turns the one interface law into a per-point law at the contact
(Gauss) points, the per-point form the law's kernel already takes (every numeric field
of :class:`~frictionlab.subloading.SubloadingParams` may be an ``(N,)`` array, the
vectors ``(N, 2)``): one kernel call updates every point with its own values.

Order: the scalar law everywhere, then each :class:`LawTable` (a parameter sampled along
the interface, linearly interpolated onto the points: ``np.interp`` along x in 2-D,
Delaunay-linear ``scipy.interpolate.LinearNDInterpolator`` over (x, y) in 3-D), then
each :class:`LawRegion` in order (a later region overrides an earlier one where they
overlap). A point outside a table's samples is refused (no extrapolation).

The penalty stiffnesses ``alpha_n``, ``alpha_t``, the surface family and the options stay
one value per interface (the linear solver's elastic contact block is built from them).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

__all__ = ["FIELD_KEYS", "PAIR_KEYS", "LawField", "LawRegion", "LawTable"]

#: Scalar law parameters that may vary along the interface.
FIELD_KEYS: tuple[str, ...] = (
    "mu_s", "mu_k", "F_s", "F_k", "M", "u", "kappa", "xi", "m", "n", "orthotropy_angle",
)  # fmt: skip
#: Pair parameters (beta, (C_1, C_2)) that may vary by region.
PAIR_KEYS: tuple[str, ...] = ("rotation", "orthotropy")


@dataclass(frozen=True)
class LawTable:
    """One law parameter sampled along the interface.

    Attributes
    ----------
    key:
        The parameter (one of :data:`FIELD_KEYS`; ``orthotropy_angle`` in rad).
    points:
        (k, d - 1) sample coordinates [m]: x (2-D, k >= 2 distinct) or (x, y) (3-D,
        k >= 3 not on one line).
    values:
        (k,) the parameter at the samples.
    source:
        Where the samples came from (named in messages).
    """

    key: str
    points: np.ndarray
    values: np.ndarray
    source: str = ""

    def __post_init__(self) -> None:
        if self.key not in FIELD_KEYS:
            raise ParameterError("key", self.key, "one of " + ", ".join(FIELD_KEYS))
        p = np.array(self.points, dtype=np.float64)
        p = p[:, None] if p.ndim == 1 else p
        v = np.array(self.values, dtype=np.float64)
        where = self.source or self.key
        if p.ndim != 2 or p.shape[1] not in (1, 2) or v.shape != (p.shape[0],):
            raise ParameterError(where, p.shape, "k samples of x (2-D) or (x, y) (3-D)")
        if not (np.all(np.isfinite(p)) and np.all(np.isfinite(v))):
            raise ParameterError(where, "non-finite values", "finite coordinates and values")
        if p.shape[1] == 1:
            order = np.argsort(p[:, 0], kind="stable")
            p, v = p[order], v[order]
            if p.shape[0] < 2 or np.any(np.diff(p[:, 0]) <= 0):
                raise ParameterError(where, "repeated or single x", "two or more distinct x")
        elif p.shape[0] < 3 or np.linalg.matrix_rank(p[1:] - p[0]) < 2:
            raise ParameterError(where, "samples on a line", "(x, y) samples spanning an area")
        p.setflags(write=False)
        v.setflags(write=False)
        object.__setattr__(self, "points", p)
        object.__setattr__(self, "values", v)

    def at(self, xy: np.ndarray) -> np.ndarray:
        """The parameter at in-plane points ``xy`` (P, d - 1) [m], linearly interpolated."""
        xy = np.asarray(xy, dtype=np.float64)
        if xy.shape[1] != self.points.shape[1]:
            want = "x (a 2-D block)" if self.points.shape[1] == 1 else "x, y (a 3-D block)"
            raise ParameterError(self.source or self.key, "samples of " + want,
                                 f"{xy.shape[1]} coordinate(s) per sample")  # fmt: skip
        if xy.shape[1] == 1:
            x, lo, hi = xy[:, 0], self.points[0, 0], self.points[-1, 0]
            tol = 1e-12 * max(hi - lo, abs(lo), abs(hi))
            inner = np.interp(x, self.points[:, 0], self.values)
            out = np.where((x < lo - tol) | (x > hi + tol), np.nan, inner)
        else:
            from scipy.interpolate import LinearNDInterpolator

            out = LinearNDInterpolator(self.points, self.values)(xy)
        bad = np.flatnonzero(~np.isfinite(out))
        if bad.size:
            span = " x ".join(
                f"[{self.points[:, a].min():.6g}, {self.points[:, a].max():.6g}]"
                for a in range(xy.shape[1])
            )
            point = ", ".join(f"{c:.6g}" for c in xy[bad[0]])
            raise ParameterError(
                self.source or self.key, f"samples over {span} m",
                f"samples covering every contact point (({point}) m is outside)",
            )  # fmt: skip
        return np.asarray(out, dtype=np.float64)


@dataclass(frozen=True)
class LawRegion:
    """A part of the interface with its own law values.

    Attributes
    ----------
    values:
        Law parameters -> a value (:data:`FIELD_KEYS`) or a pair (:data:`PAIR_KEYS`),
        in the stored conventions (angle in rad, orthotropy "divide").
    x, y:
        Closed coordinate ranges [m] the region covers (None: unbounded along that axis).
    group:
        A named group of an imported mesh: the region holds the contact points whose facet
        has all its nodes in the group (``groups`` of :meth:`LawField.resolve`); with
        ``x``/``y`` the intersection.
    name:
        Named in messages (e.g. ``[[law_region]] #2``).
    """

    values: Mapping[str, Any]
    x: tuple[float, float] | None = None
    y: tuple[float, float] | None = None
    group: str | None = None
    name: str = "region"

    def __post_init__(self) -> None:
        for key, value in self.values.items():
            shape = (2,) if key in PAIR_KEYS else ()
            if key not in FIELD_KEYS + PAIR_KEYS or np.shape(value) != shape:
                raise ParameterError(
                    f"{self.name}.{key}", value,
                    "one value of " + ", ".join(FIELD_KEYS) + " or a pair of "
                    + ", ".join(PAIR_KEYS),
                )  # fmt: skip
        for axis in ("x", "y"):
            span = getattr(self, axis)
            if span is None:
                continue
            lo, hi = (float(s) for s in span)
            if not (np.isfinite(lo) and np.isfinite(hi) and lo <= hi):
                raise ParameterError(
                    f"{self.name}.{axis}", list(span), "[from, to] with from <= to"
                )
            object.__setattr__(self, axis, (lo, hi))

    def contains(
        self, xy: np.ndarray, groups: Mapping[str, np.ndarray] | None = None
    ) -> np.ndarray:
        """(P,) True at the in-plane points ``xy`` (P, d - 1) inside the region;
        ``groups`` maps a group name to its (P,) membership of the points."""
        inside = np.ones(xy.shape[0], dtype=bool)
        if self.group is not None:
            if groups is None or self.group not in groups:
                raise ParameterError(f"{self.name}.group", self.group, "a group of the mesh")
            inside &= np.asarray(groups[self.group], dtype=bool)
        for a, span in enumerate((self.x, self.y)):
            if span is None:
                continue
            if a >= xy.shape[1]:
                raise ParameterError(f"{self.name}.y", list(span), "unset for a 2-D block")
            inside &= (xy[:, a] >= span[0]) & (xy[:, a] <= span[1])
        return inside


@dataclass(frozen=True)
class LawField:
    """Tables, then regions, applied to the interface law (see the module docstring)."""

    tables: tuple[LawTable, ...] = ()
    regions: tuple[LawRegion, ...] = field(default=())

    def __bool__(self) -> bool:
        return bool(self.tables or self.regions)

    def resolve(
        self,
        params: SubloadingParams,
        xy: np.ndarray,
        groups: Mapping[str, np.ndarray] | None = None,
    ) -> SubloadingParams:
        """The law at the contact points ``xy`` (P, d - 1) [m]: per-point arrays of the
        varying parameters (``params`` itself when nothing varies). ``groups``: each
        region group's (P,) membership."""
        if not self:
            return params
        if params.per_point:
            raise ParameterError("law", "per-point parameters", "scalar values and a field")
        xy = np.asarray(xy, dtype=np.float64)
        n = xy.shape[0]
        varying: dict[str, np.ndarray] = {}

        def column(key: str) -> np.ndarray:
            if key not in varying:
                base = getattr(params, key)
                if base is None:
                    raise ParameterError(
                        key, "varied", f"a parameter of the surface '{params.surface}'"
                    )
                shape = (n, 2) if key in PAIR_KEYS else (n,)
                varying[key] = np.array(np.broadcast_to(base, shape), dtype=np.float64)
            return varying[key]

        for table in self.tables:
            column(table.key)[:] = table.at(xy)
        for region in self.regions:
            inside = region.contains(xy, groups)
            for key, value in region.values.items():
                column(key)[inside] = value
        return params.replace(**varying, orthotropy_convention="divide")
