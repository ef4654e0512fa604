"""`frictionlab roughness` with `[contact] model = "elastic"` and the new input keys."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main
from frictionlab.io.roughness_scenario import parse_roughness_scenario
from frictionlab.roughness import flat, self_affine
from frictionlab.roughness.elastic import elastic_contact

BASE = """mu0 = 0.3
[lower]
kind = "self_affine"
hurst = 0.8
physical_sizes = [1e-4, 1e-4]
points = [32, 32]
seed = 1
rms_slope = 0.3
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0, 90.0]
"""


def _scenario(text: str) -> dict:
    import tomllib

    return tomllib.loads(text)


@pytest.mark.slow
def test_elastic_model_writes_contact_outputs(tmp_path: Path, check_summary) -> None:
    path = tmp_path / "s.toml"
    path.write_text(BASE + '[contact]\nmodel = "elastic"\npressure = 1e8\nmodulus = 1e11\n')
    assert main(["roughness", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    names = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert names == ["polar.csv", "polar.png", "pressure_map.png", "summary.json"]
    summary = check_summary(tmp_path / "out" / "summary.json")
    surface = self_affine(0.8, (1e-4, 1e-4), (32, 32), rng=np.random.default_rng(1),
                          rms_slope=0.3)  # fmt: skip
    state = elastic_contact(surface, flat(), pressure=1e8, modulus=1e11)
    assert summary["contact"]["contact_fraction"] == pytest.approx(state.contact_fraction)
    assert summary["contact"]["mean_gap_m"] == pytest.approx(state.mean_gap, rel=1e-9)
    text = (tmp_path / "out" / "polar.csv").read_text()
    assert "contact_fraction_mean" in text and summary["contact"]["model"] == "elastic"
    rows = [r for r in text.splitlines() if r[:1].isdigit()]
    assert len(rows) == 2


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        ('[contact]\nmodel = ["lattice", "elastic"]\n', ["pressure", "missing"]),
        ('[contact]\nmodel = ["lattice", "plastic"]\n', ["model", "'plastic'"]),
        (
            '[contact]\nmodel = "elastic"\npressure = [1e6, -2e6]\nmodulus = 1e9\n',
            ["pressure", "positive"],
        ),
        ("[contact]\npressure = 1e6\n", ["stiffness_per_area", "missing"]),
        (
            '[contact]\nmodel = "elastic"\npressure = -1.0\nmodulus = 1e9\n',
            ["[contact].pressure = -1.0", "allowed a positive value (Pa)"],
        ),
        (
            '[contact]\nmodel = "elastic"\npressure = 1e6\nmodulus = 1e9\nhardness = 1e5\n',
            ["hardness", "nominal pressure"],
        ),
    ],
)
def test_contact_keys_are_checked(tmp_path: Path, capsys, extra: str, words: list[str]) -> None:
    path = tmp_path / "s.toml"
    path.write_text(BASE + extra)
    assert main(["roughness", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1
    for word in words:
        assert word in err


def test_lattice_shift_invariance_key(tmp_path: Path) -> None:
    data = _scenario(BASE + "load = 1e-9\n[lattice]\nshift_invariance = false\n")
    scenario = parse_roughness_scenario(data, tmp_path)
    assert scenario.settings.shift_invariance is False
    assert scenario.contact is None


def test_file_keys_resample_and_allow_flattening(tmp_path: Path, capsys) -> None:
    x = np.sort(np.random.default_rng(2).uniform(0.0, 100.0, 200))
    np.savetxt(tmp_path / "scan.txt", np.column_stack([x, np.sin(x / 5.0)]))
    text = BASE.replace(
        '[lower]\nkind = "self_affine"\nhurst = 0.8\nphysical_sizes = [1e-4, 1e-4]\n'
        "points = [32, 32]\nseed = 1\nrms_slope = 0.3\n",
        '[lower]\nkind = "file"\npath = "scan.txt"\nformat = "xyz"\nunit = "um"\n'
        'periodicity = "mirror"\ndetrend = "center"\n',
    )
    with pytest.raises(Exception, match="resample"):
        parse_roughness_scenario(_scenario(text), tmp_path)
    resampled = text.replace('detrend = "center"\n', 'detrend = "center"\nresample = "median"\n')
    ok = parse_roughness_scenario(_scenario(resampled), tmp_path)
    assert ok.sources["lower"]["resampled"]["source_points"] == 200


def test_statistics_output(tmp_path: Path, check_summary) -> None:
    path = tmp_path / "s.toml"
    path.write_text(BASE + 'load = "full"\n[output]\nstatistics = true\nplot_full_circle = false\n')
    assert main(["roughness", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    names = {p.name for p in (tmp_path / "out").iterdir()}
    assert {"statistics_lower.png", "statistics_lower_psd_isotropic.csv",
            "statistics_lower_rms_slope_direction.csv"} <= names  # fmt: skip
    assert not any("upper" in n for n in names)  # the flat face has no statistics
    summary = check_summary(tmp_path / "out" / "summary.json")
    # rms_slope = 0.3 by the generator (spectral); SurfaceTopography's forward difference
    # reads the finest wavelengths a little lower
    assert 0.2 < summary["statistics"]["lower"]["rms_slope"] <= 0.3


@pytest.mark.slow
def test_comparison_and_sweep_write_their_files(tmp_path: Path, check_summary) -> None:
    """model = ["lattice", "elastic"] at two pressures: comparison.csv/png; each row agrees
    with the library's own runs of each model at that pressure."""
    from frictionlab.roughness.elastic import elastic_polar
    from frictionlab.roughness.lattice import friction_polar

    path = tmp_path / "s.toml"
    path.write_text(
        BASE + '[contact]\nmodel = ["lattice", "elastic"]\npressure = [1e8, 3e8]\n'
        "modulus = 1e11\nstiffness_per_area = 1e14\n[output]\nplot_step_deg = 30.0\n"
    )
    assert main(["roughness", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    out = tmp_path / "out"
    assert sorted(p.name for p in out.iterdir()) == [
        "comparison.csv", "comparison.png", "pressure_map.png", "summary.json"
    ]  # fmt: skip
    summary = check_summary(out / "summary.json")
    rows = np.genfromtxt(out / "comparison.csv", delimiter=",", skip_header=1)
    assert rows.shape == (4, 8)  # 2 pressures x 2 directions
    assert rows[:, 0].tolist() == [1e8, 1e8, 3e8, 3e8] and rows[:, 1].tolist() == [0, 90, 0, 90]
    surface = self_affine(0.8, (1e-4, 1e-4), (32, 32), rng=np.random.default_rng(1),
                          rms_slope=0.3)  # fmt: skip
    for k, p in enumerate((1e8, 3e8)):
        lattice = friction_polar(surface, flat(), 0.3, [0.0, 90.0], load=p * 1.0 / 1e14)
        elastic = elastic_polar(surface, flat(), 0.3, [0.0, 90.0], pressure=p, modulus=1e11)
        block = rows[2 * k : 2 * k + 2]
        np.testing.assert_allclose(block[:, 2], lattice.mu, rtol=1e-12)
        np.testing.assert_allclose(block[:, 5], elastic.mu, rtol=1e-6)
        assert block[0, 7] == pytest.approx(elastic.contact_fraction_mean)
    runs = summary["contact"]["runs"]
    assert [(r["model"], r["pressure_pa"]) for r in runs] == [
        ("lattice", 1e8), ("lattice", 3e8), ("elastic", 1e8), ("elastic", 3e8)
    ]  # fmt: skip
    # more load, more contact, in both models
    assert runs[1]["contact_fraction"] > runs[0]["contact_fraction"]
    assert runs[3]["contact_fraction"] > runs[2]["contact_fraction"]


def test_lattice_pressure_sweep_writes_sweep_files(tmp_path: Path, check_summary) -> None:
    path = tmp_path / "s.toml"
    path.write_text(
        BASE + "[contact]\npressure = [1e8, 2e8, 4e8]\nstiffness_per_area = 1e14\n"
        "[output]\nplot_full_circle = false\n"
    )
    assert main(["roughness", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    out = tmp_path / "out"
    assert sorted(p.name for p in out.iterdir()) == ["summary.json", "sweep.csv", "sweep.png"]
    summary = check_summary(out / "summary.json")
    loads = [r["load_per_spring_N"] for r in summary["contact"]["runs"]]
    assert loads == pytest.approx([1e-6, 2e-6, 4e-6])
    header = (out / "sweep.csv").read_text().splitlines()[0]
    assert "contact_fraction_lattice" in header and "elastic" not in header
