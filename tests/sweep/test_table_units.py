"""sweep.csv titles carry units; a sweep folder written before them still resumes."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from pathlib import Path

import pandas as pd
import pytest

from frictionlab.app import sweep as sweep_app
from frictionlab.app.sweep_task import Task, TaskResult, run_task
from frictionlab.cli import main
from frictionlab.io.tables import read_csv

from .support import read_sweep_table, write_sweep

BODY = '[grid]\n"program.2.duration" = [1.0, 10.0]\n"law.mu_s+law.mu_k" = [0.4]\n'


@pytest.fixture
def ran(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Cases run in this process (the pool's workers would compile the law afresh)."""
    seen: list[str] = []

    def in_process(
        tasks: Sequence[Task], scheduler: object, workers: object
    ) -> Iterator[TaskResult]:
        for task in tasks:
            seen.append(task.case_id)
            yield run_task(task)

    monkeypatch.setattr(sweep_app, "run_tasks", in_process)
    return seen


def test_titles_carry_the_units_the_keys_declare(tmp_path: Path, ran: list[str]) -> None:
    sweep = write_sweep(tmp_path, BODY, steps=5)
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots"]) == 0
    titles = pd.read_csv(out / "sweep.csv", nrows=0).columns.tolist()
    assert titles[:5] == ["case [-]", "id [-]", "status [-]", "program.2.duration [s]",
                          "law.mu_s+law.mu_k [-]"]  # fmt: skip
    assert "peak_friction_ratio [-]" in titles and titles[-2:] == ["seconds [s]", "error [-]"]
    table = read_csv(out / "sweep.csv")  # frictionlab's own table reader: names and units
    assert table.units["program.2.duration"] == "s" and table.units["seconds"] == "s"
    assert table["program.2.duration"].tolist() == [1.0, 10.0]


def test_a_sweep_written_without_units_resumes(tmp_path: Path, ran: list[str]) -> None:
    sweep = write_sweep(tmp_path, BODY, steps=5)
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots"]) == 0
    first = read_sweep_table(out)
    # the folder as an earlier version left it: plain titles, the second case not done
    first.to_csv(out / "sweep.csv", index=False)
    (out / "cases" / first["id"][1] / "case.json").unlink()
    ran.clear()
    assert main(["sweep", str(sweep), "--out", str(out), "--quiet", "--no-plots"]) == 0
    assert ran == [first["id"][1]]  # only the case without a record ran again
    again = read_sweep_table(out)
    assert again["status"].tolist() == ["ok", "ok"]
    assert again["peak_friction_ratio"].tolist() == first["peak_friction_ratio"].tolist()
    assert "program.2.duration [s]" in pd.read_csv(out / "sweep.csv", nrows=0).columns
