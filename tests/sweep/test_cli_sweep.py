"""`frictionlab sweep` end to end: outputs per case, failures, resume after a kill, Dask."""

from __future__ import annotations

import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from frictionlab.cli import main

from .support import read_sweep_table, write_sweep

ROUGH = """\
mu0 = 0.3
[lower]
kind = "wedge"
angles_deg = [30.0, 15.0]
wavelength = 1.0e-3
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0, 90.0]
load = 2.0e-6
[lattice]
stations = 200
time_samples = 4
"""


def read_table(out: Path) -> pd.DataFrame:
    return read_sweep_table(out)


@pytest.mark.slow
def test_grid_runs_every_case_into_its_own_directory(tmp_path: Path, capsys) -> None:
    sweep = write_sweep(
        tmp_path,
        'title = "tiny"\n[grid]\n"program.2.duration" = [1.0, 1000.0]\n'
        '"program.3.velocity" = [0.1]\n',
    )
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out), "--workers", "1"]) == 0
    table = read_table(out)
    assert len(table) == 2 and set(table["status"]) == {"ok"}
    assert table["program.2.duration"].tolist() == [1.0, 1000.0]
    for _, row in table.iterrows():
        case = out / "cases" / row["id"]
        record = json.loads((case / "case.json").read_text())
        assert record["overrides"] == {
            "program.2.duration": row["program.2.duration"],
            "program.3.velocity": row["program.3.velocity"],
        }
        assert {"history.csv", "summary.json", "friction.png"} <= set(record["files"])
        summary = json.loads((case / "summary.json").read_text())
        assert summary["inputs"]["program"][1]["duration"] == row["program.2.duration"]
        assert row["peak_friction_ratio"] == summary["points"][0]["peak"]["friction_ratio"]
    # physics through the table: a longer hold recovers more, so the restart rises higher
    by_hold = table.set_index("program.2.duration")
    assert by_hold.loc[1000.0, "delta_mu"] > by_hold.loc[1.0, "delta_mu"] + 0.05
    assert (out / "sweep.png").read_bytes()[:4] == b"\x89PNG"
    # a case's outputs are those of the command run on its own with the same overrides
    alone = tmp_path / "alone"
    sets = ["--set", "program.2.duration=1000.0", "--set", "program.3.velocity=0.1"]
    assert main(["simulate", str(tmp_path / "base.toml"), "--out", str(alone), "--quiet",
                 "--no-plots", *sets]) == 0  # fmt: skip
    case = out / "cases" / table["id"][1]
    assert (case / "history.csv").read_bytes() == (alone / "history.csv").read_bytes()
    assert (case / "healing.csv").read_bytes() == (alone / "healing.csv").read_bytes()
    assert "2 cases (0 done before, 2 run" in capsys.readouterr().out
    # a second run finds everything done and repeats nothing
    stamps = {p: p.stat().st_mtime_ns for p in out.glob("cases/*/*")}
    assert main(["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots"]) == 0
    assert {p: p.stat().st_mtime_ns for p in out.glob("cases/*/*")} == stamps


def test_a_failed_case_is_recorded_and_the_sweep_goes_on(tmp_path: Path) -> None:
    (tmp_path / "rough.toml").write_text(ROUGH)
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(
        'base = "rough.toml"\n[grid]\n'
        '"lower.angles_deg" = [[30.0, 15.0], [80.0, 15.0], [20.0, 20.0]]\n'
    )
    out = tmp_path / "out"
    code = main(["sweep", str(sweep), "--out", str(out), "--workers", "1", "--no-plots"])
    assert code == 1
    table = read_table(out)
    assert table["status"].tolist() == ["ok", "failed", "ok"]
    assert "validity" in table["error"][1] and table["error"][0] == ""
    assert float(table["mu_max"][0]) > 0.3 and table["mu_max"][1] == ""
    failed = json.loads((out / "cases" / table["id"][1] / "case.json").read_text())
    assert failed["status"] == "failed" and "Eq 1" in failed["error"]
    assert (out / "cases" / table["id"][2] / "polar.csv").is_file()


@pytest.mark.slow
def test_killed_sweep_resumes_without_losing_or_repeating(tmp_path: Path) -> None:
    sweep = write_sweep(
        tmp_path, '[grid]\n"program.2.duration" = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]\n', steps=1000,
    )  # fmt: skip
    out = tmp_path / "out"
    argv = [sys.executable, "-m", "frictionlab", "sweep", str(sweep), "--out", str(out),
            "--workers", "1", "--no-plots", "--quiet"]  # fmt: skip
    proc = subprocess.Popen(argv, start_new_session=True)
    try:
        deadline = time.monotonic() + 120
        while len(list(out.glob("cases/*/case.json"))) < 2:
            assert proc.poll() is None, "the sweep ended before it could be killed"
            assert time.monotonic() < deadline, "no case finished in 120 s"
            time.sleep(0.05)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)  # the sweep and its worker processes
        proc.wait()
    done = {p.parent.name: p.stat().st_mtime_ns for p in out.glob("cases/*/case.json")}
    assert 2 <= len(done) < 6, "the kill came too late to test a resume"
    resumed = time.time_ns()
    assert main(["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots",
                 "--workers", "1"]) == 0  # fmt: skip
    table = read_table(out)
    assert len(table) == 6 and set(table["status"]) == {"ok"}  # nothing lost
    after = {p.parent.name: p.stat().st_mtime_ns for p in out.glob("cases/*/case.json")}
    assert set(after) == set(table["id"])
    assert {k: after[k] for k in done} == done  # nothing repeated
    assert all(after[k] >= resumed for k in set(after) - set(done))  # the rest ran once, now


def test_dask_local_cluster(tmp_path: Path) -> None:
    distributed = pytest.importorskip(
        "distributed", reason="dask.distributed is not installed (pip install 'frictionlab[dask]')"
    )
    sweep = write_sweep(tmp_path, '[[case]]\n"law.mu_s" = 0.6\n[[case]]\n"law.mu_k" = 0.2\n')
    out = tmp_path / "out"
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None
    ) as cluster:
        code = main(["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots",
                     "--scheduler", cluster.scheduler_address])  # fmt: skip
    assert code == 0
    table = read_table(out)
    assert table["status"].tolist() == ["ok", "ok"]
    assert table["law.mu_s"].tolist() == ["0.6", ""] and table["law.mu_k"][1] == "0.2"
    # the steady value follows mu_k: the case with mu_k = 0.2 ends lower
    final = table["final_friction_ratio"].astype(float)
    assert final[1] < final[0] - 0.05


@pytest.mark.parametrize(
    ("body", "words"),
    [
        ('[grid]\n"law.mu_S" = [0.5]\n', "base scenario has no 'law.mu_S'"),
        ("[grid]\n", "[grid] is empty"),
        ('[grid]\n"law.nonsense" = [0.5]\n', "no 'law.nonsense'"),
        ('[grid]\n"law.mu_k" = [0.3, 0.7]\n', "sweep case 2 (law.mu_k = 0.7)"),
        ('[grid]\n"program.9.steps" = [3]\n', "entry number from 1 to 3"),
        ('surprise = 1\n[grid]\n"law.mu_s" = [0.5]\n', "unknown key surprise"),
    ],
)
def test_bad_input_exits_2_with_one_line_before_running(
    tmp_path: Path, capsys, body: str, words: str
) -> None:
    sweep = write_sweep(tmp_path, body)
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1
    assert not out.exists()  # validated before anything ran or was written


def test_unwritable_out_is_bad_input(tmp_path: Path, capsys) -> None:
    sweep = write_sweep(tmp_path, '[grid]\n"law.mu_s" = [0.5]\n')
    (tmp_path / "file").write_text("")
    assert main(["sweep", str(sweep), "--out", str(tmp_path / "file" / "out")]) == 2
    assert "cannot write to --out" in capsys.readouterr().err


def test_bundled_example_validates(tmp_path: Path) -> None:
    from importlib import resources

    from frictionlab.app.sweep import load_spec

    path = Path(str(resources.files("frictionlab") / "data" / "sweeps" / "slide_hold_slide.toml"))
    spec, command, tasks = load_spec(path, plots=False)
    assert command == "simulate" and len(tasks) == 12
    assert spec.keys == ("program.2.duration", "program.1.velocity+program.3.velocity")
    assert tasks[1].sets == (
        "program.2.duration=1.0",
        "program.1.velocity=1e-05",
        "program.3.velocity=1e-05",
    )


TABLE_PROGRAM = """
[[program]]
kind = "table"
file = "tables/slip.csv"
"""


def _table_sweep(tmp: Path, slip_end: float) -> Path:
    """A sweep whose base scenario's last segment reads tables/slip.csv (time, slip_1)."""
    sweep = write_sweep(tmp, '[grid]\n"program.2.duration" = [1.0, 10.0]\n')
    base = tmp / "base.toml"
    base.write_text(base.read_text() + TABLE_PROGRAM)
    (tmp / "tables").mkdir(exist_ok=True)
    (tmp / "tables" / "slip.csv").write_text(f"time,slip_1\n0,0\n1,{slip_end!r}\n")
    return sweep


def test_a_task_carries_the_base_and_the_files_it_names(tmp_path: Path) -> None:
    """A worker that cannot see the sweep's folder still runs the case, from the task alone."""
    from frictionlab.app.sweep import load_spec
    from frictionlab.app.sweep_task import run_task

    here = tmp_path / "here"
    here.mkdir()
    _table_sweep(here, 0.05)
    _, _, tasks = load_spec(here / "sweep.toml", plots=False)
    original = (here / "base.toml").resolve()
    moved = here.rename(tmp_path / "elsewhere")  # the worker has no file at those paths
    result = run_task(tasks[0])
    assert result.ok, result.error
    summary = json.loads(result.files["summary.json"])
    assert summary["scenario"] == str(original)  # the outputs name the original inputs
    recorded = {item["path"] for item in summary["provenance"]["inputs"]}
    assert recorded == {str(original), str(original.parent / "tables" / "slip.csv")}
    # the table was read: the last segment slides 0.05 m more than the base programme
    history = pd.read_csv(io.BytesIO(result.files["history.csv"]), comment="#")
    alone = tmp_path / "alone"
    assert main(["simulate", str(moved / "base.toml"), "--out", str(alone), "--quiet",
                 "--no-plots", "--set", "program.2.duration=1.0"]) == 0  # fmt: skip
    expected = pd.read_csv(alone / "history.csv", comment="#")
    assert history.shape == expected.shape
    assert np.array_equal(history.to_numpy(), expected.to_numpy())


@pytest.mark.slow
def test_a_changed_table_reruns_the_cases_that_read_it(tmp_path: Path) -> None:
    sweep = _table_sweep(tmp_path, 0.05)
    out = tmp_path / "out"
    argv = ["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots", "--workers", "1"]
    assert main(argv) == 0
    first = {p.parent.name: p.read_bytes() for p in out.glob("cases/*/history.csv")}
    stamps = {p: p.stat().st_mtime_ns for p in out.glob("cases/*/case.json")}
    assert main(argv) == 0  # unchanged inputs: nothing runs again
    assert {p: p.stat().st_mtime_ns for p in out.glob("cases/*/case.json")} == stamps
    (tmp_path / "tables" / "slip.csv").write_text("time,slip_1\n0,0\n1,0.1\n")
    assert main(argv) == 0  # only the table changed: every case runs again, on the new table
    second = {p.parent.name: p.read_bytes() for p in out.glob("cases/*/history.csv")}
    assert set(second) == set(first) and all(second[k] != first[k] for k in first)
    assert all(p.stat().st_mtime_ns > stamps[p] for p in stamps)
