"""The calibrate example, warm: the driver's cost per step, the fit, and the whole command.

Three measures, the load average printed beside each (a shared machine: CPU times are the
measure, wall times are shown):

1. ``steps``: one point and seven points (a fit's Jacobian run) through slide / hold /
   slide / hold / reverse (3202 steps), every step recorded, no peak refinement (as a
   fit runs the driver), with the driver's compiled loop off
   (``DriverSettings(compiled=False)``: the Python steps) and on, alternated in this
   process, median of ``--repeats``: process CPU per step [us]. The histories must agree
   to 1e-12 relative.
2. ``compute``: what ``frictionlab calibrate`` computes for the bundled example (start
   model, the least-squares fit, the profiles; no files) with the loop off and on,
   alternated: process CPU [s]. The fitted values, costs and profiles must agree to 1e-12.
3. ``command``: ``frictionlab calibrate calibrate.toml --out DIR`` in a fresh process
   (``--runs`` times, after one run that may compile), wall and CPU, with the time split
   into: start-up and imports up to the command, reading the inputs, the computation, the
   figures (matplotlib's import, drawing and PNG encoding), writing the other files, and
   the interpreter's start and exit (the command ends as ``frictionlab`` does:
   :func:`frictionlab.cli.run`).

Run: ``python benchmarks/bench_calibrate.py [--repeats 3] [--runs 2] [--command-only]`` with this
checkout's ``src`` first on ``PYTHONPATH``. Exit status 1 when the two paths disagree.
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
from typing import Any

import numpy as np

RTOL = 1e-12

#: The child process of measure 3: the real command, its phases timed by wrappers.
CHILD = r"""
import json, sys, time
t0, c0 = time.perf_counter(), time.process_time()
phases = {}
def timed(owner, name, key):
    real = getattr(owner, name)
    def wrapper(*a, **k):
        t, c = time.perf_counter(), time.process_time()
        try:
            return real(*a, **k)
        finally:
            w, p = phases.get(key, (0.0, 0.0))
            phases[key] = (w + time.perf_counter() - t, p + time.process_time() - c)
    setattr(owner, name, wrapper)
from frictionlab import cli
import frictionlab.app.calibrate as app
phases["start-up and imports"] = (time.perf_counter() - t0, time.process_time() - c0)
timed(app.Calibrate, "parse", "reading the inputs")
timed(app.Calibrate, "run", "computation")
files = app._files
def measured_files(out, run, base):
    t, c = time.perf_counter(), time.process_time()
    import frictionlab.plotting.calibration as pc, frictionlab.plotting.law as pl
    phases["figures"] = (time.perf_counter() - t, time.process_time() - c)
    for name in ("plot_curve_fit", "plot_correlation", "plot_profile"):
        timed(pc, name, "figures")
    timed(pl, "save_figure", "figures")
    return files(out, run, base)
app._files = measured_files
timed(app.Calibrate, "files", "files")
timed(app.Calibrate, "summary", "writing the other files")
main = cli.main
def measured_main(argv=None):
    code = main(argv)
    w, p = phases.pop("files")
    fw, fp = phases["figures"]
    w0, p0 = phases.get("writing the other files", (0.0, 0.0))
    phases["writing the other files"] = (w0 + w - fw, p0 + p - fp)
    phases["total"] = (time.perf_counter() - t0, time.process_time() - c0)
    print(json.dumps({"code": code, "phases": phases}))
    return code
cli.main = measured_main
cli.run()  # as the console command ends: exit handlers, then no interpreter teardown
"""


def _set_compiled(on: bool) -> None:
    """Switch the driver's compiled loop for every run made in this process."""
    from frictionlab.driver import compiled_steps as module

    simulate_module = sys.modules["frictionlab.driver.simulate"]  # the package exports the function
    simulate_module.compiled_steps = (  # type: ignore[attr-defined]
        module.compiled_steps if on else (lambda *args, **kwargs: None)
    )


def _agree(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> float:
    """Largest relative difference over the arrays (inf when shapes or keys differ)."""
    if a.keys() != b.keys():
        return float("inf")
    worst = 0.0
    for key in a:
        x, y = np.asarray(a[key], dtype=np.float64), np.asarray(b[key], dtype=np.float64)
        if x.shape != y.shape:
            return float("inf")
        scale = np.maximum(np.maximum(np.abs(x), np.abs(y)), 1e-300)
        diff = np.where(x == y, 0.0, np.abs(x - y) / scale)
        worst = max(worst, float(np.max(diff, initial=0.0)))
    return worst


def _steps(n: int) -> tuple[float, dict[str, np.ndarray]]:
    from frictionlab.driver import Hold, InitialConditions, Reverse, Slide, simulate
    from frictionlab.subloading import SubloadingParams

    params = SubloadingParams(surface="coulomb", alpha_n=5e11, alpha_t=np.linspace(2e11, 3e11, n),
                              mu_s=0.55, mu_k=0.25, u=5e4, kappa=1e3, xi=1e-2)  # fmt: skip
    program = (Slide(velocity=1e-4, distance=1e-3, max_step=5e-7), Hold(duration=10.0),
               Slide(velocity=1e-4, distance=3e-4, max_step=5e-7), Hold(duration=100.0),
               Reverse(distance=3e-4, max_step=5e-7))  # fmt: skip
    c0 = time.process_time()
    h = simulate(
        params, program, InitialConditions(normal_traction=1e6), n_points=n, peak_accuracy=None
    )  # as a fit runs it: no peak refinement
    per_step = (time.process_time() - c0) / h.work["steps"]
    arrays = {k: v for k, v in vars(h).items() if isinstance(v, np.ndarray)}
    return per_step * 1e6, arrays | {"work": np.array(list(h.work.values()))}


def _example(folder: Path) -> Path:
    subprocess.run([sys.executable, "-m", "frictionlab", "example", "calibrate", "--write",
                    str(folder)], check=True, capture_output=True)  # fmt: skip
    return folder / "calibrate.toml"


def _compute(example: Path) -> tuple[float, dict[str, np.ndarray]]:
    from frictionlab.calibration import evaluate_columns, fit_law, profile_likelihood
    from frictionlab.schema.calibrate import load_calibrate

    cfg = load_calibrate(example, [])
    c0 = time.process_time()
    x0 = np.array([[float(getattr(cfg.params, n))] for n in cfg.names])
    starts = [evaluate_columns(cfg.params, cfg.names, x0, c)[0] for c in cfg.curves]
    fit = fit_law(cfg.params, cfg.curves, cfg.names, cfg.bounds, max_nfev=cfg.max_evaluations,
                  starts=cfg.starts, seed=cfg.seed)  # fmt: skip
    out = {"values": np.asarray(fit.values), "cost": np.asarray(fit.cost),
           "stderr": np.asarray(fit.stderr)}  # fmt: skip
    if cfg.profile:
        for name in fit.worst_identified(cfg.profile_max):
            p = profile_likelihood(fit, cfg.curves, name, points=cfg.profile_points)
            out[f"profile_{name}"] = np.asarray(p.cost)
    seconds = time.process_time() - c0
    return seconds, out | {f"start_{i}": np.asarray(s) for i, s in enumerate(starts)}


def _alternate(label: str, unit: str, work: Any, repeats: int) -> bool:
    times: dict[bool, list[float]] = {False: [], True: []}
    outputs = {}
    for on in (False, True):  # warm-up (a first run may compile)
        _set_compiled(on)
        outputs[on] = work()[1]
    for _ in range(repeats):
        for on in (False, True):
            _set_compiled(on)
            times[on].append(work()[0])
    _set_compiled(True)
    before, after = statistics.median(times[False]), statistics.median(times[True])
    worst = _agree(outputs[False], outputs[True])
    print(f"{label:18s} Python steps {before:9.3f}  compiled loop {after:9.3f} {unit}"
          f"  ratio {before / after:5.2f}  agree to {worst:.1e}"
          f"  (load {os.getloadavg()[0]:.1f})")  # fmt: skip
    return worst <= RTOL


def _command(example: Path, runs: int) -> None:
    env = os.environ | {"PYTHONPATH": str(Path(__file__).resolve().parents[1] / "src")
                        + os.pathsep + os.environ.get("PYTHONPATH", "")}  # fmt: skip
    results = []
    for i in range(runs + 1):
        with tempfile.TemporaryDirectory() as out:
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            done = subprocess.run([sys.executable, "-c", CHILD, "calibrate", str(example),
                                   "--out", out], env=env, capture_output=True, text=True,
                                  cwd=example.parent)  # fmt: skip
            wall = time.perf_counter() - t0
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if done.returncode:
            raise SystemExit(done.stderr[-2000:])
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        report = json.loads(done.stdout.strip().splitlines()[-1])
        if i:  # the first run may compile
            results.append((wall, cpu, report["phases"], os.getloadavg()[0]))
    for wall, cpu, phases, load in results:
        print(f"command            wall {wall:6.2f} s  CPU {cpu:6.2f} s (user+sys)"
              f"  (load {load:.1f})")  # fmt: skip
        for name, (w, c) in phases.items():
            print(f"    {name:28s} wall {w:6.2f} s  CPU {c:6.2f} s")
        outside = wall - phases["total"][0]
        print(f"    {'interpreter start and exit':28s} wall {outside:6.2f} s")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--runs", type=int, default=2, help="warm runs of the whole command")
    parser.add_argument("--command-only", action="store_true", help="measure 3 only")
    args = parser.parse_args()
    ok = True
    with tempfile.TemporaryDirectory() as folder:
        example = _example(Path(folder))
        if not args.command_only:
            ok &= _alternate("steps, 1 point", "us CPU/step", lambda: _steps(1), args.repeats)
            ok &= _alternate("steps, 7 points", "us CPU/step", lambda: _steps(7), args.repeats)
            ok &= _alternate("compute", "s CPU", lambda: _compute(example), args.repeats)
        _command(example, args.runs)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
