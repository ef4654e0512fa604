"""Bad inputs to the closed forms: a ParameterError naming the argument, never NaN."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.roughness import closed_forms as cf

CALLS = {
    "h_local": lambda phi, beta: cf.h_local(0.2, phi, beta),
    "normal_force_factor": lambda phi, beta: cf.normal_force_factor(0.2, phi, beta),
    "max_mu0": cf.max_mu0,
    "h_global": lambda g, beta: cf.h_global(0.2, g, 0.0, beta),
    "h_rotated": lambda g, beta: cf.h_rotated(0.2, g, 0.0, beta),
}


@pytest.mark.parametrize("name", sorted(CALLS))
@pytest.mark.parametrize("beta", ["east", math.nan, [0.0, math.inf]])
def test_bad_direction_is_named(name: str, beta: object) -> None:
    with pytest.raises(ParameterError, match=r"^beta\b"):
        CALLS[name](0.1, beta)


@pytest.mark.parametrize("name", ["h_local", "normal_force_factor", "max_mu0"])
@pytest.mark.parametrize("phi", ["steep", math.nan])
def test_bad_tilt_is_named(name: str, phi: object) -> None:
    with pytest.raises(ParameterError, match=r"^phi\b"):
        CALLS[name](phi, 0.0)


@pytest.mark.parametrize("slope", ["x", math.nan])
def test_bad_slope_is_named(slope: object) -> None:
    with pytest.raises(ParameterError, match=r"^gx\b"):
        cf.h_global(0.2, slope, 0.0, 0.0)


@pytest.mark.parametrize(
    ("angles", "beta", "key"),
    [
        ((10.0, 10.0, 0.0, 0.0), "north", "beta_deg"),
        ((10.0, 10.0, 0.0, 0.0), [0.0, math.nan], "beta_deg"),
        (("a", 10.0, 0.0, 0.0), 0.0, "angles_deg"),
        ((math.nan, 10.0, 0.0, 0.0), 0.0, "angles_deg"),
    ],
)
def test_wedge_friction_names_the_bad_argument(angles: object, beta: object, key: str) -> None:
    with pytest.raises(ParameterError, match=rf"^{key}\b"):
        cf.wedge_friction(0.2, angles, beta)


@pytest.mark.parametrize("phi_deg", ["ten", math.nan])
def test_eq17_names_phi_deg(phi_deg: object) -> None:
    with pytest.raises(ParameterError, match=r"^phi_deg\b"):
        cf.flat_on_wedge_0deg(0.2, phi_deg)


def test_good_inputs_unchanged() -> None:
    """A flat contact (phi = 0) gives H = (mu0 cos beta, mu0 sin beta) (Eqs 2-3)."""
    beta = np.array([0.0, 0.3, 1.2])
    hx, hy = cf.h_local(0.2, 0.0, beta)
    np.testing.assert_allclose(hx, 0.2 * np.cos(beta), rtol=1e-15)
    np.testing.assert_allclose(hy, 0.2 * np.sin(beta), rtol=1e-15)
