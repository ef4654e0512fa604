"""Directions on parallel threads give the serial loop's polar exactly."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ValidityError
from frictionlab.roughness import generators, lattice
from frictionlab.roughness.lattice import LatticeSettings, friction_polar


def _surface(slope: float):
    return generators.self_affine(
        0.8, (1e-3, 1e-3), (256, 256), rng=np.random.default_rng(3), rms_slope=slope
    )


def test_threaded_directions_equal_the_serial_loop(monkeypatch) -> None:
    surface = _surface(0.2)
    settings = LatticeSettings(load=0.5 * float(np.std(surface.heights)), time_samples=8)
    betas = [0.0, 30.0, 90.0]
    monkeypatch.setattr(lattice, "PARALLEL_MIN_STATIONS", 1 << 30)
    serial = friction_polar(surface, generators.flat(), 0.3, betas, settings=settings)
    monkeypatch.setattr(lattice, "PARALLEL_MIN_STATIONS", 1)
    monkeypatch.setattr(lattice.numba, "get_num_threads", lambda: 2)
    seen: list[tuple[int, int]] = []
    threaded = friction_polar(surface, generators.flat(), 0.3, betas, settings=settings,
                              progress=lambda d, t: seen.append((d, t)))  # fmt: skip
    assert seen == [(1, 3), (2, 3), (3, 3)]
    for name in ("mu_x", "mu_y", "mu_apparent", "contact_fraction_mean", "time_samples"):
        np.testing.assert_array_equal(getattr(threaded, name), getattr(serial, name), name)


def test_threaded_directions_raise_the_first_invalid_direction(monkeypatch) -> None:
    monkeypatch.setattr(lattice, "PARALLEL_MIN_STATIONS", 1)
    monkeypatch.setattr(lattice.numba, "get_num_threads", lambda: 2)
    steep = _surface(3.0)
    with pytest.raises(ValidityError, match="beta = 0"):
        friction_polar(steep, generators.flat(), 0.9, [0.0, 90.0], load=1e-7, time_samples=4)
