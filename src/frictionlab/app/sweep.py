"""The sweep workflow (``frictionlab sweep SWEEP.toml --out DIR``): a grid of scenarios.

The sweep file (see :mod:`frictionlab.sweep.spec`) names a base scenario (simulate or
roughness) and a ``[grid]`` or ``[[case]]`` list of ``section.key`` overrides. Every case's
scenario is validated before anything runs (bad input: one line, exit 2). The cases run
on a local process pool (``--workers N``) or on a Dask cluster (``--scheduler ADDRESS``).
Each finished case is written at once to ``DIR/cases/<id>/``: the command's usual outputs
(each atomically) and then ``case.json`` (its parameters, status, error). A re-run skips
the cases already done, so a killed sweep loses nothing and repeats nothing. A failed
case is recorded and the sweep goes on; ``DIR/sweep.csv`` (one row per case: parameters,
summary figures, status, error) is rewritten atomically as cases finish, and
``DIR/sweep.png`` is drawn at the end. Exit 1 if any case failed, else 0.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from frictionlab._progress import ProgressFactory
from frictionlab.app.sweep_task import Task, TaskResult, run_task
from frictionlab.errors import InputError, ParameterError, ValidityError
from frictionlab.io.atomic import write_bytes_atomic, write_text_atomic
from frictionlab.io.config import apply_overrides, load_toml
from frictionlab.sweep.cases import check_key, format_overrides, override_strings
from frictionlab.sweep.figures import summary_figures
from frictionlab.sweep.ledger import (
    inputs_sha256,
    is_done,
    make_record,
    read_record,
    write_case,
)
from frictionlab.sweep.spec import SweepSpec, detect_command, named_files, parse_sweep
from frictionlab.sweep.table import format_table, sweep_table

#: Seconds between rewrites of sweep.csv while cases finish.
TABLE_INTERVAL = 2.0


def run_sweep(args: argparse.Namespace, progress_bar: ProgressFactory) -> int:
    """Run the sweep of ``frictionlab sweep`` (module docstring); returns the exit code."""
    out: Path = args.out
    if out.exists() and not out.is_dir():
        raise InputError(f"--out {out} exists and is not a directory")
    if args.workers is not None and args.workers < 1:
        raise InputError(f"--workers = {args.workers} is invalid: allowed an integer >= 1")
    spec, command, tasks = load_spec(args.sweep, plots=not args.no_plots)
    shas = {t.case_id: t.inputs_sha256 for t in tasks}
    cases_dir = out / "cases"
    records: dict[str, dict[str, Any]] = {}
    for case in spec.cases:
        record = read_record(cases_dir / case.id)
        if is_done(record, case, shas[case.id]):
            assert record is not None
            records[case.id] = record
    todo = [t for t in tasks if t.case_id not in records]
    skipped = len(spec.cases) - len(todo)
    by_id = {c.id: c for c in spec.cases}
    writer = _TableWriter(out, spec, command)
    try:
        writer.write(records, force=True)  # before anything runs: is --out writable?
    except OSError as exc:
        raise InputError(f"cannot write to --out {out}: {exc.strerror or exc}") from None
    started = time.perf_counter()
    with progress_bar(f"sweep {args.sweep.name}") as progress:
        progress(skipped, len(spec.cases))
        for result in _execute(todo, args.scheduler, args.workers):
            case = by_id[result.case_id]
            status = "ok" if result.ok else "failed"
            record = make_record(
                case, command, shas[case.id], status, result.error, result.seconds,
                list(result.files),
            )  # fmt: skip
            write_case(cases_dir / case.id, result.files, record)
            records[case.id] = record
            writer.write(records)
            progress(len(records), len(spec.cases))
            if not result.ok and not args.quiet:
                print(f"frictionlab sweep: case {case.id} failed: {result.error}", file=sys.stderr)
    writer.write(records, force=True)
    paths = [out / "sweep.csv"]
    if not args.no_plots:
        paths.append(writer.plot())
    failed = [r for r in records.values() if r["status"] != "ok"]
    if not args.quiet:
        print(
            f"frictionlab sweep: {len(spec.cases)} cases ({skipped} done before, "
            f"{len(todo)} run in {time.perf_counter() - started:.1f} s, {len(failed)} failed); "
            "wrote " + ", ".join(str(p) for p in paths)
        )
    return 1 if failed else 0


def load_spec(path: Path, plots: bool = True) -> tuple[SweepSpec, str, list[Task]]:
    """Read a sweep file and its base scenario, validate every case.

    Returns the parsed sweep (:class:`SweepSpec`), the command of its base scenario and the
    tasks; nothing runs and nothing is written.
    """
    spec = parse_sweep(load_toml(path), path.parent)
    base_data = load_toml(spec.base)
    command = detect_command(base_data, spec.command)
    return spec, command, _validate(spec, command, base_data, plots)


def _validate(spec: SweepSpec, command: str, base: dict[str, Any], plots: bool) -> list[Task]:
    """Check every case's scenario (nothing runs): bad input names the case and the key."""
    from frictionlab.io.roughness_scenario import parse_roughness_scenario
    from frictionlab.io.scenario import parse_scenario

    tasks = []
    contents: dict[Path, bytes] = {}

    def content(path: Path, where: str) -> bytes:
        if path not in contents:
            try:
                contents[path] = path.read_bytes()
            except OSError as exc:
                raise InputError(f"{where}: cannot read '{path}': {exc.strerror or exc}") from None
        return contents[path]

    base_name = spec.base.name
    for case in spec.cases:
        where = f"sweep case {case.index + 1} ({format_overrides(case.overrides)})"
        for key in case.overrides:
            check_key(base, key, where)
        sets = override_strings(case.overrides)
        try:
            data = apply_overrides(base, sets)
            if command == "simulate":
                parse_scenario(data, base_dir=spec.base.parent, source=str(spec.base))
            else:
                parse_roughness_scenario(data, spec.base.parent)
        except (InputError, ParameterError, ValidityError) as exc:
            raise InputError(f"{where}: {exc}") from None
        # the base and the files it names travel with the task (relative names, as written,
        # are rebuilt beside the base on the worker); absolute names must exist there too
        files = {base_name: content(spec.base, where)}
        hashed = dict(files)
        for name in named_files(command, data):
            path = Path(name) if Path(name).is_absolute() else spec.base.parent / name
            hashed[name] = content(path, where)
            if not Path(name).is_absolute():
                files[name] = hashed[name]
        tasks.append(
            Task(case.id, command, str(spec.base.resolve()), tuple(sets), plots,
                 tuple(files.items()), inputs_sha256(hashed))
        )  # fmt: skip
    return tasks


def _execute(
    tasks: Sequence[Task], scheduler: str | None, workers: int | None
) -> Iterator[TaskResult]:
    """Results in order of completion (a lost worker is a failed case, not a crash)."""
    if not tasks:
        return iter(())
    if scheduler is not None:
        return _on_dask(tasks, scheduler)
    return _on_pool(tasks, workers or min(os.cpu_count() or 1, len(tasks)))


def _on_pool(tasks: Sequence[Task], workers: int) -> Iterator[TaskResult]:
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    context = multiprocessing.get_context("spawn")  # no fork of a threaded parent
    pool = ProcessPoolExecutor(max_workers=workers, mp_context=context)
    try:
        futures = {pool.submit(run_task, task): task for task in tasks}
        for future in as_completed(futures):
            yield _result(futures[future], future.result)
    finally:  # on Ctrl-C: drop the queued cases (a re-run does them), let running ones end
        pool.shutdown(wait=True, cancel_futures=True)


def _on_dask(tasks: Sequence[Task], address: str) -> Iterator[TaskResult]:
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise InputError(
            "--scheduler needs dask.distributed: pip install 'frictionlab[dask]'"
        ) from None
    try:
        client = Client(address, timeout="10s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise InputError(f"--scheduler {address}: cannot connect: {exc}") from None
    try:
        futures = client.map(run_task, list(tasks), key=[f"sweep-{t.case_id}" for t in tasks])
        by_key = {f.key: t for f, t in zip(futures, tasks, strict=True)}
        for future in as_completed(futures):
            yield _result(by_key[future.key], future.result)
    finally:
        client.close()


def _result(task: Task, get: Callable[[], TaskResult]) -> TaskResult:
    try:
        return get()
    except Exception as exc:  # the worker died or the cluster lost the task
        return TaskResult(task.case_id, False, f"worker lost: {type(exc).__name__}: {exc}", 0.0, {})


class _TableWriter:
    """Rewrites sweep.csv (atomically, at most every TABLE_INTERVAL s) and draws the plot."""

    def __init__(self, out: Path, spec: SweepSpec, command: str) -> None:
        self.out, self.spec, self.command = out, spec, command
        self.last = -float("inf")
        self.figures: dict[str, dict[str, float | None]] = {}
        self.table: Any = None

    def write(self, records: dict[str, dict[str, Any]], force: bool = False) -> None:
        now = time.monotonic()
        if not force and now - self.last < TABLE_INTERVAL:
            return
        for cid, record in records.items():
            if record["status"] == "ok" and cid not in self.figures:
                self.figures[cid] = self._figures(cid)
        self.table = sweep_table(self.spec.cases, self.spec.keys, records, self.figures)
        write_text_atomic(self.out / "sweep.csv", format_table(self.table))
        self.last = now

    def _figures(self, cid: str) -> dict[str, float | None]:
        import json

        path = self.out / "cases" / cid / "summary.json"
        try:
            summary = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return {}
        return summary_figures(self.command, summary)

    def plot(self) -> Path:
        from frictionlab.plotting.roughness import figure_png_bytes
        from frictionlab.plotting.sweep import sweep_figure

        fig = sweep_figure(self.table, list(self.spec.keys), self.spec.title)
        return write_bytes_atomic(self.out / "sweep.png", figure_png_bytes(fig))
