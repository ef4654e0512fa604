"""Implicit Newton iteration of one load step of the contact model.

Unknown: the nodal displacement ``u`` [m] at the end of the step; the law is updated
from the converged state at the start of the step by the whole increment ``u - u_n``,
so every iterate is a fresh return map and the contact stiffness is the
law's algorithmic consistent tangent. Residual on the free dofs:
``r = K u - f_ext - r_c(u)``; converged when ``|r| <= tolerance * scale`` with ``scale``
the largest of |f_ext|, |r_c| and |K u| (all dofs, so reactions count).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.interface import InterfaceResponse, respond
from frictionlab.contact.linear import IterativeSolver, TangentSolver
from frictionlab.contact.mesh import Discretisation
from frictionlab.subloading import ContactState, SubloadingParams

__all__ = ["NewtonOutcome", "newton_step"]


@dataclass
class NewtonOutcome:
    """Result of one Newton solve."""

    converged: bool
    u: np.ndarray
    response: InterfaceResponse | None
    iterations: int
    residuals: list[float] = field(default_factory=list)  #: relative residual per iterate
    message: str = ""


def newton_step(
    disc: Discretisation,
    params: SubloadingParams | Frictionless,
    state: ContactState,
    u_start: np.ndarray,
    u_guess: np.ndarray,
    f_ext: np.ndarray,
    dt: float,
    solver: TangentSolver | IterativeSolver,
    *,
    tangent: str = "consistent",
    tolerance: float = 1e-10,
    max_iterations: int = 25,
) -> NewtonOutcome:
    """Solve one step from ``u_start`` (state ``state``); ``u_guess`` carries the
    prescribed values on the dofs ``solver`` holds fixed and the initial guess elsewhere
    (equal values on tied dofs); the unknowns are ``solver``'s reduced coordinates.
    """
    u = u_guess.copy()
    K = disc.stiffness
    residuals: list[float] = []

    def evaluate(u_trial: np.ndarray) -> tuple[InterfaceResponse, np.ndarray, float]:
        resp = respond(disc, params, state, u_trial - u_start, dt, tangent)
        Ku = K @ u_trial
        r = Ku - f_ext - resp.force
        scale = max(np.linalg.norm(f_ext), np.linalg.norm(resp.force), np.linalg.norm(Ku))
        norm = float(np.linalg.norm(solver.reduce(r)))
        return resp, r, float(norm / scale) if scale > 0 else norm

    response, r, rel = evaluate(u)
    for it in range(max_iterations + 1):
        if not response.result.success:
            return NewtonOutcome(
                False,
                u,
                response,
                it,
                residuals,
                "the law's local solve failed: " + response.result.message,
            )
        if not np.isfinite(rel):
            return NewtonOutcome(False, u, response, it, residuals, "non-finite residual")
        residuals.append(rel)
        if rel <= tolerance:
            return NewtonOutcome(True, u, response, it, residuals)
        if it == max_iterations:
            break
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                delta = solver.expand(solver.solve(response.moduli, -solver.reduce(r)))
        except (sla.LinAlgError, sla.LinAlgWarning, ValueError) as exc:
            return NewtonOutcome(False, u, response, it, residuals, f"singular tangent ({exc})")
        # Backtracking: the law's response has kinks (stick/slip, the slip front), where a
        # full Newton step can overshoot and cycle; halve the step (at most 4 times) while
        # the residual does not decrease. Full steps are kept whenever they decrease it, so
        # the quadratic convergence near the solution is untouched.
        step = 1.0
        for _ in range(5):
            trial = u + step * delta
            t_response, t_r, t_rel = evaluate(trial)
            if (t_response.result.success and np.isfinite(t_rel) and t_rel < rel) or step <= 0.0625:
                break
            step *= 0.5
        u, response, r, rel = trial, t_response, t_r, t_rel
    return NewtonOutcome(
        False,
        u,
        response,
        max_iterations,
        residuals,
        f"no convergence in {max_iterations} iterations (relative residual "
        f"{residuals[-1]:.2e} > {tolerance:.2e})",
    )
