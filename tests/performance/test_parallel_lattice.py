"""Time samples computed in blocks on threads give the same polar for any thread count."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ValidityError
from frictionlab.roughness import generators, lattice
from frictionlab.roughness.lattice import LatticeSettings, friction_polar

FIELDS = ("mu_x", "mu_y", "mu_apparent", "contact_fraction_mean", "tensile_fraction_mean")


def _surface(slope: float, seed: int = 3):
    return generators.self_affine(
        0.8, (1e-3, 1e-3), (128, 128), rng=np.random.default_rng(seed), rms_slope=slope
    )


def _polar(monkeypatch, threads: int, min_stations: int, **options):
    surface = _surface(0.2)
    settings = LatticeSettings(load=0.5 * float(np.std(surface.heights)), time_samples=12,
                               **options)  # fmt: skip
    monkeypatch.setattr(lattice, "PARALLEL_MIN_STATIONS", min_stations)
    monkeypatch.setattr(lattice.numba, "get_num_threads", lambda: threads)
    seen: list[tuple[int, int]] = []
    polar = friction_polar(
        surface, _surface(0.1, seed=5), 0.3, [0.0, 30.0, 90.0], settings=settings,
        progress=lambda d, t: seen.append((d, t)),
    )  # fmt: skip
    assert seen == [(1, 3), (2, 3), (3, 3)]
    return polar


@pytest.mark.parametrize("options", [{}, {"k_t": 0.5}, {"k_t": 0.5, "detachment": 1e-6}])
def test_blocks_on_threads_equal_one_thread_exactly(monkeypatch, options) -> None:
    one = _polar(monkeypatch, 1, 1, **options)
    three = _polar(monkeypatch, 3, 1, **options)
    for name in (*FIELDS, "time_samples"):
        np.testing.assert_array_equal(getattr(three, name), getattr(one, name), name)


def test_blocks_equal_the_single_warm_started_chain(monkeypatch) -> None:
    # Cold starts of the load balance at every block change only the rounding.
    chain = _polar(monkeypatch, 1, 1 << 30)
    blocks = _polar(monkeypatch, 2, 1)
    for name in FIELDS:
        np.testing.assert_allclose(getattr(blocks, name), getattr(chain, name), rtol=1e-12,
                                   atol=1e-15, err_msg=name)  # fmt: skip


def test_threaded_blocks_raise_the_first_invalid_direction(monkeypatch) -> None:
    monkeypatch.setattr(lattice, "PARALLEL_MIN_STATIONS", 1)
    monkeypatch.setattr(lattice.numba, "get_num_threads", lambda: 2)
    steep = _surface(3.0)
    with pytest.raises(ValidityError, match="beta = 0"):
        friction_polar(steep, generators.flat(), 0.9, [0.0, 90.0], load=1e-7, time_samples=4)
