"""Healing: the law's recovery form beside the per-decade rate, and what mu_s is."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.driver import Hold, InitialConditions, Slide, simulate
from frictionlab.driver.healing import Healing, healing_analysis, healing_rate, recovery_fit
from frictionlab.subloading import SubloadingParams

HOLDS = np.array([1.0, 10.0, 100.0, 1000.0, 10000.0])


def _healing(t: np.ndarray, peaks: np.ndarray) -> Healing:
    from frictionlab.driver.healing import HealingRecord, _rms

    records = tuple(HealingRecord(1, 2 * i + 2, float(h), 0.3, float(p), 0.0)
                    for i, (h, p) in enumerate(zip(t, peaks, strict=True)))  # fmt: skip
    slope, intercept = healing_rate(t, peaks - 0.3)
    assert slope is not None and intercept is not None
    rate_rms = _rms(peaks - 0.3 - (slope * np.log10(t) + intercept), 2)
    return Healing(records, slope, intercept, rate_rms, recovery_fit(t, peaks))


def test_recovery_form_is_recovered_from_exact_points_and_preferred():
    peaks = 0.48 - (0.48 - 0.31) * np.exp(-HOLDS / 300.0)
    rec = recovery_fit(HOLDS, peaks)
    assert rec is not None
    assert (rec.A, rec.mu_0, rec.tau) == pytest.approx((0.48, 0.31, 300.0), rel=1e-8)
    assert _healing(HOLDS, peaks).comparison().startswith("the law's recovery form")


def test_log_linear_points_prefer_the_rate_per_decade():
    peaks = 0.31 + 0.012 * np.log10(HOLDS)
    assert _healing(HOLDS, peaks).comparison().startswith("a rate per decade")


def test_two_hold_times_give_no_recovery_form():
    assert recovery_fit(HOLDS[:2], np.array([0.31, 0.33])) is None


def test_slide_hold_slide_recovers_with_the_law_time_constant_and_stays_below_mu_s():
    """m = n = 1: F recovers as mu_s - (mu_s - mu_0) exp(-xi t_h / mu_s), tau = mu_s/xi.
    The restart peak follows it closely when the re-loading slip is short (large alpha_t
    and u, small kappa)."""
    mu_s, xi = 0.5, 1e-3
    params = SubloadingParams(surface="coulomb", alpha_n=1e13, alpha_t=1e13, mu_s=mu_s,
                              mu_k=0.3, u=1e7, kappa=100.0, xi=xi)  # fmt: skip
    program = (Slide(velocity=1e-4, distance=1e-3, steps=200), Hold(duration=HOLDS, steps=1),
               Slide(velocity=1e-4, distance=1e-5, steps=20))  # fmt: skip
    h = simulate(params, program, InitialConditions(normal_traction=1e6))
    healing = healing_analysis(h)
    assert healing is not None and healing.recovery is not None
    assert healing.recovery.tau == pytest.approx(mu_s / xi, rel=0.02)
    assert healing.comparison().startswith("the law's recovery form")
    note = healing.static_note(mu_s)
    top = max(r.restart_peak for r in healing.records)
    assert top < mu_s and f"{top:.6g}" in note and "mu_s = 0.5 is the law's static" in note


def test_healing_figure_draws_the_recovery_form_through_exact_points():
    from frictionlab.plotting.law import plot_healing

    peaks = 0.48 - (0.48 - 0.31) * np.exp(-HOLDS / 300.0)
    rec = recovery_fit(HOLDS, peaks)
    assert rec is not None
    ax = plot_healing(HOLDS, peaks - 0.3, np.arange(1, 6), None, None,
                      recovery=(rec.A, rec.mu_0, rec.tau, 0.3))  # fmt: skip
    (line,) = [ln for ln in ax.get_lines() if "recovery form" in str(ln.get_label())]
    t, d = np.asarray(line.get_xdata()), np.asarray(line.get_ydata())
    np.testing.assert_allclose(np.interp(np.log(HOLDS), np.log(t), d), peaks - 0.3, atol=2e-3)
