"""The lattice's compiled kernels agree with their own source run by the interpreter.

``frictionlab.roughness.interpreted`` uses the mechanism of the law's interpreted
reference (``frictionlab._interpret``); the guard checks that what it returns is really
plain Python, else both sides of the comparison would be compiled.
"""

from __future__ import annotations

import math
import types

import numpy as np
import pytest

from frictionlab.roughness import _kernels as K
from frictionlab.roughness import full_contact, interpreted
from frictionlab.subloading import interpreted as law_interpreted

NAMES = ("sample_nb", "sample_into_nb", "solve_offset_nb", "solve_offset_detach_nb",
         "multipliers_nb", "_sums_nb", "_block_sums")  # fmt: skip


def test_the_interpreted_kernels_are_plain_python() -> None:
    ns = interpreted.load()
    for name in NAMES:
        assert isinstance(ns[name], types.FunctionType), name
    assert not isinstance(K.sample_nb, types.FunctionType)  # the library's is compiled
    assert isinstance(law_interpreted.load()["_point"], types.FunctionType)


@pytest.mark.parametrize("mode", [K.MODE_FULL, K.MODE_LOAD, K.MODE_SEPARATION])
@pytest.mark.parametrize(("kt", "detach", "drop"), [(0.0, math.inf, False), (0.5, 0.8, True)])
def test_sample_kernel_equals_its_interpreted_source(mode, kt, detach, drop) -> None:
    rng = np.random.default_rng(21)
    nx, ny = 9, 6
    z1, z2, h1x, h1y, h2x, h2y = rng.standard_normal((6, nx * ny))
    den1, den2 = rng.uniform(0.1, 1.0, (2, nx * ny))
    den2[[3, 17]] = -0.1  # invalid contacts on surface 2
    args = (z1, h1x, h1y, den1, z2, h2x, h2y, den2, nx, ny, 4, 5, 1.0, kt, mode, 0.4, 0.3,
            detach, drop)  # fmt: skip
    a = K.sample_nb(*args)
    b = interpreted.load()["sample_nb"](*args)
    np.testing.assert_allclose(a[:6], b[:6], rtol=1e-12, atol=1e-12)
    assert a[6:] == b[6:]


def test_full_contact_sums_equal_their_interpreted_source() -> None:
    rng = np.random.default_rng(5)
    g = rng.standard_normal((4, 300)) * 0.3
    mu0 = np.full(3, 0.4)
    beta = np.radians([0.0, 35.0, 90.0])
    args = (mu0, *g, np.cos(beta), np.sin(beta), True, 64)
    compiled = full_contact._sums_nb(*args)
    reference = interpreted.load()["_sums_nb"](*args)
    for a, b in zip(compiled, reference, strict=True):
        np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-15)
