"""With mu_s = mu_k, no softening or recovery and a large u, the subloading law becomes
a rigid-plastic Coulomb law with penalty elasticity: the block's response approaches a
plain penalty-Coulomb finite-element solution written here from scratch (scikit-fem
forms, its own return map, Newton and sparse solve; no frictionlab contact code)."""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla
import skfem
from skfem.models.elasticity import lame_parameters, linear_elasticity

from frictionlab.contact import Block, NormalLoad, Slide, run_contact
from frictionlab.subloading import SubloadingParams

E, NU, W, H, SIZE = 3.0e9, 0.3, 0.1, 0.025, 0.00625
ALPHA, MU, P = 5e11, 0.5, 1.0e6
SLIDE_DISTANCE, SLIDE_STEPS, NORMAL_STEPS = 40e-6, 10, 2


def coulomb_fe() -> tuple[np.ndarray, np.ndarray]:
    """Top displacement and tangential force Q = -int f_x (per unit depth) per slide step."""
    mesh = skfem.MeshQuad.init_tensor(
        np.linspace(0, W, round(W / SIZE) + 1), np.linspace(0, H, round(H / SIZE) + 1)
    )
    element = skfem.ElementVector(skfem.ElementQuad1())
    basis = skfem.Basis(mesh, element)
    K = linear_elasticity(*lame_parameters(E, NU)).assemble(basis)
    # two Gauss points per facet, the rule of frictionlab.contact (the comparison is of
    # the friction law, not of the quadrature)
    bottom = skfem.FacetBasis(
        mesh, element, facets=mesh.facets_satisfying(lambda x: x[1] < 1e-12), intorder=3
    )
    top = skfem.FacetBasis(mesh, element, facets=mesh.facets_satisfying(lambda x: x[1] > H - 1e-12))

    @skfem.LinearForm
    def pressure(v, w):
        return -v[1]

    @skfem.LinearForm
    def contact_force(v, w):
        return w["fx"] * v[0] + w["fy"] * v[1]

    @skfem.BilinearForm
    def contact_tangent(u, v, w):  # -d(force)/du
        return (w["kxx"] * u[0] + w["kxy"] * u[1]) * v[0] + w["kyy"] * u[1] * v[1]

    f_p = pressure.assemble(top)
    top_x = basis.get_dofs(lambda x: x[1] > H - 1e-12).nodal["u^1"]
    fixed = np.zeros(basis.N, dtype=bool)
    fixed[top_x] = True
    free = ~fixed

    def traction(u, t_old, s_old):
        uq = np.asarray(bottom.interpolate(u))
        slip, gap = -uq[0], -uq[1]  # base relative to block; approach
        fn = ALPHA * np.maximum(gap, 0.0)
        t_tr = t_old + ALPHA * (slip - s_old)
        stick = np.abs(t_tr) <= MU * fn
        t = np.where(stick, t_tr, MU * fn * np.sign(t_tr))
        closed = gap >= 0.0
        kxx = np.where(stick, ALPHA, 0.0)  # -(d f_x/d u_x): f_x = t, slip = -u_x
        kxy = np.where(stick | ~closed, 0.0, MU * np.sign(t_tr) * ALPHA)
        kyy = np.where(closed, ALPHA, 0.0)
        return t, fn, slip, (kxx, kxy, kyy)

    u = np.zeros(basis.N)
    t_old = np.zeros(bottom.dx.shape)
    s_old = np.zeros(bottom.dx.shape)
    loads = [(P * (k + 1) / NORMAL_STEPS, 0.0) for k in range(NORMAL_STEPS)]
    loads += [(P, SLIDE_DISTANCE * (k + 1) / SLIDE_STEPS) for k in range(SLIDE_STEPS)]
    tops, forces = [], []
    for p, ux in loads:
        u[top_x] = ux
        for _ in range(50):
            t, fn, slip, (kxx, kxy, kyy) = traction(u, t_old, s_old)
            r = K @ u - p * f_p - contact_force.assemble(bottom, fx=t, fy=fn)
            if np.linalg.norm(r[free]) <= 1e-11 * P * W:
                break
            J = K + contact_tangent.assemble(bottom, kxx=kxx, kxy=kxy, kyy=kyy)
            u[free] += spla.spsolve(J.tocsc()[free][:, free], -r[free])
        else:
            raise AssertionError("the reference Coulomb Newton did not converge")
        t_old, s_old = t, slip
        if ux > 0:
            tops.append(ux)
            forces.append(-float(np.sum(t * bottom.dx)))
    return np.array(tops), np.array(forces)


def subloading(u_const: float) -> tuple[np.ndarray, np.ndarray]:
    params = SubloadingParams(
        alpha_n=ALPHA, alpha_t=ALPHA, mu_s=MU, mu_k=MU, u=u_const, kappa=0.0, xi=0.0
    )
    block = Block(E=E, nu=NU, width=W, height=H, element_size=SIZE)
    history = run_contact(
        block,
        params,
        NormalLoad(pressure=P, steps=NORMAL_STEPS),
        [Slide(velocity=1e-5, distance=SLIDE_DISTANCE, steps=SLIDE_STEPS)],
    )
    assert history.success, history.message
    assert np.all(history.cuts == 0)
    rows = history.stage > 0
    return history.top_displacement[rows], history.tangential_force[rows]


def test_large_u_approaches_a_plain_penalty_coulomb_solution() -> None:
    x_ref, q_ref = coulomb_fe()
    # the reference slides: the friction saturates at mu P W (within the load steps)
    assert abs(q_ref[-1] - MU * P * W) < 1e-6 * MU * P * W
    errors = []
    for u_const in (1e7, 1e8, 1e9):
        x, q = subloading(u_const)
        np.testing.assert_allclose(x, x_ref, rtol=1e-12)
        errors.append(np.max(np.abs(q - q_ref)) / (MU * P * W))
    # the sub-yield plastic slip scales as 1/u, and so does the difference
    assert errors[1] < 0.2 * errors[0] and errors[2] < 0.2 * errors[1], errors
    assert errors[2] < 2e-4, errors
