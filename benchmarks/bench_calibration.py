"""Benchmark: the batched finite-difference Jacobian of `frictionlab calibrate`.

Not a timed test: run it by hand and compare the numbers printed on the same machine::

    python benchmarks/bench_calibration.py [--repeat 3]

Setup: the packaged calibration example, frictionlab/data/examples/calibrate.toml (one
slide-hold-slide curve of 4291 samples, about 400 driver steps; six fitted parameters).
Measured in the same process:

* one Jacobian, batched (the 6 perturbations and the base as 7 contact points of ONE
  driver run) against the naive baseline (7 separate runs), best of ``--repeat``;
* the whole least-squares fit with each Jacobian (same start, same optimiser settings:
  the iterates agree, so only the cost of the evaluations differs).

Ratios naive / batched > 1 are the speed-up. JSON goes to
benchmarks/results/calibration.json.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from pathlib import Path

import numpy as np

from frictionlab.calibration import fit_law
from frictionlab.calibration.fit import Objective, make_space
from frictionlab.io.calibration_config import load_calibration

ROOT = Path(__file__).resolve().parents[1]


def best(call, repeat: int) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    cfg = load_calibration(ROOT / "src" / "frictionlab" / "data" / "examples" / "calibrate.toml")
    space = make_space(cfg.params, cfg.names, cfg.bounds)
    theta = space.to_theta([float(getattr(cfg.params, n)) for n in cfg.names])
    batched = Objective(cfg.params, cfg.curves, space, jacobian="batched")
    naive = Objective(cfg.params, cfg.curves, space, jacobian="naive")
    batched.jac(theta)  # compile and warm up
    jac_b = best(lambda: batched.jac(theta), args.repeat)
    jac_n = best(lambda: naive.jac(theta), args.repeat)
    same = float(np.max(np.abs(batched.jac(theta) - naive.jac(theta))))
    fits = {}
    for kind in ("batched", "naive"):
        start = time.perf_counter()
        fit = fit_law(cfg.params, cfg.curves, cfg.names, cfg.bounds, jacobian=kind,
                      max_nfev=cfg.max_evaluations)  # fmt: skip
        fits[kind] = (time.perf_counter() - start, fit)
    fb, fn = fits["batched"][1], fits["naive"][1]
    result = {
        "machine": platform.platform(),
        "samples": int(sum(c.n_samples for c in cfg.curves)),
        "parameters": list(cfg.names),
        "seconds_jacobian_batched": jac_b,
        "seconds_jacobian_naive": jac_n,
        "ratio_jacobian_naive_over_batched": jac_n / jac_b,
        "max_abs_jacobian_difference": same,
        "seconds_fit_batched": fits["batched"][0],
        "seconds_fit_naive": fits["naive"][0],
        "ratio_fit_naive_over_batched": fits["naive"][0] / fits["batched"][0],
        "driver_runs_batched": fb.runs,
        "driver_runs_naive": fn.runs,
        "max_relative_difference_of_fitted_values": float(
            np.max(np.abs(fb.values / fn.values - 1.0))
        ),
    }
    print(json.dumps(result, indent=2))
    out = ROOT / "benchmarks" / "results" / "calibration.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
