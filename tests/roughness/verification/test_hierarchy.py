"""Hierarchy (spec 3.7, Eqs 28-35; scenarios T7-T11; property 15) and hierarchy with wear.

Expected values: the closed forms Eqs 33-34, hand iteration of Eqs 17-20, an independent
quadrature recursion of the area-averaged multipliers (scipy quad of the local-frame
Eqs 2-3), symmetries, and Eq 35 computed from the level amplitudes by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from frictionlab.errors import ParameterError, ValidityError
from frictionlab.roughness import closed_forms as cf
from frictionlab.roughness import generators as gen
from frictionlab.roughness.hierarchy import (
    HierarchyLevel,
    check_nested,
    hierarchy_friction,
    hierarchy_wear,
    self_similar_levels,
    wedge_hierarchy,
)
from frictionlab.roughness.lattice import LatticeSettings
from frictionlab.roughness.wear import WearSettings

TWO_PI = 2.0 * math.pi
WEAR = WearSettings(
    wear_coefficient=1e-4, hardness=2e9, normal_load=100.0, velocity=0.1, nominal_area=1e-4
)
GRID_2D = LatticeSettings(stations=32, time_samples=16)


class TestClosedForms:
    @pytest.mark.parametrize("phi", [10.0, 20.0, 30.0])
    def test_eqs_33_34_are_iterated_eqs_18_20(self, phi) -> None:
        mu_a = mu_b = 0.3
        for n in range(6):
            assert float(cf.hierarchy_flat_on_wedge_90deg(0.3, phi, n)) == pytest.approx(
                mu_a, rel=1e-14
            )
            assert float(cf.hierarchy_wedge_on_wedge_90deg(0.3, phi, n)) == pytest.approx(
                mu_b, rel=1e-14
            )
            mu_a = float(cf.flat_on_wedge_90deg(mu_a, phi))  # Eq 18 with mu0 -> mu_{n}
            mu_b = float(cf.wedge_on_wedge_90deg(mu_b, phi))  # Eq 20

    @pytest.mark.parametrize("phi", [10.0, 20.0, 30.0])
    def test_wedge_recursion_reproduces_eqs_33_34(self, phi) -> None:
        # T7 at beta = 90 deg: the general recursion (Eqs 15-16) equals the closed forms.
        n = np.arange(6)
        flat = wedge_hierarchy(0.3, (phi, phi, 0.0, 0.0), [90.0], 5)
        rough = wedge_hierarchy(0.3, (phi, phi, phi, phi), [90.0], 5)
        np.testing.assert_allclose(
            flat.mu[:, 0], cf.hierarchy_flat_on_wedge_90deg(0.3, phi, n), rtol=1e-13
        )
        np.testing.assert_allclose(
            rough.mu[:, 0], cf.hierarchy_wedge_on_wedge_90deg(0.3, phi, n), rtol=1e-13
        )

    @pytest.mark.parametrize("pair", ["flat", "rough"])
    def test_lattice_recursion_reproduces_eqs_33_34(self, pair) -> None:
        # The lattice's single-level map iterated over 4 self-similar wedge levels.
        w = gen.wedge(20.0, 1.0)
        levels = self_similar_levels(w, gen.flat() if pair == "flat" else w, 4, 10.0)
        result = hierarchy_friction(levels, 0.3, [90.0], settings=LatticeSettings(stations=4000))
        closed = (
            cf.hierarchy_flat_on_wedge_90deg
            if pair == "flat"
            else cf.hierarchy_wedge_on_wedge_90deg
        )
        np.testing.assert_allclose(result.mu[:, 0], closed(0.3, 20.0, np.arange(5)), rtol=1e-4)

    def test_beta_0_grows_monotonically_and_leaves_the_validity_domain(self) -> None:
        # T7 at beta = 0: iterate Eq 19 by hand until mu tan(phi) >= 1 (the bound of Eq 1).
        phi, expected = 30.0, [0.3]
        while expected[-1] * math.tan(math.radians(phi)) < 1.0:
            expected.append(float(cf.wedge_on_wedge_0deg(expected[-1], phi)))
        first_bad = len(expected)  # level whose local coefficient violates the bound
        n = first_bad + 1
        result = wedge_hierarchy(0.3, (phi,) * 4, [0.0, 90.0], n, on_invalid="mask")
        assert int(result.first_invalid_level[0]) == first_bad
        assert int(result.first_invalid_level[1]) == 0
        valid = np.ma.getdata(result.mu[:first_bad, 0])
        np.testing.assert_allclose(valid, expected, rtol=1e-12)
        assert np.all(np.ma.getmaskarray(result.mu)[first_bad:, 0])
        assert np.all(np.diff(valid) > 0.0)
        assert np.all(np.diff(valid)[1:] > np.diff(valid)[:-1])  # super-geometric growth
        with pytest.raises(ValidityError, match=f"hierarchy level {first_bad} of {n}"):
            wedge_hierarchy(0.3, (phi,) * 4, [0.0], n)


def sine_map(mu: float, beta_deg: float, flat_upper: bool) -> float:
    """One level of z = sin x (slope amplitude 1) in full contact, by quadrature (|mu|)."""
    b = math.radians(beta_deg)

    def h(x: float, k: int) -> float:
        return float(cf.h_local(mu, math.atan(math.cos(x)), b)[k])

    hx = quad(h, 0.0, TWO_PI, args=(0,), epsabs=1e-13, limit=200)[0] / TWO_PI
    hy = quad(h, 0.0, TWO_PI, args=(1,), epsabs=1e-13, limit=200)[0] / TWO_PI
    if flat_upper:  # half the springs on a flat face: H = mu (cos b, sin b)
        hx, hy = 0.5 * (hx + mu * math.cos(b)), 0.5 * (hy + mu * math.sin(b))
    return math.hypot(hx, hy)


class TestSinusoidHierarchies:
    @pytest.mark.parametrize("flat_upper", [True, False])
    def test_t8_recursion_equals_quadrature_recursion(self, flat_upper) -> None:
        s = gen.sinusoid(1.0, TWO_PI)
        levels = self_similar_levels(s, gen.flat() if flat_upper else s, 3, 10.0)
        result = hierarchy_friction(
            levels, 0.3, [0.0, 90.0], settings=LatticeSettings(stations=2000, time_samples=40)
        )
        for k, beta in enumerate((0.0, 90.0)):
            expected = [0.3]
            for _ in range(3):
                expected.append(sine_map(expected[-1], beta, flat_upper))
            np.testing.assert_allclose(result.mu[:, k], expected, rtol=1e-8)
            values = np.ma.getdata(result.mu[:, k])
            assert np.all(np.diff(values) > 0.0)  # mu grows with every level
            # Jensen: above the wedge approximation with tan(phi) = mean |slope| = 2/pi
            phi = math.degrees(math.atan(2.0 / math.pi))
            if beta == 90.0:
                approx = (
                    cf.hierarchy_flat_on_wedge_90deg
                    if flat_upper
                    else cf.hierarchy_wedge_on_wedge_90deg
                )(0.3, phi, np.arange(4))
                assert np.all(values[1:] > approx[1:])

    def test_t9_symmetric_2d_levels(self) -> None:
        s = gen.sinusoid(1.0, [TWO_PI, TWO_PI])
        levels = self_similar_levels(s, s, 3, 10.0)
        betas = [0.0, 20.0, 45.0, 70.0, 90.0]
        result = hierarchy_friction(levels, 0.3, betas, settings=GRID_2D)
        mu = np.ma.getdata(result.mu)
        np.testing.assert_allclose(mu, mu[:, ::-1], rtol=1e-12)  # mu(beta) = mu(90 - beta)
        assert np.all(np.diff(mu, axis=0) > 0.0)

    def test_t10_asymmetric_levels_vs_beta(self) -> None:
        # Fig 13b: (2 pi, 3 pi) and (3 pi, 2 pi) levels: equal at 45 deg, different at 0;
        # swapping the wavelengths maps beta to 90 - beta at every level.
        a = gen.sinusoid(1.0, [TWO_PI, 1.5 * TWO_PI])
        b = gen.sinusoid(1.0, [1.5 * TWO_PI, TWO_PI])
        betas = np.array([0.0, 45.0, 90.0])
        ra = hierarchy_friction(self_similar_levels(a, a, 3, 4.0), 0.3, betas, settings=GRID_2D)
        rb = hierarchy_friction(self_similar_levels(b, b, 3, 4.0), 0.3, betas, settings=GRID_2D)
        mu_a, mu_b = np.ma.getdata(ra.mu), np.ma.getdata(rb.mu)
        np.testing.assert_allclose(mu_a, mu_b[:, ::-1], rtol=1e-12)
        np.testing.assert_allclose(mu_a[:, 1], mu_b[:, 1], rtol=1e-12)
        assert abs(mu_a[3, 0] - mu_b[3, 0]) > 0.05 * mu_a[3, 0]
        assert np.all(np.diff(mu_a, axis=0) > 0.0)

    def test_passed_coefficient_option(self) -> None:
        w = gen.wedge((30.0, 15.0), 1.0)
        levels = self_similar_levels(w, gen.flat(), 2, 10.0)
        kw = {"settings": LatticeSettings(stations=4000, time_samples=40)}
        mag = hierarchy_friction(levels, 0.3, [0.0, 45.0], **kw)
        proj = hierarchy_friction(levels, 0.3, [0.0, 45.0], mu_passed="projection", **kw)
        assert float(proj.mu[2, 0]) == pytest.approx(float(mag.mu[2, 0]), rel=1e-14)
        assert float(proj.mu[2, 1]) < float(mag.mu[2, 1]) - 2e-4  # the lateral part is dropped
        cb = math.cos(math.radians(45.0))
        assert float(proj.mu[1, 1]) == pytest.approx(
            (float(proj.mu_x[1, 1]) + float(proj.mu_y[1, 1])) * cb, rel=1e-14
        )


class TestLevels:
    def test_self_similar_levels_eq_28(self) -> None:
        s = gen.sinusoid(1.0, [TWO_PI, 1.5 * TWO_PI])
        levels = self_similar_levels(s, gen.flat(), 3, 5.0)
        for i, level in enumerate(levels, 1):
            f = 5.0 ** -(3 - i)
            assert level.lower.amplitude == pytest.approx(f, rel=1e-15)
            assert level.lower.wavelengths == pytest.approx((TWO_PI * f, 3 * math.pi * f))
            assert level.lower.max_slope == pytest.approx(s.max_slope, rel=1e-14)

    def test_not_strictly_nested_levels_are_refused(self) -> None:
        big, small = gen.sinusoid(1e-4, 1e-3), gen.sinusoid(1e-5, 1e-4)
        check_nested([HierarchyLevel(small, gen.flat()), HierarchyLevel(big, gen.flat())])
        with pytest.raises(ParameterError, match="strictly nested"):
            check_nested([HierarchyLevel(big, gen.flat()), HierarchyLevel(small, gen.flat())])
        with pytest.raises(ParameterError, match="strictly nested"):
            check_nested([HierarchyLevel(big, gen.flat()), HierarchyLevel(big, big)])
        with pytest.raises(ParameterError, match="roughness"):
            check_nested([HierarchyLevel(gen.flat(), gen.flat())])
        a = gen.sinusoid(1.0, [TWO_PI, 1.5 * TWO_PI])
        with pytest.raises(ParameterError, match="strictly nested"):  # ratio 1.2 < 3pi / 2pi
            self_similar_levels(a, a, 2, 1.2)
        with pytest.raises(ParameterError, match="ratio"):
            self_similar_levels(a, a, 2, 1.0)
        with pytest.raises(ParameterError, match="levels"):
            hierarchy_friction([], 0.3, [0.0])


class TestHierarchyWithWear:
    def test_t11_stages_and_eq_35_dropout_times(self) -> None:
        s = gen.sinusoid(1.0, [TWO_PI, TWO_PI])
        ratio = 4.0
        levels = self_similar_levels(s, s, 3, ratio)
        history = hierarchy_wear(levels, 0.3, [0.0], WEAR, samples_per_level=3, settings=GRID_2D)
        # Eq 35: <z - z_min> = A_i for sin sin; both surfaces wear: V_i = 2 A_i A_n
        amplitudes = np.array([ratio**-2, ratio**-1, 1.0])
        expected_tw = 2.0 * amplitudes * WEAR.nominal_area / WEAR.volume_rate
        np.testing.assert_allclose(history.wear_time, expected_tw, rtol=1e-13)
        np.testing.assert_allclose(history.dropout_time, np.cumsum(expected_tw), rtol=1e-13)
        # T11 stages (B1, B2, B3) at the sample times: (1,1,1), (.5,1,1), (0,1,1), (0,.5,1),
        # (0,0,1), (0,0,.5), (0,0,0)
        stages = [(1, 1, 1), (0.5, 1, 1), (0, 1, 1), (0, 0.5, 1), (0, 0, 1), (0, 0, 0.5), (0, 0, 0)]
        np.testing.assert_allclose(history.reduction, stages, atol=1e-12)
        assert list(history.active_levels) == [3, 3, 2, 2, 1, 1, 0]
        mu = history.mu[:, :, 0]
        assert np.all(np.diff(mu, axis=0) <= 1e-15)  # every level's mu decreases with wear
        np.testing.assert_allclose(mu[-1], 0.3, rtol=1e-14)  # all flat: mu0 at the end
        # Removing level 1 (B1 = 0) gives exactly the 2-level hierarchy of levels 2 and 3
        two = hierarchy_friction(levels[1:], 0.3, [0.0], settings=GRID_2D)
        np.testing.assert_allclose(mu[2, 1:], np.ma.getdata(two.mu[:, 0]), rtol=1e-14)
        # Stage (0.5, 1, 1) equals the hierarchy with level 1 at half height
        half = [levels[0].worn(0.5), *levels[1:]]
        part = hierarchy_friction(half, 0.3, [0.0], settings=GRID_2D, check=False)
        np.testing.assert_allclose(mu[1], np.ma.getdata(part.mu[:, 0]), rtol=1e-14)

    def test_times_and_bad_input(self) -> None:
        w = gen.wedge(20.0, 1.0)
        levels = self_similar_levels(w, gen.flat(), 2, 10.0)
        history = hierarchy_wear(
            levels, 0.3, [90.0], WEAR, times=[0.0, 1e12], settings=LatticeSettings(stations=2000)
        )
        assert history.mu[1, 2, 0] == pytest.approx(0.3, rel=1e-14)  # long after: flat
        with pytest.raises(ParameterError, match="samples_per_level"):
            hierarchy_wear(levels, 0.3, [0.0], WEAR, samples_per_level=1)
        steep = self_similar_levels(gen.wedge(60.0, 1.0), gen.wedge(60.0, 1.0), 3, 10.0)
        with pytest.raises(ValidityError, match="hierarchy level"):
            hierarchy_wear(steep, 0.3, [0.0], WEAR, settings=LatticeSettings(stations=1000))
