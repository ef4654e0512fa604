"""``frictionlab roughness SCENARIO.toml --out DIR`` end to end.

Scenarios use modest resolutions (stated in their [lattice] tables) to stay fast.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from SurfaceTopography import Topography

from frictionlab.cli import main
from frictionlab.io.tables import read_csv
from frictionlab.roughness.closed_forms import wedge_friction

ISSUE_SCENARIO = """\
mu0 = 0.3
[lower]                    # surface 1, fixed
kind = "wedge"             # flat | wedge | sinusoid | file | ...
angles_deg = [30.0, 15.0]  # rising and falling face angles
wavelength = 1.0e-3        # m
[upper]                    # surface 2, sliding
kind = "sinusoid"
amplitude = 1.0e-4         # m
wavelengths = [1.0e-3, 2.0e-3]   # one value: 1-D profile; two values: 2-D height map
[sliding]
beta_deg = { start = 0.0, stop = 90.0, step = 5.0 }
load = "full"              # or a mean normal load per spring
"""

FAST = """
[lattice]
stations = [32, 32]
time_samples = 16
[output]
plot_step_deg = 30.0
"""

WEDGE_1D = """\
mu0 = 0.3
title = "flat on a 30/15 wedge"
[lower]
kind = "wedge"
angles_deg = [30.0, 15.0]
wavelength = 1.0e-3
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0, 30.0, 60.0, 90.0]
load = 2.0e-6
[lattice]
stations = 16000
time_samples = 10
[output]
plot_step_deg = 45.0
"""


def run_cli(tmp_path: Path, text: str, *extra: str, capsys=None) -> tuple[int, Path]:
    scenario = tmp_path / "scenario.toml"
    scenario.write_text(text)
    out = tmp_path / "out"
    code = main(["roughness", str(scenario), "--out", str(out), *extra])
    return code, out


def test_issue_scenario_end_to_end(tmp_path, capsys) -> None:
    code, out = run_cli(tmp_path, ISSUE_SCENARIO + FAST)
    assert code == 0
    assert sorted(p.name for p in out.iterdir()) == ["polar.csv", "polar.png", "summary.json"]
    table = read_csv(out / "polar.csv")
    for column in ("beta_deg", "mu_x", "mu_y", "mu", "mu_over_mu0"):
        assert column in table.columns
    np.testing.assert_array_equal(table["beta_deg"], np.arange(0.0, 91.0, 5.0))
    np.testing.assert_allclose(table["mu_over_mu0"], table["mu"] / 0.3, rtol=1e-15)
    np.testing.assert_allclose(table["mu"], np.hypot(table["mu_x"], table["mu_y"]), rtol=1e-15)
    assert abs(table["mu_y"][0]) < 1e-12  # lower profile and sin*sin are mirror symmetric in y
    assert table.units["beta_deg"] == "deg"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["lower"]["kind"] == "wedge" and summary["upper"]["kind"] == "sinusoid"
    assert summary["lattice"]["stations_shape"] == [32, 32]
    assert summary["lattice"]["cell_m"] == pytest.approx([1e-3, 2e-3], rel=1e-12)
    assert summary["results"]["mu_max"] == pytest.approx(max(table["mu"]), rel=1e-15)
    assert summary["work"]["plot_directions"] == 19 + 12 - 4  # requested + circle at 30 deg
    assert (out / "polar.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "19 directions" in capsys.readouterr().out


def test_wedge_scenario_matches_closed_form(tmp_path) -> None:
    code, out = run_cli(tmp_path, WEDGE_1D)
    assert code == 0
    table = read_csv(out / "polar.csv")
    mu_x, mu_y = wedge_friction(0.3, (30.0, 15.0, 0.0, 0.0), table["beta_deg"])
    np.testing.assert_allclose(table["mu_x"], mu_x, atol=5e-4)
    np.testing.assert_allclose(table["mu_y"], mu_y, atol=5e-4)
    assert min(table["contact_fraction_min"]) < 0.5  # partial contact
    summary = json.loads((out / "summary.json").read_text())
    check = summary["closed_form_check"]
    assert check["max_abs_diff_mu_x"] == pytest.approx(
        np.max(np.abs(table["mu_x"] - mu_x)), rel=1e-9
    )
    assert summary["title"] == "flat on a 30/15 wedge"


def test_overrides_and_module_entry(tmp_path) -> None:
    code, out = run_cli(
        tmp_path, WEDGE_1D, "--set", "sliding.beta_deg=[45.0]", "--set", "lattice.stations=4000"
    )
    assert code == 0
    table = read_csv(out / "polar.csv")
    assert list(table["beta_deg"]) == [45.0]
    done = subprocess.run(
        [sys.executable, "-m", "frictionlab", "roughness", "--help"],
        capture_output=True, text=True, check=False, timeout=120,
    )  # fmt: skip
    assert done.returncode == 0 and "--out" in done.stdout


def test_file_surface(tmp_path) -> None:
    n = 32
    x = (np.arange(n) + 0.5) / n
    heights = 5.0 * np.sin(2 * np.pi * x)[:, None] * np.sin(2 * np.pi * x)[None, :]  # um
    Topography(heights, (100.0, 100.0), unit="um").to_x3p(str(tmp_path / "s.x3p"))
    text = """\
mu0 = 0.3
[lower]
kind = "file"
path = "s.x3p"
periodicity = "assume"
detrend = "center"
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0, 45.0, 90.0]
[lattice]
time_samples = 4
[output]
plot_full_circle = false
"""
    code, out = run_cli(tmp_path, text)
    assert code == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["lower"]["kind"] == "sampled"
    assert summary["lattice"]["stations_shape"] == [32, 32]
    table = read_csv(out / "polar.csv")
    assert np.all(table["mu"] > 0.3)


BAD = [
    ("unknown kind", ISSUE_SCENARIO.replace('kind = "wedge"', 'kind = "pyramid"'), "kind"),
    ("missing wavelength", ISSUE_SCENARIO.replace("wavelength = 1.0e-3        # m\n", ""),
     r"\[lower\]\.wavelength"),
    ("angle 95", ISSUE_SCENARIO.replace("[30.0, 15.0]", "[95.0, 15.0]"), "0 < angle < 90"),
    ("angle 0", ISSUE_SCENARIO.replace("[30.0, 15.0]", "[0.0, 15.0]"), "0 < angle < 90"),
    ("mu0 zero", ISSUE_SCENARIO.replace("mu0 = 0.3", "mu0 = 0.0"), "mu0"),
    ("mu0 negative", ISSUE_SCENARIO.replace("mu0 = 0.3", "mu0 = -0.2"), "mu0"),
    ("mu0 beyond validity", WEDGE_1D.replace("mu0 = 0.3", "mu0 = 1.8"),
     r"validity domain.*mu0 < 1\.732"),
    ("unknown key", ISSUE_SCENARIO.replace("load = ", "lode = "), "unknown key"),
    ("bad load", ISSUE_SCENARIO.replace('load = "full"', 'load = "heavy"'), "load"),
    ("negative load", ISSUE_SCENARIO.replace('load = "full"', "load = -1.0"), "load"),
    ("bad stations", ISSUE_SCENARIO + "[lattice]\nstations = 0\n", r"\[lattice\]\.stations"),
    ("three wavelengths", ISSUE_SCENARIO.replace("[1.0e-3, 2.0e-3]", "[1.0, 2.0, 3.0]"),
     "wavelengths"),
    ("unreadable file", ISSUE_SCENARIO.replace(
        'kind = "wedge"', 'kind = "file"\npath = "nope.x3p"\nperiodicity = "assume"\n'
        'detrend = "none"').replace("angles_deg = [30.0, 15.0]  # rising and falling face angles\n",
                                    "").replace("wavelength = 1.0e-3        # m\n", ""),
     "no such file"),
    ("beta range", ISSUE_SCENARIO.replace("stop = 90.0", "stop = -10.0"), "stop"),
    ("not toml", "mu0 = = 3", "not valid TOML"),
]  # fmt: skip


@pytest.mark.parametrize(("label", "text", "message"), BAD, ids=[b[0] for b in BAD])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, label, text, message) -> None:
    code, out = run_cli(tmp_path, text)
    err = capsys.readouterr().err
    assert code == 2, (label, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("frictionlab: error:")
    assert pytest.importorskip("re").search(message, lines[0]), lines[0]
    assert not out.exists()


def test_nan_heights_file(tmp_path, capsys) -> None:
    h = np.ones((16, 16))
    h[2, 3] = np.nan
    Topography(np.ma.masked_invalid(h), (1.0, 1.0), unit="um").to_x3p(str(tmp_path / "nan.x3p"))
    text = """\
mu0 = 0.3
[lower]
kind = "file"
path = "nan.x3p"
periodicity = "assume"
detrend = "none"
[upper]
kind = "flat"
[sliding]
beta_deg = 0.0
"""
    code, out = run_cli(tmp_path, text)
    err = capsys.readouterr().err
    assert code == 2 and "undefined" in err and "fill_missing" in err
    assert not out.exists()
    code, out = run_cli(
        tmp_path, text.replace('detrend = "none"', 'detrend = "none"\nfill_missing = true')
    )
    assert code == 0


def test_failure_leaves_an_existing_directory_untouched(tmp_path, capsys) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / "keep.txt").write_text("x")
    code, _ = run_cli(tmp_path, WEDGE_1D.replace("mu0 = 0.3", "mu0 = 1.8"))
    assert code == 2
    assert sorted(p.name for p in out.iterdir()) == ["keep.txt"]
    (tmp_path / "file").write_text("")
    scenario = tmp_path / "scenario.toml"
    assert main(["roughness", str(scenario), "--out", str(tmp_path / "file")]) == 2
    assert "not a directory" in capsys.readouterr().err


def test_the_output_lock_is_held_for_the_whole_run(tmp_path, capsys, monkeypatch) -> None:
    """A second run on the same --out is refused while the first is still computing."""
    from frictionlab.app import roughness as command
    from frictionlab.errors import InputError
    from frictionlab.io.output_set import output_set

    out = tmp_path / "out"
    real = command.friction_polar
    seen: list[str] = []

    def computing(*args, **kwargs):
        with (
            pytest.raises(InputError, match="being written by another frictionlab run"),
            output_set(out),
        ):
            pass  # pragma: no cover - the lock is held by the run
        seen.append("refused")
        return real(*args, **kwargs)

    monkeypatch.setattr(command, "friction_polar", computing)
    code, _ = run_cli(tmp_path, WEDGE_1D.replace("stations = 16000", "stations = 2000"))
    assert code == 0 and seen and set(seen) == {"refused"}
    assert (out / "summary.json").is_file()
    # and a run that holds the lock keeps this command from starting its computation
    seen.clear()
    with output_set(out, overwrite=True):
        code, _ = run_cli(tmp_path, WEDGE_1D, "--overwrite")
    assert code == 2 and seen == []
    assert "being written by another frictionlab run" in capsys.readouterr().err
