"""U(R), Eq (29), Eq (30) and the F integrators against ODE integration."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.special import expi

from frictionlab.subloading import (
    U_function,
    hold_recovery,
    plastic_slip_for_ratio,
    ratio_closed_form,
    steady_size,
)
from frictionlab.subloading.evolution import (
    BACKWARD_EULER,
    EXPONENTIAL,
    ONE_MINUS,
    RATIO,
    U_COT,
    U_LN,
    ratio_after,
    size_after,
)


def test_U_properties() -> None:
    R = np.linspace(1e-6, 1.999, 4001)
    U = U_function(R, u=100.0)
    assert U_function(np.array([0.0]), 100.0)[0] == math.inf
    assert abs(U_function(np.array([1.0]), 100.0)[0]) < 1e-12
    assert np.all(np.diff(U) < 0)  # strictly decreasing
    assert np.all(U[R > 1.0] < 0) and np.all(U[R < 1.0] > 0)
    Uln = U_function(R[R <= 1.0], 100.0, law="ln")
    assert np.all(np.diff(Uln) < 0) and np.all(Uln > 0)
    assert U_function(np.array([1.0]), 100.0, law="ln")[0] == 0.0


@pytest.mark.parametrize(("R0", "dup"), [(0.0, 0.01), (0.5, 0.005), (0.9, 0.02)])
def test_eq29_closed_form_equals_ode(R0: float, dup: float) -> None:
    """Scenario E29: Eq (29) and the kernel against dR/du^p = u cot(pi R/2)."""
    u = 100.0
    start, R_start = (0.0, R0)
    if R0 == 0.0:  # U(0) is infinite: start the ODE from the exact small-slip expansion
        start = 1e-12
        R_start = (2 / np.pi) * math.sqrt(np.pi * u * start)
    sol = solve_ivp(
        lambda s, R: u / np.tan(0.5 * np.pi * R), (start, dup), [R_start],
        method="LSODA", rtol=1e-12, atol=1e-14,
    )  # fmt: skip
    R_ode = sol.y[0, -1]
    assert ratio_closed_form(R0, dup, u) == pytest.approx(R_ode, rel=1e-8, abs=1e-10)
    R_kernel, slope, _ = ratio_after(U_COT, u, R0, dup)
    assert R_kernel == pytest.approx(R_ode, rel=1e-8)
    assert slope == pytest.approx(u / math.tan(0.5 * math.pi * R_kernel), rel=1e-12)
    assert plastic_slip_for_ratio(R0, R_ode, u) == pytest.approx(dup, rel=1e-7)


def test_eq29_accuracy_near_one() -> None:
    """R from a start within 1e-12 of 1 stays monotone and exact (no arccos near 1)."""
    u = 100.0
    R0 = 1.0 - 1e-12
    for dlam in (1e-12, 1e-9, 1e-3):
        R = ratio_after(U_COT, u, R0, dlam)[0]
        # 1 - R = (2/pi) asin(sin(pi (1 - R0)/2) e^{-a}) to first order
        expected = (1 - R0) * math.exp(-0.5 * math.pi * u * dlam)
        assert pytest.approx(expected, rel=1e-3, abs=2e-16) == (1.0 - R)
        assert R0 <= R <= 1.0


def test_ln_law_implicit_euler_converges_to_li_solution() -> None:
    """Eq (30): many implicit-Euler steps approach li(R0) - li(R) = u Delta u^p (first order)."""
    u, R0, dup = 100.0, 0.1, 0.01
    li = lambda r: expi(math.log(r))  # noqa: E731
    exact = solve_ivp(
        lambda s, R: -u * np.log(R), (0, dup), [R0], method="LSODA", rtol=1e-12, atol=1e-14
    ).y[0, -1]
    assert li(R0) - li(exact) == pytest.approx(u * dup, rel=1e-7)
    errors = []
    for steps in (50, 100, 200, 400):
        R = R0
        for _ in range(steps):
            R = ratio_after(U_LN, u, R, dup / steps)[0]
        errors.append(abs(R - exact))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    np.testing.assert_allclose(ratios, 2.0, rtol=0.1)  # first order
    R1, slope, _ = ratio_after(U_LN, u, R0, 1e-4)
    assert R1 - R0 + u * 1e-4 * math.log(R1) == pytest.approx(0.0, abs=1e-15)
    h = 1e-9
    fd = (ratio_after(U_LN, u, R0, 1e-4 + h)[0] - ratio_after(U_LN, u, R0, 1e-4 - h)[0]) / (2 * h)
    assert slope == pytest.approx(fd, rel=1e-6)


@pytest.mark.parametrize("law", [U_COT, U_LN])
@pytest.mark.parametrize("R0", [0.05, 0.5, 0.95])
def test_ratio_derivative_with_respect_to_the_start(law: int, R0: float) -> None:
    h = 1e-7
    _, _, dR0 = ratio_after(law, 100.0, R0, 2e-3)
    fd = (ratio_after(law, 100.0, R0 + h, 2e-3)[0] - ratio_after(law, 100.0, R0 - h, 2e-3)[0]) / (
        2 * h
    )
    assert dR0 == pytest.approx(fd, rel=1e-6)


def _ode_F(F0, Fs, Fk, kappa, xi, m, n, rate, duration, form="one_minus"):
    """Reference: integrate Eq (25) with constant plastic rate over the time interval."""

    def rhs(t, F):
        soft = kappa * max(F[0] / Fk - 1.0, 0.0) ** m * rate
        if form == "one_minus":
            rec = xi * max(1.0 - F[0] / Fs, 0.0) ** n
        else:
            rec = xi * max(Fs / F[0] - 1.0, 0.0) ** n
        return [-soft + rec]

    return solve_ivp(rhs, (0, duration), [F0], method="LSODA", rtol=1e-12, atol=1e-14).y[0, -1]


@pytest.mark.parametrize(("dlam", "dt"), [(0.0, 50.0), (0.05, 0.0), (0.05, 0.5), (1.0, 10.0)])
def test_exponential_update_is_exact_for_constant_rates(dlam: float, dt: float) -> None:
    Fs, Fk, kappa, xi, F0 = 0.5, 0.3, 1.0, 1e-2, 0.42
    F, dF = size_after(F0, Fs, Fk, kappa, xi, 1.0, 1.0, dlam, dt, EXPONENTIAL, ONE_MINUS)
    duration = dt if dt > 0 else 1.0
    rate = dlam / duration
    xi_eff = xi if dt > 0 else 0.0
    expected = _ode_F(F0, Fs, Fk, kappa, xi_eff, 1.0, 1.0, rate, duration)
    assert pytest.approx(expected, rel=1e-9) == F
    h = 1e-7
    fd = (
        size_after(F0, Fs, Fk, kappa, xi, 1, 1, dlam + h, dt, EXPONENTIAL, ONE_MINUS)[0]
        - size_after(F0, Fs, Fk, kappa, xi, 1, 1, max(dlam - h, 0), dt, EXPONENTIAL, ONE_MINUS)[0]
    ) / (dlam + h - max(dlam - h, 0))
    assert dF == pytest.approx(fd, rel=1e-5, abs=1e-9)


@pytest.mark.parametrize(("m", "n"), [(2.0, 1.0), (0.5, 1.0), (1.0, 2.0), (1.0, 0.5), (1.5, 3.0)])
def test_split_update_exact_for_each_mechanism_alone(m: float, n: float) -> None:
    Fs, Fk, kappa, xi = 1.0, 0.6, 2.0, 0.05
    # pure recovery over 5 s from 0.7
    F_rec, _ = size_after(0.7, Fs, Fk, kappa, xi, m, n, 0.0, 5.0, EXPONENTIAL, ONE_MINUS)
    assert F_rec == pytest.approx(_ode_F(0.7, Fs, Fk, kappa, xi, m, n, 0.0, 5.0), rel=1e-9)
    assert F_rec == pytest.approx(hold_recovery(0.7, Fs, xi, 5.0, n=n), rel=1e-12)
    # pure softening by 0.1 from 0.95 (rate 1 over 0.1 s, no recovery)
    F_soft, _ = size_after(0.95, Fs, Fk, kappa, xi, m, n, 0.1, 0.0, EXPONENTIAL, ONE_MINUS)
    assert F_soft == pytest.approx(_ode_F(0.95, Fs, Fk, kappa, 0.0, m, n, 1.0, 0.1), rel=1e-9)


@pytest.mark.parametrize("form", [ONE_MINUS, RATIO])
@pytest.mark.parametrize(("m", "n"), [(1.0, 1.0), (2.0, 0.5)])
def test_backward_euler_is_first_order_and_bounded(form: int, m: float, n: float) -> None:
    Fs, Fk, kappa, xi, F0 = 1.0, 0.6, 1.0, 0.2, 0.8
    total_lam, total_t = 0.3, 1.0
    name = "one_minus" if form == ONE_MINUS else "ratio"
    exact = _ode_F(F0, Fs, Fk, kappa, xi, m, n, total_lam / total_t, total_t, name)
    errors = []
    for steps in (20, 40, 80, 160):
        F = F0
        for _ in range(steps):
            F, _ = size_after(F, Fs, Fk, kappa, xi, m, n, total_lam / steps, total_t / steps,
                              BACKWARD_EULER, form)  # fmt: skip
            assert Fk <= F <= Fs
        errors.append(abs(F - exact))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    np.testing.assert_allclose(ratios, 2.0, rtol=0.1)


def test_F_stays_in_bounds_for_huge_increments() -> None:
    for integ in (EXPONENTIAL, BACKWARD_EULER):
        for dlam, dt in ((1e6, 0.0), (0.0, 1e9), (1e3, 1e3)):
            F, dF = size_after(0.45, 0.5, 0.3, 1.0, 1e-3, 1.0, 1.0, dlam, dt, integ, ONE_MINUS)
            assert 0.3 <= F <= 0.5 and math.isfinite(dF)


def test_steady_size_limits() -> None:
    assert steady_size(1e12, 1.0, 1e-3, 0.5, 0.3) == pytest.approx(0.3, rel=1e-9)
    assert steady_size(0.0, 1.0, 1e-3, 0.5, 0.3) == pytest.approx(0.5, rel=1e-12)
    # the fixed point of Eq (25) with |v^p| = V
    V, kappa, xi, Fs, Fk = 0.1, 1.0, 1e-3, 0.5, 0.3
    F = steady_size(V, kappa, xi, Fs, Fk)
    assert -kappa * (F / Fk - 1) * V + xi * (1 - F / Fs) == pytest.approx(0.0, abs=1e-15)
