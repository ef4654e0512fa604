"""The no-snap-back condition wherever the normal traction is prescribed or reached.

Issue: the check ran only in ``initial_state``; a normal step beyond the threshold followed
by sliding ran silently. Threshold for the cone (spec pitfall 7, Eq 44):
f_n < alpha_t / (kappa (mu_s/mu_k - 1)^m) = 1000 / (1 * (0.5/0.3 - 1)) = 1500 Pa.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from frictionlab.cli import main
from frictionlab.driver import InitialConditions, NormalStep, Slide, simulate
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams, snap_back_violations

LAW = dict(surface="coulomb", alpha_n=1000.0, alpha_t=1000.0, mu_s=0.5, mu_k=0.3, u=100.0,
           kappa=1.0, xi=1e-3)  # fmt: skip
THRESHOLD = 1000.0 / (0.5 / 0.3 - 1.0)


def test_the_threshold_is_where_the_check_switches() -> None:
    params = SubloadingParams(**LAW)  # type: ignore[arg-type]
    ok, bad = snap_back_violations(params, [THRESHOLD * (1 - 1e-9), THRESHOLD * (1 + 1e-9)])
    assert ok == "" and "snap-back" in bad


def test_a_prescribed_normal_traction_beyond_the_threshold_is_refused_before_any_step() -> None:
    params = SubloadingParams(**LAW)  # type: ignore[arg-type]
    program = (NormalStep(traction=3001.0), Slide(velocity=0.1, distance=0.1))
    with pytest.raises(ParameterError, match=r"program\[1\]\.traction.*3001"):
        simulate(params, program, InitialConditions(normal_traction=1.0))


def test_a_change_of_normal_traction_beyond_the_threshold_is_refused() -> None:
    params = SubloadingParams(**LAW)  # type: ignore[arg-type]
    program = (Slide(velocity=0.1, distance=0.01), NormalStep(traction_change=2000.0))
    with pytest.raises(ParameterError, match=r"program\[2\]\.traction_change"):
        simulate(params, program, InitialConditions(normal_traction=1.0))


def test_a_normal_traction_reached_by_approach_is_a_recorded_warning() -> None:
    params = SubloadingParams(**LAW)  # type: ignore[arg-type]
    program = (NormalStep(approach=2.0), Slide(velocity=0.1, distance=0.01))  # f_n = 2001
    h = simulate(params, program, InitialConditions(normal_traction=1.0))
    assert len(h.warnings) == 2  # the step and the slide that follows at f_n = 2001
    assert "segment #1 (normal)" in h.warnings[0] and "2001" in h.warnings[0]
    below = simulate(params, (NormalStep(approach=1.0),), InitialConditions(normal_traction=1.0))
    assert below.warnings == ()


def test_cli_refuses_a_prescribed_traction_and_reports_a_reached_one(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    law = "\n".join(f"{k} = {v!r}" if isinstance(v, str) else f"{k} = {v}"
                    for k, v in LAW.items()).replace("'", '"')  # fmt: skip
    head = f"[law]\n{law}\n[initial]\nnormal_traction = 1.0\n"
    refused = tmp_path / "refused.toml"
    slide = '[[program]]\nkind = "slide"\nvelocity = 0.1\ndistance = 0.01\n'
    refused.write_text(head + '[[program]]\nkind = "normal"\ntraction = 3001.0\n' + slide)
    assert main(["simulate", str(refused), "--out", str(tmp_path / "a"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "program[1].traction" in err[0]
    assert not (tmp_path / "a").exists()
    reached = tmp_path / "reached.toml"
    reached.write_text(head + '[[program]]\nkind = "normal"\napproach = 2.0\n')
    assert main(["simulate", str(reached), "--out", str(tmp_path / "b"), "--quiet"]) == 0
    summary = json.loads((tmp_path / "b" / "summary.json").read_text())
    assert len(summary["warnings"]) == 1 and "snap-back" in summary["warnings"][0]
    assert "warning" in capsys.readouterr().err
