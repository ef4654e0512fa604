"""Wall and CPU time of the commands users wait for, two source trees alternated.

    python benchmarks/bench_commands.py [--before /work/main/src] [--repeats 3]
        [--commands simulate calibrate] [--keep DIR]

``simulate``: the starter scenario (``frictionlab example simulate``); ``calibrate``: the
calibrate example (``frictionlab example calibrate --write``). Each command runs in a fresh
process with ``PYTHONPATH`` set to this checkout's ``src`` ("after") and, with ``--before``,
to another source tree ("before"), alternated so that both see the same load. One untimed
run per tree first fills its compile cache (the runs then compile nothing). Each line gives
the wall time, the CPU time of the process (user + system, from the children's resource
usage) and the 1-minute load average at its end: on a shared machine the CPU time is the
measure. The last output folders of the two trees are compared with compare_outputs.py.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
AFTER = HERE.parent / "src"


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _run(src: Path, args: list[str], cwd: Path) -> tuple[float, float]:
    env = dict(os.environ, PYTHONPATH=str(src))
    c0, t0 = _cpu(), time.perf_counter()
    subprocess.run([sys.executable, "-m", "frictionlab", *args], cwd=cwd, env=env,
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)  # fmt: skip
    return time.perf_counter() - t0, _cpu() - c0


def _inputs(work: Path) -> dict[str, list[str]]:
    env = dict(os.environ, PYTHONPATH=str(AFTER))
    exe = [sys.executable, "-m", "frictionlab", "example"]
    sim = subprocess.run([*exe, "simulate"], env=env, check=True, capture_output=True, text=True)
    (work / "sim.toml").write_text(sim.stdout)
    subprocess.run([*exe, "calibrate", "--write", str(work / "cal")], env=env, check=True,
                   stdout=subprocess.DEVNULL)  # fmt: skip
    return {
        "simulate": ["simulate", str(work / "sim.toml"), "--out"],
        "calibrate": ["calibrate", str(work / "cal" / "calibrate.toml"), "--out"],
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", type=Path, help="another source tree (its src folder)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--commands", nargs="+", default=["simulate", "calibrate"])
    parser.add_argument("--keep", type=Path, help="folder for inputs and outputs (kept)")
    a = parser.parse_args(argv)
    work = a.keep or Path(tempfile.mkdtemp(prefix="bench_commands_"))
    work.mkdir(parents=True, exist_ok=True)
    commands = _inputs(work)
    trees = {"after": AFTER} | ({"before": a.before.resolve()} if a.before else {})
    status = 0
    for name in a.commands:
        for tag, src in trees.items():  # untimed: fills the tree's compile cache
            _run(src, [*commands[name], str(work / f"{name}_{tag}")], work)
        for i in range(a.repeats):
            for tag, src in trees.items():
                wall, cpu = _run(src, [*commands[name], str(work / f"{name}_{tag}")], work)
                load = os.getloadavg()[0]
                print(f"{name:9s} {tag:6s} run {i + 1}: {wall:6.2f} s wall "
                      f"{cpu:6.2f} s CPU  load {load:.1f}", flush=True)  # fmt: skip
        if a.before:
            done = subprocess.run(
                [sys.executable, str(HERE / "compare_outputs.py"),
                 str(work / f"{name}_before"), str(work / f"{name}_after")],
                capture_output=True, text=True,
            )  # fmt: skip
            print(f"{name}: compare_outputs (before vs after): {done.stdout.strip()}")
            status |= done.returncode
    return status


if __name__ == "__main__":
    raise SystemExit(main())
