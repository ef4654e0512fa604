"""Discretisation of the block with scikit-fem: stiffness, contact operator, loads.

The contact integral ``int_bottom N^T f dA`` is evaluated at the Gauss points of the
bottom facets (two per edge in 2-D, 2 x 2 per face in 3-D; scikit-fem ``FacetBasis``).
It is stored as sparse interpolation operators ``B_a`` (component ``a`` of the
displacement at the contact points from the nodal vector) and the quadrature weights
``w`` (length [m] per unit depth in 2-D, area [m^2] in 3-D), so that the contact forces
are ``sum_a B_a^T (w f_a)`` and the contact stiffness ``sum_ab B_a^T (w D_ab) B_b`` with
no re-assembly. The normal axis is the last one (y in 2-D, z in 3-D).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.sparse as sp

from frictionlab.contact._fem import require_skfem
from frictionlab.contact.block import Block

__all__ = ["Discretisation", "assemble", "discretise"]


@dataclass(frozen=True)
class Discretisation:
    """Everything the solver needs from the mesh (arrays read-only by convention).

    Attributes
    ----------
    block:
        The block it was built from.
    nodes:
        (d, n_nodes) node coordinates [m].
    cells:
        (k, n_cells) node indices of each cell (4 quads, 3 triangles, 8 hexahedra).
    stiffness:
        (n_dofs, n_dofs) CSR linear-elastic stiffness (plane strain in 2-D).
    dofs:
        (d, n_nodes) global dof index of each displacement component of each node.
    contact_xy:
        (n_points, d - 1) in-plane coordinates [m] of the contact (Gauss) points, sorted
        by x (then y).
    contact_weight:
        (n_points,) quadrature weights [m in 2-D (per unit depth), m^2 in 3-D].
    interp:
        d CSR matrices (n_points, n_dofs): displacement component a at the contact points.
    top_nodes:
        Node indices on the top face (the plane ``normal coordinate = height``).
    unit_pressure:
        (n_dofs,) nodal loads of a uniform pressure of 1 Pa pushing the top down.
    unit_shear:
        (d - 1, n_dofs) nodal loads of a uniform shear traction of 1 Pa on the top along
        x (and y in 3-D).
    fixed_dofs:
        Dofs held at zero (an imported mesh's fixed surfaces; none for a block).
    """

    block: Block
    nodes: np.ndarray
    cells: np.ndarray
    stiffness: sp.csr_matrix
    dofs: np.ndarray
    contact_xy: np.ndarray
    contact_weight: np.ndarray
    interp: tuple[sp.csr_matrix, ...]
    top_nodes: np.ndarray
    unit_pressure: np.ndarray
    unit_shear: np.ndarray
    fixed_dofs: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    @property
    def dim(self) -> int:
        """2 or 3."""
        return int(self.nodes.shape[0])

    @property
    def n_dofs(self) -> int:
        """Number of displacement unknowns."""
        return int(self.stiffness.shape[0])

    @property
    def n_points(self) -> int:
        """Number of contact integration points."""
        return int(self.contact_weight.shape[0])

    @property
    def contact_x(self) -> np.ndarray:
        """(n_points,) x coordinates [m] of the contact points."""
        return self.contact_xy[:, 0]

    @property
    def dof_x(self) -> np.ndarray:
        """(n_nodes,) dof of u_x of each node."""
        return self.dofs[0]

    @property
    def dof_y(self) -> np.ndarray:
        """(n_nodes,) dof of u_y of each node (the normal component in 2-D)."""
        return self.dofs[1]

    @property
    def interp_x(self) -> sp.csr_matrix:
        """u_x at the contact points."""
        return self.interp[0]

    @property
    def interp_y(self) -> sp.csr_matrix:
        """u_y at the contact points (the normal component in 2-D)."""
        return self.interp[1]


def discretise(block: Block) -> Discretisation:
    """Mesh the block and assemble its elastic stiffness and contact operator."""
    skfem = require_skfem()
    axes = block.axes()
    if block.element == "quad":
        mesh = skfem.MeshQuad.init_tensor(*axes)
    elif block.element == "triangle":
        mesh = skfem.MeshTri.init_tensor(*axes)
    else:
        mesh = skfem.MeshHex.init_tensor(*axes)
    normal = block.dim - 1
    tol = 1e-9 * block.height
    bottom = mesh.facets_satisfying(lambda x: x[normal] < tol)
    top = mesh.facets_satisfying(lambda x: x[normal] > block.height - tol)
    return assemble(mesh, block, bottom, top)


#: scikit-fem element of each element family.
_ELEMENTS = {"quad": "ElementQuad1", "triangle": "ElementTriP1", "hex": "ElementHex1"}


def assemble(
    mesh: Any,
    block: Block,
    contact_facets: np.ndarray,
    loaded_facets: np.ndarray,
    fixed_nodes: np.ndarray | None = None,
) -> Discretisation:
    """Assemble a scikit-fem ``mesh`` of ``block``'s material: the law on
    ``contact_facets`` (a flat face at the lowest normal coordinate), the top loads on
    ``loaded_facets``, every dof of ``fixed_nodes`` held at zero."""
    skfem = require_skfem()
    d = block.dim
    element = skfem.ElementVector(getattr(skfem, _ELEMENTS[block.element])())
    basis = skfem.Basis(mesh, element, intorder=2)
    stiffness = elastic_stiffness(skfem, mesh, element, basis, block)
    normal = d - 1
    fb = skfem.FacetBasis(mesh, element, facets=contact_facets, intorder=3)
    interp, xy, weight = _contact_operator(fb, basis.N, d)
    ft = skfem.FacetBasis(mesh, element, facets=loaded_facets, intorder=3)

    @skfem.LinearForm
    def pressure(v, w):
        return -v[normal]

    shears = []
    for a in range(d - 1):

        @skfem.LinearForm
        def shear(v, w, a=a):
            return v[a]

        shears.append(shear.assemble(ft))

    top_nodes = np.unique(mesh.facets[:, loaded_facets])
    fixed = np.zeros(0, np.int64) if fixed_nodes is None else np.asarray(fixed_nodes, np.int64)
    dofs = np.array(basis.nodal_dofs)
    return Discretisation(
        block=block,
        nodes=np.array(mesh.p, dtype=np.float64),
        cells=np.array(mesh.t),
        stiffness=stiffness,
        dofs=dofs,
        contact_xy=xy,
        contact_weight=weight,
        interp=interp,
        top_nodes=top_nodes,
        unit_pressure=pressure.assemble(ft),
        unit_shear=np.array(shears),
        fixed_dofs=np.sort(dofs[:, fixed].ravel()),
    )


def elastic_stiffness(
    skfem: Any, mesh: Any, element: Any, basis: Any, block: Block
) -> sp.csr_matrix:
    """Linear-elastic stiffness; with selective integration the volumetric part
    ``lambda div u div v`` takes one Gauss point per cell (no volumetric locking)."""
    from skfem.helpers import ddot, div, sym_grad
    from skfem.models.elasticity import linear_elasticity

    lam, mu = block.lame
    if block.integration == "full":
        return linear_elasticity(lam, mu).assemble(basis).tocsr()

    @skfem.BilinearForm
    def shear(u, v, w):
        return 2.0 * mu * ddot(sym_grad(u), sym_grad(v))

    @skfem.BilinearForm
    def volume(u, v, w):
        return lam * div(u) * div(v)

    reduced = skfem.Basis(mesh, element, intorder=1)
    return (shear.assemble(basis) + volume.assemble(reduced)).tocsr()


def _contact_operator(
    fb: object, n_dofs: int, dim: int
) -> tuple[tuple[sp.csr_matrix, ...], np.ndarray, np.ndarray]:
    """Interpolation matrices to the facet Gauss points, sorted by (x, y), and weights."""
    dx = np.asarray(fb.dx)  # type: ignore[attr-defined]  # (n_facets, n_qp)
    coords = _values(fb.global_coordinates())  # type: ignore[attr-defined]  # (d, nf, nq)
    n_f, n_q = dx.shape
    xy = coords[: dim - 1].reshape(dim - 1, -1)
    order = np.lexsort(xy[::-1])  # by x, then y
    row_of = np.empty(n_f * n_q, dtype=np.int64)
    row_of[order] = np.arange(n_f * n_q)
    rows = row_of.reshape(n_f, n_q)
    mats = []
    for comp in range(dim):
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
    return tuple(mats), np.ascontiguousarray(xy[:, order].T), dx.ravel()[order]


def _values(field: object) -> np.ndarray:
    """The values of a scikit-fem DiscreteField (an ndarray in recent versions)."""
    if isinstance(field, np.ndarray):
        return np.asarray(field)
    return np.asarray(field.value)  # type: ignore[attr-defined]  # scikit-fem < 10
