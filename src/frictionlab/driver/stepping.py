"""One step of a loading programme: mixed control and automatic substepping.

:func:`solve_control` applies one :class:`~frictionlab.driver.program.Control` to N
points with one call of the law's :func:`~frictionlab.subloading.update` when every
component is slip-controlled, and with a damped Newton iteration on the consistent
tangent when the tangential traction is prescribed. :func:`advance` wraps it with
substepping: a step whose local solve fails is halved, and, when an ``accuracy`` is
requested, a step is accepted only if one full step and two half steps agree to within
it (step doubling); otherwise both halves are refined in turn, down to
``2**-max_halvings`` of the step. All points are substepped together.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from frictionlab.driver.program import Control
from frictionlab.subloading import (
    ContactState,
    Status,
    StepResult,
    SubloadingParams,
    kernels,
    update,
)
from frictionlab.subloading.kernels import SEPARATION_RTOL
from frictionlab.subloading.return_map import (
    PARALLEL_MIN_POINTS,
    _keep_old_state,
    _update_into,
    kernel_inputs,
    kernel_outputs,
    kernel_settings,
)

__all__ = [
    "Attempt",
    "OutputPool",
    "SlipSteps",
    "StepWork",
    "advance",
    "combine_attempts",
    "slip_steps",
    "solve_control",
    "step_error",
    "substep",
]

_FAILED = int(Status.FAILED)
assert max(int(s) for s in Status) == _FAILED  # a status at or above it means a failure
#: The law's own update, the one known to write into preallocated outputs (``out``).
_LAW_UPDATE = update

#: Up to this many points, small reductions run on Python lists (cheaper than NumPy's call).
_FEW = 16
#: Newton iterations of the tangential traction control, per (sub)step.
MAX_TRACTION_ITERATIONS = 60
#: Relative tolerance of the traction control: |f_t - target| <= TOL * max(f_n, |target|).
TRACTION_RTOL = 1e-12


@dataclass
class Attempt:
    """Outcome of one increment (possibly made of substeps) for N points."""

    state: ContactState
    du: np.ndarray  #: (N, 3) slip increment actually applied [m]
    dissipation: np.ndarray  #: (N,) f . Delta u^p summed over substeps [J/m^2]
    status: np.ndarray  #: (N,) Status: OPEN if the step ends open, else SLIP if a substep slid
    iterations: np.ndarray  #: (N,) local Newton iterations summed over solves
    solves: int  #: calls of the law's update
    ok: bool
    reason: str = ""

    def __post_init__(self) -> None:
        # read-only: it may be the plan's own increment, shared by its steps (and one
        # layout for the recorder's compiled pass)
        self.du.setflags(write=False)


@dataclass
class StepWork:
    """Work counters of one recorded step."""

    substeps: int = 0
    solves: int = 0
    refined_for_failure: bool = False
    refined_for_accuracy: bool = False
    accuracy_unmet: bool = False
    iterations: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))


def _elastic(params: SubloadingParams, name: str, n: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(getattr(params, name), dtype=np.float64), (n,))


def _result_attempt(res: StepResult, du: np.ndarray, solves: int, iters: np.ndarray) -> Attempt:
    ok = res.status.shape[0] == 0 or int(res.status.max()) < _FAILED  # FAILED: the largest code
    return Attempt(
        state=res.state,
        du=du,
        dissipation=res.dissipation,
        status=res.status,
        iterations=iters,
        solves=solves,
        ok=ok,
        reason="" if ok else "the local solve of the law failed: " + res.message,
    )


def _solve2(J: np.ndarray, r: np.ndarray, fallback: np.ndarray) -> np.ndarray:
    """Solve the (N, 2, 2) systems J d = r; where J is near-singular use ``fallback``."""
    det = J[:, 0, 0] * J[:, 1, 1] - J[:, 0, 1] * J[:, 1, 0]
    scale = np.maximum(np.abs(J).max(axis=(1, 2)), 1e-300)
    good = np.abs(det) > 1e-12 * scale * scale
    safe = np.where(good, det, 1.0)
    d0 = (J[:, 1, 1] * r[:, 0] - J[:, 0, 1] * r[:, 1]) / safe
    d1 = (-J[:, 1, 0] * r[:, 0] + J[:, 0, 0] * r[:, 1]) / safe
    return np.where(good[:, None], np.column_stack([d0, d1]), fallback)


def _unreachable_normal_target(state: ContactState, fn_target: np.ndarray) -> Attempt | None:
    """A failed attempt if a positive normal-traction target is zero at the scale it is reached
    from (the separation rule of the law: at most ``SEPARATION_RTOL`` times the terms of the
    trial normal traction, here the current normal traction and the change), else None."""
    fn = state.traction[:, 2]
    scale = np.maximum(np.abs(fn), np.abs(fn_target - fn))
    lost = (fn_target > 0.0) & (fn_target <= SEPARATION_RTOL * scale)
    if not lost.any():
        return None
    i = int(np.argmax(lost))
    n = state.n_points
    return Attempt(
        state=state,
        du=np.zeros((n, 3)),
        dissipation=np.zeros(n),
        status=np.where(lost, _FAILED, Status.STICK).astype(np.int8),
        iterations=np.zeros(n, dtype=np.int64),
        solves=0,
        ok=False,
        reason=(
            f"the prescribed normal traction {fn_target[i]:.6g} Pa (point {i + 1}) is at most "
            f"{SEPARATION_RTOL:g} times the normal traction {fn[i]:.6g} Pa it is reached from: "
            "it cannot be told from zero (no contact) in that step; prescribe an approach to "
            "open the contact, or a larger traction"
        ),
    )


class OutputPool:
    """Two sets of the law's output buffers for N points, used in turn.

    The first solve of each step writes into the set that does not hold the state it
    starts from, so a run of single-solve steps allocates no new outputs. The sets hold no
    consistent tangent: only a slip-controlled step uses them, and it needs none. The state
    returned over a set stays valid until the step after next (callers copy what they
    keep longer).
    """

    def __init__(self, n_points: int) -> None:
        self.sets = tuple(kernels.empty_outputs(n_points, tangent=False) for _ in range(2))

    def free_for(self, state: ContactState) -> dict[str, np.ndarray]:
        """The set that does not hold ``state``."""
        a, b = self.sets
        return b if state.traction is a["traction"] else a

    def holds(self, state: ContactState) -> bool:
        """True when ``state`` lies in one of the sets (to be copied before it is kept)."""
        return any(state.traction is s["traction"] for s in self.sets)


class SlipSteps:
    """Slip-controlled steps without step doubling, straight to the law's kernel.

    The cheap path of :func:`advance` for the common step (no prescribed traction, no
    ``accuracy``): one kernel call into the pool's free set of buffers, with the kernel's
    settings and the output buffers prepared once per run and the new state one fixed view
    per set. :meth:`step` gives the same state, increment, work and status as
    :func:`advance` (same kernel call on the same inputs), or None when a point failed: the
    caller then runs :func:`advance`, which substeps (its first solve repeats this one).
    """

    def __init__(self, params: SubloadingParams, pool: OutputPool) -> None:
        n = pool.sets[0]["traction"].shape[0]
        self.pool = pool
        self.kernel: Callable[..., Any] = (
            kernels.step_points_parallel if n >= PARALLEL_MIN_POINTS else kernels.step_points
        )
        self.settings = {shared: kernel_settings(params, shared, False) for shared in (True, False)}
        self.outputs = tuple(kernel_outputs(s) for s in pool.sets)
        self.views: list[ContactState | None] = [None, None]
        # the kernel's inputs per state (the state first, to check the id)
        self._inputs: dict[int, tuple[Any, ...]] = {}

    def step(self, state: ContactState, control: Control) -> tuple[ContactState, np.ndarray] | None:
        """The new state and the (read-only) slip increment; None when a point failed.

        The state lies in the pool's set that did not hold ``state``; the outputs of the
        law (``diss``, ``status``, ``iterations``) are that set's buffers.
        """
        sets = self.pool.sets
        j = 1 if state.traction is sets[0]["traction"] else 0
        inputs = self._inputs.get(id(state))
        if inputs is None or inputs[0] is not state:
            if len(self._inputs) > 2:  # the two views and the latest other state
                self._inputs = {
                    id(v): self._inputs[id(v)] for v in self.views if id(v) in self._inputs
                }
            inputs = (state, *kernel_inputs(state))
            self._inputs[id(state)] = inputs
        kernel_du, du = control._slip_increment(state.traction.shape[0])
        dt = control.dt
        if dt.dtype != np.float64 or dt.ndim != 1 or not dt.flags.c_contiguous:
            dt = np.ascontiguousarray(np.atleast_1d(dt), dtype=np.float64)
        out = sets[j]
        try:
            self.kernel(
                *inputs[1:], kernel_du, dt, *self.settings[dt.shape[0] == 1], *self.outputs[j]
            )
        except ArithmeticError:  # as update(): no result, a failed step
            _keep_old_state(state, out)
            return None
        status = out["status"]
        # a few points: the Python max of a list beats a NumPy reduction's call overhead
        worst = max(status.tolist()) if status.shape[0] <= _FEW else int(status.max())
        if worst >= _FAILED:
            return None
        np.add(state.plastic_slip, out["dlam"], out=out["plastic_slip"])
        return self.view(j, state.frame), du

    def view(self, j: int, frame: np.ndarray) -> ContactState:
        """The state held in the pool's set ``j`` (one fixed view per set and frame)."""
        view = self.views[j]
        if view is None or view.frame is not frame:
            out = self.pool.sets[j]
            view = ContactState._views(
                traction=out["traction"], F=out["F"], R=out["R"],
                plastic_slip=out["plastic_slip"], gap=out["gap"], frame=frame,
            )  # fmt: skip
            self.views[j] = view
        return view


def slip_steps(
    params: SubloadingParams, pool: OutputPool, accuracy: float | None
) -> SlipSteps | None:
    """:class:`SlipSteps` where they give :func:`advance`'s result: no accuracy control and
    the law's own ``update`` (not a replacement of it, e.g. a test's); else None."""
    if accuracy is not None or update is not _LAW_UPDATE:
        return None
    return SlipSteps(params, pool)


class _LawStep:
    """The law's update for one control, with normal-traction targets reached exactly.

    A point that is open (f_n = 0, opening ``gap``) and closes onto a prescribed normal
    traction ``f_n^*`` is given to the law in the equivalent form that avoids the
    cancellation of ``alpha_n (du_n - gap)`` when ``f_n^*/alpha_n << gap``: no gap, the
    approach ``f_n^*/alpha_n`` past the closure, and the tangential slip after the
    closure, the fraction ``c = (f_n^*/alpha_n)/(gap + f_n^*/alpha_n)`` of the step's
    (the law loads only that fraction after a re-closing). The result is the same state,
    reached to the rounding of ``alpha_n (f_n^*/alpha_n)``; the tangential columns of the
    tangent are scaled by ``c`` (chain rule). ``du`` as reported is the step's own.
    """

    def __init__(
        self,
        params: SubloadingParams,
        state: ContactState,
        fn_target: np.ndarray | None,
        out: dict[str, np.ndarray] | None = None,
    ) -> None:
        self.params, self.state = params, state
        self.closing: np.ndarray | None = None
        self.out = out  # outputs for the next plain call (used once)
        if fn_target is None:
            return
        closing = (state.traction[:, 2] <= 0.0) & (fn_target > 0.0)
        if not closing.any():
            return
        alpha_n = _elastic(params, "alpha_n", state.n_points)
        self.beyond = np.where(closing, fn_target / alpha_n, 0.0)  # approach past closure [m]
        reach = state.gap + self.beyond
        self.fraction = np.where(
            closing & (reach > 0.0), self.beyond / np.where(reach > 0.0, reach, 1.0), 1.0
        )
        self.closing = closing
        self.closed_form = replace(state, gap=np.where(closing, 0.0, state.gap))

    def __call__(self, du: np.ndarray, dt: np.ndarray | float) -> StepResult:
        if self.closing is None:
            out, self.out = self.out, None
            if out is not None and update is _LAW_UPDATE:  # made here from a checked programme
                dts = np.atleast_1d(np.asarray(dt, dtype=np.float64))
                return _update_into(self.params, self.state, du, dts, out)
            return update(self.params, self.state, du, dt, raise_on_failure=False)
        c, sel = self.fraction, self.closing
        local = du.copy()
        local[sel, 2] = self.beyond[sel]
        local[sel, :2] *= c[sel, None]
        res = update(self.params, self.closed_form, local, dt, raise_on_failure=False)
        tangent = res.tangent
        if tangent.shape[0]:
            tangent = tangent.copy()
            tangent[:, :, :2] *= c[:, None, None]
        failed = sel & (res.status == _FAILED)  # failed points keep their old state
        new = res.state
        if failed.any():
            new = replace(new, gap=np.where(failed, self.state.gap, new.gap))
        return replace(res, state=new, tangent=tangent)


#: Tangential trial load over normal traction beyond which the return map cannot resolve
#: the return in double precision (its unknown 1 - q falls below the rounding of 1).
UNRESOLVED_LOAD_RATIO = 1e15


def _resolution_hint(
    params: SubloadingParams, state: ContactState, du: np.ndarray, failed: np.ndarray
) -> str:
    """Why a failed point may have failed: a tangential load far beyond its normal traction."""
    n = state.n_points
    fn = np.maximum(state.traction[:, 2], 0.0)
    trial = state.traction[:, :2] + _elastic(params, "alpha_t", n)[:, None] * du[:, :2]
    load = np.hypot(trial[:, 0], trial[:, 1])
    extreme = failed & (load > UNRESOLVED_LOAD_RATIO * fn) & (fn > 0.0)
    if not extreme.any():
        return ""
    i = int(np.argmax(extreme))
    return (
        f" (at point {i + 1} the trial tangential traction {load[i]:.3g} Pa is more than "
        f"{UNRESOLVED_LOAD_RATIO:g} times the normal traction {fn[i]:.3g} Pa: beyond what the "
        "return map resolves in double precision; use a larger normal traction)"
    )


def solve_control(
    params: SubloadingParams,
    state: ContactState,
    control: Control,
    out: dict[str, np.ndarray] | None = None,
) -> Attempt:
    """Apply one mixed-control increment (no substepping).

    ``out``: the law's output buffers (:class:`OutputPool`), apart from ``state``, for a
    slip-controlled step (the returned state then lies in them); otherwise unused.

    * prescribed normal traction: the approach is exact, ``(target - f_n)/alpha_n + gap``
      (no plastic normal sliding, Eq 32); a point closing onto the target from an
      opening is computed without cancellation against the gap (:class:`_LawStep`); a
      positive target that is zero at the scale of its step (the separation rule) fails;
    * prescribed tangential traction: damped Newton on the (2, 2) tangential block of the
      consistent tangent, with backtracking per point; fails if the target cannot be
      reached (for example beyond what the contact can carry: gross sliding).
    """
    n = state.n_points
    if control.fn_target is None and control.ft_target is None:  # the plan's own increment
        law = _LawStep(params, state, None, out)
        kernel_du, du = control._slip_increment(n)
        single = law(kernel_du, control.dt)
        attempt = _result_attempt(single, du, 1, single.iterations)
        if not attempt.ok:
            attempt.reason += _resolution_hint(params, state, du, single.status == _FAILED)
        return attempt
    du = np.empty((n, 3))
    du[:, :2] = control.du_t
    if control.fn_target is not None:
        refused = _unreachable_normal_target(state, control.fn_target)
        if refused is not None:
            return refused
        alpha_n = _elastic(params, "alpha_n", n)
        du[:, 2] = (control.fn_target - state.traction[:, 2]) / alpha_n + state.gap
    else:
        du[:, 2] = control.du_n
    law = _LawStep(params, state, control.fn_target, out if control.ft_target is None else None)
    if control.ft_target is None:
        single = law(du, control.dt)
        attempt = _result_attempt(single, du, 1, single.iterations)
        if not attempt.ok:
            attempt.reason += _resolution_hint(params, state, du, single.status == _FAILED)
        return attempt
    iters = np.zeros(n, dtype=np.int64)

    target = control.ft_target
    alpha_t = _elastic(params, "alpha_t", n)
    if control.fn_target is not None:
        fn_new = np.asarray(control.fn_target, dtype=np.float64)
    else:
        fn_new = state.traction[:, 2] + _elastic(params, "alpha_n", n) * (du[:, 2] - state.gap)
    tol = TRACTION_RTOL * np.maximum(np.maximum(fn_new, np.hypot(*target.T)), 1e-300)
    du[:, :2] = (target - state.traction[:, :2]) / alpha_t[:, None]  # elastic guess
    base = du[:, :2].copy()
    step = np.zeros((n, 2))
    lam = np.ones(n)
    base_norm = np.full(n, np.inf)
    solves = 0
    res: StepResult | None = None
    for _ in range(MAX_TRACTION_ITERATIONS):
        res = law(du, control.dt)
        solves += 1
        iters += res.iterations
        r = target - res.traction[:, :2]
        norm = np.hypot(r[:, 0], r[:, 1])
        norm[res.status == _FAILED] = np.inf
        done = norm <= tol
        if done.all():
            return _result_attempt(res, du.copy(), solves, iters)
        better = ~done & (norm < base_norm)
        worse = ~done & ~better
        if better.any():
            J = res.tangent[:, :2, :2]
            newton = _solve2(J, r, r / alpha_t[:, None])
            base[better] = du[better, :2]
            base_norm[better] = norm[better]
            step[better] = newton[better]
            lam[better] = 1.0
        lam[worse] *= 0.5
        if np.any(lam[worse] < 1e-12):
            break
        moving = better | worse
        du[moving, :2] = base[moving] + lam[moving, None] * step[moving]
    assert res is not None
    missed = float(np.max(np.hypot(*(target - res.traction[:, :2]).T)))
    return Attempt(
        state=res.state,
        du=du.copy(),
        dissipation=res.dissipation,
        status=res.status,
        iterations=iters,
        solves=solves,
        ok=False,
        reason=(
            "the prescribed tangential traction could not be reached (largest miss "
            f"{missed:.3g} Pa): the contact cannot carry it and slides away (gross "
            "sliding), or the local solve failed"
        ),
    )


def step_error(params: SubloadingParams, a: Attempt, b: Attempt) -> float:
    """Step-doubling error between a full step ``a`` and two half steps ``b``.

    The largest over points of: the difference of tangential traction and of the
    elastic equivalent of the slip ``alpha_t |du_a - du_b|`` (both divided by the normal
    traction: friction-ratio units), of R, and of F relative to its static value.
    """
    n = a.state.n_points
    fn = np.maximum(a.state.traction[:, 2], b.state.traction[:, 2])
    closed = fn > 0
    dft = np.hypot(*(a.state.traction[:, :2] - b.state.traction[:, :2]).T)
    dslip = np.hypot(*(a.du[:, :2] - b.du[:, :2]).T) * _elastic(params, "alpha_t", n)
    ratio = np.where(closed, np.maximum(dft, dslip) / np.where(closed, fn, 1.0), 0.0)
    dR = np.abs(a.state.R - b.state.R)
    dF = np.abs(a.state.F - b.state.F) / np.broadcast_to(params.static, (n,))
    return float(np.max(np.maximum(np.maximum(ratio, dR), dF)))


def combine_attempts(first: Attempt, second: Attempt) -> Attempt:
    """Join two consecutive attempts into one (sums; the second's state; SLIP if either slid)."""
    slid = (first.status == Status.SLIP) | (second.status == Status.SLIP)
    status = np.where(slid & (second.status != Status.OPEN), Status.SLIP, second.status)
    return Attempt(
        state=second.state,
        du=first.du + second.du,
        dissipation=first.dissipation + second.dissipation,
        status=status.astype(np.int8),
        iterations=first.iterations + second.iterations,
        solves=first.solves + second.solves,
        ok=first.ok and second.ok,
        reason=second.reason or first.reason,
    )


def substep(
    start: Any,
    control: Any,
    *,
    solve: Callable[[Any, Any], Any],
    halves: Callable[[Any, Any], tuple[Any, Any]],
    combine: Callable[[Any, Any], Any],
    error: Callable[[Any, Any], float],
    accuracy: float | None,
    max_halvings: int,
    n_points: int,
) -> tuple[Any, StepWork]:
    """Generic substepping of one step (used by the programme driver and the spring-slider).

    ``solve(start, control)`` returns an attempt with ``ok``, ``state``, ``solves`` and
    ``iterations``; ``halves(start, control)`` splits a control in two;
    ``combine(a, b)`` joins consecutive attempts; ``error(full, two_halves)`` measures
    the step-doubling error. A failed attempt is halved; with ``accuracy`` a step is
    accepted when ``error <= accuracy``, otherwise each half is refined in turn, at most
    ``max_halvings`` times.
    """
    work = StepWork()  # iterations: a copy of the first attempt's, then summed

    def attempt(state: Any, ctl: Any) -> Any:
        att = solve(state, ctl)
        work.solves += att.solves
        if work.iterations.shape[0] != n_points:
            work.iterations = np.array(att.iterations, dtype=np.int64)
        else:
            work.iterations += att.iterations
        return att

    def run(state: Any, ctl: Any, depth: int, full: Any) -> Any:
        if full is None:
            full = attempt(state, ctl)
        if not full.ok:
            if depth >= max_halvings:
                return full
            work.refined_for_failure = True
            c1, c2 = halves(state, ctl)
            first = run(state, c1, depth + 1, None)
            if not first.ok:
                return first
            return combine(first, run(first.state, c2, depth + 1, None))
        if accuracy is None:
            work.substeps += 1
            return full
        if depth >= max_halvings:
            work.accuracy_unmet = True
            work.substeps += 1
            return full
        c1, c2 = halves(state, ctl)
        h1 = attempt(state, c1)
        h2 = attempt(h1.state, c2) if h1.ok else None
        if h2 is not None and h2.ok:
            both = combine(h1, h2)
            if error(full, both) <= accuracy:
                work.substeps += 2
                return both
        work.refined_for_accuracy = True
        first = run(state, c1, depth + 1, h1)
        if not first.ok:
            return first
        reuse = h2 if first.state is h1.state else None
        return combine(first, run(first.state, c2, depth + 1, reuse))

    outcome = run(start, control, 0, None)
    if work.iterations.shape[0] != n_points:  # no attempt (not reached: one always runs)
        work.iterations = np.zeros(n_points, dtype=np.int64)
    return outcome, work


def advance(
    params: SubloadingParams,
    state: ContactState,
    control: Control,
    *,
    accuracy: float | None = None,
    max_halvings: int = 10,
    pool: OutputPool | None = None,
) -> tuple[Attempt, StepWork]:
    """Advance a programme by one recorded step with automatic substepping.

    With a ``pool`` the step's first solve writes into its free set of buffers (the other
    solves of a substepped step allocate their own).
    """
    first = [None if pool is None else pool.free_for(state)]

    def solve(st: ContactState, ctl: Control) -> Attempt:
        out, first[0] = first[0], None
        return solve_control(params, st, ctl, out)

    return substep(
        state,
        control,
        solve=solve,
        halves=lambda st, ctl: ctl.halves(st.traction),
        combine=combine_attempts,
        error=lambda a, b: step_error(params, a, b),
        accuracy=accuracy,
        max_halvings=max_halvings,
        n_points=state.n_points,
    )
