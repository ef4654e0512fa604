"""Public implicit update of N contact points by one increment.

:func:`update` validates its inputs, calls the compiled kernel
(:func:`frictionlab.subloading.kernels.step_points`) and returns a :class:`StepResult`
that carries the new state (the input state is never mutated), the tractions, the
consistent tangents and per-point status and work counters — the SciPy result-object
contract (``success``, ``message``).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from frictionlab._frames import TableResult
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


@dataclass(frozen=True, repr=False)
class StepResult(TableResult):
    """Result of :func:`update` for N points.

    Attributes
    ----------
    state:
        The new :class:`ContactState` (failed points keep their old state).
    traction:
        (N, 3) tractions ``(f_t1, f_t2, f_n)`` [Pa] at the end of the increment.
    tangent:
        (N, 3, 3) algorithmic consistent tangent d(traction)/d(slip increment) [Pa/m];
        non-symmetric in plastic sliding (the flow direction differs from the normal
        of the yield surface); zero for open points; (0, 3, 3)
        when ``update`` was asked for no tangent.
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

    def columns(self) -> dict[str, np.ndarray]:
        """One row per point: tractions, plastic slip increment, dissipation, status."""
        names = np.array([s.name.lower() for s in Status], dtype=object)
        codes = np.array([int(s) for s in Status])
        status = names[np.searchsorted(codes, self.status, sorter=np.argsort(codes))]
        return {
            "point": np.arange(1, self.traction.shape[0] + 1),
            "traction_1": self.traction[:, 0],
            "traction_2": self.traction[:, 1],
            "traction_n": self.traction[:, 2],
            "plastic_slip_increment_1": self.plastic_slip_increment[:, 0],
            "plastic_slip_increment_2": self.plastic_slip_increment[:, 1],
            "plastic_multiplier": self.plastic_multiplier,
            "dissipation": self.dissipation,
            "status": status,
            "iterations": self.iterations,
        }

    def units(self) -> dict[str, str]:
        """Units of :meth:`columns` (``-``: dimensionless or text)."""
        units = {"traction_1": "Pa", "traction_2": "Pa", "traction_n": "Pa",
                 "plastic_slip_increment_1": "m", "plastic_slip_increment_2": "m",
                 "plastic_multiplier": "m", "dissipation": "J/m^2"}  # fmt: skip
        return {k: units.get(k, "-") for k in self.columns()}


#: Batches of at least this many points run on numba's threads (measured cross-over on a
#: 2-core machine: below ~1e4 points the threads' start-up costs more than it saves).
PARALLEL_MIN_POINTS = 10_000

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
    tangent: bool = True,
    out: dict[str, np.ndarray] | None = None,
) -> StepResult:
    """Advance N contact points by one increment with the implicit return map.

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
    tangent:
        When False the consistent tangent is not computed (``StepResult.tangent`` then
        has zero rows); the state and every other output are unchanged.
    out:
        Optional preallocated outputs, ``kernels.empty_outputs(N, tangent)``, reused
        in place (no allocation per call). The returned state and result are views of
        these buffers, left writeable, and are overwritten by the next call that is
        given the same buffers: alternate two sets when the previous state must stay
        valid. A buffer that shares memory with ``state`` is refused.

    Points are shared among numba's threads when N >= ``PARALLEL_MIN_POINTS`` (the
    result is identical to the serial loop; smaller batches stay serial, where the
    threads' start-up would cost more than it saves).

    Returns
    -------
    StepResult
    """
    n = state.n_points
    du = np.asarray(slip_increment, dtype=np.float64)
    if du.shape != (n, 3):
        raise ParameterError("slip_increment", du.shape, f"shape ({n}, 3) for {n} points")
    dt = np.atleast_1d(np.asarray(time_increment, dtype=np.float64))
    if dt.ndim != 1 or dt.shape[0] not in (1, n):
        raise ParameterError("time_increment", dt.shape, f"a scalar or shape ({n},)")
    # a finite sum means every value is finite (NaN and infinity propagate); only a sum
    # that overflows needs the element-wise check
    with np.errstate(over="ignore", invalid="ignore"):
        du_sum, dt_sum = du.sum(), dt.sum()
    if not math.isfinite(du_sum) and not np.isfinite(du).all():
        raise ParameterError("slip_increment", du, "finite values (no NaN or infinity)")
    if not (math.isfinite(dt_sum) or np.isfinite(dt).all()) or dt.min() < 0.0:
        raise ParameterError("time_increment", dt, "finite Delta t >= 0 [s]")
    if params.per_point and params.n_points != n:
        raise ParameterError("params", f"{params.n_points} points", f"{n} points, as in the state")
    buffers = kernels.empty_outputs(n, tangent) if out is None else _checked_buffers(out, n, state)
    if tangent and buffers["tangent"].shape[0] != n:
        raise ParameterError("out", "tangent buffer without rows", "empty_outputs(N, tangent=True)")
    result = _solve(params, state, du, dt, tangent, buffers, out is not None)
    if raise_on_failure and not result.success:
        raise ConvergenceError(
            "the implicit return map failed (e.g. the normal traction left a closed "
            "sliding-yield surface, or no admissible plastic state exists)",
            mask=~result.converged,
            result=result,
        )
    return result


def _update_into(
    params: SubloadingParams,
    state: ContactState,
    du: np.ndarray,
    dt: np.ndarray,
    out: dict[str, np.ndarray],
) -> StepResult:
    """:func:`update` without its checks, no tangent, no raise, into ``out``: for a caller
    that made every input itself from checked values (the driver: ``du`` (N, 3) float64
    from a checked programme, ``dt`` (1 or N,) float64 >= 0, ``out`` from
    ``kernels.empty_outputs(N, tangent=False)`` not holding ``state``)."""
    return _solve(params, state, du, dt, False, out, True)


def _solve(
    params: SubloadingParams,
    state: ContactState,
    du: np.ndarray,
    dt: np.ndarray,
    tangent: bool,
    buffers: dict[str, np.ndarray],
    views: bool,
) -> StepResult:
    """Run the kernel on checked inputs; the result over ``buffers`` (``views``: left
    writeable, the caller's buffers; otherwise made read-only)."""
    n = state.n_points
    kernel: Callable[..., Any] = (
        kernels.step_points_parallel if n >= PARALLEL_MIN_POINTS else kernels.step_points
    )
    try:
        kernel(
            *kernel_inputs(state),
            np.ascontiguousarray(du),
            np.ascontiguousarray(dt),
            *kernel_settings(params, dt.shape[0] == 1, tangent),
            *kernel_outputs(buffers),
        )
    except ArithmeticError:  # a division by an underflowed value (f_n ~ 1e-300): no result
        _keep_old_state(state, buffers)
    if views:  # the caller's buffers are reused: the state views them
        slip = np.add(state.plastic_slip, buffers["dlam"], out=buffers["plastic_slip"])
    else:
        slip = state.plastic_slip + buffers["dlam"]
    new_state = (ContactState._views if views else ContactState._trusted)(
        traction=buffers["traction"],
        F=buffers["F"],
        R=buffers["R"],
        plastic_slip=slip,
        gap=buffers["gap"],
        frame=state.frame,
    )
    if not views:
        for key in ("traction", "tangent", "vp", "dlam", "diss", "status", "iterations"):
            buffers[key].setflags(write=False)
    return StepResult(
        state=new_state,
        traction=new_state.traction,
        tangent=buffers["tangent"],
        plastic_slip_increment=buffers["vp"],
        plastic_multiplier=buffers["dlam"],
        dissipation=buffers["diss"],
        status=buffers["status"],
        iterations=buffers["iterations"],
    )


# The kernel's arguments in three parts, in its order: the state at t_n, then the slip and
# time increments, the settings, and the output buffers. Callers that repeat the kernel
# (the driver's steps) build the parts once and join them per call.


def kernel_inputs(state: ContactState) -> tuple[np.ndarray, ...]:
    """The state arrays the kernel reads: traction, F, R, gap (contiguous)."""
    return (
        np.ascontiguousarray(state.traction),
        np.ascontiguousarray(state.F),
        np.ascontiguousarray(state.R),
        np.ascontiguousarray(state.gap),
    )


def kernel_settings(params: SubloadingParams, shared_dt: bool, tangent: bool) -> tuple[Any, ...]:
    """The kernel's arguments after the increments: parameters, codes and flags."""
    return (
        params._kernel_table,
        shared_dt,
        SURFACE_CODES[params.surface],
        params.tear_k,
        _U_CODES[params.U_law],
        _INTEG_CODES[params.F_integrator],
        _FORM_CODES[params.recovery_form],
        params.open_recovery == "frozen",
        tangent,
    )


#: The output buffers of ``kernels.empty_outputs``, in the kernel's order.
OUTPUT_KEYS = ("traction", "F", "R", "gap", "dlam", "vp", "diss", "tangent", "status", "iterations")


def kernel_outputs(buffers: dict[str, np.ndarray]) -> tuple[np.ndarray, ...]:
    """The output buffers in the kernel's order."""
    return tuple(buffers[key] for key in OUTPUT_KEYS)


def _keep_old_state(state: ContactState, out: dict[str, np.ndarray]) -> None:
    """Fill ``out`` as for failed points: the old state kept, nothing dissipated."""
    out["traction"][:] = state.traction
    out["F"][:] = state.F
    out["R"][:] = state.R
    out["gap"][:] = state.gap
    for key in ("dlam", "vp", "diss", "tangent", "iterations"):
        out[key][:] = 0
    out["status"][:] = Status.FAILED


def _checked_buffers(
    out: dict[str, np.ndarray], n: int, state: ContactState
) -> dict[str, np.ndarray]:
    """Check user-supplied output buffers: complete, the right shapes, not aliasing ``state``."""
    held = [getattr(state, name) for name in ("traction", "F", "R", "plastic_slip", "gap")]
    for key, empty in _TEMPLATE.items():
        arr = out.get(key)
        if arr is None:
            raise ParameterError("out", f"no '{key}' buffer", "kernels.empty_outputs(N)")
        rows = arr.shape[0] if key == "tangent" and arr.shape[0] == 0 else n
        if (
            arr.shape != (rows, *empty.shape[1:])
            or arr.dtype != empty.dtype
            or not arr.flags.c_contiguous
            or not arr.flags.writeable
        ):
            raise ParameterError(
                "out", f"'{key}' {arr.shape} {arr.dtype}", "kernels.empty_outputs(N) buffers"
            )
        for name, x in zip(("traction", "F", "R", "plastic_slip", "gap"), held, strict=True):
            if np.may_share_memory(arr, x) and np.shares_memory(arr, x):  # bounds first: fast
                raise ParameterError(
                    "out",
                    f"'{key}' shares memory with state.{name}",
                    "buffers apart from the state",
                )
    return out


#: Empty output buffers: the keys, trailing shapes and dtypes ``out`` must match.
_TEMPLATE = {**kernels.empty_outputs(0, True), "plastic_slip": np.empty(0)}
