"""Figure families (Figs 6a, 6b, 7, 8): content checked against closed forms, independent
quadratures and the symmetries the spec lists (section 5.1)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import dblquad, quad

from frictionlab.errors import ParameterError
from frictionlab.roughness import closed_forms as cf
from frictionlab.roughness import families as fam
from frictionlab.roughness.lattice import LatticeSettings


def test_wedge_cases_table_is_eqs_15_to_20() -> None:
    table = fam.wedge_cases(0.3, (30.0, 15.0), np.arange(0.0, 91.0, 15.0))
    assert list(table["beta_deg"]) == [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0]
    assert table.units["beta_deg"] == "deg"
    a, b = table["mu_over_mu0_A"], table["mu_over_mu0_B"]
    assert a[0] * 0.3 == pytest.approx(float(cf.flat_on_wedge_0deg(0.3, 30.0)), rel=1e-14)
    assert a[-1] * 0.3 == pytest.approx(float(cf.flat_on_wedge_90deg(0.3, 30.0)), rel=1e-14)
    assert b[0] * 0.3 == pytest.approx(float(cf.wedge_on_wedge_0deg(0.3, 30.0)), rel=1e-14)
    assert b[-1] * 0.3 == pytest.approx(float(cf.wedge_on_wedge_90deg(0.3, 30.0)), rel=1e-14)
    # "first slope steeper gives the larger mu": C > D and E > F at beta = 0 (property 9);
    # equal at 90 deg (property 10)
    assert table["mu_over_mu0_C"][0] > table["mu_over_mu0_D"][0]
    assert table["mu_over_mu0_E"][0] > table["mu_over_mu0_F"][0]
    assert table["mu_over_mu0_C"][-1] == pytest.approx(table["mu_over_mu0_D"][-1], rel=1e-14)
    assert table["mu_over_mu0_E"][-1] == pytest.approx(table["mu_over_mu0_F"][-1], rel=1e-14)
    with pytest.raises(ValueError):
        table["beta_deg"][0] = 1.0  # read-only


def test_wedge_cases_on_the_lattice_agree() -> None:
    settings = LatticeSettings(stations=16000, time_samples=80)
    closed = fam.wedge_cases(0.3, (20.0, 10.0), [0.0, 45.0])
    lattice = fam.wedge_cases(0.3, (20.0, 10.0), [0.0, 45.0], method="lattice", settings=settings)
    for name, values in closed.columns.items():
        np.testing.assert_allclose(lattice[name], values, rtol=0, atol=1e-3 / 0.3)


def test_generic_cases_exceed_the_equivalent_wedges() -> None:
    # Fig 6b text: generic roughness has a higher mu than the equivalent wedge (Jensen).
    betas = [0.0, 45.0, 90.0]
    settings = LatticeSettings(stations=2000, time_samples=40)
    generic = fam.generic_cases(0.3, (30.0, 15.0), betas, settings=settings)
    wedges = fam.wedge_cases(0.3, (30.0, 15.0), betas)
    for case in "ABCDEF":
        assert np.all(generic[f"mu_over_mu0_{case}"] > wedges[f"mu_over_mu0_{case}"] + 1e-3)
    # case A (flat on symmetric smooth wedge = sinusoid of slope amplitude pi/2 tan 30):
    # half the springs on the flat face (mu0), half on the sinusoid (area average of H)
    s = 0.5 * math.pi * math.tan(math.radians(30.0))
    avg = quad(lambda x: float(cf.h_local(0.3, math.atan(s * math.cos(x)), 0.0)[0]), 0, 2 * math.pi)
    expected = 0.5 * (0.3 + avg[0] / (2 * math.pi)) / 0.3
    assert generic["mu_over_mu0_A"][0] == pytest.approx(expected, rel=1e-9)


def area_average_2d(lx: float, ly: float, beta_deg: float) -> float:
    """|<H>| over z = sin(2 pi x/lx) sin(2 pi y/ly) (A = 1), by 2-D quadrature."""
    b = math.radians(beta_deg)
    kx, ky = 2 * math.pi / lx, 2 * math.pi / ly

    def h(y: float, x: float, k: int) -> float:
        gx = kx * math.cos(kx * x) * math.sin(ky * y)
        gy = ky * math.sin(kx * x) * math.cos(ky * y)
        return float(cf.h_global(0.3, gx, gy, b)[k])

    hx = dblquad(h, 0, lx, 0, ly, args=(0,), epsabs=1e-10)[0] / (lx * ly)
    hy = dblquad(h, 0, lx, 0, ly, args=(1,), epsabs=1e-10)[0] / (lx * ly)
    return math.hypot(hx, hy)


def test_surfaces_2d_vs_beta() -> None:
    betas = np.arange(0.0, 91.0, 15.0)
    table = fam.surfaces_2d_vs_beta(0.3, betas)
    sym = table["mu_over_mu0_l2pi_2pi"]
    np.testing.assert_allclose(sym, sym[::-1], rtol=1e-12)  # mu(beta) = mu(90 - beta)
    np.testing.assert_allclose(
        table["mu_over_mu0_l2pi_3pi"], table["mu_over_mu0_l3pi_2pi"][::-1], rtol=1e-12
    )
    assert np.ptp(sym) < 0.01  # nearly beta-independent (section 5.1)
    assert np.ptp(table["mu_over_mu0_l2pi_3pi"]) > 0.05
    # full contact: the area average, half from each (identical) surface
    expected = area_average_2d(2 * math.pi, 3 * math.pi, 30.0) / 0.3
    assert table["mu_over_mu0_l2pi_3pi"][2] == pytest.approx(expected, rel=1e-6)


def test_wavelength_map_patterns() -> None:
    table = fam.wavelength_map(0.3)
    assert table["beta_deg"].size == 75
    fx, _, m0 = fam.wavelength_matrix(table, 0.0)
    _, _, m45 = fam.wavelength_matrix(table, 45.0)
    _, _, m90 = fam.wavelength_matrix(table, 90.0)
    np.testing.assert_array_equal(fx, [1.0, 1.5, 2.0, 2.5, 3.0])
    np.testing.assert_allclose(m90, m0.T, rtol=1e-12)  # beta = 90 is the transpose
    np.testing.assert_allclose(m45, m45.T, rtol=1e-12)  # symmetric about the diagonal
    for m in (m0, m45, m90):
        assert np.unravel_index(np.argmax(m), m.shape) == (0, 0)  # lambda = pi, pi
        assert np.unravel_index(np.argmin(m), m.shape) == (4, 4)  # lambda = 3 pi, 3 pi
    # beta = 0: strong dependence on lambda_x (rows), weak on lambda_y (columns)
    assert np.ptp(m0[:, 2]) > 3 * np.ptp(m0[2, :])
    expected = area_average_2d(math.pi, 3 * math.pi, 0.0) / 0.3
    assert m0[0, 4] == pytest.approx(expected, rel=1e-6)
    with pytest.raises(ParameterError, match="beta_deg"):
        fam.wavelength_matrix(table, 30.0)


def test_bad_family_arguments() -> None:
    with pytest.raises(ParameterError, match="angles_deg"):
        fam.wedge_cases(0.3, (15.0, 30.0))
    with pytest.raises(ParameterError, match="mu0"):
        fam.wedge_cases(0.0)
    with pytest.raises(ParameterError, match="method"):
        fam.wedge_cases(method="guess")
    with pytest.raises(ParameterError, match="case"):
        fam.case_angles("G", (30.0, 15.0))


def test_families_at_physical_scale_equal_the_papers_unit_geometry() -> None:
    # the paper's A = 1, lambda = 2 pi in metres against the default micrometres: full
    # contact depends on slopes only, so mu/mu0 must agree to rounding
    betas = (0.0, 30.0, 90.0)
    unit = [(2 * np.pi, 2 * np.pi), (2 * np.pi, 3 * np.pi)]
    coarse = LatticeSettings(load="full", stations=16, time_samples=8)
    paper = fam.surfaces_2d_vs_beta(0.3, betas, wavelengths=unit, amplitude=1.0, settings=coarse)
    scaled = [(a * fam.FAMILY_LENGTH, b * fam.FAMILY_LENGTH) for a, b in unit]
    here = fam.surfaces_2d_vs_beta(0.3, betas, wavelengths=scaled, settings=coarse)
    assert set(paper.columns) == set(here.columns)
    for name in paper.columns:
        np.testing.assert_allclose(here[name], paper[name], rtol=1e-9, atol=1e-12, err_msg=name)
    assert pytest.approx(1e-6) == fam.FAMILY_LENGTH
    assert pytest.approx(1e-3) == fam.HIERARCHY_LENGTH
