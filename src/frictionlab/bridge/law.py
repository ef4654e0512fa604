"""The fitted law: a :class:`~frictionlab.subloading.SubloadingParams` from an anisotropy fit.

The lattice's mu(beta) is a kinetic friction (a rate-independent average over a sliding
period, no adhesion healing), so its polar is matched to the law's *kinetic* polar, the
steady polar at V -> inf where F = F_k (:mod:`frictionlab.bridge.steady`). The fitted shape
(C_1 = 1 >= C_2, the angle of e*_1 and rho = beta/k) goes into the law unchanged; what sets
the size is the ``scale``:

* ``"law"`` (default): the ``[law]`` values are the size. The law's kinetic coefficient
  along e*_1 stays the user's (mu_k for the cone; ``M g^{-1}(F_k/f_n)`` for a closed
  surface at the normal traction f_n) and the rotation is ``beta = mu_k rho``: the whole
  roughness polar is scaled by one factor ``mu_k / k``.
* ``"roughness"``: the roughness polar is the size. mu_k = k, and mu_s = k mu_s/mu_k keeps
  the user's static-to-kinetic ratio (the roughness model has no adhesion healing, so it
  says nothing about mu_s); for a closed surface M is scaled by ``k / (M g^{-1}(F_k/f_n))``,
  keeping F_s, F_k and so the pressure dependence. beta = k rho.

Everything else (alpha_n, alpha_t, u, kappa, xi, exponents, options) is the user's.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from frictionlab.bridge.fit import AnisotropyFit
from frictionlab.bridge.steady import steady_coefficient
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

__all__ = ["SCALES", "FittedLaw", "fitted_law", "relative_rotation_of"]

#: Where the size of the fitted law comes from (see the module docstring).
SCALES: tuple[str, ...] = ("law", "roughness")


@dataclass(frozen=True)
class FittedLaw:
    """The fitted law and how its polar relates to the fitted roughness polar.

    ``params``: the law. ``factor``: law polar = factor x fitted polar (kinetic, in the
    polar's units); 1 for ``scale = "roughness"``. ``kinetic_coefficient``: the law's
    isotropic kinetic coefficient mu_bar_k (mu_k for the cone) at ``normal_traction``.
    """

    params: SubloadingParams
    scale: str
    factor: float
    kinetic_coefficient: float
    normal_traction: float


def relative_rotation_of(params: SubloadingParams, normal_traction: float = 1.0) -> np.ndarray:
    """rho = beta / mu_bar_k of a law: its rotation relative to its kinetic coefficient."""
    return np.asarray(params.rotation, dtype=np.float64) / steady_coefficient(
        params, None, normal_traction
    )


def fitted_law(
    base: SubloadingParams,
    fit: AnisotropyFit,
    *,
    scale: str = "law",
    normal_traction: float = 1.0,
) -> FittedLaw:
    """The law ``base`` with the fitted anisotropy, sized by ``scale`` (module docstring).

    Raises :class:`~frictionlab.errors.ParameterError` when the result is not a valid law
    (e.g. a rotation outside the kinetic cone, or a snap-back bound it breaks later).
    """
    if scale not in SCALES:
        raise ParameterError("scale", scale, "one of " + ", ".join(SCALES))
    mu_k_user = steady_coefficient(base, None, normal_traction)
    changes: dict[str, object] = {}
    if scale == "law":
        mu_bar = mu_k_user
    else:
        mu_bar = fit.kinetic
        if base.is_cone:
            ratio = float(np.ravel(base.mu_s)[0]) / float(np.ravel(base.mu_k)[0])
            changes.update(mu_k=mu_bar, mu_s=mu_bar * ratio)
        else:
            changes["M"] = float(np.ravel(base.M)[0]) * mu_bar / mu_k_user
    rotation = mu_bar * np.asarray(fit.relative_rotation)
    params = base.replace(
        **changes,
        rotation=rotation,
        orthotropy=np.asarray(fit.orthotropy),
        orthotropy_angle=fit.orthotropy_angle,
        orthotropy_convention="divide",
    )
    return FittedLaw(params, scale, mu_bar / fit.kinetic, mu_bar, float(normal_traction))
