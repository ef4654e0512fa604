"""Stick-slip of a spring-slider below and above the critical machine stiffness.

Pulls a Coulomb contact (1 MPa) through a spring at 1 um/s over 20 mm for machine
stiffnesses from k_c/4 to 4 k_c (one per point, quasi-static slider), prints the
peak-to-peak friction in the last quarter of the run against the prediction of the linear
stability analysis (stick-slip below k_c, steady sliding above), and writes the curves to
the folder.

Run: ``python examples/stick_slip.py OUT_DIR``
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from frictionlab.driver import (
    InitialConditions,
    SpringSlider,
    critical_stiffness,
    friction_oscillation,
    simulate_spring_slider,
)
from frictionlab.plotting.law import plot_spring_slider, save_figure
from frictionlab.subloading import SubloadingParams


def main(out_dir: Path) -> dict[str, np.ndarray]:
    params = SubloadingParams(
        surface="coulomb", alpha_n=1e12, alpha_t=1e12, mu_s=0.5, mu_k=0.3,
        u=1e5, kappa=1e3, xi=1e-3,
    )  # fmt: skip  # Pa/m, 1/m, 1/s
    velocity = 1e-6  # m/s (1 um/s)
    normal_traction = 1e6  # Pa
    k_c = float(critical_stiffness(params, velocity, normal_traction=normal_traction)[0])
    factor = np.array([0.25, 0.5, 2.0, 4.0])
    machine = SpringSlider(stiffness=factor * k_c, velocity=velocity)
    history = simulate_spring_slider(
        params, machine, duration=2e4, steps=2000,
        initial=InitialConditions(normal_traction=normal_traction),
    )  # fmt: skip
    oscillation = friction_oscillation(history, tail=0.25)
    print(f"critical stiffness k_c = {k_c:.5g} Pa/m at V = {velocity} m/s")
    print(f"{'k/k_c':>6} {'peak-to-peak friction':>22}  regime")
    for f, o in zip(factor, oscillation, strict=True):
        print(f"{f:>6g} {o:>22.3e}  {'stick-slip' if o > 1e-3 else 'steady sliding'}")
    labels = [f"k = {f:g} k_c" for f in factor]
    save_figure(plot_spring_slider(history, labels), out_dir / "stick_slip.png")
    print(f"wrote {out_dir / 'stick_slip.png'}")
    return {"factor": factor, "oscillation": oscillation}


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir", type=Path)
    main(parser.parse_args().out_dir)
