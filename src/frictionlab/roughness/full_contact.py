"""Full contact as a direct area average of the force multiplier (spec section 2.6).

In the full-contact limit every spring carries the same force at every instant, so the
time average of the lattice (spec section 2.4) reduces to the plain area average of the
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

from dataclasses import dataclass

import numba
import numpy as np
from numpy.typing import NDArray

from frictionlab.roughness._kernels import _h_one, multipliers_np

__all__ = ["FullContactSums", "full_contact_sums"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class FullContactSums:
    """Area sums per direction over the 2 N contacts (both families).

    ``sum_x``, ``sum_y``: sums of H_x, H_y over the kept contacts; ``kept``: their count
    (2 N without dropping, or when every contact is valid); ``invalid``: contacts
    violating Eq 1; ``worst_den``: the smallest Eq 1 denominator; ``worst_station``
    (flat station index) and ``worst_family`` (1: surface 1, upper-fixed springs;
    2: surface 2, lower-fixed springs) locate it.
    """

    sum_x: FloatArray
    sum_y: FloatArray
    kept: NDArray[np.int64]
    invalid: NDArray[np.int64]
    worst_den: FloatArray
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


@numba.njit(cache=True, parallel=True)
def _sums_nb(
    mu0: np.ndarray,
    g1x: np.ndarray,
    g1y: np.ndarray,
    g2x: np.ndarray,
    g2y: np.ndarray,
    cb: np.ndarray,
    sb: np.ndarray,
    drop: bool,
    n_chunks: int,
    two: bool,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Per-chunk sums (chunks x directions); chunks run in parallel (prange).

    ``two=False``: only surface 1 is summed (the caller adds a flat surface 2 itself).
    """
    n = g1x.size
    nd = cb.size
    sx = np.zeros((n_chunks, nd))
    sy = np.zeros((n_chunks, nd))
    bad = np.zeros((n_chunks, nd), dtype=np.int64)
    worst = np.full((n_chunks, nd), np.inf)
    where = np.full((n_chunks, nd), -1, dtype=np.int64)
    size = (n + n_chunks - 1) // n_chunks
    for c in numba.prange(n_chunks):
        lo = c * size
        hi = min(n, lo + size)
        for p in range(lo, hi):
            ax = g1x[p]
            ay = g1y[p]
            bx = g2x[p]
            by = g2y[p]
            for d in range(nd):
                hx1, hy1, den1 = _h_one(mu0[d], ax, ay, cb[d], sb[d])
                ok1 = den1 > 0.0
                if ok1 or not drop:
                    sx[c, d] += hx1 if ok1 else 0.0
                    sy[c, d] += hy1 if ok1 else 0.0
                bad[c, d] += not ok1
                if den1 < worst[c, d]:
                    worst[c, d] = den1
                    where[c, d] = 2 * p
                if not two:
                    continue
                hx2, hy2, den2 = _h_one(mu0[d], bx, by, cb[d], sb[d])
                ok2 = den2 > 0.0
                if ok2 or not drop:
                    sx[c, d] += hx2 if ok2 else 0.0
                    sy[c, d] += hy2 if ok2 else 0.0
                bad[c, d] += not ok2
                if den2 < worst[c, d]:
                    worst[c, d] = den2
                    where[c, d] = 2 * p + 1
    return sx, sy, bad, worst, where


def _sums_np(
    mu0: np.ndarray,
    g1x: np.ndarray,
    g1y: np.ndarray,
    g2x: np.ndarray,
    g2y: np.ndarray,
    cb: np.ndarray,
    sb: np.ndarray,
    drop: bool,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """NumPy twin of :func:`_sums_nb` (one chunk), built on the lattice's multipliers."""
    nd = cb.size
    sx = np.zeros((1, nd))
    sy = np.zeros((1, nd))
    bad = np.zeros((1, nd), dtype=np.int64)
    worst = np.zeros((1, nd))
    where = np.zeros((1, nd), dtype=np.int64)
    for d in range(nd):
        m = float(mu0[d])
        h1x, h1y, den1 = multipliers_np(m, g1x, g1y, float(cb[d]), float(sb[d]))
        h2x, h2y, den2 = multipliers_np(m, g2x, g2y, float(cb[d]), float(sb[d]))
        sx[0, d] = h1x.sum() + h2x.sum()  # invalid contacts have H = 0 here
        sy[0, d] = h1y.sum() + h2y.sum()
        bad[0, d] = np.count_nonzero(den1 <= 0.0) + np.count_nonzero(den2 <= 0.0)
        both = np.stack([den1, den2], axis=1).ravel()  # index 2 p + family - 1
        where[0, d] = int(np.argmin(both))
        worst[0, d] = both[where[0, d]]
    return sx, sy, bad, worst, where


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
    each direction's coefficient of the level below, spec Eq 29). ``g1``, ``g2``:
    gradients (dimensionless) of surfaces 1 and 2 at the N stations
    (flat arrays of equal size); ``cos_beta``, ``sin_beta``: the sliding directions.
    ``drop``: leave contacts violating Eq 1 out of the sums and the count.
    """
    g1x, g1y, g2x, g2y = (np.ascontiguousarray(a, dtype=np.float64).ravel() for a in (*g1, *g2))
    cb = np.ascontiguousarray(cos_beta, dtype=np.float64).ravel()
    sb = np.ascontiguousarray(sin_beta, dtype=np.float64).ravel()
    n = g1x.size
    m0 = np.ascontiguousarray(np.broadcast_to(np.asarray(mu0, dtype=np.float64), cb.shape))
    if engine == "numba":
        chunks = max(1, min(n, 8 * numba.get_num_threads()))
        flat1 = not (g1x.any() or g1y.any())
        flat2 = not (g2x.any() or g2y.any())
        if flat1 != flat2:
            # A flat counter-face: H = mu0 (cos b, sin b) at each of its n contacts, which
            # are all valid (Eq 1's denominator is 1); only the rough surface is summed.
            rx, ry = (g2x, g2y) if flat1 else (g1x, g1y)
            sx, sy, bad, worst, where = _sums_nb(m0, rx, ry, rx, ry, cb, sb, drop, chunks, False)
            sx[0] += n * m0 * cb
            sy[0] += n * m0 * sb
            if flat1:
                where = where + 1  # the rough surface is surface 2: code 2 p + 1
        else:
            sx, sy, bad, worst, where = _sums_nb(m0, g1x, g1y, g2x, g2y, cb, sb, drop, chunks, True)
    else:
        sx, sy, bad, worst, where = _sums_np(m0, g1x, g1y, g2x, g2y, cb, sb, drop)
    # The worst contact over chunks (the first chunk wins a tie).
    best_chunk = np.argmin(worst, axis=0)
    cols = np.arange(cb.size)
    code = where[best_chunk, cols]
    invalid = bad.sum(axis=0)
    kept = 2 * n - invalid if drop else np.full(cb.size, 2 * n, dtype=np.int64)
    return FullContactSums(
        sum_x=sx.sum(axis=0),
        sum_y=sy.sum(axis=0),
        kept=np.asarray(kept, dtype=np.int64),
        invalid=np.asarray(invalid, dtype=np.int64),
        worst_den=worst[best_chunk, cols],
        worst_station=np.asarray(code // 2, dtype=np.int64),
        worst_family=np.asarray(code % 2 + 1, dtype=np.int64),
        n_stations=n,
    )
