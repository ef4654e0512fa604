"""Linear solves of the Newton iteration with one factorisation per run.

The global tangent differs from a constant matrix only on the contact dofs:
``J = K0 + P^T A P`` with ``K0 = K + B^T (w C^e) B`` (the elastic block on closed
elastic contact springs: never singular, whatever the Dirichlet conditions) and
``A = B_c^T (w (C - C^e)) B_c`` on the m contact dofs. ``K0`` is factorised once
(SuperLU) together with its m columns ``Z = K0^{-1} P^T``; every Newton solve is then a
back-substitution and an m x m dense solve (Woodbury identity):
``J^{-1} b = y - Z (I + A G)^{-1} A y_c`` with ``y = K0^{-1} b`` and ``G = P Z``.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from frictionlab.contact.mesh import Discretisation
from frictionlab.subloading import SubloadingParams

__all__ = ["TangentSolver"]


class TangentSolver:
    """Solve ``J_ff delta = b`` on the free dofs for given contact moduli."""

    def __init__(self, disc: Discretisation, fixed: np.ndarray, params: SubloadingParams) -> None:
        free = ~np.asarray(fixed, dtype=bool)
        self.free = free
        w = disc.contact_weight
        Bx = disc.interp_x.tocsc()[:, free]
        By = disc.interp_y.tocsc()[:, free]
        cols = np.unique(np.concatenate([Bx.nonzero()[1], By.nonzero()[1]]))
        self.contact = cols
        self.ix, self.vx = _rows(Bx[:, cols].tocsr())
        self.iy, self.vy = _rows(By[:, cols].tocsr())
        self.w = w
        self.alpha_t = float(np.asarray(params.alpha_t))
        self.alpha_n = float(np.asarray(params.alpha_n))
        K = disc.stiffness.tocsc()[free][:, free]
        K0 = K + self.alpha_t * (Bx.T @ sp.diags(w) @ Bx) + self.alpha_n * (By.T @ sp.diags(w) @ By)
        self.lu = spla.splu(K0.tocsc())
        n_free = int(free.sum())
        E = np.zeros((n_free, cols.size))
        E[cols, np.arange(cols.size)] = 1.0
        self.Z = self.lu.solve(E) if cols.size else E
        self.G = self.Z[cols, :]

    def correction(self, moduli: np.ndarray) -> np.ndarray:
        """``A`` (m, m): the contact moduli minus the elastic ones, on the contact dofs."""
        c11, c13, c31, c33 = moduli
        w, m = self.w, self.contact.size
        index, values = [], []
        for c, (ia, va), (ib, vb) in (
            (c11 - self.alpha_t, (self.ix, self.vx), (self.ix, self.vx)),
            (c13, (self.ix, self.vx), (self.iy, self.vy)),
            (c31, (self.iy, self.vy), (self.ix, self.vx)),
            (c33 - self.alpha_n, (self.iy, self.vy), (self.iy, self.vy)),
        ):
            index.append((ia[:, :, None] * m + ib[:, None, :]).ravel())
            values.append(((w * c)[:, None, None] * va[:, :, None] * vb[:, None, :]).ravel())
        flat = np.bincount(np.concatenate(index), np.concatenate(values), minlength=m * m)
        return flat.reshape(m, m)

    def solve(self, moduli: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``delta`` with ``(K_ff + Kc_ff(moduli)) delta = b``; raises on a singular tangent."""
        y = self.lu.solve(np.asarray(b, dtype=np.float64))
        if self.contact.size == 0:
            return y
        A = self.correction(moduli)
        M = np.eye(self.contact.size) + A @ self.G
        z = sla.solve(M, A @ y[self.contact], check_finite=True)
        return y - self.Z @ z


def _rows(B: sp.csr_matrix) -> tuple[np.ndarray, np.ndarray]:
    """Column indices and values of every row of ``B``, padded to equal length."""
    counts = np.diff(B.indptr)
    width = max(int(counts.max(initial=0)), 1)
    idx = np.zeros((B.shape[0], width), dtype=np.int64)
    val = np.zeros((B.shape[0], width))
    for k in range(width):
        has = counts > k
        pos = B.indptr[:-1][has] + k
        idx[has, k] = B.indices[pos]
        val[has, k] = B.data[pos]
    return idx, val
