"""Linear solves of the Newton iteration with one factorisation per run.

The global tangent differs from a constant matrix only on the contact dofs:
``J = K0 + P^T A P`` with ``K0 = K + sum_a B_a^T (w D^e_aa) B_a`` (the elastic block on
closed elastic contact springs: never singular, whatever the Dirichlet conditions) and
``A = sum_ab B_ca^T (w (D - D^e)_ab) B_cb`` on the m contact dofs. ``K0`` is factorised
once (SuperLU) together with its m columns ``Z = K0^{-1} P^T``; every Newton solve is
then a back-substitution and an m x m dense solve (Woodbury identity):
``J^{-1} b = y - Z (I + A G)^{-1} A y_c`` with ``y = K0^{-1} b`` and ``G = P Z``.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from frictionlab.contact.interface import slip_map
from frictionlab.contact.mesh import Discretisation
from frictionlab.subloading import SubloadingParams

__all__ = ["TangentSolver"]


class TangentSolver:
    """Solve ``J_ff delta = b`` on the free dofs for given contact moduli."""

    def __init__(self, disc: Discretisation, fixed: np.ndarray, params: SubloadingParams) -> None:
        free = ~np.asarray(fixed, dtype=bool)
        self.free = free
        w = disc.contact_weight
        Bs = [B.tocsc()[:, free] for B in disc.interp]
        cols = np.unique(np.concatenate([B.nonzero()[1] for B in Bs]))
        self.contact = cols
        self.rows = [_rows(B[:, cols].tocsr()) for B in Bs]
        self.w = w
        M = slip_map(disc.dim)
        alpha_t = float(np.asarray(params.alpha_t))
        alpha_n = float(np.asarray(params.alpha_n))
        self.elastic = M.T @ np.diag([alpha_t, alpha_t, alpha_n]) @ M  # (d, d), diagonal
        K = disc.stiffness.tocsc()[free][:, free]
        K0 = K + sum(self.elastic[a, a] * (B.T @ sp.diags(w) @ B) for a, B in enumerate(Bs))
        self.lu = spla.splu(sp.csc_matrix(K0))
        n_free = int(free.sum())
        E = np.zeros((n_free, cols.size))
        E[cols, np.arange(cols.size)] = 1.0
        self.Z = self.lu.solve(E) if cols.size else E
        self.G = self.Z[cols, :]

    def correction(self, moduli: np.ndarray) -> sp.csr_matrix:
        """``A`` (m, m, sparse): the contact moduli minus the elastic ones, on the contact dofs."""
        w, m = self.w, self.contact.size
        rows: list[np.ndarray] = []
        cols: list[np.ndarray] = []
        values: list[np.ndarray] = []
        dim = len(self.rows)
        for a in range(dim):
            ia, va = self.rows[a]
            for b in range(dim):
                ib, vb = self.rows[b]
                c = moduli[:, a, b] - self.elastic[a, b]
                shape = (ia.shape[0], ia.shape[1], ib.shape[1])
                rows.append(np.broadcast_to(ia[:, :, None], shape).ravel())
                cols.append(np.broadcast_to(ib[:, None, :], shape).ravel())
                values.append(((w * c)[:, None, None] * va[:, :, None] * vb[:, None, :]).ravel())
        return sp.csr_matrix(
            (np.concatenate(values), (np.concatenate(rows), np.concatenate(cols))), shape=(m, m)
        )

    def solve(self, moduli: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``delta`` with ``(K_ff + Kc_ff(moduli)) delta = b``; raises on a singular tangent."""
        y = self.lu.solve(np.asarray(b, dtype=np.float64))
        if self.contact.size == 0:
            return y
        A = self.correction(moduli)
        M = np.eye(self.contact.size) + np.asarray(A @ self.G)
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
