"""Build the C core of the law (``subloading.c``) with the system's C compiler; ctypes binding.

:func:`compiler` finds a C compiler (``$CC``, then ``cc``, ``gcc``, ``clang``),
:func:`build` compiles sources into a shared library (flags :data:`CFLAGS`: C99, no
contraction into fused multiply-adds, so that the numbers are numba's), and
:func:`step_points` runs :c:func:`sl_step_points` on the same inputs as
:func:`frictionlab.subloading.kernels.step_points`. Used by the tests, the benchmark and
``frictionlab export``; the law itself never needs a compiler.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import shutil
import subprocess
import tempfile
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.errors import ParameterError

__all__ = ["CFLAGS", "CoreError", "build", "compiler", "load_core", "source", "step_points"]

#: Flags of every build: C99, position independent, optimised, no fused multiply-add.
CFLAGS = ("-std=c99", "-O2", "-fPIC", "-ffp-contract=off")


class CoreError(RuntimeError):
    """The C core could not be built (no compiler, or the compiler failed)."""


def source(name: str) -> str:
    """Text of one file of the C core shipped with frictionlab (``subloading.c``, ...)."""
    return resources.files("frictionlab.export").joinpath(name).read_text(encoding="utf-8")


def compiler() -> str | None:
    """Path of the C compiler to use, or None: ``$CC``, else cc, gcc or clang on PATH."""
    names = [os.environ["CC"]] if os.environ.get("CC") else ["cc", "gcc", "clang"]
    for name in names:
        found = shutil.which(name)
        if found:
            return found
    return None


def build(sources: dict[str, str], out: Path, extra: tuple[str, ...] = ()) -> Path:
    """Compile ``sources`` (file name -> text, written next to ``out``) into the shared
    library ``out``; raises :class:`CoreError` with the compiler's message on failure."""
    cc = compiler()
    if cc is None:
        raise CoreError("no C compiler found (set CC, or install gcc)")
    out.parent.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, text in sources.items():
        path = out.parent / name
        path.write_text(text, encoding="utf-8")
        if name.endswith(".c"):
            paths.append(str(path))
    tmp = out.with_name(out.name + f".{os.getpid()}.tmp")
    cmd = [cc, *CFLAGS, "-shared", "-o", str(tmp), *paths, *extra, "-lm"]
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise CoreError(f"{' '.join(cmd)} failed:\n{done.stderr.strip()}")
    os.replace(tmp, out)  # atomic: concurrent builders never load a partial library
    return out


_ARGS: list[Any] = []
_LIB: dict[str, ctypes.CDLL] = {}


class Options(ctypes.Structure):
    """``sl_options`` of subloading.h."""

    _fields_ = [
        ("surface", ctypes.c_int),
        ("tear_k", ctypes.c_double),
        ("u_law", ctypes.c_int),
        ("integrator", ctypes.c_int),
        ("recovery", ctypes.c_int),
        ("open_frozen", ctypes.c_int),
        ("want_tangent", ctypes.c_int),
    ]


def load_core(cache: Path | None = None, extra: tuple[str, ...] = ()) -> ctypes.CDLL:
    """The C core as a ctypes library, built once per source version and ``extra`` flags
    into ``cache`` (default: a folder in the system's temporary directory)."""
    text = {name: source(name) for name in ("subloading.h", "subloading.c")}
    flags = " ".join((*CFLAGS, *extra))
    key = hashlib.sha256("".join(text.values()).encode() + flags.encode())
    tag = key.hexdigest()[:16]
    if tag in _LIB:
        return _LIB[tag]
    folder = cache or Path(tempfile.gettempdir()) / f"frictionlab-c-core-{os.getuid()}"
    lib_path = folder / tag / "libsubloading.so"
    if not lib_path.exists():
        build(text, lib_path, extra)
    lib = ctypes.CDLL(str(lib_path))
    dbl = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
    i32 = np.ctypeslib.ndpointer(dtype=np.int32, flags="C_CONTIGUOUS")
    lib.sl_step_points.restype = None
    lib.sl_step_points.argtypes = [
        ctypes.c_long, dbl, dbl, dbl, dbl, dbl, dbl, ctypes.c_long, dbl, ctypes.c_long,
        ctypes.POINTER(Options), dbl, dbl, dbl, dbl, dbl, dbl, dbl, dbl, i32, i32,
    ]  # fmt: skip
    _LIB[tag] = lib
    return lib


def step_points(
    lib: ctypes.CDLL,
    traction: np.ndarray,
    F: np.ndarray,
    R: np.ndarray,
    gap: np.ndarray,
    slip: np.ndarray,
    dt: np.ndarray,
    table: np.ndarray,
    options: dict[str, Any],
) -> dict[str, np.ndarray]:
    """One increment of N points by the C core; inputs as ``kernels.step_points``.

    ``options``: surface, tear_k, u_law, integrator, recovery, open_frozen, want_tangent
    (the integer codes of :mod:`frictionlab.subloading`). Returns new arrays: traction,
    F, R, gap, dlam, vp, diss, tangent, status, iterations.
    """
    n = traction.shape[0]
    if table.shape[0] not in (1, n) or dt.shape[0] not in (1, n):
        raise ParameterError("table", table.shape, f"1 or {n} rows, and dt 1 or {n} entries")
    c = np.ascontiguousarray
    out: dict[str, np.ndarray] = {
        "traction": np.empty((n, 3)),
        "F": np.empty(n),
        "R": np.empty(n),
        "gap": np.empty(n),
        "dlam": np.empty(n),
        "vp": np.empty((n, 3)),
        "diss": np.empty(n),
        "tangent": np.zeros((n, 3, 3)),
        "status": np.empty(n, dtype=np.int32),
        "iterations": np.empty(n, dtype=np.int32),
    }
    opts = Options(**{field[0]: options[field[0]] for field in Options._fields_})
    lib.sl_step_points(
        n, c(traction, dtype=np.float64), c(F, dtype=np.float64), c(R, dtype=np.float64),
        c(gap, dtype=np.float64), c(slip, dtype=np.float64), c(dt, dtype=np.float64),
        dt.shape[0], c(table, dtype=np.float64), table.shape[0], ctypes.byref(opts),
        out["traction"], out["F"], out["R"], out["gap"], out["dlam"], out["vp"], out["diss"],
        out["tangent"], out["status"], out["iterations"],
    )  # fmt: skip
    return out
