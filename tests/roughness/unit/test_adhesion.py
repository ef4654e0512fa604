"""Adhesion (spec 3.5, Eqs 21-22; scenario AD; properties 16): load sweeps with tensile springs.

Expected values come from an independent quadrature of the multipliers (scipy quad of the
local-frame Eqs 2-3), the per-spring reference loop (tests/roughness/reference.py),
limits and the spec's stated thresholds (sine/sine 2 k_c A, flat/sine k_c A).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from frictionlab.errors import ParameterError
from frictionlab.io.tables import format_csv
from frictionlab.roughness import generators as gen
from frictionlab.roughness.adhesion import adhesion_sweep
from frictionlab.roughness.closed_forms import h_local

from ..reference import reference_friction

TWO_PI = 2.0 * math.pi
SINE = gen.sinusoid(1.0, TWO_PI)  # A = 1, lambda = 2 pi: slope amplitude 1
FAST = {"stations": 1000, "time_samples": 50}


def area_average(mu0: float, beta_deg: float, component: int) -> float:
    """<H> over z = sin x (slope cos x), Eqs 2-3 by quadrature."""
    beta = math.radians(beta_deg)

    def h(x: float) -> float:
        return float(h_local(mu0, math.atan(math.cos(x)), beta)[component])

    return quad(h, 0.0, TWO_PI, epsabs=1e-13, limit=200)[0] / TWO_PI


def test_no_stretched_spring_above_full_contact_load() -> None:
    # sine/sine at beta = 0: every spring compressed for L >= 2 k_c A = 2 (spec AD); then
    # mu_a = mu (no adhesion) = the full-contact area average of H (both families alike).
    sweep = adhesion_sweep(SINE, SINE, 0.3, [4.0, 2.5], [0.0], **FAST)
    assert np.all(sweep.tensile_fraction_max == 0.0)
    assert np.all(sweep.contact_fraction_min == 1.0)
    expected = area_average(0.3, 0.0, 0)
    np.testing.assert_allclose(sweep.mu_apparent, expected, rtol=1e-9)
    assert sweep.mu_no_adhesion is not None
    np.testing.assert_allclose(sweep.mu_apparent, sweep.mu_no_adhesion, rtol=1e-12)
    np.testing.assert_allclose(sweep.tangential_force[:, 0], expected * sweep.load, rtol=1e-9)


def test_flat_on_sine_threshold_is_k_c_A() -> None:
    sweep = adhesion_sweep(gen.flat(), SINE, 0.3, [1.05, 0.9], [0.0], k_t=0.5, **FAST)
    assert sweep.tensile_fraction_max[0, 0] == 0.0
    assert sweep.tensile_fraction_max[1, 0] > 0.0


def test_zero_load_keeps_compressed_springs_and_undefined_mu_a() -> None:
    loads = [1.0, 0.5, 0.1, 0.0, -0.1]
    sweep = adhesion_sweep(SINE, SINE, 0.3, loads, [0.0], **FAST)
    i0 = loads.index(0.0)
    assert sweep.k_t == 0.5  # k_c / 2 by default
    assert sweep.tangential_force[i0, 0] > 0.0  # springs still compressed at L = 0
    assert list(sweep.mu_apparent_defined[:, 0]) == [True, True, True, False, True]
    assert sweep.mu_apparent[i0, 0] is np.ma.masked
    assert np.all(np.isfinite(np.ma.getdata(sweep.mu_apparent)))  # never NaN or inf
    assert sweep.tensile_fraction_mean[i0, 0] > 0.5  # k_t = k_c / 2: most springs stretched
    assert float(sweep.mu_apparent[-1, 0]) < 0.0  # mu_a < 0 for L < 0
    full = area_average(0.3, 0.0, 0)
    for k in range(3):  # partial contact: mu_a > mu_c, and above the full-contact value
        assert float(sweep.mu_apparent[k, 0]) > float(sweep.mu_compressed[k, 0])
        assert float(sweep.mu_apparent[k, 0]) > full
    # mu_a diverges as L -> 0+: it grows as the load falls
    assert np.all(np.diff(np.ma.getdata(sweep.mu_apparent[:3, 0])) > 0.0)
    assert sweep.mu_no_adhesion is not None
    assert list(np.ma.getmaskarray(sweep.mu_no_adhesion)[:, 0]) == [False] * 3 + [True] * 2


def test_in_phase_identical_surfaces_at_90_deg() -> None:
    # Constant gap: every spring carries the same force; R = mu L for L > 0 and 0 for L <= 0
    # (spec AD), with mu the area average of H at beta = 90 (H_x(90) = tan phi averages to 0).
    loads = [1.0, 0.3, 0.0, -0.2]
    sweep = adhesion_sweep(SINE, SINE, 0.3, loads, [90.0], **FAST)
    mu = area_average(0.3, 90.0, 1)
    np.testing.assert_allclose(sweep.tangential_force[:2, 0], mu * np.array(loads[:2]), rtol=1e-9)
    assert np.all(sweep.tangential_force[2:, 0] == 0.0)
    assert np.all(np.ma.getmaskarray(sweep.mu_compressed)[2:, 0])  # no compressed spring
    assert float(sweep.mu_apparent[3, 0]) == 0.0  # R / L = 0
    np.testing.assert_allclose(sweep.mu_apparent[:2, 0], mu, rtol=1e-9)  # no adhesion effect


def test_no_tensile_stiffness_means_no_adhesion_effect() -> None:
    sweep = adhesion_sweep(SINE, SINE, 0.3, [1.0, 0.3], [0.0, 30.0], k_t=0.0, **FAST)
    assert np.all(sweep.tensile_fraction_max == 0.0)
    np.testing.assert_allclose(sweep.mu_apparent, sweep.mu_compressed, rtol=1e-12)


@pytest.mark.parametrize("load", [0.0, -0.05, 0.02])
def test_forces_agree_with_the_reference_loop(load) -> None:
    lower = gen.sinusoid(0.1, 1.0)
    upper = gen.wedge((25.0, 40.0), 0.5)
    n, nt, beta = 24, 8, 20.0
    sweep = adhesion_sweep(
        lower, upper, 0.3, [load], [beta], k_t=0.4, stations=n, time_samples=nt,
        compare_without_adhesion=False,
    )  # fmt: skip
    xs = [(i + 0.5) / n for i in range(n)]
    shifts = [(j / nt, j / nt * math.tan(math.radians(beta))) for j in range(nt)]
    ref = reference_friction(lower, upper, 0.3, beta, xs, [0.0], shifts, load, kt=0.4)
    assert float(sweep.force_x[0, 0]) == pytest.approx(ref["force_x"], rel=1e-10, abs=1e-15)
    assert float(sweep.force_y[0, 0]) == pytest.approx(ref["force_y"], rel=1e-10, abs=1e-15)
    assert float(sweep.compressed_force[0, 0]) == pytest.approx(ref["compressed_force"], rel=1e-10)
    if load != 0.0:
        assert float(sweep.mu_apparent[0, 0]) == pytest.approx(ref["mu_apparent"], rel=1e-9)


def test_columns_write_undefined_as_empty_fields() -> None:
    sweep = adhesion_sweep(SINE, SINE, 0.3, [0.5, 0.0], [0.0, 90.0], **FAST)
    text = format_csv(sweep.columns(), sweep.units())
    lines = text.splitlines()
    header = [title.rpartition(" [")[0] for title in lines[0].split(",")]
    rows = [dict(zip(header, line.split(","), strict=True)) for line in lines[1:]]
    assert [r["mu_apparent"] == "" for r in rows] == [False, False, True, True]
    assert [r["mu_apparent_defined"] for r in rows] == ["true", "true", "false", "false"]
    assert rows[3]["mu_compressed"] == ""  # beta = 90 at L = 0: no spring compressed
    assert "nan" not in text.lower() and "inf" not in text.lower()
    assert "load_per_spring [N]" in text


def test_bad_arguments() -> None:
    with pytest.raises(ParameterError, match="loads"):
        adhesion_sweep(SINE, SINE, 0.3, [], [0.0])
    with pytest.raises(ParameterError, match="loads"):
        adhesion_sweep(SINE, SINE, 0.3, [1.0, math.nan], [0.0])
    with pytest.raises(ParameterError, match="k_t"):
        adhesion_sweep(SINE, SINE, 0.3, [1.0], [0.0], k_t=2.0)
    with pytest.raises(ParameterError, match="control"):
        adhesion_sweep(SINE, SINE, 0.3, [1.0], [0.0], control="separation", separation=0.1)
    with pytest.raises(ParameterError, match="load"):  # no tension without tensile springs
        adhesion_sweep(SINE, SINE, 0.3, [0.5, -0.1], [0.0], k_t=0.0)


class TestDetachment:
    """Option ``detachment`` (spec 8.7, off by default): springs let go beyond a cut-off."""

    @pytest.mark.parametrize("seed", range(6))
    def test_balance_takes_the_largest_root(self, seed) -> None:
        from frictionlab.roughness import _kernels as K

        rng = np.random.default_rng(seed)
        gap = rng.standard_normal(40)
        detach, kt = 0.4, 0.5

        def mean(c: float) -> float:
            u = c - gap
            return float(np.mean(np.where(u > 0, u, np.where(u >= -detach, kt * u, 0.0))))

        for load in (0.3, 0.0, -0.001):
            c, _ = K.solve_offset_detach_nb(gap, 1.0, kt, load, detach)
            c_np, _ = K.solve_offset_detach_np(gap, 1.0, kt, load, detach)
            assert c == pytest.approx(c_np, rel=1e-12, abs=1e-12)
            assert mean(c) == pytest.approx(load, abs=1e-12)
            above = c + np.geomspace(1e-9, 10.0, 400)  # no other root above it
            assert all(mean(x) > load for x in above)
        c, _ = K.solve_offset_detach_nb(gap, 1.0, kt, -10.0, detach)  # beyond pull-off
        assert math.isnan(c)

    @pytest.mark.parametrize("engine", ["numba", "numpy"])
    @pytest.mark.parametrize("load", [0.0, -0.004, 0.05])
    def test_lattice_agrees_with_the_reference_loop(self, engine, load) -> None:
        s = gen.sinusoid(0.2, 1.0)
        n, nt = 30, 6
        sweep = adhesion_sweep(
            s, s, 0.3, [load], [0.0], k_t=0.5, stations=n, time_samples=nt, engine=engine,
            detachment=0.15, compare_without_adhesion=False,
        )  # fmt: skip
        xs = [(i + 0.5) / n for i in range(n)]
        shifts = [(j / nt, 0.0) for j in range(nt)]
        ref = reference_friction(s, s, 0.3, 0.0, xs, [0.0], shifts, load, kt=0.5, detach=0.15)
        assert float(sweep.force_x[0, 0]) == pytest.approx(ref["force_x"], rel=1e-9, abs=1e-15)
        assert float(sweep.compressed_force[0, 0]) == pytest.approx(
            ref["compressed_force"], rel=1e-9
        )

    def test_limits(self) -> None:
        loads = [0.5, 0.0, -0.01]
        never = adhesion_sweep(SINE, SINE, 0.3, loads, [0.0], **FAST)
        far = adhesion_sweep(SINE, SINE, 0.3, loads, [0.0], detachment=10.0, **FAST)
        np.testing.assert_allclose(far.tangential_force, never.tangential_force, rtol=1e-12)
        short = adhesion_sweep(SINE, SINE, 0.3, loads, [0.0], detachment=0.5, **FAST)
        # letting go weakens adhesion: fewer springs pull, so more must be pushed apart
        # and at L = 0 fewer springs remain compressed
        assert short.tangential_force[1, 0] < never.tangential_force[1, 0]
        assert np.all(short.tensile_fraction_mean <= never.tensile_fraction_mean + 1e-15)
        with pytest.raises(ParameterError, match="pull-off"):
            adhesion_sweep(SINE, SINE, 0.3, [-0.2], [0.0], detachment=0.05, **FAST)
        with pytest.raises(ParameterError, match="detachment"):
            adhesion_sweep(SINE, SINE, 0.3, [0.5], [0.0], k_t=0.0, detachment=0.1, **FAST)
        with pytest.raises(ParameterError, match="detachment"):
            adhesion_sweep(SINE, SINE, 0.3, [0.5], [0.0], detachment=-1.0, **FAST)
