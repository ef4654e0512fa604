"""`[output] every / points`, the streamed history.csv, points.csv and a small summary.json."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from frictionlab.app import simulate_files as results
from frictionlab.app.simulate_files import SUMMARY_POINTS
from frictionlab.cli import main
from frictionlab.demo import bundled_scenario
from frictionlab.driver import Recording, simulate
from frictionlab.driver.table import history_columns
from frictionlab.io.scenario import parse_scenario
from frictionlab.io.tables import format_csv

SCENARIO = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
kappa = 1.0
xi = 0.001
alpha_t = 1000.0
alpha_n = 1000.0
rotation = [0.1, 0.0]
[initial]
normal_traction = 1.0
[run]
n_points = {n}
peak_accuracy = 0  # the figures are reductions of the recorded rows (refined: test_peaks.py)
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.05
steps = 31
[[program]]
kind = "hold"
duration = 10.0
steps = 3
[[program]]
kind = "turn"
angle_deg = 90.0
distance = 0.03
steps = 17
"""


def _run(tmp_path: Path, n: int, output: str = "", name: str = "out") -> Path:
    scenario = tmp_path / f"{name}.toml"
    scenario.write_text(SCENARIO.format(n=n) + output)
    out = tmp_path / name
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet", "--no-plots"]) == 0
    return out


def test_the_streamed_history_csv_is_the_in_memory_history(tmp_path: Path) -> None:
    """history.csv written chunk by chunk equals the table of the in-memory history."""
    out = _run(tmp_path, 3)
    scenario = parse_scenario(tomllib.loads(SCENARIO.format(n=3)))
    history = simulate(scenario.params, scenario.program, scenario.initial, n_points=3)  # type: ignore[arg-type]
    cols, units = history_columns(history)
    assert (out / "history.csv").read_text() == format_csv(cols, units)
    frame = pd.read_csv(out / "history.csv")
    assert len(frame) == 3 * 52 and list(frame["point [-]"][:3]) == [1, 2, 3]  # step-major
    np.testing.assert_array_equal(frame["plastic_work [J/m^2]"], frame["dissipation [J/m^2]"])


def test_every_and_points_choose_the_rows(tmp_path: Path) -> None:
    full = pd.read_csv(_run(tmp_path, 4, name="full") / "history.csv")
    part_dir = _run(tmp_path, 4, "[output]\nevery = 10\npoints = [4, 2]\n", name="part")
    part = pd.read_csv(part_dir / "history.csv")
    steps = [0, 1, 10, 20, 30, 31, 32, 34, 35, 44, 51]  # per segment: 1st, every 10th, last
    assert sorted(set(part["step [-]"])) == steps
    assert sorted(set(part["point [-]"])) == [2, 4]
    keep = full["step [-]"].isin(steps) & full["point [-]"].isin([2, 4])
    expected = full[keep].reset_index(drop=True)
    pd.testing.assert_frame_equal(part, expected)
    # the summaries cover every step and every point, whatever was recorded
    a = json.loads((tmp_path / "full" / "summary.json").read_text())
    b = json.loads((part_dir / "summary.json").read_text())
    assert a["points"] == b["points"] and a["segments"] == b["segments"]
    assert b["recorded"] == {"every": 10, "points": [2, 4], "rows": len(steps)}
    pd.testing.assert_frame_equal(
        pd.read_csv(tmp_path / "full" / "points.csv"), pd.read_csv(part_dir / "points.csv")
    )


def test_points_csv_is_the_per_point_reference(tmp_path: Path) -> None:
    """points.csv against the rows of history.csv reduced by hand (pandas only)."""
    out = _run(tmp_path, 2)
    hist = pd.read_csv(out / "history.csv")
    pts = pd.read_csv(out / "points.csv")
    for p in (1, 2):
        h = hist[hist["point [-]"] == p]
        row = pts[pts["point [-]"] == p].iloc[0]
        ratio = h["friction_ratio [-]"].to_numpy()
        assert row["peak_friction_ratio [-]"] == ratio.max()
        assert row["peak_step [-]"] == h["step [-]"].to_numpy()[ratio.argmax()]
        d = np.hypot(np.diff(h["slip_1 [m]"]), np.diff(h["slip_2 [m]"]))
        assert row["path_length [m]"] == pytest.approx(d.sum(), rel=1e-12)
        assert row["final_plastic_work [J/m^2]"] == h["plastic_work [J/m^2]"].to_numpy()[-1]


def test_many_points_keep_summary_json_small(tmp_path: Path) -> None:
    sizes = []
    for n in (2 * SUMMARY_POINTS, 6 * SUMMARY_POINTS):
        out = _run(tmp_path, n, "[output]\nevery = 100\npoints = [1]\n", name=f"n{n}")
        summary = json.loads((out / "summary.json").read_text())
        assert summary["n_points"] == n and len(summary["points"]) == SUMMARY_POINTS
        peak = summary["segments"][0]["peak_friction_ratio"]
        assert set(peak) == {"min", "mean", "max", "per_point"}
        pts = pd.read_csv(out / "points.csv")
        assert len(pts) == n and peak["max"] == pts["segment_1_peak_friction_ratio [-]"].max()
        assert len(pd.read_csv(out / "healing.csv")) == n
        sizes.append((out / "summary.json").stat().st_size)
    assert abs(sizes[1] - sizes[0]) < 0.01 * sizes[0]  # 3x the points, the same size


def test_recording_points_are_zero_based_in_python() -> None:
    scenario = parse_scenario(tomllib.loads(SCENARIO.format(n=3) + "[output]\npoints = [3]\n"))
    assert scenario.output.recording() == Recording(every=1, points=(2,))


def test_csv_written_in_small_blocks_is_the_same_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Formatting a few lines at a time (bounded memory) changes nothing in the files."""
    whole = _run(tmp_path, 5, name="whole")
    monkeypatch.setattr(results, "CSV_BLOCK", 3)  # fewer lines than points per row
    blocks = _run(tmp_path, 5, name="blocks")
    for name in ("history.csv", "points.csv"):
        assert (blocks / name).read_text() == (whole / name).read_text(), name


def test_output_selects_the_rows_of_a_spring_slider(tmp_path: Path) -> None:
    """The spring-slider records in memory; [output] chooses what history.csv holds."""
    outs = {}
    for name, extra in (
        ("all", []),
        ("part", ["--set", "output.every=10", "--set", "output.points=[2]"]),
    ):
        with bundled_scenario("stick_slip") as path:
            args = ["simulate", str(path), "--out", str(tmp_path / name), "--quiet", "--no-plots"]
            args += ["--set", "machine.steps=205"]
            assert main([*args, *extra]) == 0
        outs[name] = pd.read_csv(tmp_path / name / "history.csv")
    full, part = outs["all"], outs["part"]
    last = full["step [-]"].max()
    steps = sorted({*range(0, last + 1, 10), last})
    expected = full[full["step [-]"].isin(steps) & (full["point [-]"] == 2)]
    pd.testing.assert_frame_equal(part, expected.reset_index(drop=True))
