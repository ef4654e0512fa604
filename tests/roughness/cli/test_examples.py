"""The example script runs and writes the figure-family tables and plots."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frictionlab.io.tables import read_csv

ROOT = Path(__file__).resolve().parents[3]


@pytest.mark.slow
def test_roughness_figures_example(tmp_path, run_script) -> None:  # type: ignore[no-untyped-def]
    done = run_script(ROOT / "examples" / "roughness_figures.py", str(tmp_path))
    assert done.returncode == 0, done.stderr
    out = tmp_path / "roughness_figures"
    names = ("fig6a_wedge_cases", "fig6b_generic_cases", "fig7_surfaces_2d", "fig8_wavelength_map")
    for name in names:
        assert (out / f"{name}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    wedge = read_csv(out / "fig6a_wedge_cases.csv")
    assert wedge.units["beta_deg"] == "deg"
    np.testing.assert_array_equal(wedge["beta_deg"], np.arange(0.0, 91.0, 5.0))
    assert {f"mu_over_mu0_{c}" for c in "ABCDEF"} <= set(wedge.columns)
    grid = read_csv(out / "fig8_wavelength_map.csv")
    assert grid["beta_deg"].size == 75
    at = {}
    for b in (0.0, 90.0):
        sel = grid["beta_deg"] == b
        at[b] = {
            (lx, ly): v
            for lx, ly, v in zip(
                grid["lambda_x_over_pi"][sel],
                grid["lambda_y_over_pi"][sel],
                grid["mu_over_mu0"][sel],
                strict=True,
            )
        }
    for (lx, ly), v in at[0.0].items():
        assert abs(at[90.0][(ly, lx)] - v) <= 1e-12 * v  # beta = 90 is the transpose
    assert "A:" in done.stdout


@pytest.mark.slow
def test_roughness_life_example(tmp_path, run_script) -> None:  # type: ignore[no-untyped-def]
    done = run_script(ROOT / "examples" / "roughness_life.py", str(tmp_path))
    assert done.returncode == 0, done.stderr
    out = tmp_path / "roughness_life"
    for name in ("fig10_adhesion", "fig11_wear", "fig12_hierarchy_1d", "fig13_hierarchy_2d",
                 "fig14_hierarchy_wear"):  # fmt: skip
        assert (out / f"{name}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    ad = read_csv(out / "fig10_adhesion_sine_sine.csv")
    zero = ad["load_per_spring"] == 0.0
    assert np.all(np.ma.getmaskarray(ad["mu_apparent"]) == zero)  # undefined only at L = 0
    assert np.all(ad["tangential_force"][zero & (ad["beta_deg"] == 0.0)] > 0.0)
    wear = read_csv(out / "fig11_wear_wedge_wedge.csv")
    end = wear["t_over_Tw"] == 1.0
    np.testing.assert_allclose(wear["mu"][end], 0.3, rtol=1e-14)
    life = read_csv(out / "fig14_hierarchy_wear.csv")
    assert life.units["time_s"] == "s"
    np.testing.assert_allclose(life["mu_3"][-1], 0.3, rtol=1e-14)
    assert "drop out" in done.stdout
