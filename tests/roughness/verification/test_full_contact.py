"""Full contact as a direct area average (spec section 2.6) and the ``drop`` option.

* The average equals the lattice's time-sampled full contact on analytic surfaces to
  1e-12 when the lattice's shifts are whole stations (a shift then permutes surface 2's
  stations), for return and ergodic paths, 1-D and 2-D, both engines.
* ``on_invalid="drop"``: the kept-contact average and the dropped fraction against an
  independent NumPy evaluation built on the closed-form multiplier (``h_global``) and the
  validity bound (``max_mu0``), not on the kernels.
* Snapped time samples: the count divides the stations along the path, and the result
  moves only by the quadrature error of the time average.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.errors import ValidityError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.closed_forms import h_global, max_mu0, wedge_friction
from frictionlab.roughness.lattice import friction_polar, snap_count

BETAS_2D = [0.0, 30.0, 45.0, 90.0, 135.0, 200.0]


@pytest.mark.parametrize("engine", ["numba", "numpy"])
def test_average_equals_lattice_full_contact_2d(engine) -> None:
    lower = gen.sinusoid(0.15, [1.0, 1.5])  # lambda_x : lambda_y = 2 : 3, cell 3 x 3 wavelengths
    upper = gen.sinusoid(0.1, [1.0, 1.0])
    common = dict(load="full", stations=(48, 48), time_samples=16, engine=engine)
    avg = friction_polar(lower, upper, 0.3, BETAS_2D, full_contact="average", **common)
    lat = friction_polar(
        lower, upper, 0.3, BETAS_2D, full_contact="lattice", snap_time_samples=False, **common
    )
    assert set(lat.travel_mode) <= {"return", "ergodic"}
    np.testing.assert_allclose(avg.mu_x, lat.mu_x, rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(avg.mu_y, lat.mu_y, rtol=1e-12, atol=1e-13)
    assert avg.travel_mode == ("average",) * len(BETAS_2D)
    assert np.all(avg.time_samples == 0)
    assert np.all(lat.time_samples > 0)


def test_average_equals_lattice_full_contact_1d_and_wedge_closed_form() -> None:
    lower = gen.wedge((30.0, 15.0), 1.0)
    upper = gen.flat()
    betas = [0.0, 20.0, 60.0, 170.0]
    avg = friction_polar(lower, upper, 0.3, betas, stations=2000)
    lat = friction_polar(
        lower, upper, 0.3, betas, stations=2000, time_samples=40, full_contact="lattice"
    )
    np.testing.assert_allclose(avg.mu_x, lat.mu_x, rtol=1e-12)
    np.testing.assert_allclose(avg.mu_y, lat.mu_y, rtol=1e-12, atol=1e-13)
    # Eqs 15-16: face lengths are resolved to one station of 2000 (weights to 5e-4).
    mu_x, mu_y = wedge_friction(0.3, [30.0, 15.0, 0.0, 0.0], np.array(betas))
    np.testing.assert_allclose(avg.mu_x, mu_x, rtol=0, atol=2e-5)
    np.testing.assert_allclose(avg.mu_y, mu_y, rtol=0, atol=2e-5)


def _steep_sine_reference(mu0: float, slope: float, n: int, beta_deg: float):
    """Independent drop average for flat upper on A sin(2 pi x) with slope amplitude s."""
    x = (np.arange(n) + 0.5) / n
    g = slope * np.cos(2.0 * np.pi * x)
    beta = math.radians(beta_deg)
    phi = np.arctan(np.abs(g))
    # Local direction: beta' = beta - alpha with alpha = 0 (g > 0) or pi (g < 0).
    local = np.where(g >= 0.0, beta, beta - math.pi)
    valid = mu0 < max_mu0(phi, local)
    hx, hy = h_global(mu0, g[valid], 0.0, beta)
    flat_hx, flat_hy = mu0 * math.cos(beta), mu0 * math.sin(beta)  # the flat surface: n valid
    kept = valid.sum() + n
    return (
        (hx.sum() + n * flat_hx) / kept,
        (hy.sum() + n * flat_hy) / kept,
        (n - valid.sum()) / (2.0 * n),
    )


@pytest.mark.parametrize("engine", ["numba", "numpy"])
def test_drop_against_independent_average(engine) -> None:
    mu0, slope, n = 0.6, 2.5, 4000  # cot(phi) < 0.6 where |slope| > 1/0.6
    lower = gen.sinusoid(slope / (2.0 * math.pi), 1.0)
    betas = [0.0, 40.0, 180.0]
    with pytest.raises(ValidityError, match="phi"):
        friction_polar(lower, gen.flat(), mu0, betas, stations=n, engine=engine)
    polar = friction_polar(
        lower, gen.flat(), mu0, betas, stations=n, engine=engine, on_invalid="drop"
    )
    # rel 1e-10: contacts next to the bound have H ~ 1/den, which amplifies rounding.
    for i, beta in enumerate(betas):
        mx, my, frac = _steep_sine_reference(mu0, slope, n, beta)
        assert polar.mu_x[i] == pytest.approx(mx, rel=1e-10)
        assert polar.mu_y[i] == pytest.approx(my, rel=1e-10, abs=1e-15)
        assert polar.invalid_fraction[i] == pytest.approx(frac, rel=0, abs=1e-15)
    assert 0.0 < polar.invalid_fraction[0] < 0.5
    assert "invalid_fraction" in polar.columns()


def test_drop_partial_contact_engines_agree_and_equal_raise_when_valid() -> None:
    lower = gen.sinusoid(2.5 / (2.0 * math.pi), 1.0)
    upper = gen.sinusoid(0.02, 0.5)
    opts = dict(load=0.05, stations=400, time_samples=20, on_invalid="drop")
    a = friction_polar(lower, upper, 0.6, [0.0, 30.0], engine="numba", **opts)
    b = friction_polar(lower, upper, 0.6, [0.0, 30.0], engine="numpy", **opts)
    np.testing.assert_allclose(a.mu_x, b.mu_x, rtol=1e-10)
    np.testing.assert_allclose(a.invalid_fraction, b.invalid_fraction, rtol=1e-12)
    assert np.all(a.invalid_fraction > 0.0)
    gentle = gen.sinusoid(0.5 / (2.0 * math.pi), 1.0)
    c = friction_polar(gentle, upper, 0.6, [0.0, 30.0], **opts)
    d = friction_polar(gentle, upper, 0.6, [0.0, 30.0], **{**opts, "on_invalid": "error"})
    np.testing.assert_array_equal(c.mu_x, d.mu_x)
    assert np.all(c.invalid_fraction == 0.0)


@pytest.mark.parametrize(
    ("count", "stations", "expected"), [(400, 1024, 512), (256, 1024, 256), (16, 40, 20), (7, 7, 7)]
)
def test_snap_count_is_the_nearest_divisor(count, stations, expected) -> None:
    assert snap_count(count, stations) == expected
    assert stations % snap_count(count, stations) == 0


def test_snapped_samples_change_mu_by_quadrature_only() -> None:
    lower = gen.sinusoid(0.05, 1.0)
    upper = gen.sinusoid(0.03, 0.5)
    kw = dict(load=0.05, stations=2000)
    snapped = friction_polar(lower, upper, 0.3, [30.0], time_samples=300, **kw)
    exact = friction_polar(
        lower, upper, 0.3, [30.0], time_samples=300, snap_time_samples=False, **kw
    )
    fine = friction_polar(lower, upper, 0.3, [30.0], time_samples=2000, **kw)
    assert int(snapped.time_samples[0]) == 250 and int(exact.time_samples[0]) == 300
    assert abs(snapped.mu[0] - fine.mu[0]) < 1e-6
    assert abs(exact.mu[0] - fine.mu[0]) < 1e-6


def test_flat_counter_face_is_travel_invariant() -> None:
    lower = gen.self_affine(0.8, [1e-3, 1e-3], [64, 64], rng=np.random.default_rng(3),
                            rms_slope=0.2)  # fmt: skip
    kw = dict(load=1e-8, time_samples=60, shift_invariance=False)  # the path itself
    snapped = friction_polar(lower, gen.flat(), 0.3, [0.0, 45.0], **kw)
    exact = friction_polar(lower, gen.flat(), 0.3, [0.0, 45.0], snap_time_samples=False, **kw)
    assert list(snapped.time_samples) == [64, 64]
    np.testing.assert_allclose(snapped.mu, exact.mu, rtol=1e-12)


@pytest.mark.parametrize("pair", ["rough/flat", "flat/rough", "rough/rough"])
def test_flat_counter_face_shortcut_matches_the_numpy_twin(pair) -> None:
    rough = gen.sinusoid(0.3, [1.0, 2.0])
    lower, upper = {
        "rough/flat": (rough, gen.flat()),
        "flat/rough": (gen.flat(), rough),
        "rough/rough": (rough, gen.sinusoid(0.2, [1.0, 1.0])),
    }[pair]
    opts = dict(stations=(32, 64), on_invalid="drop")
    a = friction_polar(lower, upper, 0.9, BETAS_2D, engine="numba", **opts)
    b = friction_polar(lower, upper, 0.9, BETAS_2D, engine="numpy", **opts)
    np.testing.assert_allclose(a.mu_x, b.mu_x, rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(a.mu_y, b.mu_y, rtol=1e-12, atol=1e-13)
    np.testing.assert_array_equal(a.invalid_fraction, b.invalid_fraction)
    assert np.any(a.invalid_fraction > 0)  # slopes up to 1.9 with mu0 = 0.9
    if pair == "flat/rough":
        with pytest.raises(ValidityError, match="upper surface"):
            friction_polar(lower, upper, 0.9, [0.0], stations=(32, 64))
