"""Convergence in the number of spring stations and of time samples.

* Wedges: the error against Eqs 15-16 (maximum over 8 random asymmetric wedges, flat
  counter-face, beta = 0 and 45 deg) falls like 1/N: measured N * error = 0.3 (full
  contact) and 3 (load 0.02 h per spring) for N = 1000 ... 64 000.
* Smooth 2-D partial contact (sin x sin y, load 0.5 per spring, beta = 0, 128 samples):
  successive differences fall by more than a factor 2 per doubling of the stations.
* Time samples: smooth 1-D partial contact (sine/sine, 3200 stations) and rough/rough
  wedges at a light load (64 000 stations), where too few samples dominate the error.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from frictionlab.roughness import generators as gen
from frictionlab.roughness.closed_forms import wedge_friction
from frictionlab.roughness.lattice import friction_polar


def test_wedge_error_is_first_order_in_the_station_count() -> None:
    rng = np.random.default_rng(0)
    pairs = rng.uniform(8.0, 40.0, (8, 2))
    counts = (1000, 4000, 16000, 64000)
    for light in (False, True):
        worst = []
        for n in counts:
            errors = []
            for rise, fall in pairs:
                lower = gen.wedge((rise, fall), 1.0)
                load = 0.02 * lower.height if light else "full"
                mu_x, mu_y = wedge_friction(0.3, (rise, fall, 0.0, 0.0), [0.0, 45.0])
                polar = friction_polar(
                    lower, gen.flat(), 0.3, [0.0, 45.0], load=load, stations=n, time_samples=10
                )
                errors.append(
                    max(np.max(np.abs(polar.mu_x - mu_x)), np.max(np.abs(polar.mu_y - mu_y)))
                )
            worst.append(max(errors))
        worst_arr = np.array(worst)
        scaled = worst_arr * np.array(counts)
        assert np.all(scaled < (5.0 if light else 0.5)), scaled
        orders = np.log(worst_arr[:-1] / worst_arr[1:]) / math.log(4.0)
        assert np.all(orders > 0.7), orders


def test_smooth_partial_contact_converges_in_stations() -> None:
    s = gen.sinusoid(1.0, [2 * math.pi, 2 * math.pi])
    values = [
        float(friction_polar(s, s, 0.3, [0.0], load=0.5, stations=n, time_samples=128).mu[0])
        for n in (16, 32, 64, 128)
    ]
    diffs = np.abs(np.diff(values))
    assert np.all(diffs[1:] < diffs[:-1] / 2), diffs
    assert diffs[-1] < 1e-6


def test_time_samples_smooth_partial_contact() -> None:
    s = gen.sinusoid(1.0, 2 * math.pi)
    values = [
        float(friction_polar(s, s, 0.3, [30.0], load=0.5, stations=3200, time_samples=n).mu[0])
        for n in (10, 20, 40, 80, 160)
    ]
    diffs = np.abs(np.diff(values))
    assert np.all(diffs[1:] < diffs[:-1]), diffs
    assert diffs[-1] < 1e-5


def test_time_samples_rough_rough_wedges_light_load() -> None:
    w = gen.wedge((30.0, 15.0), 1.0)
    mu_x, _ = wedge_friction(0.3, (30.0, 15.0, 30.0, 15.0), 30.0)
    errors = []
    for n in (25, 50, 100, 200):
        polar = friction_polar(
            w, w, 0.3, [30.0], load=0.005 * w.height, stations=64000, time_samples=n
        )
        errors.append(abs(float(polar.mu_x[0]) - float(mu_x)))
    assert all(b < a for a, b in itertools.pairwise(errors)), errors
    assert errors[-1] < 1e-4 < errors[0]
