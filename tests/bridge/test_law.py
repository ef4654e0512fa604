"""fitted_law: the fitted shape in a SubloadingParams, sized by the [law] or by the roughness."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.bridge import (
    DirectionalFriction,
    fit_anisotropy,
    fitted_law,
    law_polar,
    relative_rotation_of,
)
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

from .support import DIRECTIONS, support_polar

K, C2, ANGLE, BETA = 0.42, 0.6, math.radians(25.0), np.array([0.03, -0.01])


@pytest.fixture(scope="module")
def fit():  # type: ignore[no-untyped-def]
    """A fit of a roughness-like polar written with the support-point formula."""
    data = support_polar(DIRECTIONS, K, C2, ANGLE, BETA)
    return fit_anisotropy(DirectionalFriction(DIRECTIONS, data[:, 0], data[:, 1]))


def cone(**changes: object) -> SubloadingParams:
    base: dict[str, object] = dict(mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3)
    base.update(changes)
    return SubloadingParams(**base)  # type: ignore[arg-type]


def closed(**changes: object) -> SubloadingParams:
    base: dict[str, object] = dict(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5)
    base.update(changes)
    return SubloadingParams(**base)  # type: ignore[arg-type]


def test_scale_roughness_gives_the_roughness_polar_as_the_kinetic_polar(fit) -> None:  # type: ignore[no-untyped-def]
    law = fitted_law(cone(), fit, scale="roughness").params
    assert float(law.mu_k) == pytest.approx(K, rel=1e-10)
    assert float(law.mu_s) / float(law.mu_k) == pytest.approx(0.5 / 0.3, rel=1e-14)  # kept
    np.testing.assert_allclose(law.rotation, BETA, atol=1e-10)
    np.testing.assert_allclose(
        law_polar(law, DIRECTIONS), support_polar(DIRECTIONS, K, C2, ANGLE, BETA), atol=1e-10
    )
    assert float(law.u) == 100.0 and float(law.xi) == 1e-3  # the rest is the user's


def test_scale_law_keeps_the_users_kinetic_coefficient_and_scales_the_shape(fit) -> None:  # type: ignore[no-untyped-def]
    result = fitted_law(cone(), fit, scale="law")
    law = result.params
    assert float(law.mu_k) == 0.3 and float(law.mu_s) == 0.5
    assert result.factor == pytest.approx(0.3 / K, rel=1e-10)
    np.testing.assert_allclose(law.rotation, BETA * 0.3 / K, atol=1e-10)
    # along e*_1 the law's kinetic friction is mu_k + beta . e*_1 (spec test 10 with beta)
    along = law_polar(law, [math.degrees(ANGLE)])[0]
    e1 = np.array([math.cos(ANGLE), math.sin(ANGLE)])
    np.testing.assert_allclose(along, 0.3 * e1 + BETA * 0.3 / K, atol=1e-10)


@pytest.mark.parametrize("scale", ["law", "roughness"])
def test_closed_surface_sizes(fit, scale: str) -> None:  # type: ignore[no-untyped-def]
    fn = 0.2
    result = fitted_law(closed(), fit, scale=scale, normal_traction=fn)
    law = result.params
    assert float(law.F_s) == 1.0 and float(law.F_k) == 0.6  # pressure dependence kept
    mu_k_user = 0.5 * math.sqrt(0.6 / fn - 1.0)  # Eq 52 at F_k
    expected_k = mu_k_user if scale == "law" else K
    assert float(law.M) == pytest.approx(0.5 * expected_k / mu_k_user, rel=1e-10)
    np.testing.assert_allclose(
        law_polar(law, DIRECTIONS, None, fn),
        support_polar(DIRECTIONS, expected_k, C2, ANGLE, BETA * expected_k / K),
        atol=1e-10,
    )


def test_relative_rotation_round_trip() -> None:
    np.testing.assert_allclose(relative_rotation_of(cone(rotation=(0.03, 0.0))), [0.1, 0.0])
    law = closed(rotation=(0.02, 0.0))
    np.testing.assert_allclose(
        relative_rotation_of(law, 0.2), [0.02 / (0.5 * math.sqrt(0.6 / 0.2 - 1.0)), 0.0]
    )


def test_a_fit_the_law_cannot_hold_is_an_error(fit) -> None:  # type: ignore[no-untyped-def]
    t = np.radians(DIRECTIONS)
    data = np.column_stack([0.1 * np.cos(t) + 0.15, 0.1 * np.sin(t)])  # beta outside
    outside = fit_anisotropy(DirectionalFriction(DIRECTIONS, data[:, 0], data[:, 1]))
    with pytest.raises(ParameterError) as info:
        fitted_law(cone(), outside)
    assert info.value.field == "rotation"
    with pytest.raises(ParameterError, match="scale"):
        fitted_law(cone(), fit, scale="lattice")
