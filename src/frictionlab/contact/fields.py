"""Field output of a contact run per recorded load step (pure: arrays, no files).

For every row of a :class:`ContactHistory` recorded with ``record_displacement=True``:

* the block: nodal displacement [m] (3 components, z = 0 in 2-D) and the cell-mean
  Cauchy stress [Pa] (3 x 3, row-major; plane strain: sigma_zz = lambda tr(eps));
* the interface: at each contact point the traction on the block [Pa] (global x, y,
  z components), ``traction_n`` [Pa], ``R``, ``F``, the relative ``slip`` [m] (block
  displacement along x, y), ``plastic_slip`` [m] and ``status`` (0 stick, 1 slip,
  2 open, 3 failed).

:func:`frictionlab.io.mesh_files.write_field_series` writes them as .vtu + .pvd.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from frictionlab.contact._fem import require_skfem
from frictionlab.contact.history import ContactHistory
from frictionlab.contact.mesh import Discretisation
from frictionlab.errors import ParameterError

__all__ = ["FieldFrame", "field_frames"]

_MESHES = {"quad": "MeshQuad", "triangle": "MeshTri", "hex": "MeshHex"}
_ELEMENTS = {"quad": "ElementQuad1", "triangle": "ElementTriP1", "hex": "ElementHex1"}


@dataclass(frozen=True)
class FieldFrame:
    """One load step: the block and interface data (meshio meshes) at ``time`` [s]."""

    time: float
    block: object  #: meshio.Mesh of the block
    interface: object  #: meshio.Mesh of the contact points (vertex cells)


def field_frames(history: ContactHistory, disc: Discretisation) -> list[FieldFrame]:
    """Block and interface fields of every recorded row."""
    if history.nodal_displacement is None:
        raise ParameterError(
            "record_displacement", False, "True in run_contact to write field output"
        )
    skfem = require_skfem()
    import meshio
    from skfem.io.meshio import to_meshio

    block = disc.block
    mesh = getattr(skfem, _MESHES[block.element])(disc.nodes, disc.cells)
    element = skfem.ElementVector(getattr(skfem, _ELEMENTS[block.element])())
    basis = skfem.Basis(mesh, element, intorder=1)
    lam, mu = block.lame
    d = disc.dim
    n_nodes = disc.nodes.shape[1]
    xyz = np.zeros((disc.n_points, 3))
    xyz[:, : d - 1] = disc.contact_xy
    vertices = [("vertex", np.arange(disc.n_points)[:, None])]
    frames = []
    for k in range(history.n_rows):
        u = history.nodal_displacement[k]
        grad = np.asarray(basis.interpolate(u).grad).mean(axis=-1)  # (d, d, n_cells)
        eps = np.zeros((3, 3, grad.shape[-1]))
        eps[:d, :d] = 0.5 * (grad + grad.transpose(1, 0, 2))
        trace = np.trace(eps)
        sigma = 2.0 * mu * eps + lam * trace[None, None, :] * np.eye(3)[:, :, None]
        disp = np.zeros((n_nodes, 3))
        disp[:, :d] = u[disc.dofs.T]
        block_mesh = to_meshio(
            mesh,
            point_data={"displacement": disp},
            cell_data={"stress": [sigma.transpose(2, 0, 1).reshape(-1, 9)]},
            encode_cell_data=False,
        )
        traction = np.zeros((disc.n_points, 3))
        traction[:, 0] = history.traction_t[k]
        traction[:, 1] = history.traction_t_y[k] if d == 3 else -history.traction_n[k]
        if d == 3:
            traction[:, 2] = -history.traction_n[k]
        slip = np.column_stack([history.slip[k], history.slip_y[k], np.zeros(disc.n_points)])
        interface = meshio.Mesh(
            xyz,
            vertices,
            point_data={
                "traction": traction,
                "traction_n": history.traction_n[k],
                "R": history.R[k],
                "F": history.F[k],
                "slip": slip,
                "plastic_slip": history.plastic_slip[k],
                "status": history.status[k].astype(np.int32),
            },
        )
        frames.append(FieldFrame(float(history.time[k]), block_mesh, interface))
    return frames
