"""Exact (constant-rate) integration of the size F for every exponent and recovery form.

Issue: exponents m, n != 1 and the ``F_s/F - 1`` recovery form were integrated by a
first-order split, so a few large steps did not give the answer of many small ones
References here are independent: the m = n = 1 closed form, an
accurate ODE solution (SciPy DOP853), and the driver with many small steps.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from frictionlab.driver import History, Hold, Slide, simulate
from frictionlab.driver.simulate import InitialConditions
from frictionlab.subloading import SubloadingParams
from frictionlab.subloading.evolution import (
    EXPONENTIAL,
    ONE_MINUS,
    RATIO,
    constant_rate_size,
    size_after,
)

FS, FK = 0.5, 0.3


def _ode_size(F0: float, a: float, b: float, m: float, n: float, form: int) -> float:
    """dF/dtau = b psi(F) - a phi(F) over tau in [0, 1], solved accurately (SciPy Radau)."""

    def rate(_t: float, F: np.ndarray) -> list[float]:
        x = min(max(F[0], FK), FS)
        phi = max(x / FK - 1.0, 0.0) ** m
        psi = max(1.0 - x / FS, 0.0) ** n if form == ONE_MINUS else max(FS / x - 1.0, 0.0) ** n
        return [b * psi - a * phi]

    sol = solve_ivp(rate, (0.0, 1.0), [F0], method="Radau", rtol=1e-13, atol=1e-16)
    return float(sol.y[0, -1])


def test_general_solver_reproduces_the_closed_form_for_unit_exponents() -> None:
    rng = np.random.default_rng(3)
    for _ in range(40):
        F0 = rng.uniform(FK, FS)
        a, b = 10.0 ** rng.uniform(-3, 1, size=2)
        F1, _ = constant_rate_size(F0, FS, FK, a, b, 1.0, 1.0, ONE_MINUS)
        A = a / FK + b / FS
        F_inf = (a + b) / A
        assert abs(F1 - (F_inf + (F0 - F_inf) * np.exp(-A))) <= 2e-15


@pytest.mark.parametrize("form", [ONE_MINUS, RATIO])
@pytest.mark.parametrize(("m", "n"), [(2.0, 0.5), (0.5, 2.0), (1.5, 0.7), (1.0, 1.0)])
def test_size_after_solves_the_rate_equation(form: int, m: float, n: float) -> None:
    rng = np.random.default_rng(int(10 * m + n) + form)
    for _ in range(6):
        F0 = rng.uniform(FK, FS)
        kappa, xi = 10.0 ** rng.uniform(-2, 1), 10.0 ** rng.uniform(-5, -1)
        dlam, dt = 10.0 ** rng.uniform(-4, 0), 10.0 ** rng.uniform(-1, 3)
        F, dF = size_after(F0, FS, FK, kappa, xi, m, n, dlam, dt, EXPONENTIAL, form)
        assert abs(F - _ode_size(F0, kappa * dlam, xi * dt, m, n, form)) <= 1e-12

        # dF/d(dlam) against a central difference (Richardson-extrapolated)
        def at(lam: float, F0: float = F0, kappa: float = kappa, xi: float = xi,
               dt: float = dt) -> float:  # fmt: skip
            return size_after(F0, FS, FK, kappa, xi, m, n, lam, dt, EXPONENTIAL, form)[0]

        h = 1e-3 * dlam
        d1 = (at(dlam + h) - at(dlam - h)) / (2 * h)
        d2 = (at(dlam + h / 2) - at(dlam - h / 2)) / h
        fd = (4 * d2 - d1) / 3
        assert dF == pytest.approx(fd, rel=1e-5, abs=1e-9)


@pytest.mark.parametrize("form", [ONE_MINUS, RATIO])
@pytest.mark.parametrize(("m", "n"), [(2.0, 0.5), (0.5, 2.0), (1.0, 1.0)])
def test_one_step_equals_two_half_steps(form: int, m: float, n: float) -> None:
    """The rate equation is autonomous: exact integration composes."""
    F0, kappa, xi, dlam, dt = 0.45, 2.0, 1e-2, 0.05, 40.0
    one = size_after(F0, FS, FK, kappa, xi, m, n, dlam, dt, EXPONENTIAL, form)[0]
    half = size_after(F0, FS, FK, kappa, xi, m, n, dlam / 2, dt / 2, EXPONENTIAL, form)[0]
    two = size_after(half, FS, FK, kappa, xi, m, n, dlam / 2, dt / 2, EXPONENTIAL, form)[0]
    assert one == pytest.approx(two, abs=1e-14)


def _law(form: str, m: float, n: float) -> SubloadingParams:
    return SubloadingParams(surface="coulomb", alpha_n=1000.0, alpha_t=1000.0, mu_s=0.5,
                            mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3, m=m, n=n,
                            recovery_form=form)  # fmt: skip


@pytest.mark.slow
@pytest.mark.parametrize(("form", "m", "n"), [("one_minus", 2.0, 0.5), ("ratio", 2.0, 0.5),
                                              ("ratio", 1.0, 1.0)])  # fmt: skip
def test_few_large_steps_give_the_answer_of_many_small_ones(form: str, m: float, n: float) -> None:
    """A slide and a 1000 s hold: 10 (slide) and 1 (hold) steps against 2000 and 1000.

    The bound is the one the default option (m = n = 1, closed form) meets on the same
    programme (its 10-step error is 1.1e-8 in the traction); the split integrator was off
    by 1.6e-3 (slide, m = 2, n = 0.5) and 4e-2 (hold, ratio form).
    """
    law = _law(form, m, n)
    initial = InitialConditions(normal_traction=1.0)

    def slide(steps: int) -> History:
        return simulate(law, (Slide(velocity=0.1, distance=1.0, steps=steps),), initial)

    coarse, fine = slide(10), slide(2000)
    assert coarse.traction[-1, 0, 0] == pytest.approx(fine.traction[-1, 0, 0], abs=2e-7)
    start = fine.final_state
    one = simulate(law, (Hold(duration=1000.0, steps=1),), start)
    many = simulate(law, (Hold(duration=1000.0, steps=1000),), start)
    assert one.F[-1, 0] == pytest.approx(many.F[-1, 0], abs=1e-13)
    assert one.R[-1, 0] == pytest.approx(many.R[-1, 0], abs=1e-13)
