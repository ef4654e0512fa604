"""The SurfaceTopography adapter: files written by the test itself (x3p, NetCDF, text)."""

from __future__ import annotations

import numpy as np
import pytest
from SurfaceTopography import Topography, UniformLineScan

from frictionlab.errors import InputError, ParameterError
from frictionlab.roughness.surface import SampledHeightMap, SampledProfile
from frictionlab.roughness.topography import from_topography, read_surface

NX, NY = 24, 16
SIZE_UM = (48.0, 32.0)


def wave_um() -> np.ndarray:
    x = np.arange(NX)[:, None] / NX
    y = np.arange(NY)[None, :] / NY
    return 0.5 * np.sin(2 * np.pi * x) * np.cos(2 * np.pi * y)  # micrometres


@pytest.fixture
def x3p_file(tmp_path):
    path = tmp_path / "wave.x3p"
    Topography(wave_um(), SIZE_UM, unit="um").to_x3p(str(path))
    return path


def test_x3p_to_si_heightmap(x3p_file) -> None:
    s = read_surface(x3p_file, periodicity="assume", detrend="center")
    assert isinstance(s, SampledHeightMap)
    assert s.physical_sizes == pytest.approx((48e-6, 32e-6), rel=1e-12)
    expected = (wave_um() - wave_um().mean()) * 1e-6
    np.testing.assert_allclose(s.heights, expected, rtol=0, atol=1e-18)
    # the gradient of the sampled sine is close to the analytic one (fd, 24 points)
    gx, _ = s.gradients
    x = np.arange(NX)[:, None] / NX
    analytic = (
        0.5 * 2 * np.pi / 48.0 * np.cos(2 * np.pi * x) * np.cos(2 * np.pi * np.arange(NY) / NY)
    )
    np.testing.assert_allclose(gx, analytic, rtol=0, atol=0.02 * np.max(np.abs(analytic)))


def test_periodicity_must_be_declared_for_require(x3p_file, tmp_path) -> None:
    with pytest.raises(InputError, match="periodicity"):
        read_surface(x3p_file, periodicity="require", detrend="none")
    nc = tmp_path / "wave.nc"
    Topography(wave_um(), SIZE_UM, unit="um", periodic=True).to_netcdf(str(nc))
    s = read_surface(nc, periodicity="require", detrend="none")
    assert s.heights.shape == (NX, NY)
    with pytest.raises(InputError, match="breaks periodicity"):
        read_surface(nc, periodicity="require", detrend="height")


def test_mirror_doubles_and_is_continuous(x3p_file) -> None:
    s = read_surface(x3p_file, periodicity="mirror", detrend="none")
    assert s.heights.shape == (2 * NX, 2 * NY)
    assert s.physical_sizes == pytest.approx((96e-6, 64e-6), rel=1e-12)
    np.testing.assert_array_equal(s.heights[:NX, :NY], wave_um() * 1e-6)
    np.testing.assert_array_equal(s.heights[NX:, :NY], (wave_um() * 1e-6)[::-1, :])


def test_detrend_height_removes_a_tilt(tmp_path) -> None:
    path = tmp_path / "tilted.x3p"
    x = np.arange(NX)[:, None] / NX
    tilted = wave_um() + 3.0 * x + 0.0 * np.arange(NY)[None, :]
    Topography(tilted, SIZE_UM, unit="um").to_x3p(str(path))
    s = read_surface(path, periodicity="assume", detrend="height")
    plain = read_surface(path, periodicity="assume", detrend="none")
    assert np.ptp(plain.heights) > 2.5e-6
    assert np.ptp(s.heights) < 1.2e-6  # the sine remains (peak to valley 1 um)


def test_missing_data(tmp_path) -> None:
    path = tmp_path / "holes.x3p"
    h = wave_um()
    h[3, 4] = np.nan
    h[10, 2] = np.nan
    Topography(np.ma.masked_invalid(h), SIZE_UM, unit="um").to_x3p(str(path))
    with pytest.raises(InputError, match=r"2 undefined.*fill_missing = true"):
        read_surface(path, periodicity="assume", detrend="center")
    s = read_surface(path, periodicity="assume", detrend="center", fill_missing=True)
    assert np.all(np.isfinite(s.heights))
    ref = (wave_um() - np.nanmean(h)) * 1e-6
    assert s.heights[3, 4] == pytest.approx(ref[3, 4], abs=0.1e-6)


def test_line_scan_from_text(tmp_path) -> None:
    path = tmp_path / "scan.txt"
    z = np.sin(2 * np.pi * np.arange(32) / 32)
    UniformLineScan(z, 2.0, unit="mm").to_matrix(str(path))
    s = read_surface(path, periodicity="assume", detrend="none")
    assert isinstance(s, SampledProfile)
    assert s.length == pytest.approx(2e-3, rel=1e-12)
    np.testing.assert_allclose(s.heights, z * 1e-3, rtol=1e-12, atol=1e-18)


def test_unreadable_files(tmp_path) -> None:
    with pytest.raises(InputError, match="no such file"):
        read_surface(tmp_path / "absent.x3p", periodicity="assume", detrend="none")
    junk = tmp_path / "junk.sur"
    junk.write_bytes(b"\x00\x01 definitely not a topography \xff" * 3)
    with pytest.raises(InputError, match="cannot read surface file"):
        read_surface(junk, periodicity="assume", detrend="none")


def test_from_topography_checks() -> None:
    t = Topography(wave_um(), SIZE_UM)  # no unit
    with pytest.raises(ParameterError, match="unit"):
        from_topography(t, periodicity="assume", detrend="none")
    t = Topography(wave_um(), SIZE_UM, unit="um")
    with pytest.raises(ParameterError, match="periodicity"):
        from_topography(t, periodicity="maybe", detrend="none")
    with pytest.raises(ParameterError, match="detrend"):
        from_topography(t, periodicity="assume", detrend="quartic")
    with pytest.raises(ParameterError, match="topography"):
        from_topography(np.zeros((4, 4)), periodicity="assume", detrend="none")
    with pytest.raises(TypeError):
        from_topography(t)  # type: ignore[call-arg]  # the decisions are required
