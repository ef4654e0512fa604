"""Benchmark: `frictionlab contact` on a ~10^4-dof mesh, Newton iterations and time per step.

Not a timed test: run it by hand and compare the numbers printed on the same machine::

    python benchmarks/bench_contact.py [--element-size 7.142857e-4] [--steps 15]

Setup: the bundled PMMA-like block (100 mm x 25 mm, E = 3 GPa, nu = 0.35; cone law
mu_s = 0.6, mu_k = 0.4), 140 x 35 bilinear quadrilaterals (10,152 dofs, 280 contact
points), 1 MPa in 2 steps, then a 30 um slide in ``--steps`` steps through the static
peak. Reported: mesh and factorisation time, Newton iterations and wall time per
step and per iteration (from the end of the first step to the end of the last), and two
in-process baselines on the same mesh and boundary conditions: one linear-elastic solve
(factorise K with the pressure load and solve), and one sparse LU of the assembled
consistent tangent (what a Newton iteration would cost without the one-factorisation
Woodbury solve). JSON goes to benchmarks/results/contact.json.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from pathlib import Path

import numpy as np
import scipy.sparse.linalg as spla

from frictionlab.contact import Block, NormalLoad, Slide, discretise, run_contact
from frictionlab.contact.interface import contact_stiffness, open_state, respond
from frictionlab.contact.linear import TangentSolver
from frictionlab.subloading import SubloadingParams


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element-size", type=float, default=0.1 / 140)
    parser.add_argument("--steps", type=int, default=15)
    args = parser.parse_args()
    block = Block(E=3e9, nu=0.35, width=0.1, height=0.025, element_size=args.element_size)
    params = SubloadingParams(
        alpha_n=5e11, alpha_t=5e11, mu_s=0.6, mu_k=0.4, u=2e6, kappa=1e5, xi=0.05
    )
    normal = NormalLoad(pressure=1e6, steps=2)
    program = [Slide(velocity=1e-5, distance=30e-6, steps=args.steps)]
    # warm the law's compiled kernel on a tiny mesh
    run_contact(Block(3e9, 0.35, 0.1, 0.025, 0.05), params, normal, program[:1])

    start = time.perf_counter()
    disc = discretise(block)
    seconds_mesh = time.perf_counter() - start
    fixed = np.zeros(disc.n_dofs, dtype=bool)
    fixed[disc.dof_x[disc.top_nodes]] = True
    free = ~fixed
    start = time.perf_counter()
    TangentSolver(disc, fixed, params)
    seconds_factor = time.perf_counter() - start

    # baseline 1: the linear-elastic solve alone (block on elastic springs, pressure load)
    K = disc.stiffness
    springs = respond(disc, params, open_state(params, disc.n_points), np.zeros(disc.n_dofs), 0.0)
    K_el = (K + contact_stiffness(disc, springs.moduli)).tocsc()[free][:, free]
    start = time.perf_counter()
    spla.splu(K_el).solve(1e6 * disc.unit_pressure[free])
    seconds_elastic = time.perf_counter() - start

    stamps: list[float] = []  # the end of every step (the progress callback)
    start = time.perf_counter()
    history = run_contact(
        block, params, normal, program, discretisation=disc,
        progress=lambda fraction: stamps.append(time.perf_counter()),
    )  # fmt: skip
    seconds_run = time.perf_counter() - start
    assert history.success, history.message
    sliding = history.stage > 0
    iterations = history.iterations[sliding]
    n_steps = int(history.iterations[1:].size)
    # steps 2..n: after the factorisation and the first step
    per_step = (stamps[-1] - stamps[0]) / (n_steps - 1)
    per_iteration = (stamps[-1] - stamps[0]) / max(int(history.iterations[2:].sum()), 1)

    # baseline 2: one sparse LU of the assembled tangent at the last step
    last = respond(disc, params, open_state(params, disc.n_points), np.zeros(disc.n_dofs), 0.0)
    J = (K + contact_stiffness(disc, last.moduli)).tocsc()[free][:, free]
    start = time.perf_counter()
    spla.splu(J)
    seconds_lu = time.perf_counter() - start

    result = {
        "machine": platform.platform(),
        "dofs": disc.n_dofs,
        "contact_points": disc.n_points,
        "cells": list(block.cells),
        "steps": n_steps,
        "sliding_steps": int(iterations.size),
        "iterations_per_sliding_step_mean": float(iterations.mean()),
        "iterations_per_sliding_step_max": int(iterations.max()),
        "seconds_mesh": seconds_mesh,
        "seconds_factorisation": seconds_factor,
        "seconds_run": seconds_run,
        "seconds_per_step": per_step,
        "seconds_per_iteration": per_iteration,
        "seconds_baseline_linear_elastic_solve": seconds_elastic,
        "seconds_baseline_sparse_lu_of_tangent": seconds_lu,
        "ratio_step_over_linear_elastic_solve": per_step / seconds_elastic,
        "ratio_iteration_over_sparse_lu": per_iteration / seconds_lu,
        "peak_friction_ratio": float(history.friction_ratio.max()),
    }
    print(
        f"contact on {disc.n_dofs} dofs ({block.cells[0]} x {block.cells[1]} cells, "
        f"{disc.n_points} contact points): mesh {seconds_mesh:.2f} s, factorisation "
        f"{seconds_factor:.2f} s; {n_steps} steps in {seconds_run:.2f} s, "
        f"{iterations.mean():.1f} Newton iterations per sliding step (max {iterations.max()}), "
        f"{per_step * 1e3:.1f} ms per step, {per_iteration * 1e3:.1f} ms per iteration; "
        f"one linear-elastic solve {seconds_elastic * 1e3:.1f} ms (step / solve = "
        f"{result['ratio_step_over_linear_elastic_solve']:.2f}); one sparse LU of the tangent "
        f"{seconds_lu * 1e3:.1f} ms (iteration / LU = "
        f"{result['ratio_iteration_over_sparse_lu']:.2f})"
    )
    out = Path(__file__).parent / "results" / "contact.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
