"""From roughness to a constitutive friction law (the bridge).

The lattice-spring model gives friction vectors per sliding direction; the
subloading-friction law has a steady-sliding polar in closed form. This package
connects them, as pure computation (no I/O):

* :mod:`~frictionlab.bridge.steady` — the law's steady traction ratio in any sliding
  direction (:func:`law_polar`, :func:`steady_traction_ratio`), its coefficient at speed V
  (:func:`steady_coefficient`) and a slide long enough to reach it
  (:func:`steady_distance`);
* :mod:`~frictionlab.bridge.fit` — :func:`fit_anisotropy` -> :class:`AnisotropyFit`
  (orthotropy axes, C_1/C_2, rotation vector, misfit and a sentence when the law cannot
  express the polar);
* :mod:`~frictionlab.bridge.law` — :func:`fitted_law`: the fitted anisotropy in a
  :class:`~frictionlab.subloading.SubloadingParams`, sized by the ``[law]`` or by the
  roughness.

``frictionlab bridge`` (:mod:`frictionlab.commands.bridge`) runs them and checks the result
against the driver's simulated steady sliding.
"""

from frictionlab.bridge.fit import FIT_GROUPS, AnisotropyFit, DirectionalFriction, fit_anisotropy
from frictionlab.bridge.law import SCALES, FittedLaw, fitted_law, relative_rotation_of
from frictionlab.bridge.steady import (
    law_polar,
    steady_coefficient,
    steady_direction,
    steady_distance,
    steady_size_at,
    steady_traction_ratio,
)

__all__ = [
    "FIT_GROUPS",
    "SCALES",
    "AnisotropyFit",
    "DirectionalFriction",
    "FittedLaw",
    "fit_anisotropy",
    "fitted_law",
    "law_polar",
    "relative_rotation_of",
    "steady_coefficient",
    "steady_direction",
    "steady_distance",
    "steady_size_at",
    "steady_traction_ratio",
]
