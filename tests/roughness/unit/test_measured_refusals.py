"""Measured maps the user can trust: each refusal and warning of the preparation.

Every test builds its own small topography; each fails on the code before these checks
(the cutoffs, the flattening and the window passed silently, a non-uniform scan had no
key to resample it, a large fill was only a count).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.signal import get_window
from SurfaceTopography import NonuniformLineScan, Topography

from frictionlab.errors import ParameterError
from frictionlab.roughness import from_array, self_affine
from frictionlab.roughness.multiscale import band_surfaces
from frictionlab.roughness.topography import prepare_topography, read_prepared

L_UM = 10.0  # scan size in um
N = 64


def _map(nx: int = N, ny: int = N, ly: float = L_UM, seed: int = 1) -> np.ndarray:
    rng = np.random.default_rng(seed)
    x = np.arange(nx)[:, None] / nx
    y = np.arange(ny)[None, :] / ny
    return 0.05 * np.sin(2 * np.pi * 4 * x) * np.cos(
        2 * np.pi * 3 * y
    ) + 0.01 * rng.standard_normal((nx, ny))


def _topo(heights: np.ndarray, sizes: tuple[float, float] = (L_UM, L_UM)) -> Topography:
    return Topography(heights, sizes, unit="um", periodic=False)


def _prepare(topo, **kw):
    return prepare_topography(topo, periodicity="assume", detrend="center", **kw)


@pytest.mark.parametrize(
    ("key", "value"),
    [("short_cutoff", 2e-7), ("short_cutoff", 2e-5), ("long_cutoff", 1e-7), ("long_cutoff", 5e-5)],
)
def test_cutoff_outside_the_resolvable_range_is_refused(key: str, value: float) -> None:
    # pixel 10 um / 64 = 0.156 um: resolvable 0.3125 um to 10 um
    with pytest.raises(ParameterError, match=key) as info:
        _prepare(_topo(_map()), **{key: value})
    text = str(info.value)
    assert "3.125e-07 m" in text and "1e-05 m" in text


def test_cutoff_inside_the_range_is_kept() -> None:
    prepared = _prepare(_topo(_map()), short_cutoff=1e-6, long_cutoff=8e-6)
    assert prepared.info["short_cutoff_m"] == 1e-6
    assert 0.01 < prepared.info["rms_kept"]["height"] < 1.0


def test_multiscale_cutoff_longer_than_the_scan_is_refused() -> None:
    surface = self_affine(0.8, (5e-7, 5e-7), (32, 32), rng=np.random.default_rng(2),
                          rms_height=1e-9)  # fmt: skip
    with pytest.raises(ParameterError, match=r"cutoffs.*resolvable range") as info:
        band_surfaces(surface, [1e-6, 1e-7])
    assert "1e-06" in str(info.value)
    assert len(band_surfaces(surface, [2e-7, 1e-7])) == 3


def test_flattening_below_one_percent_is_refused_unless_allowed() -> None:
    x = np.arange(N) / N
    heights = 0.05 * np.sin(2 * np.pi * 16 * x)[:, None] * np.ones((1, N))  # wavelength L/16
    with pytest.raises(ParameterError, match="allow_flattening") as info:
        _prepare(_topo(heights), short_cutoff=4e-6)  # keeps >= 4 um: nothing of L/16
    assert "rms height" in str(info.value) and "rms slope" in str(info.value)
    prepared = _prepare(_topo(heights), short_cutoff=4e-6, allow_flattening=True)
    assert any("allow_flattening" in w for w in prepared.warnings)
    assert prepared.info["rms_kept"]["height"] < 0.01


def test_large_fill_fraction_warns() -> None:
    heights = _map()
    mask = np.zeros(heights.shape, dtype=bool)
    mask[:10, :] = True  # 15.6 % undefined
    filled = _prepare(_topo(np.ma.masked_array(heights, mask)), fill_missing=True)
    assert filled.info["filled_fraction"] == pytest.approx(10 / 64)
    assert any("15.6 %" in w and "fill_missing" in w for w in filled.warnings)
    mask[5:, :] = False  # 7.8 %: no warning
    small = _prepare(_topo(np.ma.masked_array(heights, mask)), fill_missing=True)
    assert not any("fill_missing" in w for w in small.warnings)


def test_fill_warning_counts_isolated_measured_points() -> None:
    """frt-2's case: measured pixels alone inside a gap become cones once filled."""
    heights = _map()
    mask = np.zeros(heights.shape, dtype=bool)
    mask[:16, :] = True  # 25 % undefined
    lone = [(3, 5), (8, 20), (12, 40)]
    for i, j in lone:
        mask[i, j] = False  # measured, every neighbour missing
    mask[5, 50] = mask[5, 51] = False  # a measured pair: not alone
    filled = _prepare(_topo(np.ma.masked_array(heights, mask)), fill_missing=True)
    assert filled.info["isolated_measured_points"] == len(lone)
    assert any("3 measured points stand alone" in w and "cones" in w for w in filled.warnings)


def test_window_on_a_non_square_map_is_separable() -> None:
    nx, ny = 64, 16
    heights = _map(nx, ny)
    prepared = _prepare(_topo(heights, (L_UM, L_UM / 4)), window="hann")
    wx = get_window("hann", nx)
    wy = get_window("hann", ny)
    wx *= math.sqrt(nx / (wx**2).sum())
    wy *= math.sqrt(ny / (wy**2).sum())
    expected = (heights - heights.mean()) * wx[:, None] * wy[None, :] * 1e-6
    np.testing.assert_allclose(prepared.surface.heights, expected, rtol=0, atol=1e-15)
    assert prepared.info["window_shape"] == "separable"
    # a radial window zeroes the points outside its circle; this one only the edge rows
    zero = np.mean(np.abs(prepared.surface.heights) == 0.0)
    assert zero <= (nx + ny) / (nx * ny)


def _nonuniform() -> NonuniformLineScan:
    rng = np.random.default_rng(4)
    x = np.sort(rng.uniform(0.0, 100.0, 400))
    return NonuniformLineScan(x, np.sin(2 * np.pi * x / 25.0), unit="um")


def test_non_uniform_line_scan_is_refused_naming_resample() -> None:
    with pytest.raises(ParameterError, match="resample = None") as info:
        _prepare(_nonuniform())
    assert "median" in str(info.value)
    with pytest.raises(ParameterError, match="resample"):
        _prepare(_nonuniform(), resample="cubic")


@pytest.mark.parametrize("resample", ["median", "finest", 500])
def test_non_uniform_line_scan_is_resampled(resample) -> None:
    scan = _nonuniform()
    prepared = _prepare(scan, resample=resample)
    info = prepared.info["resampled"]
    assert info["source_points"] == 400
    x = np.asarray(scan.positions())
    if resample == 500:
        assert info["points"] == 500
    elif resample == "median":
        assert info["points"] == pytest.approx((x[-1] - x[0]) / np.median(np.diff(x)), abs=2)
    # the resampled heights follow the sine (linear interpolation between the points)
    h = np.asarray(prepared.surface.heights) / 1e-6
    assert np.ptp(h) == pytest.approx(2.0, abs=0.05)


def test_file_keys_reach_the_preparation(tmp_path) -> None:
    heights = _map()
    path = tmp_path / "map.npy"
    np.save(path, heights)
    with pytest.raises(ParameterError, match="short_cutoff"):
        read_prepared(path, periodicity="assume", detrend="center", unit="um",
                      physical_sizes=(L_UM, L_UM), short_cutoff=1e-9)  # fmt: skip
    ok = read_prepared(path, periodicity="assume", detrend="center", unit="um",
                       physical_sizes=(L_UM, L_UM), window="hann")  # fmt: skip
    assert ok.info["window_shape"] == "radial"
    assert from_array(np.zeros(4), 1.0).is_flat
