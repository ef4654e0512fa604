"""First run as a user meets it: an empty compile cache, then ``frictionlab warmup`` (what
``make venv`` runs), then the first ``frictionlab simulate`` of the starter scenario, each
in a fresh process; then a second simulate (everything loaded from the cache).

Each line gives the wall time, the CPU time of the process (user + system, from the
children's resource usage) and the load average at its end: on a shared machine the CPU
time is the measure, the wall time only when the load is below the number of cores. The
first simulate also lists the kernels numba compiled in it (a listener on numba's
``numba:compile`` event, which fires only for a real compilation, not a cache load): after
the warm-up it should list none.

``--cold`` adds the same first simulate on a second empty cache without the warm-up;
``--repeat N`` runs the warm simulate N times (default 1) and gives the median and range
(one run spreads by tenths of a second of CPU on a loaded machine).
Run: ``python benchmarks/bench_first_run.py [--cold] [--repeat N] [--json FILE]``.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXE = [sys.executable, "-m", "frictionlab"]
#: Runs the CLI with a listener that prints each kernel numba compiles (to stderr).
SPY = (
    "import sys\n"
    "from numba.core import event\n"
    "class Spy(event.Listener):\n"
    "    def on_start(self, e):\n"
    "        d = e.data['dispatcher']\n"
    "        print('COMPILED', d.py_func.__module__ + '.' + d.py_func.__qualname__,"
    " file=sys.stderr)\n"
    "    def on_end(self, e):\n"
    "        pass\n"
    "event.register('numba:compile', Spy())\n"
    "from frictionlab.cli import run\n"
    "sys.argv[0] = 'frictionlab'\n"
    "run()\n"
)


def timed(args: list[str], env: dict[str, str], cwd: Path, spy: bool = False) -> dict:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    cmd = [sys.executable, "-c", SPY, *args] if spy else [*EXE, *args]
    done = subprocess.run(cmd, env=env, cwd=cwd, check=True, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    result = {"wall_s": round(wall, 2), "cpu_s": round(cpu, 2), "load": os.getloadavg()[0]}
    if spy:
        compiled = [line.split(" ", 1)[1] for line in done.stderr.splitlines()
                    if line.startswith("COMPILED ")]  # fmt: skip
        result["compiled"] = sorted(set(compiled))
    return result


def _median(runs: list[dict]) -> dict:
    """The median wall and CPU time of ``runs`` (with their ranges when more than one)."""
    out = {key: round(statistics.median(r[key] for r in runs), 2) for key in ("wall_s", "cpu_s")}
    out["load"] = runs[-1]["load"]
    if len(runs) > 1:
        out["runs"] = len(runs)
        for key in ("wall_s", "cpu_s"):
            out[key + "_range"] = [min(r[key] for r in runs), max(r[key] for r in runs)]
    return out


def main() -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cold", action="store_true", help="also a first simulate, no warm-up")
    parser.add_argument("--repeat", type=int, default=1, help="warm simulates to run (median)")
    parser.add_argument("--json", type=Path, help="write the figures here")
    args = parser.parse_args()
    result: dict = {"cores": os.cpu_count(), "load_at_start": os.getloadavg()[0]}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        scenario = work / "sim.toml"
        out = subprocess.run([*EXE, "example", "simulate"], capture_output=True, check=True)
        scenario.write_bytes(out.stdout)
        simulate = ["simulate", str(scenario), "--quiet", "--out"]
        for warm in (True, False) if args.cold else (True,):
            env = dict(os.environ, FRICTIONLAB_CACHE_DIR=str(work / f"cache-{warm}"))
            env.pop("NUMBA_CACHE_DIR", None)
            if warm:
                result["warmup"] = timed(["warmup", "--quiet"], env, work)
                result["first_simulate_after_warmup"] = timed(
                    [*simulate, "out-first"], env, work, spy=True
                )
                runs = [timed([*simulate, f"out-{k}"], env, work) for k in range(args.repeat)]
                result["second_simulate"] = _median(runs)
            else:
                result["first_simulate_cold"] = timed([*simulate, "out-cold"], env, work, spy=True)
    for key, value in result.items():
        if isinstance(value, dict):
            extra = (
                f"  compiled: {', '.join(value['compiled']) or 'nothing'}"
                if "compiled" in value
                else ""
            )
            if "runs" in value:
                extra += (f"  median of {value['runs']}: CPU {value['cpu_s_range'][0]:.2f}-"
                          f"{value['cpu_s_range'][1]:.2f} s")  # fmt: skip
            print(f"{key:30s} wall {value['wall_s']:7.2f} s  CPU {value['cpu_s']:7.2f} s  "
                  f"load {value['load']:5.2f}{extra}")  # fmt: skip
    if args.json:
        args.json.write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main()
