"""Newton with the law's consistent tangent: quadratic convergence, and the linear
algebra behind it checked against independent assemblies."""

from __future__ import annotations

import itertools

import numpy as np
import scipy.sparse.linalg as spla
from tests.contact.support import NORMAL, SLIDE, law, pmma_block

from frictionlab.contact import SolverOptions, discretise, run_contact
from frictionlab.contact.interface import contact_stiffness
from frictionlab.contact.linear import TangentSolver


def _pairs(residuals: list[list[float]]) -> list[tuple[float, float]]:
    """Consecutive relative residuals (e_k, e_k+1) in the asymptotic range, above round-off."""
    out = []
    for res in residuals:
        for a, b in itertools.pairwise(res):
            if a < 1e-3 and b > 1e-13:
                out.append((a, b))
    return out


def test_newton_converges_quadratically_with_the_consistent_tangent() -> None:
    history = run_contact(pmma_block(), law(), NORMAL, SLIDE)
    assert history.success, history.message
    sliding = [r for r, s in zip(history.residuals, history.stage, strict=True) if s > 0]
    pairs = _pairs(sliding)
    assert len(pairs) >= 10
    # quadratic: e_{k+1} <= C e_k^2, with C of order one for these relative residuals
    ratios = np.array([b / a**2 for a, b in pairs])
    assert np.max(ratios) < 50.0, ratios
    # the order estimated from the steps with three iterates in the asymptotic range
    orders = [
        np.log(r[k + 2] / r[k + 1]) / np.log(r[k + 1] / r[k])
        for r in sliding
        for k in range(len(r) - 2)
        if r[k] < 1e-2 and r[k + 2] > 1e-13
    ]
    assert orders and np.median(orders) > 1.8, orders


def test_the_elastic_tangent_needs_many_more_iterations_and_converges_linearly() -> None:
    """The law's elastic moduli (a fixed secant-type stiffness) instead of its tangent."""
    tight = SolverOptions(tolerance=1e-8, max_iterations=60, max_cuts=0)
    consistent = run_contact(pmma_block(), law(), NORMAL, SLIDE, settings=tight)
    elastic = run_contact(
        pmma_block(),
        law(),
        NORMAL,
        SLIDE,
        settings=SolverOptions(tangent="elastic", tolerance=1e-8, max_iterations=60, max_cuts=0),
    )
    assert consistent.success, consistent.message
    rows = elastic.n_rows  # rows the elastic run completed
    sliding = consistent.stage[:rows] > 0
    it_c = int(consistent.iterations[:rows][sliding].sum())
    it_e = int(elastic.iterations[sliding].sum())
    if not elastic.success:  # the step it could not solve in 60 iterations counts 60
        it_c += int(consistent.iterations[rows])
        it_e += 60
    assert it_e > 3 * it_c, (it_e, it_c)
    np.testing.assert_allclose(
        elastic.tangential_force, consistent.tangential_force[:rows], rtol=1e-6, atol=1e-3
    )
    pairs = _pairs([r for r, s in zip(elastic.residuals, elastic.stage, strict=True) if s > 0])
    rates = np.array([b / a for a, b in pairs])
    assert rates.size and np.median(rates) > 1e-2, rates  # linear, not quadratic


def test_tangent_solver_equals_a_direct_solve_of_the_assembled_tangent() -> None:
    disc = discretise(pmma_block(element_size=0.00625, nu=0.3))
    params = law()
    rng = np.random.default_rng(11)
    fixed = np.zeros(disc.n_dofs, dtype=bool)
    fixed[disc.dof_x[disc.top_nodes]] = True
    solver = TangentSolver(disc, fixed, params)
    n = disc.n_points
    # a non-symmetric, partly open set of moduli (n, 2, 2), as in plastic sliding
    moduli = np.zeros((n, 2, 2))
    moduli[:, 0, 0] = rng.uniform(0.0, 5e11, n)
    moduli[:, 0, 1] = rng.uniform(-2e11, 2e11, n)
    moduli[:, 1, 1] = rng.uniform(0.0, 5e11, n)
    moduli[:3] = 0.0  # three open points
    b = rng.normal(size=int((~fixed).sum())) * 1e3
    J = (disc.stiffness + contact_stiffness(disc, moduli)).tocsc()[~fixed][:, ~fixed]
    expected = spla.spsolve(J, b)
    np.testing.assert_allclose(
        solver.solve(moduli, b), expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max()
    )


def test_contact_stiffness_is_the_penalty_times_the_facet_mass_matrix_of_scikit_fem() -> None:
    import skfem

    block = pmma_block(element_size=0.00625)
    disc = discretise(block)
    n = disc.n_points
    alpha = 3.0e11
    moduli = np.broadcast_to(alpha * np.eye(2), (n, 2, 2))
    Kc = contact_stiffness(disc, moduli)
    nx, ny = block.cells
    mesh = skfem.MeshQuad.init_tensor(np.linspace(0, 0.1, nx + 1), np.linspace(0, 0.025, ny + 1))
    element = skfem.ElementVector(skfem.ElementQuad1())
    fb = skfem.FacetBasis(mesh, element, facets=mesh.facets_satisfying(lambda x: x[1] < 1e-12))

    @skfem.BilinearForm
    def penalty(u, v, w):  # type: ignore[no-untyped-def]
        return alpha * (u[0] * v[0] + u[1] * v[1])

    expected = penalty.assemble(fb)
    assert abs(Kc - expected).max() <= 1e-9 * abs(expected).max()
