"""Material parameters of the subloading-friction law of Hashiguchi & Ozaki (2008).

:class:`SubloadingParams` is a frozen, validated description of one contact interface.
Numeric fields are either scalars (shared by all points) or arrays of shape ``(N,)``
(one value per contact point); the options (surface family, integrators, conventions)
are shared by every point of one call.

Units (SI). Coulomb cone: ``mu_s``, ``mu_k`` dimensionless, ``kappa`` [1/m], ``xi``
[1/s]. Closed surfaces: ``F_s``, ``F_k`` [Pa], ``kappa`` [Pa/m], ``xi`` [Pa/s], ``M``
dimensionless. Always: ``alpha_n``, ``alpha_t`` [Pa/m], ``u`` [1/m].
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field, fields
from typing import Any, ClassVar

import numpy as np

from frictionlab._arrays import readonly as _readonly
from frictionlab.errors import ParameterError

__all__ = [
    "F_INTEGRATORS",
    "OPEN_RECOVERY",
    "ORTHOTROPY_CONVENTIONS",
    "RECOVERY_FORMS",
    "SURFACES",
    "U_LAWS",
    "SubloadingParams",
]

#: Sliding-yield surface families: the Coulomb cone (Eqs 67, 95) and the closed surfaces
#: of Eqs (51)–(54).
SURFACES: tuple[str, ...] = ("coulomb", "cam_clay", "modified_cam_clay", "tear", "parabola")
#: Forms of U(R): Eq (28) ``u cot(pi R/2)`` (default) and Eq (30) ``-u ln R``.
U_LAWS: tuple[str, ...] = ("cot", "ln")
#: Integrators of F over a step: exponential (exact for constant rates when m = n = 1)
#: or backward Euler (the monotone scalar equation of one step).
F_INTEGRATORS: tuple[str, ...] = ("exponential", "backward_euler")
#: Recovery term of Eq (25): ``xi (1 - F/F_s)^n`` (default) or ``xi (F_s/F - 1)^n``
#: (the paper's printed form is ambiguous; see docs/theory.md).
RECOVERY_FORMS: tuple[str, ...] = ("one_minus", "ratio")
#: Orthotropy input convention: coefficient ``C_i mu`` ("divide", default)
#: or ``mu / sqrt(C_i)`` ("multiply", converted on input by C_div = C_mult**-0.5).
ORTHOTROPY_CONVENTIONS: tuple[str, ...] = ("divide", "multiply")
#: What F does while the contact is open: the recovery continues (default) or F is frozen.
OPEN_RECOVERY: tuple[str, ...] = ("continue", "frozen")

_CODES: dict[str, tuple[str, ...]] = {
    "surface": SURFACES,
    "U_law": U_LAWS,
    "F_integrator": F_INTEGRATORS,
    "recovery_form": RECOVERY_FORMS,
    "open_recovery": OPEN_RECOVERY,
}


@dataclass(frozen=True)
class SubloadingParams:
    """Parameters of the subloading-friction law.

    Give ``mu_s`` and ``mu_k`` for the Coulomb cone, ``F_s``, ``F_k`` and ``M`` for a
    closed surface. Numeric fields accept a scalar or an ``(N,)`` array.

    Attributes
    ----------
    surface:
        ``"coulomb"`` (Eq 67), ``"cam_clay"`` (Eq 51, g = exp chi), ``"modified_cam_clay"``
        (Eq 52, g = 1 + chi^2), ``"tear"`` (Eq 53, g = (1 - a chi^2)^-k, a = 1/(2k+1);
        default k = 1 gives 3/(3 - chi^2)), ``"parabola"`` (Eq 54, g = 2/(2 - chi)).
    alpha_n, alpha_t:
        Normal and tangential elastic contact moduli, Eq (16) [Pa/m].
    mu_s, mu_k:
        Static (maximum) and kinetic (minimum) friction coefficients of the cone, Eq (69).
    F_s, F_k:
        Static and kinetic sizes of a closed sliding-yield surface, Eq (25) [Pa].
    M:
        Traction ratio at the top of a closed surface, Eq (50).
    u:
        Constant of U(R), Eq (28) or (30) [1/m].
    kappa:
        Softening rate by plastic sliding, Eq (25) [F units per m].
    xi:
        Recovery rate with time, Eq (25) [F units per s].
    m, n:
        Softening and recovery exponents of Eq (25) (the paper's m and n). Default 1.
    rotation:
        The rotational-anisotropy vector beta = (beta_1, beta_2) in the contact frame,
        Eqs (17)–(19); tangential, constant in the co-rotating frame. Shape (2,) or (N, 2).
    orthotropy:
        (C_1, C_2) for the cone, Eq (95); for closed surfaces the factors on M, so that
        M_i = C_i M, Eq (83). Default (1, 1) (isotropic).
    orthotropy_angle:
        Angle [rad] from the contact-frame axis e_1 to the principal axis e*_1 of
        orthotropy (counter-clockwise about n). Default 0.
    orthotropy_convention:
        ``"divide"`` (default, coefficient C_i mu along e*_i) or ``"multiply"`` (the
        alternative reading sqrt(C_1 f1^2 + C_2 f2^2); converted to ``"divide"`` on
        input by C -> C**-0.5). The stored ``orthotropy`` is always in the
        "divide" convention.
    tear_k:
        Exponent k of the tear family ``g = (1 - a chi^2)^-k``, ``a = 1/(2k + 1)``. Default 1.
    U_law:
        ``"cot"`` (Eq 28, default, integrated in closed form Eq 29) or ``"ln"`` (Eq 30,
        implicit Euler).
    F_integrator:
        ``"exponential"`` (default; exact for constant rates when m = n = 1, otherwise an
        exact-recovery-then-exact-softening split) or ``"backward_euler"`` (implicit in F,
        first order).
    recovery_form:
        ``"one_minus"`` (default, xi (1 - F/F_s)^n) or ``"ratio"`` (xi (F_s/F - 1)^n).
    open_recovery:
        ``"continue"`` (default: F recovers while the contact is open) or ``"frozen"``.
    """

    surface: str = "coulomb"
    alpha_n: Any = 1000.0
    alpha_t: Any = 1000.0
    mu_s: Any = None
    mu_k: Any = None
    F_s: Any = None
    F_k: Any = None
    M: Any = None
    u: Any = 100.0
    kappa: Any = 1.0
    xi: Any = 1.0e-3
    m: Any = 1.0
    n: Any = 1.0
    rotation: Any = (0.0, 0.0)
    orthotropy: Any = (1.0, 1.0)
    orthotropy_angle: Any = 0.0
    orthotropy_convention: str = "divide"
    tear_k: float = 1.0
    U_law: str = "cot"
    F_integrator: str = "exponential"
    recovery_form: str = "one_minus"
    open_recovery: str = "continue"
    _n_points: int = field(default=1, init=False, repr=False, compare=False)

    _SCALAR_FIELDS: ClassVar[tuple[str, ...]] = (
        "alpha_n", "alpha_t", "mu_s", "mu_k", "F_s", "F_k", "M",
        "u", "kappa", "xi", "m", "n", "orthotropy_angle",
    )  # fmt: skip

    def __post_init__(self) -> None:
        for name, allowed in _CODES.items():
            value = getattr(self, name)
            if value not in allowed:
                raise ParameterError(name, value, "one of " + ", ".join(allowed))
        if self.orthotropy_convention not in ORTHOTROPY_CONVENTIONS:
            raise ParameterError(
                "orthotropy_convention",
                self.orthotropy_convention,
                "one of " + ", ".join(ORTHOTROPY_CONVENTIONS),
            )
        cone = self.surface == "coulomb"
        given = {k: getattr(self, k) is not None for k in ("mu_s", "mu_k", "F_s", "F_k", "M")}
        need, forbid = (
            (("mu_s", "mu_k"), ("F_s", "F_k", "M"))
            if cone
            else (
                ("F_s", "F_k", "M"),
                ("mu_s", "mu_k"),
            )
        )
        for key in need:
            if not given[key]:
                raise ParameterError(key, None, f"a value is required for surface '{self.surface}'")
        for key in forbid:
            if given[key]:
                raise ParameterError(
                    key, getattr(self, key), f"not used by surface '{self.surface}'; leave it unset"
                )
        # Convert every numeric field to a read-only float64 array and find N.
        sizes: set[int] = set()
        for name in self._SCALAR_FIELDS:
            value = getattr(self, name)
            if value is None:
                continue
            arr = _as_float_array(name, value, ndim_max=1)
            if arr.ndim == 1:
                sizes.add(arr.shape[0])
            object.__setattr__(self, name, arr)
        for name in ("rotation", "orthotropy"):
            arr = _as_float_array(name, getattr(self, name), ndim_max=2)
            if arr.shape[-1:] != (2,):
                raise ParameterError(name, arr, "two components, shape (2,) or (N, 2)")
            if arr.ndim == 2:
                sizes.add(arr.shape[0])
            object.__setattr__(self, name, arr)
        if len(sizes) > 1:
            raise ParameterError(
                "parameter arrays", sorted(sizes), "one common number of points N (or scalars)"
            )
        object.__setattr__(self, "_n_points", sizes.pop() if sizes else 1)
        if not (isinstance(self.tear_k, int | float) and math.isfinite(self.tear_k)):
            raise ParameterError("tear_k", self.tear_k, "a finite number > 0")
        if self.tear_k <= 0:
            raise ParameterError("tear_k", self.tear_k, "tear_k > 0")
        object.__setattr__(self, "tear_k", float(self.tear_k))
        if self.orthotropy_convention == "multiply":
            _check_positive("orthotropy", self.orthotropy)
            converted = _readonly(self.orthotropy**-0.5)
            object.__setattr__(self, "orthotropy", converted)
            object.__setattr__(self, "orthotropy_convention", "divide")
        self._validate()

    # ------------------------------------------------------------------ validation
    def _validate(self) -> None:
        _check_positive("alpha_n", self.alpha_n)
        _check_positive("alpha_t", self.alpha_t)
        _check_positive("u", self.u)
        _check_nonnegative("kappa", self.kappa)
        _check_nonnegative("xi", self.xi)
        _check_positive("m", self.m)
        _check_positive("n", self.n)
        _check_positive("orthotropy", self.orthotropy)
        static, kinetic = self.static, self.kinetic
        s_name, k_name = ("mu_s", "mu_k") if self.is_cone else ("F_s", "F_k")
        _check_positive(k_name, kinetic)
        shape = np.broadcast(static, kinetic).shape
        bad = ~(np.broadcast_to(kinetic, shape) <= static)
        if bad.any():
            i = int(np.flatnonzero(bad.ravel())[0])
            s_value = float(np.ravel(np.broadcast_to(static, shape))[i])
            raise ParameterError(
                k_name,
                float(np.ravel(np.broadcast_to(kinetic, shape))[i]),
                f"0 < {k_name} <= {s_name} (= {s_value})",
            )
        if not self.is_cone:
            _check_positive("M", self.M)
        # |beta| measured in the elliptic norm of the surface must stay inside the
        # kinetic cone (cone) or below the top ratio M (closed surfaces), Eqs (17)–(21).
        # The norm acts on the components along the principal axes e*_i (Eqs 83, 95),
        # so beta (given in the contact frame) is first turned by -orthotropy_angle.
        axes = self.axis_factors
        c, s = np.cos(self.orthotropy_angle), np.sin(self.orthotropy_angle)
        b1, b2 = self.rotation[..., 0], self.rotation[..., 1]
        beta_principal = np.stack(np.broadcast_arrays(c * b1 + s * b2, c * b2 - s * b1), axis=-1)
        beta_norm = np.sqrt(np.sum((beta_principal / axes) ** 2, axis=-1))
        limit = kinetic if self.is_cone else np.ones_like(beta_norm)
        over = np.broadcast_to(beta_norm >= limit, np.broadcast(beta_norm, limit).shape)
        if over.any():
            what = "mu_k" if self.is_cone else "1 (i.e. |beta| < M in the norm of Eq 83)"
            raise ParameterError(
                "rotation",
                self.rotation,
                f"|beta| (scaled by the orthotropy axes) < {what}",
            )

    # ------------------------------------------------------------------ derived views
    @property
    def is_cone(self) -> bool:
        """True for the Coulomb cone (degree-zero f, F is mu)."""
        return self.surface == "coulomb"

    @property
    def static(self) -> np.ndarray:
        """F_s, or mu_s for the cone."""
        return self.mu_s if self.is_cone else self.F_s

    @property
    def kinetic(self) -> np.ndarray:
        """F_k, or mu_k for the cone."""
        return self.mu_k if self.is_cone else self.F_k

    @property
    def axis_factors(self) -> np.ndarray:
        """(A_1, A_2): C_i for the cone, M C_i for closed surfaces; shape (2,) or (N, 2)."""
        if self.is_cone:
            return self.orthotropy
        return _readonly(np.asarray(self.M)[..., None] * self.orthotropy)

    @property
    def n_points(self) -> int:
        """Number of points the parameter arrays describe (1 when all are scalars)."""
        return self._n_points

    @functools.cached_property
    def per_point(self) -> bool:
        """True when some numeric parameter is given per point."""
        return any(
            np.ndim(getattr(self, f)) == 1
            for f in self._SCALAR_FIELDS
            if getattr(self, f) is not None
        ) or any(np.ndim(getattr(self, f)) == 2 for f in ("rotation", "orthotropy"))

    @functools.cached_property
    def _kernel_table(self) -> np.ndarray:
        """The kernel's parameter table, built once (read-only)."""
        from frictionlab.subloading.return_map import parameter_table

        table = parameter_table(self)
        table.setflags(write=False)
        return table

    def replace(self, **changes: Any) -> SubloadingParams:
        """A copy with some fields changed (validated again)."""
        values = {f.name: getattr(self, f.name) for f in fields(self) if f.init}
        values.update(changes)
        return SubloadingParams(**values)

    def as_dict(self) -> dict[str, Any]:
        """Plain-Python view (lists for arrays), for JSON summaries."""
        out: dict[str, Any] = {}
        for f in fields(self):
            if not f.init:
                continue
            value = getattr(self, f.name)
            if isinstance(value, np.ndarray):
                value = value.tolist()
            out[f.name] = value
        return out


def _as_float_array(name: str, value: Any, ndim_max: int) -> np.ndarray:
    try:
        arr = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError(name, value, "a real number or an array of real numbers") from None
    if arr.ndim > ndim_max:
        raise ParameterError(name, value, f"at most {ndim_max}-dimensional")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(name, value, "finite values (no NaN or infinity)")
    arr.setflags(write=False)
    return arr


def _first_bad(arr: np.ndarray, bad: np.ndarray) -> float:
    return float(np.ravel(arr)[int(np.flatnonzero(np.ravel(bad))[0])])


def _check_positive(name: str, arr: np.ndarray) -> None:
    bad = ~(np.asarray(arr) > 0)
    if bad.any():
        raise ParameterError(name, _first_bad(arr, bad), f"{name} > 0")


def _check_nonnegative(name: str, arr: np.ndarray) -> None:
    bad = ~(np.asarray(arr) >= 0)
    if bad.any():
        raise ParameterError(name, _first_bad(arr, bad), f"{name} >= 0")
