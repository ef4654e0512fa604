"""Archard wear of rough surfaces and the friction history mu(t) (Eqs 23-28w).

* **Eq 23** (Archard): worn volume ``V = K L s / H`` over a sliding distance s, i.e. the
  wear rate ``W = V / s = K L / H`` (m^3/m) and the volume-loss rate ``W v`` (m^3/s) at
  sliding speed v. K is dimensionless, the normal load L in N, the hardness H in Pa.
* Wear scales the roughness **vertically** above its fixed valley: ``z(t) = B(t) z0``, so
  every slope scales by B (a wedge keeps its face shares, ``tan phi(t) = B tan phi0``).
* **Eqs 24-27**: the removed volume ``(1 - B) V0`` equals ``W v t``, where ``V0`` is the
  roughness volume above the valley (``z - z_min``) over the nominal contact
  area: ``V0 = A_n <z - z_min>`` (2-D: ``A_n`` is the apparent area; 1-D: ``A_n = Y (x_f -
  x_0)``, the depth Y along the ridges times the length). Hence the **reduction
  coefficient** ``B(t) = 1 - t / T_w`` (0 after T_w) and the **wear time**
  ``T_w = V0 / (W v)``.
* **Eq 28w** (wedge; the printed form is uncertain): the linear law
  ``tan phi(t) = tan phi0 (1 - t / T_w)`` (default and only law), equivalent to the
  reconstructed rate form ``d tan(phi)/dt = -2 q / (S1^2 Y)`` with q the volume-loss rate
  attributed to one face of horizontal length S1 (:func:`wedge_tan_phi_rate`).
* **mu(t)**: the friction coefficient of the worn pair, from mu(B = 1) to exactly mu0
  at ``t = T_w`` when both surfaces are flat (:func:`wear_history`).

Which surfaces wear (option ``surfaces`` of :class:`WearSettings`):
``"both"`` (default: both rough surfaces share one B; the volume of both is removed, so
``T_w = (V0_lower + V0_upper) / (W v)``), ``"lower"`` or ``"upper"`` (only that surface
wears; ``T_w = V0_that / (W v)``; the other keeps its roughness, so mu(T_w) is the value
of a flat surface on the unworn one).

Pure physics: no I/O.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray, finite_vector
from frictionlab._arrays import readonly as _ro
from frictionlab._frames import TableResult
from frictionlab.errors import ParameterError
from frictionlab.roughness.closed_forms import wedge_friction
from frictionlab.roughness.generators import (
    FlatProfile,
    ProductSineMap,
    ScaledHeightMap,
    ScaledProfile,
    SineProfile,
    SmoothWedgeProfile,
    WedgeProfile,
    scaled,
)
from frictionlab.roughness.lattice import (
    LatticeSettings,
    check_betas,
    friction_polar,
    long_mu_columns,
)
from frictionlab.roughness.surface import (
    Profile,
    SampledHeightMap,
    SampledProfile,
    Surface,
)

__all__ = [
    "WEAR_METHODS",
    "WEAR_SURFACES",
    "WearHistory",
    "WearSettings",
    "WearingFriction",
    "archard_volume",
    "mean_height_above_valley",
    "pair_volume",
    "reduction_coefficient",
    "roughness_volume",
    "wear_history",
    "wear_time",
    "wearing_fields",
    "wedge_height",
    "wedge_tan_phi",
    "wedge_tan_phi_rate",
    "worn_pair",
]

#: Which surfaces wear; the first is the default.
WEAR_SURFACES = ("both", "lower", "upper")
#: How mu(B) is computed: "auto" (Eqs 15-16 for wedge/flat pairs, else the lattice),
#: "lattice", "closed_form" (wedge/flat pairs only).
WEAR_METHODS = ("auto", "lattice", "closed_form")

#: Grid points per axis for the numerical mean height of surfaces without a closed form.
_MEAN_POINTS_1D = 8192
_MEAN_POINTS_2D = 512


def _positive(name: str, value: Any, unit: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating):
        raise ParameterError(name, value, f"a positive number in {unit}")
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise ParameterError(name, value, f"a finite number > 0 ({unit})")
    return v


@dataclass(frozen=True)
class WearSettings:
    """Archard wear inputs, SI units (validated).

    Attributes
    ----------
    wear_coefficient:
        K (dimensionless), > 0.
    hardness:
        H of the softer material (Pa), > 0.
    normal_load:
        Normal load on the nominal contact (N), > 0. (Not the lattice's load per spring.)
    velocity:
        Sliding speed v (m/s), > 0.
    nominal_area:
        Apparent contact area A_n (m^2), > 0; for 1-D roughness the depth Y along the
        ridges times the length along x.
    surfaces:
        ``"both"`` (default), ``"lower"`` or ``"upper"``: which surfaces wear.
    """

    wear_coefficient: float
    hardness: float
    normal_load: float
    velocity: float
    nominal_area: float
    surfaces: str = "both"

    def __post_init__(self) -> None:
        for name, unit in (
            ("wear_coefficient", "1 (dimensionless)"),
            ("hardness", "Pa"),
            ("normal_load", "N"),
            ("velocity", "m/s"),
            ("nominal_area", "m^2"),
        ):
            object.__setattr__(self, name, _positive(name, getattr(self, name), unit))
        if self.surfaces not in WEAR_SURFACES:
            raise ParameterError("surfaces", self.surfaces, f"one of {WEAR_SURFACES}")

    @property
    def wear_rate(self) -> float:
        """W = K L / H (m^3 per m of sliding), Eq 23."""
        return self.wear_coefficient * self.normal_load / self.hardness

    @property
    def volume_rate(self) -> float:
        """W v (m^3/s), the worn volume per unit time."""
        return self.wear_rate * self.velocity

    def as_dict(self) -> dict[str, Any]:
        return {
            "wear_coefficient": self.wear_coefficient,
            "hardness_Pa": self.hardness,
            "normal_load_N": self.normal_load,
            "velocity_m_per_s": self.velocity,
            "nominal_area_m2": self.nominal_area,
            "surfaces": self.surfaces,
            "wear_rate_m3_per_m": self.wear_rate,
            "volume_rate_m3_per_s": self.volume_rate,
        }


def archard_volume(
    wear_coefficient: float, normal_load: float, distance: ArrayLike, hardness: float
) -> FloatArray:
    """Eq 23: the worn volume ``V = K L s / H`` (m^3) after sliding ``distance`` s (m).

    K dimensionless (> 0), L in N (> 0), H in Pa (> 0), s >= 0.
    """
    k = _positive("wear_coefficient", wear_coefficient, "1 (dimensionless)")
    load = _positive("normal_load", normal_load, "N")
    h = _positive("hardness", hardness, "Pa")
    s = np.asarray(distance, dtype=np.float64)
    if not np.all(np.isfinite(s) & (s >= 0.0)):
        raise ParameterError("distance", distance, "finite sliding distances >= 0 m")
    return np.asarray(k * load * s / h, dtype=np.float64)


def wear_time(volume: float, volume_rate: float) -> float:
    """Eqs 27 and 35: ``T_w = V0 / (W v)`` (s), the time to remove the volume V0 (m^3)
    at the volume-loss rate ``W v`` (m^3/s)."""
    if not (isinstance(volume, int | float) and math.isfinite(volume) and volume >= 0.0):
        raise ParameterError("volume", volume, "a finite volume >= 0 m^3")
    return float(volume) / _positive("volume_rate", volume_rate, "m^3/s")


def reduction_coefficient(time: ArrayLike, wear_time_s: float) -> FloatArray:
    """Eqs 25 and 27: ``B(t) = 1 - t / T_w`` for 0 <= t <= T_w and 0 afterwards.

    B = 1: unworn; B = 0: flat. ``time`` (s) >= 0; ``wear_time_s`` (s) > 0.
    """
    tw = _positive("wear_time", wear_time_s, "s")
    t = np.asarray(time, dtype=np.float64)
    if not np.all(np.isfinite(t) & (t >= 0.0)):
        raise ParameterError("time", time, "finite times >= 0 s")
    return np.asarray(np.clip(1.0 - t / tw, 0.0, 1.0), dtype=np.float64)


def wedge_tan_phi(tan_phi0: ArrayLike, time: ArrayLike, wear_time_s: float) -> FloatArray:
    """Eq 28w (default linear law): ``tan phi(t) = tan phi0 B(t)``, B of Eq 27."""
    t0 = np.asarray(tan_phi0, dtype=np.float64)
    if not np.all(np.isfinite(t0) & (t0 >= 0.0)):
        raise ParameterError("tan_phi0", tan_phi0, "finite slopes >= 0")
    return np.asarray(t0 * reduction_coefficient(time, wear_time_s), dtype=np.float64)


def wedge_tan_phi_rate(face_volume_rate: float, face_length: float, depth: float) -> float:
    """Eq 28w, rate form: ``d tan(phi)/dt = -2 q / (S1^2 Y)`` (1/s) while the face exists.

    ``q`` (m^3/s) is the volume-loss rate attributed to one face, ``S1`` (m) the face's
    horizontal length, ``Y`` (m) the depth along the ridges. It follows from the area
    under one face, ``S1 * S1 tan(phi) / 2``. For a row of N symmetric wedges of base b
    sharing ``W v`` over their 2N faces it gives ``T_w = N Y b^2 tan(phi0) / (4 W v)``,
    the wear time of Eq 27.
    """
    q = _positive("face_volume_rate", face_volume_rate, "m^3/s")
    s1 = _positive("face_length", face_length, "m")
    y = _positive("depth", depth, "m")
    return -2.0 * q / (s1 * s1 * y)


def mean_height_above_valley(surface: Surface) -> float:
    """``<z - z_min>`` over one period (m): the roughness volume per unit nominal area.

    Exact for flat surfaces (0), wedges and smooth wedges (h/2), sinusoids and product
    sinusoids (A) and sampled surfaces (the mean of the samples minus their minimum);
    other surfaces are sampled on a midpoint grid of 8192 points (1-D) or 512 x 512 (2-D).
    """
    if isinstance(surface, FlatProfile):
        return 0.0
    if isinstance(surface, WedgeProfile):
        return 0.5 * surface.height
    if isinstance(surface, SmoothWedgeProfile):
        return 0.5 * wedge_height(surface)
    if isinstance(surface, SineProfile | ProductSineMap):
        return float(surface.amplitude)
    if isinstance(surface, SampledProfile | SampledHeightMap):
        return float(np.mean(surface.heights) - np.min(surface.heights))
    if isinstance(surface, ScaledProfile | ScaledHeightMap):
        return surface.vertical * mean_height_above_valley(surface.base)
    lx, ly = surface.periods
    if isinstance(surface, Profile):
        if lx is None:
            return 0.0
        x = (np.arange(_MEAN_POINTS_1D) + 0.5) * (lx / _MEAN_POINTS_1D)
        z, _, _ = surface.evaluate(x)
    else:
        assert lx is not None and ly is not None
        n = _MEAN_POINTS_2D
        z, _, _ = surface.evaluate(
            ((np.arange(n) + 0.5) * (lx / n))[:, None], ((np.arange(n) + 0.5) * (ly / n))[None, :]
        )
    return float(np.mean(z) - np.min(z))


def wedge_height(surface: SmoothWedgeProfile) -> float:
    """Peak-to-valley height (m) of a smooth wedge (that of the wedge with its angles)."""
    return WedgeProfile(surface.angles_deg, surface.wavelength).height


def roughness_volume(surface: Surface, nominal_area: float) -> float:
    """Eqs 24 and 26: ``V0 = A_n <z - z_min>`` (m^3), the volume of the roughness above its
    valley over the nominal area ``A_n`` (m^2)."""
    return _positive("nominal_area", nominal_area, "m^2") * mean_height_above_valley(surface)


def _worn_flags(surfaces: str) -> tuple[bool, bool]:
    if surfaces not in WEAR_SURFACES:
        raise ParameterError("surfaces", surfaces, f"one of {WEAR_SURFACES}")
    return surfaces in ("both", "lower"), surfaces in ("both", "upper")


def pair_volume(lower: Surface, upper: Surface, wear: WearSettings) -> float:
    """The roughness volume (m^3) of the surfaces that wear (option ``surfaces``)."""
    wear_lower, wear_upper = _worn_flags(wear.surfaces)
    volume = 0.0
    if wear_lower:
        volume += roughness_volume(lower, wear.nominal_area)
    if wear_upper:
        volume += roughness_volume(upper, wear.nominal_area)
    if volume <= 0.0:
        raise ParameterError(
            "surfaces",
            wear.surfaces,
            "a choice that includes a rough surface (the worn surfaces are flat: nothing to wear)",
        )
    return volume


def worn_pair(
    lower: Surface, upper: Surface, reduction: float, surfaces: str = "both"
) -> tuple[Surface, Surface]:
    """The pair with the wearing surfaces' heights scaled by B (``reduction`` in [0, 1])."""
    if not (isinstance(reduction, int | float) and 0.0 <= float(reduction) <= 1.0):
        raise ParameterError("reduction", reduction, "0 <= B <= 1")
    wear_lower, wear_upper = _worn_flags(surfaces)
    b = float(reduction)
    out_lower = scaled(lower, b) if wear_lower else lower  # type: ignore[arg-type]
    out_upper = scaled(upper, b) if wear_upper else upper  # type: ignore[arg-type]
    return out_lower, out_upper


def _is_wedge_pair(lower: Surface, upper: Surface) -> bool:
    return all(isinstance(s, WedgeProfile | FlatProfile) for s in (lower, upper))


def _wedge_angles(surface: Surface) -> tuple[float, float]:
    if isinstance(surface, WedgeProfile):
        return surface.angles_deg
    return (0.0, 0.0)


@dataclass(frozen=True, repr=False)
class WearingFriction(TableResult):
    """The leading fields of every wear history (read-only arrays).

    Attributes
    ----------
    time:
        Times (s), shape (n_t,).
    reduction:
        The roughness reductions B(t) (Eq 31), first axis the time.
    beta_deg:
        Directions (deg), shape (n_beta,).
    mu, mu_x, mu_y:
        Friction coefficients over time and direction (first axis the time, last the
        direction).
    """

    time: FloatArray
    reduction: FloatArray
    beta_deg: FloatArray
    mu: FloatArray
    mu_x: FloatArray
    mu_y: FloatArray


def wearing_fields(
    time: FloatArray,
    reduction: FloatArray,
    beta_deg: FloatArray,
    mu: FloatArray,
    mu_x: FloatArray,
    mu_y: FloatArray,
) -> dict[str, FloatArray]:
    """The fields of :class:`WearingFriction` as read-only float64 copies."""
    values = (time, reduction, beta_deg, mu, mu_x, mu_y)
    return {f.name: _ro(v) for f, v in zip(fields(WearingFriction), values, strict=True)}


@dataclass(frozen=True, repr=False)
class WearHistory(WearingFriction):
    """mu(t) of a wearing pair (the fields of :class:`WearingFriction`, then these).

    ``reduction`` is B(t), shape (n_t,); ``mu``, ``mu_x``, ``mu_y`` (n_t, n_beta) are the
    coefficients of the worn pair (``mu`` follows the lattice settings' ``mu_definition``).

    Attributes
    ----------
    wear_time:
        T_w (s).
    volume:
        The initial roughness volume of the wearing surfaces V0 (m^3).
    mu0:
        The local coefficient (the limit at t >= T_w when both surfaces wear).
    wear:
        The wear inputs.
    method:
        ``"closed_form"`` (Eqs 15-16) or ``"lattice"``.
    """

    wear_time: float
    volume: float
    mu0: float
    wear: WearSettings
    method: str

    def columns(self) -> dict[str, np.ndarray]:
        """A long table, one row per (time, beta), time-major."""
        n_t, n_b = self.mu.shape
        out: dict[str, np.ndarray] = {
            "time_s": np.repeat(self.time, n_b),
            "t_over_Tw": np.repeat(self.time / self.wear_time, n_b),
            "reduction_B": np.repeat(self.reduction, n_b),
            **long_mu_columns(self, n_t),
        }
        return out

    @staticmethod
    def units() -> dict[str, str]:
        return {"time_s": "s", "beta_deg": "deg"}


def wear_history(
    lower: Surface,
    upper: Surface,
    mu0: float,
    beta_deg: ArrayLike,
    wear: WearSettings,
    *,
    times: ArrayLike | None = None,
    samples: int = 21,
    method: str = "auto",
    settings: LatticeSettings | None = None,
) -> WearHistory:
    """mu(t) from the unworn value to mu0 at T_w (Eqs 23-28w).

    Parameters
    ----------
    lower, upper:
        The unworn surfaces.
    mu0:
        Local Coulomb coefficient.
    beta_deg:
        Sliding directions (deg).
    wear:
        Archard inputs and which surfaces wear.
    times:
        Times (s, >= 0); default ``samples`` equally spaced times from 0 to T_w.
    samples:
        Number of default times (>= 2).
    method:
        ``"auto"`` (default: Eqs 15-16 when both surfaces are wedges or flat, exact;
        otherwise the lattice), ``"lattice"`` or ``"closed_form"``.
    settings:
        Lattice settings (default: full contact, default resolution).
    """
    if method not in WEAR_METHODS:
        raise ParameterError("method", method, f"one of {WEAR_METHODS}")
    wedge_pair = _is_wedge_pair(lower, upper)
    if method == "closed_form" and not wedge_pair:
        raise ParameterError("method", method, "'lattice' or 'auto' unless both are wedges/flat")
    use_closed = method == "closed_form" or (method == "auto" and wedge_pair)
    volume = pair_volume(lower, upper, wear)
    tw = wear_time(volume, wear.volume_rate)
    if times is None:
        if isinstance(samples, bool) or not isinstance(samples, int) or samples < 2:
            raise ParameterError("samples", samples, "an integer >= 2")
        t = np.linspace(0.0, tw, samples)
    else:
        t = finite_vector("times", times, "a non-empty list of times >= 0 s", minimum=0.0)
    b = reduction_coefficient(t, tw)
    betas = check_betas(beta_deg)
    lattice = settings or LatticeSettings()
    mu_x = np.empty((t.size, betas.size))
    mu_y = np.empty_like(mu_x)
    mu = np.empty_like(mu_x)
    for k, reduction in enumerate(b):
        lo, up = worn_pair(lower, upper, float(reduction), wear.surfaces)
        if use_closed:
            angles = (*_wedge_angles(lo), *_wedge_angles(up))
            mx, my = wedge_friction(mu0, angles, betas)
            mu_x[k], mu_y[k] = mx, my
            rad = np.radians(betas)
            if lattice.mu_definition == "magnitude":
                mu[k] = np.hypot(mx, my)
            else:
                mu[k] = mx * np.cos(rad) + my * np.sin(rad)
        else:
            polar = friction_polar(lo, up, mu0, betas, settings=lattice)
            mu_x[k], mu_y[k], mu[k] = polar.mu_x, polar.mu_y, polar.mu
    return WearHistory(
        **wearing_fields(t, b, betas, mu, mu_x, mu_y),
        wear_time=tw,
        volume=volume,
        mu0=float(mu0),
        wear=wear,
        method="closed_form" if use_closed else "lattice",
    )
