"""The benchmark's floor evaluates exactly the math-library calls the law makes per point.

``transcendental_floor`` bounds any scalar implementation of the update from below by
doing only the law's memory traffic and its transcendental calls. The bound is honest only
while those calls are the ones the law really makes: this test counts them in the
interpreted kernel (the law's own source) on the benchmark's sliding state and in the
floor, through a counting stand-in for ``math``.
"""

from __future__ import annotations

import math
import types
from collections import Counter

import numpy as np
import pytest

from frictionlab import benchmark
from frictionlab.subloading import SubloadingParams, interpreted, kernels, update

COUNTED = ("exp", "expm1", "log", "log1p", "atan2", "atan", "acos", "cos", "sin", "pow", "tan")


def _counting_math(counter: Counter) -> types.SimpleNamespace:
    names = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}

    def counted(name: str):
        func = names[name]

        def call(*args: float) -> float:
            counter[name] += 1
            return func(*args)

        return call

    for name in COUNTED:
        names[name] = counted(name)
    return types.SimpleNamespace(**names)


def _bench_state(n: int):
    full = SubloadingParams(
        surface="coulomb", mu_s=0.5, mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3,
        rotation=(0.05, 0.02), orthotropy=(1.0, 0.6), orthotropy_angle=0.3,
    )  # fmt: skip
    state, du = benchmark._sliding(full, n, 1.0)
    return full, state, du


def test_floor_makes_the_laws_math_calls(monkeypatch: pytest.MonkeyPatch) -> None:
    n = 40
    full, state, du = _bench_state(n)
    outs = kernels.empty_outputs(n)
    traction = np.ascontiguousarray(state.traction)
    args = (traction, state.F, state.R, state.gap, du, np.array([0.01]), full._kernel_table,
            True, 0, 1.0, 0, 0, 0, False, True, outs["traction"], outs["F"], outs["R"],
            outs["gap"], outs["dlam"], outs["vp"], outs["diss"], outs["tangent"],
            outs["status"], outs["iterations"])  # fmt: skip
    law_calls: Counter = Counter()
    namespace = interpreted.load()
    monkeypatch.setitem(namespace, "math", _counting_math(law_calls))
    namespace["step_points_by_point"](*args)  # the per-point definition
    assert np.all(outs["status"] == kernels.SLIP)
    # two residual evaluations per point, the design the floor assumes
    assert np.all(outs["iterations"] == 2)

    floor_calls: Counter = Counter()
    monkeypatch.setattr(benchmark, "math", _counting_math(floor_calls))
    check = update(full, state, du, 0.01)
    row = full._kernel_table[0]
    fo = kernels.empty_outputs(n)
    benchmark.transcendental_floor.py_func(
        traction, state.F, state.R, state.gap, du, check.plastic_multiplier,
        row[kernels.P_U], row[kernels.P_KAPPA], row[kernels.P_XI], row[kernels.P_FS],
        row[kernels.P_FK], 0.01, 2, fo["traction"], fo["F"], fo["R"], fo["gap"], fo["dlam"],
        fo["vp"], fo["diss"], fo["tangent"], fo["status"], fo["iterations"],
    )  # fmt: skip
    law_calls.subtract({"cos": 1, "sin": 1})  # the orthotropy angle's, once per call
    law = {name: count / n for name, count in law_calls.items()}
    floor = {name: count / n for name, count in floor_calls.items()}
    assert law == floor
    # and what they are, written out: recovery exp, cos and sin of pi R0/2, and per
    # residual evaluation the expm1 and atan2 of R and the expm1 of F
    assert floor == {"exp": 1.0, "cos": 1.0, "sin": 1.0, "expm1": 4.0, "atan2": 2.0}
