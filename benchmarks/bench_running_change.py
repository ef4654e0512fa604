"""The driver's running-figure passes (driver/_running.py) before and after a change.

The file of a git revision is imported as a separate module (its numba cache goes to a
temporary folder, so the normal cache is not touched) beside the current one; both
passes (``accumulate``, ``accumulate_row``) then run alternately on the same inputs:
median process CPU time per point, and whether the outputs are identical bit for bit.

Run: ``python benchmarks/bench_running_change.py --before REV [--points N]`` from a git
checkout (``REV`` e.g. ``main``).
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType

import numpy as np

_PATH = "src/frictionlab/driver/_running.py"


def _module(name: str, source: str, folder: Path) -> ModuleType:
    path = folder / f"{name}.py"
    path.write_text(source)
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def _inputs(n: int) -> tuple[tuple, tuple]:
    """(arguments of accumulate, those of accumulate_row), fresh arrays."""
    rng = np.random.default_rng(1)
    traction = rng.normal(size=(n, 3))
    traction[::3, 1] = 0.0
    du = rng.normal(size=(n, 3)) * 1e-3
    dt = rng.random(1)
    dpath = np.hypot(du[:, 0], du[:, 1])
    work = rng.random(n)
    run = (rng.random(n), rng.random((n, 2)), rng.random(n), rng.random(n), rng.random(n),
           np.empty(n), rng.random(n) * 0.5, np.zeros(n, dtype=np.int64), rng.random(n),
           rng.random(n), np.full(n, -np.inf), np.zeros(n), rng.normal(size=n))  # fmt: skip
    state = (rng.random(n), rng.random(n), rng.random(n), np.zeros(n, dtype=np.int8),
             np.zeros(n, dtype=np.int32))  # fmt: skip
    rows = (np.empty(n), np.empty((n, 2)), np.empty(n), np.empty(n), np.empty((n, 3)),
            np.empty(n), np.empty(n), np.empty(n), np.empty(n, dtype=np.int8),
            np.empty(n, dtype=np.int32))  # fmt: skip
    head = (3, dt, du, dpath, work, traction)
    return (*head, *run), (*head, *state, *run, *rows)


def _copy(args: tuple) -> tuple:
    return tuple(a.copy() if isinstance(a, np.ndarray) else a for a in args)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", required=True, help="git revision of the old file")
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--repeats", type=int, default=41)
    args = parser.parse_args()
    old_source = subprocess.run(
        ["git", "show", f"{args.before}:{_PATH}"], check=True, capture_output=True, text=True
    ).stdout
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["NUMBA_CACHE_DIR"] = tmp
        folder = Path(tmp)
        before = _module("_running_before", old_source, folder)
        after = _module("_running_after", Path(_PATH).read_text(), folder)
        plain, row = _inputs(args.points)
        for name, inputs in (("accumulate", plain), ("accumulate_row", row)):
            times: dict[str, list[float]] = {"before": [], "after": []}
            results = {}
            for k in range(args.repeats):
                for label, mod in (("before", before), ("after", after)):
                    a = _copy(inputs)
                    t0 = time.process_time()
                    rose = getattr(mod, name)(*a)
                    if k > 0:  # the first call compiles
                        times[label].append(time.process_time() - t0)
                    results[label] = (rose, a)
            same = results["before"][0] == results["after"][0] and all(
                np.array_equal(x, y, equal_nan=True)
                for x, y in zip(results["before"][1], results["after"][1], strict=True)
                if isinstance(x, np.ndarray)
            )
            b, a = (statistics.median(times[s]) / args.points * 1e9 for s in ("before", "after"))
            print(f"{name:15s} before {b:6.2f} ns/point, after {a:6.2f} ns/point CPU "
                  f"(after/before {a / b:.3f}); outputs identical: {same}")  # fmt: skip


if __name__ == "__main__":
    main()
