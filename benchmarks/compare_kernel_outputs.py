"""Bit-for-bit comparison of the law kernel with the kernel of another git revision.

The kernel sources of ``--before`` are compiled beside the current ones (as in
``bench_kernel_change.py``); both run the serial and the ``prange`` loop on the same random
inputs: every surface, every combination of the five options (U law, F integrator,
recovery form, open recovery, tangent), per-point parameter rows (random stiffnesses,
sizes, rotations, orthotropy), closed, open and re-closing points, steps from tiny to
far beyond the surface, dt from 0 up. Every output array must be identical bit for bit.

Run: ``python benchmarks/compare_kernel_outputs.py --before REV [--points N]``; exit 1 on
any difference.
"""

from __future__ import annotations

import argparse
import itertools
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))

from bench_kernel_change import _old_kernels

from frictionlab.subloading import kernels
from frictionlab.subloading.surfaces import SURFACE_CODES


def _inputs(rng: np.random.Generator, n: int, cone: bool) -> tuple[np.ndarray, ...]:
    """Random per-point parameters, states and increments (closed, open, re-closing)."""
    P = np.empty((n, kernels.N_PARAMS))
    P[:, kernels.P_ALPHA_N] = 10.0 ** rng.uniform(1, 7, n)
    P[:, kernels.P_ALPHA_T] = 10.0 ** rng.uniform(1, 7, n)
    Fk = rng.uniform(0.1, 1.0, n) * (1.0 if cone else 10.0 ** rng.uniform(0, 4, n))
    P[:, kernels.P_FK] = Fk
    P[:, kernels.P_FS] = Fk * rng.uniform(1.0, 2.5, n)
    P[:, kernels.P_U] = 10.0 ** rng.uniform(0, 4, n)
    P[:, kernels.P_KAPPA] = rng.uniform(0.0, 5.0, n) * np.where(rng.random(n) < 0.2, 0.0, 1.0)
    P[:, kernels.P_XI] = rng.uniform(0.0, 0.5, n) * Fk
    P[:, kernels.P_M] = rng.choice([1.0, 0.5, 2.0], n)
    P[:, kernels.P_N] = rng.choice([1.0, 0.5, 2.0], n)
    beta = rng.uniform(0.0, 0.3, n) * np.where(rng.random(n) < 0.3, 0.0, 1.0)
    angle = rng.uniform(0, 2 * np.pi, n)
    P[:, kernels.P_BETA1] = beta * np.cos(angle)
    P[:, kernels.P_BETA2] = beta * np.sin(angle)
    P[:, kernels.P_A1] = rng.uniform(0.4, 1.6, n)
    P[:, kernels.P_A2] = np.where(rng.random(n) < 0.3, P[:, kernels.P_A1], rng.uniform(0.4, 1.6, n))
    P[:, kernels.P_ANGLE] = rng.uniform(-1.5, 1.5, n)
    F = P[:, kernels.P_FK] + rng.random(n) * (P[:, kernels.P_FS] - P[:, kernels.P_FK])
    fn = (1.0 if cone else Fk) * rng.uniform(0.01, 0.9, n)
    open_ = rng.random(n) < 0.25
    fn[open_] = 0.0
    gap = np.where(open_, 10.0 ** rng.uniform(-9, -2, n), 0.0)
    scale = (fn if cone else 1.0) * F  # tangential traction scale [Pa]
    ft = scale[:, None] * rng.uniform(-1.0, 1.0, (n, 2)) * rng.choice([0.01, 0.3, 1.0], (n, 1))
    ft[open_] = 0.0
    traction = np.column_stack([ft, fn])
    R = np.where(open_, 0.0, rng.random(n))
    slip_scale = F / P[:, kernels.P_ALPHA_T] * 10.0 ** rng.uniform(-4, 2, n)
    du = np.empty((n, 3))
    du[:, :2] = slip_scale[:, None] * rng.uniform(-1.0, 1.0, (n, 2))
    du[rng.random(n) < 0.1, :2] = 0.0
    approach = (Fk / P[:, kernels.P_ALPHA_N]) * rng.uniform(-1.5, 1.5, n)
    du[:, 2] = np.where(open_, gap * rng.uniform(0.0, 2.0, n) + np.abs(approach), approach)
    du[rng.random(n) < 0.2, 2] = 0.0
    dt = np.where(rng.random(n) < 0.3, 0.0, 10.0 ** rng.uniform(-3, 2, n))
    return traction, F, R, gap, du, dt, P


def _run(loop, args: tuple, n: int, tangent: bool) -> dict[str, np.ndarray]:
    outs = kernels.empty_outputs(n, tangent)
    loop(*args, outs["traction"], outs["F"], outs["R"], outs["gap"], outs["dlam"], outs["vp"],
         outs["diss"], outs["tangent"], outs["status"], outs["iterations"])  # fmt: skip
    return outs


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", required=True, help="git revision of the old kernel")
    parser.add_argument("--points", type=int, default=3000, help="points per combination")
    args = parser.parse_args()
    rng = np.random.default_rng(2026)
    n = args.points
    values = 0
    differing: list[str] = []
    with tempfile.TemporaryDirectory() as folder:
        old = _old_kernels(args.before, Path(folder))
        for surface, code in SURFACE_CODES.items():
            inputs = _inputs(rng, n, surface == "coulomb")
            combos = itertools.product((0, 1), (0, 1), (0, 1), (False, True), (False, True))
            for ulaw, integ, rform, frozen, tangent in combos:
                tear_k = float(rng.choice([1.0, 2.5]))
                call = (*inputs, False, code, tear_k, ulaw, integ, rform, frozen, tangent)
                for name in ("step_points", "step_points_parallel"):
                    a = _run(getattr(old, name), call, n, tangent)
                    b = _run(getattr(kernels, name), call, n, tangent)
                    for key in a:
                        if key == "plastic_slip":
                            continue
                        values += a[key].size
                        same = a[key].tobytes() == b[key].tobytes()
                        if not same:
                            differing.append(f"{surface} {ulaw}{integ}{rform}{frozen:d}"
                                             f"{tangent:d} {name} {key}")  # fmt: skip
            print(f"{surface}: compared", flush=True)
    print(f"{values} values compared; {len(differing)} arrays differ")
    for line in differing[:20]:
        print("  ", line)
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main())
