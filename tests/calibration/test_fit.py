"""fit_law: recovery of known parameters, the batched Jacobian, the uncertainty, the profile."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from frictionlab.calibration import CHI2_95, FitSpace, fit_law, profile_likelihood
from frictionlab.calibration.fit import Objective, make_space, uncertainty
from frictionlab.errors import ParameterError

from .support import TRUE, make_curve, true_params

NAMES = ["mu_s", "mu_k", "u", "kappa", "xi"]
#: A start away from the truth by 10 % to a factor 3 (rate constants).
START = dict(mu_s=0.55, mu_k=0.25, u=5.0e4, kappa=1000.0, xi=1.0e-2)
#: Noise of the synthetic data: standard deviation of the friction ratio.
NOISE = 0.002


@pytest.fixture(scope="module")
def noisy_fit():
    curve = make_curve(NOISE, seed=1)
    return curve, fit_law(true_params(**START), [curve], NAMES)


def test_zero_noise_recovers_the_parameters_to_solver_tolerance() -> None:
    fit = fit_law(true_params(**START), [make_curve(0.0)], NAMES)
    truth = np.array([TRUE[n] for n in NAMES])
    np.testing.assert_allclose(fit.values, truth, rtol=1e-9)
    assert fit.cost < 1e-20


def test_noisy_recovery_within_the_reported_stderr(noisy_fit) -> None:
    curve, fit = noisy_fit
    truth = np.array([TRUE[n] for n in NAMES])
    z = (fit.values - truth) / fit.stderr
    # Linearised standard errors: each |error| below 4 stderr (a 6e-5 chance per parameter
    # for a correct stderr), and the errors are not all far below 1 stderr either.
    assert np.all(np.abs(z) < 4.0), dict(zip(NAMES, z, strict=True))
    assert np.max(np.abs(z)) > 0.1
    # With the right law the residuals are the noise: s within 5 % of NOISE (n = 3401,
    # the sample standard deviation scatters by 1/sqrt(2n) = 1.2 %).
    assert np.sqrt(fit.residual_variance) == pytest.approx(NOISE, rel=0.05)
    # The stderr scales with the noise: a 1 % error in mu_s costs about NOISE/sqrt(n)
    # per sample; every parameter is determined to better than 10 % here.
    assert np.all(fit.relative_stderr < 0.1)
    assert fit.n_points == curve.n_samples and fit.dof == curve.n_samples - 5


def test_correlation_matrix_is_a_correlation_matrix(noisy_fit) -> None:
    _, fit = noisy_fit
    c = fit.correlation
    np.testing.assert_allclose(c, c.T, atol=1e-12)
    np.testing.assert_allclose(np.diag(c), 1.0)
    assert np.all(np.linalg.eigvalsh(c) > -1e-12)
    cov = fit.covariance
    np.testing.assert_allclose(np.sqrt(np.diag(cov)), fit.stderr, rtol=1e-12)


def test_batched_jacobian_equals_one_run_per_perturbation() -> None:
    curve = make_curve(NOISE, seed=2)
    params = true_params(**START)
    space = make_space(params, NAMES)
    theta = space.to_theta([START[n] for n in NAMES])
    batched = Objective(params, [curve], space, jacobian="batched")
    naive = Objective(params, [curve], space, jacobian="naive")
    jb, jn = batched.jac(theta), naive.jac(theta)
    np.testing.assert_allclose(jb, jn, rtol=1e-9, atol=1e-12 * np.abs(jn).max())
    assert batched.runs == 1 and naive.runs == len(NAMES) + 1


def test_uncertainty_of_a_linear_model_matches_regression_formulas() -> None:
    # Straight line y = a + b t with known design: cov = s^2 (X^T X)^-1 typed here.
    t = np.linspace(0.0, 1.0, 11)
    X = np.column_stack([np.ones_like(t), t])
    r = np.array([0.1, -0.2, 0.05, 0.0, 0.1, -0.1, 0.2, -0.05, 0.0, 0.1, -0.2])
    cost = 0.5 * float(r @ r)
    s2 = float(r @ r) / (11 - 2)
    sxx = float(np.sum((t - t.mean()) ** 2))
    se_b = np.sqrt(s2 / sxx)
    se_a = np.sqrt(s2 * (1 / 11 + t.mean() ** 2 / sxx))
    lin = FitSpace(("mu_s", "mu_k"), np.zeros(2), np.full(2, np.inf))
    stderr, _, corr, _ = uncertainty(X, cost, lin, np.array([1.0, 2.0]))
    np.testing.assert_allclose(stderr, [se_a, se_b], rtol=1e-12)
    np.testing.assert_allclose(corr[0, 1], -t.mean() / np.sqrt(np.mean(t**2)), rtol=1e-12)
    # Log parameters: the delta method gives stderr(x) = x stderr(ln x).
    logs = FitSpace(("u", "kappa"), np.zeros(2), np.full(2, np.inf))
    x = np.array([3.0, 0.5])
    stderr_log, _, _, _ = uncertainty(X, cost, logs, x)
    np.testing.assert_allclose(stderr_log, x * np.array([se_a, se_b]), rtol=1e-12)


def test_undetermined_parameter_gets_infinite_stderr() -> None:
    X = np.column_stack([np.ones(5), np.zeros(5)])  # the second parameter changes nothing
    lin = FitSpace(("mu_s", "mu_k"), np.zeros(2), np.full(2, np.inf))
    stderr, _, corr, _ = uncertainty(X, 0.5, lin, np.ones(2))
    assert np.isfinite(stderr[0]) and np.isinf(stderr[1])
    assert np.isnan(corr[0, 1])


def test_profile_of_a_well_identified_parameter_is_the_linearised_interval() -> None:
    curve = make_curve(NOISE, seed=3)
    fit = fit_law(true_params(mu_k=0.25, xi=1e-2), [curve], ["mu_k", "xi"])
    prof = profile_likelihood(fit, [curve], "mu_k", points=9, span=2.5)
    j = fit.names.index("mu_k")
    low, high = prof.interval
    assert low is not None and high is not None
    # Where the model is nearly linear, delta chi^2 = 3.84 at x_hat -+ 1.96 stderr (the
    # grid's linear interpolation of the parabola errs by < 1 % of that here).
    half = np.sqrt(CHI2_95) * fit.stderr[j]
    assert low == pytest.approx(fit.values[j] - half, rel=0, abs=0.1 * half)
    assert high == pytest.approx(fit.values[j] + half, rel=0, abs=0.1 * half)


@pytest.mark.parametrize(
    ("names", "bounds", "field"),
    [
        (["mu_s", "mu_s"], None, "fit.parameters"),
        (["F_s"], None, "fit.parameters"),
        (["rotation"], None, "fit.parameters"),
        (["mu_s"], {"mu_s": (0.6, 0.9)}, "law.mu_s"),
        (["mu_s"], {"mu_s": (0.9, 0.6)}, "fit.bounds.mu_s"),
        (["u"], {"u": (-1.0, 1e6)}, "fit.bounds.u"),
        (["mu_s"], {"xi": (0.0, 1.0)}, "fit.bounds.xi"),
    ],
)
def test_bad_fit_specification_names_the_field(names, bounds, field) -> None:
    with pytest.raises(ParameterError) as info:
        make_space(true_params(), names, bounds)
    assert info.value.field == field


def test_weight_two_equals_the_curve_given_twice() -> None:
    curve = make_curve(NOISE, seed=5)
    heavy = dataclasses.replace(curve, weight=2.0)
    start = true_params(mu_k=0.25, xi=1e-2)
    twice = fit_law(start, [curve, curve], ["mu_k", "xi"])
    weighted = fit_law(start, [heavy], ["mu_k", "xi"])
    # Same cost function: equal optima up to the optimiser's stopping tolerance (xtol 1e-10).
    np.testing.assert_allclose(weighted.values, twice.values, rtol=1e-8)
    assert weighted.cost == pytest.approx(twice.cost, rel=1e-8)


def test_jacobian_falls_back_to_single_runs_and_flips_a_failing_step(monkeypatch) -> None:
    import frictionlab.calibration.fit as fit_module
    from frictionlab.errors import ConvergenceError

    curve = make_curve(NOISE, seed=2)
    params = true_params(**START)
    space = make_space(params, NAMES)
    theta = space.to_theta([START[n] for n in NAMES])
    reference = Objective(params, [curve], space, jacobian="naive").jac(theta)
    real = fit_module.evaluate_columns
    kappa_start = START["kappa"]

    def failing(base, names, columns, curve, **kw):  # type: ignore[no-untyped-def]
        # The batched run fails, and so does any law with kappa above its start.
        if columns.shape[1] > 1 or columns[3, 0] > kappa_start:
            raise ConvergenceError("made to fail", mask=np.ones(1, dtype=bool))
        return real(base, names, columns, curve, **kw)

    monkeypatch.setattr(fit_module, "evaluate_columns", failing)
    jac = Objective(params, [curve], space).jac(theta)
    others = [0, 1, 2, 4]
    np.testing.assert_allclose(jac[:, others], reference[:, others], rtol=1e-9, atol=1e-14)
    # kappa's column is the backward difference: equal to the forward one to O(h).
    k = reference[:, 3]
    assert np.max(np.abs(jac[:, 3] - k)) < 1e-4 * np.max(np.abs(k))
