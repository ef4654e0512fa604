"""``frictionlab demo``: the bundled default simulation.

Slides a virgin Coulomb contact (parameter set A of the spec) to kinetic friction, holds
it for three hold times and slides again, for the three hold times at once (one
vectorised run of three points). Prints a table and writes it to ``OUT/demo.csv``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from frictionlab.io.atomic import write_text_atomic
from frictionlab.subloading import SubloadingParams, initial_state, update

HOLD_TIMES = (10.0, 1000.0, 1e5)  # s


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("demo", help="run the bundled default simulation")
    parser.add_argument("--out", type=Path, default=Path("out/demo"), help="output directory")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    params = SubloadingParams(
        surface="coulomb", alpha_n=1000.0, alpha_t=1000.0, mu_s=0.5, mu_k=0.3,
        u=100.0, kappa=1.0, xi=1e-3,
    )  # fmt: skip
    holds = np.array(HOLD_TIMES)
    n = holds.size
    state = initial_state(params, normal_traction=np.ones(n))
    velocity, dx = 0.1, 1e-3
    rows = []
    first_peak = 0.0
    for _ in range(1000):  # slide 1 m
        state = update(params, state, np.tile([dx, 0.0, 0.0], (n, 1)), dx / velocity).state
        first_peak = max(first_peak, float(state.traction[0, 0]))
    before = state.traction[:, 0].copy()
    for _ in range(100):  # hold
        state = update(params, state, np.zeros((n, 3)), holds / 100).state
    recovered = state.F.copy()
    peaks = np.zeros(n)
    for _ in range(300):  # slide again 0.3 m
        state = update(params, state, np.tile([dx, 0.0, 0.0], (n, 1)), dx / velocity).state
        peaks = np.maximum(peaks, state.traction[:, 0])
    for k in range(n):
        rows.append((holds[k], before[k], recovered[k], peaks[k]))
    header = "hold_time_s,friction_before_hold,mu_after_hold,restart_peak"
    lines = [header] + [",".join(f"{v:.6g}" for v in row) for row in rows]
    print(f"first static peak: {first_peak:.4f} (mu_s = 0.5, mu_k = 0.3)")
    print(f"{'hold [s]':>10} {'before':>8} {'mu after':>9} {'restart peak':>13}")
    for row in rows:
        print(f"{row[0]:>10.3g} {row[1]:>8.4f} {row[2]:>9.4f} {row[3]:>13.4f}")
    path = write_text_atomic(args.out / "demo.csv", "\n".join(lines) + "\n")
    print(f"wrote {path}")
    return 0
