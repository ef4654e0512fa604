"""The C core of the law (export/subloading.c) against the numba kernel, one process.

Both update the same N points in plastic sliding (the ``frictionlab bench`` state: the
full cone with rotation and orthotropy, and modified Cam-clay), with the consistent
tangent, one thread each (numba's serial ``step_points``; the C core through ctypes with
its arrays allocated per call). Alternating runs, median time per point; the outputs
are compared bit for bit.

Run: ``python benchmarks/bench_c_core.py [--points N] [--repeats K] [--cflags FLAGS]``
(needs a C compiler).
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from frictionlab.benchmark import _sliding
from frictionlab.export import c_core
from frictionlab.subloading import SubloadingParams, kernels
from frictionlab.subloading.return_map import _FORM_CODES, _INTEG_CODES, _U_CODES
from frictionlab.subloading.surfaces import SURFACE_CODES

LAWS = {
    "cone, rotation + orthotropy": SubloadingParams(
        surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
        rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
    ),
    "modified Cam-clay": SubloadingParams(
        surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5, u=100.0, kappa=1.0, xi=1e-3,
    ),
}  # fmt: skip


def compare(
    params: SubloadingParams, points: int, repeats: int, extra: tuple[str, ...] = ()
) -> dict[str, float]:
    state, du = _sliding(params, points, 1.0 if params.is_cone else 0.3)
    dt = np.array([0.01])
    table = params._kernel_table
    codes = (SURFACE_CODES[params.surface], params.tear_k, _U_CODES[params.U_law],
             _INTEG_CODES[params.F_integrator], _FORM_CODES[params.recovery_form],
             params.open_recovery == "frozen")  # fmt: skip
    out = kernels.empty_outputs(points, True)
    traction = np.ascontiguousarray(state.traction)
    args = (traction, state.F, state.R, state.gap, du, dt, table, True, *codes, True,
            out["traction"], out["F"], out["R"], out["gap"], out["dlam"], out["vp"],
            out["diss"], out["tangent"], out["status"], out["iterations"])  # fmt: skip
    lib = c_core.load_core(extra=extra)
    options = dict(zip(("surface", "tear_k", "u_law", "integrator", "recovery", "open_frozen"),
                       codes, strict=True), want_tangent=1)  # fmt: skip

    def run_c() -> dict[str, np.ndarray]:
        return c_core.step_points(lib, traction, state.F, state.R, state.gap, du, dt, table,
                                  options)  # fmt: skip

    kernels.step_points(*args)  # compile or load, warm
    got = run_c()
    same = all(np.array_equal(got[k], out[k]) for k in got)
    t_numba, t_c = [], []
    for _ in range(repeats):
        start = time.perf_counter()
        kernels.step_points(*args)
        t_numba.append(time.perf_counter() - start)
        start = time.perf_counter()
        run_c()
        t_c.append(time.perf_counter() - start)
    numba_us = statistics.median(t_numba) / points * 1e6
    c_us = statistics.median(t_c) / points * 1e6
    sliding = float(np.mean(out["status"] == kernels.SLIP))
    return {"numba_us": numba_us, "c_us": c_us, "ratio": c_us / numba_us,
            "sliding": sliding, "identical": float(same)}  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--cflags", default="", help="extra C flags, e.g. '-march=native'")
    args = parser.parse_args()
    extra = tuple(args.cflags.split())
    flags = " ".join((*c_core.CFLAGS, *extra))
    print(f"{args.points} points, median of {args.repeats} alternating runs, one thread")
    print(f"C compiler {c_core.compiler()}, flags {flags}")
    print(f"{'law':<30} {'numba us/pt':>12} {'C us/pt':>9} {'C/numba':>8} {'slip':>5} same")
    for name, params in LAWS.items():
        r = compare(params, args.points, args.repeats, extra)
        print(f"{name:<30} {r['numba_us']:12.4f} {r['c_us']:9.4f} {r['ratio']:8.3f} "
              f"{r['sliding']:5.2f} {'yes' if r['identical'] else 'NO'}")  # fmt: skip


if __name__ == "__main__":
    main()
