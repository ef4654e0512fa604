"""Reference scenarios with their analytic expectations."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.subloading import (
    Status,
    friction_coefficient_on_yield,
    hold_recovery,
    initial_state,
    ratcheting_slip_per_cycle,
    steady_size,
    update,
)

from .support import V, fresh, hold, run, set_a, set_b, slide

MU_S, MU_K, KAPPA, XI, U = 0.5, 0.3, 1.0, 1e-3, 100.0


def mu_ss(velocity: float) -> float:
    """Steady size, typed independently of the library: (kappa V + xi)/(kappa V/mu_k + xi/mu_s)."""
    return (KAPPA * velocity + XI) / (KAPPA * velocity / MU_K + XI / MU_S)


# --------------------------------------------------------------------------- A1
def test_a1_monotonic_curve_is_smooth_with_peak_below_mu_s() -> None:
    params = set_a()
    h = slide(params, fresh(params), distance=1.0, steps=1000)
    ratio = h.traction[:, 0, 0]
    peak = int(np.argmax(ratio))
    assert 0.3 < ratio[peak] < MU_S  # softening during the transition
    assert h.R[-1, 0] == pytest.approx(1.0, abs=1e-12)
    # after the peak: plastic loading in the softening branch, decaying toward mu_ss
    assert np.all(h.status[peak:, 0] == Status.SLIP)
    assert np.all(np.diff(ratio[peak + 1 :]) < 0)
    assert ratio[-1] > mu_ss(V)


def test_a1_rise_is_concave_without_a_yield_kink() -> None:
    params = set_a()
    h = slide(params, fresh(params), distance=0.01, steps=1000)  # dx = 1e-5
    ratio = h.traction[:, 0, 0]
    slope = np.diff(np.concatenate([[0.0], ratio])) / 1e-5
    peak = int(np.argmax(ratio))
    assert slope[0] > 0.75 * 1000.0  # starts elastic (U(0) = inf)
    assert np.all(np.diff(slope[:peak]) < 0)  # the tangent falls continuously (concave)
    assert np.max(-np.diff(slope[:peak])) < 0.25 * 1000.0  # no kink: no sudden drop


def test_a1_step_size_invariance_with_the_exponential_update() -> None:
    params = set_a()
    finals = []
    for steps in (10, 100, 1000, 10000):
        finals.append(slide(params, fresh(params), 1.0, steps).traction[-1, 0, 0])
    np.testing.assert_allclose(finals, finals[-1], rtol=1e-6)


def test_a1_backward_euler_converges_at_first_order() -> None:
    params_be = set_a(F_integrator="backward_euler")
    exact = slide(set_a(), fresh(set_a()), 1.0, 10000).traction[-1, 0, 0]
    errors = [
        abs(slide(params_be, fresh(params_be), 1.0, steps).traction[-1, 0, 0] - exact)
        for steps in (100, 200, 400, 800)
    ]
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    np.testing.assert_allclose(ratios, 2.0, rtol=0.15)


# --------------------------------------------------------------------------- A2
def test_a2_steady_sliding_friction_matches_mu_ss() -> None:
    params = set_a()
    velocities = np.array([1e-4, 1e-3, 1e-2, 1e-1, 1.0])
    n, steps, distance = velocities.size, 4000, 5.0
    du = np.zeros((steps, n, 3))
    du[:, :, 0] = distance / steps
    dts = np.broadcast_to(distance / steps / velocities, (steps, n))
    state = fresh(params, n=n)
    for k in range(steps):
        state = update(params, state, du[k], dts[k]).state
    expected = np.array([mu_ss(v) for v in velocities])
    np.testing.assert_allclose(state.traction[:, 0], expected, rtol=1e-6)
    np.testing.assert_allclose(state.R, 1.0, atol=1e-9)
    np.testing.assert_allclose(steady_size(velocities, KAPPA, XI, MU_S, MU_K), expected, rtol=1e-14)


def test_a2_without_recovery_friction_goes_to_mu_k_exactly() -> None:
    params = set_a(xi=0.0)
    h = slide(params, fresh(params), 8.0, 2000)
    assert h.traction[-1, 0, 0] == pytest.approx(MU_K, rel=1e-9)


# --------------------------------------------------------------------------- A3
def test_a3_slide_hold_slide() -> None:
    params = set_a()
    holds = np.array([10.0, 100.0, 1000.0, 1e4])
    n = holds.size
    state = slide(params, fresh(params, n=n), 1.0, 1000).state
    stop_traction, mu0, R0 = state.traction.copy(), state.F.copy(), state.R.copy()
    R_prev = R0
    for k in range(200):
        step = update(params, state, np.zeros((n, 3)), holds / 200)
        assert np.all(step.status == Status.STICK) and np.all(step.plastic_multiplier == 0)
        np.testing.assert_array_equal(step.traction, stop_traction)  # no relaxation
        assert np.all(R_prev > step.state.R)
        R_prev = step.state.R
        state = step.state
        expected = MU_S - (MU_S - mu0) * np.exp(-XI * holds * (k + 1) / 200 / MU_S)
        np.testing.assert_allclose(state.F, expected, rtol=1e-13)
    np.testing.assert_allclose(state.R, stop_traction[:, 0] / state.F, rtol=1e-14)
    again = slide(params, state, 0.3, 300, x0=1.0)
    ratio = again.traction[:, :, 0]
    peaks = ratio.max(axis=0)
    assert np.all(np.diff(peaks) > 0) and np.all(peaks <= MU_S)
    assert np.all(peaks > stop_traction[:, 0])  # a restart peak above the stop value
    ipk = ratio.argmax(axis=0)
    for j in range(n):  # after the peak, the friction decays toward kinetic again
        assert ipk[j] < 299 and np.all(np.diff(ratio[ipk[j] + 1 :, j]) < 0)


def test_hold_with_one_step_equals_many_steps() -> None:
    params = set_a()
    state = slide(params, fresh(params), 1.0, 200).state
    one = hold(params, state, 500.0, 1).state
    many = hold(params, state, 500.0, 500).state
    np.testing.assert_allclose(one.F, many.F, rtol=1e-13)
    np.testing.assert_allclose(one.F, hold_recovery(state.F, MU_S, XI, 500.0), rtol=1e-13)


# --------------------------------------------------------------------------- A4
def test_a4_rotational_anisotropy() -> None:
    beta = 0.05
    params = set_a(rotation=(beta, 0.0))
    state = fresh(params, n=2)
    assert pytest.approx(beta / MU_S, rel=1e-14) == state.R  # R0 = |beta|/mu_s
    du = np.zeros((2000, 2, 3))
    du[:, 0, 0], du[:, 1, 0] = 10.0 / 2000, -10.0 / 2000
    h = run(params, state, du, np.full(2000, 10.0 / 2000 / V))
    final = h.traction[-1, :, 0]
    np.testing.assert_allclose(final, [mu_ss(V) + beta, -(mu_ss(V) - beta)], rtol=1e-6)
    early = slide(params, state, 2.0, 2000).traction[:, :, 0]  # both points forward
    back = run(params, state, -np.abs(du[:2000]), np.full(2000, 10.0 / 2000 / V))
    assert early.max() > np.abs(back.traction[:, 1, 0]).max()  # larger peak along +beta


# --------------------------------------------------------------------------- A5
def test_a5_cyclic_turning_points_alternate_and_decay() -> None:
    params = set_a()
    state = fresh(params)
    turning = []
    dx = 0.05 / 100
    for _ in range(4):
        for steps, sign in ((100, 1.0), (200, -1.0), (100, 1.0)):
            du = np.zeros((steps, 1, 3))
            du[:, 0, 0] = sign * dx
            h = run(params, state, du, np.full(steps, dx / V))
            state = h.state
            assert np.all(h.dissipation >= 0.0)
            turning.append(h.traction[-1, 0, 0])
    tp = np.array(turning).reshape(4, 3)[:, :2].ravel()  # +0.05 and -0.05 turning points
    assert np.all(np.sign(tp) == np.tile([1.0, -1.0], 4))
    assert np.all(np.diff(np.abs(tp)) < 0)


# --------------------------------------------------------------------------- A6
@pytest.mark.parametrize("increments", [1, 200])
def test_a6_ratcheting_slip_per_cycle_is_exact(increments: int) -> None:
    params = set_a(kappa=0.0, xi=0.0)
    state = fresh(params)
    R_max = 0.8
    target_max = R_max * MU_S * 1.0
    slip = 0.0
    residual = []
    for _ in range(3):
        targets = np.concatenate(
            [
                np.linspace(0, target_max, increments + 1)[1:],
                np.linspace(target_max, 0, increments + 1)[1:],
            ]
        )
        for target in targets:
            du = np.zeros((1, 3))
            for _newton in range(50):  # traction control with the consistent tangent
                trial = update(params, state, du, 0.0)
                r = target - trial.traction[0, 0]
                if abs(r) < 1e-14:
                    break
                du[0, 0] += r / trial.tangent[0, 0, 0]
            state = trial.state
            slip += du[0, 0]
        residual.append(slip)
    per_cycle = np.diff(np.concatenate([[0.0], residual]))
    expected = (2.0 / (math.pi * U)) * math.log(1.0 / math.cos(math.pi * R_max / 2.0))
    np.testing.assert_allclose(per_cycle, expected, rtol=1e-9)
    assert ratcheting_slip_per_cycle(R_max, U) == pytest.approx(expected, rel=1e-14)


# --------------------------------------------------------------------------- A7
def test_a7a_peak_tends_to_mu_s_at_the_elastic_limit_as_u_grows() -> None:
    us = np.array([10.0, 100.0, 1e3, 1e4, 1e5])
    params = set_a(u=us)
    h = slide(params, fresh(params, n=5), 0.1, 2000)
    ratio = h.traction[:, :, 0]
    peaks = ratio.max(axis=0)
    x_peak = h.x[ratio.argmax(axis=0)]
    elastic_limit = MU_S * 1.0 / 1000.0  # mu_s f_n / alpha_t
    assert np.all(np.diff(peaks) > 0) and np.all(peaks < MU_S)
    assert np.all(np.diff(MU_S - peaks) < 0)
    assert peaks[-1] == pytest.approx(MU_S, rel=1e-3)
    assert np.all(np.diff(x_peak) < 0)  # the peak moves toward the elastic limit
    assert elastic_limit < x_peak[-1] < 1.5 * elastic_limit


def test_a7b_without_softening_and_recovery_the_curve_is_the_closed_form() -> None:
    """kappa = xi = 0: x = f/alpha_t + (2/(pi u)) ln sec(pi f / (2 mu_s f_n)) exactly (Eq 29)."""
    params = set_a(kappa=0.0, xi=0.0)
    h = slide(params, fresh(params), 1.0, 1000)
    f = h.traction[:, 0, 0]
    assert np.all(np.diff(f) >= -1e-15)  # monotone hardening-like rise, no peak
    inner = f < MU_S * (1 - 1e-5)  # ln sec is ill-conditioned as R -> 1
    x_closed = f / 1000.0 + (2.0 / (math.pi * U)) * np.log(1.0 / np.cos(0.5 * math.pi * f / MU_S))
    np.testing.assert_allclose(x_closed[inner], h.x[inner], rtol=1e-9)
    assert f[-1] == pytest.approx(MU_S, rel=1e-12)
    assert f[9] < f[49] < f[-1]


def test_no_softening_keeps_mu_at_mu_s() -> None:
    params = set_a(kappa=0.0)
    h = slide(params, fresh(params), 1.0, 300)
    np.testing.assert_allclose(h.F, MU_S, rtol=0, atol=0)


# --------------------------------------------------------------------------- A8
def test_a8_orthotropic_cone() -> None:
    C2 = 0.6
    params = set_a(orthotropy=(1.0, C2))
    directions = [(1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
    finals = []
    for d in directions:
        finals.append(slide(params, fresh(params), 10.0, 2000, direction=d).traction[-1, 0])
    m = mu_ss(V)
    np.testing.assert_allclose(finals[0][:2], [m, 0.0], rtol=1e-6, atol=1e-12)
    np.testing.assert_allclose(finals[1][:2], [0.0, C2 * m], rtol=1e-6, atol=1e-12)
    f1 = m / math.sqrt(1.0 + C2**2)
    np.testing.assert_allclose(finals[2][:2], [f1, C2**2 * f1], rtol=1e-6)
    angle = math.degrees(math.atan2(finals[2][1], finals[2][0]))
    assert angle == pytest.approx(math.degrees(math.atan(C2**2)), rel=1e-6)


def test_a8_principal_axes_at_an_angle_rotate_the_response() -> None:
    theta = 0.4
    base = set_a(orthotropy=(1.0, 0.6))
    turned = set_a(orthotropy=(1.0, 0.6), orthotropy_angle=theta)
    Q = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])
    d = np.array([0.8, 0.6])
    a = slide(base, fresh(base), 2.0, 400, direction=tuple(d)).traction[-1, 0, :2]
    b = slide(turned, fresh(turned), 2.0, 400, direction=tuple(Q @ d)).traction[-1, 0, :2]
    np.testing.assert_allclose(b, Q @ a, rtol=1e-10, atol=1e-13)


def test_a8_orthotropic_closed_surface() -> None:
    M, M2f, fn = 0.5, 0.6, 0.2
    params = set_b(orthotropy=(1.0, M2f), xi=0.0, kappa=5.0)
    finals = [
        slide(params, fresh(params, fn=fn), 6.0, 1500, direction=d).traction[-1, 0]
        for d in ((1.0, 0.0), (0.0, 1.0))
    ]
    F_k = 0.6
    np.testing.assert_allclose(finals[0][0] / fn, M * math.sqrt(F_k / fn - 1), rtol=1e-6)
    np.testing.assert_allclose(finals[1][1] / fn, M2f * M * math.sqrt(F_k / fn - 1), rtol=1e-6)


# --------------------------------------------------------------------------- B1, B2, E5
def test_b1_b2_modified_cam_clay() -> None:
    params = set_b()
    fn, M = 0.2, 0.5
    b1 = slide(params, fresh(params, fn=fn), 1.0, 1000)
    ratio = b1.traction[:, 0, 0] / fn
    assert ratio.max() <= M * math.sqrt(1.0 / fn - 1.0)
    b2 = slide(params, b1.state, 19.0, 3800, x0=1.0)
    F_ss = (KAPPA * V + XI) / (KAPPA * V / 0.6 + XI / 1.0)
    assert b2.F[-1, 0] == pytest.approx(F_ss, rel=1e-7)
    assert b2.traction[-1, 0, 0] / fn == pytest.approx(M * math.sqrt(F_ss / fn - 1.0), rel=1e-7)


@pytest.mark.parametrize("surface", ["cam_clay", "modified_cam_clay", "tear", "parabola"])
def test_e5_pressure_dependence_of_steady_friction(surface: str) -> None:
    ratios = np.array([0.05, 0.10, 0.20, 0.30, 0.40])
    params = set_b(surface, F_s=1.0, F_k=1.0, kappa=0.0, xi=0.0)
    state = initial_state(params, normal_traction=ratios)
    h = slide(params, state, 0.5, 500)
    mu = h.traction[-1, :, 0] / ratios
    expected = friction_coefficient_on_yield(surface, ratios, 1.0, 0.5)
    np.testing.assert_allclose(mu, expected, rtol=1e-10)
    if surface == "modified_cam_clay":  # the friction coefficient falls with pressure
        assert np.all(np.diff(mu) < 0)


# --------------------------------------------------------------------------- symmetry
@pytest.mark.parametrize("factory", [set_a, set_b])
def test_mirror_symmetry_without_rotation(factory) -> None:  # type: ignore[no-untyped-def]
    params = factory()
    fn = 1.0 if factory is set_a else 0.2
    steps = 600
    du = np.zeros((steps, 2, 3))
    pattern = np.concatenate([np.full(250, 1e-3), np.full(150, -1.5e-3), np.full(200, 8e-4)])
    du[:, 0, 0], du[:, 1, 0] = pattern, -pattern
    du[:, 0, 1], du[:, 1, 1] = 0.3 * pattern, -0.3 * pattern
    h = run(params, fresh(params, fn=fn, n=2), du, np.full(steps, 0.01))
    np.testing.assert_allclose(h.traction[:, 0, :2], -h.traction[:, 1, :2], rtol=0, atol=1e-15)
    np.testing.assert_allclose(h.F[:, 0], h.F[:, 1], rtol=1e-15)
    np.testing.assert_allclose(h.R[:, 0], h.R[:, 1], rtol=1e-15)


# --------------------------------------------------------------------------- loading criterion
def test_loading_criterion_with_recovery_term() -> None:
    """Creep below N.C^e v = m^c is elastic; above it is plastic (Eq 47)."""
    params = set_a()
    state = slide(params, fresh(params), 2.0, 400).state
    mu = float(state.F[0])
    dt = 1.0
    v_crit = 1.0 * XI * (1.0 - mu / MU_S) / 1000.0  # f_n xi (1 - mu/mu_s)/alpha_t
    slow = update(params, state, np.array([[0.5 * v_crit * dt, 0, 0]]), dt)
    fast = update(params, state, np.array([[2.0 * v_crit * dt, 0, 0]]), dt)
    assert slow.status[0] == Status.STICK and fast.status[0] == Status.SLIP
    assert slow.state.R[0] < state.R[0]


def test_unloading_after_reversal_has_the_elastic_tangent() -> None:
    params = set_a()
    state = slide(params, fresh(params), 1.0, 200).state
    back = update(params, state, np.array([[-1e-4, 0, 0]]), 1e-3)
    assert back.status[0] == Status.STICK
    np.testing.assert_array_equal(back.tangent[0], np.diag([1000.0, 1000.0, 1000.0]))
    assert back.state.R[0] < state.R[0]
    np.testing.assert_allclose(back.state.R, back.traction[:, 0] / back.state.F, rtol=1e-15)


def test_partial_unloading_correction_for_a_reversal_inside_one_step() -> None:
    """A single step through zero traction reloads smoothly from R_start = 0."""
    params = set_a(kappa=0.0, xi=0.0)
    state = slide(params, fresh(params), 0.5, 100).state  # at mu_s, R = 1
    reverse = -(2 * MU_S / 1000.0 + 2e-4)  # unload fully, reload 2e-4 the other way
    one = update(params, state, np.array([[reverse, 0, 0]]), 0.0)
    fine = run(params, state, np.tile([[[reverse / 1000, 0, 0]]], (1000, 1, 1)), np.zeros(1000))
    assert one.status[0] == Status.SLIP
    assert one.traction[0, 0] == pytest.approx(fine.traction[-1, 0, 0], rel=1e-3)
    # without the correction the reload would start from R = 1 and reach -mu_s at once
    assert abs(one.traction[0, 0]) < 0.3


def test_initial_ratio_of_a_rotated_closed_surface() -> None:
    """R0 = f_n g(|beta|/M)/F_s for a virgin closed surface (set B)."""
    beta, M, fn = 0.1, 0.5, 0.2
    params = set_b("modified_cam_clay", rotation=(0.0, beta))
    state = fresh(params, fn=fn)
    assert state.R[0] == pytest.approx(fn * (1.0 + (beta / M) ** 2) / 1.0, rel=1e-14)
