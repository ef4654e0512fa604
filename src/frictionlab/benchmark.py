"""Speed figures of the law and the lattice, measured in one process (``frictionlab bench``).

Every timing is taken after a warm-up call, as the median of ``repeats`` (>= 5) runs,
with its baseline measured in the same process just before it (the machine may be
shared: compare ratios, not absolute times between runs). Only the first-call cost needs
fresh processes (a child process with an empty, then a filled, compile cache).

Figures (per contact point per increment, N points, all sliding unless stated):

* ``coulomb_penalty``: a lean Coulomb penalty radial return (traction in, traction and
  dlam out), compiled with numba ``parallel=True`` like the law's kernel;
* ``coulomb_like_for_like``: :func:`coulomb_like_for_like`, a Coulomb radial return with
  the law's inputs and outputs (the 3x3 tangent included) into fresh arrays, as
  ``update()`` returns them: the baseline of the ``<= 3x`` target, timed with
  one numba thread and with all of them, each time beside ``update()``;
* ``floor``: :func:`transcendental_floor`, only the update's memory traffic and the
  math-library calls the law's per-point definition makes per sliding point (a test
  counts them in the law's own source): a bound for a scalar implementation, not the
  reason the law is slow (the chains of dependent divisions are);
* ``law_*``: :func:`frictionlab.subloading.update` for the full law (cone, softening,
  recovery, rotation, orthotropy), with fresh outputs and the tangent (the default),
  with preallocated outputs and no tangent, and the serial kernel (the parallel gain);
  modified Cam-clay for a closed surface;
* ``lattice_partial``: a 1024^2 self-affine map in partial contact against a flat
  counter-face, 3 directions, 64 time samples: springs per second (target >= 3e8);
* ``first_call``: import + first call of the law and of the lattice in a child process,
  with an empty compile cache (compilation) and with the cache filled;
* ``driver_overhead``: :func:`frictionlab.driver.simulate` of a slide, N = min(points,
  1e4) points: the share of its wall time spent outside the law's compiled kernel
  (target <= 10 % at N = 1e4), recording every step in memory (the default) and
  streaming the rows to a sink that keeps a bounded plot subset (as ``frictionlab
  simulate`` does, without the CSV formatting).
"""

from __future__ import annotations

import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from frictionlab._jit import njit, numba, prange
from frictionlab._version import __version__

__all__ = ["coulomb_return", "run"]

TARGET_LAW_OVER_COULOMB = 10.0
TARGET_LAW_OVER_LIKE_FOR_LIKE = 3.0
TARGET_SPRINGS_PER_SECOND = 3e8


@njit(cache=True, parallel=True)
def coulomb_return(traction, du, alpha_t, alpha_n, mu, out_traction, out_dlam):  # fmt: skip
    """Plain Coulomb penalty radial return of N points (the benchmark's baseline).

    ``f^tr = f + alpha du``; if ``|f_t^tr| > mu f_n^tr`` the tangential traction is
    scaled back to the cone and ``dlam = (|f_t^tr| - mu f_n^tr)/alpha_t`` [m].
    """
    for k in prange(traction.shape[0]):
        i = np.int64(k)
        f1 = traction[i, 0] + alpha_t * du[i, 0]
        f2 = traction[i, 1] + alpha_t * du[i, 1]
        fn = traction[i, 2] + alpha_n * du[i, 2]
        norm = math.hypot(f1, f2)
        limit = mu * fn
        dlam = 0.0
        if norm > limit:
            scale = limit / norm
            dlam = (norm - limit) / alpha_t
            f1 *= scale
            f2 *= scale
        out_traction[i, 0] = f1
        out_traction[i, 1] = f2
        out_traction[i, 2] = fn
        out_dlam[i] = dlam


@njit(cache=True, parallel=True)
def coulomb_like_for_like(traction, F_old, R_old, gap_old, du, dt_arr, P, out_traction, out_F,
                          out_R, out_gap, out_dlam, out_vp, out_diss, out_tangent, out_status,
                          out_iter):  # fmt: skip
    """A Coulomb penalty radial return with the law's inputs and outputs (the fair baseline).

    The arguments of the law's kernel (``P`` one row; its ``F`` column is mu): the same
    arrays read, the same arrays written, the 3x3 consistent tangent of the radial return
    included (``alpha_t (mu f_n/|f_t|) (I - n n^T)`` and ``mu alpha_n n``), R = |f_t|/(mu
    f_n) capped at 1, F unchanged. ``R_old`` and ``dt_arr`` are read and not needed.
    """
    alpha_n = P[0, 0]
    alpha_t = P[0, 1]
    for k in prange(traction.shape[0]):
        i = np.int64(k)
        mu = F_old[i] + 0.0 * (R_old[i] + dt_arr[0])
        f1 = traction[i, 0] + alpha_t * du[i, 0]
        f2 = traction[i, 1] + alpha_t * du[i, 1]
        fn = traction[i, 2] + alpha_n * (du[i, 2] - gap_old[i])
        norm = math.sqrt(f1 * f1 + f2 * f2)
        limit = mu * fn
        n1 = f1 / norm if norm > 0.0 else 0.0
        n2 = f2 / norm if norm > 0.0 else 0.0
        slip = norm > limit and fn > 0.0
        scale = limit / norm if slip else 1.0
        dlam = (norm - limit) / alpha_t if slip else 0.0
        kt = alpha_t * scale
        out_traction[i, 0] = f1 * scale
        out_traction[i, 1] = f2 * scale
        out_traction[i, 2] = fn
        out_F[i] = mu
        out_R[i] = min(norm / limit, 1.0) if limit > 0.0 else 0.0
        out_gap[i] = 0.0
        out_dlam[i] = dlam
        out_vp[i, 0] = dlam * n1
        out_vp[i, 1] = dlam * n2
        out_vp[i, 2] = 0.0
        out_diss[i] = dlam * limit
        out_tangent[i, 0, 0] = kt * (1.0 - n1 * n1) if slip else alpha_t
        out_tangent[i, 0, 1] = -kt * n1 * n2 if slip else 0.0
        out_tangent[i, 1, 0] = -kt * n1 * n2 if slip else 0.0
        out_tangent[i, 1, 1] = kt * (1.0 - n2 * n2) if slip else alpha_t
        out_tangent[i, 0, 2] = mu * alpha_n * n1 if slip else 0.0
        out_tangent[i, 1, 2] = mu * alpha_n * n2 if slip else 0.0
        out_tangent[i, 2, 0] = 0.0
        out_tangent[i, 2, 1] = 0.0
        out_tangent[i, 2, 2] = alpha_n
        out_status[i] = 1 if slip else 0
        out_iter[i] = 0


def coulomb_update(state: Any, du: np.ndarray, dt: float, P: np.ndarray) -> dict[str, np.ndarray]:
    """:func:`coulomb_like_for_like` into fresh arrays, as ``update()`` returns them (the new
    plastic slip included)."""
    from frictionlab.subloading import kernels

    out = kernels.empty_outputs(state.n_points)
    coulomb_like_for_like(state.traction, state.F, state.R, state.gap, du, np.array([dt]), P,
                          out["traction"], out["F"], out["R"], out["gap"], out["dlam"],
                          out["vp"], out["diss"], out["tangent"], out["status"],
                          out["iterations"])  # fmt: skip
    out["plastic_slip"] = state.plastic_slip + out["dlam"]
    return out


@njit(cache=True, parallel=True)
def transcendental_floor(traction, F_old, R_old, gap, du, dlam, u, kappa, xi, Fs, Fk, dt,
                         evaluations, out_traction, out_F, out_R, out_gap, out_dlam, out_vp,
                         out_diss, out_tangent, out_status, out_iter):  # fmt: skip
    """A lower bound of any scalar implementation of the law's update (not the law).

    Per point, exactly the memory traffic of ``update()`` (the same inputs read, the same
    outputs written, tangent included) and the transcendental functions that the built
    return map evaluates for a sliding point with ``evaluations`` residual evaluations
    (two as built: one Newton step from the model start and the converged check): the recovery
    ``exp``, ``cos``/``sin`` of pi R0/2, and per evaluation the ``expm1`` and ``atan2``
    of the closed-form ratio R and the ``expm1`` of the size F; the second evaluation
    depends on the first, as Newton's does. Everything else the law computes is left
    out, so no implementation calling the same scalar math library can be faster.
    """
    half_pi = 0.5 * math.pi
    for k in prange(traction.shape[0]):
        i = np.int64(k)
        F_rec = Fs - (Fs - F_old[i]) * math.exp(-xi * dt / Fs)
        y0 = math.cos(half_pi * R_old[i])
        s0 = math.sin(half_pi * R_old[i])
        step = dlam[i]
        R = R_old[i]
        F = F_rec
        for _ in range(evaluations):
            em = math.expm1(-half_pi * u * step)
            y = y0 * (1.0 + em)
            s2 = s0 * s0 - y0 * y0 * (em * (2.0 + em))
            R = math.atan2(math.sqrt(max(s2, 0.0)), y) / half_pi
            F = Fk + (F_rec - Fk) * (1.0 + math.expm1(-kappa * step / Fk))
            step *= 1.0 + 1e-3 * (R - R_old[i])  # the next evaluation depends on this one
        for a in range(3):
            out_traction[i, a] = traction[i, a] + 1e-3 * du[i, a] * F
            out_vp[i, a] = du[i, a] * R
            for b in range(3):
                out_tangent[i, a, b] = F * (a == b)
        out_F[i] = F
        out_R[i] = R
        out_gap[i] = gap[i]
        out_dlam[i] = step
        out_diss[i] = step * F
        out_status[i] = 1
        out_iter[i] = evaluations


def _median(func: Callable[[], object], repeats: int) -> dict[str, float]:
    """Warm-up call, then ``repeats`` timed calls: median and minimum wall time [s].

    Also the median process CPU time (all threads summed): on a shared machine a serial
    run's CPU time is what it costs, whatever the wait for a core.
    """
    func()
    times = []
    cpu = []
    for _ in range(repeats):
        start = time.perf_counter()
        start_cpu = time.process_time()
        func()
        cpu.append(time.process_time() - start_cpu)
        times.append(time.perf_counter() - start)
    return {
        "median_s": statistics.median(times),
        "min_s": min(times),
        "cpu_median_s": statistics.median(cpu),
        "runs": repeats,
    }


def _sliding(params: Any, n: int, fn: float) -> tuple[Any, np.ndarray]:
    """A state of n points in plastic sliding and the increment that keeps them sliding."""
    from frictionlab.subloading import initial_state, update

    rng = np.random.default_rng(0)
    state = initial_state(params, normal_traction=np.full(n, fn))
    du = np.zeros((n, 3))
    du[:, 0] = 1e-3 * rng.uniform(0.5, 1.5, n)
    du[:, 1] = 3e-4 * rng.uniform(-1.0, 1.0, n)
    for _ in range(20):
        state = update(params, state, du, 0.01, tangent=False).state
    return state, du


def per_us(timing: dict[str, float], points: int) -> float:
    """Median wall time per point [us]."""
    return timing["median_s"] / points * 1e6


def cpu_us(timing: dict[str, float], points: int) -> float:
    """Median process CPU time per point [us] (all threads summed)."""
    return timing["cpu_median_s"] / points * 1e6


def _law(points: int, repeats: int, log: Callable[[str], None]) -> dict:
    from frictionlab.subloading import SubloadingParams, kernels, update

    full = SubloadingParams(
        surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
        rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
    )  # fmt: skip
    state, du = _sliding(full, points, 1.0)
    check = update(full, state, du, 0.01)
    sliding = float(np.mean(check.status == kernels.SLIP))
    iterations = float(np.mean(check.iterations[check.status == kernels.SLIP]))

    out_t = np.empty((points, 3))
    out_l = np.empty(points)
    traction = np.ascontiguousarray(state.traction)
    coulomb = _median(lambda: coulomb_return(traction, du, 1000.0, 1000.0, 0.3, out_t, out_l),
                      repeats)  # fmt: skip
    log(f"coulomb penalty return       {coulomb['median_s'] / points * 1e6:8.4f} us/point")
    floor_out = kernels.empty_outputs(points)
    row = full._kernel_table[0]
    floor_args = (traction, state.F, state.R, state.gap, du, check.plastic_multiplier,
                  row[kernels.P_U], row[kernels.P_KAPPA], row[kernels.P_XI], row[kernels.P_FS],
                  row[kernels.P_FK], 0.01, 2, floor_out["traction"],
                  floor_out["F"], floor_out["R"], floor_out["gap"], floor_out["dlam"],
                  floor_out["vp"], floor_out["diss"], floor_out["tangent"],
                  floor_out["status"], floor_out["iterations"])  # fmt: skip
    floor = _median(lambda: transcendental_floor(*floor_args), repeats)
    log(f"floor: I/O + libm calls only {floor['median_s'] / points * 1e6:8.4f} us/point")
    default = _median(lambda: update(full, state, du, 0.01), repeats)
    log(f"full law, update()           {default['median_s'] / points * 1e6:8.4f} us/point")
    buffers = kernels.empty_outputs(points, tangent=False)
    lean = _median(lambda: update(full, state, du, 0.01, tangent=False, out=buffers), repeats)
    log(f"full law, no tangent, out=   {lean['median_s'] / points * 1e6:8.4f} us/point")

    table = full._kernel_table
    dt = np.array([0.01])
    outs = kernels.empty_outputs(points)
    args = (traction, state.F, state.R, state.gap, du, dt, table, True, 0, 1.0, 0, 0, 0,
            False, True, outs["traction"], outs["F"], outs["R"], outs["gap"], outs["dlam"],
            outs["vp"], outs["diss"], outs["tangent"], outs["status"],
            outs["iterations"])  # fmt: skip
    serial = _median(lambda: kernels.step_points(*args), repeats)
    parallel = _median(lambda: kernels.step_points_parallel(*args), repeats)
    log(f"kernel serial / parallel     {serial['median_s'] / points * 1e6:8.4f} / "
        f"{parallel['median_s'] / points * 1e6:.4f} us/point (serial CPU time "
        f"{serial['cpu_median_s'] / points * 1e6:.4f} us/point)")  # fmt: skip

    # like for like, one thread each, then numba's threads (2 on the reference machine)
    threads = numba.get_num_threads()
    table = full._kernel_table
    paired = {}
    for count in sorted({1, threads}):
        numba.set_num_threads(count)
        try:
            fair = _median(lambda: coulomb_update(state, du, 0.01, table), repeats)
            law_t = _median(lambda: update(full, state, du, 0.01), repeats)
        finally:
            numba.set_num_threads(threads)
        paired[count] = (fair, law_t)
        log(f"{count} thread(s): Coulomb like for like {per_us(fair, points):8.4f}, law update() "
            f"{per_us(law_t, points):8.4f} us/point (CPU {cpu_us(fair, points):.4f} / "
            f"{cpu_us(law_t, points):.4f}): "
            f"{per_us(law_t, points) / per_us(fair, points):.1f}x")  # fmt: skip

    mcc = SubloadingParams(surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5, u=100.0,
                           kappa=1.0, xi=1e-3)  # fmt: skip
    mcc_state, mcc_du = _sliding(mcc, points, 0.2)
    closed = _median(lambda: update(mcc, mcc_state, mcc_du, 0.01), repeats)
    log(f"modified Cam-clay, update()  {closed['median_s'] / points * 1e6:8.4f} us/point")

    def per_point(t: dict[str, float]) -> float:
        return t["median_s"] / points * 1e6

    log(
        f"law / Coulomb = {per_point(default) / per_point(coulomb):.1f} (target <= "
        f"{TARGET_LAW_OVER_COULOMB:g}; the floor alone: "
        f"{per_point(floor) / per_point(coulomb):.1f})"
    )
    return {
        "points": points,
        "fraction_sliding": sliding,
        "mean_newton_iterations": iterations,
        "coulomb_penalty_us_per_point": per_point(coulomb),
        "law_update_us_per_point": per_point(default),
        "law_lean_us_per_point": per_point(lean),
        "law_kernel_serial_us_per_point": per_point(serial),
        "law_kernel_parallel_us_per_point": per_point(parallel),
        "law_kernel_serial_cpu_us_per_point": serial["cpu_median_s"] / points * 1e6,
        "modified_cam_clay_update_us_per_point": per_point(closed),
        "law_over_coulomb": per_point(default) / per_point(coulomb),
        "floor_us_per_point": per_point(floor),
        "floor_over_coulomb": per_point(floor) / per_point(coulomb),
        "law_lean_over_coulomb": per_point(lean) / per_point(coulomb),
        "parallel_gain": per_point(serial) / per_point(parallel),
        "coulomb_like_for_like_us_per_point": per_us(paired[1][0], points),
        "law_update_one_thread_us_per_point": per_us(paired[1][1], points),
        "law_over_coulomb_like_for_like": per_us(paired[1][1], points)
        / per_us(paired[1][0], points),
        "law_over_coulomb_like_for_like_cpu": cpu_us(paired[1][1], points)
        / cpu_us(paired[1][0], points),
        "threads": threads,
        "coulomb_like_for_like_threads_us_per_point": per_us(paired[threads][0], points),
        "law_update_threads_us_per_point": per_us(paired[threads][1], points),
        "law_over_coulomb_like_for_like_threads": per_us(paired[threads][1], points)
        / per_us(paired[threads][0], points),
        "target_law_over_coulomb_like_for_like": TARGET_LAW_OVER_LIKE_FOR_LIKE,
        # one thread, wall (the ratio above); the CPU ratio beside it for a shared machine
        "law_over_coulomb_like_for_like_target_met": bool(
            per_us(paired[1][1], points) / per_us(paired[1][0], points)
            <= TARGET_LAW_OVER_LIKE_FOR_LIKE
        ),
        "target_law_over_coulomb": TARGET_LAW_OVER_COULOMB,
        "timings": {
            "coulomb": coulomb,
            "floor": floor,
            "update": default,
            "lean": lean,
            "serial": serial,
            "parallel": parallel,
            "modified_cam_clay": closed,
            "coulomb_like_for_like": paired[1][0],
            "update_one_thread": paired[1][1],
        },
    }


def _lattice(size: int, repeats: int, log: Callable[[str], None]) -> dict:
    """Springs per second of a partial-contact polar on numba's threads and on one thread.

    Springs are counted as ``2 x spring_evaluations`` (both families at every station and
    time sample). The one-thread run gives the parallel gain and efficiency (gain over
    the thread count); the process CPU time shows what the run cost on a shared machine.
    """
    from frictionlab.roughness import generators
    from frictionlab.roughness.lattice import LatticeSettings, friction_polar

    surface = generators.self_affine(
        0.8, (1e-3, 1e-3), (size, size), rng=np.random.default_rng(7), rms_slope=0.2
    )
    settings = LatticeSettings(load=0.5 * float(np.std(surface.heights)), time_samples=64)
    betas = [0.0, 45.0, 90.0]
    result: dict[str, Any] = {}

    def polar() -> None:
        result["polar"] = friction_polar(surface, generators.flat(), 0.3, betas, settings=settings)

    threads = numba.get_num_threads()
    timing = _median(polar, repeats)
    numba.set_num_threads(1)
    try:
        single = _median(polar, repeats)
    finally:
        numba.set_num_threads(threads)
    springs = 2.0 * result["polar"].spring_evaluations
    rate = springs / timing["median_s"]
    gain = single["median_s"] / timing["median_s"]
    log(f"lattice {size}^2 partial       {rate:8.3g} springs/s ({timing['median_s']:.2f} s, "
        f"CPU {timing['cpu_median_s']:.2f} s, {threads} threads); one thread "
        f"{springs / single['median_s']:.3g} springs/s: gain {gain:.2f}")  # fmt: skip
    return {
        "grid": size,
        "directions": betas,
        "time_samples": result["polar"].time_samples.tolist(),
        "contact_fraction_mean": float(np.mean(result["polar"].contact_fraction_mean)),
        "springs": springs,
        "springs_per_second": rate,
        "springs_per_cpu_second": springs / timing["cpu_median_s"],
        "threads": threads,
        "springs_per_second_one_thread": springs / single["median_s"],
        "parallel_gain": gain,
        "parallel_efficiency": gain / threads,
        "target_springs_per_second": TARGET_SPRINGS_PER_SECOND,
        "timing": timing,
        "timing_one_thread": single,
    }


_FIRST_CALL = """
import time
t0 = time.perf_counter()
import numpy as np
from frictionlab.subloading import SubloadingParams, initial_state, update
t1 = time.perf_counter()
p = SubloadingParams(surface="coulomb", mu_s=0.5, mu_k=0.3)
s = initial_state(p, normal_traction=np.ones(4))
update(p, s, np.tile([1e-3, 0.0, 0.0], (4, 1)), 0.01)
update(p, initial_state(p, normal_traction=np.ones(20000)), np.tile([1e-3, 0, 0], (20000, 1)), 0.01)
t2 = time.perf_counter()
from frictionlab.roughness import generators
from frictionlab.roughness.lattice import LatticeSettings, friction_polar
s = generators.self_affine(0.8, (1e-3, 1e-3), (32, 32), rng=np.random.default_rng(1), rms_slope=0.2)
t3 = time.perf_counter()
friction_polar(s, generators.flat(), 0.3, [0.0], settings=LatticeSettings(load=1e-9))
t4 = time.perf_counter()
print(t1 - t0, t2 - t1, t4 - t3)
"""


def _first_call(log: Callable[[str], None]) -> dict:
    with tempfile.TemporaryDirectory() as folder:
        env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
        env["FRICTIONLAB_CACHE_DIR"] = folder
        rows = {}
        for label in ("empty_cache", "filled_cache"):
            done = subprocess.run([sys.executable, "-c", _FIRST_CALL], env=env, check=True,
                                  capture_output=True, text=True)  # fmt: skip
            imp, law, lattice = (float(x) for x in done.stdout.split()[-3:])
            rows[label] = {"import_s": imp, "law_first_call_s": law,
                           "lattice_first_call_s": lattice}  # fmt: skip
            log(f"first call ({label:12s})    law {law:6.2f} s, lattice {lattice:6.2f} s "
                f"(import {imp:.2f} s)")  # fmt: skip
    return rows


TARGET_DRIVER_OVERHEAD = 0.10


def _driver_overhead(points: int, steps: int, repeats: int, log: Callable[[str], None]) -> dict:
    """Share of a Python driver run's wall time outside the kernel (kernel calls timed in
    place). ``compiled=False``: the compiled step loop and peak refinement call the kernel
    out of the timer's reach (timed, they would count as outside)."""
    from frictionlab.driver import DriverSettings, Recording, Slide, simulate
    from frictionlab.subloading import SubloadingParams, kernels

    params = SubloadingParams(surface="coulomb", alpha_n=1e3, alpha_t=1e3, mu_s=0.5, mu_k=0.3,
                              u=100.0, kappa=1.0, xi=1e-3)  # fmt: skip
    program = (Slide(velocity=0.1, distance=0.05, steps=steps),)
    inside = [0.0]
    originals = (kernels.step_points, kernels.step_points_parallel)

    def timed(kernel: Callable[..., Any]) -> Callable[..., Any]:
        def call(*args: Any) -> Any:
            start = time.perf_counter()
            kernel(*args)
            inside[0] += time.perf_counter() - start

        return call

    shown = range(min(points, 40))
    modes = {
        "in_memory": lambda: None,
        "streamed": lambda: Recording(sink=lambda chunk: None, keep_rows=4000, keep_points=shown),
    }
    runs: dict[str, list[tuple[float, float]]] = {m: [] for m in modes}
    python = DriverSettings(compiled=False)
    kernels.step_points, kernels.step_points_parallel = map(timed, originals)  # type: ignore[assignment]
    try:
        simulate(params, program[:1], n_points=points, settings=python)  # warm-up
        for _ in range(repeats):  # alternate the modes (a shared machine drifts)
            for mode, recording in modes.items():
                inside[0] = 0.0
                start = time.perf_counter()
                simulate(params, program, n_points=points, recording=recording(), settings=python)
                runs[mode].append((time.perf_counter() - start, inside[0]))
    finally:
        kernels.step_points, kernels.step_points_parallel = originals
    out: dict[str, Any] = {"points": points, "steps": steps, "runs": repeats,
                           "target_outside_fraction": TARGET_DRIVER_OVERHEAD}  # fmt: skip
    for mode, rows in runs.items():
        total = statistics.median(t for t, _ in rows)
        outside = statistics.median(1.0 - k / t for t, k in rows)
        out[mode] = {"median_s_per_step": total / steps, "outside_kernel_fraction": outside}
        log(f"driver ({mode:9s}) N = {points}: {1e3 * total / steps:8.3f} ms/step, "
            f"{100 * outside:5.1f} % outside the kernel")  # fmt: skip
    return out


def run(
    points: int = 1_000_000,
    repeats: int = 5,
    lattice_size: int = 1024,
    first_call: bool = True,
    log: Callable[[str], None] = print,
) -> dict[str, Any]:
    """Measure every figure; returns the JSON-ready dictionary (see the module docstring)."""
    if repeats < 5:
        raise ValueError("repeats must be >= 5 (median of at least 5 runs)")
    machine = {
        "cpu_count": os.cpu_count(),
        "numba_threads": numba.get_num_threads(),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "numba": numba.__version__,
        "platform": platform.platform(),
    }
    log(f"frictionlab {__version__}: {machine['cpu_count']} cores, "
        f"{machine['numba_threads']} numba threads")  # fmt: skip
    law = _law(points, repeats, log)
    log(f"numba threading layer: {numba.threading_layer()}")
    machine["numba_threading_layer"] = numba.threading_layer()
    lattice = _lattice(lattice_size, repeats, log)
    payload = {
        "benchmark": "speed and scale",
        "frictionlab": __version__,
        "method": f"one process, warm-up then median of {repeats} runs; baselines measured "
        "in the same process",
        "machine": machine,
        "law": law,
        "lattice_partial": lattice,
    }
    payload["driver_overhead"] = _driver_overhead(min(points, 10_000), 50, repeats, log)
    if first_call:
        payload["first_call"] = _first_call(log)
    return payload


def write(payload: dict[str, Any], path: str) -> None:
    """Write the payload as JSON (atomically)."""
    from frictionlab.io.atomic import write_text_atomic

    write_text_atomic(path, json.dumps(payload, indent=2) + "\n")
