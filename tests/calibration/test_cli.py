"""`frictionlab calibrate` end to end: outputs, fitted.toml runs with simulate, bad input."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main

from .support import (
    TRUE,
    config,
    make_curve,
    write_config,
    write_export,
)

NAMES = ["mu_s", "mu_k", "u", "kappa", "xi"]
START = dict(mu_s=0.55, mu_k=0.25, u=5.0e4, kappa=1000.0, xi=1.0e-2)


@pytest.fixture(scope="module")
def calibrated(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, int]:
    root = tmp_path_factory.mktemp("calibrate")
    write_export(root / "run.csv", make_curve(0.002, seed=4))
    cfg = write_config(
        root / "calibrate.toml",
        config("run.csv", NAMES, START, profile_points=5, profile_max=1),
    )
    out = root / "out"
    code = main(["calibrate", str(cfg), "--out", str(out), "--quiet"])
    return cfg, out, code


def read_csv(path: Path, keys: tuple[str, ...]) -> dict[str, np.ndarray]:
    with open(path, newline="") as handle:
        rows = [
            {t.rpartition(" [")[0]: v for t, v in row.items()} for row in csv.DictReader(handle)
        ]
    return {k: np.array([float(r[k]) for r in rows]) for k in keys}


def test_outputs_and_fit_json(calibrated, check_summary) -> None:
    _, out, code = calibrated
    assert code == 0
    for name in ("fitted.toml", "summary.json", "fit.json", "curves.csv", "curve_1.png",
                 "correlation.png", "report.html"):  # fmt: skip
        assert (out / name).is_file(), name
    fit = check_summary(out / "summary.json")
    # fit.json: the deprecated copy of summary.json, kept for one release
    assert (out / "fit.json").read_bytes() == (out / "summary.json").read_bytes()
    assert [Path(i["path"]).suffix for i in fit["provenance"]["inputs"]] == [".toml", ".csv"]
    assert list(fit["parameters"]) == NAMES
    for name, entry in fit["parameters"].items():
        assert abs(entry["value"] - TRUE[name]) < 4.0 * entry["stderr"], name
    corr = np.array(fit["correlation"]["matrix"])
    assert corr.shape == (5, 5) and fit["correlation"]["names"] == NAMES
    assert fit["n_points"] == 3401 and fit["cost"] > 0
    assert fit["identifiability"] and all(isinstance(s, str) for s in fit["identifiability"])
    # The profiled parameter has its figure and a 95 % range in fit.json.
    (name,) = fit["profiles"]
    assert (out / f"profile_{name}.png").is_file()
    assert len(fit["profiles"][name]["interval_95"]) == 2
    html = (out / "report.html").read_text()
    assert "Uncertainty and identifiability" in html and "curve_1.png" in html


def test_fitted_toml_runs_with_simulate_and_reproduces_the_model(calibrated, tmp_path) -> None:
    _, out, _ = calibrated
    code = main(["simulate", str(out / "fitted.toml"), "--out", str(tmp_path), "--quiet",
                 "--no-plots"])  # fmt: skip
    assert code == 0
    hist = read_csv(tmp_path / "history.csv", ("time", "friction_ratio"))
    curves = read_csv(out / "curves.csv", ("time", "data", "model", "residual"))
    # The model column of curves.csv is the simulated friction ratio at the data times.
    model = np.interp(curves["time"], hist["time"], hist["friction_ratio"])
    np.testing.assert_allclose(model, curves["model"], rtol=0, atol=1e-12)
    residual = curves["model"] - curves["data"]
    np.testing.assert_allclose(curves["residual"], residual, atol=1e-15)


def _bad(tmp_path: Path, data: dict, csv_lines: list[str] | None = None) -> tuple[int, Path]:
    if csv_lines is None:
        write_export(tmp_path / "run.csv", make_curve(0.0))
    else:
        (tmp_path / "run.csv").write_text("\n".join(csv_lines) + "\n")
    cfg = write_config(tmp_path / "c.toml", data)
    out = tmp_path / "out"
    return main(["calibrate", str(cfg), "--out", str(out), "--quiet"]), out


def _base() -> dict:
    return config("run.csv", NAMES, START)


@pytest.mark.parametrize(
    ("change", "needle"),
    [
        (
            lambda d: d["data"][0]["units"].update(time="parsec"),
            "units.time: 'parsec' is not a unit of time",
        ),
        (lambda d: d["data"][0]["columns"].update(friction_ratio="mu"), "missing column 'mu'"),
        (lambda d: d["fit"].update(parameters=["mu_s", "lambda"]), "[fit].parameters"),
        (lambda d: d["fit"].update(bounds={"kappa": [1.0, 10.0]}), "[law].kappa"),
        (lambda d: d["fit"].update(bounds={"alpha_n": [1.0, 10.0]}), "[fit].bounds.alpha_n"),
        (lambda d: d["data"][0].update(weight=-1.0), "[[data]] #1.weight"),
        (lambda d: d["data"][0]["program"][1].update(duration=[10.0, 20.0]), "per-point lists"),
        (lambda d: d["data"][0]["program"][4].update(distance=1e-4), "past the end"),
        (lambda d: d["data"][0]["program"][0].update(velocity=-1.0), "velocity"),
        (lambda d: d.update(data=[]), "[[data]]"),
    ],
)
def test_bad_config_exits_2_with_one_line_and_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], change, needle
) -> None:
    data = _base()
    change(data)
    code, out = _bad(tmp_path, data)
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and needle in err, err
    assert not out.exists()


def test_bad_data_file_exits_2_naming_the_file(tmp_path, capsys) -> None:
    lines = [",Time,Displacement,COF", ",min,mm,-"] + [
        f"{i},{t},{t},{0.3}" for i, t in enumerate([0.0, 0.1, 0.05, 0.2, 0.3, 0.4])
    ]
    code, out = _bad(tmp_path, _base(), lines)
    err = capsys.readouterr().err.strip()
    assert code == 2 and not out.exists()
    assert "[[data]] #1.file 'run.csv'" in err and "not strictly increasing" in err


def test_data_a_hair_past_the_end_are_accepted(tmp_path) -> None:
    # 1e-7 relative past the programme's end (the lab clock's round-off) is tolerated.
    duration = 6.0 + 30.0 + 2.0 + 300.0 + 2.0
    times = np.linspace(0.0, duration * (1 + 1e-7), 12)
    lines = [",Time,Displacement,COF", ",s,mm,-"] + [
        f"{i},{float(t)!r},0.0,0.3" for i, t in enumerate(times)
    ]
    data = config("run.csv", ["mu_k"], {}, profile=False)
    data["data"][0]["units"] = {"time": "s", "slip": "mm"}
    code, _ = _bad(tmp_path, data, lines)
    assert code == 0


_HEAD = [",Time,Displacement,COF", ",min,mm,-"]
_OK = [f"{i},{0.01 * i},{0.001 * i},0.3" for i in range(6)]


@pytest.mark.parametrize(
    ("lines", "needle"),
    [
        ([*_HEAD, _OK[0], _OK[2], _OK[1], *_OK[3:]], "not strictly increasing"),
        ([*_HEAD, _OK[0], "1,0.01,0.001,nan", *_OK[2:]], "line 4: column 'COF' = 'nan'"),
        (_HEAD + _OK[:3], "only 3 samples"),
        ([",Time,Displacement,mu", ",min,mm,-", *_OK], "missing column 'COF'"),
        ([",Time,Time,Displacement,COF", ",min,min,mm,-"]
         + [f"{i},{0.01 * i},{0.01 * i},0.0,0.3" for i in range(6)], "2 columns for time"),
        ([*_HEAD, "0,-0.01,0.0,0.3", *_OK[1:]], "is negative"),
        ([*_HEAD, _OK[0], "1,0.01,0.001,-0.3", *_OK[2:]], "is negative"),
    ],
)  # fmt: skip
def test_bad_data_corpus_exits_2_with_one_line_and_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], lines: list[str], needle: str
) -> None:
    code, out = _bad(tmp_path, _base(), lines)
    err = capsys.readouterr().err.strip()
    assert code == 2 and not out.exists()
    assert len(err.splitlines()) == 1, err
    assert "[[data]] #1.file 'run.csv'" in err and needle in err, err


def test_two_curves_give_two_runnable_scenarios(tmp_path: Path) -> None:
    write_export(tmp_path / "a.csv", make_curve(0.002, seed=6))
    write_export(tmp_path / "b.csv", make_curve(0.002, seed=7))
    data = config("a.csv", ["mu_k", "xi"], {"mu_k": 0.25, "xi": 1e-2}, profile=False)
    second = dict(data["data"][0], file="b.csv", weight=0.5)
    data["data"].append(second)
    cfg = write_config(tmp_path / "two.toml", data)
    out = tmp_path / "out"
    assert main(["calibrate", str(cfg), "--out", str(out), "--quiet"]) == 0
    fit = json.loads((out / "summary.json").read_text())
    assert [c["file"] for c in fit["curves"]] == ["a.csv", "b.csv"]
    assert fit["n_points"] == 2 * 3401 and (out / "curve_2.png").is_file()
    for name in ("fitted.toml", "fitted_2.toml"):
        assert main(["simulate", str(out / name), "--out", str(tmp_path / name), "--quiet",
                     "--no-plots"]) == 0  # fmt: skip
