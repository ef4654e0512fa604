"""`frictionlab simulate` with the default output against `[output] every = 100`.

Target (issue "speed where users wait", item 2): the 10^4 points x 10^4 steps run with the
default output takes <= 3x its ``every = 100`` time. Each case is one CLI run in a child
process (the starter scenario's Coulomb slide, the points at 0.1-1 mm/s, ``--no-plots``);
the CPU time (user + system of the child) and the wall time are reported with the history's
size and the load average. A first tiny run fills the compile cache, so no case compiles.

Cases: ``every100``; ``default`` (no ``[output] every``: every step while the history stays
under 1 GB, else the smallest k that keeps it under); ``every1`` (every step, written in
full: the writer's own cost); ``default_parquet`` (the default with ``format = "parquet"``).

Run: ``python benchmarks/bench_default_output.py [--points N] [--steps S] [--keep]``
(defaults 10^3 x 10^4: the 10^4 x 10^4 run needs ~90 CPU s per case on a quiet machine).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

SCENARIO = """
[law]
surface = "coulomb"
alpha_n = 1.0e12
alpha_t = 1.0e12
mu_s = 0.5
mu_k = 0.3
u = 1.0e6
kappa = 1.0e4
xi = 1.0e-2
[initial]
normal_traction = 1.0e6
[[program]]
kind = "slide"
velocity = {velocities}
distance = 1.0e-3
steps = {steps}
"""

CASES = {
    "every100": "[output]\nevery = 100\n",
    "default": "",
    "every1": "[output]\nevery = 1\n",
    "default_parquet": '[output]\nformat = "parquet"\n',
}


def run_case(folder: Path, name: str, points: int, steps: int, output: str) -> dict[str, float]:
    """One `frictionlab simulate` in a child process: CPU and wall seconds, history size."""
    scenario = folder / f"{name}.toml"
    velocities = [float(v) for v in np.geomspace(1e-4, 1e-3, points)]  # distinct histories
    scenario.write_text(SCENARIO.format(velocities=velocities, steps=steps) + output)
    out = folder / name
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    cmd = [sys.executable, "-m", "frictionlab", "simulate", str(scenario), "--out", str(out)]
    subprocess.run([*cmd, "--quiet", "--no-plots", "--overwrite"], check=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    summary = json.loads((out / "summary.json").read_text())
    history = next(out.glob("history.*"))
    return {
        "cpu_s": cpu,
        "wall_s": wall,
        "history_bytes": float(history.stat().st_size),
        "every": float(summary["recorded"]["every"]),
        "rows": float(summary["recorded"]["rows"]) * points,
        "load_average": os.getloadavg()[0],
    }


def main(argv: list[str] | None = None) -> dict[str, dict[str, float]]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--steps", type=int, default=10_000)
    parser.add_argument("--cases", nargs="*", default=list(CASES), choices=list(CASES))
    parser.add_argument("--keep", action="store_true", help="keep the output folders")
    args = parser.parse_args(argv)
    folder = Path(tempfile.mkdtemp(prefix="bench_default_output_"))
    results: dict[str, dict[str, float]] = {}
    try:
        run_case(folder, "warm", 2, 10, "")  # fills the compile cache
        for name in args.cases:
            results[name] = run_case(folder, name, args.points, args.steps, CASES[name])
            r = results[name]
            size = r["history_bytes"] / 1e6
            print(f"{name:16s} cpu {r['cpu_s']:8.1f} s  wall {r['wall_s']:8.1f} s  "
                  f"every {int(r['every']):4d}  rows {r['rows']:.3g}  "
                  f"history {size:8.1f} MB  load {r['load_average']:.1f}")  # fmt: skip
            if not args.keep:  # the histories are large
                shutil.rmtree(folder / name, ignore_errors=True)
    finally:
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)
    if "every100" in results:
        base = results["every100"]
        for name, r in results.items():
            print(f"{name:16s} / every100: cpu {r['cpu_s'] / base['cpu_s']:.2f}x, "
                  f"wall {r['wall_s'] / base['wall_s']:.2f}x")  # fmt: skip
    return results


if __name__ == "__main__":
    main()
