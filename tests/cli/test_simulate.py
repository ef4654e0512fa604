"""`frictionlab simulate` end to end: bundled scenarios, physics in the output, bad input."""

from __future__ import annotations

import csv
import itertools
import json
import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main
from frictionlab.demo import bundled_scenario

REQUIRED_COLUMNS = [
    "time",
    "slip_1",
    "slip_2",
    "approach",
    "traction_1",
    "traction_2",
    "traction_n",
    "friction_ratio",
    "R",
    "F",
    "plastic_slip",
    "status",
]
# the law of the bundled cone scenarios (1 MPa, alpha = 1e12 Pa/m, slips of mm)
MU_S, MU_K, KAPPA, XI, U = 0.5, 0.3, 1e3, 1e-3, 1e5
FN, ALPHA_T = 1e6, 1e12


def mu_ss(v: float) -> float:
    return (KAPPA * v + XI) / (KAPPA * v / MU_K + XI / MU_S)


def read_history(out: Path) -> dict[int, dict[str, np.ndarray]]:
    """history.csv -> {point: {column: array}}, read with the csv module only.

    Titles are ``name [unit]``; the keys here are the names.
    """
    with open(out / "history.csv", newline="") as handle:
        rows = [
            {title.rpartition(" [")[0]: value for title, value in row.items()}
            for row in csv.DictReader(handle)
        ]
    points: dict[int, dict[str, list[str]]] = {}
    for row in rows:
        cols = points.setdefault(int(row["point"]), {})
        for key, value in row.items():
            cols.setdefault(key, []).append(value)
    out_cols: dict[int, dict[str, np.ndarray]] = {}
    for p, cols in points.items():
        out_cols[p] = {}
        for key, values in cols.items():
            try:
                out_cols[p][key] = np.array(values, dtype=float)
            except ValueError:
                out_cols[p][key] = np.array(values)
    return out_cols


def simulate(scenario: str | Path, out: Path, *extra: str) -> int:
    if isinstance(scenario, str):
        with bundled_scenario(scenario) as path:
            return main(["simulate", str(path), "--out", str(out), "--quiet", *extra])
    return main(["simulate", str(scenario), "--out", str(out), "--quiet", *extra])


def summary(out: Path) -> dict:  # type: ignore[type-arg]
    return json.loads((out / "summary.json").read_text())


# --------------------------------------------------------------------------- physics
def test_slide_hold_slide_restart_peak_grows_with_hold_time(tmp_path: Path) -> None:
    assert simulate("slide_hold_slide", tmp_path, "--no-plots") == 0
    s = summary(tmp_path)
    holds = s["segments"][1]["resolved"]["duration"]
    peaks = s["segments"][2]["peak_friction_ratio"]
    assert holds == sorted(holds) and len(peaks) == 5
    assert all(b > a for a, b in itertools.pairwise(peaks)) and max(peaks) <= MU_S
    hist = read_history(tmp_path)
    for p, t_h in enumerate(holds, start=1):
        h = hist[p]
        stop = int(np.flatnonzero(h["kind"] == "hold")[0]) - 1
        end = int(np.flatnonzero(h["kind"] == "hold")[-1])
        mu0 = h["F"][stop]
        assert h["F"][end] == pytest.approx(
            MU_S - (MU_S - mu0) * math.exp(-XI * t_h / MU_S), rel=1e-12
        )
        assert h["traction_1"][end] == h["traction_1"][stop]  # no relaxation during the hold


def test_monotonic_steady_friction_matches_mu_ss(tmp_path: Path) -> None:
    assert simulate("monotonic", tmp_path, "--no-plots") == 0
    s = summary(tmp_path)
    V = s["segments"][0]["resolved"]["velocity"]
    final = [p["final"]["friction_ratio"] for p in s["points"]]
    np.testing.assert_allclose(final, [mu_ss(v) for v in V], rtol=1e-6)
    assert all(p["peak"]["friction_ratio"] < MU_S for p in s["points"])
    assert s["inputs"]["law"]["m"] == 1.0 and s["inputs"]["run"]["max_halvings"] == 10  # defaults


def test_ratcheting_per_cycle(tmp_path: Path) -> None:
    assert simulate("ratcheting", tmp_path, "--no-plots") == 0
    h = read_history(tmp_path)[1]
    at_zero = np.flatnonzero((h["step"] > 0) & (np.abs(h["traction_1"]) < 1e-12 * FN))
    per_cycle = np.diff(np.concatenate([[0.0], h["slip_1"][at_zero]]))
    expected = 2.0 / (math.pi * U) * math.log(1.0 / math.cos(math.pi * 0.8 / 2.0))
    assert len(per_cycle) == 5
    np.testing.assert_allclose(per_cycle, expected, rtol=1e-9)


def test_pressure_dependence_with_a_surface_override(tmp_path: Path) -> None:
    assert simulate("pressure", tmp_path, "--no-plots", "--set", 'law.surface="tear"') == 0
    s = summary(tmp_path)
    assert s["inputs"]["law"]["surface"] == "tear"
    fn = np.array(s["inputs"]["initial"]["normal_traction"])
    F, M = s["inputs"]["law"]["F_s"], s["inputs"]["law"]["M"]  # F = F_s = F_k: no softening
    final = np.array([p["final"]["friction_ratio"] for p in s["points"]])
    np.testing.assert_allclose(final, M * np.sqrt(3.0 * (1.0 - fn / F)), rtol=1e-9)


@pytest.mark.slow
def test_stick_slip_scenario_regimes(tmp_path: Path) -> None:
    assert simulate("stick_slip", tmp_path, "--no-plots") == 0
    s = summary(tmp_path)["stick_slip"]
    osc = s["friction_oscillation_last_quarter"]
    assert osc[0] > 0.1 and osc[1] < 1e-6 and osc[2] < 1e-6
    assert s["slip_events"][0] >= 3 and s["slip_events"][1] == 0
    v_slow = summary(tmp_path)["inputs"]["machine"]["velocity"][0]
    k_soft = FN * KAPPA * (mu_ss(v_slow) / MU_K - 1.0)
    expected = ALPHA_T * k_soft / (ALPHA_T - k_soft)
    assert s["critical_stiffness"][0] == pytest.approx(expected, rel=1e-12)


TURN = """
[law]
mu_s = 0.5
mu_k = 0.3
[initial]
normal_traction = 1.0
[[program]]
kind = "slide"
velocity = 0.1
distance = 1.0
steps = 50
[[program]]
kind = "turn"
angle_deg = 90.0
distance = 0.05
steps = 8
"""


@pytest.mark.slow
def test_substepping_makes_a_coarse_run_agree_with_a_fine_run(tmp_path: Path) -> None:
    scenario = tmp_path / "turn.toml"
    scenario.write_text(TURN)
    runs = {
        "fine": ["--set", "program.2.steps=8000"],
        "coarse": [],
        "controlled": ["--set", "run.accuracy=1e-5"],
    }
    results = {}
    for name, flags in runs.items():
        assert simulate(scenario, tmp_path / name, "--no-plots", *flags) == 0
        h = read_history(tmp_path / name)[1]
        turn = h["kind"] == "turn"
        rows = np.concatenate([[np.flatnonzero(turn)[0] - 1], np.flatnonzero(turn)])
        step = 1000 if name == "fine" else 1
        results[name] = np.column_stack([h["traction_1"], h["traction_2"]])[rows][::step]
    assert np.abs(results["coarse"] - results["fine"]).max() > 1e-3
    assert np.abs(results["controlled"] - results["fine"]).max() < 1e-4
    work = summary(tmp_path / "controlled")["work"]
    assert work["refined_for_accuracy"] > 0 and work["substeps"] > 58


@pytest.mark.slow
def test_outputs_of_a_2d_programme(tmp_path: Path) -> None:
    assert simulate("orthotropy", tmp_path) == 0
    for name in ("friction.png", "traction_path.png"):
        assert (tmp_path / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    lines = (tmp_path / "history.csv").read_text().splitlines()
    titles = lines[0].split(",")  # pandas-ready: the header row comes first
    assert {"time [s]", "traction_1 [Pa]", "slip_1 [m]", "R [-]"} <= set(titles)
    assert set(REQUIRED_COLUMNS) <= {t.rpartition(" [")[0] for t in titles}
    s = summary(tmp_path)
    assert s["success"] and s["frictionlab"] and s["n_points"] == 6
    assert set(s["outputs"]) == {
        "history.csv",
        "points.csv",
        "peaks.csv",
        "friction.png",
        "traction_path.png",
        "summary.json",
    }
    assert not list(tmp_path.glob(".*.tmp*"))


def test_set_override_changes_the_law(tmp_path: Path) -> None:
    assert simulate("monotonic", tmp_path / "a", "--no-plots", "--set", "law.xi=0.0") == 0
    final = [p["final"]["friction_ratio"] for p in summary(tmp_path / "a")["points"]]
    np.testing.assert_allclose(final, MU_K, rtol=1e-6)  # no recovery: kinetic at every speed


# --------------------------------------------------------------------------- failures
GOOD = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
[initial]
normal_traction = 1.0
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.2
steps = 20
[[program]]
kind = "hold"
duration = 10.0
"""


@pytest.fixture
def write_scenario(tmp_path: Path) -> Iterator:  # type: ignore[type-arg]
    def write(text: str) -> Path:
        path = tmp_path / "scenario.toml"
        path.write_text(text)
        return path

    yield write


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        pytest.param("mu_k = 0.3", "mu_kk = 0.3", "unknown key [law].mu_kk", id="wrong key"),
        pytest.param(
            "velocity = 0.1",
            'velocity = "fast"',
            "[[program]] #1.velocity must be a number",
            id="wrong type",
        ),
        pytest.param(
            "normal_traction = 1.0",
            "",
            "missing required key [initial].normal_traction",
            id="missing value",
        ),
        pytest.param(
            'surface = "coulomb"',
            'surface = "cone"',
            "[law].surface = 'cone' is not allowed",
            id="unknown surface",
        ),
        pytest.param(
            'kind = "hold"',
            'kind = "rest"',
            "[[program]] #2.kind = 'rest' is not allowed",
            id="unknown segment kind",
        ),
        pytest.param(
            "mu_k = 0.3",
            "mu_k = 0.6",
            "[law].mu_k = 0.6 is invalid: allowed 0 < mu_k <= mu_s",
            id="invalid parameter",
        ),
        pytest.param(
            "mu_k = 0.3",
            "mu_k = 0.3\nalpha_t = 0.5\nkappa = 5.0",
            "[law].alpha_t = 0.5 is invalid: allowed alpha_t > C_max f_n kappa",
            id="snap-back",
        ),
        pytest.param(
            "velocity = 0.1",
            "velocity = -0.1",
            "[[program]] #1.velocity",
            id="invalid segment value",
        ),
        pytest.param(
            "normal_traction = 1.0",
            "normal_traction = [1.0, 2.0]\n[run]\nn_points = 3",
            "number of points",
            id="inconsistent points",
        ),
        pytest.param("[[program]]", "[[program]\n", "is not valid TOML", id="malformed file"),
    ],
)
def test_bad_input_is_one_line_exit_2_and_nothing_written(
    write_scenario,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    old: str,
    new: str,
    message: str,
) -> None:  # type: ignore[no-untyped-def]
    assert old in GOOD
    path = write_scenario(GOOD.replace(old, new, 1))
    out = tmp_path / "out"
    assert simulate(path, out) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("frictionlab: error:")
    assert message in err[0]
    assert not out.exists()


def test_unreadable_files(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert simulate(tmp_path / "missing.toml", tmp_path / "out") == 2
    assert "cannot read file" in capsys.readouterr().err
    scenario = tmp_path / "table.toml"
    scenario.write_text(
        GOOD.replace('kind = "hold"\nduration = 10.0', 'kind = "table"\nfile = "nope.csv"')
    )
    assert simulate(scenario, tmp_path / "out") == 2
    assert "cannot read table" in capsys.readouterr().err
    (tmp_path / "bad.csv").write_text("time,slip_1\n0,0\n1,abc\n")
    scenario.write_text(
        GOOD.replace('kind = "hold"\nduration = 10.0', 'kind = "table"\nfile = "bad.csv"')
    )
    assert simulate(scenario, tmp_path / "out") == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "column 'slip_1' must hold numbers" in err[0]
    assert not (tmp_path / "out").exists()


def test_bad_override_and_out_path(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert simulate("monotonic", tmp_path / "o", "--set", "law.mu_s") == 2
    assert "section.key=value" in capsys.readouterr().err
    blocker = tmp_path / "file"
    blocker.write_text("")
    assert simulate("monotonic", blocker) == 2
    assert "not a directory" in capsys.readouterr().err


PATH_ROWS = "0,0,0,1\n1,0.1,0,1\n2,0.2,0,2\n3,0.2,0.1,2\n"
PANDAS_ROWS = "".join(f"{i},{row}\n" for i, row in enumerate(PATH_ROWS.splitlines()))


@pytest.mark.parametrize(
    "text",
    [
        "# a tribometer record\ntime,slip_1,slip_2,normal_traction\n" + PATH_ROWS,
        # pandas.DataFrame.to_csv: an index column with an empty title, units in the titles
        ",time [s],slip_1 [m],slip_2 [m],normal_traction [Pa]\n" + PANDAS_ROWS,
    ],
    ids=["plain", "pandas-to-csv"],
)
def test_table_segment_from_csv(tmp_path: Path, text: str) -> None:
    (tmp_path / "path.csv").write_text(text)
    scenario = tmp_path / "s.toml"
    scenario.write_text(
        GOOD.replace(
            'kind = "hold"\nduration = 10.0', 'kind = "table"\nfile = "path.csv"\nmax_step = 0.01'
        )
    )
    assert simulate(scenario, tmp_path / "out", "--no-plots") == 0
    h = read_history(tmp_path / "out")[1]
    assert h["slip_1"][-1] == pytest.approx(0.2 + 0.2, rel=1e-12)
    assert h["slip_2"][-1] == pytest.approx(0.1, rel=1e-12)
    assert h["traction_n"][-1] == pytest.approx(2.0, rel=1e-12)
    assert h["time"][-1] == pytest.approx(2.0 + 3.0, rel=1e-12)


def test_table_segment_in_other_units_is_refused(tmp_path: Path, capsys) -> None:
    (tmp_path / "path.csv").write_text("time [ms],slip_1 [m]\n0,0\n1,0.1\n")
    scenario = tmp_path / "s.toml"
    scenario.write_text(
        GOOD.replace('kind = "hold"\nduration = 10.0', 'kind = "table"\nfile = "path.csv"')
    )
    assert simulate(scenario, tmp_path / "out", "--no-plots") == 2
    err = capsys.readouterr().err
    assert "column 'time' is in [ms]; allowed: [s]" in err and err.count("\n") == 1


def test_failed_computation_exits_1_and_keeps_the_history(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text = GOOD.replace(
        'kind = "hold"\nduration = 10.0', 'kind = "traction"\ntraction = [0.6, 0.0]\nsteps = 10'
    )
    scenario = tmp_path / "s.toml"
    scenario.write_text(text)
    out = tmp_path / "out"
    assert simulate(scenario, out) == 1
    err = capsys.readouterr().err
    assert "computation failed" in err and "segment #2 (traction)" in err
    s = summary(out)
    assert s["success"] is False and "gross sliding" in s["message"]
    h = read_history(out)[1]
    # softened to about 0.4 by the slide, the contact cannot carry more: the first traction
    # step fails, and the history keeps the complete slide (initial row + 20 steps)
    assert len(h["step"]) == 21 and h["slip_1"][-1] == pytest.approx(0.2, rel=1e-12)
    assert (out / "friction.png").exists()


def test_orthotropy_angle_in_degrees_equals_radians(tmp_path: Path) -> None:
    base = GOOD.replace("mu_k = 0.3", "mu_k = 0.3\northotropy = [1.0, 0.6]")
    (tmp_path / "deg.toml").write_text(
        base.replace("mu_k = 0.3", "mu_k = 0.3\northotropy_angle_deg = 30.0")
    )
    (tmp_path / "rad.toml").write_text(
        base.replace("mu_k = 0.3", f"mu_k = 0.3\northotropy_angle = {math.radians(30.0)!r}")
    )
    assert simulate(tmp_path / "deg.toml", tmp_path / "deg", "--no-plots") == 0
    assert simulate(tmp_path / "rad.toml", tmp_path / "rad", "--no-plots") == 0
    a, b = read_history(tmp_path / "deg")[1], read_history(tmp_path / "rad")[1]
    np.testing.assert_array_equal(a["traction_2"], b["traction_2"])
    assert np.abs(a["traction_2"]).max() > 1e-3  # the turned axes make the response non-coaxial
    both = base.replace(
        "mu_k = 0.3", "mu_k = 0.3\northotropy_angle = 0.1\northotropy_angle_deg = 5.0"
    )
    (tmp_path / "both.toml").write_text(both)
    assert simulate(tmp_path / "both.toml", tmp_path / "both") == 2
    assert not (tmp_path / "both").exists()


def test_broken_pipe_is_not_a_traceback() -> None:
    import subprocess
    import sys

    proc = subprocess.run(
        f"{sys.executable} -m frictionlab --help | head -c 10",
        shell=True, capture_output=True, text=True,
    )  # fmt: skip
    assert "Traceback" not in proc.stderr
