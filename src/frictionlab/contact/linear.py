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

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from frictionlab.contact.block import Block
from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.interface import slip_map
from frictionlab.contact.mesh import Discretisation
from frictionlab.errors import ParameterError
from frictionlab.subloading import SubloadingParams

__all__ = [
    "FACTOR_MODELS",
    "LINEAR_SOLVERS",
    "ORDERINGS",
    "FactorModel",
    "IterativeSolver",
    "TangentSolver",
    "cost",
    "estimate",
    "make_solver",
    "reduction",
]

#: Linear solvers: sparse direct (SuperLU, the contact block of K0^-1 kept) or iterative
#: (GMRES preconditioned by algebraic multigrid, pyamg; memory linear in the unknowns).
LINEAR_SOLVERS: tuple[str, ...] = ("direct", "iterative")

#: Orderings of the direct solver: METIS nested dissection with the contact unknowns
#: last (default), or one of SuperLU's column orderings (scipy ``splu(permc_spec=...)``).
ORDERINGS: tuple[str, ...] = ("nested_dissection", "MMD_AT_PLUS_A", "COLAMD", "MMD_ATA")
#: Libraries of the nested-dissection factorisation: CHOLMOD's supernodal Cholesky
#: (cvxopt, one factor stored) when installed under ``"auto"``, else SuperLU (scipy).
BACKENDS: tuple[str, ...] = ("auto", "cholmod", "superlu")
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


class _Reduced:
    """Reduced coordinates ``q`` of a solver: ``u = u_prescribed + T q``."""

    T: sp.csc_matrix

    def reduce(self, r: np.ndarray) -> np.ndarray:
        """A full-length vector of forces in reduced coordinates, ``T^T r``."""
        return np.asarray(self.T.T @ r)

    def expand(self, delta: np.ndarray) -> np.ndarray:
        """A reduced increment as nodal displacements, ``T delta``."""
        return np.asarray(self.T @ delta)


class TangentSolver(_Reduced):
    """Solve ``T^T J T delta = b`` for given contact moduli (``b``, ``delta`` reduced).

    ``ordering``: ``"nested_dissection"`` (METIS through pymetis, default; reverse
    Cuthill-McKee when pymetis is missing) orders the bulk unknowns with the contact
    unknowns (and any rigid-plate unknown) last, so that the trailing block of the
    factors is the Schur complement ``S`` of ``K0`` on them and ``G = S^{-1}`` costs
    one dense inversion; the other names are SuperLU's own column orderings
    (:data:`ORDERINGS`), with ``G`` built by back-substitution in chunks of columns.
    ``backend`` (nested dissection only, :data:`BACKENDS`): ``"cholmod"`` factorises
    ``K0 = L L^T`` (CHOLMOD's supernodal Cholesky through cvxopt: one factor stored,
    half of SuperLU's ``L`` and ``U``) and forms ``G = W^T W``, ``W = L_tt^{-1}`` the
    inverse of the factor's trailing block; ``"superlu"`` (scipy) factorises
    ``K0 = L U`` without pivoting; ``"auto"`` (default) takes CHOLMOD when cvxopt is
    installed. Both give ``G`` and the solves to round-off.
    """

    def __init__(
        self,
        disc: Discretisation,
        fixed: np.ndarray,
        params: SubloadingParams | Frictionless,
        ties: Sequence[np.ndarray] = (),
        *,
        ordering: str = "nested_dissection",
        backend: str = "auto",
    ) -> None:
        if ordering not in ORDERINGS:
            raise ParameterError("ordering", ordering, "one of " + ", ".join(ORDERINGS))
        T = reduction(fixed, ties)
        self.T = T
        w = disc.contact_weight
        Bs = [_pruned((B @ T).tocsc()) for B in disc.interp]
        cols = np.unique(np.concatenate([B.nonzero()[1] for B in Bs]))
        self.contact = cols
        self.rows = [_rows(B[:, cols].tocsr()) for B in Bs]
        self.w = w
        M = slip_map(disc.dim)
        alpha_t = float(np.asarray(params.alpha_t))
        alpha_n = float(np.asarray(params.alpha_n))
        self.elastic = M.T @ np.diag([alpha_t, alpha_t, alpha_n]) @ M  # (d, d), diagonal
        K = (T.T @ disc.stiffness @ T).tocsc()
        K0 = (
            K + sum(self.elastic[a, a] * (B.T @ sp.diags(w) @ B) for a, B in enumerate(Bs))
        ).tocsc()
        del K
        self.n = int(T.shape[1])
        self.dim = disc.dim
        m = cols.size
        self.perm: np.ndarray | None = None
        self.G: np.ndarray
        chosen = _backend(backend)  # checked for every ordering
        self.backend = chosen if ordering == "nested_dissection" else "superlu"
        if self.backend == "cholmod":
            self.perm, _ = _contact_last_order(K0, cols)
            self.lu: Any = _Cholmod(K0, self.perm)
            del K0
            self.G = self.lu.inverse_block(cols)
            return
        if ordering == "nested_dissection":
            self.perm, last = _contact_last_order(K0, cols)
            self.iperm = np.empty_like(self.perm)
            self.iperm[self.perm] = np.arange(self.n)
            K0 = K0[self.perm][:, self.perm].tocsc()
            self.lu = spla.splu(
                K0, permc_spec="NATURAL", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
            )
            del K0
            inverse = _trailing_inverse(self.lu, last)
            if inverse is not None:
                # the contact unknowns' places in the trailing block
                tail = self.perm[self.n - last :]
                if np.array_equal(tail, cols):
                    self.G = inverse
                else:
                    order = np.argsort(tail)
                    where = order[np.searchsorted(tail[order], cols)]
                    self.G = np.ascontiguousarray(inverse[np.ix_(where, where)])
                return
        else:
            self.lu = spla.splu(K0, permc_spec=ordering)
            del K0
        # SuperLU pivoted or reordered the trailing block: back-substitution in chunks
        self.G = np.empty((m, m))
        for start in range(0, m, _CHUNK):
            stop = min(start + _CHUNK, m)
            E = np.zeros((self.n, stop - start))
            E[cols[start:stop], np.arange(stop - start)] = 1.0
            self.G[:, start:stop] = self._lu_solve(E)[cols, :]

    def _lu_solve(self, b: np.ndarray) -> np.ndarray:
        """``K0^{-1} b`` (``b`` a vector or columns, in reduced coordinates)."""
        if self.perm is None or self.backend == "cholmod":
            return np.asarray(self.lu.solve(b))
        return np.asarray(self.lu.solve(b[self.perm]))[self.iperm]

    @property
    def memory_bytes(self) -> int:
        """Bytes held by the factors and the contact block (SuperLU's counted; CHOLMOD's
        estimated by :func:`cost`'s fill, as cvxopt does not report its factor's size)."""
        if self.backend == "cholmod":
            need = cost(self.n, self.contact.size, self.dim, "direct", "cholmod")["bytes"]
            return int(need - self.n * MESH_BYTES[self.dim - 2])
        nnz = int(self.lu.L.nnz + self.lu.U.nnz)
        return 12 * nnz + 8 * self.G.size

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
        y = self._lu_solve(np.asarray(b, dtype=np.float64))
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
        return y - self._lu_solve(scatter)


class IterativeSolver(_Reduced):
    """GMRES on ``T^T J T`` preconditioned by smoothed-aggregation AMG (pyamg).

    The hierarchy is built on the symmetric part of the tangent (with the rigid-body
    modes as near-null space) and rebuilt only when the contact moduli change; memory
    stays linear in the unknowns (no factorisation). Same interface as
    :class:`TangentSolver`.
    """

    def __init__(
        self,
        disc: Discretisation,
        fixed: np.ndarray,
        ties: Sequence[np.ndarray] = (),
        *,
        rtol: float = 1e-10,
    ) -> None:
        try:
            import pyamg
        except ImportError:
            raise ParameterError(
                "linear_solver", "iterative", 'installed pyamg (pip install "frictionlab[fem]")'
            ) from None
        self._pyamg = pyamg
        self.T = reduction(fixed, ties)
        self.disc = disc
        self.K = (self.T.T @ disc.stiffness @ self.T).tocsr()
        self.n = int(self.T.shape[1])
        self.rtol = rtol
        self._key: bytes | None = None
        self._J: sp.csr_matrix | None = None
        self._M: Any = None
        self.near_null = _rigid_modes(disc, self.T)
        self.iterations = 0

    @property
    def memory_bytes(self) -> int:
        """Bytes of the tangent and the multigrid hierarchy (an estimate)."""
        J = self._J if self._J is not None else self.K
        return int(3 * 12 * J.nnz)

    def solve(self, moduli: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``delta`` with ``T^T (K + Kc(moduli)) T delta = b``; raises when GMRES fails."""
        from frictionlab.contact.interface import contact_stiffness

        key = np.ascontiguousarray(moduli).tobytes()
        if key != self._key:
            Kc = self.T.T @ contact_stiffness(self.disc, moduli) @ self.T
            J = (self.K + Kc).tocsr()
            sym = (0.5 * (J + J.T)).tocsr()
            ml = self._pyamg.smoothed_aggregation_solver(sym, B=self.near_null, max_coarse=500)
            self._J, self._M, self._key = J, ml.aspreconditioner(), key
        count = [0]

        def tick(_: object) -> None:
            count[0] += 1

        x, info = spla.gmres(
            self._J, np.asarray(b, dtype=np.float64), M=self._M, rtol=self.rtol, atol=0.0,
            restart=60, maxiter=20, callback=tick, callback_type="pr_norm",
        )  # fmt: skip
        self.iterations += count[0]
        if info != 0 or not np.all(np.isfinite(x)):
            raise ValueError(f"GMRES did not converge (info {info}, {count[0]} iterations)")
        return np.asarray(x)


def make_solver(
    kind: str,
    disc: Discretisation,
    fixed: np.ndarray,
    params: SubloadingParams | Frictionless,
    ties: Sequence[np.ndarray] = (),
) -> TangentSolver | IterativeSolver:
    """The linear solver of :data:`LINEAR_SOLVERS` named ``kind``."""
    if kind == "direct":
        return TangentSolver(disc, fixed, params, ties)
    if kind == "iterative":
        return IterativeSolver(disc, fixed, ties)
    raise ParameterError("linear_solver", kind, "one of " + ", ".join(LINEAR_SOLVERS))


@dataclass(frozen=True)
class FactorModel:
    """Fitted size and time of one nested-dissection factorisation (contact unknowns
    last) on this model's meshes, one core of the shared machine, upper ends.

    ``fill``: factor entries per unknown over ``log2(n)`` (2-D) or ``n**(1/3)`` (3-D);
    ``bytes``: bytes per entry at the peak (2-D, 3-D); ``factor``: seconds per entry
    (2-D) and per entry and unknown (3-D, ~n^2 overall); ``sweep_flops``: the rate of
    the forward sweeps that form ``G`` (0: ``G`` read from the factors' trailing
    block); ``inversions``: dense m x m inversions of ``G``'s set-up.
    """

    fill: tuple[float, float]
    bytes: tuple[float, float]
    factor: tuple[float, float]
    sweep_flops: float
    inversions: float


#: SuperLU's ``L`` and ``U`` (167 entries per unknown at 51k, 2-D; 984 at 13.9k and 1,617
#: at 45k, 3-D); at the peak the supernodal factors, the CSC copy of one of them while
#: the trailing block is read and the allocator's slack (3-D 32^3 hexahedra 5.9 GB above
#: the interpreter). CHOLMOD's ``L`` alone (503 entries per unknown at 14.2k, 3-D): the
#: supernodal factor and its workspace (9.4 bytes per entry measured at 45.6k, 3-D; 14
#: at 51.7k, 2-D) and the forward sweeps that form ``G`` (6.6e9 flop/s measured).
FACTOR_MODELS: dict[str, FactorModel] = {
    "superlu": FactorModel((11.0, 46.0), (19.0, 19.0), (1e-7, 1e-11), 0.0, 3.0),
    "cholmod": FactorModel((5.5, 23.0), (14.0, 11.0), (1e-7, 3e-12), 4e9, 1.0),
}
#: Bytes per unknown of the mesh, its assembly and the solver's sparse matrices (2-D,
#: 3-D): what the measured peaks leave above the interpreter, the factors and the dense
#: blocks (2-D 52k unknowns: 2.8 kB; 3-D 14.7k: 12 kB; scikit-fem's hexahedron assembly
#: alone peaks at 10 kB per unknown).
MESH_BYTES = (3000.0, 12000.0)
#: Seconds per factor entry of one solve (two triangular sweeps; 3.3e-9 measured) and
#: the dense rate [flop/s].
SOLVE_S_PER_ENTRY, DENSE_FLOPS = 4e-9, 5e9
#: The iterative solver: GMRES basis vectors, the multigrid hierarchy's size relative to
#: the tangent, and seconds per unknown of one solve (a hierarchy rebuilt and GMRES: 108
#: CPU s for ~70 solves at 14.7k unknowns, 3-D).
GMRES_RESTART, AMG_COMPLEXITY, ITERATIVE_S_PER_UNKNOWN = 60, 3.0, 1e-4


def cost(
    unknowns: float,
    contact_unknowns: float,
    dim: int,
    linear_solver: str = "direct",
    backend: str = "auto",
) -> dict[str, float]:
    """Memory and time of the linear solver for ``unknowns`` free unknowns of which
    ``contact_unknowns`` on the contact face: ``bytes`` (the peak), ``setup`` [s] (the
    factorisation and the contact block) and ``per_solve`` [s] (one Newton solve).

    Direct (:data:`FACTOR_MODELS`, ``backend`` as in :class:`TangentSolver`, ``"auto"``
    the one installed): the nested-dissection factors (``fill * log2(n)`` or
    ``fill * n**(1/3)`` entries per unknown), the dense contact blocks (three m x m
    arrays while ``G`` is formed) and the mesh and its matrices; a solve is two sweeps of
    the factors and a dense solve on at most m contact unknowns. Iterative: the tangent
    and its hierarchy, the GMRES basis and the mesh.
    """
    n, m = float(unknowns), float(contact_unknowns)
    i = 0 if dim == 2 else 1
    mesh = n * MESH_BYTES[i]
    if linear_solver == "direct":
        model = FACTOR_MODELS[_backend(backend)]
        scale = math.log2(max(n, 2.0)) if dim == 2 else n ** (1.0 / 3.0)
        entries = model.fill[i] * scale * n
        need = mesh + model.bytes[i] * entries + 3 * 8.0 * m * m
        setup = model.factor[i] * entries * (1.0 if dim == 2 else n)
        if model.sweep_flops:
            setup += 2.0 * entries * m / model.sweep_flops
        setup += model.inversions * m**3 / DENSE_FLOPS
        per_solve = 2.0 * SOLVE_S_PER_ENTRY * entries + (2.0 / 3.0) * m**3 / DENSE_FLOPS
    elif linear_solver == "iterative":
        nnz = n * (9 if dim == 2 else 27) * dim
        need = mesh + (1.0 + AMG_COMPLEXITY) * 12.0 * nnz + 8.0 * GMRES_RESTART * n
        setup = 0.0
        per_solve = ITERATIVE_S_PER_UNKNOWN * n  # a hierarchy and GMRES per solve
    else:
        raise ParameterError("linear_solver", linear_solver, "one of " + ", ".join(LINEAR_SOLVERS))
    return {"bytes": need, "setup": setup, "per_solve": per_solve}


def estimate(block: Block, linear_solver: str = "direct") -> dict[str, float]:
    """Size of a run of ``block`` before meshing: ``unknowns``, ``contact_unknowns`` and
    the solver's ``bytes``, ``setup`` and ``per_solve`` seconds (:func:`cost`)."""
    cells = np.asarray(block.cells, dtype=np.float64)
    d = block.dim
    n = d * float(np.prod(cells + 1))
    m = d * float(np.prod(cells[:-1] + 1))
    return {"unknowns": n, "contact_unknowns": m, **cost(n, m, d, linear_solver)}


def _rigid_modes(disc: Discretisation, T: sp.csc_matrix) -> np.ndarray:
    """Rigid-body modes of the block in reduced coordinates (AMG near-null space)."""
    d = disc.dim
    x = disc.nodes
    modes = []
    for a in range(d):  # translations
        u = np.zeros(disc.n_dofs)
        u[disc.dofs[a]] = 1.0
        modes.append(u)
    pairs = [(0, 1)] if d == 2 else [(0, 1), (1, 2), (0, 2)]
    for a, b in pairs:  # rotations
        u = np.zeros(disc.n_dofs)
        u[disc.dofs[a]] = -x[b]
        u[disc.dofs[b]] = x[a]
        modes.append(u)
    full = np.column_stack(modes)
    # least-squares restriction to the reduced coordinates (exact on untied free dofs)
    counts = np.asarray(T.sum(axis=0)).ravel()
    counts[counts == 0] = 1.0
    return np.asarray(T.T @ full) / counts[:, None]


def _pruned(B: sp.csc_matrix) -> sp.csc_matrix:
    """``B`` without its round-off entries (< 1e-12 of the largest): scikit-fem's facet
    interpolation stores ~1e-33 values of the nodes off the face, which would make them
    contact unknowns."""
    B = B.copy()
    B.data[np.abs(B.data) < 1e-12 * float(np.abs(B.data).max(initial=0.0))] = 0.0
    B.eliminate_zeros()
    return B


def _contact_last_order(K0: sp.csc_matrix, contact: np.ndarray) -> tuple[np.ndarray, int]:
    """A fill-reducing order of ``K0``'s unknowns with ``contact`` and the dense unknowns
    (a rigid plate's, coupled to a whole face) last; returns it and the trailing count.

    The bulk is ordered by METIS nested dissection (pymetis), or by reverse
    Cuthill-McKee when pymetis is not installed (more fill in 3-D).
    """
    n = K0.shape[0]
    degree = np.diff(K0.indptr)
    dense = np.flatnonzero(degree > 8 * max(int(np.median(degree)), 1))
    last = np.union1d(contact, dense)
    bulk = np.setdiff1d(np.arange(n), last)
    graph = abs(K0[bulk][:, bulk]).tocsr()
    # METIS needs a symmetric adjacency (an unsymmetric one corrupts its heap and hangs):
    # K0's pattern is unsymmetric when fixed unknowns keep only their diagonal row.
    graph = (graph + graph.T).tocsr()
    graph.setdiag(0.0)
    graph.eliminate_zeros()
    try:
        import pymetis
    except ImportError:
        from scipy.sparse.csgraph import reverse_cuthill_mckee

        local = np.asarray(reverse_cuthill_mckee(graph, symmetric_mode=True))
    else:
        if bulk.size > 1 and graph.nnz:
            adjacency = pymetis.CSRAdjacency(graph.indptr, graph.indices)
            local = np.asarray(pymetis.nested_dissection(adjacency)[0], dtype=np.int64)
        else:
            local = np.arange(bulk.size)
    return np.concatenate([bulk[local], last]).astype(np.int64), int(last.size)


def _trailing_inverse(lu: Any, k: int) -> np.ndarray | None:
    """The inverse of the Schur complement on the last ``k`` unknowns, ``(L U)_kk^{-1}``,
    from the trailing blocks of SuperLU's factors; None when SuperLU moved a row or
    column into or out of the trailing block (then the factors' tail is not the Schur
    complement)."""
    n = lu.shape[0]
    tail = np.arange(n - k, n)
    if k == 0 or not (
        np.array_equal(lu.perm_r[n - k :], tail) and np.array_equal(lu.perm_c[n - k :], tail)
    ):
        return None
    L = lu.L  # one full factor in memory at a time
    L_kk = L[n - k :, n - k :].toarray()
    del L
    U = lu.U
    U_kk = U[n - k :, n - k :].toarray()
    del U
    inv_L, info_l = sla.lapack.dtrtri(L_kk, lower=1, unitdiag=1, overwrite_c=1)
    del L_kk
    inv_U, info_u = sla.lapack.dtrtri(U_kk, lower=0, overwrite_c=1)
    del U_kk
    if info_l or info_u:
        return None
    return np.asarray(inv_U @ inv_L)  # symmetric to round-off (K0 is)


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


def _backend(name: str) -> str:
    """The factorisation's library: ``"cholmod"`` (cvxopt's CHOLMOD) when importable under
    ``"auto"``, else ``"superlu"`` (scipy)."""
    if name not in BACKENDS:
        raise ParameterError("backend", name, "one of " + ", ".join(BACKENDS))
    if name != "auto":
        return name
    try:
        import cvxopt.cholmod  # noqa: F401
    except ImportError:
        return "superlu"
    return "cholmod"


class _Cholmod:
    """Supernodal Cholesky ``P A P^T = L L^T`` of a symmetric positive definite ``A``
    (CHOLMOD through cvxopt; one factor stored), in the fill-reducing order ``perm``
    (CHOLMOD may postorder it: :attr:`order` is the one used)."""

    def __init__(self, A: sp.csc_matrix, perm: np.ndarray) -> None:
        from cvxopt import cholmod, matrix, spmatrix

        self._cholmod, self._matrix = cholmod, matrix
        low = sp.tril(A, format="coo")
        self._A = spmatrix(
            matrix(low.data), matrix(low.row.astype(np.int64)), matrix(low.col.astype(np.int64)),
            A.shape,
        )  # fmt: skip
        del low
        self._perm = matrix(np.asarray(perm, dtype=np.int64))
        self.n = int(A.shape[0])
        self.F = self._factor()
        del self._A
        # CHOLMOD's order: P x = x[order] (sys=7 solves P^T y = x)
        x = matrix(np.arange(self.n, dtype=np.float64))
        cholmod.solve(self.F, x, sys=7)
        self.order = np.asarray(x, dtype=np.int64).ravel()

    def _factor(self) -> Any:
        cholmod = self._cholmod
        saved = dict(cholmod.options)
        cholmod.options.update({"supernodal": 2, "nmethods": 1, "postorder": True})
        try:
            F = cholmod.symbolic(self._A, p=self._perm, uplo="L")
            cholmod.numeric(self._A, F)
        except ArithmeticError as exc:
            raise ValueError(f"the elastic stiffness is not positive definite ({exc})") from None
        finally:
            cholmod.options.clear()
            cholmod.options.update(saved)
        return F

    def solve(self, b: np.ndarray) -> np.ndarray:
        """``A^{-1} b`` (a vector or columns)."""
        B = self._matrix(np.asarray(b, dtype=np.float64))
        self._cholmod.solve(self.F, B, sys=0)
        out = np.asarray(B)
        return out.ravel() if np.ndim(b) == 1 else out

    def inverse_block(self, idx: np.ndarray) -> np.ndarray:
        """``(A^{-1})[idx][:, idx] = W^T W`` with ``W = L^{-1} P E_idx``, zero above the
        first of ``idx``'s places in the order (only the factor's trailing block acts):
        forward sweeps on sparse right-hand sides in chunks of columns, no copy of the
        factor."""
        from cvxopt import spmatrix

        where = np.empty(self.n, dtype=np.int64)
        where[self.order] = np.arange(self.n)
        pos = where[np.asarray(idx, dtype=np.int64)]
        first = int(pos.min(initial=self.n))
        m = pos.size
        W = np.zeros((self.n - first, m))
        for start in range(0, m, _CHUNK):
            stop = min(start + _CHUNK, m)
            k = stop - start
            B = spmatrix(1.0, pos[start:stop].tolist(), list(range(k)), (self.n, k))
            X = self._cholmod.spsolve(self.F, B, sys=4)
            colptr, rows, values = (np.asarray(a).ravel() for a in X.CCS)
            cols = np.repeat(np.arange(k), np.diff(colptr))
            W[rows - first, start + cols] = values
            del B, X
        return np.asarray(W.T @ W)
