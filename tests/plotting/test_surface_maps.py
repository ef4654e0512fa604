"""Height maps are drawn as the scan itself, at equal aspect, on physical axes."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.plotting.roughness import mirrored_scans, plot_surface, scenario_figure
from frictionlab.roughness.generators import flat, from_array, sinusoid
from frictionlab.roughness.lattice import friction_polar
from frictionlab.roughness.topography import PreparedSurface, prepare_topography


def _scan(nx: int = 24, ny: int = 12) -> np.ndarray:
    rng = np.random.default_rng(5)
    return rng.normal(0.0, 1.0, (nx, ny))  # um; first index x


def _prepared(heights_um: np.ndarray, sizes_um: tuple[float, float]) -> PreparedSurface:
    from SurfaceTopography import Topography

    return prepare_topography(
        Topography(heights_um, sizes_um, unit="um"), periodicity="mirror", detrend="none"
    )


def test_a_mirrored_scan_is_drawn_once_at_its_own_size_and_equal_aspect() -> None:
    heights = _scan()
    prepared = _prepared(heights, (240.0, 120.0))
    assert prepared.surface.heights.shape == (48, 24)  # the model's surface is the double
    scans = mirrored_scans({"lower": prepared.info})
    ax = plot_surface(prepared.surface, scan=scans["lower"])
    (image,) = ax.get_images()
    x0, x1, y0, y1 = image.get_extent()
    assert (x0, x1, y0, y1) == pytest.approx((0.0, 240.0, 0.0, 120.0))  # um, the scan
    assert ax.get_xlabel() == "x [um]" and ax.get_ylabel() == "y [um]"
    assert ax.get_aspect() == 1.0
    # the pixels are the scan's heights (um), x along the image's columns
    np.testing.assert_allclose(np.asarray(image.get_array()), heights.T, rtol=0, atol=1e-12)


def test_the_demo_and_cli_figure_draw_the_scan_not_the_double() -> None:
    heights = _scan(16, 16)
    prepared = _prepared(heights, (100.0, 100.0))
    polar = friction_polar(prepared.surface, flat(), 0.3, np.array([0.0, 90.0]))
    fig = scenario_figure(
        polar, prepared.surface, flat(), scans=mirrored_scans({"lower": prepared.info})
    )
    (image,) = [im for ax in fig.axes for im in ax.get_images()]
    assert image.get_extent()[1] == pytest.approx(100.0)
    assert "the scan (mirrored for the model)" in image.axes.get_title()


def test_unmirrored_maps_keep_their_period_and_units_follow_the_scale() -> None:
    surface = from_array(np.random.default_rng(1).normal(0, 2e-9, (8, 16)), (4e-3, 8e-3))
    ax = plot_surface(surface)
    (image,) = ax.get_images()
    assert image.get_extent() == pytest.approx((0.0, 4.0, 0.0, 8.0))  # mm
    assert ax.get_aspect() == 1.0
    assert ax.figure.axes[-1].get_ylabel() == "z [nm]"  # the colour bar


def test_a_very_elongated_map_says_it_is_not_to_scale() -> None:
    ax = plot_surface(sinusoid(1e-6, (1e-3, 1e-5)), points=20)
    assert ax.get_aspect() == "auto"
    assert "not to scale" in ax.get_title()


def test_the_elastic_pressure_map_of_a_mirrored_scan_shows_the_scan(monkeypatch) -> None:
    from types import SimpleNamespace

    from frictionlab.app import roughness as app

    drawn = []
    monkeypatch.setattr(
        "frictionlab.plotting.roughness.figure_png_bytes", lambda fig: drawn.append(fig) or b""
    )
    pressure = np.arange(48 * 24, dtype=float).reshape(48, 24)  # the doubled grid
    polar = SimpleNamespace(
        states=[SimpleNamespace(pressure=pressure)],
        geometry=SimpleNamespace(cell=(480e-6, 240e-6), dimension=2),
        settings=SimpleNamespace(pressure=1e6),
        contact_fraction_mean=0.1,
    )
    app._pressure_png(polar, [240e-6, 120e-6])
    (image,) = drawn[0].axes[0].get_images()
    assert image.get_extent() == pytest.approx((0.0, 240.0, 0.0, 120.0))
    np.testing.assert_array_equal(np.asarray(image.get_array()), pressure[:24, :12].T / 1e6)
