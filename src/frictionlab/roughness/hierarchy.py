"""Hierarchical roughness (Eqs 28-35) and its wear (the paper's section 3.4).

A hierarchy has n levels, i = 1 the innermost (smallest) and i = n the outermost. Each
level is a pair of surfaces (:class:`HierarchyLevel`) and acts as one lattice-spring
model whose local coefficient is the global coefficient of the level below (**Eq 29**)::

    mu_i = f_i(mu_{i-1}),   mu_n = f_n(... f_1(mu0))

where ``f_i`` is the single-level map of :func:`~frictionlab.roughness.lattice.friction_polar`
(Eqs 30-32: Eqs 2-3 with mu0 -> mu_{i-1}). The isotropic Coulomb law holds at every
sub-level and the scalar passed upward is, by option ``mu_passed``,
``"magnitude"`` (default, ``|mu| = sqrt(mu_x^2 + mu_y^2)``) or ``"projection"`` (the
dissipative ``mu_x cos(beta) + mu_y sin(beta)``). Every level slides along the same beta.

* **Eq 28** (self-similar levels, :func:`self_similar_levels`): level i is the outermost
  pair scaled by ``r^-(n-i)`` horizontally *and* vertically (amplitude ``A r^-(n-i)``,
  wavelengths ``lambda r^-(n-i)``), so slopes are identical at every level.
* A user-supplied list of levels must be **strictly nested** (innermost first): every
  period of level i shorter than every period of level i + 1 (:func:`check_nested`).
* **Eqs 33-34** (wedges at beta = 90 deg) are public in
  :mod:`~frictionlab.roughness.closed_forms`; :func:`wedge_hierarchy` iterates the wedge
  closed forms (Eqs 15-16) at any beta.
* **Validity**: Eq 1's bound must hold with mu_{i-1} at every level. A violation
  raises a :class:`~frictionlab.errors.ValidityError` naming the level (``on_invalid=
  "error"``, default) or masks that level and all above it for that direction
  (``"mask"``); nothing is clipped.
* **Hierarchy with wear** (:func:`hierarchy_wear`): the innermost level wears first
  (Archard, :mod:`~frictionlab.roughness.wear`); level i wears during its own window of
  length ``T_w,i = V0_i / (W v)`` (**Eq 35**, V0_i the roughness volume of the level's
  wearing surfaces over the nominal area) with ``B_i = 1 - (t - t_start,i) / T_w,i``;
  when it is flat it passes mu through unchanged (the number of active levels drops by
  one) and the next level starts wearing.

Pure physics: no I/O.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frictionlab._arrays import FloatArray, finite_vector, readonly_masked
from frictionlab._arrays import readonly as _ro
from frictionlab._frames import TableResult
from frictionlab.errors import ParameterError, ValidityError
from frictionlab.roughness.closed_forms import wedge_friction
from frictionlab.roughness.generators import scaled
from frictionlab.roughness.lattice import (
    LatticeSettings,
    check_betas,
    friction_polar,
    long_mu_columns,
)
from frictionlab.roughness.surface import Surface
from frictionlab.roughness.validity import check_on_invalid
from frictionlab.roughness.wear import (
    WearingFriction,
    WearSettings,
    pair_volume,
    wear_time,
    wearing_fields,
    worn_pair,
)

__all__ = [
    "MU_PASSED",
    "HierarchyLevel",
    "HierarchyResult",
    "HierarchyWearHistory",
    "check_nested",
    "hierarchy_friction",
    "hierarchy_wear",
    "self_similar_levels",
    "wedge_hierarchy",
]

#: The scalar passed to the next level; the first is the default.
MU_PASSED = ("magnitude", "projection")
ON_INVALID = ("error", "mask")


@dataclass(frozen=True)
class HierarchyLevel:
    """One level: a lower (fixed) and an upper (sliding) surface; at least one is rough."""

    lower: Surface
    upper: Surface

    def __post_init__(self) -> None:
        for name in ("lower", "upper"):
            if not isinstance(getattr(self, name), Surface):
                raise ParameterError(name, type(getattr(self, name)).__name__, "a Surface")

    @property
    def periods(self) -> list[float]:
        """Every period of both surfaces (m), both axes."""
        return [float(p) for s in (self.lower, self.upper) for p in s.periods if p is not None]

    @property
    def is_flat(self) -> bool:
        return self.lower.is_flat and self.upper.is_flat

    def worn(self, reduction: float, surfaces: str = "both") -> HierarchyLevel:
        """The level with its wearing surfaces' heights scaled by B."""
        lower, upper = worn_pair(self.lower, self.upper, reduction, surfaces)
        return HierarchyLevel(lower, upper)


def _as_levels(levels: Sequence[HierarchyLevel]) -> tuple[HierarchyLevel, ...]:
    if isinstance(levels, HierarchyLevel) or not isinstance(levels, Sequence) or not levels:
        raise ParameterError("levels", levels, "a non-empty sequence of HierarchyLevel")
    for i, level in enumerate(levels, 1):
        if not isinstance(level, HierarchyLevel):
            raise ParameterError(f"levels[{i}]", type(level).__name__, "a HierarchyLevel")
    return tuple(levels)


def check_nested(levels: Sequence[HierarchyLevel]) -> None:
    """Refuse levels that are not strictly nested (innermost first).

    Every level needs roughness (a period), and every period of level i must be shorter
    than every period of level i + 1.
    """
    seq = _as_levels(levels)
    for i, level in enumerate(seq, 1):
        if not level.periods or level.is_flat:
            raise ParameterError(
                f"levels[{i}]", "two flat surfaces", "a level with roughness (a period)"
            )
    for i in range(len(seq) - 1):
        inner, outer = max(seq[i].periods), min(seq[i + 1].periods)
        if not inner < outer:
            raise ParameterError(
                "levels",
                f"level {i + 1} period {inner:.6g} m >= level {i + 2} period {outer:.6g} m",
                "strictly nested levels, innermost first: every period of level i shorter "
                "than every period of level i + 1",
            )


def self_similar_levels(
    lower: Surface, upper: Surface, n: int, ratio: float
) -> tuple[HierarchyLevel, ...]:
    """Eq 28: n self-similar levels whose outermost (level n) is the pair (lower, upper).

    Level i is the pair scaled by ``ratio^-(n-i)`` in heights and lengths alike (the
    paper's ``A = B = C``, ``a = -(n - i)``, ``b = c = n - i``), so slopes are the same at
    every level. ``n`` >= 1; ``ratio`` > 1 and large enough for strict nesting (greater
    than the ratio of the pair's largest to shortest period).
    """
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 1:
        raise ParameterError("n", n, "an integer number of levels >= 1")
    if not (isinstance(ratio, int | float) and math.isfinite(ratio) and ratio > 1.0):
        raise ParameterError("ratio", ratio, "a scale factor between levels > 1")
    levels = []
    for i in range(1, int(n) + 1):
        f = float(ratio) ** (-(int(n) - i))
        levels.append(HierarchyLevel(scaled(lower, f, f), scaled(upper, f, f)))  # type: ignore[arg-type]
    out = tuple(levels)
    check_nested(out)
    return out


@dataclass(frozen=True, repr=False)
class HierarchyResult(TableResult):
    """mu_i of every level (rows i = 0 ... n; row 0 is the local mu0) per direction.

    ``mu`` is the scalar passed upward (option ``mu_passed``); ``mu_x``, ``mu_y`` the
    components of each level. Entries beyond the validity domain are masked (``valid``
    False); ``first_invalid_level`` is 0 where every level is valid.
    """

    beta_deg: FloatArray
    mu: np.ma.MaskedArray
    mu_x: np.ma.MaskedArray
    mu_y: np.ma.MaskedArray
    valid: NDArray[np.bool_]
    first_invalid_level: NDArray[np.int64]
    mu0: float
    mu_passed: str
    messages: tuple[str, ...]

    @property
    def n_levels(self) -> int:
        return int(self.mu.shape[0]) - 1

    @property
    def success(self) -> bool:
        return bool(np.all(self.valid))

    def columns(self) -> dict[str, np.ndarray]:
        """A long table, one row per (level, beta), level-major; invalid entries masked."""
        n1, n_b = self.mu.shape
        out: dict[str, np.ndarray] = {
            "level": np.repeat(np.arange(n1), n_b),
            **long_mu_columns(self, n1),
        }
        out["valid"] = self.valid.ravel()
        return out

    @staticmethod
    def units() -> dict[str, str]:
        return {"beta_deg": "deg"}


def _cos_sin(beta_deg: float) -> tuple[float, float]:
    b = math.fmod(beta_deg, 360.0) + (360.0 if beta_deg < 0.0 else 0.0)
    exact = {0.0: (1.0, 0.0), 90.0: (0.0, 1.0), 180.0: (-1.0, 0.0), 270.0: (0.0, -1.0)}
    if b in exact:
        return exact[b]
    return math.cos(math.radians(b)), math.sin(math.radians(b))


def _check_options(mu0: float, mu_passed: str, on_invalid: str) -> tuple[float, str]:
    if not (isinstance(mu0, int | float) and math.isfinite(mu0) and mu0 >= 0.0):
        raise ParameterError("mu0", mu0, "a finite local coefficient >= 0")
    if mu_passed not in MU_PASSED:
        raise ParameterError("mu_passed", mu_passed, f"one of {MU_PASSED}")
    return float(mu0), check_on_invalid(on_invalid, ON_INVALID)


def _recursion(
    maps: Sequence[Any],
    mu0: float,
    betas: FloatArray,
    mu_passed: str,
    on_invalid: str,
) -> HierarchyResult:
    """Iterate level maps ``map(mu, beta) -> (mu_x, mu_y, message or None)``."""
    n = len(maps)
    mu = np.zeros((n + 1, betas.size))
    mu_x = np.zeros_like(mu)
    mu_y = np.zeros_like(mu)
    valid = np.ones((n + 1, betas.size), dtype=bool)
    first_bad = np.zeros(betas.size, dtype=np.int64)
    messages = []
    for k, beta in enumerate(betas):
        cb, sb = _cos_sin(float(beta))
        m = mu0
        mu[0, k], mu_x[0, k], mu_y[0, k] = mu0, mu0 * cb, mu0 * sb
        for i, level_map in enumerate(maps, 1):
            mx, my, problem = level_map(m, float(beta))
            if problem is not None:
                text = (
                    f"hierarchy level {i} of {n} (local coefficient mu_{i - 1} = {m:.6g}, "
                    f"beta = {beta:g} deg) leaves the validity domain: {problem}"
                )
                if on_invalid == "error":
                    raise ValidityError(text)
                messages.append(text)
                valid[i:, k] = False
                first_bad[k] = i
                break
            m = math.hypot(mx, my) if mu_passed == "magnitude" else mx * cb + my * sb
            mu[i, k], mu_x[i, k], mu_y[i, k] = m, mx, my
    invalid = ~valid
    return HierarchyResult(
        beta_deg=_ro(betas),
        mu=readonly_masked(mu, invalid),
        mu_x=readonly_masked(mu_x, invalid),
        mu_y=readonly_masked(mu_y, invalid),
        valid=_ro(valid, bool),
        first_invalid_level=_ro(first_bad, np.int64),
        mu0=mu0,
        mu_passed=mu_passed,
        messages=tuple(messages),
    )


def _lattice_map(level: HierarchyLevel, settings: LatticeSettings) -> Any:
    if level.is_flat:  # a flat level (e.g. worn away) passes mu through exactly

        def passthrough(m: float, beta: float) -> tuple[float, float, str | None]:
            cb, sb = _cos_sin(beta)
            return m * cb, m * sb, None

        return passthrough
    masked = replace(settings, on_invalid="mask")

    def level_map(m: float, beta: float) -> tuple[float, float, str | None]:
        polar = friction_polar(level.lower, level.upper, m, [beta], settings=masked)
        if not polar.valid[0]:
            return math.nan, math.nan, polar.invalid_messages[0]
        return float(polar.mu_x[0]), float(polar.mu_y[0]), None

    return level_map


def hierarchy_friction(
    levels: Sequence[HierarchyLevel],
    mu0: float,
    beta_deg: ArrayLike,
    *,
    mu_passed: str = "magnitude",
    on_invalid: str = "error",
    settings: LatticeSettings | None = None,
    check: bool = True,
) -> HierarchyResult:
    """Eq 29 on the lattice: mu_i = f_i(mu_{i-1}) for every level and direction.

    Parameters
    ----------
    levels:
        Levels innermost first (e.g. :func:`self_similar_levels`); checked for strict
        nesting unless ``check=False`` (worn levels may be flat).
    mu0:
        The local coefficient of the innermost contacts.
    beta_deg:
        Sliding directions (deg), the same at every level.
    mu_passed:
        ``"magnitude"`` (default) or ``"projection"``.
    on_invalid:
        ``"error"`` (default; ValidityError naming the level) or ``"mask"`` (the old
        spelling ``"raise"`` warns).
    settings:
        Lattice settings of every level (default: full contact, default resolution);
        their ``on_invalid`` is superseded by this function's.
    """
    m0, on_invalid = _check_options(mu0, mu_passed, on_invalid)
    seq = _as_levels(levels)
    if check:
        check_nested(seq)
    lattice = settings or LatticeSettings()
    maps = [_lattice_map(level, lattice) for level in seq]
    return _recursion(maps, m0, check_betas(beta_deg), mu_passed, on_invalid)


def wedge_hierarchy(
    mu0: float,
    angles_deg: ArrayLike,
    beta_deg: ArrayLike,
    n: int,
    *,
    mu_passed: str = "magnitude",
    on_invalid: str = "error",
) -> HierarchyResult:
    """n self-similar levels of wedge profiles by the closed forms (Eqs 15-16 iterated).

    ``angles_deg = (phi1, phi2, phi3, phi4)`` as in
    :func:`~frictionlab.roughness.closed_forms.wedge_friction` (the same at every level:
    self-similar). At beta = 90 deg the symmetric cases reproduce Eqs 33-34; at beta = 0
    there is no closed form and the recursion can leave the validity domain.
    """
    m0, on_invalid = _check_options(mu0, mu_passed, on_invalid)
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 0:
        raise ParameterError("n", n, "an integer number of levels >= 0")
    angles = np.asarray(angles_deg, dtype=np.float64)
    if angles.shape != (4,):
        raise ParameterError("angles_deg", angles_deg, "four angles (phi1, phi2, phi3, phi4)")

    def level_map(m: float, beta: float) -> tuple[float, float, str | None]:
        try:
            mx, my = wedge_friction(m, angles, beta)
        except ValidityError as exc:
            return math.nan, math.nan, str(exc)
        return float(mx), float(my), None

    return _recursion([level_map] * int(n), m0, check_betas(beta_deg), mu_passed, on_invalid)


@dataclass(frozen=True, repr=False)
class HierarchyWearHistory(WearingFriction):
    """mu_i(t) of every level of a wearing hierarchy (innermost level first).

    The fields of :class:`~frictionlab.roughness.wear.WearingFriction`, then these:
    ``reduction`` holds B_i(t) of each level, shape (n_t, n); ``mu``, ``mu_x``, ``mu_y``
    have shape (n_t, n + 1, n_beta): row 0 is mu0, row i the global coefficient of level
    i (``mu`` is the scalar passed upward).

    Attributes
    ----------
    wear_time:
        T_w,i of each level (s), Eq 35, shape (n,).
    start_time, dropout_time:
        When level i starts wearing and when it is flat (s), shape (n,).
    volume:
        The roughness volume of each level's wearing surfaces (m^3), shape (n,).
    active_levels:
        Number of levels not yet flat at each time, shape (n_t,).
    """

    wear_time: FloatArray
    start_time: FloatArray
    dropout_time: FloatArray
    volume: FloatArray
    active_levels: NDArray[np.int64]
    mu0: float
    mu_passed: str
    wear: WearSettings

    @property
    def n_levels(self) -> int:
        return int(self.wear_time.size)

    def columns(self) -> dict[str, np.ndarray]:
        """A long table, one row per (time, beta): B_i and mu_i of every level."""
        n_t, n1, n_b = self.mu.shape
        out: dict[str, np.ndarray] = {
            "time_s": np.repeat(self.time, n_b),
            "beta_deg": np.tile(self.beta_deg, n_t),
            "active_levels": np.repeat(self.active_levels, n_b),
        }
        for i in range(1, n1):
            out[f"B_{i}"] = np.repeat(self.reduction[:, i - 1], n_b)
        for i in range(n1):
            out[f"mu_{i}"] = self.mu[:, i, :].ravel()
        if self.mu0 > 0.0:
            for i in range(n1):
                out[f"mu_{i}_over_mu0"] = self.mu[:, i, :].ravel() / self.mu0
        return out

    @staticmethod
    def units() -> dict[str, str]:
        return {"time_s": "s", "beta_deg": "deg"}


def hierarchy_wear(
    levels: Sequence[HierarchyLevel],
    mu0: float,
    beta_deg: ArrayLike,
    wear: WearSettings,
    *,
    samples_per_level: int = 11,
    times: ArrayLike | None = None,
    mu_passed: str = "magnitude",
    settings: LatticeSettings | None = None,
) -> HierarchyWearHistory:
    """mu_i(t) of every level while the levels wear one after another, innermost first.

    Level i wears during ``[t_start,i, t_start,i + T_w,i]`` with ``T_w,i = V0_i / (W v)``
    (Eq 35) and ``t_start,i = sum_{j < i} T_w,j``; within it ``B_i = 1 - (t -
    t_start,i) / T_w,i``, before it 1, after it 0. The unworn hierarchy must be valid
    (ValidityError otherwise); wear only lowers slopes and coefficients. Times: ``times``
    (s), or ``samples_per_level`` (>= 2) equally spaced points per window (windows share
    their end points).
    """
    m0, _ = _check_options(mu0, mu_passed, "error")
    seq = _as_levels(levels)
    check_nested(seq)
    betas = check_betas(beta_deg)
    volumes = np.array([pair_volume(level.lower, level.upper, wear) for level in seq])
    tw = np.array([wear_time(float(v), wear.volume_rate) for v in volumes])
    start = np.concatenate(([0.0], np.cumsum(tw)[:-1]))
    end = start + tw
    if times is None:
        if (
            isinstance(samples_per_level, bool)
            or not isinstance(samples_per_level, int)
            or samples_per_level < 2
        ):
            raise ParameterError("samples_per_level", samples_per_level, "an integer >= 2")
        parts = [np.linspace(s, e, samples_per_level)[:-1] for s, e in zip(start, end, strict=True)]
        t = np.concatenate([*parts, end[-1:]])
    else:
        t = finite_vector("times", times, "a non-empty list of times >= 0 s", minimum=0.0)
    lattice = settings or LatticeSettings()
    n = len(seq)
    reduction = np.clip(1.0 - (t[:, None] - start[None, :]) / tw[None, :], 0.0, 1.0)
    # Window ends are exact: B_i = 0 from the drop-out time on.
    reduction[t[:, None] >= end[None, :]] = 0.0
    mu = np.empty((t.size, n + 1, betas.size))
    mu_x = np.empty_like(mu)
    mu_y = np.empty_like(mu)
    for k in range(t.size):
        worn = [level.worn(float(reduction[k, i]), wear.surfaces) for i, level in enumerate(seq)]
        result = hierarchy_friction(
            worn, m0, betas, mu_passed=mu_passed, settings=lattice, check=False
        )
        mu[k], mu_x[k], mu_y[k] = (np.ma.getdata(a) for a in (result.mu, result.mu_x, result.mu_y))
    return HierarchyWearHistory(
        **wearing_fields(t, reduction, betas, mu, mu_x, mu_y),
        wear_time=_ro(tw),
        start_time=_ro(start),
        dropout_time=_ro(end),
        volume=_ro(volumes),
        active_levels=_ro(np.count_nonzero(reduction > 0.0, axis=1), np.int64),
        mu0=m0,
        mu_passed=mu_passed,
        wear=wear,
    )
