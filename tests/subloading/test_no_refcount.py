"""Per-point / per-row numba helpers take no arrays that numba reference-counts per call.

A non-inlined numba function receiving an array increfs it on entry and decrefs it on
each exit (atomic operations on shared cache lines); called once per point or row this
costs a large share of the kernel's time. The check compiles a fresh, uncached copy of
each helper for the signature the kernel uses and reads its own LLVM IR.
"""

import re

import numba
import numpy as np
import pytest

from frictionlab.roughness import _kernels as lattice_kernels
from frictionlab.subloading import kernels as law_kernels


def _fresh(dispatcher, sig):
    """An uncached copy of ``dispatcher`` compiled for ``sig`` (its callees compile too)."""
    dropped = ("cache", "inline", "nopython")
    options = {k: v for k, v in dispatcher.targetoptions.items() if k not in dropped}
    fresh = numba.njit(**options)(dispatcher.py_func)
    fresh.compile(sig)
    return fresh


def _refcount_calls(dispatcher, sig) -> int:
    """Number of NRT_incref / NRT_decref calls in the body of ``dispatcher`` compiled for sig."""
    fresh = _fresh(dispatcher, sig)
    cres = fresh.overloads[fresh.signatures[0]]
    ir = cres.library.get_llvm_str()
    name = re.escape(cres.fndesc.mangled_name)
    match = re.search(r'define [^\n]*@"?' + name + r'"?\(.*?\n}\n', ir, re.S)
    assert match is not None, "function body not found in the LLVM IR"
    body = match.group(0)
    return body.count("@NRT_incref") + body.count("@NRT_decref")


def _signatures(dispatcher, run, callers=()) -> list:
    """Signatures ``dispatcher`` is compiled for by ``run`` (via uncached ``callers``)."""
    if not dispatcher.signatures:
        run()
        for caller in callers:
            for sig in list(caller.signatures):
                _fresh(caller, sig)
    assert dispatcher.signatures, f"{dispatcher.py_func.__name__} was not compiled by the run"
    return list(dispatcher.signatures)


def _law_run() -> None:
    from frictionlab.benchmark import _law

    _law(200, 1, lambda s: None)


def _lattice_run() -> None:
    from frictionlab.benchmark import _lattice

    _lattice(16, 1, lambda s: None)


def test_detector_flags_an_array_helper_with_early_returns():
    @numba.njit(cache=False)
    def helper(a, b, x):  # the old design: arrays in, several returns
        if x > 1.0:
            return a[0]
        t = a[1] + b[0]
        if t > x:
            return t
        for i in range(3):
            if a[i] < 0.0:
                return b[i]
        return x

    sig = (numba.float64[::1], numba.float64[::1], numba.float64)
    assert helper(np.array([1.0, -2.0, 3.0]), np.array([0.5, 7.0, 9.0]), 0.0) == 7.0
    assert _refcount_calls(helper, sig) > 0


def test_detector_passes_a_scalar_helper():
    @numba.njit(cache=False)
    def helper(x):
        if x > 1.0:
            return 1.0
        if x < -1.0:
            return -1.0
        return x

    assert _refcount_calls(helper, (numba.float64,)) == 0


@pytest.mark.slow
def test_law_point_function_has_no_refcounting():
    callers = (law_kernels.step_points, law_kernels._by_point)
    for sig in _signatures(law_kernels._point, _law_run, callers):
        assert _refcount_calls(law_kernels._point, sig) == 0


@pytest.mark.slow
@pytest.mark.parametrize(
    "name", ["_accumulate_row", "_accumulate_lean", "_difference", "_mean_force", "_force_sum"]
)
def test_lattice_row_helpers_have_no_refcounting(name):
    k = lattice_kernels
    callers = (k.sample_into_nb, k._gap_chunk, k._sums_chunk, k._solve_offset)
    dispatcher = getattr(k, name)
    for sig in _signatures(dispatcher, _lattice_run, callers):
        assert _refcount_calls(dispatcher, sig) == 0
