"""Benchmark: a 91-direction polar curve mu(beta) of a 256 x 256 surface pair, partial contact.

Not a timed test: run it by hand and compare the numbers printed on the same machine::

    python benchmarks/bench_roughness_polar.py [--points 256] [--time-samples 64]

Setup: two independent self-affine height maps (H = 0.8, rms slope 0.2, 1 mm x 1 mm,
256 x 256 samples, seeds 1 and 2), mu0 = 0.3, load 0.5 k_c rms_height per spring (partial
contact; the contact fraction is printed), beta = 0, 1, ..., 90 deg, travel "auto" (exact
return at 0, 45, 90 deg; the ergodic average elsewhere) with ``--time-samples`` samples.

Unit of work: one **station-sample** = the two springs (one per family) at one lattice
station for one time sample: the gap, its share of the load balance (Newton passes over
all stations, counted in the printed iterations), the lookup of both multipliers
H(mu0, grad f, beta) and the force sums. Reported: seconds for the whole polar curve,
nanoseconds per station-sample and per spring, and the same for the NumPy engine on the
first ``--baseline-directions`` directions in the same process. JSON goes to
benchmarks/results/roughness_polar.json.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from pathlib import Path

import numpy as np

from frictionlab.roughness import generators
from frictionlab.roughness.lattice import LatticeSettings, friction_polar


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=256)
    parser.add_argument("--time-samples", type=int, default=64)
    parser.add_argument("--baseline-directions", type=int, default=3)
    args = parser.parse_args()
    n = args.points
    size = (1e-3, 1e-3)
    lower = generators.self_affine(0.8, size, (n, n), rng=np.random.default_rng(1), rms_slope=0.2)
    upper = generators.self_affine(0.8, size, (n, n), rng=np.random.default_rng(2), rms_slope=0.2)
    rms = float(np.std(lower.heights))
    load = 0.5 * rms  # per spring, k_c = 1 N/m
    betas = np.arange(0.0, 91.0, 1.0)
    settings = LatticeSettings(load=load, time_samples=args.time_samples)

    friction_polar(lower, upper, 0.3, [0.0, 33.0], settings=settings)  # compile / warm up
    start = time.perf_counter()
    polar = friction_polar(lower, upper, 0.3, betas, settings=settings)
    seconds = time.perf_counter() - start
    work = polar.spring_evaluations
    ns = seconds / work * 1e9

    base_betas = betas[: args.baseline_directions]
    numpy_settings = LatticeSettings(load=load, time_samples=args.time_samples, engine="numpy")
    start = time.perf_counter()
    base = friction_polar(lower, upper, 0.3, base_betas, settings=numpy_settings)
    base_seconds = time.perf_counter() - start
    base_ns = base_seconds / base.spring_evaluations * 1e9
    agree = float(np.max(np.abs(base.mu - polar.mu[: base_betas.size])))

    modes = {m: polar.travel_mode.count(m) for m in sorted(set(polar.travel_mode))}
    result = {
        "benchmark": "roughness_polar",
        "surfaces": f"2 x self-affine {n} x {n}, H = 0.8, rms slope 0.2, 1 mm x 1 mm",
        "directions": int(betas.size),
        "time_samples_setting": args.time_samples,
        "time_samples_total": int(polar.time_samples.sum()),
        "travel_modes": modes,
        "stations": int(polar.geometry.n_stations),
        "load_per_spring_N": load,
        "contact_fraction_mean": float(np.mean(polar.contact_fraction_mean)),
        "newton_iterations_max": int(polar.solver_iterations_max.max()),
        "seconds_numba": seconds,
        "station_samples": int(work),
        "ns_per_station_sample_numba": ns,
        "ns_per_spring_numba": ns / 2.0,
        "seconds_numpy_baseline": base_seconds,
        "baseline_directions": int(base_betas.size),
        "ns_per_station_sample_numpy": base_ns,
        "speedup_numba_over_numpy": base_ns / ns,
        "max_abs_diff_numba_numpy": agree,
        "mu_over_mu0_range": [float(polar.mu_over_mu0.min()), float(polar.mu_over_mu0.max())],
        "machine": platform.processor() or platform.machine(),
        "python": platform.python_version(),
    }
    out = Path(__file__).resolve().parent / "results" / "roughness_polar.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n")
    print(
        f"91-direction polar curve, {n} x {n} pair, partial contact "
        f"(mean contact fraction {result['contact_fraction_mean']:.2f}):"
    )
    print(
        f"  numba : {seconds:.2f} s for {work:.3e} station-samples = {ns:.2f} ns each "
        f"({ns / 2:.2f} ns per spring); travel {modes}; "
        f"Newton iterations <= {result['newton_iterations_max']}"
    )
    print(
        f"  numpy : {base_ns:.2f} ns per station-sample on {base_betas.size} directions "
        f"-> numba is {base_ns / ns:.1f}x faster; max |mu diff| = {agree:.1e}"
    )
    low, high = result["mu_over_mu0_range"]
    print(f"  mu/mu0 from {low:.4f} to {high:.4f}")
    print(f"  wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
