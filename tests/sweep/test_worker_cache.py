"""Sweep workers never compile: the sweep warms the compile cache before its pool starts.

The sweep runs in a fresh process on a copy of this process's compile cache from which one
kernel every simulate uses (the driver's ``slip_lengths``, quick to compile) was removed.
A listener on numba's ``numba:compile`` event (it fires for a real compilation only, not
for a load from the cache) is installed in the sweep's process and, through the spawned
workers' import of the main script, in every worker; each compilation is logged with its
process id. That kernel must be compiled by the sweep's own process, nothing by a worker.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from .support import write_sweep

DRIVER = """\
import os, sys
from numba.core import event

class _Spy(event.Listener):
    def on_start(self, e):
        f = e.data["dispatcher"].py_func
        with open(os.environ["SPY_LOG"], "a") as log:
            log.write(f"{os.getpid()} {f.__module__}.{f.__qualname__}\\n")

    def on_end(self, e):
        pass

event.register("numba:compile", _Spy())  # also in spawned workers (they import this file)

if __name__ == "__main__":
    from frictionlab.cli import main

    print("PARENT", os.getpid())
    sys.exit(main(sys.argv[1:]))
"""


@pytest.mark.slow
def test_sweep_workers_find_every_kernel_compiled(tmp_path: Path) -> None:
    import numba.core.config

    from frictionlab.warmup import warm_for

    warm_for("simulate", [1])  # this process's cache holds the simulate kernels
    cache = Path(numba.core.config.CACHE_DIR)
    root = tmp_path / "cache"
    copy = root / cache.name
    shutil.copytree(cache, copy, ignore=shutil.ignore_patterns(".frictionlab-in-use"))
    removed = [p for p in copy.rglob("_running.slip_lengths-*") if p.suffix in (".nbi", ".nbc")]
    assert removed  # this kernel now needs compiling
    for path in removed:
        path.unlink()
    sweep = write_sweep(tmp_path, '[grid]\n"law.mu_s" = [0.5]\n', steps=5)
    (tmp_path / "driver.py").write_text(DRIVER)
    log = tmp_path / "compiled.log"
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(FRICTIONLAB_CACHE_DIR=str(root), SPY_LOG=str(log))
    done = subprocess.run(
        [sys.executable, str(tmp_path / "driver.py"), "sweep", str(sweep), "--out",
         str(tmp_path / "out"), "--workers", "1", "--no-plots", "--quiet"],
        env=env, cwd=tmp_path, capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    parent = done.stdout.split("PARENT", 1)[1].split()[0]
    events = [line.split(" ", 1) for line in log.read_text().splitlines()]
    by_workers = [name for pid, name in events if pid != parent]
    assert by_workers == [], by_workers
    assert any(name.endswith("slip_lengths") for pid, name in events if pid == parent)
    assert len(list((tmp_path / "out" / "cases").iterdir())) == 1


def test_a_sweep_warms_the_kernels_of_its_cases_before_its_workers_start(
    tmp_path: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    from frictionlab import warmup as warmup_module
    from frictionlab.app import sweep as sweep_app
    from frictionlab.cli import main

    events: list[tuple[str, Any]] = []
    monkeypatch.setattr(warmup_module, "warm_for", lambda command, points=(): events.append(
        ("warm", (command, list(points)))))  # fmt: skip

    def run_tasks(tasks: Any, scheduler: Any, workers: Any) -> Any:
        events.append(("pool", len(tasks)))
        return iter(())

    monkeypatch.setattr(sweep_app, "run_tasks", run_tasks)
    sweep = write_sweep(tmp_path, '[grid]\n"law.mu_s" = [0.5, 0.6]\n', steps=5)
    main(["sweep", str(sweep), "--out", str(tmp_path / "out"), "--no-plots", "--quiet"])
    assert events == [("warm", ("simulate", [1, 1])), ("pool", 2)]
