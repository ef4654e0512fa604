"""Stick-slip of the spring-slider: both regimes, the stability boundary, the integrator."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.driver import (
    InitialConditions,
    SpringSlider,
    count_slip_events,
    critical_stiffness,
    friction_oscillation,
    simulate_spring_slider,
)
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

from .support import ALPHA, KAPPA, MU_K, mu_ss, set_a


def k_c_cone(velocity: float, fn: float = 1.0) -> float:
    """Critical machine stiffness, derived independently in docs/driver.md: the series
    stiffness k alpha_t/(k + alpha_t) must exceed f_n kappa (mu_ss(V)/mu_k - 1)."""
    k_soft = fn * KAPPA * (mu_ss(velocity) / MU_K - 1.0)
    return ALPHA * k_soft / (ALPHA - k_soft)


def test_critical_stiffness_closed_forms() -> None:
    for V in (1e-3, 1e-2, 1.0):
        assert critical_stiffness(set_a(), V, 1.0)[0] == pytest.approx(k_c_cone(V), rel=1e-12)
    # closed surface (modified Cam-clay): d f_t/dF = M/g'(chi*), g' = 2 chi, chi* = sqrt(F/f_n - 1)
    params = SubloadingParams(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5)
    F = (1e-3 + 1e-3) / (1e-3 / 0.6 + 1e-3 / 1.0)
    chi = math.sqrt(F / 0.2 - 1.0)
    k_soft = 1.0 * (F / 0.6 - 1.0) * 0.5 / (2.0 * chi)
    expected = 1000.0 * k_soft / (1000.0 - k_soft)
    assert critical_stiffness(params, 1e-3, 0.2)[0] == pytest.approx(expected, rel=1e-12)


@pytest.mark.slow
def test_quasi_static_regimes_in_one_run() -> None:
    """Soft machine at 1 mm/s: stick-slip. Just above k_c, or the soft machine at 1 m/s:
    steady sliding at mu_ss(V). Just below k_c: stick-slip. (20 m of load-point travel.)"""
    kc = k_c_cone(1e-3)
    machine = SpringSlider(stiffness=[0.25 * kc, 0.8 * kc, 1.25 * kc, 0.25 * kc],
                           velocity=[1e-3, 1e-3, 1e-3, 1.0])  # fmt: skip
    h = simulate_spring_slider(set_a(), machine, [2e4, 2e4, 2e4, 20.0], steps=2000)
    assert h.success
    osc = friction_oscillation(h, 0.25)
    assert osc[0] > 0.1 and osc[1] > 0.05  # sustained stick-slip
    assert osc[2] < 1e-6 and osc[3] < 1e-6  # steady
    np.testing.assert_allclose(h.friction_ratio[-1, 2], mu_ss(1e-3), rtol=1e-6)
    np.testing.assert_allclose(h.friction_ratio[-1, 3], mu_ss(1.0), rtol=1e-6)
    events = count_slip_events(h, tail=0.5)
    assert events[0] >= 2 and events[1] >= 2 and events[2] == 0 and events[3] == 0
    # quasi-static equilibrium at every step: spring force = friction along the rail
    np.testing.assert_allclose(h.extra["spring_force"], h.traction[..., 0], rtol=0, atol=1e-9)
    # during stick the slider creeps at the contact's elastic share of the load-point speed
    speed = h.extra["velocity"][1:, 0] / 1e-3
    k = 0.25 * kc
    assert np.min(speed) == pytest.approx(k / (k + ALPHA), rel=0.05)


def test_closed_surface_boundary_at_its_critical_stiffness() -> None:
    params = SubloadingParams(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5)
    kc = float(critical_stiffness(params, 1e-3, 0.2)[0])
    h = simulate_spring_slider(
        params, SpringSlider(stiffness=[0.8 * kc, 1.25 * kc], velocity=1e-3), 2e4, steps=1500,
        initial=InitialConditions(normal_traction=0.2),
    )  # fmt: skip
    osc = friction_oscillation(h, 0.25)
    assert osc[0] > 0.05 and osc[1] < 1e-6


def test_inertial_slider_both_regimes() -> None:
    kc = k_c_cone(1e-3)
    k = np.array([0.25 * kc, 4.0 * kc])
    m = 10.0
    machine = SpringSlider(stiffness=k, velocity=1e-3, mass=m, damping=0.2 * np.sqrt(k * m))
    h = simulate_spring_slider(set_a(), machine, 2e4, steps=2000)
    assert h.success
    osc = friction_oscillation(h, 0.25)
    assert osc[0] > 0.1 and osc[1] < 1e-6
    np.testing.assert_allclose(h.friction_ratio[-1, 1], mu_ss(1e-3), rtol=1e-6)
    assert h.extra["velocity"][:, 0].max() > 100 * 1e-3  # dynamic slips


def test_inertial_integrator_is_second_order_on_a_free_oscillation() -> None:
    """Stuck contact (elastic, far below yield): x'' = -(k + alpha_t)/m x + k V t / m.

    With rho_inf = 1 (trapezoidal) the error at t = T falls 4x per halving of dt."""
    params = set_a(mu_s=0.5, mu_k=0.5, kappa=0.0, xi=0.0, u=1e6)  # stays elastic at tiny traction
    k, m, V, T = 100.0, 1.0, 1e-6, 0.5
    w = math.sqrt((k + ALPHA) / m)
    # exact: x(0) = v(0) = 0 -> x = (k V/(m w^2)) (t - sin(w t)/w)
    exact = k * V / (m * w * w) * (T - math.sin(w * T) / w)
    errors = []
    for steps in (200, 400, 800):
        h = simulate_spring_slider(
            params,
            SpringSlider(stiffness=k, velocity=V, mass=m, spectral_radius=1.0),
            T,
            steps=steps,
        )
        errors.append(abs(h.slip[-1, 0, 0] - exact))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    np.testing.assert_allclose(ratios, 4.0, rtol=0.1)


def test_validation() -> None:
    with pytest.raises(ParameterError, match="stiffness"):
        SpringSlider(stiffness=0.0, velocity=1.0)
    with pytest.raises(ParameterError, match="mass"):
        SpringSlider(stiffness=1.0, velocity=1.0, mass=-1.0)
    with pytest.raises(ParameterError, match="spectral_radius"):
        SpringSlider(stiffness=1.0, velocity=1.0, spectral_radius=1.5)
    with pytest.raises(ParameterError, match="number of points"):
        simulate_spring_slider(
            set_a(), SpringSlider(stiffness=[1.0, 2.0], velocity=[1.0, 2.0, 3.0]), 1.0
        )
    with pytest.raises(ParameterError, match="duration"):
        simulate_spring_slider(set_a(), SpringSlider(stiffness=1.0, velocity=1.0), -1.0)
