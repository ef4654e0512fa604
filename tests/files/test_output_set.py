"""Whole output sets: --out holds the complete old set or the complete new one, never a mix."""

from __future__ import annotations

import json
import os
import random
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from frictionlab.cli import main
from frictionlab.errors import InputError
from frictionlab.io.output_set import OutputError, output_set

SCENARIO = """
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
steps = 5
"""


def _names(path: Path) -> list[str]:
    return sorted(p.name for p in path.iterdir())


def _write_set(out: Path, files: dict[str, str], **kw: bool) -> None:
    with output_set(out, **kw) as oset:
        for name, text in files.items():
            (oset.staging / name).write_text(text)


def test_a_new_set_replaces_the_old_one_as_a_whole(tmp_path: Path) -> None:
    out = tmp_path / "out"
    _write_set(out, {"summary.json": "1", "traction_path.png": "old"})
    _write_set(out, {"summary.json": "2"})
    assert _names(out) == ["summary.json"] and (out / "summary.json").read_text() == "2"
    assert _names(tmp_path) == ["out"]  # no staging, old set or lock left beside it


def test_a_2d_run_then_a_1d_run_leaves_no_stale_plot(tmp_path: Path) -> None:
    scenario = tmp_path / "s.toml"
    scenario.write_text(SCENARIO.replace("distance = 0.2", "distance = 0.2\ndirection_deg = 30"))
    out = tmp_path / "out"
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet"]) == 0
    assert "traction_path.png" in _names(out)
    scenario.write_text(SCENARIO)
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet"]) == 0
    assert _names(out) == ["friction.png", "history.csv", "peaks.csv", "points.csv", "summary.json"]


def test_a_foreign_directory_is_refused_unless_overwrite(tmp_path: Path) -> None:
    out = tmp_path / "mine"
    out.mkdir()
    (out / "thesis.tex").write_text("precious")
    with pytest.raises(InputError, match=r"--out .*mine.* 'thesis.tex'.*--overwrite"):
        _write_set(out, {"summary.json": "1"})
    assert _names(out) == ["thesis.tex"]
    _write_set(out, {"summary.json": "1"}, overwrite=True)
    assert _names(out) == ["summary.json"]


@pytest.mark.parametrize("value", ["", ".", "./"])
def test_the_current_directory_is_refused(
    value: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "s.toml").write_text(SCENARIO)
    assert main(["simulate", "s.toml", "--out", value, "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--out" in err[0] and "current directory" in err[0]
    assert _names(tmp_path) == ["s.toml"]


def test_a_second_run_on_the_same_out_is_refused(tmp_path: Path) -> None:
    out = tmp_path / "out"
    with output_set(out) as first:
        (first.staging / "summary.json").write_text("1")
        with pytest.raises(InputError, match="being written by another frictionlab run"):
            _write_set(out, {"summary.json": "2"})
    assert (out / "summary.json").read_text() == "1"


def test_a_write_error_changes_nothing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    _write_set(out, {"summary.json": "old"})
    nospace = pytest.raises(OutputError, match="No space left on device; nothing was changed")
    with nospace, output_set(out) as oset:
        (oset.staging / "history.csv").write_text("partial")
        raise OSError(28, os.strerror(28))
    assert _names(out) == ["summary.json"] and (out / "summary.json").read_text() == "old"
    assert _names(tmp_path) == ["out"]


def test_leftovers_of_a_killed_run_are_cleaned(tmp_path: Path) -> None:
    out = tmp_path / "out"
    (tmp_path / ".out.new-abc").mkdir()
    (tmp_path / ".out.new-abc" / "history.csv").write_text("x" * 1000)
    (tmp_path / ".out.old-def").mkdir()  # an old set moved aside, out itself missing
    (tmp_path / ".out.old-def" / "summary.json").write_text("old")
    (tmp_path / ".out.lock").write_text("")
    with pytest.raises(InputError), output_set(out):  # the old set is restored first
        assert (out / "summary.json").read_text() == "old"
        raise InputError("stop")
    assert _names(tmp_path) == ["out"] and _names(out) == ["summary.json"]


_WRITER = textwrap.dedent(
    """
    import json, sys
    from pathlib import Path
    from frictionlab.io.output_set import output_set
    out = Path(sys.argv[1])
    generation = 0
    while True:
        generation += 1
        with output_set(out) as oset:
            for name in ("history.csv", "friction.png", "healing.csv"):
                (oset.staging / name).write_text(f"{generation}\\n" * 20000)
            (oset.staging / "summary.json").write_text(json.dumps({"generation": generation}))
        print(generation, flush=True)
    """
)


@pytest.mark.slow
def test_kill_9_at_random_moments_leaves_a_complete_set(tmp_path: Path) -> None:
    out = tmp_path / "out"
    rng = random.Random(13)
    seen = set()
    for _ in range(6):
        proc = subprocess.Popen(
            [sys.executable, "-c", _WRITER, str(out)],
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
        assert proc.stdout is not None
        proc.stdout.readline()  # at least one set was published: the kill falls mid-write
        time.sleep(rng.uniform(0.0, 0.3))
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        generation = json.loads((out / "summary.json").read_text())["generation"]
        seen.add(generation)
        assert _names(out) == ["friction.png", "healing.csv", "history.csv", "summary.json"]
        for name in ("history.csv", "friction.png", "healing.csv"):
            assert (out / name).read_text() == f"{generation}\n" * 20000
    _write_set(out, {"summary.json": "{}"})  # the next run cleans what the kills left
    assert _names(tmp_path) == ["out"]
    assert len(seen) > 1


def test_disk_full_during_simulate_exits_1_and_keeps_the_old_set(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """ENOSPC while writing summary.json (history.csv already written): exit 1, old set kept."""
    import frictionlab.app.outputs as results

    scenario = tmp_path / "s.toml"
    scenario.write_text(SCENARIO)
    out = tmp_path / "out"
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet", "--no-plots"]) == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}

    def full(*args: object, **kw: object) -> None:
        raise OSError(28, os.strerror(28), "summary.json")

    monkeypatch.setattr(results, "write_json_atomic", full)
    scenario.write_text(SCENARIO.replace("mu_k = 0.3", "mu_k = 0.2"))
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet", "--no-plots"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "No space left on device; nothing was changed" in err[0]
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert _names(tmp_path) == ["out", "s.toml"]
