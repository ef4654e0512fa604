"""Adhesion in the lattice-spring model (Eqs 21-22): normal-load sweeps.

With adhesion, stretched springs pull with ``F = k_t u < 0`` (``u = l0 - l < 0``) and
compressed springs push with ``F = k_c u > 0``; the applied normal load is their sum
(**Eq 21**, ``L = sum F^(c) + sum F^(t)``), and only the compressed springs carry friction.
The apparent coefficient is (**Eq 22**)::

    mu_a = R_xy^(c) / L,    R_xy^(c) = |(R_x^(c), R_y^(c))|

against the coefficient of the compressed springs ``mu_c = R_xy^(c) / sum F^(c)``. When
tensile springs exist and L > 0, ``mu_a > mu_c``; mu_a diverges as L -> 0+ while R > 0, is
undefined at L = 0 and negative for L < 0.

:func:`adhesion_sweep` runs the lattice (:func:`~frictionlab.roughness.lattice.friction_polar`,
load control) at each load of a sweep and returns an :class:`AdhesionSweep`. Units: loads
and forces are **per spring** (N), the mean over both spring families, as everywhere in
the lattice (total load ``L = 2 N_stations * load``); stiffnesses in N/m.

Undefined values are **masked** (``numpy.ma``), never NaN or infinite: ``mu_apparent`` at
L = 0 (Eq 22 singular), ``mu_compressed`` where no spring is compressed (then R = 0),
``mu_no_adhesion`` at L <= 0 (no equilibrium without tensile springs).

Options: ``k_t`` defaults to ``k_c / 2`` (the paper's value). The
paper gives no detachment criterion, so by default stretched springs never detach; the
lattice option ``detachment`` (a cut-off elongation in m, off by default) lets a spring
stretched beyond it carry no force. The load balance then has several roots and the
largest offset is taken (pulling apart from full contact); a load below the pull-off
force is an error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frictionlab._arrays import FloatArray, finite_vector, readonly_masked
from frictionlab._arrays import readonly as _ro
from frictionlab._frames import TableResult
from frictionlab.errors import ParameterError
from frictionlab.roughness.lattice import LatticeSettings, friction_polar, settings_from
from frictionlab.roughness.surface import Surface

__all__ = ["DEFAULT_TENSILE_RATIO", "AdhesionSweep", "adhesion_sweep"]

#: k_t / k_c by default (the paper's k_t = k_c / 2).
DEFAULT_TENSILE_RATIO = 0.5


@dataclass(frozen=True, repr=False)
class AdhesionSweep(TableResult):
    """The outcome of a normal-load sweep with tensile springs (arrays (loads, directions)).

    Attributes
    ----------
    load:
        Applied load per spring (N), shape (n_loads,), in the order given.
    beta_deg:
        Sliding directions (deg), shape (n_beta,).
    force_x, force_y, tangential_force:
        Resisting force of the compressed springs R^(c) per spring (N) and its magnitude
        ``|R_xy^(c)|`` (time averages).
    compressed_force:
        Mean compressive force per spring ``sum F^(c) / (2 N)`` (N).
    mu_compressed:
        ``R_xy^(c) / sum F^(c)`` (masked where no spring is compressed).
    mu_apparent:
        Eq 22, ``R_xy^(c) / L`` (masked at L = 0).
    mu_no_adhesion:
        The coefficient at the same load without tensile springs (``k_t = 0``), masked
        at L <= 0; ``None`` when not computed.
    contact_fraction_mean, contact_fraction_min, tensile_fraction_mean, tensile_fraction_max:
        Fractions of compressed and of stretched springs over the time samples of one
        period (mean and extreme sample).
    mu0, k_c, k_t:
        Local coefficient; stiffnesses (N/m).
    settings:
        The lattice settings of the sweep (their ``load`` is the first load).
    """

    load: FloatArray
    beta_deg: FloatArray
    force_x: FloatArray
    force_y: FloatArray
    tangential_force: FloatArray
    compressed_force: FloatArray
    mu_compressed: np.ma.MaskedArray
    mu_apparent: np.ma.MaskedArray
    mu_no_adhesion: np.ma.MaskedArray | None
    contact_fraction_mean: FloatArray
    contact_fraction_min: FloatArray
    tensile_fraction_mean: FloatArray
    tensile_fraction_max: FloatArray
    mu0: float
    k_c: float
    k_t: float
    settings: LatticeSettings

    @property
    def mu_apparent_defined(self) -> NDArray[np.bool_]:
        """False where Eq 22 is undefined (L = 0)."""
        return np.asarray(~np.ma.getmaskarray(self.mu_apparent))

    def columns(self) -> dict[str, np.ndarray]:
        """A long table, one row per (load, beta), load-major; undefined values masked."""
        n_l, n_b = self.tangential_force.shape
        out: dict[str, np.ndarray] = {
            "load_per_spring": np.repeat(self.load, n_b),
            "beta_deg": np.tile(self.beta_deg, n_l),
            "tangential_force": self.tangential_force.ravel(),
            "force_x": self.force_x.ravel(),
            "force_y": self.force_y.ravel(),
            "compressed_force": self.compressed_force.ravel(),
            "mu_compressed": self.mu_compressed.ravel(),
            "mu_apparent": self.mu_apparent.ravel(),
            "mu_apparent_defined": self.mu_apparent_defined.ravel(),
        }
        if self.mu0 > 0.0:
            out["mu_apparent_over_mu0"] = self.mu_apparent.ravel() / self.mu0
        if self.mu_no_adhesion is not None:
            out["mu_no_adhesion"] = self.mu_no_adhesion.ravel()
        out.update(
            contact_fraction_mean=self.contact_fraction_mean.ravel(),
            contact_fraction_min=self.contact_fraction_min.ravel(),
            tensile_fraction_mean=self.tensile_fraction_mean.ravel(),
            tensile_fraction_max=self.tensile_fraction_max.ravel(),
        )
        return out

    @staticmethod
    def units() -> dict[str, str]:
        """Units of :meth:`columns` (``1``: dimensionless)."""
        return {
            "load_per_spring": "N",
            "beta_deg": "deg",
            "tangential_force": "N",
            "force_x": "N",
            "force_y": "N",
            "compressed_force": "N",
        }


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def adhesion_sweep(
    lower: Surface,
    upper: Surface,
    mu0: float,
    loads: ArrayLike,
    beta_deg: ArrayLike,
    *,
    k_t: float | None = None,
    compare_without_adhesion: bool = True,
    settings: LatticeSettings | None = None,
    **options: Any,
) -> AdhesionSweep:
    """Friction with tensile springs over a sweep of normal loads (Eqs 21-22).

    Parameters
    ----------
    lower, upper:
        Surface 1 (fixed) and surface 2 (sliding).
    mu0:
        Local Coulomb coefficient (>= 0).
    loads:
        Applied loads per spring (N), any sign, at least one; e.g. from high compression
        through zero to tension.
    beta_deg:
        Sliding directions (deg).
    k_t:
        Tensile stiffness (N/m), ``0 <= k_t <= k_c``; default ``k_c / 2``.
    compare_without_adhesion:
        Also compute the coefficient at each positive load with ``k_t = 0``.
    settings, options:
        The lattice settings (or their fields as keywords); ``load`` and ``k_t`` are set
        by the sweep; ``control`` must be ``"load"``.
    """
    k_c = options.get("k_c", 1.0)
    tensile = DEFAULT_TENSILE_RATIO * k_c if k_t is None and _number(k_c) else k_t
    settings = settings_from(LatticeSettings, settings, options, {"k_t": tensile})
    if settings.control != "load":
        raise ParameterError("control", settings.control, "'load' for a load sweep")
    values = finite_vector("loads", loads, "a non-empty 1-D list of finite loads per spring (N)")
    kt = DEFAULT_TENSILE_RATIO * settings.k_c if k_t is None else k_t
    if not (isinstance(kt, int | float) and math.isfinite(kt) and 0.0 <= kt <= settings.k_c):
        raise ParameterError("k_t", k_t, f"0 <= k_t <= k_c = {settings.k_c} N/m")
    kt = float(kt)
    polars = []
    plain: list[FloatArray | None] = []
    for load in values:
        run = replace(settings, load=float(load), k_t=kt)
        polars.append(friction_polar(lower, upper, mu0, beta_deg, settings=run))
        if compare_without_adhesion and load > 0.0:
            run = replace(settings, load=float(load), k_t=0.0, detachment=None)
            plain.append(friction_polar(lower, upper, mu0, beta_deg, settings=run).mu)
        else:
            plain.append(None)
    betas = polars[0].beta_deg

    def stack(name: str) -> FloatArray:
        return np.array([getattr(p, name) for p in polars], dtype=np.float64)

    fx, fy, fc = stack("force_x"), stack("force_y"), stack("compressed_force")
    tangential = np.hypot(fx, fy)
    in_contact = np.array([p.in_contact for p in polars], dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu_c = np.where(in_contact, tangential / np.where(in_contact, fc, 1.0), 0.0)
        zero = values == 0.0
        mu_a = np.where(zero[:, None], 0.0, tangential / np.where(zero, 1.0, values)[:, None])
    no_adhesion = None
    if compare_without_adhesion:
        undefined = np.array([[p is None] * betas.size for p in plain])
        data = np.array([np.zeros(betas.size) if p is None else p for p in plain])
        no_adhesion = readonly_masked(data, undefined)
    return AdhesionSweep(
        load=_ro(values),
        beta_deg=_ro(betas),
        force_x=_ro(fx),
        force_y=_ro(fy),
        tangential_force=_ro(tangential),
        compressed_force=_ro(fc),
        mu_compressed=readonly_masked(mu_c, ~in_contact),
        mu_apparent=readonly_masked(mu_a, np.broadcast_to(zero[:, None], mu_a.shape)),
        mu_no_adhesion=no_adhesion,
        contact_fraction_mean=_ro(stack("contact_fraction_mean")),
        contact_fraction_min=_ro(stack("contact_fraction_min")),
        tensile_fraction_mean=_ro(stack("tensile_fraction_mean")),
        tensile_fraction_max=_ro(stack("tensile_fraction_max")),
        mu0=float(mu0),
        k_c=settings.k_c,
        k_t=kt,
        settings=replace(settings, load=float(values[0]), k_t=kt),
    )
