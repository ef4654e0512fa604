"""Slide-hold-slide analysis: restart peaks against the closed-form recovery, healing rate."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main
from frictionlab.demo import bundled_scenario
from frictionlab.driver import Hold, Slide, simulate
from frictionlab.driver.healing import healing_analysis
from frictionlab.subloading import SubloadingParams

MU_S, MU_K, XI = 0.5, 0.3, 1e-3
HOLDS = np.array([1.0, 10.0, 100.0, 1000.0, 1e4])


def recovered(mu0: float, t: float) -> float:
    """Spec §2.6 hold recovery (m = n = 1): mu_s - (mu_s - mu_0) exp(-xi t/mu_s)."""
    return MU_S - (MU_S - mu0) * math.exp(-XI * t / MU_S)


@pytest.fixture(scope="module")
def stiff_shs():
    # Large alpha_t and u, small kappa: the restart re-loads over ~1e-4 m of slip, so the
    # peak is the recovered mu less at most kappa * 1e-4 ~ 1e-4 of softening.
    params = SubloadingParams(mu_s=MU_S, mu_k=MU_K, u=1e4, kappa=1.0, xi=XI,
                              alpha_n=1e5, alpha_t=1e5)  # fmt: skip
    program = (
        Slide(velocity=0.1, distance=1.0, steps=500),
        Hold(duration=HOLDS),
        Slide(velocity=0.1, distance=0.005, steps=500),
    )
    return simulate(params, program)


def test_restart_peak_is_the_closed_form_recovery(stiff_shs) -> None:
    h = stiff_shs
    healing = healing_analysis(h)
    assert healing is not None and len(healing.records) == HOLDS.size
    for r, t_h in zip(healing.records, HOLDS, strict=True):
        assert r.hold_time == pytest.approx(t_h, rel=1e-12)
        # friction before = the ratio at the stop (end of the first slide, row 500)
        assert r.friction_before == h.friction_ratio[500, r.point - 1]
        expected = recovered(r.friction_before, t_h)
        assert r.restart_peak <= expected + 1e-6
        assert r.restart_peak == pytest.approx(expected, abs=5e-4)
        assert r.delta_mu == pytest.approx(expected - r.friction_before, abs=5e-4)


def test_healing_rate_is_the_least_squares_slope_of_the_closed_form(stiff_shs) -> None:
    healing = healing_analysis(stiff_shs)
    assert healing is not None and healing.rate_per_decade is not None
    mu0 = healing.records[0].friction_before
    delta = [recovered(mu0, t) - mu0 for t in HOLDS]
    slope, intercept = np.polyfit(np.log10(HOLDS), delta, 1)
    assert healing.rate_per_decade == pytest.approx(slope, abs=5e-4)
    assert healing.intercept == pytest.approx(intercept, abs=5e-4)
    assert healing.rate_per_decade > 0


def test_several_holds_of_one_point_and_holds_without_restart() -> None:
    params = SubloadingParams(mu_s=MU_S, mu_k=MU_K, u=100.0, kappa=1.0, xi=XI)
    program = (
        Slide(velocity=0.1, distance=0.5, steps=100),
        Hold(duration=10.0),
        Slide(velocity=0.1, distance=0.2, steps=100),
        Hold(duration=100.0),
        Slide(velocity=0.1, distance=0.2, steps=100),
        Hold(duration=1000.0),  # no slide after it: not a restart
    )
    h = simulate(params, program)
    healing = healing_analysis(h)
    assert healing is not None
    assert [r.hold_segment for r in healing.records] == [2, 4]
    assert [r.hold_time for r in healing.records] == pytest.approx([10.0, 100.0])
    second = h.segments[3]
    assert healing.records[1].friction_before == h.friction_ratio[second.first_row - 1, 0]
    assert healing_analysis(simulate(params, program[:1])) is None
    one = healing_analysis(simulate(params, program[:3]))
    assert one is not None and one.rate_per_decade is None  # one hold time: no slope


def test_simulate_writes_healing_outputs(tmp_path: Path, capsys) -> None:
    with bundled_scenario("slide_hold_slide") as path:
        code = main(["simulate", str(path), "--out", str(tmp_path)])
    assert code == 0
    shown = capsys.readouterr().out
    assert "restart peaks after holds" in shown and "healing rate" in shown
    summary = json.loads((tmp_path / "summary.json").read_text())
    records = summary["healing"]["records"]
    assert [r["hold_time"] for r in records] == pytest.approx(HOLDS.tolist())
    peaks = [r["restart_peak"] for r in records]
    assert np.all(np.diff(peaks) > 0) and max(peaks) <= MU_S  # spec A3
    lines = (tmp_path / "healing.csv").read_text().splitlines()
    assert lines[-1].split(",")[0] == "5" and (tmp_path / "healing.png").stat().st_size > 1000
