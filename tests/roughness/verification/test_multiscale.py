"""Scale-resolved friction: spectral bands as hierarchy levels.

* One band (the cutoff beyond the surface size leaves only the mean above it): the
  all-bands row is the single-level full-contact result, the coarse row is mu0.
* Bands add up to the heights; a two-mode map splits exactly into its two modes, and
  the multiscale result equals the hierarchy of the two analytic modes computed by
  :func:`hierarchy_friction` (another recursion, analytic gradients).
* Self-similar wedge levels at beta = 90 deg reproduce Eqs 33 and 34.
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.closed_forms import (
    hierarchy_flat_on_wedge_90deg,
    hierarchy_wedge_on_wedge_90deg,
)
from frictionlab.roughness.lattice import friction_polar
from frictionlab.roughness.multiscale import band_surfaces, bands_hierarchy, multiscale_friction

BETAS = [0.0, 30.0, 45.0, 90.0, 200.0]


def rough_map(seed: int = 5):
    return gen.self_affine(
        0.8, [1e-4, 1e-4], [64, 64], rng=np.random.default_rng(seed), rms_slope=0.3
    )


def test_a_cutoff_beyond_the_period_is_refused() -> None:
    """1 m >> 0.1 mm would leave the outer band empty (only the mean): refused."""
    lower, upper = rough_map(5), rough_map(6)
    with pytest.raises(ParameterError, match="cutoffs"):
        multiscale_friction(lower, upper, 0.3, BETAS, [1.0])
    result = multiscale_friction(lower, upper, 0.3, BETAS, [1e-4])  # the period
    assert result.cutoff_m[-1] == pytest.approx(2 * 1e-4 / 64, rel=1e-12)  # Nyquist
    assert result.valid.all()


def two_mode_heights(n: int = 64, size: float = 1e-4) -> tuple[np.ndarray, ...]:
    x = (np.arange(n)[:, None] + 0.5) * size / n
    y = (np.arange(n)[None, :] + 0.5) * size / n
    k = 2 * np.pi / size
    coarse = 2e-6 * np.sin(k * x) * np.sin(k * y)
    fine = 0.25e-6 * np.sin(8 * k * x) * np.sin(8 * k * y)
    return coarse, fine


def test_bands_split_a_two_mode_map_exactly() -> None:
    coarse, fine = two_mode_heights()
    surface = gen.from_array(coarse + fine, [1e-4, 1e-4], gradient="spectral")
    bands = band_surfaces(surface, [1e-4 / 3])
    np.testing.assert_allclose(bands[0].heights, coarse, rtol=0, atol=1e-18)
    np.testing.assert_allclose(bands[1].heights, fine, rtol=0, atol=1e-18)
    three = band_surfaces(surface, [1e-4 / 2, 1e-4 / 5, 1e-4 / 20])
    np.testing.assert_allclose(sum(b.heights for b in three), surface.heights, atol=1e-18)


def test_multiscale_equals_the_recursion_over_the_analytic_modes() -> None:
    coarse, fine = two_mode_heights()
    lower = gen.from_array(coarse + fine, [1e-4, 1e-4], gradient="spectral")
    result = multiscale_friction(lower, gen.flat(), 0.3, BETAS, [1e-4 / 3])
    fine_mode = gen.sinusoid(0.25e-6, [1e-4 / 8, 1e-4 / 8])
    coarse_mode = gen.sinusoid(2e-6, [1e-4, 1e-4])
    # Eq 29 by hand, each level at the pixel centres of the 64 x 64 map (the fine mode's
    # cell holds 8 x 8 of them), analytic gradients, one direction at a time.
    for k, beta in enumerate(BETAS):
        inner = friction_polar(fine_mode, gen.flat(), 0.3, [beta], stations=(8, 8))
        outer = friction_polar(coarse_mode, gen.flat(), float(inner.mu[0]), [beta],
                               stations=(64, 64))  # fmt: skip
        assert result.mu[-1, k] == pytest.approx(float(outer.mu[0]), rel=1e-12)
        alone = friction_polar(coarse_mode, gen.flat(), 0.3, [beta], stations=(64, 64))
        assert result.mu[0, k] == pytest.approx(float(alone.mu[0]), rel=1e-12)
    assert np.all(result.mu[-1] > result.mu[0])  # the fine band adds friction


@pytest.mark.parametrize("phi", [10.0, 20.0])
def test_self_similar_wedge_levels_reproduce_eqs_33_34(phi) -> None:
    n = 4
    wedges = [gen.wedge((phi,), 1e-3 / 10**i) for i in range(n)][::-1]  # innermost first
    flat_rough = bands_hierarchy([(w, gen.flat()) for w in wedges], 0.3, [90.0])
    rough_rough = bands_hierarchy([(w, w) for w in wedges], 0.3, [90.0])
    assert flat_rough[0][0] == pytest.approx(hierarchy_flat_on_wedge_90deg(0.3, phi, n), rel=1e-12)
    assert rough_rough[0][0] == pytest.approx(
        hierarchy_wedge_on_wedge_90deg(0.3, phi, n), rel=1e-12
    )
