"""Checkable properties of spec section 6 on the discrete lattice.

Expected values come from closed forms, an independent quadrature of the multipliers
(scipy.integrate.quad of the local-frame Eqs 2-3), limits and symmetries. Resolutions are
stated per test.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from frictionlab.errors import ParameterError, ValidityError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.closed_forms import (
    h_local,
    wedge_friction,
    wedge_on_wedge_0deg,
    wedge_on_wedge_90deg,
)
from frictionlab.roughness.lattice import friction_polar

TWO_PI = 2.0 * math.pi


def sine_area_average(mu0: float, slope_amplitude: float, beta_deg: float) -> tuple[float, float]:
    """<H> over one period of z = A sin(x) with slope amplitude s (1-D, Eqs 2-3)."""
    beta = math.radians(beta_deg)

    def h(x: float, k: int) -> float:
        return float(h_local(mu0, math.atan(slope_amplitude * math.cos(x)), beta)[k])

    return (
        quad(h, 0.0, TWO_PI, args=(0,), epsabs=1e-13, limit=200)[0] / TWO_PI,
        quad(h, 0.0, TWO_PI, args=(1,), epsabs=1e-13, limit=200)[0] / TWO_PI,
    )


class TestLimits:
    def test_flat_limit(self) -> None:
        betas = [0.0, 17.0, 45.0, 90.0, 200.0]
        polar = friction_polar(gen.flat(), gen.flat(), 0.3, betas, load=0.1)
        b = np.radians(betas)
        np.testing.assert_allclose(polar.mu_x, 0.3 * np.cos(b), rtol=1e-14, atol=1e-15)
        np.testing.assert_allclose(polar.mu_y, 0.3 * np.sin(b), rtol=1e-14, atol=1e-15)
        np.testing.assert_allclose(polar.mu, 0.3, rtol=1e-13)
        plane = gen.from_array(np.zeros((8, 8)), (1.0, 1.0))
        polar = friction_polar(plane, plane, 0.3, betas, load=0.5, time_samples=8)
        np.testing.assert_allclose(polar.mu, 0.3, rtol=1e-13)

    def test_axis_components_of_asymmetric_wedges(self) -> None:
        # Property 4 on the lattice: mu_y(0) = 0 exactly, mu_x(90) = 0 to the lattice error.
        for angles in ((30, 15, 0, 0), (30, 15, 30, 15)):
            lower = gen.wedge(angles[:2], 1.0)
            upper = gen.flat() if angles[2] == 0 else gen.wedge(angles[2:], 1.0)
            polar = friction_polar(
                lower, upper, 0.3, [0.0, 90.0], load=0.02 * lower.height, stations=16000,
                time_samples=100,
            )  # fmt: skip
            assert abs(float(polar.mu_y[0])) < 1e-15
            assert abs(float(polar.mu_x[1])) < 1e-4
            assert abs(float(polar.mu_x[0])) > 0.3

    def test_mirror_symmetry_in_1d(self) -> None:
        lower = gen.wedge((30.0, 15.0), 1.0)
        upper = gen.sinusoid(0.05, 0.5)
        betas = np.array([10.0, 35.0, 70.0])
        plus = friction_polar(lower, upper, 0.3, betas, load=0.01, stations=2000, time_samples=100)
        minus = friction_polar(
            lower, upper, 0.3, -betas, load=0.01, stations=2000, time_samples=100
        )
        np.testing.assert_allclose(minus.mu_x, plus.mu_x, rtol=1e-12)
        np.testing.assert_allclose(minus.mu_y, -plus.mu_y, rtol=1e-12)

    def test_direction_reversal_is_face_swap(self) -> None:
        # Property 9 / scenario RV on the lattice (16000 stations, full contact).
        kw = {"load": "full", "stations": 16000, "time_samples": 100}
        back = friction_polar(gen.wedge((30.0, 15.0), 1.0), gen.flat(), 0.3, [180.0], **kw)
        swapped = friction_polar(gen.wedge((15.0, 30.0), 1.0), gen.flat(), 0.3, [0.0], **kw)
        forward = friction_polar(gen.wedge((30.0, 15.0), 1.0), gen.flat(), 0.3, [0.0], **kw)
        assert float(back.mu[0]) == pytest.approx(float(swapped.mu[0]), abs=2e-4)
        assert float(forward.mu[0]) > float(back.mu[0]) + 1e-3  # ratchet: C > D


class TestLoadIndependence:
    def test_wedges_any_load_and_stiffness(self) -> None:
        # Property 5: 64000 stations, 400 samples; loads from 0.5 % to 5x the height.
        lower = gen.wedge((30.0, 15.0), 1.0)
        upper = gen.wedge((30.0, 15.0), 1.0)
        h = lower.height
        mu_x, mu_y = wedge_friction(0.3, (30, 15, 30, 15), 30.0)
        results = []
        for load in (0.005 * h, 0.05 * h, 0.5 * h, 5 * h):
            polar = friction_polar(
                lower, upper, 0.3, [30.0], load=load, stations=64000, time_samples=400
            )
            results.append((float(polar.mu_x[0]), float(polar.mu_y[0])))
            assert results[-1] == pytest.approx((float(mu_x), float(mu_y)), abs=1e-4)
        assert polar.contact_fraction_min[0] == 1.0  # the largest load is full contact
        stiff = friction_polar(
            lower, upper, 0.3, [30.0], load=0.05 * h * 1e4, k_c=1e4, stations=64000,
            time_samples=400,
        )  # fmt: skip
        assert float(stiff.mu_x[0]) == pytest.approx(results[1][0], rel=1e-12)

    @pytest.mark.parametrize("beta", [0.0, 30.0, 60.0])
    def test_full_contact_sinusoids_equal_the_area_average(self, beta) -> None:
        # Property 6: sine/sine (A = 1, lambda = 2 pi, 2000 stations): any load above the
        # full-contact threshold 2 k A gives the area average of H, half from each family.
        s = gen.sinusoid(1.0, TWO_PI)
        hx, hy = sine_area_average(0.3, 1.0, beta)
        full = friction_polar(s, s, 0.3, [beta], load="full", stations=2000, time_samples=100)
        assert float(full.mu_x[0]) == pytest.approx(hx, rel=1e-10)
        assert float(full.mu_y[0]) == pytest.approx(hy, rel=1e-10, abs=1e-14)
        for load in (2.5, 10.0):
            polar = friction_polar(s, s, 0.3, [beta], load=load, stations=2000, time_samples=100)
            assert polar.contact_fraction_min[0] == 1.0
            assert float(polar.mu_x[0]) == pytest.approx(hx, rel=1e-9)
            assert float(polar.mu_y[0]) == pytest.approx(hy, rel=1e-9, abs=1e-12)

    def test_partial_contact_depends_on_load(self) -> None:
        # Scenario LD: below the thresholds (sine/sine 2kA, flat/sine kA) mu changes.
        s = gen.sinusoid(1.0, TWO_PI)
        kw = {"stations": 2000, "time_samples": 200}
        full = float(friction_polar(s, s, 0.3, [0.0], load="full", **kw).mu[0])
        for load in (0.5, 0.1):
            polar = friction_polar(s, s, 0.3, [0.0], load=load, **kw)
            assert polar.contact_fraction_min[0] < 1.0
            assert abs(float(polar.mu[0]) - full) > 1e-3
        flat_full = float(friction_polar(gen.flat(), s, 0.3, [0.0], load="full", **kw).mu[0])
        above = friction_polar(gen.flat(), s, 0.3, [0.0], load=1.05, **kw)
        assert above.contact_fraction_min[0] == 1.0
        assert float(above.mu[0]) == pytest.approx(flat_full, rel=1e-10)
        below = friction_polar(gen.flat(), s, 0.3, [0.0], load=0.5, **kw)
        assert abs(float(below.mu[0]) - flat_full) > 1e-3

    def test_2d_full_contact_at_beta_0(self) -> None:
        s = gen.sinusoid(1.0, [TWO_PI, TWO_PI])
        kw = {"stations": 32, "time_samples": 32}
        full = friction_polar(s, s, 0.3, [0.0], load="full", **kw)
        heavy = friction_polar(s, s, 0.3, [0.0], load=5.0, **kw)
        assert heavy.contact_fraction_min[0] == 1.0
        assert float(heavy.mu[0]) == pytest.approx(float(full.mu[0]), rel=1e-10)


class TestTwoDimensional:
    def test_symmetric_surface_symmetries(self) -> None:
        # Property 12 (full contact, 48 x 48 stations, 64 samples).
        s = gen.sinusoid(1.0, [TWO_PI, TWO_PI])
        betas = np.array([0.0, 10.0, 25.0, 45.0, 65.0, 80.0, 90.0])
        polar = friction_polar(s, s, 0.3, betas, stations=48, time_samples=64)
        np.testing.assert_allclose(polar.mu, polar.mu[::-1], rtol=1e-12)
        assert float(polar.mu_x[0]) == pytest.approx(float(polar.mu_y[-1]), rel=1e-12)
        assert float(polar.mu_y[0]) == pytest.approx(0.0, abs=1e-14)
        # at 45 deg the resisting force is parallel to v: both definitions coincide
        assert float(polar.mu_projection[3]) == pytest.approx(
            float(polar.mu_magnitude[3]), rel=1e-12
        )

    def test_swapping_wavelengths_maps_beta_to_90_minus_beta(self) -> None:
        a = gen.sinusoid(1.0, [TWO_PI, 1.5 * TWO_PI])
        b = gen.sinusoid(1.0, [1.5 * TWO_PI, TWO_PI])
        betas = np.array([0.0, 20.0, 45.0, 90.0])
        pa = friction_polar(a, a, 0.3, betas, stations=32, time_samples=36)
        pb = friction_polar(b, b, 0.3, 90.0 - betas, stations=32, time_samples=36)
        np.testing.assert_allclose(pa.mu, pb.mu, rtol=1e-12)
        assert abs(float(pa.mu[0]) - float(pa.mu[-1])) > 1e-3  # anisotropic

    def test_initial_phase_matters_in_partial_contact_at_resonance(self) -> None:
        # Scenario PH: sin x sin y, beta = 45 deg, 40 x 40 stations, 100 samples.
        s = gen.sinusoid(1.0, [TWO_PI, TWO_PI])
        kw = {"stations": 40, "time_samples": 100}

        def phase_gap(load: float) -> float:
            a = friction_polar(s, s, 0.3, [45.0], load=load, **kw)
            b = friction_polar(s, s, 0.3, [45.0], load=load, phase=(math.pi / 2, 0.0), **kw)
            return abs(float(a.mu[0]) - float(b.mu[0])) / 0.3

        light, heavy = phase_gap(0.1), phase_gap(5.0)
        assert light > 0.2
        assert heavy < light / 10


class TestValidityAndOptions:
    def test_validity_error_names_the_contact(self) -> None:
        # phi = 60 deg: mu0 < cot(60) = 0.577 at beta' = 0; at 60 deg the bound is
        # cot(phi) sqrt(cos^2 phi / cos^2 beta + sin^2 phi) = 0.7638.
        w = gen.wedge(60.0, 1.0)
        with pytest.raises(ValidityError, match=r"phi = 60 deg.*mu0 < 0\.57735"):
            friction_polar(w, gen.flat(), 0.6, [0.0], stations=200, time_samples=10)
        polar = friction_polar(
            w, gen.flat(), 0.7, [0.0, 60.0, 90.0], stations=200, time_samples=10, on_invalid="mask"
        )
        assert list(polar.valid) == [False, True, True]
        assert not polar.success and "1 of 3" in polar.message
        assert math.isnan(float(polar.mu[0])) and math.isfinite(float(polar.mu[1]))
        with pytest.raises(ValidityError, match=r"mu0 < 0\.7637"):
            friction_polar(w, gen.flat(), 0.77, [60.0], stations=200, time_samples=10)
        ok = friction_polar(w, gen.flat(), 0.57, [0.0], stations=200, time_samples=10)
        assert ok.success and math.isfinite(float(ok.mu[0])) and float(ok.mu[0]) > 1.0

    def test_invalid_contact_out_of_contact_is_not_reported(self) -> None:
        # Under a light load only the apex region touches; but every wedge face carries
        # load, so the violation is still found (spec: no clipping, no silent skipping).
        w = gen.wedge((60.0, 20.0), 1.0)
        with pytest.raises(ValidityError, match="lower surface"):
            friction_polar(w, gen.flat(), 0.6, [0.0], load=1e-3, stations=400, time_samples=10)

    def test_mu_definitions(self) -> None:
        w = gen.wedge((40.0, 10.0), 1.0)
        proj = friction_polar(w, w, 0.3, [0.0, 45.0], mu_definition="projection")
        mag = friction_polar(w, w, 0.3, [0.0, 45.0])
        assert float(proj.mu[0]) == pytest.approx(float(mag.mu[0]), rel=1e-14)
        assert float(mag.mu[1]) - float(proj.mu[1]) > 1e-3  # lateral component at 45 deg
        assert float(mag.mu[1]) == pytest.approx(float(mag.mu_magnitude[1]), rel=1e-15)
        b = math.radians(45.0)
        expected = float(mag.mu_x[1]) * math.cos(b) + float(mag.mu_y[1]) * math.sin(b)
        assert float(proj.mu[1]) == pytest.approx(expected, rel=1e-14)

    @pytest.mark.parametrize("slope", [0.5, 1.0, 1.5])
    def test_jensen_sinusoid_above_equivalent_wedge(self, slope) -> None:
        # Property 11 / scenario JN: tan(phi) = 2 s / pi (same mean |slope|).
        s = gen.sinusoid(slope, TWO_PI)
        polar = friction_polar(s, s, 0.3, [0.0, 90.0], stations=2000, time_samples=50)
        phi = math.degrees(math.atan(2 * slope / math.pi))
        assert float(polar.mu[0]) > float(wedge_on_wedge_0deg(0.3, phi))
        assert float(polar.mu[1]) > float(wedge_on_wedge_90deg(0.3, phi))

    def test_tensile_springs(self) -> None:
        # With k_t = 0 the apparent coefficient is mu; with tensile springs in partial
        # contact the load is smaller than the compressive force: mu_a > mu (Eq 22).
        s = gen.sinusoid(1.0, TWO_PI)
        kw = {"stations": 1000, "time_samples": 50}
        plain = friction_polar(s, s, 0.3, [0.0], load=0.5, **kw)
        np.testing.assert_allclose(plain.mu_apparent, plain.mu_magnitude, rtol=1e-12)
        sticky = friction_polar(s, s, 0.3, [0.0], load=0.5, k_t=0.5, **kw)
        assert sticky.tensile_fraction_max[0] > 0.0
        assert float(sticky.mu_apparent[0]) > float(sticky.mu_magnitude[0]) * 1.01
        # Identical in-phase surfaces at 90 deg: constant gap, every spring stretched at
        # L < 0: no friction (R = 0), mu of the compressed springs undefined, Eq 22 gives 0.
        pulled = friction_polar(s, s, 0.3, [90.0], load=-0.1, k_t=0.5, **kw)
        assert not pulled.in_contact[0] and pulled.tensile_fraction_mean[0] == 1.0
        assert pulled.tangential_force[0] == 0.0 and math.isnan(float(pulled.mu[0]))
        assert pulled.mu_apparent is not None and float(pulled.mu_apparent[0]) == 0.0
        # L = 0: Eq 22 is singular, mu_apparent is None; the tangential force is defined.
        zero = friction_polar(s, s, 0.3, [0.0], load=0.0, k_t=0.5, **kw)
        assert zero.mu_apparent is None and zero.tangential_force[0] > 0.0
        with pytest.raises(ParameterError, match="load"):  # no tension without k_t
            friction_polar(s, s, 0.3, [0.0], load=0.0, **kw)
