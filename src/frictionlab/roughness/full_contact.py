"""Full contact as a direct area average of the force multiplier.

In the full-contact limit every spring carries the same force at every instant, so the
time average of the lattice reduces to the plain area average of the
multipliers ``H(mu0, grad f, beta)`` (frame-free Eqs 1-4) over the stations of both
surfaces, one half from each spring family:

    mu_x = (sum_P H_x(grad f1(P)) + sum_P H_x(grad f2(P))) / (2 N)

and likewise mu_y. A relative shift of the upper surface by whole station spacings
only permutes the stations of surface 2, so this is *exactly* the lattice's full-contact
result whenever its time samples are whole-station shifts (sampled surfaces with snapped
time samples, or analytic surfaces whose station count is a multiple of the samples);
otherwise the two are two quadratures of the same area average. No time sampling, no
load solve: one pass over the points computes every direction.

Contacts violating Eq 1's bound (denominator ``n_z - mu0 t_z <= 0``) are counted per
direction; with ``drop=True`` they are left out of both sums (they carry neither load
nor friction), which is the ``on_invalid="drop"`` option of
:class:`~frictionlab.roughness.lattice.LatticeSettings`.

Pure physics, private kernels (numba, parallel over points) with a NumPy twin.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from frictionlab._arrays import FloatArray
from frictionlab._jit import numba
from frictionlab.roughness._kernels import _FAST, multipliers_np

__all__ = ["FullContactSums", "full_contact_sums"]


@dataclass(frozen=True)
class FullContactSums:
    """Area sums per direction over the 2 N contacts (both families).

    ``sum_x``, ``sum_y``: sums of H_x, H_y over the kept contacts; ``kept``: their count
    (2 N without dropping, or when every contact is valid); ``invalid``: contacts
    violating Eq 1; where a direction has invalid contacts, ``worst_station`` (flat
    station index) and ``worst_family`` (1: surface 1, upper-fixed springs; 2: surface 2,
    lower-fixed springs) locate the least Eq 1 denominator (-1 and 0 elsewhere).
    """

    sum_x: FloatArray
    sum_y: FloatArray
    kept: NDArray[np.int64]
    invalid: NDArray[np.int64]
    worst_station: NDArray[np.int64]
    worst_family: NDArray[np.int64]
    n_stations: int

    @property
    def mu_x(self) -> FloatArray:
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.asarray(self.sum_x / self.kept, dtype=np.float64)

    @property
    def mu_y(self) -> FloatArray:
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.asarray(self.sum_y / self.kept, dtype=np.float64)

    @property
    def invalid_fraction(self) -> FloatArray:
        """Fraction of the 2 N contacts violating Eq 1, per direction."""
        return np.asarray(self.invalid / (2.0 * self.n_stations), dtype=np.float64)


#: Points per block: the gradients of one block stay in cache while every direction
#: sweeps it; blocks run in parallel.
BLOCK = 4096


@numba.njit(cache=True, fastmath=_FAST, error_model="numpy", inline="always")
def _block_sums(
    m: float, gx: np.ndarray, gy: np.ndarray, lo: int, hi: int, cb: float, sb: float
) -> tuple[float, float, float]:
    """Sums of H over the valid contacts lo .. hi-1 and the count of invalid ones.

    The multiplier of ``_kernels._h_one`` written branch-free (an invalid contact gets
    the weight 0) so that the compiler vectorises the loop. Inlined into
    :func:`_sums_nb` (same fastmath licences): a separately compiled reassociating callee
    would be optimised differently standalone and inside its caller, and numba's JIT
    runs whichever copy it loaded first (the standalone one after a cold compile, the
    caller's own after a cache hit), so the sums would change in the last bits from run
    to run.
    """
    sx = 0.0
    sy = 0.0
    bad = 0.0
    mcb = m * cb
    msb = m * sb
    for p in range(lo, hi):
        x = gx[p]
        y = gy[p]
        inv_n = 1.0 / math.sqrt(1.0 + x * x + y * y)
        a = x * cb + y * sb
        inv_t = 1.0 / math.sqrt(1.0 + a * a)
        den = inv_n - m * a * inv_t
        ok = 1.0 * (den > 0.0)
        big_n = ok / max(den, 1e-300)  # 1 / den where valid, else 0
        sx += big_n * (x * inv_n + mcb * inv_t)
        sy += big_n * (y * inv_n + msb * inv_t)
        bad += 1.0 - ok
    return sx, sy, bad


@numba.njit(cache=True, parallel=True, fastmath=_FAST, error_model="numpy")
def _sums_nb(
    mu0: np.ndarray,
    g1x: np.ndarray,
    g1y: np.ndarray,
    g2x: np.ndarray,
    g2y: np.ndarray,
    cb: np.ndarray,
    sb: np.ndarray,
    two: bool,
    block: int,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per-block sums (blocks x directions), blocks in parallel (prange).

    ``two=False``: only surface 1 is summed (the caller adds a flat surface 2 itself).
    """
    n = g1x.size
    nd = cb.size
    nb = (n + block - 1) // block
    sx = np.zeros((nb, nd))
    sy = np.zeros((nb, nd))
    bad = np.zeros((nb, nd))
    for c in numba.prange(nb):
        lo = c * block
        hi = min(n, lo + block)
        for d in range(nd):
            a = _block_sums(mu0[d], g1x, g1y, lo, hi, cb[d], sb[d])
            sx[c, d] = a[0]
            sy[c, d] = a[1]
            bad[c, d] = a[2]
            if two:
                b = _block_sums(mu0[d], g2x, g2y, lo, hi, cb[d], sb[d])
                sx[c, d] += b[0]
                sy[c, d] += b[1]
                bad[c, d] += b[2]
    return sx, sy, bad


def _sums_np(
    mu0: np.ndarray,
    g1x: np.ndarray,
    g1y: np.ndarray,
    g2x: np.ndarray,
    g2y: np.ndarray,
    cb: np.ndarray,
    sb: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """NumPy twin of :func:`_sums_nb` (one block), built on the lattice's multipliers."""
    nd = cb.size
    sx = np.zeros((1, nd))
    sy = np.zeros((1, nd))
    bad = np.zeros((1, nd))
    for d in range(nd):
        m = float(mu0[d])
        h1x, h1y, den1 = multipliers_np(m, g1x, g1y, float(cb[d]), float(sb[d]))
        h2x, h2y, den2 = multipliers_np(m, g2x, g2y, float(cb[d]), float(sb[d]))
        sx[0, d] = h1x.sum() + h2x.sum()  # invalid contacts have H = 0 here
        sy[0, d] = h1y.sum() + h2y.sum()
        bad[0, d] = np.count_nonzero(den1 <= 0.0) + np.count_nonzero(den2 <= 0.0)
    return sx, sy, bad


def _locate_worst(mu0: float, g: tuple[np.ndarray, ...], cb: float, sb: float) -> tuple[int, int]:
    """(station, family) of the least Eq 1 denominator of one direction (NumPy)."""
    _, _, den1 = multipliers_np(mu0, g[0], g[1], cb, sb)
    _, _, den2 = multipliers_np(mu0, g[2], g[3], cb, sb)
    code = int(np.argmin(np.stack([den1, den2], axis=1).ravel()))  # 2 p + family - 1
    return code // 2, code % 2 + 1


def full_contact_sums(
    mu0: float | np.ndarray,
    g1: tuple[np.ndarray, np.ndarray],
    g2: tuple[np.ndarray, np.ndarray],
    cos_beta: np.ndarray,
    sin_beta: np.ndarray,
    *,
    drop: bool = False,
    engine: str = "numba",
) -> FullContactSums:
    """Sums of the multipliers over both surfaces for every direction in one pass.

    ``mu0``: the local coefficient, one value or one per direction (hierarchies pass
    each direction's coefficient of the level below, Eq 29). ``g1``, ``g2``:
    gradients (dimensionless) of surfaces 1 and 2 at the N stations (flat arrays of
    equal size); ``cos_beta``, ``sin_beta``: the sliding directions. ``drop``: leave
    contacts violating Eq 1 out of the count (their H is never summed). The worst
    contact is located only for directions with invalid contacts (-1 elsewhere).
    """
    g1x, g1y, g2x, g2y = (np.ascontiguousarray(a, dtype=np.float64).ravel() for a in (*g1, *g2))
    cb = np.ascontiguousarray(cos_beta, dtype=np.float64).ravel()
    sb = np.ascontiguousarray(sin_beta, dtype=np.float64).ravel()
    n = g1x.size
    m0 = np.ascontiguousarray(np.broadcast_to(np.asarray(mu0, dtype=np.float64), cb.shape))
    if engine == "numba":
        flat1 = not (g1x.any() or g1y.any())
        flat2 = not (g2x.any() or g2y.any())
        if flat1 != flat2:
            # A flat counter-face: H = mu0 (cos b, sin b) at each of its n contacts, which
            # are all valid (Eq 1's denominator is 1); only the rough surface is summed.
            rx, ry = (g2x, g2y) if flat1 else (g1x, g1y)
            sx, sy, bad = _sums_nb(m0, rx, ry, rx, ry, cb, sb, False, BLOCK)
            sx[0] += n * m0 * cb
            sy[0] += n * m0 * sb
        else:
            sx, sy, bad = _sums_nb(m0, g1x, g1y, g2x, g2y, cb, sb, True, BLOCK)
    else:
        sx, sy, bad = _sums_np(m0, g1x, g1y, g2x, g2y, cb, sb)
    invalid = np.rint(bad.sum(axis=0)).astype(np.int64)
    station = np.full(cb.size, -1, dtype=np.int64)
    family = np.zeros(cb.size, dtype=np.int64)
    for d in np.flatnonzero(invalid):
        station[d], family[d] = _locate_worst(
            float(m0[d]), (g1x, g1y, g2x, g2y), float(cb[d]), float(sb[d])
        )
    kept = 2 * n - invalid if drop else np.full(cb.size, 2 * n, dtype=np.int64)
    return FullContactSums(
        sum_x=sx.sum(axis=0),
        sum_y=sy.sum(axis=0),
        kept=np.asarray(kept, dtype=np.int64),
        invalid=np.asarray(invalid, dtype=np.int64),
        worst_station=station,
        worst_family=family,
        n_stations=n,
    )
