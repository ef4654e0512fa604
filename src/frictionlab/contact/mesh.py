"""Discretisation of the block with scikit-fem: stiffness, contact operator, loads.

The contact integral ``int_bottom N^T f dx`` is evaluated at the Gauss points of the
bottom facets (two per facet, scikit-fem ``FacetBasis``, exact for the cubic
integrands of bilinear elements). It is stored as a sparse interpolation operator
``B`` (values of the displacement at the contact points from the nodal vector) and the
quadrature weights ``w`` (length per point [m], per unit depth), so that the contact
forces are ``B^T (w f)`` and the contact stiffness ``B^T (w C) B`` with no re-assembly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from frictionlab.contact._fem import require_skfem
from frictionlab.contact.block import Block

__all__ = ["Discretisation", "discretise"]


@dataclass(frozen=True)
class Discretisation:
    """Everything the solver needs from the mesh (arrays read-only by convention).

    Attributes
    ----------
    block:
        The block it was built from.
    nodes:
        (2, n_nodes) node coordinates [m].
    cells:
        (k, n_cells) node indices of each cell (k = 4 quads, 3 triangles).
    stiffness:
        (n_dofs, n_dofs) CSR linear-elastic plane-strain stiffness [N/m per m depth].
    dof_x, dof_y:
        (n_nodes,) global dof index of u_x and u_y of each node.
    contact_x:
        (n_points,) x coordinate [m] of the contact (Gauss) points, increasing.
    contact_weight:
        (n_points,) quadrature weights [m] (per unit depth).
    interp_x, interp_y:
        (n_points, n_dofs) CSR: u_x and u_y at the contact points.
    top_nodes:
        Node indices on the top edge ``y = height``.
    unit_pressure, unit_shear:
        (n_dofs,) nodal loads of a uniform pressure of 1 Pa pushing the top down and of
        a uniform shear traction of 1 Pa along +x on the top [N/m].
    """

    block: Block
    nodes: np.ndarray
    cells: np.ndarray
    stiffness: sp.csr_matrix
    dof_x: np.ndarray
    dof_y: np.ndarray
    contact_x: np.ndarray
    contact_weight: np.ndarray
    interp_x: sp.csr_matrix
    interp_y: sp.csr_matrix
    top_nodes: np.ndarray
    unit_pressure: np.ndarray
    unit_shear: np.ndarray

    @property
    def n_dofs(self) -> int:
        """Number of displacement unknowns."""
        return int(self.stiffness.shape[0])

    @property
    def n_points(self) -> int:
        """Number of contact integration points."""
        return int(self.contact_x.shape[0])


def discretise(block: Block) -> Discretisation:
    """Mesh the block and assemble its elastic stiffness and contact operator."""
    skfem = require_skfem()
    from skfem.models.elasticity import linear_elasticity

    nx, ny = block.cells
    xs = np.linspace(0.0, block.width, nx + 1)
    ys = np.linspace(0.0, block.height, ny + 1)
    if block.element == "quad":
        mesh = skfem.MeshQuad.init_tensor(xs, ys)
        element = skfem.ElementVector(skfem.ElementQuad1())
    else:
        mesh = skfem.MeshTri.init_tensor(xs, ys)
        element = skfem.ElementVector(skfem.ElementTriP1())
    basis = skfem.Basis(mesh, element, intorder=2)
    lam, mu = block.lame
    stiffness = linear_elasticity(lam, mu).assemble(basis).tocsr()

    tol = 1e-9 * block.height
    bottom = mesh.facets_satisfying(lambda x: x[1] < tol)
    top = mesh.facets_satisfying(lambda x: x[1] > block.height - tol)
    fb = skfem.FacetBasis(mesh, element, facets=bottom, intorder=3)
    interp_x, interp_y, xq, weight = _contact_operator(fb, basis.N)

    ft = skfem.FacetBasis(mesh, element, facets=top, intorder=3)

    @skfem.LinearForm
    def pressure(v, w):
        return -v[1]

    @skfem.LinearForm
    def shear(v, w):
        return v[0]

    top_nodes = np.flatnonzero(mesh.p[1] > block.height - tol)
    return Discretisation(
        block=block,
        nodes=np.array(mesh.p, dtype=np.float64),
        cells=np.array(mesh.t),
        stiffness=stiffness,
        dof_x=np.array(basis.nodal_dofs[0]),
        dof_y=np.array(basis.nodal_dofs[1]),
        contact_x=xq,
        contact_weight=weight,
        interp_x=interp_x,
        interp_y=interp_y,
        top_nodes=top_nodes,
        unit_pressure=pressure.assemble(ft),
        unit_shear=shear.assemble(ft),
    )


def _contact_operator(
    fb: object, n_dofs: int
) -> tuple[sp.csr_matrix, sp.csr_matrix, np.ndarray, np.ndarray]:
    """Interpolation matrices to the facet Gauss points, sorted by x, and their weights."""
    dx = np.asarray(fb.dx)  # type: ignore[attr-defined]  # (n_facets, n_qp)
    xq = _values(fb.global_coordinates())[0]  # type: ignore[attr-defined]
    n_f, n_q = dx.shape
    order = np.argsort(xq.ravel(), kind="stable")
    row_of = np.empty(n_f * n_q, dtype=np.int64)
    row_of[order] = np.arange(n_f * n_q)
    rows = row_of.reshape(n_f, n_q)
    mats = []
    for comp in (0, 1):
        r, c, v = [], [], []
        for i, phi in enumerate(fb.basis):  # type: ignore[attr-defined]
            values = _values(phi[0])[comp]  # (n_facets, n_qp)
            dofs = np.asarray(fb.element_dofs[i])  # type: ignore[attr-defined]  # (n_facets,)
            keep = values != 0.0
            r.append(rows[keep])
            c.append(np.broadcast_to(dofs[:, None], values.shape)[keep])
            v.append(values[keep])
        mats.append(
            sp.csr_matrix(
                (np.concatenate(v), (np.concatenate(r), np.concatenate(c))),
                shape=(n_f * n_q, n_dofs),
            )
        )
    return mats[0], mats[1], xq.ravel()[order], dx.ravel()[order]


def _values(field: object) -> np.ndarray:
    """The values of a scikit-fem DiscreteField (an ndarray in recent versions)."""
    if isinstance(field, np.ndarray):
        return np.asarray(field)
    return np.asarray(field.value)  # type: ignore[attr-defined]  # scikit-fem < 10
