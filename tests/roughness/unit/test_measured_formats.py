"""Measured maps in instrument formats, all written here with SurfaceTopography or NumPy.

* One map in x3p, NetCDF, Gwyddion (gwy), a text matrix and .npy gives the same heights
  and the same axis: ridges along y (heights vary with x only) give mu(0) > mu(90)
  in every format (the first array axis is x).
* Undefined points: refused with the TOML key to set, filled on request.
* Preparation: crop, window, filters (SurfaceTopography's), the edge-step warning, and
  bad values naming their key.
"""

from __future__ import annotations

import numpy as np
import pytest
from SurfaceTopography import Topography

from frictionlab.errors import InputError, ParameterError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.lattice import friction_polar
from frictionlab.roughness.topography import prepare_topography, read_prepared

NX, NY = 32, 24
SIZE_UM = (64.0, 48.0)


def ridges_um() -> np.ndarray:
    """Asymmetric ridges along y: heights vary with x only (plus a weak y ripple)."""
    x = (np.arange(NX)[:, None] + 0.5) / NX
    y = (np.arange(NY)[None, :] + 0.5) / NY
    return 6.0 * np.sin(2 * np.pi * x) + 1.8 * np.sin(4 * np.pi * x) + 0.1 * np.cos(2 * np.pi * y)


def write_all(tmp_path) -> dict[str, object]:
    h = ridges_um()
    topo = Topography(h, SIZE_UM, unit="um")
    paths: dict[str, object] = {}
    paths["x3p"] = tmp_path / "map.x3p"
    topo.to_x3p(str(paths["x3p"]))
    paths["nc"] = tmp_path / "map.nc"
    topo.to_netcdf(str(paths["nc"]))
    paths["gwy"] = tmp_path / "map.gwy"
    topo.to_gwy(str(paths["gwy"]))
    paths["txt"] = tmp_path / "map.txt"
    np.savetxt(paths["txt"], h.T)  # one file row per y (the documented text layout)
    paths["npy"] = tmp_path / "map.npy"
    np.save(paths["npy"], h)  # first index x
    return paths


def test_one_map_in_five_formats_same_heights_and_axes(tmp_path) -> None:
    expected = ridges_um() * 1e-6
    results = {}
    for fmt, path in write_all(tmp_path).items():
        kwargs = {}
        if fmt in ("txt", "npy"):  # no metadata in these files
            kwargs = {"unit": "um", "physical_sizes": SIZE_UM}
        prepared = read_prepared(path, periodicity="assume", detrend="none", **kwargs)
        s = prepared.surface
        assert s.heights.shape == (NX, NY), fmt
        np.testing.assert_allclose(s.heights, expected, rtol=1e-6, atol=1e-12, err_msg=fmt)
        assert s.physical_sizes == pytest.approx((64e-6, 48e-6), rel=1e-6), fmt
        assert len(prepared.info["sha256"]) == 64
        polar = friction_polar(s, gen.flat(), 0.3, [0.0, 90.0])
        results[fmt] = polar.mu
        assert polar.mu[0] > polar.mu[1] * 1.01, fmt  # sliding across the ridges: more friction
    for fmt, mu in results.items():
        np.testing.assert_allclose(mu, results["x3p"], rtol=1e-5, err_msg=fmt)


def test_undefined_points_name_the_key_and_fill(tmp_path) -> None:
    h = np.ma.masked_invalid(np.where(np.arange(NX)[:, None] == 5, np.nan, ridges_um()))
    path = tmp_path / "holes.x3p"
    Topography(h, SIZE_UM, unit="um").to_x3p(str(path))
    with pytest.raises(ParameterError, match=r"24 undefined points.*fill_missing = true"):
        read_prepared(path, periodicity="mirror", detrend="none")
    prepared = read_prepared(path, periodicity="mirror", detrend="none", fill_missing=True)
    assert prepared.info["filled_points"] == NY
    assert np.all(np.isfinite(prepared.surface.heights))
    # cropping the holes away works too
    cropped = read_prepared(
        path, periodicity="mirror", detrend="none", crop=(12e-6, 64e-6, 0, 48e-6)
    )
    assert cropped.info["cropped_points"] == [26, NY]
    assert cropped.info["filled_points"] == 0


def test_crop_window_filters_and_rms_after_filtering() -> None:
    topo = Topography(ridges_um(), SIZE_UM, unit="um")
    p = prepare_topography(topo, periodicity="assume", detrend="none", crop=(0, 32e-6, 0, 48e-6))
    assert p.surface.heights.shape == (16, NY)
    assert p.surface.physical_sizes == pytest.approx((32e-6, 48e-6), rel=1e-12)
    # the short cutoff keeps wavelengths >= 40 um: only the 64 um and 48 um modes
    f = prepare_topography(topo, periodicity="assume", detrend="center", short_cutoff=40e-6)
    x = (np.arange(NX)[:, None] + 0.5) / NX
    y = (np.arange(NY)[None, :] + 0.5) / NY
    kept = 6.0 * np.sin(2 * np.pi * x) + 0.1 * np.cos(2 * np.pi * y)
    np.testing.assert_allclose(f.surface.heights, kept * 1e-6, atol=1e-18)
    assert f.info["rms_height_m"] == pytest.approx(np.std(kept) * 1e-6, rel=1e-12)
    assert f.info["short_cutoff_m"] == 40e-6
    w = prepare_topography(topo, periodicity="assume", detrend="center", window="hann")
    assert abs(w.surface.heights[0, 0]) < 1e-9 * 1e-6 + abs(w.surface.heights).max() * 0.05
    assert w.info["window"] == "hann"


def test_assume_warns_about_a_steep_edge_step() -> None:
    x = (np.arange(NX)[:, None] + 0.5) / NX
    tilted = np.broadcast_to(5.0 * x, (NX, NY))  # a ramp: the wrap is one big step
    topo = Topography(tilted, SIZE_UM, unit="um")
    p = prepare_topography(topo, periodicity="assume", detrend="none")
    assert p.warnings and "edge" in p.warnings[0]
    assert p.info["edge_step_slope"]["edge"] > p.info["edge_step_slope"]["interior"]
    m = prepare_topography(topo, periodicity="mirror", detrend="none")
    assert m.warnings == ()


@pytest.mark.parametrize(
    ("kwargs", "key"),
    [
        ({"unit": "furlong", "physical_sizes": SIZE_UM}, "unit"),
        ({"unit": "um", "physical_sizes": (1.0, 2.0, 3.0)}, "physical_sizes"),
        ({"unit": "um", "physical_sizes": SIZE_UM, "crop": (0.0, 1.0)}, "crop"),
        ({"unit": "um", "physical_sizes": SIZE_UM, "short_cutoff": -1.0}, "short_cutoff"),
        ({"unit": "um", "physical_sizes": SIZE_UM, "window": "nonsense"}, "window"),
    ],
)
def test_bad_values_name_their_key(tmp_path, kwargs, key) -> None:
    path = tmp_path / "map.npy"
    np.save(path, ridges_um())
    with pytest.raises((ParameterError, InputError), match=rf"^{key} = "):
        read_prepared(path, periodicity="assume", detrend="none", **kwargs)


def test_shipped_demo_file_is_what_the_script_writes(tmp_path) -> None:
    from frictionlab.demo.topography_file import ground_demo_path, write_ground_demo

    shipped = ground_demo_path()
    assert shipped.is_file() and shipped.stat().st_size < 200_000
    fresh = write_ground_demo(tmp_path / "again.x3p")
    a = read_prepared(shipped, periodicity="assume", detrend="none").surface
    b = read_prepared(fresh, periodicity="assume", detrend="none").surface
    assert a.heights.shape == (128, 128)
    np.testing.assert_allclose(a.heights, b.heights, rtol=0, atol=1e-15)
    assert a.physical_sizes == pytest.approx((5e-4, 5e-4), rel=1e-12)
