"""Linear solves of the Newton iteration with one sparse factorisation per run.

Unknowns: the reduced coordinates ``q`` with ``u = u_prescribed + T q``; ``T`` (n_dofs,
n_q, sparse 0/1) drops the prescribed dofs and ties groups of dofs to one unknown (a
rigid top plate). The global tangent differs from a constant matrix only on the contact
dofs: ``J = K0 + P^T A P`` with ``K0 = T^T (K + sum_a B_a^T (w D^e_aa) B_a) T`` (the
block on closed elastic contact springs: never singular) and ``A`` the contact moduli
minus the elastic ones on the m contact unknowns.

``K0`` is factorised once (SuperLU; ``permc_spec`` the column ordering). Only the m x m
contact block of its inverse, ``G = P K0^{-1} P^T``, is kept (built by back-substitution
in chunks of columns): memory O(nnz(LU) + m^2), no dense n x m storage. A Newton solve
is then two back-substitutions and a dense solve on the k <= m contact unknowns where
``A != 0`` (the sliding and open points; Woodbury identity):
``J^{-1} b = y - K0^{-1} P^T z``, ``(I + A_ss G_ss) z_s = A_ss y_s``, ``y = K0^{-1} b``.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.interface import slip_map
from frictionlab.contact.mesh import Discretisation
from frictionlab.subloading import SubloadingParams

__all__ = ["ORDERINGS", "TangentSolver", "reduction"]

#: SuperLU column orderings (scipy ``splu(permc_spec=...)``).
ORDERINGS: tuple[str, ...] = ("MMD_AT_PLUS_A", "COLAMD", "MMD_ATA", "NATURAL")
_CHUNK = 256  # columns per back-substitution block when G is built


def reduction(fixed: np.ndarray, ties: Sequence[np.ndarray] = ()) -> sp.csc_matrix:
    """``T`` (n_dofs, n_q): identity on the free untied dofs, one column per tie group.

    ``fixed`` is a boolean mask of prescribed dofs; each array of ``ties`` lists free
    dofs that move together (one unknown; their loads add up on it).
    """
    fixed = np.asarray(fixed, dtype=bool)
    n = fixed.size
    col = np.full(n, -1, dtype=np.int64)
    tied = np.zeros(n, dtype=bool)
    for group in ties:
        tied[np.asarray(group, dtype=np.int64)] = True
    single = np.flatnonzero(~fixed & ~tied)
    col[single] = np.arange(single.size)
    k = single.size
    for group in ties:
        g = np.asarray(group, dtype=np.int64)
        g = g[~fixed[g]]
        if g.size:
            col[g] = k
            k += 1
    rows = np.flatnonzero(col >= 0)
    return sp.csc_matrix((np.ones(rows.size), (rows, col[rows])), shape=(n, k))


class TangentSolver:
    """Solve ``T^T J T delta = b`` for given contact moduli (``b``, ``delta`` reduced)."""

    def __init__(
        self,
        disc: Discretisation,
        fixed: np.ndarray,
        params: SubloadingParams | Frictionless,
        ties: Sequence[np.ndarray] = (),
        *,
        ordering: str = "MMD_AT_PLUS_A",
    ) -> None:
        T = reduction(fixed, ties)
        self.T = T
        w = disc.contact_weight
        Bs = [(B @ T).tocsc() for B in disc.interp]
        cols = np.unique(np.concatenate([B.nonzero()[1] for B in Bs]))
        self.contact = cols
        self.rows = [_rows(B[:, cols].tocsr()) for B in Bs]
        self.w = w
        M = slip_map(disc.dim)
        alpha_t = float(np.asarray(params.alpha_t))
        alpha_n = float(np.asarray(params.alpha_n))
        self.elastic = M.T @ np.diag([alpha_t, alpha_t, alpha_n]) @ M  # (d, d), diagonal
        K = (T.T @ disc.stiffness @ T).tocsc()
        K0 = K + sum(self.elastic[a, a] * (B.T @ sp.diags(w) @ B) for a, B in enumerate(Bs))
        self.lu = spla.splu(sp.csc_matrix(K0), permc_spec=ordering)
        self.n = int(T.shape[1])
        m = cols.size
        self.G = np.empty((m, m))
        for start in range(0, m, _CHUNK):
            stop = min(start + _CHUNK, m)
            E = np.zeros((self.n, stop - start))
            E[cols[start:stop], np.arange(stop - start)] = 1.0
            self.G[:, start:stop] = self.lu.solve(E)[cols, :]

    @property
    def memory_bytes(self) -> int:
        """Bytes held by the factors and the contact block (an estimate of the peak)."""
        nnz = int(self.lu.L.nnz + self.lu.U.nnz)
        return 12 * nnz + 8 * self.G.size

    def reduce(self, r: np.ndarray) -> np.ndarray:
        """A full-length vector of forces in reduced coordinates, ``T^T r``."""
        return np.asarray(self.T.T @ r)

    def expand(self, delta: np.ndarray) -> np.ndarray:
        """A reduced increment as nodal displacements, ``T delta``."""
        return np.asarray(self.T @ delta)

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
                keep = c != 0.0
                if not keep.any():
                    continue
                ia_k, va_k, ib_k, vb_k = ia[keep], va[keep], ib[keep], vb[keep]
                shape = (ia_k.shape[0], ia_k.shape[1], ib_k.shape[1])
                rows.append(np.broadcast_to(ia_k[:, :, None], shape).ravel())
                cols.append(np.broadcast_to(ib_k[:, None, :], shape).ravel())
                values.append(
                    (
                        (w[keep] * c[keep])[:, None, None] * va_k[:, :, None] * vb_k[:, None, :]
                    ).ravel()
                )
        if not rows:
            return sp.csr_matrix((m, m))
        return sp.csr_matrix(
            (np.concatenate(values), (np.concatenate(rows), np.concatenate(cols))), shape=(m, m)
        )

    def solve(self, moduli: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``delta`` with ``T^T (K + Kc(moduli)) T delta = b``; raises on a singular tangent."""
        y = self.lu.solve(np.asarray(b, dtype=np.float64))
        if self.contact.size == 0:
            return y
        A = self.correction(moduli)
        A.eliminate_zeros()
        rows, cols = A.nonzero()
        s = np.union1d(rows, cols)
        if s.size == 0:
            return y
        A_ss = A[s][:, s].toarray()
        M = np.eye(s.size) + A_ss @ self.G[np.ix_(s, s)]
        z = sla.solve(M, A_ss @ y[self.contact[s]], check_finite=True)
        scatter = np.zeros(self.n)
        scatter[self.contact[s]] = z
        return y - self.lu.solve(scatter)


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
