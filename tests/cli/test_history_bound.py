"""The default recording is bounded: a history beyond 1 GB warns naming [output] every and
points; without [output] every the run records every k-th step, the smallest k under 1 GB.

The sizes are estimates made before anything runs, so the 10^4 points x 10^4 steps case
is checked without writing anything; the CLI run lowers the limit to a few kB.
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import pandas as pd
import pytest

from frictionlab.app import budget
from frictionlab.cli import main
from frictionlab.schema.scenario import parse_scenario

BIG = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
kappa = 1.0
xi = 0.001
alpha_t = 1000.0
alpha_n = 1000.0
[initial]
normal_traction = 1.0
[run]
n_points = {n}
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.05
steps = {steps}
"""


def _smallest_every(steps: int, points: int, per_row: float, limit: float) -> int:
    """The smallest k with rows(k) = 1 + ceil(steps / k) + 2 <= limit / (points * per_row)."""
    allowed_rows = math.floor(limit / (points * per_row))
    k = 1
    while 1 + math.ceil(steps / k) + 2 > allowed_rows:
        k += 1
    return k


CSV_ROW = budget.HISTORY_BYTES_PER_ROW["csv"]
#: 10^4 points x 10^4 steps (10001 rows) recorded every step; the every and the points
#: that keep it under 1 GB.
FULL = 10_001 * 10_000 * CSV_ROW
K = _smallest_every(10_000, 10_000, CSV_ROW, 1e9)
POINTS = math.floor(1e9 / (10_001 * CSV_ROW))


def test_the_default_recording_of_a_large_history_records_every_kth_step() -> None:
    scenario = parse_scenario(tomllib.loads(BIG.format(n=10_000, steps=10_000)))
    assert FULL > 1e10 and 10 < K < 100  # the 22 GB case
    assert scenario.output.every == K and not scenario.output.every_given
    (warning,) = scenario.warnings
    assert f"history.csv would be about {FULL / 1e9:.3g} GB" in warning
    assert f"[output] every = {K}" in warning and "[output] every = 1 " in warning
    assert f"[output] points listing at most {POINTS} point(s)" in warning
    assert scenario.estimate is not None and scenario.estimate.history <= 1e9


def test_a_given_every_is_kept_and_the_warning_says_what_fits() -> None:
    text = BIG.format(n=10_000, steps=10_000) + "[output]\nevery = 1\n"
    scenario = parse_scenario(tomllib.loads(text))
    assert scenario.output.every == 1
    (warning,) = scenario.warnings
    assert f"history.csv will be about {FULL / 1e9:.3g} GB" in warning
    assert f"[output] every = {K} or [output] points listing at most {POINTS}" in warning


def test_parquet_is_estimated_with_its_own_row_size() -> None:
    text = BIG.format(n=10_000, steps=10_000) + '[output]\nformat = "parquet"\n'
    scenario = parse_scenario(tomllib.loads(text))
    per_row = budget.HISTORY_BYTES_PER_ROW["parquet"]
    assert scenario.output.every == _smallest_every(10_000, 10_000, per_row, 1e9)
    assert "history.parquet would be about" in scenario.warnings[0]


@pytest.mark.parametrize("output", ["", "[output]\nevery = 100\n"])
def test_no_warning_under_the_limit(output: str) -> None:
    small = parse_scenario(tomllib.loads(BIG.format(n=10, steps=1000) + output))
    assert small.warnings == () and small.output.every == (100 if output else 1)
    big = parse_scenario(tomllib.loads(BIG.format(n=10_000, steps=10_000) + output))
    assert (big.warnings == ()) == bool(output)  # every = 100: 103 rows, under 1 GB


def test_the_cli_warns_before_the_run_and_in_summary_json(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setattr(budget, "HISTORY_LIMIT", 50 * 51 * CSV_ROW)  # 50 points x 51 rows
    scenario = tmp_path / "s.toml"
    scenario.write_text(BIG.format(n=50, steps=100))
    out = tmp_path / "out"
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet", "--no-plots"]) == 0
    err = capsys.readouterr().err
    k = _smallest_every(100, 50, CSV_ROW, 50 * 51 * CSV_ROW)  # rows(k) <= 51: 3 (1 + 34 + 2)
    assert k == 3
    size = 50 * 101 * CSV_ROW
    assert f"frictionlab: warning: history.csv would be about {size / 1e6:.3g} MB" in err
    assert f"[output] every = {k}" in err
    summary = json.loads((out / "summary.json").read_text())
    assert any(f"[output] every = {k}" in w for w in summary["warnings"])
    assert summary["recorded"]["every"] == k
    steps = [0, 1, *range(3, 100, 3), 100]  # first, every 3rd, last step
    history = pd.read_csv(out / "history.csv")
    assert sorted(set(history["step [-]"])) == steps and len(history) == 50 * len(steps)
    assert summary["recorded"]["rows"] == len(steps)  # of every point (the plots keep fewer)
