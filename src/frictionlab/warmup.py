"""Compile, once, the kernels that the commands use, so a first run does not wait for numba.

numba compiles a kernel the first time it is called with a new type signature and keeps the
result in frictionlab's compile cache (:mod:`frictionlab._compile_cache`). :func:`warmup` calls
each family of kernels on a problem of a few points: the law's update for every sliding-yield
surface, with and without the tangent, in the serial and the parallel loop; the driver's
recorder and peak refinement; the lattice's partial- and full-contact kernels; and it
byte-compiles frictionlab's modules. With the cache already filled it only loads the
compiled code (about a second). ``make venv`` and ``make demo`` run it.

:func:`warm_for` warms only what one command's runs use (a sweep calls it before its
workers start, so that no worker compiles): the law's parallel loop only for runs of at
least ``PARALLEL_POINTS`` points.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from frictionlab.subloading.return_map import PARALLEL_MIN_POINTS as PARALLEL_POINTS

__all__ = ["steps_for", "warm_for", "warmup"]


def _law(loops: tuple[int, ...] = (2, PARALLEL_POINTS)) -> None:
    """The law's update for every surface; ``loops``: point counts (serial, parallel)."""
    from frictionlab import subloading
    from frictionlab.subloading import SURFACES, SubloadingParams, initial_state

    for surface in SURFACES:
        if surface == "coulomb":
            params = SubloadingParams(surface=surface, alpha_n=1e12, alpha_t=1e12, mu_s=0.5,
                                      mu_k=0.3, u=1e5, kappa=1e3, xi=1e-3)  # fmt: skip
        else:
            params = SubloadingParams(surface=surface, alpha_n=1e12, alpha_t=1e12, F_s=2e6,
                                      F_k=1.5e6, M=0.5, u=1e5, kappa=1e3, xi=1e-3)  # fmt: skip
        for n in loops:  # the serial and the parallel loop
            state = initial_state(params, normal_traction=np.full(n, 1e6))
            du = np.tile([1e-7, 0.0, 0.0], (n, 1))
            for tangent in (True, False):
                subloading.update(params, state, slip_increment=du, time_increment=1e-3,
                                  tangent=tangent)  # fmt: skip


def _driver() -> None:
    from frictionlab.driver import (
        DriverSettings,
        Hold,
        InitialConditions,
        Recording,
        Slide,
        simulate,
    )
    from frictionlab.subloading import SubloadingParams

    params = SubloadingParams(surface="coulomb", alpha_n=1e12, alpha_t=1e12, mu_s=0.5,
                              mu_k=0.3, u=1e5, kappa=1e3, xi=1e-3)  # fmt: skip
    program = (Slide(velocity=1e-4, distance=1e-6, steps=4), Hold(duration=1.0, steps=2))
    rows: list[dict[str, np.ndarray]] = []
    for n in (1, 3):  # every row of every point, then every 2nd row of some points
        for recording in (Recording(every=1, sink=rows.append),
                          Recording(every=2, points=[0], sink=rows.append)):  # fmt: skip
            simulate(params, program, InitialConditions(normal_traction=1e6), n_points=n,
                     recording=recording)  # fmt: skip
        # a peak of the ratio between steps: the refinement's compiled step doubling
        simulate(params, (Slide(velocity=1e-4, distance=2e-4, steps=8),),
                 InitialConditions(normal_traction=1e6), n_points=n)  # fmt: skip
        # the steps the compiled loop hands back (a failed point, substepped) run in Python
        simulate(params, program, InitialConditions(normal_traction=1e6), n_points=n,
                 recording=Recording(every=1, sink=rows.append),
                 settings=DriverSettings(compiled=False))  # fmt: skip


def _lattice() -> None:
    from frictionlab.roughness import LatticeSettings, friction_polar, generators

    lower = generators.sinusoid(0.05, (1.0, 1.0))
    upper = generators.flat()
    for load in ("full", 0.02):
        settings = LatticeSettings(load=load, stations=(16, 16), time_samples=4)
        friction_polar(lower, upper, 0.3, [0.0, 45.0], settings=settings)


def _bytecode(package: Path | None = None) -> None:
    """Byte-compile frictionlab's modules (``package``: another directory), as pip does for
    an installed wheel, so that a first command does not compile the modules this warm-up
    does not import (the workflows, the schema, the figures: ~0.2 CPU s). Written whatever
    ``PYTHONDONTWRITEBYTECODE`` says, like pip's; an install that cannot be written to is
    left as it is."""
    import compileall
    import contextlib

    import frictionlab

    with contextlib.suppress(OSError):
        compileall.compile_dir(package or Path(frictionlab.__file__).parent, quiet=2)


STEPS: tuple[tuple[str, Callable[[], None]], ...] = (
    ("law update (every surface; serial and parallel)", _law),
    ("driver and recorder", _driver),
    ("lattice (partial and full contact)", _lattice),
    ("bytecode of frictionlab's modules", _bytecode),
)


def warmup(
    report: Callable[[str], None] | None = None,
    steps: tuple[tuple[str, Callable[[], None]], ...] | None = None,
) -> list[tuple[str, float]]:
    """Compile (or load from the cache) every kernel family (or those of ``steps``);
    return (step, seconds) pairs."""
    times = []
    for label, step in STEPS if steps is None else steps:
        t0 = time.perf_counter()
        step()
        times.append((label, time.perf_counter() - t0))
        if report is not None:
            report(f"{label}: {times[-1][1]:.1f} s")
    return times


def steps_for(
    command: str, n_points: Sequence[int] = ()
) -> tuple[tuple[str, Callable[[], None]], ...]:
    """The warm-up steps of the kernels that runs of ``command`` use (``simulate``: the law
    and the driver, the law's parallel loop only when some run has at least
    ``PARALLEL_POINTS`` of ``n_points``; ``roughness``: the lattice; other commands: all)."""
    if command == "simulate":
        loops = (2, PARALLEL_POINTS) if any(n >= PARALLEL_POINTS for n in n_points) else (2,)
        label = "law update (every surface; " + (
            "serial and parallel)" if len(loops) > 1 else "serial)"
        )
        return ((label, lambda: _law(loops)), STEPS[1])
    if command == "roughness":
        return (STEPS[2],)
    return STEPS


def warm_for(command: str, n_points: Sequence[int] = ()) -> list[tuple[str, float]]:
    """Compile (or load) the kernels that runs of ``command`` use (:func:`steps_for`)."""
    return warmup(steps=steps_for(command, n_points))
