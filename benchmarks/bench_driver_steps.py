"""The driver's Python per step, before and after a change, alternated in one process.

The whole ``frictionlab`` package of a git revision is copied to a cache folder as the
package ``_before_frictionlab`` (every ``frictionlab`` name in its sources renamed) and
imported beside the current one. Both then run, alternating, median of ``--repeats``:

* ``steps``: one point through slide / hold / slide (3100 steps, every step recorded):
  process CPU per step [us];
* ``calibrate``: the computation of ``frictionlab calibrate`` on the bundled example
  (start models, the least-squares fit, the profiles; no files, no figures): process CPU [s].

The outputs of the two are compared (every history array; the fitted values, costs and
profiles) and must be identical. The old package's kernels compile on the first run (into
``--cache``, kept for later runs). CPU times are the measure on a loaded machine; the load
average is printed beside them.

Run: ``python benchmarks/bench_driver_steps.py --before main [--repeats 5]`` from a git
checkout, with this checkout's ``src`` first on ``PYTHONPATH``.
"""

from __future__ import annotations

import argparse
import importlib
import io
import os
import re
import statistics
import subprocess
import sys
import tarfile
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OLD = "_before_frictionlab"


def _old_package(rev: str, cache: Path) -> str:
    """Copy the package of ``rev`` to ``cache`` as :data:`OLD`; returns the commit."""
    commit = subprocess.run(["git", "rev-parse", rev], cwd=ROOT, check=True, capture_output=True,
                            text=True).stdout.strip()  # fmt: skip
    folder = cache / commit[:12]
    if not (folder / OLD / "__init__.py").exists():
        data = subprocess.run(["git", "archive", commit, "src/frictionlab"], cwd=ROOT, check=True,
                              capture_output=True).stdout  # fmt: skip
        with tarfile.open(fileobj=io.BytesIO(data)) as tar:
            tar.extractall(folder / "x", filter="data")
        (folder / "x" / "src" / "frictionlab").rename(folder / OLD)
        word = re.compile(r"\bfrictionlab\b")
        for path in (folder / OLD).rglob("*.py"):
            path.write_text(word.sub(OLD, path.read_text(encoding="utf-8")), encoding="utf-8")
    sys.path.insert(0, str(folder))
    return commit


def _steps(pkg: str, example: Path) -> tuple[float, dict[str, np.ndarray]]:
    drv = importlib.import_module(f"{pkg}.driver")
    sub = importlib.import_module(f"{pkg}.subloading")
    params = sub.SubloadingParams(surface="coulomb", alpha_n=5e11, alpha_t=2e11, mu_s=0.55,
                                  mu_k=0.25, u=5e4, kappa=1e3, xi=1e-2)  # fmt: skip
    program = (drv.Slide(velocity=1e-4, distance=1e-3, max_step=5e-7),
               drv.Hold(duration=10.0, steps=500),
               drv.Slide(velocity=1e-4, distance=3e-4, max_step=5e-7))  # fmt: skip
    t0 = time.process_time()
    h = drv.simulate(params, program, drv.InitialConditions(normal_traction=1e6), n_points=1)
    per_step = (time.process_time() - t0) / h.work["steps"]
    arrays = {k: v for k, v in vars(h).items() if isinstance(v, np.ndarray)}
    return per_step * 1e6, arrays | {"work": np.array(list(h.work.values()))}


def _example(cache: Path) -> Path:
    """The calibrate starter and its data (``frictionlab example calibrate --write``)."""
    folder = cache / "calibrate-example"
    subprocess.run([sys.executable, "-m", "frictionlab", "example", "calibrate", "--write",
                    str(folder)], check=True, capture_output=True)  # fmt: skip
    return folder / "calibrate.toml"


def _calibrate(pkg: str, example: Path) -> tuple[float, dict[str, np.ndarray]]:
    load = importlib.import_module(f"{pkg}.schema.calibrate").load_calibrate
    cal = importlib.import_module(f"{pkg}.calibration")
    cfg = load(example, [])
    t0 = time.process_time()
    x0 = np.array([[float(getattr(cfg.params, n))] for n in cfg.names])
    starts = [cal.evaluate_columns(cfg.params, cfg.names, x0, c)[0] for c in cfg.curves]
    fit = cal.fit_law(cfg.params, cfg.curves, cfg.names, cfg.bounds, max_nfev=cfg.max_evaluations,
                      starts=cfg.starts, seed=cfg.seed)  # fmt: skip
    out = {"values": np.asarray(fit.values), "cost": np.asarray(fit.cost)}
    if cfg.profile:
        for name in fit.worst_identified(cfg.profile_max):
            p = cal.profile_likelihood(fit, cfg.curves, name, points=cfg.profile_points)
            out[f"profile_{name}"] = np.asarray(p.cost)
    seconds = time.process_time() - t0
    out |= {f"start_{i}": np.asarray(s) for i, s in enumerate(starts)}
    return seconds, out


def _compare(label: str, a: dict[str, Any], b: dict[str, Any]) -> bool:
    same = a.keys() == b.keys() and all(np.array_equal(a[k], b[k], equal_nan=True) for k in a)
    print(f"  {label}: outputs {'identical' if same else 'DIFFER'}")
    return same


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", default="main", help="git revision of the old driver")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--cache", type=Path, default=Path.home() / ".cache" / "frictionlab-bench")
    args = parser.parse_args()
    importlib.import_module("frictionlab.calibration")  # the current package's cache first
    importlib.import_module("frictionlab.driver")
    os.environ["FRICTIONLAB_CACHE_DIR"] = str(args.cache / "numba")  # the old one's apart
    commit = _old_package(args.before, args.cache)
    example = _example(args.cache)
    print(f"before: {args.before} ({commit[:10]}); after: the working tree")
    ok = True
    for label, work in (("steps", _steps), ("calibrate", _calibrate)):
        times: dict[str, list[float]] = {"before": [], "after": []}
        outputs = {}
        for pkg, name in ((OLD, "before"), ("frictionlab", "after")):  # compile, warm up
            outputs[name] = work(pkg, example)[1]
        for _ in range(args.repeats):
            for pkg, name in ((OLD, "before"), ("frictionlab", "after")):
                times[name].append(work(pkg, example)[0])
        unit = "us CPU/step" if label == "steps" else "s CPU"
        b, a = statistics.median(times["before"]), statistics.median(times["after"])
        print(f"{label:10s} before {b:8.3f}  after {a:8.3f} {unit}  ratio {b / a:5.2f}"
              f"  (load {os.getloadavg()[0]:.1f})")  # fmt: skip
        ok &= _compare(label, outputs["before"], outputs["after"])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
