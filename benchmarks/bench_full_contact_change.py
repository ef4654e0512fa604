"""The full-contact sums before and after a change, alternated in one process.

``roughness/full_contact.py`` of a git revision is written to a temporary module and
compiled beside the current one; both then sum a 512 x 512 station map over 72
directions (``full_contact_sums``), alternating: the median process CPU time and wall
time per call, and the largest relative change of the sums.

Run: ``python benchmarks/bench_full_contact_change.py --before REV [--repeats 7]`` from a
git checkout (``REV`` e.g. ``main``).
"""

from __future__ import annotations

import argparse
import importlib.util
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from frictionlab.roughness import full_contact

_PATH = "src/frictionlab/roughness/full_contact.py"


def _before(rev: str, folder: Path):
    """``full_contact.py`` of git revision ``rev``, imported as the module ``_fc_before``."""
    source = subprocess.run(["git", "show", f"{rev}:{_PATH}"], capture_output=True,
                            text=True, check=True).stdout  # fmt: skip
    path = folder / "_fc_before.py"
    path.write_text(source)
    spec = importlib.util.spec_from_file_location("_fc_before", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["_fc_before"] = module
    spec.loader.exec_module(module)
    return module


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", required=True, help="git revision to compare with")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(2)
    n = 512 * 512
    g = [rng.normal(0.0, 0.3, n) for _ in range(4)]
    beta = np.radians(np.arange(0.0, 360.0, 5.0))
    with tempfile.TemporaryDirectory() as folder:
        versions = {"before": _before(args.before, Path(folder)), "after": full_contact}
        sums = {}
        for name, module in versions.items():  # compile (or load) first
            s = module.full_contact_sums(0.3, (g[0], g[1]), (g[2], g[3]), np.cos(beta),
                                         np.sin(beta))  # fmt: skip
            sums[name] = np.concatenate([s.sum_x, s.sum_y])
        times: dict[str, list[tuple[float, float]]] = {name: [] for name in versions}
        for rep in range(args.repeats):
            for name in sorted(versions, reverse=bool(rep % 2)):
                cpu, wall = time.process_time(), time.perf_counter()
                versions[name].full_contact_sums(0.3, (g[0], g[1]), (g[2], g[3]),
                                                 np.cos(beta), np.sin(beta))  # fmt: skip
                times[name].append((time.process_time() - cpu, time.perf_counter() - wall))
    for name, runs in times.items():
        cpu = statistics.median(t[0] for t in runs)
        wall = statistics.median(t[1] for t in runs)
        print(f"{name}: median CPU {cpu:.4f} s, wall {wall:.4f} s per call ({len(runs)} runs)")
    scale = np.maximum(np.abs(sums["before"]), np.abs(sums["after"]))
    change = float(np.max(np.abs(sums["before"] - sums["after"]) / np.where(scale > 0, scale, 1)))
    print(f"largest relative change of the sums: {change:.3g}")
    print("load average:", Path("/proc/loadavg").read_text().split()[:3])
    return 0


if __name__ == "__main__":
    sys.exit(main())
