"""The command-line entry points."""

from __future__ import annotations

import csv
import itertools
import subprocess
import sys
from pathlib import Path

from frictionlab import __version__
from frictionlab.cli import main


def test_module_entry_point_reports_the_version() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "frictionlab", "--version"], capture_output=True, text=True
    )
    assert out.returncode == 0 and __version__ in out.stdout


def test_no_command_is_bad_usage() -> None:
    assert main([]) == 2
    assert main(["no-such-command"]) == 2


def test_demo_writes_a_table_with_recovery_of_static_friction(tmp_path: Path) -> None:
    assert main(["demo", "--out", str(tmp_path)]) == 0
    with open(tmp_path / "demo.csv") as handle:
        rows = list(csv.DictReader(handle))
    peaks = [float(r["restart_peak"]) for r in rows]
    holds = [float(r["hold_time_s"]) for r in rows]
    assert holds == sorted(holds)
    assert all(b > a for a, b in itertools.pairwise(peaks)) and max(peaks) <= 0.5
    assert not list(tmp_path.glob(".*.tmp*"))  # no temporary files left behind
