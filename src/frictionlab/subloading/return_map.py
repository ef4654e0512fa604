"""Public implicit update of N contact points by one increment, spec §4.

:func:`update` validates its inputs, calls the compiled kernel
(:func:`frictionlab.subloading.kernels.step_points`) and returns a :class:`StepResult`
that carries the new state (the input state is never mutated), the tractions, the
consistent tangents and per-point status and work counters — the SciPy result-object
contract (``success``, ``message``).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Any

import numpy as np

from frictionlab.errors import ConvergenceError, ParameterError
from frictionlab.subloading import kernels
from frictionlab.subloading.evolution import (
    BACKWARD_EULER,
    EXPONENTIAL,
    ONE_MINUS,
    RATIO,
    U_COT,
    U_LN,
)
from frictionlab.subloading.params import SubloadingParams
from frictionlab.subloading.state import ContactState
from frictionlab.subloading.surfaces import SURFACE_CODES

__all__ = ["Status", "StepResult", "parameter_table", "update"]


class Status(enum.IntEnum):
    """Per-point outcome of one increment."""

    STICK = kernels.STICK  #: elastic (no plastic sliding), including unloading and rest
    SLIP = kernels.SLIP  #: plastic sliding (loading, Lambda > 0)
    OPEN = kernels.OPEN  #: separated contact: zero traction
    FAILED = kernels.FAILED  #: the local solve failed; the point kept its old state


@dataclass(frozen=True)
class StepResult:
    """Result of :func:`update` for N points.

    Attributes
    ----------
    state:
        The new :class:`ContactState` (failed points keep their old state).
    traction:
        (N, 3) tractions ``(f_t1, f_t2, f_n)`` [Pa] at the end of the increment.
    tangent:
        (N, 3, 3) algorithmic consistent tangent d(traction)/d(slip increment) [Pa/m];
        non-symmetric in plastic sliding (pitfall 11); zero for open points.
    plastic_slip_increment:
        (N, 3) plastic slip increment ``dlam * t_bar`` [m]; the normal component is 0.
    plastic_multiplier:
        (N,) dlam = |Delta u^p| [m].
    dissipation:
        (N,) ``f_{n+1} . Delta u^p`` [J/m^2].
    status:
        (N,) :class:`Status` codes (int8).
    iterations:
        (N,) Newton iterations of the local solve (0 for elastic or open points).
    """

    state: ContactState
    traction: np.ndarray
    tangent: np.ndarray
    plastic_slip_increment: np.ndarray
    plastic_multiplier: np.ndarray
    dissipation: np.ndarray
    status: np.ndarray
    iterations: np.ndarray

    @property
    def converged(self) -> np.ndarray:
        """(N,) True where the point's update succeeded."""
        return np.asarray(self.status != Status.FAILED)

    @property
    def success(self) -> bool:
        """True when every point converged."""
        return bool(np.all(self.converged))

    @property
    def message(self) -> str:
        """A one-line summary of the outcome."""
        counts = {s.name.lower(): int(np.sum(self.status == s)) for s in Status}
        text = ", ".join(f"{k} {v}" for k, v in counts.items() if v)
        return ("all points converged: " if self.success else "local solve failed: ") + text


_U_CODES = {"cot": U_COT, "ln": U_LN}
_INTEG_CODES = {"exponential": EXPONENTIAL, "backward_euler": BACKWARD_EULER}
_FORM_CODES = {"one_minus": ONE_MINUS, "ratio": RATIO}


def parameter_table(params: SubloadingParams) -> np.ndarray:
    """The (1 or N, N_PARAMS) float64 table of the kernel's numeric parameters (a new array)."""
    rows = params.n_points if params.per_point else 1
    table = np.empty((rows, kernels.N_PARAMS))
    columns = {
        kernels.P_ALPHA_N: params.alpha_n,
        kernels.P_ALPHA_T: params.alpha_t,
        kernels.P_FS: params.static,
        kernels.P_FK: params.kinetic,
        kernels.P_U: params.u,
        kernels.P_KAPPA: params.kappa,
        kernels.P_XI: params.xi,
        kernels.P_M: params.m,
        kernels.P_N: params.n,
        kernels.P_BETA1: np.asarray(params.rotation)[..., 0],
        kernels.P_BETA2: np.asarray(params.rotation)[..., 1],
        kernels.P_A1: np.asarray(params.axis_factors)[..., 0],
        kernels.P_A2: np.asarray(params.axis_factors)[..., 1],
        kernels.P_ANGLE: params.orthotropy_angle,
    }
    for col, value in columns.items():
        table[:, col] = np.broadcast_to(np.asarray(value, dtype=np.float64), (rows,))
    return table


def update(
    params: SubloadingParams,
    state: ContactState,
    slip_increment: Any,
    time_increment: Any,
    *,
    raise_on_failure: bool = True,
) -> StepResult:
    """Advance N contact points by one increment with the implicit return map (spec §4.2).

    Parameters
    ----------
    params:
        Law parameters, shared (scalars) or per point ((N,) arrays).
    state:
        State at t_n (not modified).
    slip_increment:
        (N, 3) relative slip increment ``(du_t1, du_t2, du_n)`` [m] of the counter body
        in the co-rotating contact frame; ``du_n`` is the approach (positive closes).
    time_increment:
        Delta t [s] >= 0, scalar or (N,).
    raise_on_failure:
        When True (default) a failed local solve raises :class:`ConvergenceError` whose
        ``mask`` marks the failed points and whose ``result`` is this StepResult; when
        False the failure is only reported through ``status``.

    Returns
    -------
    StepResult
    """
    n = state.n_points
    du = np.asarray(slip_increment, dtype=np.float64)
    if du.shape != (n, 3):
        raise ParameterError("slip_increment", du.shape, f"shape ({n}, 3) for {n} points")
    if not np.all(np.isfinite(du)):
        raise ParameterError("slip_increment", du, "finite values (no NaN or infinity)")
    dt = np.atleast_1d(np.asarray(time_increment, dtype=np.float64))
    if dt.ndim != 1 or dt.shape[0] not in (1, n):
        raise ParameterError("time_increment", dt.shape, f"a scalar or shape ({n},)")
    if not np.all(np.isfinite(dt)) or np.any(dt < 0.0):
        raise ParameterError("time_increment", dt, "finite Delta t >= 0 [s]")
    if params.per_point and params.n_points != n:
        raise ParameterError("params", f"{params.n_points} points", f"{n} points, as in the state")
    table = params._kernel_table
    out = kernels.empty_outputs(n)
    try:
        _step_points(params, state, du, dt, table, out)
    except ArithmeticError:  # a division by an underflowed value (f_n ~ 1e-300): no result
        _keep_old_state(state, out)
    new_state = ContactState._trusted(
        traction=out["traction"],
        F=out["F"],
        R=out["R"],
        plastic_slip=state.plastic_slip + out["dlam"],
        gap=out["gap"],
        frame=state.frame,
    )
    for key in ("traction", "tangent", "vp", "dlam", "diss", "status", "iterations"):
        out[key].setflags(write=False)
    result = StepResult(
        state=new_state,
        traction=new_state.traction,
        tangent=out["tangent"],
        plastic_slip_increment=out["vp"],
        plastic_multiplier=out["dlam"],
        dissipation=out["diss"],
        status=out["status"],
        iterations=out["iterations"],
    )
    if raise_on_failure and not result.success:
        raise ConvergenceError(
            "the implicit return map failed (e.g. the normal traction left a closed "
            "sliding-yield surface, or no admissible plastic state exists)",
            mask=~result.converged,
            result=result,
        )
    return result


def _step_points(
    params: SubloadingParams,
    state: ContactState,
    du: np.ndarray,
    dt: np.ndarray,
    table: np.ndarray,
    out: dict[str, np.ndarray],
) -> None:
    """Call the compiled kernel for every point, filling ``out``."""
    kernels.step_points(
        np.ascontiguousarray(state.traction),
        np.ascontiguousarray(state.F),
        np.ascontiguousarray(state.R),
        np.ascontiguousarray(state.gap),
        np.ascontiguousarray(du),
        np.ascontiguousarray(dt),
        table,
        dt.shape[0] == 1,
        SURFACE_CODES[params.surface],
        params.tear_k,
        _U_CODES[params.U_law],
        _INTEG_CODES[params.F_integrator],
        _FORM_CODES[params.recovery_form],
        params.open_recovery == "frozen",
        out["traction"],
        out["F"],
        out["R"],
        out["gap"],
        out["dlam"],
        out["vp"],
        out["diss"],
        out["tangent"],
        out["status"],
        out["iterations"],
    )


def _keep_old_state(state: ContactState, out: dict[str, np.ndarray]) -> None:
    """Fill ``out`` as for failed points: the old state kept, nothing dissipated."""
    out["traction"][:] = state.traction
    out["F"][:] = state.F
    out["R"][:] = state.R
    out["gap"][:] = state.gap
    for key in ("dlam", "vp", "diss", "tangent", "iterations"):
        out[key][:] = 0
    out["status"][:] = Status.FAILED
