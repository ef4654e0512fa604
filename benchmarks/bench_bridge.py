"""Benchmark: `frictionlab bridge` on a 256 x 256 self-affine pair, stage by stage.

Not a timed test: run it by hand and compare the numbers printed on the same machine::

    python benchmarks/bench_bridge.py [--points 256] [--time-samples 400]

Setup: two independent self-affine height maps (H = 0.8, rms slope 0.2, 1 mm x 1 mm,
``--points`` squared samples, seeds 1 and 2), mu0 = 0.3, full contact, the bridge's default
polar (36 directions every 10 deg), the default [bridge] check (400 steps, every direction).

Reported: seconds of the three stages of :func:`frictionlab.app.bridge.run_bridge`
(lattice polar, least-squares fit, steady-sliding check of the fitted law) and, as the
in-process baseline, one ``friction_polar`` call over the same 36 directions: the ratio
bridge-polar / baseline is the cost of computing the polar in chunks for the progress bar
(1.0 = free). JSON goes to benchmarks/results/bridge.json.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from pathlib import Path

from frictionlab.app.bridge import run_bridge
from frictionlab.io.bridge_scenario import parse_bridge_scenario
from frictionlab.roughness.lattice import friction_polar


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=256)
    parser.add_argument("--time-samples", type=int, default=400)
    args = parser.parse_args()
    surface = {
        "kind": "self_affine", "hurst": 0.8, "physical_sizes": [1e-3, 1e-3],
        "points": [args.points, args.points], "rms_slope": 0.2,
    }  # fmt: skip
    data = {
        "title": "benchmark",
        "mu0": 0.3,
        "lower": {**surface, "seed": 1},
        "upper": {**surface, "seed": 2},
        "sliding": {"beta_deg": 0.0},
        "lattice": {"time_samples": args.time_samples},
        "law": {
            "mu_s": 0.5,
            "mu_k": 0.3,
            "alpha_n": 1e5,
            "alpha_t": 1e5,
            "u": 1e4,
            "kappa": 100.0,
            "xi": 1e-3,
        },
        "bridge": {"scale": "roughness"},
    }
    scenario = parse_bridge_scenario(data, Path("."))
    r = scenario.roughness
    friction_polar(r.lower, r.upper, r.mu0, [0.0, 33.0], settings=r.settings)  # compile
    start = time.perf_counter()
    baseline = friction_polar(r.lower, r.upper, r.mu0, scenario.directions_deg, settings=r.settings)
    base_seconds = time.perf_counter() - start
    run = run_bridge(scenario, Path("benchmark.toml"))
    ratio = run.seconds["polar"] / base_seconds
    result = {
        "machine": platform.platform(),
        "points": args.points,
        "time_samples": args.time_samples,
        "directions": int(scenario.directions_deg.size),
        "station_samples": int(baseline.spring_evaluations),
        "seconds_polar": run.seconds["polar"],
        "seconds_fit": run.seconds["fit"],
        "seconds_check": run.seconds["check"],
        "seconds_baseline_polar": base_seconds,
        "ratio_bridge_polar_over_baseline": ratio,
        "relative_rms_misfit": run.fit.relative_rms_misfit,
        "check_max_abs_difference": float(run.difference.max()),
    }
    print(
        f"bridge on {args.points}^2 self-affine pair, {result['directions']} directions: "
        f"polar {run.seconds['polar']:.3f} s (one friction_polar call: {base_seconds:.3f} s, "
        f"ratio {ratio:.3f}), fit {run.seconds['fit'] * 1e3:.1f} ms, check "
        f"{run.seconds['check'] * 1e3:.1f} ms; misfit {run.fit.relative_rms_misfit:.2%}, "
        f"check difference {result['check_max_abs_difference']:.1e}"
    )
    out = Path(__file__).parent / "results" / "bridge.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
