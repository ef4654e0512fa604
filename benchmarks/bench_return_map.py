"""Benchmark of the vectorised implicit return map.

Reports the cost per contact point and per increment of ``frictionlab.subloading.update`` for
several surfaces, and measures, in the same process, the speed-up of the compiled kernel over the
same per-point loop run by the Python interpreter (``frictionlab.subloading.interpreted``: the
kernel's source with every function interpreted) on a smaller batch. ``frictionlab bench`` (or
``benchmarks/bench_speed.py``) reports the speed figures against a plain Coulomb return.

Run: ``python benchmarks/bench_return_map.py [--points N]``; writes
``benchmarks/results/return_map.json``.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from pathlib import Path

import numpy as np

from frictionlab import __version__
from frictionlab.subloading import SubloadingParams, initial_state, interpreted, kernels, update
from frictionlab.subloading.return_map import parameter_table

CASES = {
    "coulomb isotropic": dict(surface="coulomb", mu_s=0.5, mu_k=0.3),
    "coulomb rotated orthotropic": dict(
        surface="coulomb", mu_s=0.5, mu_k=0.3, rotation=(0.05, 0.02), orthotropy=(1.0, 0.6)
    ),
    "modified_cam_clay": dict(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5),
}


def _sliding_state(params: SubloadingParams, n: int, fn: float, rng: np.random.Generator):
    state = initial_state(params, normal_traction=np.full(n, fn))
    du = np.zeros((n, 3))
    du[:, 0] = 1e-3 * rng.uniform(0.5, 1.5, n)
    du[:, 1] = 3e-4 * rng.uniform(-1, 1, n)
    for _ in range(20):  # into plastic sliding
        state = update(params, state, du, 0.01).state
    return state, du


def _time(fn, min_seconds: float = 1.0) -> float:
    fn()
    count, start = 0, time.perf_counter()
    while True:
        fn()
        count += 1
        elapsed = time.perf_counter() - start
        if elapsed >= min_seconds:
            return elapsed / count


def bench_case(name: str, kw: dict, points: int, m: int, rng: np.random.Generator) -> dict:
    """Time one surface: compiled on ``points`` points, interpreted loop on ``m`` points."""
    params = SubloadingParams(u=100.0, kappa=1.0, xi=1e-3, **kw)
    fn = 1.0 if params.is_cone else 0.2
    state, du = _sliding_state(params, points, fn, rng)
    per_call = _time(lambda: update(params, state, du, 0.01))
    step = update(params, state, du, 0.01)
    slip_fraction = float(np.mean(step.status == 1))
    mean_iter = float(np.mean(step.iterations[step.status == 1]))
    small, du_small = state.take(slice(0, m)), du[:m]
    out = kernels.empty_outputs(m)
    table = parameter_table(params)

    def python_loop() -> None:
        interpreted.step_points(
            small.traction, small.F, small.R, small.gap, du_small, np.array([0.01]), table,
            True, 0 if params.is_cone else 2, 1.0, 0, 0, 0, False, True,
            out["traction"], out["F"], out["R"], out["gap"], out["dlam"], out["vp"],
            out["diss"], out["tangent"], out["status"], out["iterations"],
        )  # fmt: skip

    compiled_small = _time(lambda: update(params, small, du_small, 0.01), 0.5)
    interp = _time(python_loop, 1.0)
    return {
        "case": name,
        "points": points,
        "seconds_per_increment": per_call,
        "microseconds_per_point": per_call / points * 1e6,
        "fraction_sliding": slip_fraction,
        "mean_newton_iterations": mean_iter,
        "interpreted_microseconds_per_point": interp / m * 1e6,
        "compiled_microseconds_per_point_same_batch": compiled_small / m * 1e6,
        "speedup_over_interpreted": interp / compiled_small,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--interpreted-points", type=int, default=200)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    results = []
    for name, kw in CASES.items():
        row = bench_case(name, kw, args.points, args.interpreted_points, rng)
        results.append(row)
        print(
            f"{name:30s} {row['microseconds_per_point']:7.3f} us/point  "
            f"({row['fraction_sliding']:.0%} sliding, {row['mean_newton_iterations']:.1f} "
            f"Newton its)  compiled/interpreted speed-up x{row['speedup_over_interpreted']:.0f}"
        )
    out_dir = Path(__file__).parent / "results"
    out_dir.mkdir(exist_ok=True)
    payload = {
        "benchmark": "return_map",
        "frictionlab": __version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
        "results": results,
    }
    (out_dir / "return_map.json").write_text(json.dumps(payload, indent=2) + "\n")
    print(f"wrote {out_dir / 'return_map.json'}")


if __name__ == "__main__":
    main()
