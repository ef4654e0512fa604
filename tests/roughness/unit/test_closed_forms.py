"""Closed forms: multipliers (Eqs 1-4), validity bound, wedge formulas (Eqs 14-20).

Expected values come from an independent force balance written in the test, special
values stated in the spec, and symmetries; never from the functions under test.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from frictionlab.errors import ParameterError, ValidityError
from frictionlab.roughness import closed_forms as cf


def equilibrium(mu0: float, gx: float, gy: float, beta: float) -> tuple[float, float, float]:
    """Force on the upper body at a contact from first principles, per unit F_z.

    Unit normal n of the contacted surface (pointing to the upper body), unit tangent t
    of the sliding velocity lifted onto the tangent plane, F = N n - mu0 N t with F_z = 1.
    Returns (N, -F_x, -F_y).
    """
    n = np.array([-gx, -gy, 1.0]) / math.sqrt(1.0 + gx * gx + gy * gy)
    v = np.array([math.cos(beta), math.sin(beta), 0.0])
    v[2] = gx * v[0] + gy * v[1]  # stays on z = f(x, y) to first order
    t = v / np.linalg.norm(v)
    direction = n - mu0 * t
    big_n = 1.0 / direction[2]
    force = big_n * direction
    return big_n, -force[0], -force[1]


def printed_eq4(mu0: float, gx: float, gy: float, beta: float) -> tuple[float, float]:
    """Eq 4 exactly as printed, applied with counter-clockwise alpha (known to be wrong)."""
    alpha = math.atan2(gy, gx)
    phi = math.atan(math.hypot(gx, gy))
    hx, hy = cf.h_local(mu0, phi, beta - alpha)
    return (
        math.cos(alpha) * float(hx) + math.sin(alpha) * float(hy),
        -math.sin(alpha) * float(hx) + math.cos(alpha) * float(hy),
    )


class TestMultipliers:
    def test_special_values(self) -> None:
        mu0, phi = 0.3, math.radians(25.0)
        t = math.tan(phi)
        hx, hy = cf.h_local(mu0, phi, 0.0)
        assert float(hx) == pytest.approx((mu0 + t) / (1.0 - mu0 * t), rel=1e-14)
        assert float(hy) == 0.0
        hx, hy = cf.h_local(mu0, phi, math.pi / 2)
        assert float(hx) == pytest.approx(t, rel=1e-14)
        assert float(hy) == pytest.approx(mu0 / math.cos(phi), rel=1e-14)
        for beta in (0.3, 1.1, 2.5):
            hx, hy = cf.h_local(mu0, 0.0, beta)
            assert (float(hx), float(hy)) == pytest.approx(
                (mu0 * math.cos(beta), mu0 * math.sin(beta)), abs=1e-15
            )

    @settings(max_examples=200, deadline=None)
    @given(
        mu0=st.floats(0.0, 1.0),
        gx=st.floats(-1.5, 1.5),
        gy=st.floats(-1.5, 1.5),
        beta=st.floats(-math.pi, math.pi),
    )
    def test_global_form_equals_force_balance(
        self, mu0: float, gx: float, gy: float, beta: float
    ) -> None:
        big_n, ex, ey = equilibrium(mu0, gx, gy, beta)
        if big_n <= 0.0 or not math.isfinite(big_n):
            with pytest.raises(ValidityError):
                cf.h_global(mu0, gx, gy, beta)
            return
        assume(big_n < 1e6)  # too close to the singular bound for a relative comparison
        hx, hy = cf.h_global(mu0, gx, gy, beta)
        assert float(hx) == pytest.approx(ex, rel=1e-10, abs=1e-12)
        assert float(hy) == pytest.approx(ey, rel=1e-10, abs=1e-12)

    def test_rotated_local_frame_equals_frame_free_on_1000_random_points(self) -> None:
        rng = np.random.default_rng(3)
        gx, gy = rng.uniform(-1.2, 1.2, (2, 1000))
        beta = rng.uniform(-math.pi, math.pi, 1000)
        hx, hy = cf.h_global(0.3, gx, gy, beta)
        rx, ry = cf.h_rotated(0.3, gx, gy, beta)
        np.testing.assert_allclose(rx, hx, rtol=1e-12, atol=1e-13)
        np.testing.assert_allclose(ry, hy, rtol=1e-12, atol=1e-13)
        # The printed matrix with counter-clockwise alpha is off by O(1) (spec section 3.1).
        worst = max(
            math.hypot(p[0] - float(hx[i]), p[1] - float(hy[i]))
            for i, p in enumerate(printed_eq4(0.3, gx[i], gy[i], beta[i]) for i in range(200))
        )
        assert worst > 0.1

    def test_1d_signed_slope_equals_2d_with_alpha_0_or_pi(self) -> None:
        phi = np.radians(np.linspace(-60.0, 60.0, 25))
        for beta in np.radians([0.0, 20.0, 75.0, 90.0, 135.0]):
            hx, hy = cf.h_local(0.4, phi, beta)
            gx, gy = cf.h_global(0.4, np.tan(phi), 0.0, beta)
            np.testing.assert_allclose(hx, gx, rtol=1e-13, atol=1e-14)
            np.testing.assert_allclose(hy, gy, rtol=1e-13, atol=1e-14)

    def test_normal_force_factor_is_eq1(self) -> None:
        for phi_deg, beta_deg in ((20.0, 0.0), (35.0, 40.0), (-30.0, 10.0), (50.0, 120.0)):
            phi, beta = math.radians(phi_deg), math.radians(beta_deg)
            big_n, _, _ = equilibrium(0.3, math.tan(phi), 0.0, beta)
            assert float(cf.normal_force_factor(0.3, phi, beta)) == pytest.approx(big_n, rel=1e-12)

    def test_small_slope_law(self) -> None:
        # Spec property 13: R_par = mu0 + (1+mu0^2) a + mu0 (1+mu0^2) a^2 + mu0 b^2 / 2,
        # R_perp = b + mu0 a b, for slope a along v and b across v.
        mu0 = 0.3
        for a, b in ((1e-3, 0.0), (0.0, 1e-3), (7e-4, -5e-4)):
            beta = 0.4
            gx = a * math.cos(beta) - b * math.sin(beta)
            gy = a * math.sin(beta) + b * math.cos(beta)
            hx, hy = cf.h_global(mu0, gx, gy, beta)
            par = float(hx) * math.cos(beta) + float(hy) * math.sin(beta)
            perp = -float(hx) * math.sin(beta) + float(hy) * math.cos(beta)
            expected_par = mu0 + (1 + mu0**2) * a + mu0 * (1 + mu0**2) * a**2 + 0.5 * mu0 * b**2
            assert par == pytest.approx(expected_par, abs=10 * 1e-9)
            assert perp == pytest.approx(b + mu0 * a * b, abs=10 * 1e-9)


class TestValidity:
    def test_bound_is_cot_phi_at_beta_0_and_looser_elsewhere(self) -> None:
        phi = np.radians([10.0, 30.0, 45.0, 60.0])
        np.testing.assert_allclose(cf.max_mu0(phi, 0.0), 1.0 / np.tan(phi), rtol=1e-14)
        for beta in np.radians([10.0, 45.0, 80.0]):
            assert np.all(cf.max_mu0(phi, beta) > 1.0 / np.tan(phi))
        assert np.all(np.isinf(cf.max_mu0(phi, math.radians(120.0))))  # descending contact
        assert np.all(np.isinf(cf.max_mu0(-phi, 0.0)))

    def test_just_inside_finite_just_outside_refused(self) -> None:
        phi, beta = math.radians(50.0), math.radians(30.0)
        bound = float(cf.max_mu0(phi, beta))
        hx, _ = cf.h_local(bound * (1 - 1e-9), phi, beta)
        assert math.isfinite(float(hx)) and float(hx) > 1e6
        with pytest.raises(ValidityError, match=r"mu0 <"):
            cf.h_local(bound * (1 + 1e-9), phi, beta)
        with pytest.raises(ValidityError, match="phi = 50"):
            cf.h_global(bound * 1.01, math.tan(phi), 0.0, beta)

    def test_bad_arguments(self) -> None:
        with pytest.raises(ParameterError, match="mu0"):
            cf.h_local(-0.1, 0.1, 0.0)
        with pytest.raises(ParameterError, match="phi"):
            cf.h_local(0.3, math.pi / 2, 0.0)
        with pytest.raises(ParameterError, match="mu0"):
            cf.h_global(float("nan"), 0.1, 0.0, 0.0)


class TestWedgeFormulas:
    PHIS = np.arange(0.0, 71.0, 5.0)

    def test_eqs_17_to_20_follow_from_eqs_15_16(self) -> None:
        mu0 = 0.3
        phis = self.PHIS[cf.singular_angle_deg(mu0) > self.PHIS]
        for phi in phis:
            flat_0 = cf.wedge_friction(mu0, (phi, phi, 0.0, 0.0), 0.0)
            flat_90 = cf.wedge_friction(mu0, (phi, phi, 0.0, 0.0), 90.0)
            rough_0 = cf.wedge_friction(mu0, (phi, phi, phi, phi), 0.0)
            rough_90 = cf.wedge_friction(mu0, (phi, phi, phi, phi), 90.0)
            assert float(flat_0[0]) == pytest.approx(
                float(cf.flat_on_wedge_0deg(mu0, phi)), rel=1e-13
            )
            assert float(flat_90[1]) == pytest.approx(
                float(cf.flat_on_wedge_90deg(mu0, phi)), rel=1e-13
            )
            assert float(rough_0[0]) == pytest.approx(
                float(cf.wedge_on_wedge_0deg(mu0, phi)), rel=1e-13
            )
            assert float(rough_90[1]) == pytest.approx(
                float(cf.wedge_on_wedge_90deg(mu0, phi)), rel=1e-13
            )
            assert abs(float(flat_0[1])) < 1e-15 and abs(float(flat_90[0])) < 1e-15

    def test_eq19_two_forms_and_flat_limit(self) -> None:
        mu0 = 0.3
        phi = np.radians(self.PHIS[:12])
        np.testing.assert_allclose(
            cf.wedge_on_wedge_0deg(mu0, self.PHIS[:12]),
            mu0 * (1 + np.tan(phi) ** 2) / (1 - mu0**2 * np.tan(phi) ** 2),
            rtol=1e-13,
        )
        for f in (
            cf.flat_on_wedge_0deg,
            cf.flat_on_wedge_90deg,
            cf.wedge_on_wedge_0deg,
            cf.wedge_on_wedge_90deg,
        ):
            assert float(f(mu0, 0.0)) == pytest.approx(mu0, rel=1e-15)

    def test_orderings(self) -> None:
        mu0 = 0.3
        phis = self.PHIS[(self.PHIS > 0) & (cf.singular_angle_deg(mu0) > self.PHIS)]
        assert np.all(cf.flat_on_wedge_0deg(mu0, phis) < cf.wedge_on_wedge_0deg(mu0, phis))
        assert np.all(cf.flat_on_wedge_90deg(mu0, phis) < cf.wedge_on_wedge_90deg(mu0, phis))
        assert np.all(cf.wedge_on_wedge_0deg(mu0, phis) > cf.wedge_on_wedge_90deg(mu0, phis))

    def test_singular_angle(self) -> None:
        mu0 = 0.3
        phi_star = cf.singular_angle_deg(mu0)
        assert phi_star == pytest.approx(math.degrees(math.atan(1 / mu0)), rel=1e-15)
        assert float(cf.wedge_on_wedge_0deg(mu0, phi_star - 1e-6)) > 1e4
        for f in (cf.flat_on_wedge_0deg, cf.wedge_on_wedge_0deg):
            with pytest.raises(ValidityError, match="singular angle"):
                f(mu0, phi_star + 1e-6)
        with pytest.raises(ValidityError):
            cf.wedge_friction(mu0, (phi_star + 0.5, 10.0, 0.0, 0.0), 0.0)

    def test_face_weights(self) -> None:
        w1, w2 = cf.wedge_face_weights(30.0, 15.0)
        psi = math.tan(math.radians(15.0)) / math.tan(math.radians(30.0))
        assert (w1, w2) == pytest.approx((psi / (1 + psi), 1 / (1 + psi)), rel=1e-15)
        assert cf.wedge_face_weights(0.0, 0.0) == (0.5, 0.5)
        with pytest.raises(ParameterError, match="angles_deg"):
            cf.wedge_face_weights(20.0, 0.0)
        with pytest.raises(ParameterError, match="0 <= angle < 90"):
            cf.wedge_face_weights(90.0, 10.0)

    def test_axis_components_need_horizontal_weights(self) -> None:
        # Property 4: mu_y(0) = 0 and mu_x(90) = 0 for asymmetric wedges.
        for angles in ((30, 15, 0, 0), (15, 30, 0, 0), (30, 15, 30, 15), (40, 10, 20, 35)):
            mu_x, mu_y = cf.wedge_friction(0.3, angles, [0.0, 90.0])
            assert abs(float(mu_y[0])) < 1e-16
            assert abs(float(mu_x[1])) < 1e-15
        # The reversed weights would leave a lateral force at 90 deg: the test can tell.
        t1, t2 = math.tan(math.radians(30)), math.tan(math.radians(15))
        reversed_mu_x = 0.5 * (t1 / (t1 + t2) * t1 - t2 / (t1 + t2) * t2)
        assert abs(reversed_mu_x) > 0.05

    def test_lower_bound_and_slope_monotonicity_on_20000_random_wedges(self) -> None:
        # Property 7: mu >= mu0 for any wedge at any beta; scaling all tan(phi) by 0.9
        # never increases mu.
        rng = np.random.default_rng(11)
        n = 20000
        angles = rng.uniform(1.0, 40.0, (n, 4))
        angles[rng.random(n) < 0.3, 2:] = 0.0  # some flat upper surfaces
        beta = rng.uniform(0.0, 360.0, n)
        mu0 = 0.3  # tan(40 deg) * 0.3 < 1: all valid
        mx, my = cf.wedge_friction(mu0, angles, beta)
        mu = np.hypot(mx, my)
        assert mu.shape == (n,)
        assert np.count_nonzero(mu < mu0 * (1 - 1e-12)) == 0
        scaled = np.degrees(np.arctan(0.9 * np.tan(np.radians(angles))))
        sx, sy = cf.wedge_friction(mu0, scaled, beta)
        assert np.count_nonzero(np.hypot(sx, sy) > mu * (1 + 1e-12)) == 0
        # The vectorised call agrees with single calls.
        for i in range(0, n, 4000):
            one = cf.wedge_friction(mu0, tuple(angles[i]), beta[i])
            assert float(one[0]) == pytest.approx(mx[i], rel=1e-15)

    def test_beta_dependence_symmetric_wedges(self) -> None:
        betas = np.linspace(0.0, 90.0, 91)
        for angles in ((30, 30, 0, 0), (25, 25, 25, 25), (45, 45, 10, 10)):
            mx, my = cf.wedge_friction(0.3, angles, betas)
            mu = np.hypot(mx, my)
            assert np.all(np.diff(mu) <= 1e-14)  # property 8: non-increasing on [0, 90]
            mx2, my2 = cf.wedge_friction(0.3, angles, -betas)
            np.testing.assert_allclose(np.hypot(mx2, my2), mu, rtol=1e-14)

    def test_direction_reversal_is_face_swap(self) -> None:
        # Property 9 / scenario RV.
        forward_x, _ = cf.wedge_friction(0.3, (30, 15, 0, 0), 0.0)
        back_x, back_y = cf.wedge_friction(0.3, (30, 15, 0, 0), 180.0)
        swapped_x, _ = cf.wedge_friction(0.3, (15, 30, 0, 0), 0.0)
        assert -float(back_x) == pytest.approx(float(swapped_x), rel=1e-14)
        assert abs(float(back_y)) < 1e-15
        assert float(forward_x) > float(swapped_x)  # ratchet: C > D
        e, _ = cf.wedge_friction(0.3, (30, 15, 30, 15), 0.0)
        f, _ = cf.wedge_friction(0.3, (15, 30, 15, 30), 0.0)
        assert float(e) > float(f)

    def test_beta_90_coincidences(self) -> None:
        # Property 10: E and F coincide at 90 deg, and so do C and D.
        for big, small in ((30, 15), (20, 10)):
            pairs = (((big, small, big, small), (small, big, small, big)),
                     ((big, small, 0, 0), (small, big, 0, 0)))  # fmt: skip
            for a, b in pairs:
                ya = cf.wedge_friction(0.3, a, 90.0)[1]
                yb = cf.wedge_friction(0.3, b, 90.0)[1]
                assert float(ya) == pytest.approx(float(yb), rel=1e-14)
