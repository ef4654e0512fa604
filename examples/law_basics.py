"""Calling the subloading-friction law directly: one slide of many contact points.

Each point gets its own static friction coefficient (per-point parameters), all points slide
together in one vectorised call per increment, and the script prints the static peak and the
steady friction of each point next to the closed-form steady value mu_ss(V).

Run: ``python examples/law_basics.py``
"""

from __future__ import annotations

import numpy as np

from frictionlab.subloading import SubloadingParams, initial_state, steady_size, update


def main() -> dict[str, np.ndarray]:
    mu_s = np.array([0.35, 0.45, 0.55, 0.65])  # one static coefficient per contact point
    # A contact at 1 MPa: stiffness 1 MPa per um, R saturates over ~10 um, softening ~1 mm
    params = SubloadingParams(
        surface="coulomb", alpha_n=1e12, alpha_t=1e12, mu_s=mu_s, mu_k=0.3,
        u=1e5, kappa=1e3, xi=1e-3,
    )  # fmt: skip  # alpha in Pa/m, u and kappa in 1/m, xi in 1/s
    n = mu_s.size
    state = initial_state(params, normal_traction=np.full(n, 1e6))  # Pa, compression positive
    velocity, dx, steps = 1e-4, 2e-6, 2500  # 0.1 mm/s in 2 um increments: slide 5 mm
    slip_increment = np.tile([dx, 0.0, 0.0], (n, 1))
    peak = np.zeros(n)
    for _ in range(steps):
        step = update(params, state, slip_increment, dx / velocity)
        state = step.state
        peak = np.maximum(peak, step.traction[:, 0] / step.traction[:, 2])  # friction ratio
    steady = state.traction[:, 0] / state.traction[:, 2]
    expected = steady_size(velocity, 1e3, 1e-3, mu_s, 0.3)
    print(f"{'mu_s':>6} {'peak':>8} {'steady':>8} {'mu_ss(V)':>9}")
    for row in zip(mu_s, peak, steady, expected, strict=True):
        print(" ".join(f"{v:8.4f}" for v in row))
    return {"mu_s": mu_s, "peak": peak, "steady": steady, "mu_ss": expected}


if __name__ == "__main__":
    main()
