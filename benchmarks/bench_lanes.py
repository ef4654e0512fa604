"""update() of the law against the like-for-like Coulomb return, one and two threads.

Both at N points of the ``frictionlab bench`` state (the full cone law, all sliding),
fresh outputs with the 3x3 tangent, alternated in one process, median of the runs: wall
and process CPU time per point, and the ratio law / Coulomb (target <= 3, issue 26).
The serial lanes kernel is timed beside the per-point reference loop (the gain of the
lanes; the same numbers to rounding), and with ``--before REF`` beside the serial lanes
kernel of the git revision REF (its kernels.py loaded as a module of its own, so that
before and after alternate in one process).

Run: ``python benchmarks/bench_lanes.py [--points N] [--repeats R] [--before main]``.
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

from frictionlab._jit import numba
from frictionlab.benchmark import _sliding, coulomb_update
from frictionlab.subloading import SubloadingParams, kernels, update


def _kernels_at(ref: str) -> ModuleType:
    """subloading/kernels.py of the git revision ``ref``, imported as a module of its own."""
    source = subprocess.run(
        ["git", "show", f"{ref}:src/frictionlab/subloading/kernels.py"],
        capture_output=True, text=True, check=True, cwd=Path(__file__).parent,
    ).stdout  # fmt: skip
    # one fixed file per revision, rewritten only when it changes: numba's cache keys on it
    tag = "".join(c if c.isalnum() else "_" for c in ref)
    path = Path(tempfile.gettempdir()) / f"bench_lanes_before_{tag}" / "kernels_before.py"
    path.parent.mkdir(exist_ok=True)
    if not path.exists() or path.read_text() != source:
        path.write_text(source)
    spec = importlib.util.spec_from_file_location("kernels_before", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # numba's cache re-imports the module by its name
    spec.loader.exec_module(module)
    return module


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--before", help="a git revision whose serial lanes to time beside")
    args = parser.parse_args()
    n = args.points
    params = SubloadingParams(
        surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
        rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
    )  # fmt: skip
    state, du = _sliding(params, n, 1.0)
    table = params._kernel_table
    outs = kernels.empty_outputs(n)
    call = (np.ascontiguousarray(state.traction), state.F, state.R, state.gap, du,
            np.array([0.01]), table, True, 0, 1.0, 0, 0, 0, False, True, outs["traction"],
            outs["F"], outs["R"], outs["gap"], outs["dlam"], outs["vp"], outs["diss"],
            outs["tangent"], outs["status"], outs["iterations"])  # fmt: skip
    threads = numba.get_num_threads()
    before = _kernels_at(args.before) if args.before else None
    runs = {
        "by_point serial": (1, lambda: kernels.step_points_by_point(*call)),
        "lanes serial": (1, lambda: kernels.step_points(*call)),
        **({f"lanes {args.before}": (1, lambda: before.step_points(*call))} if args.before else {}),
        "coulomb, 1 thread": (1, lambda: coulomb_update(state, du, 0.01, table)),
        "update(), 1 thread": (1, lambda: update(params, state, du, 0.01)),
        f"coulomb, {threads} threads": (threads, lambda: coulomb_update(state, du, 0.01, table)),
        f"update(), {threads} threads": (threads, lambda: update(params, state, du, 0.01)),
    }
    wall: dict[str, list[float]] = {k: [] for k in runs}
    cpu: dict[str, list[float]] = {k: [] for k in runs}
    for count, func in runs.values():
        numba.set_num_threads(count)
        func()
    for _ in range(args.repeats):
        for label, (count, func) in runs.items():
            numba.set_num_threads(count)
            start, start_cpu = time.perf_counter(), time.process_time()
            func()
            cpu[label].append(time.process_time() - start_cpu)
            wall[label].append(time.perf_counter() - start)
    numba.set_num_threads(threads)

    def ns(times: list[float]) -> float:
        return statistics.median(times) / n * 1e9

    print(f"N = {n}, median of {args.repeats}, load {os.getloadavg()}")
    for label in runs:
        print(f"{label:22s} wall {ns(wall[label]):7.1f} ns/point, CPU {ns(cpu[label]):7.1f}")
    for count in sorted({1, threads}):
        law, fair = f"update(), {count} thread", f"coulomb, {count} thread"
        law = law + ("s" if count > 1 else "")
        fair = fair + ("s" if count > 1 else "")
        ratio_wall = ns(wall[law]) / ns(wall[fair])
        ratio_cpu = ns(cpu[law]) / ns(cpu[fair])
        print(f"{count} thread(s): law / like-for-like Coulomb, wall {ratio_wall:.2f}, "
              f"CPU {ratio_cpu:.2f}")  # fmt: skip
    print(f"lanes gain (serial CPU) {ns(cpu['by_point serial']) / ns(cpu['lanes serial']):.2f}")
    if args.before:
        gain = ns(cpu[f"lanes {args.before}"]) / ns(cpu["lanes serial"])
        print(f"serial lanes, {args.before} / this tree (CPU) {gain:.2f}")


if __name__ == "__main__":
    main()
