"""frictionlab: anisotropic friction.

Two published models and the bridge between them:

* the subloading-friction constitutive law of Hashiguchi & Ozaki (2008), in
  :mod:`frictionlab.subloading`;
* the lattice-spring roughness model (ALSFM / H-ALSFM) of Berardo & Pugno, in
  :mod:`frictionlab.roughness`.
"""

from frictionlab._version import __version__
from frictionlab.errors import (
    ConvergenceError,
    FrictionlabError,
    InputError,
    ParameterError,
    ValidityError,
)

__all__ = [
    "ConvergenceError",
    "FrictionlabError",
    "InputError",
    "ParameterError",
    "ValidityError",
    "__version__",
]
