"""Surface statistics against closed forms: a sinusoid's spectrum and slopes, a Gaussian
map's height distribution, a profile's directional slope."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.roughness import from_array, sinusoid
from frictionlab.roughness.statistics import surface_statistics

L = 1e-4


def _ridges(nx: int = 64, ny: int = 32, waves: int = 4, amp: float = 1e-7):
    x = (np.arange(nx) + 0.5) * L / nx
    return from_array(amp * np.sin(2 * np.pi * waves * x / L)[:, None] * np.ones((1, ny)),
                      (L, L / 2))  # fmt: skip


def test_sinusoid_spectrum_and_directional_slope() -> None:
    nx, waves, amp = 64, 4, 1e-7
    stats = surface_statistics(_ridges(nx, waves=waves, amp=amp), theta_deg=[0, 30, 60, 90])
    k = 2 * math.pi * waves / L
    q, c = stats.psd_x
    assert q[np.argmax(c)] == pytest.approx(k, rel=1e-12)
    assert stats.psd_y is not None and np.max(stats.psd_y[1]) < 1e-20 * np.max(c)
    # forward difference of SurfaceTopography: 2 sin(k d / 2) / d times amp / sqrt(2)
    d = L / nx
    rms = amp / math.sqrt(2) * 2 * math.sin(k * d / 2) / d
    expected = rms * np.abs(np.cos(np.radians([0, 30, 60, 90])))
    np.testing.assert_allclose(stats.rms_slope_theta, expected, rtol=1e-9, atol=1e-15)
    assert stats.rms_height == pytest.approx(amp / math.sqrt(2), rel=1e-12)
    assert stats.summary()["rms_slope_max_theta_deg"] == 0.0


def test_gaussian_heights_and_normalised_densities() -> None:
    rng = np.random.default_rng(0)
    sigma = 2e-8
    surface = from_array(sigma * rng.standard_normal((128, 128)), (L, L))
    stats = surface_statistics(surface, bins=40)
    peak = 1 / (sigma * math.sqrt(2 * math.pi))
    centre = np.interp(0.0, stats.height_bins, stats.height_density)
    assert centre == pytest.approx(peak, rel=0.1)
    for bins, dens in ((stats.height_bins, stats.height_density),
                       (stats.slope_bins, stats.slope_density_x)):  # fmt: skip
        assert np.sum(dens) * (bins[1] - bins[0]) == pytest.approx(1.0, rel=1e-9)
    assert stats.psd_isotropic is not None and stats.psd_isotropic[0].size > 5


def test_profile_statistics_and_tables() -> None:
    heights = 1e-8 * np.sin(np.linspace(0, 8 * np.pi, 256, endpoint=False))
    stats = surface_statistics(from_array(heights, L))
    assert stats.psd_y is None and stats.psd_isotropic is None
    assert stats.rms_slope_theta[18] == pytest.approx(0.0, abs=1e-15)  # 90 deg
    tables = stats.tables()
    assert set(tables) == {"psd_x", "rms_slope_direction", "height_distribution",
                           "slope_distribution"}  # fmt: skip


def test_analytic_surface_is_refused() -> None:
    with pytest.raises(ParameterError, match="surface"):
        surface_statistics(sinusoid(1e-6, [1e-4]))
