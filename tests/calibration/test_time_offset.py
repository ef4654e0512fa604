"""``[[data]] time_offset = "fit"``: the offset is estimated from the data with the law."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from frictionlab.calibration import Curve
from frictionlab.calibration.model import best_offset
from frictionlab.cli import main
from frictionlab.driver import simulate
from frictionlab.errors import FrictionlabError
from frictionlab.schema.calibrate import load_calibrate

from .support import PROGRAM, TRUE, config, make_curve, true_params, write_config

#: When the recording started on the programme's clock [s] (inside the first slide).
T0 = 4.3


def _late_recording(tmp_path: Path) -> Path:
    """The curve as recorded from programme time T0 on, with the recorder's clock at 0."""
    full = make_curve(0.0)
    kept = (full.time >= T0 - 1e-9) & (full.time <= 330.0)  # stopped 10 s before the end
    assert full.slip is not None
    lines = ["time [s],slip [m],COF"] + [
        f"{float(t) - T0!r},{float(s)!r},{float(r)!r}"
        for t, s, r in zip(full.time[kept], full.slip[kept], full.friction_ratio[kept], strict=True)
    ]
    path = tmp_path / "late.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def _config(tmp_path: Path, **data: object) -> Path:
    cfg = config("late.csv", ["mu_k"], {"mu_k": 0.32}, profile=False)
    del cfg["data"][0]["columns"], cfg["data"][0]["units"]
    cfg["data"][0].update(data)
    return write_config(tmp_path / "calibrate.toml", cfg)


def test_best_offset_of_the_true_law_is_the_recording_start(tmp_path: Path) -> None:
    _late_recording(tmp_path)
    cfg = load_calibrate(_config(tmp_path, time_offset="fit", time_offset_bounds=[0.0, 10.0]))
    (curve,) = cfg.curves
    h = simulate(true_params(), PROGRAM, curve.initial)
    offset = best_offset(h.time[:, 0], h.friction_ratio[:, 0], curve)
    assert offset == pytest.approx(T0, abs=1e-6)


@pytest.mark.slow
def test_calibrate_recovers_a_known_offset_beside_the_law(tmp_path: Path, capsys) -> None:
    _late_recording(tmp_path)
    path = _config(tmp_path, time_offset="fit", time_offset_bounds=[0.0, 10.0])
    out = tmp_path / "out"
    assert main(["calibrate", str(path), "--out", str(out)]) == 0
    summary = json.loads((out / "summary.json").read_text())
    (curve,) = summary["curves"]
    assert curve["time_offset_fitted"] is True
    assert curve["time_offset"] == pytest.approx(T0, abs=1e-4)
    assert summary["parameters"]["mu_k"]["value"] == pytest.approx(TRUE["mu_k"], rel=1e-5)
    assert summary["dof"] == curve["samples"] - 2  # mu_k and the offset
    assert "time offset fitted 4.3" in capsys.readouterr().out


def test_a_fixed_offset_misplaced_by_the_recording_start_fits_worse(tmp_path: Path) -> None:
    """The same file read with offset 0 puts every peak T0 too early: the misfit of the
    true law is large, so estimating the offset matters."""
    _late_recording(tmp_path)
    (curve,) = load_calibrate(_config(tmp_path)).curves
    h = simulate(true_params(), PROGRAM, curve.initial)

    def rms(offset: float) -> float:
        model = np.interp(curve.time + offset, h.time[:, 0], h.friction_ratio[:, 0])
        return float(np.sqrt(np.mean((model - curve.friction_ratio) ** 2)))

    assert rms(0.0) > 0.005 and rms(0.0) > 1e4 * rms(T0)


@pytest.mark.parametrize(
    ("data", "words"),
    [
        ({"time_offset": "fit"}, "time_offset_bounds = None is invalid"),
        ({"time_offset_bounds": [0.0, 1.0]}, "exactly when time_offset = 'fit'"),
        ({"time_offset": "guess"}, "time_offset = 'guess' is invalid: allowed a number"),
        ({"time_offset": "fit", "time_offset_bounds": [0.0, 50.0]}, "high <= 14.3"),
        ({"time_offset": "fit", "time_offset_bounds": [-1.0, 2.0]}, "low >= 0"),
        (
            {"time_offset": "fit", "time_offset_bounds": [0.0, 2.0], "segment_weights": [1.0] * 5},
            "segment_weights",
        ),
    ],
)
def test_bad_offset_keys_are_one_line(tmp_path: Path, data: dict, words: str) -> None:
    _late_recording(tmp_path)
    with pytest.raises(FrictionlabError) as info:
        load_calibrate(_config(tmp_path, **data))
    assert words in str(info.value) and "\n" not in str(info.value)


def test_curve_refuses_bounds_in_the_wrong_order() -> None:
    c = make_curve(0.0)
    with pytest.raises(Exception, match="time_offset_bounds"):
        Curve("c", c.time, c.friction_ratio, PROGRAM, c.initial, offset_bounds=(2.0, 1.0))
