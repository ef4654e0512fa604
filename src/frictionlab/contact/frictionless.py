"""A frictionless interface (mu = 0): the baseline of every FE contact study.

The subloading law needs mu_k > 0 (its yield ratio divides by F); mu = 0 is this
separate, exact interface law with the same normal part: penalty contact with the
normal stiffness ``alpha_n`` [Pa/m], the same opening and re-closing rule as the law
(``f_n^tr = f_n + alpha_n (du_n - gap)``, Eqs 2-3; ``f_n^tr <= 0`` opens and keeps the
opening in ``gap``) and zero tangential traction. Every closed point slides freely:
status SLIP with R = 1 (on the sliding surface |f_t| = mu f_n = 0), its tangential slip
all plastic.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from frictionlab.errors import ParameterError
from frictionlab.subloading import ContactState, Status, StepResult

__all__ = ["Frictionless", "frictionless_update"]


@dataclass(frozen=True)
class Frictionless:
    """mu = 0 with the normal penalty stiffness ``alpha_n`` [Pa/m] > 0."""

    alpha_n: float

    def __post_init__(self) -> None:
        a = self.alpha_n
        if isinstance(a, bool) or not isinstance(a, int | float) or not math.isfinite(a) or a <= 0:
            raise ParameterError("alpha_n", a, "a finite alpha_n > 0 [Pa/m]")
        object.__setattr__(self, "alpha_n", float(a))

    @property
    def alpha_t(self) -> float:
        """The springs of the solver's constant matrix (any stiffness > 0 works: the
        Woodbury correction removes them); the interface itself has none."""
        return self.alpha_n

    @property
    def static(self) -> float:
        """mu_s = 0."""
        return 0.0

    @property
    def per_point(self) -> bool:
        """One interface for all points."""
        return False


def frictionless_update(
    params: Frictionless, state: ContactState, slip_increment: np.ndarray
) -> StepResult:
    """Advance N points by ``slip_increment`` (N, 3) ``(du_t1, du_t2, du_n)`` [m]."""
    du = np.asarray(slip_increment, dtype=np.float64)
    n = du.shape[0]
    a = params.alpha_n
    trial = state.traction[:, 2] + a * (du[:, 2] - state.gap)
    closed = trial > 0.0
    fn = np.where(closed, trial, 0.0)
    gap = np.where(closed, 0.0, -trial / a)
    traction = np.zeros((n, 3))
    traction[:, 2] = fn
    slip = np.where(closed, np.hypot(du[:, 0], du[:, 1]), 0.0)
    tangent = np.zeros((n, 3, 3))
    tangent[:, 2, 2] = np.where(closed, a, 0.0)
    plastic = np.zeros((n, 3))
    plastic[:, :2] = np.where(closed[:, None], du[:, :2], 0.0)
    new = ContactState(
        traction=traction,
        F=np.zeros(n),
        R=np.where(closed, 1.0, 0.0),
        plastic_slip=state.plastic_slip + slip,
        gap=gap,
        frame=state.frame,
    )
    status = np.where(closed, Status.SLIP, Status.OPEN).astype(np.int8)
    return StepResult(
        state=new,
        traction=traction,
        tangent=tangent,
        plastic_slip_increment=plastic,
        plastic_multiplier=slip,
        dissipation=np.zeros(n),
        status=status,
        iterations=np.zeros(n, dtype=np.int64),
    )
