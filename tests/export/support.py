"""Helpers of the export tests: record the law's calls in a run, build and run harnesses."""

from __future__ import annotations

import contextlib
import importlib
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.export import abaqus, c_core
from frictionlab.subloading import SubloadingParams, kernels

# the module (the package exports the function of the same name)
simulate_module = importlib.import_module("frictionlab.driver.simulate")

HERE = Path(__file__).resolve().parent
N_IN, N_OUT = 41, 23  # values per call record in and out (harness_uinter.f90)


@contextlib.contextmanager
def recorded_calls() -> Iterator[list[dict[str, Any]]]:
    """Every call of the law's compiled kernel inside the block: inputs and outputs.

    The driver's compiled step loop calls the kernel from compiled code, out of reach of
    the wrapper: it is switched off inside the block (every step then runs in Python).
    """
    calls: list[dict[str, Any]] = []
    originals = kernels.step_points, kernels.step_points_parallel
    loop = simulate_module.compiled_steps

    def wrap(kernel):  # type: ignore[no-untyped-def]
        def recorder(*args):  # type: ignore[no-untyped-def]
            names = ("traction", "F", "R", "gap", "slip", "dt", "P")
            call = {k: np.array(v, copy=True) for k, v in zip(names, args[:7], strict=True)}
            call["tangent_wanted"] = bool(args[14])
            call["options"] = args[8:14]
            kernel(*args)
            outs = ("traction", "F", "R", "gap", "dlam", "vp", "diss", "tangent", "status")
            for k, v in zip(outs, args[15:24], strict=True):
                call["out_" + k] = np.array(v, copy=True)
            calls.append(call)

        return recorder

    kernels.step_points = wrap(originals[0])
    kernels.step_points_parallel = wrap(originals[1])
    simulate_module.compiled_steps = lambda *args: None  # type: ignore[assignment]
    try:
        yield calls
    finally:
        kernels.step_points, kernels.step_points_parallel = originals
        simulate_module.compiled_steps = loop


def records(calls: list[dict[str, Any]], params: SubloadingParams) -> np.ndarray:
    """UINTER call records (harness_uinter.f90 layout), one per point and call."""
    rows = []
    for call in calls:
        n = call["traction"].shape[0]
        rec = np.zeros((n, N_IN))
        rec[:, 0] = 3.0
        P = np.broadcast_to(call["P"], (n, kernels.N_PARAMS))
        rec[:, 1:23] = [abaqus.props_from_row(row, params, 0.0) for row in P]
        rec[:, 23:26] = call["traction"][:, [2, 0, 1]]
        rec[:, 26] = call["F"]
        rec[:, 27] = call["R"]
        rec[:, 28] = call["gap"]
        rec[:, 33] = 1.0  # initialised
        rec[:, 37:40] = call["slip"][:, [2, 0, 1]]
        rec[:, 40] = np.broadcast_to(call["dt"], (n,))
        rows.append(rec)
    return np.concatenate(rows)


def build_uinter_harness(build_dir: Path, fortran: str) -> Path:
    """The Fortran harness linked with the exported source (system compilers)."""
    exe = build_dir / "harness_uinter"
    if exe.exists():
        return exe
    cc = c_core.compiler()
    assert cc is not None
    # the very file `frictionlab export abaqus` writes
    src = build_dir / abaqus.SOURCE_NAME
    src.write_text(abaqus.self_contained_source())
    obj = build_dir / "frictionlab_uinter.o"
    run_checked([cc, *c_core.CFLAGS, "-Wall", "-Werror", "-c", str(src), "-o", str(obj)])
    objects = [str(obj)]
    main = build_dir / "harness_uinter.o"
    run_checked([fortran, "-O2", "-c", str(HERE / "harness_uinter.f90"), "-o", str(main)])
    run_checked([fortran, "-o", str(exe), str(main), *objects, "-lm"])
    return exe


def build_vuinter_harness(build_dir: Path) -> Path:
    """The C harness of VUINTER linked with the exported source."""
    exe = build_dir / "harness_vuinter"
    if exe.exists():
        return exe
    cc = c_core.compiler()
    assert cc is not None
    src = build_dir / abaqus.SOURCE_NAME
    src.write_text(abaqus.self_contained_source())
    run_checked([cc, *c_core.CFLAGS, "-Wall", "-o", str(exe), str(HERE / "harness_vuinter.c"),
          str(src), "-lm"])  # fmt: skip
    return exe


def run_uinter(exe: Path, recs: np.ndarray, work: Path) -> np.ndarray:
    """Run the harness on the records; (n, 23) outputs."""
    inp, out = work / "calls.bin", work / "results.bin"
    np.concatenate([[float(recs.shape[0])], recs.ravel()]).astype("<f8").tofile(inp)
    run_checked([str(exe), str(inp), str(out)])
    return np.fromfile(out, dtype="<f8").reshape(-1, N_OUT)


def run_checked(cmd: list[str]) -> None:
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    assert done.returncode == 0, f"{' '.join(cmd)}:\n{done.stdout}\n{done.stderr}"
