"""The three speed targets of rough contact (issue 22), each timed as a first run.

Usage::

    PYTHONPATH=src python benchmarks/bench_rough_contact.py [--case NAME] [--out F.json]

Each case runs in a fresh Python process (imports, numba's cache load or compilation and
the computation all counted: what a user waits for); the process's own wall time is
reported beside the time of the computation alone and the process's CPU time (all
threads), with the machine's load average: on a shared machine the CPU time is the part
that does not depend on the other users.

* ``lattice_1024``: 1024^2 self-affine map (H = 0.8, rms slope 0.5) on a flat face, 91
  directions (0 to 90 deg), partial contact (about 5 % of the springs compressed):
  target <= 20 s wall;
* ``elastic_512``: the same kind of map at 512^2, elastic half-space, one pressure, 72
  directions: target <= 15 s;
* ``elastic_1024``: 1024^2, one pressure, 72 directions: target <= 90 s.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time

CASES = {
    "lattice_1024": 20.0,
    "elastic_512": 15.0,
    "elastic_1024": 90.0,
}

_CODE = """
import json, sys, time
t0 = time.perf_counter()
import numpy as np
from frictionlab.roughness import elastic_polar, flat, friction_polar, self_affine
case = sys.argv[1]
n = 512 if case == "elastic_512" else 1024
surface = self_affine(0.8, (1e-4, 1e-4), (n, n), rng=np.random.default_rng(1), rms_slope=0.5)
t1 = time.perf_counter()
if case == "lattice_1024":
    h = np.asarray(surface.heights).ravel()
    gap = h.max() - h
    c = float(np.quantile(gap, 0.05))
    load = float(np.mean(np.clip(c - gap, 0.0, None)))  # about 5 % compressed
    polar = friction_polar(surface, flat(), 0.3, np.arange(0.0, 90.5, 1.0), load=load,
                           on_invalid="drop")
    area = float(np.mean(polar.contact_fraction_mean))
else:
    polar = elastic_polar(surface, flat(), 0.3, np.arange(0.0, 360.0, 5.0),
                          pressure=0.025 * 1e11 * 0.5, modulus=1e11, on_invalid="drop")
    area = polar.contact_fraction_mean
t2 = time.perf_counter()
print(json.dumps({"setup_s": t1 - t0, "compute_s": t2 - t1, "area": area,
                  "mu_min": float(np.nanmin(polar.mu)), "mu_max": float(np.nanmax(polar.mu))}))
"""


def run_case(name: str) -> dict[str, object]:
    load_before = os.getloadavg()
    cpu_before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-c", _CODE, name], capture_output=True, text=True, check=False
    )
    wall = time.perf_counter() - start
    cpu_after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (cpu_after.ru_utime - cpu_before.ru_utime) + (cpu_after.ru_stime - cpu_before.ru_stime)
    row: dict[str, object] = {
        "case": name,
        "target_s": CASES[name],
        "process_wall_s": round(wall, 2),
        "process_cpu_s": round(cpu, 2),
        "load_before": [round(v, 2) for v in load_before],
        "load_after": [round(v, 2) for v in os.getloadavg()],
    }
    if done.returncode != 0:
        row["error"] = done.stderr.strip().splitlines()[-1:]
        return row
    row.update(json.loads(done.stdout.strip().splitlines()[-1]))
    row["met"] = wall <= CASES[name]
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=sorted(CASES), action="append")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    rows = [run_case(name) for name in (args.case or list(CASES))]
    text = json.dumps({"cpus": os.cpu_count(), "cases": rows}, indent=1)
    print(text)
    if args.out:
        with open(args.out, "w") as handle:
            handle.write(text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
