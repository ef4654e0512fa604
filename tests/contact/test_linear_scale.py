"""The direct solver at scale: the Schur complement taken from nested-dissection factors
gives the tangent's solution (2-D and 3-D, with a rigid plate's tie), and the size
estimate refuses a mesh that does not fit, naming the key, before meshing."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla
from tests.contact.support import law, pmma_block

from frictionlab.contact import Block, SolverOptions, discretise
from frictionlab.contact.interface import contact_stiffness
from frictionlab.contact.linear import TangentSolver, reduction
from frictionlab.contact.solver import check_memory
from frictionlab.errors import ParameterError


def _moduli(rng: np.random.Generator, n: int, d: int) -> np.ndarray:
    """Non-symmetric moduli as in plastic sliding, a few points open, some elastic."""
    moduli = rng.uniform(-2e11, 2e11, (n, d, d))
    for a in range(d):
        moduli[:, a, a] = rng.uniform(0.0, 5e11, n)
    moduli[:3] = 0.0
    moduli[-4:] = np.diag([5e11] * d)  # sticking: no correction there
    return moduli


@pytest.mark.parametrize(
    "block",
    [
        pmma_block(element_size=0.00625),
        Block(3e9, 0.35, 0.01, 0.01, 0.0025, element="hex", depth=0.01),
    ],
    ids=["2d", "3d"],
)
def test_schur_solver_equals_a_sparse_solve_of_the_assembled_tangent(block: Block) -> None:
    disc = discretise(block)
    d = disc.dim
    rng = np.random.default_rng(5)
    fixed = np.zeros(disc.n_dofs, dtype=bool)
    for a in range(d - 1):
        fixed[disc.dofs[a][disc.top_nodes]] = True
    ties = [disc.dofs[-1][disc.top_nodes]]  # a rigid plate pressing the top
    solver = TangentSolver(disc, fixed, law(), ties)
    assert solver.perm is not None  # the contact unknowns ordered last
    reference = TangentSolver(disc, fixed, law(), ties, ordering="MMD_AT_PLUS_A")
    moduli = _moduli(rng, disc.n_points, d)
    T = reduction(fixed, ties)
    J = (T.T @ (disc.stiffness + contact_stiffness(disc, moduli)) @ T).tocsc()
    b = rng.normal(size=J.shape[0]) * 1e3
    expected = spla.spsolve(J, b)
    tol = 1e-9 * np.abs(expected).max()
    np.testing.assert_allclose(solver.solve(moduli, b), expected, rtol=0, atol=tol)
    np.testing.assert_allclose(reference.solve(moduli, b), expected, rtol=0, atol=tol)
    # G is the contact block of K0^-1 (checked on one column against a full solve)
    e = np.zeros(J.shape[0])
    j = solver.contact[len(solver.contact) // 2]
    e[j] = 1.0
    column = solver._lu_solve(e)[solver.contact]
    np.testing.assert_allclose(
        solver.G[:, len(solver.contact) // 2], column, rtol=0, atol=1e-10 * np.abs(column).max()
    )


def test_memory_estimate_refuses_a_million_hex_block_before_meshing() -> None:
    block = Block(3e9, 0.35, 1.0, 1.0, 1.0 / 100, element="hex", depth=1.0)
    with pytest.raises(ParameterError, match=r"element_size .* memory_limit = 4e\+09"):
        check_memory(block, SolverOptions(memory_limit=4e9))
    check_memory(pmma_block(), SolverOptions(memory_limit=4e9))


def test_nested_dissection_gets_a_symmetric_graph_from_an_unsymmetric_pattern(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Fixed unknowns that keep only their diagonal row make K0's pattern unsymmetric;
    METIS needs a symmetric adjacency (an unsymmetric one corrupted its heap and hung the
    3-D Hertz run), so the ordering symmetrises the pattern it hands over."""
    pymetis = pytest.importorskip("pymetis")
    import scipy.sparse as sp

    from frictionlab.contact import linear

    disc = discretise(Block(3e9, 0.35, 0.01, 0.01, 0.0025, element="hex", depth=0.01))
    K0 = disc.stiffness.tolil()
    rows = np.arange(0, K0.shape[0], 7)
    for r in rows:  # a fixed unknown: its row becomes the identity, its column stays
        K0.rows[r], K0.data[r] = [int(r)], [1.0]
    K0 = K0.tocsr()
    assert abs(K0 - K0.T).nnz > 0  # the pattern is unsymmetric
    seen: list[sp.csr_matrix] = []
    real = pymetis.nested_dissection

    def spy(adjacency: object, *args: object, **kwargs: object) -> object:
        starts = np.asarray(adjacency.adj_starts)  # type: ignore[attr-defined]
        adjacent = np.asarray(adjacency.adjacent)  # type: ignore[attr-defined]
        n = len(starts) - 1
        seen.append(sp.csr_matrix((np.ones(len(adjacent)), adjacent, starts), shape=(n, n)))
        return real(adjacency, *args, **kwargs)

    monkeypatch.setattr(pymetis, "nested_dissection", spy)
    contact = disc.dofs[-1][np.isclose(disc.nodes[-1], disc.nodes[-1].min())]
    order, k = linear._contact_last_order(K0, contact)
    assert len(seen) == 1 and abs(seen[0] - seen[0].T).nnz == 0
    assert np.array_equal(np.sort(order), np.arange(K0.shape[0]))
    assert k >= contact.size


def test_cholmod_inverse_block_equals_the_dense_inverse() -> None:
    """G = (A^-1)[idx][:, idx] from the Cholesky factor's trailing block, in any given
    order (CHOLMOD may postorder it), against numpy's dense inverse."""
    pytest.importorskip("cvxopt")
    import scipy.sparse as sp

    from frictionlab.contact.linear import _Cholmod

    rng = np.random.default_rng(3)
    n = 300
    R = sp.random(n, n, density=0.02, random_state=4)
    A = (R @ R.T + 3.0 * sp.eye(n)).tocsc()
    idx = np.array([5, 17, 200, 3, 299])
    last = np.setdiff1d(rng.permutation(n), idx)
    for perm in (rng.permutation(n), np.concatenate([last, idx])):
        factor = _Cholmod(A, perm)
        inverse = np.linalg.inv(A.toarray())
        G = factor.inverse_block(idx)
        np.testing.assert_allclose(G, inverse[np.ix_(idx, idx)], rtol=0, atol=1e-13)
        b = rng.normal(size=(n, 2))
        np.testing.assert_allclose(factor.solve(b), inverse @ b, rtol=0, atol=1e-12)


@pytest.mark.parametrize(
    "block",
    [
        pmma_block(element_size=0.0125),
        Block(3e9, 0.35, 0.01, 0.01, 0.0025, element="hex", depth=0.01),
    ],
    ids=["2d", "3d"],
)
def test_cholmod_and_superlu_give_the_same_contact_block_and_run(
    block: Block, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The two factorisations agree to round-off: G, and the recorded forces of a slide
    through the static peak (relative 1e-10)."""
    pytest.importorskip("cvxopt")
    from tests.contact.support import NORMAL

    from frictionlab.contact import Slide, linear, run_contact

    disc = discretise(block)
    fixed = np.zeros(disc.n_dofs, dtype=bool)
    for a in range(disc.dim - 1):
        fixed[disc.dofs[a][disc.top_nodes]] = True
    ties = [disc.dofs[-1][disc.top_nodes]]
    chol = TangentSolver(disc, fixed, law(), ties, backend="cholmod")
    slu = TangentSolver(disc, fixed, law(), ties, backend="superlu")
    assert (chol.backend, slu.backend) == ("cholmod", "superlu")
    np.testing.assert_allclose(chol.G, slu.G, rtol=0, atol=1e-10 * np.abs(slu.G).max())
    runs = {}
    for name in ("cholmod", "superlu"):
        monkeypatch.setattr(linear, "_backend", lambda _name, chosen=name: chosen)
        runs[name] = run_contact(block, law(), NORMAL, [Slide(1e-5, 30e-6, steps=5)])
    for key in ("tangential_force", "normal_force", "top_displacement"):
        a, b = getattr(runs["cholmod"], key), getattr(runs["superlu"], key)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-10 * np.abs(b).max())
    assert np.array_equal(runs["cholmod"].iterations, runs["superlu"].iterations)


def test_unknown_backend_is_refused_naming_the_key() -> None:
    disc = discretise(pmma_block(element_size=0.025))
    fixed = np.zeros(disc.n_dofs, dtype=bool)
    fixed[disc.dofs[0][disc.top_nodes]] = True
    with pytest.raises(ParameterError, match="backend"):
        TangentSolver(disc, fixed, law(), backend="mumps")
