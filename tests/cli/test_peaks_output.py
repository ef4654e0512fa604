"""`frictionlab simulate` reports peaks located between steps; healing says what mu_s is."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from frictionlab.cli import main

#: The starter's peak (0.1 mm/s): one law update from rest, maximised over the slip (see
#: tests/driver/test_peaks.py, which computes it with SciPy).
STARTER_PEAK = 0.47840864


def test_starter_at_100_steps_reports_the_converged_peak_and_writes_peaks_csv(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Before: 0.4455 at 100 steps, -7 % (the largest recorded step)."""
    assert main(["example", "simulate", "--write", str(tmp_path)]) == 0
    out = tmp_path / "out"
    code = main(["simulate", str(tmp_path / "simulate.toml"), "--out", str(out), "--quiet",
                 "--no-plots", "--set", "program.1.steps=100"])  # fmt: skip
    assert code == 0
    summary = json.loads((out / "summary.json").read_text())
    peak = summary["points"][0]["peak"]["friction_ratio"]
    assert peak == pytest.approx(STARTER_PEAK, rel=1e-4)
    with open(out / "peaks.csv", newline="") as handle:
        rows = list(csv.DictReader(line for line in handle if not line.startswith("#")))
    assert len(rows) == 2  # one per point of the one segment
    first = rows[0]
    assert float(first["friction_ratio [-]"]) == pytest.approx(STARTER_PEAK, rel=1e-4)
    assert float(first["sampled_friction_ratio [-]"]) < 0.95 * STARTER_PEAK


def test_slide_hold_slide_says_mu_s_is_not_the_observed_peak(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["example", "slide-hold-slide", "--write", str(tmp_path)]) == 0
    out = tmp_path / "out"
    assert main(["simulate", str(tmp_path / "slide-hold-slide.toml"), "--out", str(out),
                 "--no-plots"]) == 0  # fmt: skip
    text = capsys.readouterr().out
    assert "is the law's static coefficient" in text and "not an observed peak" in text
    healing = json.loads((out / "summary.json").read_text())["healing"]
    assert "comparison" in healing and "recovery" in healing


def test_run_peak_accuracy_0_reports_the_largest_recorded_step(tmp_path: Path) -> None:
    assert main(["example", "simulate", "--write", str(tmp_path)]) == 0
    out = tmp_path / "out"
    code = main(["simulate", str(tmp_path / "simulate.toml"), "--out", str(out), "--quiet",
                 "--no-plots", "--set", "program.1.steps=100",
                 "--set", "run.peak_accuracy=0"])  # fmt: skip
    assert code == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["points"][0]["peak"]["friction_ratio"] < 0.95 * STARTER_PEAK
    assert not (out / "peaks.csv").exists()
