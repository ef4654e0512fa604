"""The compiled kernels agree with the interpreted per-point definition.

``frictionlab.subloading.interpreted`` runs the very source of the kernels by the Python
interpreter (numba's decorators replaced by the identity). The compiled serial loop, the
compiled parallel loop (``prange``) and the run without the tangent must give the same
numbers on random states and increments, for every surface and option.
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab._jit import njit
from frictionlab.benchmark import _sliding
from frictionlab.subloading import SubloadingParams, initial_state, interpreted, kernels, update
from frictionlab.subloading.return_map import (
    _FORM_CODES,
    _INTEG_CODES,
    _U_CODES,
    PARALLEL_MIN_POINTS,
)
from frictionlab.subloading.surfaces import SURFACE_CODES

CONE = dict(surface="coulomb", mu_s=0.5, mu_k=0.3, rotation=(0.04, -0.02))
ORTHO = dict(orthotropy=(1.0, 0.7), orthotropy_angle=0.4)

CASES = {
    "cone": dict(CONE, **ORTHO),
    "cone ln, backward Euler, ratio form, m n": dict(
        CONE, U_law="ln", F_integrator="backward_euler", recovery_form="ratio", m=2.0, n=0.5
    ),
    "cone exact general exponents, frozen": dict(CONE, m=1.5, n=2.0, open_recovery="frozen"),
    "cam_clay": dict(surface="cam_clay", F_s=1.0, F_k=0.6, M=0.5, rotation=(0.05, 0.0)),
    "modified_cam_clay": dict(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5, **ORTHO),
    "tear": dict(surface="tear", F_s=1.0, F_k=0.6, M=0.5, tear_k=2.0),
    "parabola ln, ratio form": dict(
        surface="parabola", F_s=1.0, F_k=0.6, M=0.5, U_law="ln", recovery_form="ratio", n=2.0
    ),
}
N = 24


def _random_inputs(params: SubloadingParams, rng: np.random.Generator):
    """States reached by random increments (sliding, unloading, opening, holds)."""
    fn = rng.uniform(0.5, 1.5, N) if params.is_cone else rng.uniform(0.15, 0.35, N)
    state = initial_state(params, normal_traction=fn)
    scale = np.array([2e-4, 2e-4, 2e-5 if params.is_cone else 2e-6])
    for _ in range(6):
        du = rng.normal(size=(N, 3)) * scale
        du[rng.random(N) < 0.1, 2] = -2e-3  # some points open, and re-close later
        state = update(params, state, du, rng.uniform(0.0, 0.2, N), raise_on_failure=False).state
    du = rng.normal(size=(N, 3)) * scale
    du[rng.random(N) < 0.1, 2] = -2e-3
    back = np.arange(N) % 3 == 0  # unloading: against the rotated tangential traction
    fhat = state.traction[:, :2] - state.traction[:, 2:] * np.asarray(params.rotation)
    du[back, :2] = -0.02 * fhat[back] / params.alpha_t
    du[back, 2] = 0.0
    return state, du, rng.uniform(0.0, 0.2, N)


def _run(kernel, params, state, du, dt, tangent: bool, shared_dt: bool = False):  # type: ignore[no-untyped-def]
    out = kernels.empty_outputs(state.n_points, tangent)
    kernel(
        np.ascontiguousarray(state.traction), state.F.copy(), state.R.copy(), state.gap.copy(),
        du, dt, params._kernel_table, shared_dt, SURFACE_CODES[params.surface], params.tear_k,
        _U_CODES[params.U_law], _INTEG_CODES[params.F_integrator],
        _FORM_CODES[params.recovery_form], params.open_recovery == "frozen", tangent,
        out["traction"], out["F"], out["R"], out["gap"], out["dlam"], out["vp"], out["diss"],
        out["tangent"], out["status"], out["iterations"],
    )  # fmt: skip
    del out["plastic_slip"]
    return out


@pytest.mark.slow
@pytest.mark.parametrize("name", list(CASES))
def test_compiled_kernels_equal_the_interpreted_definition(name: str) -> None:
    params = SubloadingParams(**CASES[name])  # type: ignore[arg-type]
    state, du, dt = _random_inputs(params, np.random.default_rng(len(name)))
    reference = _run(interpreted.step_points, params, state, du, dt, True)
    statuses = set(reference["status"].tolist())
    assert kernels.SLIP in statuses and kernels.STICK in statuses  # both branches exercised
    for kernel in (kernels.step_points, kernels.step_points_parallel):
        for tangent in (True, False):
            got = _run(kernel, params, state, du, dt, tangent)
            assert got["tangent"].shape[0] == (N if tangent else 0)
            for key, ref in reference.items():
                value = got[key]
                if key == "tangent" and not tangent:
                    continue
                if key in ("status", "iterations"):
                    np.testing.assert_array_equal(value, ref, err_msg=key)
                else:
                    scale = max(float(np.abs(ref).max()), 1e-300)
                    np.testing.assert_allclose(value, ref, rtol=1e-12, atol=1e-12 * scale,
                                               err_msg=f"{name}: {key}")  # fmt: skip


@pytest.mark.slow
def test_update_options_give_the_same_state() -> None:
    """Parallel (large N), no tangent, and preallocated buffers: one and the same update."""
    params = SubloadingParams(**CASES["cone"])  # type: ignore[arg-type]
    n = PARALLEL_MIN_POINTS + 7
    rng = np.random.default_rng(3)
    state = initial_state(params, normal_traction=rng.uniform(0.5, 1.5, n))
    du = rng.normal(size=(n, 3)) * np.array([1e-3, 1e-3, 1e-5])
    full = update(params, state, du, 0.01)
    lean = update(params, state, du, 0.01, tangent=False)
    buffers = kernels.empty_outputs(n)
    reused = update(params, state, du, 0.01, out=buffers)
    small = update(params, state.take(slice(0, 50)), du[:50], 0.01)  # serial path
    for other in (lean, reused):
        np.testing.assert_array_equal(other.traction, full.traction)
        np.testing.assert_array_equal(other.state.F, full.state.F)
        np.testing.assert_array_equal(other.state.plastic_slip, full.state.plastic_slip)
    # the serial run's last 50 % LANES points go through _point, the parallel run's through
    # the lanes: the same to rounding there, identical where the grouping is the same
    grouped = 50 - 50 % kernels.LANES
    np.testing.assert_array_equal(small.traction[:grouped], full.traction[:grouped])
    np.testing.assert_array_equal(small.tangent[:grouped], full.tangent[:grouped])
    for got, ref in ((small.traction, full.traction[:50]), (small.tangent, full.tangent[:50])):
        scale = float(np.abs(ref).max())
        np.testing.assert_allclose(got[grouped:], ref[grouped:], rtol=1e-12, atol=1e-12 * scale)
    np.testing.assert_array_equal(reused.tangent, full.tangent)
    assert lean.tangent.shape == (0, 3, 3)
    assert reused.traction is buffers["traction"]
    with pytest.raises(Exception, match="shares memory"):
        update(params, reused.state, du, 0.01, out=buffers)  # output over its own input


LANE_CASES = {
    "cone, orthotropic, rotated": CASES["cone"],
    "cone, isotropic, no recovery": dict(CONE, xi=0.0),
}


@pytest.mark.parametrize("name", list(LANE_CASES))
def test_lanes_give_the_numbers_of_the_point_loop(name: str) -> None:
    """step_points (groups of LANES points, shared parameters and time increment) agrees
    with the per-point reference loop to rounding (the lanes' inline elementary functions
    against libm's), with the same statuses and iterations, on states that slide, stick,
    unload, open and re-close; and the serial loop agrees with the interpreted definition."""
    params = SubloadingParams(**LANE_CASES[name])  # type: ignore[arg-type]
    state, du, _ = _random_inputs(params, np.random.default_rng(len(name)))
    state, du = state.take(slice(0, N - 3)), du[: N - 3]  # two groups of LANES and a rest
    dt = np.array([0.05])
    shared = dict(shared_dt=True)
    reference = _run(kernels.step_points_by_point, params, state, du, dt, True, **shared)
    statuses = set(reference["status"].tolist())
    assert {kernels.SLIP, kernels.STICK, kernels.OPEN} <= statuses
    interpreted_ref = _run(interpreted.step_points, params, state, du, dt, True, **shared)
    for kernel in (kernels.step_points, kernels.step_points_parallel):
        for tangent in (True, False):
            got = _run(kernel, params, state, du, dt, tangent, **shared)
            for key, ref in reference.items():
                if key == "tangent" and not tangent:
                    continue
                if key in ("status", "iterations"):
                    np.testing.assert_array_equal(got[key], ref, err_msg=f"{name}: {key}")
                    continue
                scale = max(float(np.abs(ref).max()), 1e-300)
                np.testing.assert_allclose(
                    got[key], ref, rtol=1e-12, atol=1e-12 * scale, err_msg=f"{name}: {key}"
                )
    for key, ref in interpreted_ref.items():
        scale = max(float(np.abs(ref).max()), 1e-300)
        np.testing.assert_allclose(reference[key], ref, rtol=1e-12, atol=1e-12 * scale)


#: The law of ``frictionlab bench``, whose state (benchmark._sliding: f_n = 1, 20 steps)
#: slides at every point.
BENCH_LAW = dict(CONE, u=100.0, kappa=1.0, xi=1e-3, rotation=(0.05, 0.02),
                 orthotropy=(1.0, 0.6), orthotropy_angle=0.3)  # fmt: skip


def test_lanes_agree_when_every_point_slides() -> None:
    """Every lane plastic (no lane handed to the per-point loop for being elastic): the
    lanes' solve, its series follow-up of the last step and the packed result and tangent
    stage agree with the per-point loop to 1e-12, same statuses and iterations."""
    params = SubloadingParams(**BENCH_LAW)  # type: ignore[arg-type]
    state, du = _sliding(params, 4 * kernels.LANES, 1.0)
    dt = np.array([0.01])
    reference = _run(kernels.step_points_by_point, params, state, du, dt, True, shared_dt=True)
    assert (reference["status"] == kernels.SLIP).all()
    assert (reference["iterations"] >= 2).all()  # a Newton step after the first residual
    for tangent in (True, False):
        got = _run(kernels.step_points, params, state, du, dt, tangent, shared_dt=True)
        for key, ref in reference.items():
            if key == "tangent" and not tangent:
                continue
            if key in ("status", "iterations"):
                np.testing.assert_array_equal(got[key], ref, err_msg=key)
                continue
            scale = max(float(np.abs(ref).max()), 1e-300)
            np.testing.assert_allclose(got[key], ref, rtol=1e-12, atol=1e-12 * scale,
                                       err_msg=key)  # fmt: skip


@njit(cache=True, error_model="numpy")
def _follow_and_fresh(traction, F_old, R_old, gap_old, slip_inc, P, dt, step):  # fmt: skip
    """One group solved by the lanes, then its q moved by the relative ``step``: the
    residual there by the series follow-up and afresh (two scratch arrays)."""
    law, _, ca, sa, e_rec, _, _ = kernels._call_constants(P, dt, 0, 1.0, 0, 0, 0)
    v = np.zeros(kernels.N_ROWS * kernels.LANES)
    kernels._lanes_trial(v, 0, law, ca, sa, dt, e_rec, traction, F_old, R_old, gap_old,
                         slip_inc)  # fmt: skip
    kernels._lanes_start(v, law)
    kernels._lanes_solve(v, law, dt)
    for j in range(kernels.LANES):
        q = v[kernels.V_Q + j] * (1.0 + step)
        v[kernels.V_Q + j] = q
        v[kernels.V_OMQ + j] = 1.0 - q
        v[kernels.V_ACTIVE + j] = 1.0
    fresh = v.copy()
    kernels._lanes_residual(v, law, dt, True)
    kernels._lanes_residual(fresh, law, dt, False)
    return v, fresh


def test_the_series_follow_up_is_the_fresh_residual_to_rounding() -> None:
    """_lanes_residual after a small step (the last Newton step, ~1e-6 relative): the
    series of expm1 and of the ratio's angle give the fresh evaluation's residual, R, F
    and slope to a few ulp; a step beyond the bounds falls back to the fresh one."""
    params = SubloadingParams(**BENCH_LAW)  # type: ignore[arg-type]
    state, du = _sliding(params, kernels.LANES, 1.0)
    args = (np.ascontiguousarray(state.traction), state.F, state.R, state.gap, du,
            params._kernel_table, 0.01)  # fmt: skip
    K = kernels
    rows = {"R": K.V_R, "F": K.V_F, "angle": K.V_ATAN, "y": K.V_Y, "s": K.V_S}
    # sums that cancel (dR F + R dF, Phi - R F): a few ulp of the group's largest
    cancelling = {"r_gamma": K.V_R_GAMMA, "hard": K.V_HARD, "residual": K.V_RES}
    lanes = slice(0, K.LANES)
    for step in (1e-6, -1e-6):
        follow, fresh = _follow_and_fresh(*args, step)
        assert (follow[K.V_STEP_OK :][lanes] == 1.0).all()  # every lane within the bounds
        for name, row in rows.items():
            got, ref = follow[row:][lanes], fresh[row:][lanes]
            np.testing.assert_allclose(got, ref, rtol=8 * 2.0**-52, atol=0.0, err_msg=name)
        for name, row in cancelling.items():
            got, ref = follow[row:][lanes], fresh[row:][lanes]
            scale = max(float(np.abs(ref).max()), float(fresh[K.V_F :][lanes].max()))
            np.testing.assert_allclose(got, ref, rtol=0.0, atol=8 * 2.0**-52 * scale,
                                       err_msg=name)  # fmt: skip
    follow, fresh = _follow_and_fresh(*args, 1e-3)  # beyond ANGLE_STEP_RTOL: afresh
    assert (follow[K.V_STEP_OK :][lanes] == 0.0).all()
    np.testing.assert_array_equal(follow[K.V_R :][lanes], fresh[K.V_R :][lanes])
