"""frictionlab: anisotropic friction.

Two published models and the bridge between them:

* the subloading-friction constitutive law of Hashiguchi & Ozaki (2008), in
  :mod:`frictionlab.subloading`;
* the lattice-spring roughness model (ALSFM / H-ALSFM) of Berardo & Pugno, in
  :mod:`frictionlab.roughness`.
"""

from frictionlab._compile_cache import configure as _configure_compile_cache
from frictionlab._version import __version__

# numba's cache: a per-user directory keyed on the sources (before any kernel is defined)
_configure_compile_cache()
from frictionlab.errors import (  # noqa: E402
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
