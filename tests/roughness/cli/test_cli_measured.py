"""``frictionlab roughness`` on measured files (written here by SurfaceTopography).

End to end: provenance in summary.json (file, sha256, preparation, rms after
filtering), --quiet and --no-plots, [multiscale] output, validity failures with a way
forward (exit 2, nothing written), ``on_invalid = "drop"``, the assume-edge warning and
bad values naming their TOML key.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest
from SurfaceTopography import Topography

from frictionlab.cli import main
from frictionlab.io.tables import read_csv

N = 32
SIZE_UM = (64.0, 64.0)


def write_map(path: Path, slope: float = 0.3, ramp: float = 0.0) -> None:
    """Two modes (64 um and 16 um) with rms slope about ``slope``; ``ramp``: a tilt (um)."""
    x = (np.arange(N)[:, None] + 0.5) / N
    y = (np.arange(N)[None, :] + 0.5) / N
    a = slope * 64.0 / (2 * np.pi) / 1.2
    h = a * np.sin(2 * np.pi * x) * np.cos(2 * np.pi * y) + 0.2 * a * np.sin(8 * np.pi * x)
    Topography(h + ramp * x, SIZE_UM, unit="um").to_x3p(str(path))


def scenario(file: str, extra: str = "", sliding: str = "", mu0: float = 0.3) -> str:
    return f"""\
mu0 = {mu0}
[lower]
kind = "file"
path = "{file}"
periodicity = "mirror"
detrend = "center"
{extra}
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0, 45.0, 90.0]
load = "full"
{sliding}
[output]
plot_step_deg = 45.0
"""


def run(tmp_path: Path, text: str, *extra: str) -> tuple[int, Path]:
    path = tmp_path / "scenario.toml"
    path.write_text(text)
    out = tmp_path / "out"
    return main(["roughness", str(path), "--out", str(out), *extra]), out


@pytest.mark.slow
def test_provenance_multiscale_and_quiet(tmp_path, capsys, check_summary) -> None:
    write_map(tmp_path / "map.x3p")
    text = scenario("map.x3p", "long_cutoff = 1.0e-4") + "[multiscale]\ncutoffs = [40.0e-6]\n"
    code, out = run(tmp_path, text, "--quiet")
    assert code == 0
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == ""
    names = sorted(p.name for p in out.iterdir())
    assert names == ["multiscale.csv", "multiscale.png", "polar.csv", "polar.png", "summary.json"]
    summary = check_summary(out / "summary.json")
    source = summary["sources"]["lower"]
    digest = hashlib.sha256((tmp_path / "map.x3p").read_bytes()).hexdigest()
    inputs = summary["provenance"]["inputs"]
    assert [Path(i["path"]).name for i in inputs] == ["scenario.toml", "map.x3p"]
    assert inputs[1]["sha256"] == digest
    assert summary["provenance"]["command"][:2] == ["frictionlab", "roughness"]
    assert source["file"] == "map.x3p" and source["sha256"] == digest
    assert source["periodicity"] == "mirror" and source["detrend"] == "center"
    assert source["long_cutoff_m"] == 1e-4 and source["short_cutoff_m"] is None
    assert source["source_physical_sizes_m"] == [64e-6, 64e-6]
    assert source["physical_sizes_m"] == [128e-6, 128e-6]
    assert 0.2 < source["rms_slope"] < 0.4
    assert summary["sliding"]["directions_deg"] == [0.0, 45.0, 90.0]
    table = read_csv(out / "multiscale.csv")
    assert list(table)[:5] == ["cutoff_m", "beta_deg", "mu", "mu_over_mu0", "valid"]
    assert np.asarray(table["cutoff_m"]).size == 2 * 3  # (cutoff, Nyquist) x 3 directions
    mu = np.asarray(table["mu"], dtype=float).reshape(2, 3)
    assert np.all(mu[1] >= mu[0])  # adding the fine band never lowers friction here


def test_no_plots_and_mask_report_invalid_fraction(tmp_path, capsys) -> None:
    write_map(tmp_path / "steep.x3p", slope=2.5)
    code, out = run(tmp_path, scenario("steep.x3p", mu0=0.6))
    assert code == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "on_invalid" in err and "short_cutoff" in err and "%" in err
    assert not out.exists()
    code, out = run(
        tmp_path, scenario("steep.x3p", sliding='on_invalid = "drop"', mu0=0.6), "--no-plots"
    )
    assert code == 0
    assert sorted(p.name for p in out.iterdir()) == ["polar.csv", "summary.json"]
    table = read_csv(out / "polar.csv")
    fraction = np.asarray(table["invalid_fraction"], dtype=float)
    assert np.all(fraction > 0.0) and np.all(fraction < 0.5)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["sliding"]["on_invalid"] == "drop"
    assert summary["sliding"]["invalid_fraction"] == fraction.tolist()


def test_assume_warns_on_the_edge_step(tmp_path, capsys) -> None:
    write_map(tmp_path / "tilted.x3p", ramp=30.0)
    text = scenario("tilted.x3p").replace('"mirror"', '"assume"')
    code, out = run(tmp_path, text, "--no-plots")
    assert code == 0
    err = capsys.readouterr().err
    assert "warning" in err and "periodicity = 'assume'" in err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["warnings"] and "edge" in summary["warnings"][0]


def test_bad_values_name_the_toml_key(tmp_path, capsys) -> None:
    np.save(tmp_path / "map.npy", np.zeros((N, N)))
    cases = {
        'unit = "furlong"\nphysical_sizes = [64.0, 64.0]': "[lower].unit = 'furlong'",
        'unit = "um"\nphysical_sizes = [64.0]': "[lower].physical_sizes",
        'unit = "um"\nphysical_sizes = [64.0, 64.0]\ncrop = [0.0, 1.0]': "[lower].crop",
    }
    for extra, key in cases.items():
        code, _ = run(tmp_path, scenario("map.npy", extra))
        err = capsys.readouterr().err.strip()
        assert code == 2, extra
        assert len(err.splitlines()) == 1 and key in err, err


def test_two_scans_of_incommensurate_sizes_quote_the_files(tmp_path, capsys) -> None:
    write_map(tmp_path / "a.x3p")
    x = (np.arange(N)[:, None] + 0.5) / N
    Topography(np.sin(2 * np.pi * x) * np.ones((1, N)), (64.0 * 1.37, 64.0), unit="um").to_x3p(
        str(tmp_path / "b.x3p")
    )
    text = scenario("a.x3p").replace(
        '[upper]\nkind = "flat"',
        '[upper]\nkind = "file"\npath = "b.x3p"\nperiodicity = "mirror"\ndetrend = "none"',
    )
    code, _ = run(tmp_path, text)
    err = capsys.readouterr().err
    assert code == 2
    assert "64 x 64" in err.replace("6.4e-05", "64") or "6.4e-05 x 6.4e-05 m" in err
    assert "8.768e-05" in err and "mirrored" in err
