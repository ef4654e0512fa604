"""Closed sliding-yield surfaces, Eqs (48)–(54), and their friction-coefficient closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.subloading import friction_coefficient_on_yield, g_function, g_inverse
from frictionlab.subloading.surfaces import chi_max

CLOSED = ("cam_clay", "modified_cam_clay", "tear", "parabola")


@pytest.mark.parametrize("surface", CLOSED)
def test_g_normalisation_and_top_point(surface: str) -> None:
    """g(0) = 1 and g(1) = g'(1): the top of the surface lies at the ratio M."""
    g0, _ = g_function(surface, np.array([0.0]))
    g1, dg1 = g_function(surface, np.array([1.0]))
    assert g0[0] == pytest.approx(1.0, rel=1e-15)
    assert g1[0] == pytest.approx(dg1[0], rel=1e-14)


@pytest.mark.parametrize("surface", CLOSED)
def test_g_derivative_and_inverse(surface: str) -> None:
    chi = np.linspace(0.05, 0.95 * min(chi_max(surface), 3.0), 25)
    g, dg = g_function(surface, chi)
    h = 1e-6
    fd = (g_function(surface, chi + h)[0] - g_function(surface, chi - h)[0]) / (2 * h)
    np.testing.assert_allclose(dg, fd, rtol=1e-7)
    np.testing.assert_allclose(g_inverse(surface, g), chi, rtol=1e-12)


def test_outside_domain_is_infinite_not_nan() -> None:
    g, dg = g_function("tear", np.array([1.7321, 2.0]))
    assert np.all(np.isinf(g)) and np.all(np.isinf(dg))
    g, _ = g_function("parabola", np.array([2.0, 2.5]))
    assert np.all(np.isinf(g))


@pytest.mark.parametrize("ratio", [0.05, 0.10, 0.20, 0.30, 0.40])
def test_friction_coefficient_closed_forms_of_the_table(ratio: float) -> None:
    """mu(f_n) = M g^-1(F/f_n) against closed forms typed independently."""
    M, F = 0.5, 1.0
    fn = ratio * F
    expected = {
        "cam_clay": M * np.log(F / fn),
        "modified_cam_clay": M * np.sqrt(F / fn - 1.0),
        "tear": M * np.sqrt(3.0 * (1.0 - fn / F)),
        "parabola": 2.0 * M * (1.0 - fn / F),
    }
    for surface, value in expected.items():
        got = friction_coefficient_on_yield(surface, fn, F, M)
        assert got == pytest.approx(value, rel=1e-12), surface


def test_friction_coefficient_domain_checked() -> None:
    with pytest.raises(ParameterError):
        friction_coefficient_on_yield("modified_cam_clay", 1.5, 1.0, 0.5)
    with pytest.raises(ParameterError):
        friction_coefficient_on_yield("tear", 0.0, 1.0, 0.5)


def test_tear_family_option_keeps_the_tear_property() -> None:
    """(1 - a chi^2)^-k with a = 1/(2k+1): g(0) = 1, g(1) = g'(1) for any k."""
    for k in (0.5, 1.0, 2.0, 3.0):
        g1, dg1 = g_function("tear", np.array([1.0]), tear_k=k)
        assert g1[0] == pytest.approx(dg1[0], rel=1e-13)
        assert chi_max("tear", k) == pytest.approx(np.sqrt(2 * k + 1))
