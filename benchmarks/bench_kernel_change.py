"""The law kernel before and after a change, alternated in one process.

The kernel sources (``surfaces.py``, ``evolution.py``, ``kernels.py``) of a git revision
are written to a temporary package and compiled beside the current ones; both then run the
``frictionlab bench`` state (N points of the full cone law, or modified Cam-clay, all
sliding), alternating, median of the runs: the serial kernel's process CPU time, the
``prange`` kernel's wall time, the plain Coulomb return's wall time, the mean Newton
iteration count (kernels up to 52405b8 also evaluated the residual at q = 1 once per
sliding point, so theirs is one below their evaluation count), and the largest change of
the results.

Run: ``python benchmarks/bench_kernel_change.py --before REV [--points N] [--surface mcc]``
from a git checkout (``REV`` e.g. ``HEAD~3``).
"""

from __future__ import annotations

import argparse
import importlib
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from frictionlab.benchmark import _sliding, coulomb_return
from frictionlab.subloading import SubloadingParams, kernels

_FILES = ("surfaces", "evolution", "kernels")


def _old_kernels(rev: str, folder: Path):
    """Import the kernel modules of git revision ``rev`` as the package ``_before``."""
    package = folder / "_before"
    package.mkdir()
    (package / "__init__.py").write_text("")
    for name in _FILES:
        source = subprocess.run(
            ["git", "show", f"{rev}:src/frictionlab/subloading/{name}.py"],
            check=True, capture_output=True, text=True,
        ).stdout  # fmt: skip
        for other in _FILES:
            source = source.replace(f"frictionlab.subloading.{other}", f"_before.{other}")
        (package / f"{name}.py").write_text(source)
    sys.path.insert(0, str(folder))
    return importlib.import_module("_before.kernels")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", required=True, help="git revision of the old kernel")
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--surface", choices=["cone", "mcc"], default="cone")
    args = parser.parse_args()
    n = args.points
    if args.surface == "cone":
        params = SubloadingParams(
            surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
            rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
        )  # fmt: skip
        state, du = _sliding(params, n, 1.0)
        code = 0
    else:
        params = SubloadingParams(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5,
                                  u=100.0, kappa=1.0, xi=1e-3)  # fmt: skip
        state, du = _sliding(params, n, 0.2)
        code = 2
    traction = np.ascontiguousarray(state.traction)
    with tempfile.TemporaryDirectory() as folder:
        modules = {"before": _old_kernels(args.before, Path(folder)), "after": kernels}
        runs = {}
        for label, module in modules.items():
            outs = kernels.empty_outputs(n, True)
            call = (traction, state.F, state.R, state.gap, du, np.array([0.01]),
                    params._kernel_table, True, code, 1.0, 0, 0, 0, False, True,
                    outs["traction"], outs["F"], outs["R"], outs["gap"], outs["dlam"],
                    outs["vp"], outs["diss"], outs["tangent"], outs["status"],
                    outs["iterations"])  # fmt: skip
            module.step_points(*call)
            module.step_points_parallel(*call)
            runs[label] = (module, call, outs)
        out_t, out_l = np.empty((n, 3)), np.empty(n)
        coulomb_return(traction, du, 1000.0, 1000.0, 0.3, out_t, out_l)
        serial: dict[str, list[float]] = {k: [] for k in runs}
        parallel: dict[str, list[float]] = {k: [] for k in runs}
        coulomb = []
        for _ in range(args.repeats):
            for label, (module, call, _) in runs.items():
                start = time.process_time()
                module.step_points(*call)
                serial[label].append(time.process_time() - start)
                start = time.perf_counter()
                module.step_points_parallel(*call)
                parallel[label].append(time.perf_counter() - start)
            start = time.perf_counter()
            coulomb_return(traction, du, 1000.0, 1000.0, 0.3, out_t, out_l)
            coulomb.append(time.perf_counter() - start)

    def us(times: list[float]) -> float:
        return statistics.median(times) / n * 1e6

    old, new = runs["before"][2], runs["after"][2]
    change = 0.0
    for k in ("traction", "tangent", "dlam", "F", "R"):
        diff = np.abs(old[k] - new[k]).reshape(n, -1).max(1)
        change = max(change, float(np.max(diff / np.abs(old[k]).reshape(n, -1).max(1))))
    print(f"{args.surface}, N = {n}, median of {args.repeats}; load {os.getloadavg()}")
    print(f"coulomb return, parallel wall     {us(coulomb):.4f} us/point")
    for label in runs:
        iterations = runs[label][2]["iterations"].mean()
        print(f"{label:7s} serial CPU {us(serial[label]):.4f} us/point, parallel wall "
              f"{us(parallel[label]):.4f} us/point, iterations {iterations:.2f}")  # fmt: skip
    print(f"serial gain {us(serial['before']) / us(serial['after']):.2f}x; statuses equal: "
          f"{np.array_equal(old['status'], new['status'])}; largest change {change:.1e} "
          "(relative to each point's largest entry)")  # fmt: skip


if __name__ == "__main__":
    main()
