"""Scale: the summary costs a fixed number of whole-history passes; plots draw a subset."""

from __future__ import annotations

import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

from frictionlab.app.budget import check_grid_size, check_output_space, check_run_size, largest
from frictionlab.app.simulate import run_scenario
from frictionlab.app.simulate_files import SUMMARY_POINTS, summarise
from frictionlab.cli import main
from frictionlab.driver import History
from frictionlab.errors import InputError
from frictionlab.io.scenario import parse_scenario
from frictionlab.plotting.law import (
    MAX_CURVES,
    MAX_LEGEND_CURVES,
    plot_friction,
    save_figure,
    shown_points,
)

SCENARIO = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
[initial]
normal_traction = 1.0
[run]
peak_accuracy = 0  # the summary against the recorded rows (refined: test_peaks.py)
n_points = {n}
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.02
steps = 4
[[program]]
kind = "hold"
duration = 1.0
steps = 2
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.02
steps = 4
"""


def _run(n: int) -> tuple[object, History]:
    scenario = parse_scenario(tomllib.loads(SCENARIO.format(n=n)))
    return scenario, run_scenario(scenario)


def test_summary_makes_a_fixed_number_of_whole_history_passes(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Counting the (rows, N) passes: the same for 3 and 300 points (was one per point)."""
    calls = {"friction_ratio": 0, "path_length": 0}
    for name in calls:
        original = getattr(History, name)

        def counted(self: History, _name: str = name, _original: property = original) -> object:
            calls[_name] += 1
            return _original.fget(self)  # type: ignore[misc]

        monkeypatch.setattr(History, name, property(counted))
    counts = []
    for n in (3, 300):
        scenario, history = _run(n)
        for name in calls:
            calls[name] = 0
        summary = summarise(scenario, history, 0.0, [])  # type: ignore[arg-type]
        assert len(summary["points"]) == min(n, SUMMARY_POINTS)
        assert summary["n_points"] == n
        counts.append(dict(calls))
    assert counts[0] == counts[1]
    assert counts[1]["friction_ratio"] <= 2 and counts[1]["path_length"] <= 2


def test_summary_values_match_a_per_point_reference() -> None:
    scenario, history = _run(5)
    summary = summarise(scenario, history, 0.0, [])  # type: ignore[arg-type]
    for i, point in enumerate(summary["points"]):
        ratio = history.point(i)["friction_ratio"]
        k = int(np.argmax(ratio))
        assert point["peak"]["step"] == k
        assert point["peak"]["friction_ratio"] == pytest.approx(ratio[k], rel=1e-15, abs=0)
        travelled = np.abs(np.diff(history.slip[: k + 1, i, 0])).sum()
        assert point["peak"]["slip_distance"] == pytest.approx(travelled, rel=1e-12, abs=1e-300)


@pytest.mark.parametrize("n", [1, MAX_CURVES, MAX_CURVES + 1, 10**6])
def test_plots_draw_an_evenly_spaced_subset(n: int) -> None:
    shown = shown_points(n)
    assert shown.size == min(n, MAX_CURVES)
    assert shown[0] == 0 and shown[-1] == n - 1 and np.all(np.diff(shown) > 0)


def test_a_plot_of_many_points_says_it_shows_a_subset() -> None:
    _, history = _run(MAX_CURVES + 10)
    fig = plot_friction(history)
    ax_s, ax_t = fig.axes[:2]
    assert len(ax_s.lines) == 2 * MAX_CURVES  # a curve and a hold marker per point drawn
    labels = [t.get_text() for t in ax_t.get_legend().get_texts()]
    assert f"{MAX_CURVES} of {MAX_CURVES + 10} points shown (evenly spaced)" in labels


BIG = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
[initial]
normal_traction = 1.0
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.02
steps = 10
"""


@pytest.mark.parametrize(
    ("override", "key"),
    [
        ("program.1.steps=1000000000000", "[[program]] #1.steps makes 1e+12 recorded rows"),
        ("program.1.steps=9223372036854775807", "[[program]] #1.steps makes 9.223e+18"),
        ("run.n_points=1000000000", "[run].n_points makes 2 recorded rows x 1000000000"),
    ],
)
def test_absurd_work_is_refused_before_running(
    override: str, key: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scenario = tmp_path / "s.toml"
    scenario.write_text(BIG)
    out = tmp_path / "out"
    assert main(["simulate", str(scenario), "--out", str(out), "--set", override]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and key in err[0] and "[run].allow_large = true" in err[0]
    assert "of memory" in err[0] and "of output files" in err[0]
    assert not out.exists()


def test_max_step_sets_the_estimate_and_allow_large_overrides_it() -> None:
    text = BIG.replace("steps = 10", "max_step = 1e-300")
    with pytest.raises(InputError, match=r"\[\[program\]\] #1.max_step makes 2e\+298 recorded"):
        parse_scenario(tomllib.loads(text))
    estimate = largest([(10**9, "[[program]] #1.steps")], 3, "[run].n_points")
    assert estimate.rows == 10**9 + 1 and estimate.key == "[[program]] #1.steps"
    check_run_size(estimate, allow_large=True, memory=1)  # the user insists: no error
    with pytest.raises(InputError, match=r"2\.7 TB of memory"):
        check_run_size(estimate, allow_large=False, memory=2**30)


SELF_AFFINE = """
mu0 = 0.3
[lower]
kind = "flat"
[upper]
kind = "self_affine"
hurst = 0.8
physical_sizes = [1e-3, 1e-3]
points = [200000, 200000]
seed = 1
rms_slope = 0.1
[sliding]
beta_deg = [0.0]
load = 1e-6
"""


def test_a_huge_surface_grid_is_refused_before_allocating(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """[200000, 200000] used to die with MemoryError (298 GiB) after minutes."""
    (tmp_path / "s.toml").write_text(SELF_AFFINE)
    assert main(["roughness", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[upper].points = [200000, 200000] makes 4e+10 grid points" in err[0]
    assert "4 TB of memory" in err[0] and "[upper].allow_large = true" in err[0]
    check_grid_size("[upper].points", [200000, 200000], allow_large=True, memory=1)
    check_grid_size("[upper].points", [64, 64], allow_large=False, memory=2**30)


def test_a_streamed_run_is_held_to_its_bounded_memory_not_its_rows() -> None:
    """10^6 points x 100 steps: kept in memory 10^8 point-rows (~90 GB) would be refused;
    streamed (what ``frictionlab simulate`` does with a programme) it needs the per-point
    state only, and runs on a 24 GB machine."""
    counts = [(100, "[[program]] #1.steps")]
    held = largest(counts, 10**6, "[run].n_points")
    streamed = largest(counts, 10**6, "[run].n_points", streamed=True)
    with pytest.raises(InputError, match="of memory"):
        check_run_size(held, allow_large=False, memory=24 * 2**30)
    check_run_size(streamed, allow_large=False, memory=24 * 2**30)
    assert streamed.memory < 0.05 * held.memory
    assert streamed.output == held.output  # the same history.csv either way


def test_every_divides_the_recorded_rows_and_the_output() -> None:
    """1000 steps in one segment, every = 10: at most 1 + 100 + 2 rows (each segment's first
    and last step are always kept), against 1001."""
    one = largest([(1000, "k")], 5, "n", every=1, streamed=True)
    tenth = largest([(1000, "k")], 5, "n", every=10, streamed=True)
    assert one.recorded_rows == 1001
    assert tenth.recorded_rows == 1 + 100 + 2
    only_two = largest([(1000, "k")], 5, "n", every=10, recorded_points=2, streamed=True)
    assert only_two.output < tenth.output < one.output


def test_a_run_longer_than_a_day_is_refused_naming_its_key(tmp_path: Path) -> None:
    """One point, 10^9 steps recorded every 10^6: small in memory and on disk, but at
    >= 0.2 ms per driver step it would compute for days."""
    text = BIG.replace("steps = 10", "steps = 1000000000") + "[output]\nevery = 1000000\n"
    with pytest.raises(InputError) as err:
        parse_scenario(tomllib.loads(text))
    message = str(err.value)
    assert "[[program]] #1.steps" in message and "days of computing" in message
    assert "[run].allow_large = true" in message and "\n" not in message
    parse_scenario(tomllib.loads(text.replace("[initial]", "[run]\nallow_large = true\n[initial]")))


def test_output_beyond_the_free_disk_space_is_refused(tmp_path: Path) -> None:
    estimate = largest([(10**6, "[[program]] #1.steps")], 100, "[run].n_points", streamed=True)
    with pytest.raises(InputError, match=r"free on the disk of .*\[output\]\.every"):
        check_output_space(estimate, tmp_path / "out", allow_large=False, free=10**9)
    check_output_space(estimate, tmp_path / "out", allow_large=False, free=10**13)
    check_output_space(estimate, tmp_path / "out", allow_large=True, free=1)
    small = largest([(10, "[[program]] #1.steps")], 1, "[run].n_points", streamed=True)
    check_output_space(small, tmp_path / "out" / "deeper", allow_large=False)  # real disk


def test_many_labelled_curves_get_a_colour_bar_not_a_legend_entry_each(tmp_path: Path) -> None:
    """40 legend entries overflowed the axes (and collapsed the layout); above
    MAX_LEGEND_CURVES the colours are explained by a colour bar of the point number."""
    n = MAX_CURVES + 10
    _, history = _run(n)
    labels = [f"point {i + 1}" for i in range(n)]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # e.g. "constrained_layout not applied"
        fig = plot_friction(history, labels)
        save_figure(fig, tmp_path / "f.png")
    ax_t = fig.axes[1]
    entries = [t.get_text() for t in ax_t.get_legend().get_texts()]
    assert len(entries) <= MAX_LEGEND_CURVES and not any(e.startswith("point ") for e in entries)
    assert [ax.get_ylabel() for ax in fig.axes[2:]] == ["point number"]
    assert fig.axes[2].get_ylim() == (1.0, float(n))  # the points' own numbers
    _, few = _run(3)
    fig = plot_friction(few, ["a", "b", "c"])
    assert len(fig.axes) == 2  # few curves: a legend entry each, no colour bar
    assert {"a", "b", "c"} <= {t.get_text() for t in fig.axes[1].get_legend().get_texts()}
