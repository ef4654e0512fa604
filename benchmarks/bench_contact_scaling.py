"""Benchmark: how `frictionlab contact` scales with the number of unknowns (2-D and 3-D).

Not a timed test: run it by hand, on a quiet machine if possible::

    python benchmarks/bench_contact_scaling.py [--cases 2d-80,2d-160,2d-320,3d-8,3d-32]
                                               [--timeout 900] [--out FILE.json]

Each case runs in its own process (peak memory is the process's maximum resident set
size, the interpreter and compiled law included: the ``base`` column is that of the
warm-up alone; CPU time is the process's, the figure to compare on a loaded machine,
beside the load average at the end of the case). Setup: the bundled PMMA-like law
(cone, mu_s = 0.6, mu_k = 0.4) on a block pressed with 1 MPa in 2 steps and dragged
30 um in 15 steps through the static
peak. ``2d-N``: the 100 mm x 25 mm plane-strain block with N x N/4 quadrilaterals;
``3d-N``: a 100 mm cube of N^3 hexahedra. Reported: unknowns (dofs), contact unknowns,
wall time of the run (meshing included), Newton iterations, peak memory, and the share
of the wall (and CPU) time spent in the law's update (``frictionlab.subloading.update``). The
code under test is whatever ``frictionlab`` imports (PYTHONPATH picks a checkout, so
the same script times an older version). JSON goes to benchmarks/results/.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import subprocess
import sys
import time
from pathlib import Path

CASES = "2d-80,2d-160,2d-320,3d-8,3d-16,3d-24"  # add 3d-32 (~110k unknowns) by hand


def run_case(name: str) -> dict[str, float | int | str]:
    """Run one case in this process and return its measures."""
    import numpy as np

    import frictionlab.contact.interface as interface
    from frictionlab.contact import Block, NormalLoad, Slide, run_contact
    from frictionlab.subloading import SubloadingParams

    params = SubloadingParams(
        alpha_n=5e11, alpha_t=5e11, mu_s=0.6, mu_k=0.4, u=2e6, kappa=1e5, xi=0.05
    )
    normal = NormalLoad(pressure=1e6, steps=2)
    program = [Slide(velocity=1e-5, distance=30e-6, steps=15)]
    # warm the compiled law on a tiny mesh, then take the base memory
    run_contact(Block(3e9, 0.35, 0.1, 0.025, 0.05), params, normal, program)
    base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    kind, n = name.split("-")
    cells = int(n)
    if kind == "2d":
        block = Block(E=3e9, nu=0.35, width=0.1, height=0.025, element_size=0.1 / cells)
    else:
        block = Block(
            E=3e9, nu=0.35, width=0.1, depth=0.1, height=0.1, element_size=0.1 / cells,
            element="hex",
        )  # fmt: skip
    law_seconds = [0.0]
    law_cpu = [0.0]
    original = interface.update

    def timed_update(*args, **kwargs):  # type: ignore[no-untyped-def]
        start = time.perf_counter()
        start_cpu = time.process_time()
        try:
            return original(*args, **kwargs)
        finally:
            law_seconds[0] += time.perf_counter() - start
            law_cpu[0] += time.process_time() - start_cpu

    interface.update = timed_update  # type: ignore[assignment]
    start = time.perf_counter()
    cpu = time.process_time()
    history = run_contact(block, params, normal, program)
    wall = time.perf_counter() - start
    cpu = time.process_time() - cpu
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    dofs = int(np.asarray(history.nodes).size)
    return {
        "case": name,
        "cells": int(np.prod(block.cells)),
        "unknowns": dofs,
        "contact_points": int(history.x.size),
        "success": str(history.success),
        "wall_s": round(wall, 2),
        "cpu_s": round(cpu, 2),
        "iterations": int(history.iterations.sum()),
        "peak_mb": round(peak, 1),
        "base_mb": round(base, 1),
        "law_share": round(law_seconds[0] / wall, 3),
        "law_cpu_share": round(law_cpu[0] / cpu, 3),
        "load": round(os.getloadavg()[0], 1),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", default=CASES)
    parser.add_argument("--timeout", type=float, default=900.0)
    parser.add_argument("--one", help=argparse.SUPPRESS)  # internal: run one case
    parser.add_argument("--label", default="this checkout")
    default_out = Path(__file__).parent / "results" / "contact_scaling.json"
    parser.add_argument("--out", default=str(default_out))
    args = parser.parse_args()
    if args.one:
        print(json.dumps(run_case(args.one)))
        return 0
    rows = []
    load = os.getloadavg()[0]
    for name in args.cases.split(","):
        try:
            done = subprocess.run(
                [sys.executable, __file__, "--one", name],
                capture_output=True, text=True, timeout=args.timeout, check=True,
            )  # fmt: skip
            row = json.loads(done.stdout.strip().splitlines()[-1])
        except subprocess.TimeoutExpired:
            row = {"case": name, "success": f"stopped after {args.timeout:.0f} s"}
        except subprocess.CalledProcessError as exc:
            last = (exc.stderr.strip().splitlines() or [""])[-1]
            row = {"case": name, "success": "error: " + last}
        rows.append(row)
        print(json.dumps(row), flush=True)
    out = Path(args.out)
    out.parent.mkdir(exist_ok=True)
    out.write_text(
        json.dumps(
            {
                "label": args.label,
                "machine": platform.platform(),
                "cpus": os.cpu_count(),
                "load_at_start": load,
                "load_at_end": os.getloadavg()[0],
                "rows": rows,
            },
            indent=2,
        )
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
