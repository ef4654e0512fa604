"""Archard wear (spec 3.6, Eqs 23-28w; scenarios T5, T6; property 14).

Expected values: hand arithmetic of Archard's law, the wedge closed forms (Eqs 17-20) at
the worn angle arctan(B tan phi0), midpoint quadratures of the frame-free multiplier for
2-D surfaces, and the limits B = 1 and B = 0.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.errors import ParameterError
from frictionlab.roughness import closed_forms as cf
from frictionlab.roughness import generators as gen
from frictionlab.roughness.lattice import LatticeSettings
from frictionlab.roughness.wear import (
    WearSettings,
    archard_volume,
    mean_height_above_valley,
    reduction_coefficient,
    roughness_volume,
    wear_history,
    wear_time,
    wedge_tan_phi,
    wedge_tan_phi_rate,
    worn_pair,
)

WEAR = WearSettings(
    wear_coefficient=1e-4, hardness=2e9, normal_load=100.0, velocity=0.1, nominal_area=1e-4
)
TWO_PI = 2.0 * math.pi


def test_archard_law_and_rates() -> None:
    # V = K L s / H: 1e-3 * 10 N * 2 m / 1e9 Pa = 2e-11 m^3
    assert float(archard_volume(1e-3, 10.0, 2.0, 1e9)) == pytest.approx(2e-11, rel=1e-15)
    assert WEAR.wear_rate == pytest.approx(1e-4 * 100.0 / 2e9, rel=1e-15)
    assert WEAR.volume_rate == pytest.approx(5e-13, rel=1e-15)
    assert wear_time(1e-9, 5e-13) == pytest.approx(2000.0, rel=1e-15)


def test_reduction_coefficient_is_linear_then_zero() -> None:
    b = reduction_coefficient([0.0, 25.0, 50.0, 100.0, 150.0], 100.0)
    np.testing.assert_allclose(b, [1.0, 0.75, 0.5, 0.0, 0.0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        wedge_tan_phi(math.tan(math.radians(30.0)), [0.0, 50.0], 100.0),
        [math.tan(math.radians(30.0)), 0.5 * math.tan(math.radians(30.0))],
        rtol=1e-15,
    )


def test_rate_form_of_eq_28w_integrates_to_the_wear_time() -> None:
    # N symmetric wedges of base b (faces S1 = b/2) over depth Y share W v on 2N faces.
    n, b, y, phi0 = 5, 2e-4, 3e-3, 25.0
    surface = gen.wedge(phi0, b)
    volume = roughness_volume(surface, nominal_area=n * b * y)
    assert volume == pytest.approx(n * y * b * b * math.tan(math.radians(phi0)) / 4, rel=1e-13)
    tw = wear_time(volume, WEAR.volume_rate)
    rate = wedge_tan_phi_rate(WEAR.volume_rate / (2 * n), b / 2, y)
    assert -math.tan(math.radians(phi0)) / rate == pytest.approx(tw, rel=1e-13)


def test_mean_heights_against_midpoint_grids() -> None:
    x = (np.arange(200000) + 0.5) / 200000
    for surface in (
        gen.wedge((30.0, 15.0), 1.0),
        gen.smooth_wedge((40.0, 10.0), 1.0),
        gen.sinusoid(0.2, 1.0),
        gen.scaled(gen.from_function(lambda s: np.sin(TWO_PI * s) ** 3, lambda s: 0 * s, 1.0), 0.5),
    ):
        z, _, _ = surface.evaluate(x)
        expected = float(np.mean(z) - np.min(z))
        assert mean_height_above_valley(surface) == pytest.approx(expected, rel=2e-4)
    assert mean_height_above_valley(gen.sinusoid(0.3, [1.0, 2.0])) == 0.3
    sampled = gen.from_array(np.array([0.0, 2.0, 1.0, 5.0]), 1.0)
    assert mean_height_above_valley(sampled) == pytest.approx(2.0, rel=1e-15)
    assert mean_height_above_valley(gen.flat()) == 0.0


@pytest.mark.parametrize(("upper_flat", "exact"), [(True, cf.flat_on_wedge_0deg), (False, None)])
def test_wedge_wear_t5(upper_flat, exact) -> None:
    # T5: tan(phi) = B tan(30 deg); mu(t) from the unworn value down to mu0 at T_w.
    lower = gen.wedge(30.0, 1e-3)
    upper = gen.flat() if upper_flat else gen.wedge(30.0, 1e-3)
    history = wear_history(lower, upper, 0.3, [0.0, 45.0, 90.0], WEAR, samples=5)
    assert history.method == "closed_form"
    np.testing.assert_allclose(history.time / history.wear_time, [0, 0.25, 0.5, 0.75, 1.0])
    surfaces = 1 if upper_flat else 2
    expected_tw = surfaces * WEAR.nominal_area * lower.height / 2 / WEAR.volume_rate
    assert history.wear_time == pytest.approx(expected_tw, rel=1e-13)
    phi = np.degrees(np.arctan(history.reduction * math.tan(math.radians(30.0))))
    closed_0 = exact(0.3, phi) if exact else cf.wedge_on_wedge_0deg(0.3, phi)
    at_90 = cf.flat_on_wedge_90deg if upper_flat else cf.wedge_on_wedge_90deg
    closed_90 = at_90(0.3, phi)
    np.testing.assert_allclose(history.mu[:, 0], closed_0, rtol=1e-13)
    np.testing.assert_allclose(history.mu[:, 2], closed_90, rtol=1e-13)
    assert np.all(np.diff(history.mu, axis=0) < 0.0)  # strictly decreasing while rough
    np.testing.assert_allclose(history.mu[-1], 0.3, rtol=1e-15)  # exactly mu0 at T_w
    # the decrease is not linear in t: mu - mu0 ~ B^2 slope^2 for small slopes
    excess = history.mu[:, 0] - 0.3
    assert excess[2] < 0.5 * excess[0]


def test_lattice_and_closed_form_agree_for_wedges() -> None:
    lower, upper = gen.wedge((30.0, 15.0), 1.0), gen.wedge(20.0, 1.0)
    kw = {"samples": 3, "settings": LatticeSettings(stations=8000, time_samples=20)}
    closed = wear_history(lower, upper, 0.3, [0.0, 60.0], WEAR, **kw)
    lattice = wear_history(lower, upper, 0.3, [0.0, 60.0], WEAR, method="lattice", **kw)
    assert lattice.method == "lattice"
    np.testing.assert_allclose(lattice.mu, closed.mu, rtol=0, atol=2e-4)


def test_2d_symmetric_surface_t6() -> None:
    # T6: A(t) = B A0 on identical sin x sin y surfaces, full contact: the area average of
    # H at slope scale B, by an independent midpoint grid of the frame-free multiplier.
    s = gen.sinusoid(1.0, [TWO_PI, TWO_PI])
    settings = LatticeSettings(stations=48, time_samples=16)
    history = wear_history(s, s, 0.3, [0.0, 30.0], WEAR, samples=5, settings=settings)
    assert history.method == "lattice"
    assert history.wear_time == pytest.approx(2 * 1e-4 * 1.0 / 5e-13, rel=1e-13)  # <z-zmin> = A
    n = 48
    x = (np.arange(n) + 0.5) * TWO_PI / n
    for k, b in enumerate(history.reduction):
        gx = b * np.cos(x)[:, None] * np.sin(x)[None, :]
        gy = b * np.sin(x)[:, None] * np.cos(x)[None, :]
        hx, hy = cf.h_global(0.3, gx, gy, math.radians(30.0))
        assert history.mu[k, 1] == pytest.approx(math.hypot(hx.mean(), hy.mean()), rel=1e-10)
    assert np.all(np.diff(history.mu, axis=0) < 0.0)
    np.testing.assert_allclose(history.mu[-1], 0.3, rtol=1e-14)
    assert np.ptp(history.mu[0]) < 0.01 * history.mu[0, 0]  # weak beta dependence in 2-D


def test_which_surfaces_wear() -> None:
    w = gen.wedge(30.0, 1e-3)
    both = wear_history(w, w, 0.3, [0.0], WEAR, samples=3)
    only_lower = WearSettings(**{**_kw(), "surfaces": "lower"})
    lower = wear_history(w, w, 0.3, [0.0], only_lower, samples=3)
    assert lower.wear_time == pytest.approx(0.5 * both.wear_time, rel=1e-14)
    # only the lower surface is flat at T_w: a flat surface on the unworn wedge (Eq 17)
    assert lower.mu[-1, 0] == pytest.approx(float(cf.flat_on_wedge_0deg(0.3, 30.0)), rel=1e-13)
    lo, up = worn_pair(w, w, 0.5, "upper")
    assert lo is w and up.angles_deg[0] == pytest.approx(
        math.degrees(math.atan(0.5 * math.tan(math.radians(30.0)))), rel=1e-14
    )
    with pytest.raises(ParameterError, match="surfaces"):  # the upper surface is flat
        wear_history(w, gen.flat(), 0.3, [0.0], WearSettings(**{**_kw(), "surfaces": "upper"}))


def _kw() -> dict[str, float]:
    return {
        "wear_coefficient": 1e-4,
        "hardness": 2e9,
        "normal_load": 100.0,
        "velocity": 0.1,
        "nominal_area": 1e-4,
    }


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("wear_coefficient", -1e-4),
        ("wear_coefficient", 0.0),
        ("hardness", 0.0),
        ("normal_load", -1.0),
        ("velocity", math.inf),
        ("nominal_area", 0.0),
        ("surfaces", "middle"),
    ],
)
def test_bad_wear_settings(field, value) -> None:
    with pytest.raises(ParameterError, match=field):
        WearSettings(**{**_kw(), field: value})


def test_bad_history_arguments() -> None:
    w = gen.wedge(30.0, 1e-3)
    with pytest.raises(ParameterError, match="method"):
        wear_history(gen.sinusoid(1e-4, 1e-3), w, 0.3, [0.0], WEAR, method="closed_form")
    with pytest.raises(ParameterError, match="times"):
        wear_history(w, w, 0.3, [0.0], WEAR, times=[-1.0])
    with pytest.raises(ParameterError, match="samples"):
        wear_history(w, w, 0.3, [0.0], WEAR, samples=1)
    with pytest.raises(ParameterError, match="surfaces"):  # nothing rough to wear
        wear_history(gen.flat(), gen.flat(), 0.3, [0.0], WEAR)
