"""The lattice (both engines) against the independent per-spring reference loop.

Tiny lattices (at most 48 stations, 16 time samples) so the plain-Python reference stays
fast; agreement is to rounding (rtol 1e-10). The time samples are used as given (no
snapping) and full contact is time-sampled too, as the reference does.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.roughness import generators as gen
from frictionlab.roughness import lattice

from ..reference import reference_friction


def friction_polar(*args, **options):
    """The time-sampled lattice with exactly the requested samples (the reference's)."""
    options.setdefault("snap_time_samples", False)
    options.setdefault("full_contact", "lattice")
    return lattice.friction_polar(*args, **options)


ENGINES = ("numba", "numpy")


def compare(polar, expected: dict[str, float], apparent: bool = False) -> None:
    assert float(polar.mu_x[0]) == pytest.approx(expected["mu_x"], rel=1e-10, abs=1e-13)
    assert float(polar.mu_y[0]) == pytest.approx(expected["mu_y"], rel=1e-10, abs=1e-13)
    if apparent:
        assert float(polar.mu_apparent[0]) == pytest.approx(expected["mu_apparent"], rel=1e-10)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("load", ["full", 0.01, 0.002])
def test_1d_wedge_on_sinusoid(engine, load) -> None:
    lower = gen.wedge((30.0, 15.0), 1.0)
    upper = gen.sinusoid(0.05, 0.5)
    n, nt, beta = 40, 16, 30.0
    polar = friction_polar(
        lower, upper, 0.3, [beta], load=load, stations=n, time_samples=nt, engine=engine
    )
    xs = [(i + 0.5) / n for i in range(n)]
    shifts = [(j / nt, j / nt * math.tan(math.radians(beta))) for j in range(nt)]
    compare(polar, reference_friction(lower, upper, 0.3, beta, xs, [0.0], shifts, load))
    assert polar.travel_mode == ("return",)
    assert polar.travel_m[0] == pytest.approx(1.0 / math.cos(math.radians(beta)), rel=1e-14)


@pytest.mark.parametrize("engine", ENGINES)
def test_1d_reversed_direction_and_phase(engine) -> None:
    lower = gen.sinusoid(0.1, 1.0)
    upper = gen.wedge((20.0, 35.0), 1.0)
    n, nt, beta, phase = 30, 12, 160.0, (0.13, 0.0)
    polar = friction_polar(
        lower, upper, 0.25, [beta], load=0.02, stations=n, time_samples=nt, engine=engine,
        phase=phase,
    )  # fmt: skip
    xs = [(i + 0.5) / n for i in range(n)]
    shifts = [(0.13 - j / nt, 0.0) for j in range(nt)]  # cos(beta) < 0: backwards along x
    compare(polar, reference_friction(lower, upper, 0.25, beta, xs, [0.0], shifts, 0.02))


@pytest.mark.parametrize("engine", ENGINES)
def test_1d_separation_control_and_tensile_springs(engine) -> None:
    lower = gen.sinusoid(0.1, 1.0)
    upper = gen.sinusoid(0.1, 1.0)
    n, nt, beta = 24, 10, 0.0
    xs = [(i + 0.5) / n for i in range(n)]
    shifts = [(j / nt, 0.0) for j in range(nt)]
    polar = friction_polar(
        lower, upper, 0.3, [beta], control="separation", separation=0.05, stations=n,
        time_samples=nt, engine=engine, k_t=0.5,
    )  # fmt: skip
    expected = reference_friction(
        lower, upper, 0.3, beta, xs, [0.0], shifts, 0.0, kt=0.5, separation=0.05
    )
    compare(polar, expected, apparent=True)
    polar = friction_polar(
        lower, upper, 0.3, [beta], load=0.01, stations=n, time_samples=nt, engine=engine, k_t=0.5
    )
    expected = reference_friction(lower, upper, 0.3, beta, xs, [0.0], shifts, 0.01, kt=0.5)
    compare(polar, expected, apparent=True)
    assert polar.tensile_fraction_max[0] > 0.0


@pytest.mark.parametrize("engine", ENGINES)
def test_2d_product_sinusoids_straight_path(engine) -> None:
    lower = gen.sinusoid(0.1, [1.0, 1.0])
    upper = gen.sinusoid(0.08, [1.0, 2.0])
    nx, ny, nt, beta, travel = 6, 8, 7, 30.0, 1.7
    polar = friction_polar(
        lower, upper, 0.3, [beta], load=0.02, stations=(nx, ny), time_samples=nt,
        travel=travel, engine=engine,
    )  # fmt: skip
    xs = [(i + 0.5) / nx for i in range(nx)]
    ys = [(k + 0.5) * 2.0 / ny for k in range(ny)]
    b = math.radians(beta)
    shifts = [(j / nt * travel * math.cos(b), j / nt * travel * math.sin(b)) for j in range(nt)]
    compare(polar, reference_friction(lower, upper, 0.3, beta, xs, ys, shifts, 0.02))
    assert polar.travel_mode == ("explicit",)


@pytest.mark.parametrize("engine", ENGINES)
def test_2d_whole_station_return_path(engine) -> None:
    # beta = 0 on an 8 x 8 lattice with 8 samples: every shift is one station spacing,
    # the kernel reuses the upper surface rolled by whole stations.
    lower = gen.sinusoid(0.1, [1.0, 1.0])
    upper = gen.sinusoid(0.1, [1.0, 1.0])
    n, nt = 8, 8
    polar = friction_polar(
        lower, upper, 0.3, [0.0, 90.0], load=0.05, stations=n, time_samples=nt, engine=engine,
        phase=(0.25, 0.0),
    )  # fmt: skip
    assert polar.travel_mode == ("return", "return")
    xs = [(i + 0.5) / n for i in range(n)]
    for k, beta in enumerate((0.0, 90.0)):
        b = math.radians(beta)
        shifts = [
            (0.25 + j / nt * round(math.cos(b)), j / nt * round(math.sin(b))) for j in range(nt)
        ]
        expected = reference_friction(lower, upper, 0.3, beta, xs, xs, shifts, 0.05)
        assert float(polar.mu_x[k]) == pytest.approx(expected["mu_x"], rel=1e-10, abs=1e-13)
        assert float(polar.mu_y[k]) == pytest.approx(expected["mu_y"], rel=1e-10, abs=1e-13)


@pytest.mark.parametrize("engine", ENGINES)
def test_2d_sampled_surfaces_interpolated(engine) -> None:
    rng = np.random.default_rng(7)
    lower = gen.self_affine(0.8, (1.0, 1.0), (16, 16), rng=rng, rms_slope=0.3)
    upper = gen.self_affine(0.8, (1.0, 1.0), (16, 16), rng=rng, rms_slope=0.3)
    nt, beta, travel = 9, 20.0, 0.77
    polar = friction_polar(
        lower, upper, 0.3, [beta], load=0.01, stations=(5, 6), time_samples=nt, travel=travel,
        engine=engine,
    )  # fmt: skip
    xs = [(i + 0.5) / 5 for i in range(5)]
    ys = [(k + 0.5) / 6 for k in range(6)]
    b = math.radians(beta)
    shifts = [(j / nt * travel * math.cos(b), j / nt * travel * math.sin(b)) for j in range(nt)]
    compare(polar, reference_friction(lower, upper, 0.3, beta, xs, ys, shifts, 0.01))
