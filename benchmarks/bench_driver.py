"""Benchmark of the loading-programme driver, ratios measured in one process.

1. driver overhead: ``simulate`` on a 2000-step slide against a bare loop of
   ``subloading.update`` calls doing the same increments (ratio of wall times);
2. vectorisation: cost per point-step of one run with N points against N = 1;
3. accuracy control: a coarse 90-degree turn with step doubling against the fine-step
   run it matches (error of each against a 64000-step reference, and the time ratio);
4. spring-slider: cost per step of the quasi-static stick-slip run (law solves per step).

Run: ``python benchmarks/bench_driver.py``; writes ``benchmarks/results/driver.json``.
"""

from __future__ import annotations

import json
import platform
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from frictionlab import __version__
from frictionlab.driver import (
    DriverSettings,
    Slide,
    SpringSlider,
    Turn,
    critical_stiffness,
    simulate,
    simulate_spring_slider,
)
from frictionlab.subloading import SubloadingParams, initial_state, update

PARAMS = SubloadingParams(mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3)


def best_of(fn: Callable[[], object], repeat: int = 3) -> float:
    fn()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def overhead() -> dict[str, float]:
    steps = 2000

    def bare() -> None:
        state = initial_state(PARAMS, 1.0)
        du = np.array([[1e-3, 0.0, 0.0]])
        for _ in range(steps):
            state = update(PARAMS, state, du, 0.01).state

    def driven() -> None:
        simulate(PARAMS, (Slide(velocity=0.1, distance=2.0, steps=steps),))

    t_bare, t_drv = best_of(bare), best_of(driven)
    return {"steps": steps, "bare_update_loop_s": t_bare, "simulate_s": t_drv,
            "driver_over_bare": t_drv / t_bare}  # fmt: skip


def vectorisation() -> dict[str, float]:
    out: dict[str, float] = {}
    t1 = best_of(lambda: simulate(PARAMS, (Slide(velocity=0.1, distance=0.5, steps=500),)))
    for n in (100, 10_000):
        tn = best_of(
            lambda n=n: simulate(
                PARAMS, (Slide(velocity=np.linspace(0.01, 1, n), distance=0.5, steps=500),)
            ),
            1,
        )
        out[f"speedup_per_point_step_N{n}"] = t1 * n / tn
        out[f"us_per_point_step_N{n}"] = tn / (500 * n) * 1e6
    out["us_per_step_N1"] = t1 / 500 * 1e6
    return out


def accuracy() -> dict[str, float]:
    def prog(steps: int) -> tuple:  # type: ignore[type-arg]
        return (
            Slide(velocity=0.1, distance=1.0, steps=50),
            Turn(angle_deg=90.0, distance=0.05, steps=steps),
        )

    ref = simulate(PARAMS, prog(64_000))
    rows_ref = ref.segments[1].first_row - 1 + 8000 * np.arange(9)

    def error(h: object, every: int) -> float:
        rows = h.segments[1].first_row - 1 + every * np.arange(9)  # type: ignore[attr-defined]
        return float(np.max(np.abs(h.traction[rows, 0] - ref.traction[rows_ref, 0])))  # type: ignore[attr-defined]

    controlled = simulate(PARAMS, prog(8), settings=DriverSettings(accuracy=1e-5))
    err_c = error(controlled, 1)
    # the uniform step count that reaches the same error
    for steps in (64, 128, 256, 512, 1024, 2048, 4096, 8192):
        uniform = simulate(PARAMS, prog(steps))
        err_u = error(uniform, steps // 8)
        if err_u <= err_c:
            break
    t_c = best_of(lambda: simulate(PARAMS, prog(8), settings=DriverSettings(accuracy=1e-5)))
    t_u = best_of(lambda: simulate(PARAMS, prog(steps)))
    return {"controlled_error": err_c, "controlled_solves": controlled.work["solves"],
            "uniform_steps_for_same_error": steps, "uniform_error": err_u,
            "uniform_solves": uniform.work["solves"], "time_ratio_controlled_over_uniform": t_c / t_u}  # fmt: skip  # noqa: E501


def spring_slider() -> dict[str, float]:
    kc = float(critical_stiffness(PARAMS, 1e-3, 1.0)[0])
    machine = SpringSlider(stiffness=0.25 * kc, velocity=1e-3)
    h = simulate_spring_slider(PARAMS, machine, 2e4, steps=2000)
    t = best_of(lambda: simulate_spring_slider(PARAMS, machine, 2e4, steps=2000), 1)
    return {"steps": 2000, "seconds": t, "solves_per_step": h.work["solves"] / 2000,
            "us_per_step": t / 2000 * 1e6}  # fmt: skip


def main() -> None:
    results = {
        "overhead": overhead(),
        "vectorisation": vectorisation(),
        "accuracy_control": accuracy(),
        "spring_slider": spring_slider(),
    }
    o, v, a, s = (
        results[k] for k in ("overhead", "vectorisation", "accuracy_control", "spring_slider")
    )
    print(f"driver overhead: simulate / bare update loop = {o['driver_over_bare']:.2f}")
    print(f"vectorisation: {v['us_per_step_N1']:.1f} us/step at N=1; per point-step speed-up "
          f"x{v['speedup_per_point_step_N100']:.0f} (N=100), x{v['speedup_per_point_step_N10000']:.0f} (N=10000)")  # fmt: skip  # noqa: E501
    print(f"accuracy control: error {a['controlled_error']:.1e} with {a['controlled_solves']} solves; "  # noqa: E501
          f"uniform steps need {a['uniform_steps_for_same_error']} steps ({a['uniform_solves']} solves); "  # noqa: E501
          f"time ratio controlled/uniform = {a['time_ratio_controlled_over_uniform']:.2f}")  # fmt: skip  # noqa: E501
    print(
        f"spring-slider: {s['solves_per_step']:.2f} law solves and {s['us_per_step']:.0f} us/step"
    )
    out_dir = Path(__file__).parent / "results"
    out_dir.mkdir(exist_ok=True)
    payload = {"benchmark": "driver", "frictionlab": __version__, "python": platform.python_version(),  # noqa: E501
               "machine": platform.machine(), "results": results}  # fmt: skip
    (out_dir / "driver.json").write_text(json.dumps(payload, indent=2) + "\n")
    print(f"wrote {out_dir / 'driver.json'}")


if __name__ == "__main__":
    main()
