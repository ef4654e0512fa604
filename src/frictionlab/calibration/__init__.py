"""Calibration of the subloading-friction law from tribometer curves (pure computation).

Public API:

* :class:`Curve` — a measured curve with the programme that produced it;
* :func:`fit_law` -> :class:`FitResult` — bounded least squares with the driver in the
  loop, standard errors and correlations (:mod:`~frictionlab.calibration.fit`);
* :func:`profile_likelihood` -> :class:`Profile` — the profile of a poorly identified
  parameter (:mod:`~frictionlab.calibration.profile`);
* :data:`FITTABLE` — the parameters that can be fitted (True: fitted as ln x).
"""

from frictionlab.calibration.fit import (
    CORRELATION_LIMIT,
    RELATIVE_STDERR_LIMIT,
    FitResult,
    fit_law,
)
from frictionlab.calibration.model import FITTABLE, Curve, FitSpace, evaluate_columns
from frictionlab.calibration.profile import CHI2_95, Profile, profile_likelihood

__all__ = [
    "CHI2_95",
    "CORRELATION_LIMIT",
    "FITTABLE",
    "RELATIVE_STDERR_LIMIT",
    "Curve",
    "FitResult",
    "FitSpace",
    "Profile",
    "evaluate_columns",
    "fit_law",
    "profile_likelihood",
]
