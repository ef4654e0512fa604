"""Surfaces and generators: geometry, gradients, immutability, bad input.

Resolutions: at most 512 samples per axis; every comparison states rtol/atol.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad

from frictionlab.errors import ParameterError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.surface import HeightMap, Profile, SampledHeightMap, SampledProfile


def central_difference(surface, x, y, h):
    """Gradient of the heights by central differences of step h (m)."""
    zx1, _, _ = surface.evaluate(x + h, y)
    zx0, _, _ = surface.evaluate(x - h, y)
    zy1, _, _ = surface.evaluate(x, y + h)
    zy0, _, _ = surface.evaluate(x, y - h)
    return (zx1 - zx0) / (2 * h), (zy1 - zy0) / (2 * h)


class TestWedge:
    def test_geometry_and_eq14_share(self) -> None:
        w = gen.wedge((30.0, 15.0), 2e-3)
        t1, t2 = math.tan(math.radians(30)), math.tan(math.radians(15))
        psi = t2 / t1
        assert w.rise_length / w.wavelength == pytest.approx(psi / (1 + psi), rel=1e-14)
        assert w.height == pytest.approx(w.rise_length * t1, rel=1e-14)
        # continuous at the apex and periodic
        eps = 1e-12
        z_left, _, _ = w.evaluate([w.rise_length - eps])
        z_right, _, _ = w.evaluate([w.rise_length + eps])
        assert z_left[0] == pytest.approx(z_right[0], abs=1e-11)
        x = np.linspace(0.0, 2e-3, 37)
        np.testing.assert_allclose(w.evaluate(x + 2e-3)[0], w.evaluate(x)[0], atol=1e-15)
        _, g, gy = w.evaluate(np.array([0.1e-3, 1.5e-3]))
        np.testing.assert_allclose(g, [t1, -t2], rtol=1e-15)
        assert np.all(gy == 0.0)

    def test_equally_spaced_springs_land_in_eq14_proportion(self) -> None:
        w = gen.wedge((40.0, 12.0), 1.0)
        n = 100_000
        x = (np.arange(n) + 0.5) / n
        _, g, _ = w.evaluate(x)
        share = np.count_nonzero(g > 0) / n
        psi = math.tan(math.radians(12)) / math.tan(math.radians(40))
        assert share == pytest.approx(psi / (1 + psi), abs=1.0 / n)

    def test_symmetric_from_one_angle(self) -> None:
        assert gen.wedge(25.0, 1.0).angles_deg == (25.0, 25.0)
        assert gen.wedge([25.0], 1.0).angles_deg == (25.0, 25.0)

    @pytest.mark.parametrize(
        "angles", [(0.0, 15.0), (90.0, 10.0), (30.0, -1.0), (95.0,), (1, 2, 3)]
    )
    def test_bad_angles(self, angles) -> None:
        with pytest.raises(ParameterError, match="angles_deg"):
            gen.wedge(angles, 1e-3)

    @pytest.mark.parametrize("wavelength", [0.0, -1e-3, float("nan"), float("inf"), "a"])
    def test_bad_wavelength(self, wavelength) -> None:
        with pytest.raises(ParameterError, match="wavelength"):
            gen.wedge(30.0, wavelength)


class TestSmoothWedge:
    def test_mean_face_slopes_equal_the_wedge_angles(self) -> None:
        s = gen.smooth_wedge((30.0, 15.0), 1.0)
        w = gen.wedge((30.0, 15.0), 1.0)
        a = w.rise_length

        def slope(x: float) -> float:
            return float(s.evaluate(np.array([x]))[1][0])

        rise = quad(slope, 0.0, a, epsabs=1e-13)[0] / a
        fall = -quad(slope, a, 1.0, epsabs=1e-13)[0] / (1.0 - a)
        assert rise == pytest.approx(math.tan(math.radians(30)), rel=1e-10)
        assert fall == pytest.approx(math.tan(math.radians(15)), rel=1e-10)
        z, _, _ = s.evaluate(np.array([a]))
        assert z[0] == pytest.approx(w.height, rel=1e-14)
        # C1: the slope vanishes at the apex from both sides
        _, ga, _ = s.evaluate(np.array([w.rise_length - 1e-9, w.rise_length + 1e-9]))
        np.testing.assert_allclose(ga, 0.0, atol=1e-7)
        assert s.max_slope == pytest.approx(0.5 * math.pi * math.tan(math.radians(30)), rel=1e-14)

    def test_symmetric_is_a_sinusoid(self) -> None:
        s = gen.smooth_wedge(20.0, 1.0)
        x = np.linspace(0, 1, 101)
        amp = 0.25 * math.tan(math.radians(20))  # h/2 with h = (lambda/2) tan(phi)
        z, _, _ = s.evaluate(x)
        np.testing.assert_allclose(z, amp * (1 - np.cos(2 * np.pi * x)), atol=1e-15)


class TestSinusoids:
    def test_profile_gradient(self) -> None:
        s = gen.sinusoid(1e-4, 1e-3)
        assert isinstance(s, Profile)
        x = np.linspace(0, 1e-3, 50)
        gx, _ = central_difference(s, x, np.zeros_like(x), 1e-9)
        np.testing.assert_allclose(s.evaluate(x)[1], gx, rtol=1e-5, atol=1e-9)
        assert s.max_slope == pytest.approx(2 * math.pi * 0.1, rel=1e-14)

    def test_product_map_values_gradient_and_max_slope(self) -> None:
        m = gen.sinusoid(2.0, [3.0, 5.0])
        assert isinstance(m, HeightMap)
        rng = np.random.default_rng(0)
        x, y = rng.uniform(0, 15, (2, 40))
        z, gx, gy = m.evaluate(x, y)
        np.testing.assert_allclose(
            z, 2.0 * np.sin(2 * np.pi * x / 3) * np.sin(2 * np.pi * y / 5), rtol=1e-13, atol=1e-14
        )
        fx, fy = central_difference(m, x, y, 1e-6)
        np.testing.assert_allclose(gx, fx, rtol=1e-6, atol=1e-8)
        np.testing.assert_allclose(gy, fy, rtol=1e-6, atol=1e-8)
        xx, yy = np.meshgrid(np.linspace(0, 3, 301), np.linspace(0, 5, 301), indexing="ij")
        _, gx, gy = m.evaluate(xx, yy)
        assert np.max(np.hypot(gx, gy)) == pytest.approx(m.max_slope, rel=1e-9)
        assert m.max_slope == pytest.approx(2 * math.pi * 2.0 / 3.0, rel=1e-14)

    def test_outer_broadcast(self) -> None:
        m = gen.sinusoid(1.0, [1.0, 2.0])
        z, gx, gy = m.evaluate(np.linspace(0, 1, 4)[:, None], np.linspace(0, 2, 3)[None, :])
        assert z.shape == gx.shape == gy.shape == (4, 3)

    def test_bad_input(self) -> None:
        with pytest.raises(ParameterError, match="wavelengths"):
            gen.sinusoid(1.0, [1.0, 2.0, 3.0])
        with pytest.raises(ParameterError, match="amplitude"):
            gen.sinusoid(0.0, 1.0)


class TestSampled:
    def test_exact_on_samples_and_periodic_interpolation(self) -> None:
        rng = np.random.default_rng(1)
        h = rng.standard_normal((8, 6))
        s = gen.from_array(h, (4.0, 3.0))
        assert isinstance(s, SampledHeightMap)
        px, py = s.positions()
        z, _, _ = s.evaluate(px[:, None], py[None, :])
        np.testing.assert_array_equal(z, h)
        # midway between two samples along x: the mean; shifted by a period: the same
        z, _, _ = s.evaluate(np.array([px[2] + 0.25]), np.array([py[1]]))
        assert z[0] == pytest.approx(0.5 * (h[2, 1] + h[3, 1]), rel=1e-14)
        z2, _, _ = s.evaluate(np.array([px[2] + 0.25 + 4.0]), np.array([py[1] - 3.0]))
        assert z2[0] == pytest.approx(z[0], rel=1e-14)
        # wrap-around between the last and the first sample
        z, _, _ = s.evaluate(np.array([0.0]), np.array([py[0]]))
        assert z[0] == pytest.approx(0.5 * (h[-1, 0] + h[0, 0]), rel=1e-14)

    def test_gradients_fd_second_order_spectral_exact(self) -> None:
        n, lam, amp = 64, 2.0, 0.3
        x = (np.arange(n) + 0.5) * lam / n
        heights = amp * np.sin(2 * np.pi * x / lam)
        exact = amp * 2 * np.pi / lam * np.cos(2 * np.pi * x / lam)
        spectral = gen.from_array(heights, lam, gradient="spectral")
        fd = gen.from_array(heights, lam, gradient="fd")
        assert isinstance(spectral, SampledProfile)
        np.testing.assert_allclose(spectral.slopes, exact, atol=1e-12)
        kd = 2 * np.pi / n
        bound = amp * 2 * np.pi / lam * kd**2 / 6 * 1.01  # leading FD error term
        assert np.max(np.abs(fd.slopes - exact)) <= bound
        assert np.max(np.abs(fd.slopes - exact)) > bound / 2  # it is the FD scheme

    def test_immutability_and_no_aliasing(self) -> None:
        h = np.linspace(0.0, 1.0, 16).reshape(4, 4)
        s = gen.from_array(h, (1.0, 1.0))
        h[0, 0] = 99.0
        assert s.heights[0, 0] == 0.0
        with pytest.raises(ValueError):
            s.heights[0, 0] = 1.0
        with pytest.raises(dataclasses.FrozenInstanceError):
            s.gradient = "spectral"  # type: ignore[misc]
        assert s.heights.dtype == np.float64

    def test_missing_data_refused_unless_filled(self) -> None:
        n = 32
        x = (np.arange(n) + 0.5) / n
        h = np.sin(2 * np.pi * x)[:, None] * np.cos(2 * np.pi * x)[None, :]
        holey = h.copy()
        holey[10, 7] = np.nan
        with pytest.raises(ParameterError, match=r"1 undefined.*fill_missing=True"):
            gen.from_array(holey, (1.0, 1.0))
        filled = gen.from_array(holey, (1.0, 1.0), fill_missing=True)
        assert np.all(np.isfinite(filled.heights))
        assert filled.heights[10, 7] == pytest.approx(h[10, 7], abs=0.02)
        np.testing.assert_array_equal(np.delete(filled.heights.ravel(), 10 * n + 7),
                                      np.delete(h.ravel(), 10 * n + 7))  # fmt: skip
        with pytest.raises(ParameterError, match="infinite"):
            gen.from_array(np.array([0.0, np.inf, 1.0, 2.0]), 1.0)

    def test_bad_shapes(self) -> None:
        with pytest.raises(ParameterError, match="physical_sizes"):
            gen.from_array(np.zeros((4, 4)), 1.0)
        with pytest.raises(ParameterError, match=r"heights\.shape"):
            gen.from_array(np.zeros(2), 1.0)
        with pytest.raises(ParameterError, match="gradient"):
            gen.from_array(np.zeros(8), 1.0, gradient="magic")


class TestFunctionSurfaces:
    def test_profile_and_map(self) -> None:
        p = gen.from_function(lambda x: np.cos(x), lambda x: -np.sin(x), 2 * math.pi)
        assert isinstance(p, Profile)
        z, g, _ = p.evaluate(np.array([0.0, 1.0]))
        np.testing.assert_allclose(z, np.cos([0.0, 1.0]), rtol=1e-15)
        np.testing.assert_allclose(g, -np.sin([0.0, 1.0]), rtol=1e-15)
        m = gen.from_function(
            lambda x, y: np.sin(x) * np.sin(2 * y),
            lambda x, y: (np.cos(x) * np.sin(2 * y), 2 * np.sin(x) * np.cos(2 * y)),
            (2 * math.pi, math.pi),
        )
        assert isinstance(m, HeightMap)
        assert m.max_slope == pytest.approx(2.0, rel=1e-2)

    def test_non_periodic_function_refused(self) -> None:
        with pytest.raises(ParameterError, match="not periodic"):
            gen.from_function(lambda x: x, lambda x: np.ones_like(x), 1.0)
        with pytest.raises(ParameterError, match="non-finite"), np.errstate(all="ignore"):
            gen.from_function(lambda x: np.log(np.sin(x)), lambda x: 1 / np.tan(x), math.pi)


class TestSelfAffine:
    def test_reproducible_scaled_and_rng_required(self) -> None:
        a = gen.self_affine(
            0.8, (1e-3, 1e-3), (64, 64), rng=np.random.default_rng(5), rms_slope=0.2
        )
        b = gen.self_affine(
            0.8, (1e-3, 1e-3), (64, 64), rng=np.random.default_rng(5), rms_slope=0.2
        )
        c = gen.self_affine(
            0.8, (1e-3, 1e-3), (64, 64), rng=np.random.default_rng(6), rms_slope=0.2
        )
        np.testing.assert_array_equal(a.heights, b.heights)
        assert not np.allclose(a.heights, c.heights)
        assert a.parameters()["rms_slope"] == pytest.approx(0.2, rel=1e-10)
        assert abs(float(np.mean(a.heights))) < 1e-15
        p = gen.self_affine(0.5, 2.0, 256, rng=np.random.default_rng(0), rms_height=1e-6)
        assert isinstance(p, SampledProfile)
        assert float(np.std(p.heights)) == pytest.approx(1e-6, rel=1e-12)
        with pytest.raises(ParameterError, match="rng"):
            gen.self_affine(0.8, 1.0, 64, rng=None, rms_height=1.0)  # type: ignore[arg-type]
        with pytest.raises(ParameterError, match="exactly one"):
            gen.self_affine(0.8, 1.0, 64, rng=np.random.default_rng(0))
        with pytest.raises(ParameterError, match="hurst"):
            gen.self_affine(1.5, 1.0, 64, rng=np.random.default_rng(0), rms_height=1.0)

    def test_power_spectrum_exponent(self) -> None:
        hurst = 0.7
        s = gen.self_affine(
            hurst, (1.0, 1.0), (256, 256), rng=np.random.default_rng(2), rms_height=1.0
        )
        spectrum = np.abs(np.fft.fft2(s.heights)) ** 2
        q = np.hypot(*np.meshgrid(np.fft.fftfreq(256), np.fft.fftfreq(256), indexing="ij")) * 256
        bins = np.geomspace(2, 100, 15)
        centres, means = [], []
        for lo, hi in itertools.pairwise(bins):
            sel = (q >= lo) & (q < hi)
            centres.append(np.sqrt(lo * hi))
            means.append(spectrum[sel].mean())
        slope = np.polyfit(np.log(centres), np.log(means), 1)[0]
        assert slope == pytest.approx(-2 * (1 + hurst), abs=0.25)
