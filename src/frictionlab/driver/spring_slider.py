"""Stick-slip: a compliant loading system driving a contact governed by the law.

A slider (the counter body, per unit nominal contact area) is pulled along the rail
direction ``e = (cos theta, sin theta)`` of the contact plane by a spring of stiffness
``k`` [Pa/m] whose far end (the load point) moves at ``V`` [m/s], with an optional
dashpot ``c`` [Pa s/m] in parallel and slider mass ``m`` [kg/m^2]:

    m x'' = k (V t - x) + c (V - x') - f(x) . e

where x [m] is the slip of the slider and f the contact traction given by the
subloading-friction law (the normal traction is held). Each time step is implicit:
one scalar unknown Delta x per point, solved with a safeguarded Newton iteration on
the law's consistent tangent (``d f . e / d Delta x = e . T e``) that takes the *first*
root in the direction of the out-of-balance force, so that a quasi-static slip event
(a jump) lands on the nearest equilibrium.

* ``m = 0`` (quasi-static): ``k (V t_{n+1} - x_{n+1}) + c (V - Delta x/Delta t) = f_{n+1} . e``.
* ``m > 0``: generalized-alpha (Chung & Hulbert 1993) with spectral radius
  ``rho_inf`` (default 0.5: second order, damps the unresolved high-frequency contact
  mode sqrt((alpha_t + k)/m) when the step is large; ``rho_inf = 1`` is the
  trapezoidal rule).

Steady sliding is stable when the machine is stiffer than the softening of the
steady friction with plastic slip (linear stability of the quasi-static system, see
:func:`critical_stiffness` and docs/driver.md): stick-slip appears where softening
outpaces the machine stiffness and vanishes for a stiff machine or a high velocity.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from frictionlab.driver.program import _count
from frictionlab.driver.simulate import (
    _UNSET,
    DriverSettings,
    History,
    InitialConditions,
    ProgressCallback,
    SegmentRecord,
    _count_work,
    count_points,
    driver_settings,
)
from frictionlab.driver.stepping import StepWork, substep
from frictionlab.errors import ParameterError
from frictionlab.loading import _check_field, _checked, _max_step, _steps
from frictionlab.subloading import (
    ContactState,
    Status,
    SubloadingParams,
    g_function,
    g_inverse,
    steady_size,
    update,
)

__all__ = [
    "SpringSlider",
    "count_slip_events",
    "critical_stiffness",
    "friction_oscillation",
    "simulate_spring_slider",
    "steady_F",
]

#: Newton iterations of one implicit step of the spring-slider.
MAX_ITERATIONS = 100


@dataclass(frozen=True)
class SpringSlider:
    """The loading system of a stick-slip test (per unit nominal contact area).

    Attributes
    ----------
    stiffness:
        k [Pa/m] > 0, the machine spring.
    velocity:
        V [m/s] >= 0, the load-point velocity.
    mass:
        m [kg/m^2] >= 0; 0 gives the quasi-static system.
    damping:
        c [Pa s/m] >= 0, a dashpot parallel to the spring.
    direction_deg:
        Rail direction in the contact plane, counter-clockwise from e_1 [deg].
    spectral_radius:
        rho_inf in [0, 1] of the generalized-alpha scheme (inertial points only).

    Numeric fields are scalars or (N,) arrays (one machine per point).
    """

    stiffness: Any
    velocity: Any
    mass: Any = 0.0
    damping: Any = 0.0
    direction_deg: Any = 0.0
    spectral_radius: float = 0.5

    def __post_init__(self) -> None:
        _check_field(self, "stiffness", ">0")
        _check_field(self, "velocity", ">=0")
        _check_field(self, "mass", ">=0")
        _check_field(self, "damping", ">=0")
        _check_field(self, "direction_deg", None)
        rho = self.spectral_radius
        if isinstance(rho, bool) or not isinstance(rho, int | float) or not 0.0 <= rho <= 1.0:
            raise ParameterError("spectral_radius", rho, "0 <= spectral_radius <= 1")
        object.__setattr__(self, "spectral_radius", float(rho))

    def sizes(self) -> set[int]:
        names = ("stiffness", "velocity", "mass", "damping", "direction_deg")
        return {getattr(self, k).shape[0] for k in names if getattr(self, k).ndim == 1}

    def alpha_coefficients(self) -> tuple[float, float, float, float]:
        """(alpha_m, alpha_f, gamma, beta) of the generalized-alpha method for rho_inf."""
        rho = self.spectral_radius
        am = (2.0 * rho - 1.0) / (rho + 1.0)
        af = rho / (rho + 1.0)
        gamma = 0.5 - am + af
        beta = 0.25 * (1.0 - am + af) ** 2
        return am, af, gamma, beta


@dataclass
class _SliderState:
    contact: ContactState
    x: np.ndarray  #: slider slip along the rail [m]
    v: np.ndarray  #: slider velocity [m/s]
    a: np.ndarray  #: slider acceleration [m/s^2]
    t: np.ndarray  #: time [s]
    slipping: np.ndarray  #: (N,) bool, the last step slid (then its dx is tried first)
    dx_last: np.ndarray  #: (N,) slip of the last step [m]
    dt_last: np.ndarray  #: (N,) time step of the last step [s]


@dataclass
class _SliderAttempt:
    state: _SliderState
    dx: np.ndarray
    dissipation: np.ndarray
    status: np.ndarray
    iterations: np.ndarray
    solves: int
    ok: bool
    reason: str = ""


class _Machine:
    """Per-point arrays of a SpringSlider and the law's data needed by the residual."""

    def __init__(self, params: SubloadingParams, machine: SpringSlider, n: int) -> None:
        def vec(a: np.ndarray) -> np.ndarray:
            return np.broadcast_to(a, (n,)).astype(np.float64)

        self.params = params
        self.k = vec(machine.stiffness)
        self.V = vec(machine.velocity)
        self.m = vec(machine.mass)
        self.c = vec(machine.damping)
        theta = np.radians(vec(machine.direction_deg))
        self.e = np.column_stack([np.cos(theta), np.sin(theta)])
        self.am, self.af, self.gamma, self.beta = machine.alpha_coefficients()
        self.inertial = self.m > 0
        self.n = n

    def along(self, traction: np.ndarray) -> np.ndarray:
        return np.einsum("ni,ni->n", traction[:, :2], self.e)

    def residual(
        self, s: _SliderState, dt: np.ndarray, dx: np.ndarray, f1: np.ndarray, T: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Out-of-balance force g [Pa], dg/d(dx), and the end velocity and acceleration."""
        X1 = self.V * (s.t + dt)
        x1 = s.x + dx
        # quasi-static points: backward-Euler velocity
        v_qs = dx / dt
        g_qs = f1 + self.k * (x1 - X1) + self.c * (v_qs - self.V)
        d_qs = T + self.k + self.c / dt
        # inertial points: generalized-alpha
        am, af, gam, bet = self.am, self.af, self.gamma, self.beta
        a1 = (dx - dt * s.v - dt * dt * (0.5 - bet) * s.a) / (bet * dt * dt)
        v1 = s.v + dt * ((1.0 - gam) * s.a + gam * a1)
        f0 = self.along(s.contact.traction)
        g_dyn = (
            self.m * ((1.0 - am) * a1 + am * s.a)
            + (1.0 - af) * (f1 + self.k * (x1 - X1) + self.c * (v1 - self.V))
            + af * (f0 + self.k * (s.x - self.V * s.t) + self.c * (s.v - self.V))
        )
        d_dyn = self.m * (1.0 - am) / (bet * dt * dt) + (1.0 - af) * (
            T + self.k + self.c * gam / (bet * dt)
        )
        i = self.inertial
        return (
            np.where(i, g_dyn, g_qs),
            np.where(i, d_dyn, d_qs),
            np.where(i, v1, v_qs),
            np.where(i, a1, 0.0),
        )

    def evaluate(
        self, s: _SliderState, dt: np.ndarray, dx: np.ndarray
    ) -> tuple[Any, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        du = np.zeros((self.n, 3))
        du[:, :2] = self.e * dx[:, None]
        res = update(self.params, s.contact, du, dt, raise_on_failure=False)
        f1 = self.along(res.traction)
        T = np.einsum("ni,nij,nj->n", self.e, res.tangent[:, :2, :2], self.e)
        g, d, v1, a1 = self.residual(s, dt, dx, f1, T)
        return res, g, d, v1, a1


def _solve_step(mach: _Machine, s: _SliderState, dt: np.ndarray) -> _SliderAttempt:
    """One implicit step: the first root of g(dx) from dx = 0 (see the module docstring).

    Safeguarded Newton: before any sign change, Newton from the latest iterate where the
    slope points to the root, otherwise a geometric expansion away from 0; once a sign
    change brackets a root, Newton from the latest iterate or from either end of the
    bracket if it stays inside, else bisection. The previous step's dx (scaled to this
    step) is tried first where the last step slid in the direction of the out-of-balance
    force.
    """
    n = mach.n
    zero = np.zeros(n)
    res, g, d, v1, a1 = mach.evaluate(s, dt, zero)
    solves = 1
    iters = np.array(res.iterations, dtype=np.int64)
    fn = s.contact.traction[:, 2]
    k_mach = mach.k + np.where(
        mach.inertial,
        mach.m * (1.0 - mach.am) / (mach.beta * dt * dt),
        mach.c / dt,
    )
    tol = 1e-11 * (np.maximum(fn, np.abs(g)) + 1e-300)
    sign0 = np.sign(g)
    direction = -sign0
    x = zero.copy()
    lo, glo, dlo = zero.copy(), g.copy(), d.copy()
    hi, ghi, dhi = np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan)
    done = np.abs(g) <= tol
    guess = s.dx_last * dt / s.dt_last
    use_guess = bool(np.any(s.slipping & (np.sign(guess) == direction) & ~done))
    for _ in range(MAX_ITERATIONS):
        if done.all():
            break
        bracketed = np.isfinite(hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            from_x = x - g / d
            from_lo = lo - glo / dlo
            from_hi = hi - ghi / dhi
        a_, b_ = np.minimum(lo, hi), np.maximum(lo, hi)

        def inside(t: np.ndarray, a_: np.ndarray = a_, b_: np.ndarray = b_) -> np.ndarray:
            return (a_ < t) & (t < b_)

        open_trial = np.where(
            d > 0, from_x, lo + direction * np.maximum(np.abs(lo), np.abs(g) / k_mach)
        )
        closed_trial = np.where(
            inside(from_x),
            from_x,
            np.where(inside(from_lo), from_lo, np.where(inside(from_hi), from_hi, 0.5 * (lo + hi))),
        )
        trial = np.where(bracketed, closed_trial, open_trial)
        if use_guess:
            good = s.slipping & (np.sign(guess) == direction)
            trial = np.where(good, guess, trial)
            use_guess = False
        trial = np.where(np.isfinite(trial), trial, lo)
        x = np.where(done, x, trial)
        res, g_new, d_new, v_new, a_new = mach.evaluate(s, dt, x)
        solves += 1
        iters += res.iterations
        failed = res.status == Status.FAILED
        same = (np.sign(g_new) == sign0) & ~failed
        active = ~done
        to_lo, to_hi = active & same, active & ~same
        lo, glo, dlo = (
            np.where(to_lo, x, lo),
            np.where(to_lo, g_new, glo),
            np.where(to_lo, d_new, dlo),
        )
        hi = np.where(to_hi, x, hi)
        ghi = np.where(to_hi, np.where(failed, np.nan, g_new), ghi)
        dhi = np.where(to_hi, np.where(failed, np.nan, d_new), dhi)
        g = np.where(active & ~failed, g_new, np.where(active, glo, g))
        d = np.where(active & ~failed, d_new, np.where(active, dlo, d))
        x = np.where(active & failed, lo, x)
        v1 = np.where(active, v_new, v1)
        a1 = np.where(active, a_new, a1)
        narrow = np.isfinite(hi) & (np.abs(hi - lo) <= 4e-16 * np.maximum(np.abs(hi), 1e-300))
        done = done | (((np.abs(g_new) <= tol) | narrow) & ~failed)
    if not done.all() or not res.success:
        return _SliderAttempt(
            s, zero, zero, np.asarray(res.status), iters, solves, False,
            "the implicit spring-slider step did not converge (local solve failed or no "
            "equilibrium found)",
        )  # fmt: skip
    slipping = res.status == Status.SLIP
    new = _SliderState(res.state, s.x + x, v1, a1, s.t + dt, slipping, x, dt)
    return _SliderAttempt(
        new, x, np.asarray(res.dissipation), np.asarray(res.status), iters, solves, True
    )


def _combine(a: _SliderAttempt, b: _SliderAttempt) -> _SliderAttempt:
    slid = (a.status == Status.SLIP) | (b.status == Status.SLIP)
    return _SliderAttempt(
        b.state,
        a.dx + b.dx,
        a.dissipation + b.dissipation,
        np.where(slid, Status.SLIP, b.status).astype(np.int8),
        a.iterations + b.iterations,
        a.solves + b.solves,
        a.ok and b.ok,
        b.reason or a.reason,
    )


def _error(mach: _Machine, a: _SliderAttempt, b: _SliderAttempt) -> float:
    fn = np.maximum(a.state.contact.traction[:, 2], 1e-300)
    df = np.abs(mach.along(a.state.contact.traction) - mach.along(b.state.contact.traction))
    dx = mach.k * np.abs(a.state.x - b.state.x)
    dR = np.abs(a.state.contact.R - b.state.contact.R)
    return float(np.max(np.maximum(np.maximum(df, dx) / fn, dR)))


def simulate_spring_slider(
    params: SubloadingParams,
    machine: SpringSlider,
    duration: Any,
    *,
    steps: int | None = None,
    max_step: float | None = None,
    initial: InitialConditions | ContactState | None = None,
    n_points: int | None = None,
    settings: DriverSettings | None = None,
    progress: ProgressCallback | None = None,
    accuracy: Any = _UNSET,
    max_halvings: Any = _UNSET,
) -> History:
    """Pull the slider for ``duration`` [s] (scalar or per point) and record every step.

    ``steps`` equal time steps (default 1000) or as many as needed for ``max_step`` [s].
    The slider starts at rest with the spring relaxed on the initial contact (zero
    tangential traction by default). Returns a :class:`~frictionlab.driver.History`
    whose ``extra`` holds ``load_point`` [m], ``velocity`` (slider) [m/s] and
    ``spring_force`` k (V t - x) [Pa]; the slip is ``x e``. ``settings``
    (:class:`~frictionlab.driver.simulate.DriverSettings`: substepping and accuracy) works
    as in :func:`~frictionlab.driver.simulate`; ``accuracy=`` and ``max_halvings=`` are
    deprecated (one release).
    """
    chosen = driver_settings(settings, accuracy, max_halvings, "simulate_spring_slider")
    accuracy, max_halvings = chosen.accuracy, chosen.max_halvings
    total_time = _checked("duration", duration, ">0")
    init = InitialConditions() if initial is None else initial
    sizes = machine.sizes() | ({total_time.shape[0]} if total_time.ndim == 1 else set())
    n = count_points(params, (), init, n_points, sizes)
    contact = init if isinstance(init, ContactState) else init.state(params, n)
    if steps is not None and max_step is not None:
        raise ParameterError("steps", steps, "steps or max_step, not both")
    limit = _max_step(max_step)
    checked = _steps("steps", steps)
    n_steps: int = _count(total_time, limit) if limit is not None else (checked or 1000)
    mach = _Machine(params, machine, n)
    dt = np.broadcast_to(total_time, (n,)) / n_steps
    f0 = mach.along(contact.traction)
    a0 = np.where(mach.inertial, (mach.c * mach.V - f0) / np.where(mach.inertial, mach.m, 1.0), 0.0)
    state = _SliderState(
        contact, np.zeros(n), np.zeros(n), a0, np.zeros(n), np.zeros(n, bool), np.zeros(n), dt
    )

    rows: dict[str, list[np.ndarray]] = {
        "t": [state.t], "x": [state.x], "v": [state.v], "traction": [contact.traction],
        "F": [contact.F], "R": [contact.R], "up": [contact.plastic_slip],
        "diss": [np.zeros(n)], "status": [np.full(n, -1, dtype=np.int8)],
        "iterations": [np.zeros(n, dtype=np.int64)],
    }  # fmt: skip
    substeps, solves = [0], [0]
    work = dict.fromkeys(
        ("steps", "substeps", "solves", "iterations", "refined_for_failure",
         "refined_for_accuracy", "accuracy_unmet"), 0,
    )  # fmt: skip
    success, message = True, f"completed {n_steps} steps"
    for k in range(n_steps):
        outcome, w = substep(
            state,
            dt,
            solve=lambda st, h: _solve_step(mach, st, h),
            halves=lambda st, h: (0.5 * h, 0.5 * h),
            combine=_combine,
            error=lambda a, b: _error(mach, a, b),
            accuracy=accuracy,
            max_halvings=max_halvings,
            n_points=n,
        )
        _count_work(work, w, completed=outcome.ok)
        if not outcome.ok:
            success = False
            message = (
                f"step {k + 1} of {n_steps} (t = {float(state.t.max()):.6g} s): {outcome.reason}"
            )
            break
        state = outcome.state
        _record(rows, state, outcome, w)
        substeps.append(w.substeps)
        solves.append(w.solves)
        if progress is not None:
            progress(k + 1, n_steps)
    t = np.array(rows["t"])
    x = np.array(rows["x"])
    load = mach.V * t
    resolved = {
        "kind": "spring_slider",
        "stiffness": mach.k,
        "velocity": mach.V,
        "mass": mach.m,
        "damping": mach.c,
        "direction_deg": np.degrees(np.arctan2(mach.e[:, 1], mach.e[:, 0])),
        "spectral_radius": machine.spectral_radius,
        "duration": np.broadcast_to(total_time, (n,)).astype(float),
        "steps": n_steps,
    }
    n_rows = t.shape[0]
    return History(
        time=t,
        slip=x[..., None] * mach.e[None, :, :],
        approach=np.zeros_like(t),
        traction=np.array(rows["traction"]),
        F=np.array(rows["F"]),
        R=np.array(rows["R"]),
        plastic_slip=np.array(rows["up"]),
        dissipation=np.array(rows["diss"]),
        status=np.array(rows["status"]),
        segment=np.minimum(np.arange(n_rows), 1),
        substeps=np.array(substeps),
        solves=np.array(solves),
        iterations=np.array(rows["iterations"]),
        segments=(SegmentRecord(1, "spring_slider", 1, n_rows - 1, resolved),)
        if n_rows > 1
        else (),
        final_state=state.contact,
        success=success,
        message=message,
        work=work,
        extra={
            "load_point": load,
            "velocity": np.array(rows["v"]),
            "spring_force": mach.k * (load - x),
        },
        extra_units={"load_point": "m", "velocity": "m/s", "spring_force": "Pa"},
    )


def _record(
    rows: dict[str, list[np.ndarray]], s: _SliderState, att: _SliderAttempt, w: StepWork
) -> None:
    rows["t"].append(s.t)
    rows["x"].append(s.x)
    rows["v"].append(s.v)
    rows["traction"].append(s.contact.traction)
    rows["F"].append(s.contact.F)
    rows["R"].append(s.contact.R)
    rows["up"].append(s.contact.plastic_slip)
    rows["diss"].append(rows["diss"][-1] + att.dissipation)
    rows["status"].append(att.status.astype(np.int8))
    rows["iterations"].append(w.iterations)


# --------------------------------------------------------------------------- stability
def steady_F(params: SubloadingParams, velocity: Any) -> np.ndarray:
    """Steady size F_ss(V) (mu_ss for the cone) at plastic sliding speed V [m/s], Eq (25).

    Closed form ``(kappa V + xi) / (kappa V/F_k + xi/F_s)`` for m = n = 1 and the default
    recovery form; otherwise the root of ``kappa phi(F) V = xi psi(F)`` on [F_k, F_s].
    """
    V = np.abs(np.atleast_1d(np.asarray(velocity, dtype=np.float64)))
    n = max(V.size, params.n_points if params.per_point else 1)

    def vec(a: Any) -> np.ndarray:
        return np.broadcast_to(np.asarray(a, dtype=np.float64), (n,))

    Fs, Fk, kappa, xi = vec(params.static), vec(params.kinetic), vec(params.kappa), vec(params.xi)
    m, nn, V = vec(params.m), vec(params.n), vec(V)
    if params.recovery_form == "one_minus" and np.all(m == 1.0) and np.all(nn == 1.0):
        return np.asarray(steady_size(V, kappa, xi, Fs, Fk), dtype=np.float64)  # type: ignore[arg-type]
    from scipy.optimize import brentq  # here: importing SciPy's optimisers costs every run ~0.3 s

    out = np.empty(n)
    for i in range(n):
        if kappa[i] * V[i] == 0.0 or Fk[i] == Fs[i]:
            out[i] = Fs[i] if xi[i] > 0 or Fk[i] == Fs[i] else Fk[i]
            continue
        if xi[i] == 0.0:
            out[i] = Fk[i]
            continue

        def balance(F: float, i: int = i) -> float:
            soft = kappa[i] * V[i] * max(F / Fk[i] - 1.0, 0.0) ** m[i]
            x = (1.0 - F / Fs[i]) if params.recovery_form == "one_minus" else (Fs[i] / F - 1.0)
            return soft - xi[i] * max(x, 0.0) ** nn[i]

        out[i] = brentq(balance, Fk[i], Fs[i], xtol=1e-15, rtol=1e-14)
    return out


def critical_stiffness(params: SubloadingParams, velocity: Any, normal_traction: Any) -> np.ndarray:
    """Machine stiffness k_c [Pa/m] below which steady sliding at V is unstable (stick-slip).

    Linear stability of the quasi-static spring-slider about steady sliding (R = 1,
    F = F_ss(V)) along the principal axis e*_1 (docs/driver.md): the R equation
    decouples (dR'/dR = -pi u V/2 < 0) and the F equation is stable if and only if the
    series stiffness of machine and contact, ``k alpha_t / (k + alpha_t)``, exceeds the
    softening slope of the steady traction with plastic slip,

        k_soft = kappa (F_ss/F_k - 1)^m  d f_t/dF,   d f_t/dF = A_1 f_n (cone),
        A_1 / g'(chi*) with g(chi*) = F_ss/f_n (closed surfaces),

    so ``k_c = alpha_t k_soft / (alpha_t - k_soft)``. Valid for sliding along e*_1
    (``orthotropy_angle = 0`` and the rail along e_1); the value is per point.
    """
    F = steady_F(params, velocity)
    n = F.size
    fn = np.broadcast_to(np.asarray(normal_traction, dtype=np.float64), (n,))

    def vec(a: Any) -> np.ndarray:
        return np.broadcast_to(np.asarray(a, dtype=np.float64), (n,))

    A1 = np.broadcast_to(params.axis_factors, (n, 2))[:, 0]
    if params.is_cone:
        sensitivity = A1 * fn
    else:
        chi = g_inverse(params.surface, F / fn, params.tear_k)
        sensitivity = A1 / g_function(params.surface, chi, params.tear_k)[1]
    k_soft = vec(params.kappa) * np.maximum(F / vec(params.kinetic) - 1.0, 0.0) ** vec(params.m)
    k_soft = k_soft * sensitivity
    alpha_t = vec(params.alpha_t)
    return np.asarray(alpha_t * k_soft / (alpha_t - k_soft), dtype=np.float64)


def friction_oscillation(history: History, tail: float = 0.5) -> np.ndarray:
    """(N,) peak-to-peak friction ratio over the last ``tail`` fraction of each point's time.

    Near zero for steady sliding; of the order of the stress drop for stick-slip.
    """
    t = history.time
    mu = history.friction_ratio
    start = t[-1] * (1.0 - tail)
    inside = t >= start[None, :]
    hi = np.where(inside, mu, -np.inf).max(axis=0)
    lo = np.where(inside, mu, np.inf).min(axis=0)
    return np.asarray(hi - lo)


def count_slip_events(history: History, factor: float = 10.0, tail: float = 1.0) -> np.ndarray:
    """(N,) number of slip events: upward crossings of ``factor * V`` by the slider speed.

    Counted over the last ``tail`` fraction of the time; needs the spring-slider's
    ``velocity`` series and the load-point velocity from ``segments[0].resolved``.
    """
    v = history.extra["velocity"]
    V = np.asarray(history.segments[0].resolved["velocity"])
    fast = v > factor * np.maximum(V, 1e-300)[None, :]
    t = history.time
    inside = t >= (t[-1] * (1.0 - tail))[None, :]
    ups = fast[1:] & ~fast[:-1] & inside[1:]
    return np.asarray(ups.sum(axis=0))
