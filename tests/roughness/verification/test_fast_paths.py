"""The lattice's fast paths equal its slow paths.

* a flat counter-face is shift-invariant: one time sample gives the time-sampled average
  (whole-station shifts: a permutation of the same sums);
* the ergodic grid takes a divisor of the station count per axis (whole-station shifts).
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.roughness import flat, friction_polar, self_affine, sinusoid
from frictionlab.roughness.lattice import _ergodic_count


@pytest.fixture(scope="module")
def rough():
    return self_affine(0.8, (1e-4, 1e-4), (48, 48), rng=np.random.default_rng(5), rms_slope=0.3)


@pytest.mark.slow
@pytest.mark.parametrize("rough_below", [True, False])
def test_flat_counter_face_takes_one_sample(rough, rough_below: bool) -> None:
    lower, upper = (rough, flat()) if rough_below else (flat(), rough)
    betas = [0.0, 30.0, 90.0, 135.0]
    opts = dict(load=2e-7, time_samples=24)
    fast = friction_polar(lower, upper, 0.2, betas, **opts)
    slow = friction_polar(lower, upper, 0.2, betas, shift_invariance=False, **opts)
    assert set(fast.travel_mode) == {"invariant"}
    assert np.all(fast.time_samples == 1)
    assert np.all(slow.time_samples > 1)
    np.testing.assert_allclose(fast.mu_x, slow.mu_x, rtol=0, atol=1e-12)
    np.testing.assert_allclose(fast.mu_y, slow.mu_y, rtol=0, atol=1e-12)
    np.testing.assert_allclose(
        fast.contact_fraction_mean, slow.contact_fraction_mean, rtol=0, atol=1e-12
    )
    assert fast.mu_over_mu0.max() > 1.01  # a rough case, not a trivial one


def test_two_rough_surfaces_still_sample_the_path(rough) -> None:
    polar = friction_polar(rough, sinusoid(1e-6, [1e-4]), 0.2, [0.0], load=1e-7,
                           time_samples=8)  # fmt: skip
    assert polar.travel_mode[0] != "invariant" and polar.time_samples[0] > 1


@pytest.mark.parametrize(
    ("samples", "stations", "expected"),
    [(400, 1024, 16), (400, 1000, 20), (100, 64, 8), (400, 1021, 20), (36, 48, 6)],
)
def test_ergodic_grid_rounds_to_a_divisor(samples: int, stations: int, expected: int) -> None:
    """sqrt(samples) per axis, moved to the nearest divisor within a factor 2."""
    count = _ergodic_count(samples**0.5, stations)
    assert count == expected
    if stations % expected == 0:
        assert stations % count == 0


@pytest.mark.slow
def test_a_load_giving_full_contact_says_so(rough) -> None:
    """Every spring compressed: a note, one sample on a flat face, and the limit of a
    large load is the full-contact average (forces equal to first order in heights/L)."""
    h = np.asarray(rough.heights)
    span = float(h.max() - h.min())  # k_c = 1: this load compresses every spring
    betas = [0.0, 45.0, 90.0]
    big = friction_polar(rough, flat(), 0.2, betas, load=1e4 * span)
    assert np.all(big.contact_fraction_min == 1.0) and np.all(big.time_samples == 1)
    assert big.notes and "full contact" in big.notes[0] and "load = 'full'" in big.notes[0]
    full = friction_polar(rough, flat(), 0.2, betas, load="full")
    np.testing.assert_allclose(big.mu, full.mu, rtol=1e-3)
    partial = friction_polar(rough, flat(), 0.2, betas, load=1e-3 * span)
    assert partial.notes == () and partial.contact_fraction_min.max() < 1.0
