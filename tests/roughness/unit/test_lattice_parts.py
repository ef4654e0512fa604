"""Lattice building blocks: load balance, sample kernels (numba vs NumPy), settings, geometry."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from frictionlab.errors import ParameterError
from frictionlab.roughness import _kernels as K
from frictionlab.roughness import generators as gen
from frictionlab.roughness.lattice import (
    LatticeSettings,
    friction_polar,
    lattice_geometry,
    merge_polars,
)


def mean_force(gap: np.ndarray, c: float, kc: float, kt: float) -> float:
    u = c - gap
    return float(np.mean(np.where(u > 0, kc * u, kt * u)))


class TestLoadBalance:
    @settings(max_examples=150, deadline=None)
    @given(
        n=st.integers(1, 300),
        seed=st.integers(0, 2**31),
        kt_frac=st.sampled_from([0.0, 0.25, 0.5, 1.0]),
        load=st.floats(-2.0, 5.0),
        scale=st.sampled_from([1e-6, 1.0, 1e3]),
    )
    def test_newton_and_sorting_solve_the_balance(self, n, seed, kt_frac, load, scale) -> None:
        kc = 2.0
        kt = kt_frac * kc
        if kt == 0.0 and load <= 0.0:
            load = 0.5
        rng = np.random.default_rng(seed)
        gap = rng.standard_normal(n) * scale
        load = load * scale
        tol = 1e-12 * (abs(load) + kc * scale)
        for start in (math.nan, float(gap.min()) - scale, float(gap.max()) + 3 * scale):
            c, iterations = K.solve_offset_nb(gap, kc, kt, load, start)
            assert abs(mean_force(gap, c, kc, kt) - load) <= tol
            assert iterations <= 100  # no bisection fallback
        c_np, _ = K.solve_offset_np(gap, kc, kt, load)
        assert abs(mean_force(gap, c_np, kc, kt) - load) <= tol

    def test_full_contact_shortcut(self) -> None:
        gap = np.array([0.0, 0.1, -0.1])
        c, iterations = K.solve_offset_nb(gap, 1.0, 0.0, 5.0, math.nan)
        assert iterations == 0 and c == pytest.approx(5.0, rel=1e-15)


class TestSampleKernels:
    @pytest.mark.parametrize("mode", [K.MODE_FULL, K.MODE_LOAD, K.MODE_SEPARATION])
    @pytest.mark.parametrize("kt", [0.0, 0.5])
    @pytest.mark.parametrize(
        ("nx", "ny", "shifts"),
        [(7, 5, ((0, 0), (3, 1), (6, 4))), (35, 1, ((0, 0), (1, 0), (34, 0), (17, 0)))],
    )
    def test_numba_equals_numpy(self, mode, kt, nx, ny, shifts) -> None:
        rng = np.random.default_rng(4)
        n = nx * ny
        z1, z2 = rng.standard_normal((2, n))
        h1x, h1y, h2x, h2y = rng.standard_normal((4, n))
        den1, den2 = rng.uniform(0.1, 1.0, (2, n))
        den2[3] = -0.1  # one invalid contact on surface 2
        for kx, ky in shifts:
            args = (z1, h1x, h1y, den1, z2, h2x, h2y, den2, nx, ny, kx, ky, 1.0, kt, mode, 0.4, 0.3)
            a = K.sample_nb(*args)
            b = K.sample_np(*args)
            np.testing.assert_allclose(a[0], b[0], rtol=1e-12, atol=1e-12)  # c
            np.testing.assert_allclose(a[2:6], b[2:6], rtol=1e-12, atol=1e-12)  # sums
            assert a[6:] == b[6:]

    def test_shift_reads_the_rolled_surface(self) -> None:
        nx, ny = 4, 3
        z2 = np.arange(12.0)
        zeros = np.zeros(12)
        ones = np.ones(12)
        h2x = np.arange(12.0)  # identifies the entry read at each station
        res = K.sample_nb(
            zeros, zeros, zeros, ones, z2, h2x, zeros, ones, nx, ny, 1, 2, 1.0, 0.0,
            K.MODE_FULL, 0.0, 0.0,
        )  # fmt: skip
        rolled = np.roll(h2x.reshape(nx, ny), (1, 2), axis=(0, 1))
        assert res[3] == pytest.approx(rolled.sum(), rel=1e-15)


class TestChunkedKernel:
    """sample_into_nb: any chunking of the rows, with or without reading denominators."""

    @pytest.mark.parametrize("mode", [K.MODE_FULL, K.MODE_LOAD, K.MODE_SEPARATION])
    @pytest.mark.parametrize(("kt", "detach"), [(0.0, math.inf), (0.5, math.inf), (0.5, 0.8)])
    @pytest.mark.parametrize(("nx", "ny", "kx", "ky"), [(9, 6, 4, 5), (40, 1, 13, 0)])
    def test_equals_numpy_for_any_chunks(self, mode, kt, detach, nx, ny, kx, ky) -> None:
        rng = np.random.default_rng(11)
        n = nx * ny
        z1, z2 = rng.standard_normal((2, n))
        h1x, h1y, h2x, h2y = rng.standard_normal((4, n))
        den1, den2 = rng.uniform(0.1, 1.0, (2, n))  # every contact valid
        rows = 1 if ny == 1 else nx
        args = (z1, h1x, h1y, den1, z2, h2x, h2y, den2, nx, ny, kx, ky, 1.0, kt, mode, 0.4)
        for c_in in (0.3, math.nan, -5.0, 5.0):  # warm starts left and right of the root
            if mode != K.MODE_LOAD and math.isnan(c_in):
                continue
            want = K.sample_np(*args, c_in, detach, False)
            for bounds in (np.array([0, rows]), np.arange(rows + 1), np.array([0, 1, rows])):
                for check in (True, False):
                    gap = np.full(n, np.nan)
                    parts = np.full((bounds.size - 1, K.PART_COLUMNS), np.nan)
                    got = K.sample_into_nb(*args, c_in, detach, False, check, gap,
                                           bounds.astype(np.int64), parts)  # fmt: skip
                    np.testing.assert_allclose(got[0], want[0], rtol=1e-12, atol=1e-12)
                    np.testing.assert_allclose(got[2:6], want[2:6], rtol=1e-12, atol=1e-12)
                    assert got[6:] == want[6:]

    def test_chunk_bounds_cover_whole_rows(self) -> None:
        b = K.chunk_bounds(1000, 100)  # rows of 100 stations
        step = K.CHUNK_STATIONS // 100
        assert b[0] == 0 and b[-1] == 1000 and np.all(np.diff(b)[:-1] == step)
        assert 0 < b[-1] - b[-2] <= step
        assert list(K.chunk_bounds(50, 1)) == [0, 1]  # a profile is one row
        assert list(K.chunk_bounds(3, 10**6)) == [0, 1, 2, 3]  # one row at least


class TestSettings:
    @pytest.mark.parametrize(
        ("kwargs", "field"),
        [
            ({"load": 0.0}, "load"),
            ({"load": -1.0}, "load"),
            ({"load": "heavy"}, "load"),
            ({"load": float("nan")}, "load"),
            ({"control": "speed"}, "control"),
            ({"control": "separation"}, "separation"),
            ({"control": "separation", "separation": 1e-6, "load": 1.0}, "load"),
            ({"separation": 1e-6}, "separation"),
            ({"k_c": 0.0}, "k_c"),
            ({"k_t": 2.0}, "k_t"),
            ({"k_t": -0.1}, "k_t"),
            ({"stations": 0}, "stations"),
            ({"stations": (10, 0)}, "stations"),
            ({"stations": 2.5}, "stations"),
            ({"time_samples": 0}, "time_samples"),
            ({"travel": "far"}, "travel"),
            ({"travel": -1.0}, "travel"),
            ({"max_return_periods": 0}, "max_return_periods"),
            ({"phase": (0.0,)}, "phase"),
            ({"phase": (0.0, float("inf"))}, "phase"),
            ({"mu_definition": "norm"}, "mu_definition"),
            ({"on_invalid": "ignore"}, "on_invalid"),
            ({"engine": "cuda"}, "engine"),
        ],
    )
    def test_rejects(self, kwargs, field) -> None:
        with pytest.raises(ParameterError, match=field):
            LatticeSettings(**kwargs)

    def test_accepts_adhesive_negative_load(self) -> None:
        s = LatticeSettings(load=-0.1, k_t=0.5)
        assert s.load == -0.1 and s.k_t == 0.5

    def test_unknown_option_and_double_settings(self) -> None:
        w = gen.wedge(20.0, 1.0)
        with pytest.raises(ParameterError, match="options"):
            friction_polar(w, w, 0.3, [0.0], loads=1.0)
        with pytest.raises(ParameterError, match="either"):
            friction_polar(w, w, 0.3, [0.0], LatticeSettings(), load=1.0)
        with pytest.raises(ParameterError, match="mu0"):
            friction_polar(w, w, -0.3, [0.0])
        with pytest.raises(ParameterError, match="beta_deg"):
            friction_polar(w, w, 0.3, [])
        with pytest.raises(ParameterError, match="lower"):
            friction_polar("wedge", w, 0.3, [0.0])  # type: ignore[arg-type]


class TestGeometry:
    def test_common_cell_and_default_stations(self) -> None:
        g = lattice_geometry(gen.wedge(30.0, 1e-3), gen.sinusoid(1e-4, 2e-3))
        assert g.dimension == 1
        assert g.cell[0] == pytest.approx(2e-3, rel=1e-12)
        assert g.shape == (4000,)  # 2000 per shortest period
        g = lattice_geometry(gen.sinusoid(1.0, 1.0), gen.sinusoid(1.0, 1.5))
        assert g.cell[0] == pytest.approx(3.0, rel=1e-12)
        g = lattice_geometry(gen.wedge(30.0, 1e-3), gen.sinusoid(1e-4, [1e-3, 2e-3]))
        assert g.dimension == 2 and g.shape == (64, 64)
        assert g.cell == pytest.approx((1e-3, 2e-3), rel=1e-12)
        g = lattice_geometry(gen.flat(), gen.flat())
        assert g.shape == (1,)
        sampled = gen.from_array(np.zeros((100, 50)), (1e-3, 1e-3))
        g = lattice_geometry(sampled, gen.flat())
        assert g.shape == (100, 50)

    def test_incommensurate_periods_refused(self) -> None:
        with pytest.raises(ParameterError, match="commensurate"):
            lattice_geometry(gen.sinusoid(1.0, 1.0), gen.sinusoid(1.0, math.pi))

    def test_explicit_stations(self) -> None:
        g = lattice_geometry(gen.wedge(30.0, 1.0), gen.flat(), 123)
        assert g.shape == (123,)
        with pytest.raises(ParameterError, match="one integer"):
            lattice_geometry(gen.wedge(30.0, 1.0), gen.flat(), (10, 10))
        with pytest.raises(ParameterError, match="at most"):
            lattice_geometry(gen.sinusoid(1.0, [1.0, 1.0]), gen.flat(), (5000, 5000))


def test_merge_polars_equals_one_computation() -> None:
    w = gen.wedge((30.0, 15.0), 1.0)
    kw = {"load": 0.01, "stations": 400, "time_samples": 20}
    whole = friction_polar(w, gen.flat(), 0.3, [0.0, 30.0, 60.0, 90.0], **kw)
    part_a = friction_polar(w, gen.flat(), 0.3, [60.0, 0.0], **kw)
    part_b = friction_polar(w, gen.flat(), 0.3, [90.0, 30.0], **kw)
    merged = merge_polars(part_a, part_b)
    np.testing.assert_array_equal(merged.beta_deg, whole.beta_deg)
    for name in ("mu", "mu_x", "mu_y", "contact_fraction_min", "time_samples"):
        np.testing.assert_array_equal(getattr(merged, name), getattr(whole, name))
    assert merged.travel_mode == whole.travel_mode
    assert merged.spring_evaluations == whole.spring_evaluations
    other = friction_polar(w, gen.flat(), 0.4, [45.0], **kw)
    with pytest.raises(ParameterError, match="same settings"):
        merge_polars(part_a, other)
