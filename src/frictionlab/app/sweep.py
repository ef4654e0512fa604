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

``DIR`` is checked like every command's ``--out`` (never the current, home or root
directory) and must be new, empty or a sweep's folder (it holds ``sweep.csv``);
``--overwrite`` starts any other folder afresh. A lock on ``DIR`` is held for the whole
run, and nothing is written before every case is validated and the scheduler answered
(:mod:`frictionlab.sweep.executors`).
"""

from __future__ import annotations

import argparse
import shutil
import sys
import time
from pathlib import Path
from typing import Any

from frictionlab._progress import ProgressFactory
from frictionlab.app.budget import check_roughness
from frictionlab.app.sweep_task import Task
from frictionlab.errors import InputError, ParameterError, ValidityError
from frictionlab.io.atomic import write_bytes_atomic, write_text_atomic
from frictionlab.io.config import apply_overrides, load_toml
from frictionlab.io.inputs import read_input_bytes
from frictionlab.io.output_set import check_out, lock_out
from frictionlab.schema.sweep import SweepSpec, parse_sweep
from frictionlab.sweep.cases import check_key, format_overrides, override_strings
from frictionlab.sweep.executors import probe_scheduler, run_tasks
from frictionlab.sweep.figures import summary_figures
from frictionlab.sweep.ledger import (
    inputs_sha256,
    is_done,
    make_record,
    read_record,
    write_case,
)
from frictionlab.sweep.spec import detect_command, named_files
from frictionlab.sweep.table import format_table, sweep_table

#: The sweep's table, also the mark of a sweep's folder.
TABLE = "sweep.csv"
#: Seconds between rewrites of sweep.csv while cases finish.
TABLE_INTERVAL = 2.0


def run_sweep(args: argparse.Namespace, progress_bar: ProgressFactory) -> int:
    """Run the sweep of ``frictionlab sweep`` (module docstring); returns the exit code."""
    # a sweep's folder is marked by sweep.csv; anything else needs --overwrite
    out = check_out(args.out, args.overwrite, markers=(TABLE,))
    if args.workers is not None and args.workers < 1:
        raise InputError(f"--workers = {args.workers} is invalid: allowed an integer >= 1")
    points: list[int] = []
    spec, command, tasks = load_spec(args.sweep, plots=not args.no_plots, points=points)
    where = out.resolve()
    for source in (Path(args.sweep), spec.base):
        if where == source.resolve().parent or where in source.resolve().parents:
            raise InputError(
                f"--out '{args.out}' holds the sweep's own input '{source}': allowed a "
                "folder outside the inputs' folders"
            )
    if args.scheduler is not None:
        probe_scheduler(args.scheduler)  # before anything is written
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot write to --out {out}: {exc.strerror or exc}") from None
    with lock_out(out):  # held for the whole run: one sweep per folder at a time
        if args.overwrite and out.is_dir() and not (out / TABLE).is_file():
            shutil.rmtree(out)  # --overwrite: a folder that is not a sweep's starts afresh
        return _run(args, progress_bar, out, spec, command, tasks, points)


def _run(
    args: argparse.Namespace, progress_bar: ProgressFactory, out: Path, spec: SweepSpec,
    command: str, tasks: list[Task], points: list[int],
) -> int:  # fmt: skip
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
    if todo:  # compile here, once, what the cases use: the workers then load it
        from frictionlab.warmup import warm_for

        warm_for(command, points)
    started = time.perf_counter()
    with progress_bar(f"sweep {args.sweep.name}") as progress:
        progress(skipped, len(spec.cases))
        for result in run_tasks(todo, args.scheduler, args.workers):
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
    paths = [out / TABLE]
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


def load_spec(
    path: Path, plots: bool = True, points: list[int] | None = None
) -> tuple[SweepSpec, str, list[Task]]:
    """Read a sweep file and its base scenario, validate every case.

    Returns the parsed sweep (:class:`SweepSpec`), the command of its base scenario and the
    tasks; nothing runs and nothing is written. ``points``, when given, receives the
    number of contact points of each simulate case.
    """
    spec = parse_sweep(load_toml(path), base_dir=path.parent, source=str(path))
    base_data = load_toml(spec.base)
    command = detect_command(base_data, spec.command)
    return spec, command, _validate(spec, command, base_data, plots, points)


def _validate(
    spec: SweepSpec, command: str, base: dict[str, Any], plots: bool,
    points: list[int] | None = None,
) -> list[Task]:  # fmt: skip
    """Check every case's scenario (nothing runs): bad input names the case and the key."""
    from frictionlab.schema.roughness import parse_roughness
    from frictionlab.schema.scenario import parse_scenario

    tasks = []
    contents: dict[Path, bytes] = {}

    def content(path: Path, where: str) -> bytes:
        if path not in contents:
            try:
                contents[path] = read_input_bytes(path)
            except InputError as exc:
                raise InputError(f"{where}: {exc}") from None
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
                scenario = parse_scenario(data, base_dir=spec.base.parent, source=str(spec.base))
                if points is not None:
                    points.append(scenario.n_points)
            else:
                check_roughness(
                    parse_roughness(data, base_dir=spec.base.parent, source=str(spec.base))
                )
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
        write_text_atomic(self.out / TABLE, format_table(self.table))
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
