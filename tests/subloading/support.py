"""Helpers shared by the subloading tests: two reference parameter sets and a stepper."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from frictionlab.subloading import ContactState, SubloadingParams, initial_state, update

V = 0.1  # driving velocity of the reference scenarios [m/s]


def set_a(**changes: object) -> SubloadingParams:
    """Parameter set A: isotropic Coulomb cone."""
    base: dict[str, object] = dict(
        surface="coulomb", alpha_n=1000.0, alpha_t=1000.0, mu_s=0.5, mu_k=0.3,
        u=100.0, kappa=1.0, xi=1e-3,
    )  # fmt: skip
    base.update(changes)
    return SubloadingParams(**base)  # type: ignore[arg-type]


def set_b(surface: str = "modified_cam_clay", **changes: object) -> SubloadingParams:
    """Parameter set B: closed surface, F_s = 1, F_k = 0.6, M = 0.5."""
    base: dict[str, object] = dict(
        surface=surface, alpha_n=1000.0, alpha_t=1000.0, F_s=1.0, F_k=0.6, M=0.5,
        u=100.0, kappa=1.0, xi=1e-3,
    )  # fmt: skip
    base.update(changes)
    return SubloadingParams(**base)  # type: ignore[arg-type]


@dataclass
class History:
    """Per-step records of a run (points first, steps second for arrays)."""

    x: np.ndarray  # (steps,) accumulated tangential displacement along the programme
    traction: np.ndarray  # (steps, N, 3)
    F: np.ndarray  # (steps, N)
    R: np.ndarray  # (steps, N)
    dissipation: np.ndarray  # (steps, N)
    status: np.ndarray  # (steps, N)
    state: ContactState  # final state


def run(
    params: SubloadingParams,
    state: ContactState,
    increments: np.ndarray,
    dts: np.ndarray,
    x0: float = 0.0,
) -> History:
    """Apply the increments (steps, N, 3) with time steps (steps,) one call each."""
    xs, tr, Fs, Rs, ds, st = [], [], [], [], [], []
    x = x0
    for du, dt in zip(increments, dts, strict=True):
        step = update(params, state, du, dt)
        state = step.state
        x += float(np.hypot(du[0, 0], du[0, 1]))
        xs.append(x)
        tr.append(step.traction)
        Fs.append(state.F)
        Rs.append(state.R)
        ds.append(step.dissipation)
        st.append(step.status)
    return History(
        np.array(xs), np.array(tr), np.array(Fs), np.array(Rs), np.array(ds), np.array(st), state
    )


def slide(
    params: SubloadingParams,
    state: ContactState,
    distance: float,
    steps: int,
    velocity: float = V,
    direction: tuple[float, float] = (1.0, 0.0),
    x0: float = 0.0,
) -> History:
    """Slide every point by ``distance`` along ``direction`` at ``velocity`` in equal steps."""
    n = state.n_points
    d = np.asarray(direction, dtype=float)
    d = d / np.linalg.norm(d)
    du = np.zeros((steps, n, 3))
    du[:, :, :2] = d * (distance / steps)
    dts = np.full(steps, abs(distance) / steps / velocity)
    return run(params, state, du, dts, x0)


def hold(params: SubloadingParams, state: ContactState, duration: float, steps: int) -> History:
    """Rest for ``duration`` with zero slip."""
    n = state.n_points
    return run(params, state, np.zeros((steps, n, 3)), np.full(steps, duration / steps))


def fresh(params: SubloadingParams, fn: float = 1.0, n: int = 1, **kw: object) -> ContactState:
    """A virgin contact state for N points."""
    return initial_state(params, normal_traction=np.full(n, fn), **kw)  # type: ignore[arg-type]
