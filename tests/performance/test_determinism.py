"""Compiled reductions give the same bits whatever ran before them and on any thread count.

numba links a copy of every compiled callee into its caller, and the process's JIT
resolves the callee's symbol to the first copy it loaded. A callee compiled with
reassociation (fastmath) is optimised differently standalone and inside its caller, so
the caller's result depended on whether the standalone callee had been loaded first: a
cold compile loads it, a cache hit does not (the demo's roughness and bridge files
differed by round-off between a first and a second run).
"""

from __future__ import annotations

import subprocess
import sys

import numba
import numpy as np
import pytest

from frictionlab.roughness import full_contact

PROBE = """
import sys
import numpy as np
from frictionlab.roughness import _kernels as K, full_contact as fc
rng = np.random.default_rng(7)
n = 3 * fc.BLOCK + 17
g = [rng.normal(0.0, 0.3, n) for _ in range(4)]
beta = np.radians(np.arange(0.0, 360.0, 15.0))
nx, ny = 96, 128  # the lattice kernel: 96 x 128 stations, several chunks
z1, z2 = rng.normal(0.0, 1.0, (2, nx * ny))
h1 = K.multipliers_nb(0.3, g[0][: nx * ny], g[1][: nx * ny], 0.6, 0.8)
h2 = K.multipliers_nb(0.3, g[2][: nx * ny], g[3][: nx * ny], 0.6, 0.8)
if sys.argv[1] == "callee-first":  # the reassociating callees loaded standalone first,
    gap, part = z2 - z1, np.zeros(K.PART_COLUMNS)  # as a cold compile does
    fc._block_sums(0.3, g[0], g[1], 0, 10, 1.0, 0.0)
    K._gap_stats(gap)
    K._force_sum(gap, 0.1, 1.0, 0.5)
    K._difference(gap, z2, z1, 0, 0, 5)
    K._accumulate_row(gap, *h1, *h2, 0, 0, 5, 0.1, 1.0, 0.5, False, np.inf, False)
    K._accumulate_lean(gap, h1[0], h1[1], h2[0], h2[1], 0, 0, 5, 0.1, 1.0, 0.5, False, np.inf)
    K._gap_chunk(gap, z1, z2, 0, 1, nx, ny, 3, 5, 0.1, 1.0, 0.5, part)
s = fc.full_contact_sums(0.3, (g[0], g[1]), (g[2], g[3]), np.cos(beta), np.sin(beta))
out = [s.sum_x.tolist(), s.sum_y.tolist()]
for mode in (K.MODE_FULL, K.MODE_LOAD, K.MODE_SEPARATION):
    for check in (False, True):
        work = K.workspace(nx, ny)
        out.append(K.sample_into_nb(z1, *h1, z2, *h2, nx, ny, 3, 5, 1.0, 0.5, mode, 0.1, 0.2,
                                    np.inf, False, check, *work))
print(np.array([v for row in out for v in np.ravel(row)], dtype=np.float64).tobytes().hex())
"""


def _sums(order: str) -> str:
    done = subprocess.run([sys.executable, "-c", PROBE, order], capture_output=True, text=True,
                          check=True)  # fmt: skip
    return done.stdout.strip().splitlines()[-1]


@pytest.mark.slow  # two fresh interpreters (~1.5 s CPU each)
def test_roughness_sums_do_not_depend_on_the_kernels_loaded_before() -> None:
    assert _sums("callee-first") == _sums("plain")


def test_full_contact_sums_equal_on_one_and_two_threads() -> None:
    rng = np.random.default_rng(11)
    n = 5 * full_contact.BLOCK + 3
    g = [rng.normal(0.0, 0.3, n) for _ in range(4)]
    beta = np.radians(np.arange(0.0, 360.0, 30.0))
    before = numba.get_num_threads()
    found = []
    try:
        for threads in (1, min(2, numba.config.NUMBA_NUM_THREADS)):
            numba.set_num_threads(threads)
            s = full_contact.full_contact_sums(
                0.3, (g[0], g[1]), (g[2], g[3]), np.cos(beta), np.sin(beta)
            )
            found.append(s.sum_x.tobytes() + s.sum_y.tobytes())
    finally:
        numba.set_num_threads(before)
    assert found[0] == found[1]
