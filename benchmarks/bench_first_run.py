"""First run as a user meets it: an empty compile cache, then ``frictionlab warmup``, then
the first ``frictionlab simulate`` of the starter scenario, each in a fresh process.

For comparison the same first simulate on a second empty cache without the warm-up.
Wall-clock seconds; run: ``python benchmarks/bench_first_run.py``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXE = [sys.executable, "-m", "frictionlab"]


def timed(args: list[str], env: dict[str, str], cwd: Path) -> float:
    t0 = time.perf_counter()
    subprocess.run([*EXE, *args], env=env, cwd=cwd, check=True, capture_output=True)
    return time.perf_counter() - t0


def main() -> dict[str, float]:
    result = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        scenario = work / "sim.toml"
        out = subprocess.run([*EXE, "example", "simulate"], capture_output=True, check=True)
        scenario.write_bytes(out.stdout)
        for warm in (True, False):
            env = dict(os.environ, FRICTIONLAB_CACHE_DIR=str(work / f"cache-{warm}"))
            env.pop("NUMBA_CACHE_DIR", None)
            if warm:
                result["warmup_s"] = timed(["warmup", "--quiet"], env, work)
            key = "first_simulate_after_warmup_s" if warm else "first_simulate_cold_s"
            result[key] = timed(["simulate", str(scenario), "--out", f"out-{warm}"], env, work)
    for key, value in result.items():
        print(f"{key:32s} {value:7.2f}")
    return result


if __name__ == "__main__":
    main()
