"""The compiled per-point helpers equal direct NumPy evaluations."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.subloading import (
    SubloadingParams,
    g_function,
    g_inverse,
    snap_back_violations,
    yield_function,
)
from frictionlab.subloading.state import ratio_of


@pytest.mark.parametrize("surface", ["cam_clay", "modified_cam_clay", "tear", "parabola"])
def test_closed_surface_snap_back_check_equals_the_grid_formula(surface: str) -> None:
    rng = np.random.default_rng(5)
    params = SubloadingParams(
        surface=surface, F_s=1.0, F_k=0.6, M=0.5, alpha_t=rng.uniform(0.05, 3.0, 200),
        kappa=20.0, m=1.5, tear_k=2.0,
    )  # fmt: skip
    fn = rng.uniform(0.01, 0.59, 200)
    grid = 0.6 + 0.4 * np.linspace(0.0, 1.0, 65)[None, :] + 0.0 * fn[:, None]
    chi = g_inverse(surface, grid / fn[:, None], 2.0)
    g = {"cam_clay": np.exp(chi), "modified_cam_clay": 2.0 * chi,
         "tear": 2 * (1 / 5) * 2.0 * chi * (1 - chi**2 / 5) ** -3.0,
         "parabola": 2.0 / (2.0 - chi) ** 2}[surface]  # fmt: skip
    bad = ~(params.alpha_t[:, None] * g / 0.5 > 20.0 * (grid / 0.6 - 1.0) ** 1.5)
    reasons = snap_back_violations(params, fn)
    expected = bad.any(axis=1)
    assert 0 < expected.sum() < fn.size  # both outcomes exercised
    np.testing.assert_array_equal([r != "" for r in reasons], expected)


def test_vectorised_surface_helpers_equal_closed_forms() -> None:
    rng = np.random.default_rng(1)
    chi = rng.uniform(0.0, 1.9, (7, 3))
    np.testing.assert_allclose(g_function("parabola", chi)[0], 2.0 / (2.0 - chi), rtol=1e-15)
    traction = np.column_stack([rng.normal(size=(50, 2)), rng.uniform(0.1, 0.5, 50)])
    w = np.hypot(traction[:, 0] / 0.5, traction[:, 1] / 0.5)
    expected = traction[:, 2] * (1.0 + (w / traction[:, 2]) ** 2)
    got = yield_function("modified_cam_clay", traction, axis_factors=(0.5, 0.5))
    np.testing.assert_allclose(got, expected, rtol=1e-14)
    params = SubloadingParams(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5)
    np.testing.assert_allclose(ratio_of(params, traction, np.full(50, 0.8)), expected / 0.8,
                               rtol=1e-14)  # fmt: skip
