"""Calibration never crashes on what the data cannot say; starts, weights, offset, bands."""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

from frictionlab.calibration import Curve, fit_law, profile_likelihood
from frictionlab.calibration.fit import _starting_points, make_space
from frictionlab.calibration.model import LOG_BOUNDS
from frictionlab.cli import main
from frictionlab.driver import InitialConditions, Slide, simulate

from .support import FN, PROGRAM, config, make_curve, true_params, write_config

FAST = 1.0  # m/s: the slide lasts 0.6 ms, in which recovery at xi ~ 1e-2 1/s does nothing


def _fast_slide_csv(path: Path) -> Path:
    """61 samples of a 0.6 mm slide at 1 m/s: xi leaves no trace in them."""
    program = (Slide(velocity=FAST, distance=6e-4, max_step=1e-5),)
    h = simulate(true_params(), program, InitialConditions(normal_traction=FN))
    t = np.linspace(0.0, 6e-4 / FAST, 61)
    noise = 0.002 * np.random.default_rng(1).standard_normal(t.size)
    r = np.abs(np.interp(t, h.time[:, 0], h.friction_ratio[:, 0]) + noise)
    rows = "".join(f"{a!r},{b!r}\n" for a, b in zip(t.tolist(), r.tolist(), strict=True))
    path.write_text("time,friction_ratio\n" + rows)
    return path


@pytest.mark.slow
def test_unidentifiable_xi_exits_0_and_names_xi_not_identified(tmp_path: Path, capsys):
    """Before: the profile of xi overflowed to 'xi = nan is invalid', exit 2, nothing written."""
    _fast_slide_csv(tmp_path / "first.csv")
    cfg = config("first.csv", ["mu_s", "mu_k", "xi"], dict(mu_s=0.45, mu_k=0.33, xi=1.0))
    del cfg["data"][0]["columns"], cfg["data"][0]["units"]
    cfg["data"][0]["program"] = [{"kind": "slide", "velocity": FAST, "distance": 6e-4,
                                  "max_step": 1e-5}]  # fmt: skip
    path = write_config(tmp_path / "cal.toml", cfg)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no overflow on the way
        code = main(["calibrate", str(path), "--out", str(tmp_path / "out")])
    out = capsys.readouterr().out
    assert code == 0
    assert "xi is not identified" in out, out
    fit = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert "xi" in fit["not_identified"]
    assert "mu_s" not in fit["not_identified"]
    lo, hi = LOG_BOUNDS["xi"]
    assert lo <= fit["parameters"]["xi"]["value"] <= hi


def test_open_ends_of_rate_parameters_take_their_physical_range():
    space = make_space(true_params(), ["mu_k", "xi", "alpha_t"], {"mu_k": (0.0, 1.0)})
    assert space.lower[1:].tolist() == [LOG_BOUNDS["xi"][0], LOG_BOUNDS["alpha_t"][0]]
    assert space.upper[1:].tolist() == [LOG_BOUNDS["xi"][1], LOG_BOUNDS["alpha_t"][1]]
    lo, hi = space.theta_bounds()
    assert np.all(np.isfinite(lo[1:])) and np.all(np.isfinite(hi[1:]))


def test_quasi_random_starts_lie_inside_the_bounds_and_repeat_with_the_seed():
    space = make_space(true_params(), ["mu_s", "kappa", "xi"], {"mu_s": (0.3, 0.9)})
    x0 = np.array([0.5, 3000.0, 5e-3])
    a = _starting_points(space, x0, 9, seed=3)
    b = _starting_points(space, x0, 9, seed=3)
    lo, hi = space.theta_bounds()
    assert len(a) == 9 and np.array_equal(a[0], space.to_theta(x0))
    assert all(np.array_equal(p, q) for p, q in zip(a, b, strict=True))
    assert all(np.all((lo < p) & (p < hi)) for p in a)
    # quasi-random: the 8 extra starts spread over the range of each parameter
    spread = np.ptp(np.array(a[1:]), axis=0) / (hi - lo)
    assert np.all(spread > 0.5)


def test_segment_weights_and_time_offset_place_each_sample():
    """PROGRAM: slide 6 s, hold 30 s, slide 2 s, hold 300 s, slide 2 s."""
    t = np.array([0.0, 5.9, 6.1, 35.9, 36.1, 37.9, 38.1, 337.9, 338.1, 340.0])
    r = np.full(t.size, 0.3)
    curve = Curve("c", t, r, PROGRAM, segment_weights=(1.0, 0.0, 2.0, 0.5, 3.0))
    np.testing.assert_array_equal(curve.segment_of_samples(), [0, 0, 1, 1, 2, 2, 3, 3, 4, 4])
    np.testing.assert_array_equal(curve.sample_weights(), [1, 1, 0, 0, 2, 2, 0.5, 0.5, 3, 3])
    shifted = Curve("c", t - 1.0, r, PROGRAM, time_offset=1.0)
    np.testing.assert_array_equal(shifted.segment_of_samples(), curve.segment_of_samples())
    with pytest.raises(Exception, match="segment_weights"):
        Curve("c", t, r, PROGRAM, segment_weights=(1.0, 2.0))


@pytest.mark.slow
def test_confidence_band_of_mu_k_alone_is_z_times_its_stderr_where_sliding_is_steady():
    """Fitting mu_k alone: d(model)/d(mu_k) = 1 where the ratio has reached mu_k, so the
    95 % confidence half-width there is 1.96 stderr, and the prediction half-width adds the
    residual variance in quadrature."""
    curve = make_curve(0.002, seed=5)
    start = true_params(mu_k=0.32)
    fit = fit_law(start, [curve], ["mu_k"])
    ((conf, pred),) = fit.bands(0.95)
    late = (curve.time > 4.0) & (curve.time < 6.0)  # end of the first slide: steady
    z = 1.959963984540054
    np.testing.assert_allclose(conf[late], z * fit.stderr[0], rtol=0.05)
    s2 = fit.residual_variance
    np.testing.assert_allclose(pred[late], z * np.sqrt((conf[late] / z) ** 2 + s2), rtol=1e-12)
    assert "mu_k" not in fit.not_identified()


@pytest.mark.slow
def test_profile_of_an_undetermined_rate_stays_finite(tmp_path: Path):
    from frictionlab.io.tribometer import read_tribometer

    m = read_tribometer(_fast_slide_csv(tmp_path / "first.csv"))
    program = (Slide(velocity=FAST, distance=6e-4, max_step=1e-5),)
    curve = Curve("first", m.time, m.friction_ratio, program, InitialConditions(FN))
    fit = fit_law(true_params(xi=1.0), [curve], ["mu_k", "xi"], max_nfev=20)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        prof = profile_likelihood(fit, [curve], "xi", points=5)
    assert np.all(np.isfinite(prof.values)) and None in prof.interval
    fit = type(fit)(**{**fit.__dict__, "profiles": {"xi": prof}})
    assert "xi" in fit.not_identified()
