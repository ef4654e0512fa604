"""Law kernel before/after passing scalars to the per-point function, in one process.

The old kernel source (the per-point function took the 14 input/output arrays) is taken
from git (``--old REV``, default the commit before the change) and compiled next to the
current one; both loops run on the same sliding state, alternating, median of the runs.
Run: PYTHONPATH=src python benchmarks/bench_refcount_point.py [--points N] [--runs R]
"""

import argparse
import importlib.util
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numba
import numpy as np

from frictionlab.benchmark import _sliding
from frictionlab.subloading import SubloadingParams, kernels

ROOT = Path(__file__).resolve().parents[1]


def _old_module(rev: str):
    source = subprocess.run(
        ["git", "show", f"{rev}:src/frictionlab/subloading/kernels.py"],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout  # fmt: skip
    path = Path(tempfile.mkdtemp()) / "old_kernels.py"
    path.write_text(source.replace("cache=True", "cache=False"))
    spec = importlib.util.spec_from_file_location("old_kernels", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--old", default="e6c3563^")
    parser.add_argument("--points", type=int, default=200_000)
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    old = _old_module(args.old)
    params = SubloadingParams(
        surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
        rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
    )  # fmt: skip
    n = args.points
    state, du = _sliding(params, n, 1.0)
    traction = np.ascontiguousarray(state.traction)
    outs = {"old": kernels.empty_outputs(n), "new": kernels.empty_outputs(n)}

    def call(module, fn_name, o):
        return lambda: getattr(module, fn_name)(
            traction, state.F, state.R, state.gap, du, np.array([0.01]),
            params._kernel_table, True, 0, 1.0, 0, 0, 0, False, True,
            o["traction"], o["F"], o["R"], o["gap"], o["dlam"], o["vp"], o["diss"],
            o["tangent"], o["status"], o["iterations"],
        )  # fmt: skip

    cases = {
        (mod, fn): call(m, fn, outs[mod])
        for mod, m in (("old", old), ("new", kernels))
        for fn in ("step_points", "step_points_parallel")
    }
    for f in cases.values():
        f()
    passed = ("traction", "F", "R", "gap", "dlam", "vp", "diss", "tangent", "status", "iterations")
    for key in passed:
        same = np.array_equal(outs["old"][key], outs["new"][key], equal_nan=True)
        print(f"{key:10s} bit-identical: {same}")
    times = {k: [] for k in cases}
    for _ in range(args.runs):
        for k, f in cases.items():
            t0 = time.perf_counter()
            f()
            times[k].append(time.perf_counter() - t0)
    med = {k: statistics.median(v) / n * 1e6 for k, v in times.items()}
    print(f"threads {numba.get_num_threads()}, {n} points, median of {args.runs} (us/point)")
    for fn in ("step_points", "step_points_parallel"):
        o, w = med[("old", fn)], med[("new", fn)]
        print(f"{fn:22s} old {o:.4f}  new {w:.4f}  old/new {o / w:.2f}x")
    for mod in ("old", "new"):
        gain = med[(mod, "step_points")] / med[(mod, "step_points_parallel")]
        print(f"{mod}: parallel gain {gain:.2f}x")


if __name__ == "__main__":
    sys.exit(main())
