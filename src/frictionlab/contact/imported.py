"""A block from an FE user's own mesh (read by meshio): named groups pick its surfaces.

The mesh is one family of linear elements (quads or triangles in 2-D, hexahedra in
3-D; the z coordinate of a 2-D mesh is dropped). Three kinds of named groups (gmsh
physical groups, Abaqus element or node sets, meshio cell or point sets) select:

* ``contact`` — the face on the rigid base where the law acts: flat, at the lowest
  normal coordinate (y in 2-D, z in 3-D), like a block's bottom face;
* ``loaded`` — the faces that carry the normal load and the tangential programme
  (the "top" of the block: pressure, force through a rigid plate, shear or slide);
* ``fixed`` — faces or nodes held at zero displacement (any number of groups).

A group selects the mesh facets whose nodes all belong to it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from frictionlab.contact._fem import require_skfem
from frictionlab.contact.block import Block
from frictionlab.contact.mesh import Discretisation, assemble
from frictionlab.errors import ParameterError

__all__ = [
    "MESH_CELLS", "MeshSource", "discretise_mesh", "group_nodes", "mesh_block", "points_on_nodes",
]  # fmt: skip

#: meshio cell types of the volume elements, and the element family of each.
MESH_CELLS = {"quad": "quad", "triangle": "triangle", "hexahedron": "hex"}
_DIM = {"vertex": 0, "line": 1, "triangle": 2, "quad": 2, "tetra": 3, "hexahedron": 3}


def group_nodes(mesh: Any, name: str, key: str) -> np.ndarray:
    """Node indices of the named group ``name`` (the input ``key`` is named in errors)."""
    field_data = getattr(mesh, "field_data", {}) or {}
    physical = (getattr(mesh, "cell_data", {}) or {}).get("gmsh:physical")
    if name in field_data and physical is not None:
        tag, dim = (int(v) for v in np.asarray(field_data[name]).ravel()[:2])
        nodes = [
            block.data[np.asarray(tags) == tag].ravel()
            for block, tags in zip(mesh.cells, physical, strict=True)
            if _DIM.get(block.type, -1) == dim
        ]
        found = np.unique(np.concatenate(nodes)) if nodes else np.zeros(0, np.int64)
    elif name in (getattr(mesh, "cell_sets", {}) or {}):
        parts = [
            block.data[np.asarray(idx, dtype=np.int64)].ravel()
            for block, idx in zip(mesh.cells, mesh.cell_sets[name], strict=True)
            if idx is not None and len(idx)
        ]
        found = np.unique(np.concatenate(parts)) if parts else np.zeros(0, np.int64)
    elif name in (getattr(mesh, "point_sets", {}) or {}):
        found = np.unique(np.asarray(mesh.point_sets[name], dtype=np.int64))
    else:
        names = sorted(
            n
            for n in set(field_data)
            | set(getattr(mesh, "cell_sets", {}) or {})
            | set(getattr(mesh, "point_sets", {}) or {})
            if not n.startswith("gmsh:")  # meshio's own bookkeeping, not a user's group
        )
        listed = ", ".join(names) or "none"
        raise ParameterError(key, name, f"a named group of the mesh: {listed}")
    if found.size == 0:
        raise ParameterError(key, name, "a group with at least one node")
    return found


def _cell_dim(block: Any) -> int:
    """Topological dimension of a meshio cell block (0 for unknown types)."""
    return int(getattr(block, "dim", None) or _DIM.get(block.type, 0))


def _volume(mesh: Any) -> tuple[str, np.ndarray, np.ndarray]:
    """The element family, the volume cells' node indices and the nodes they use."""
    dims = [_cell_dim(b) for b in mesh.cells]
    top = max(dims, default=0)
    volume = [b for b, d in zip(mesh.cells, dims, strict=True) if d == top and top >= 2]
    types = {b.type for b in volume}
    if len(types) != 1 or not types <= set(MESH_CELLS):
        raise ParameterError(
            "mesh.file", "cells " + (", ".join(sorted(types)) or "none of 2 or 3 dimensions"),
            "one element family: quad or triangle (2-D), hexahedron (3-D)",
        )  # fmt: skip
    kind = MESH_CELLS[types.pop()]
    cells = np.concatenate([b.data for b in volume])
    return kind, cells, np.unique(cells)


def mesh_block(mesh: Any, *, E: float, nu: float, integration: str = "full") -> Block:
    """The :class:`Block` of an imported mesh: its material and bounding box
    (``element_size`` is the largest extent: the block is not meshed from it)."""
    kind, _, used = _volume(mesh)
    dim = 3 if kind == "hex" else 2
    points = np.asarray(mesh.points, dtype=np.float64)[used, :dim]
    extent = points.max(axis=0) - points.min(axis=0)
    if np.any(extent <= 0):
        raise ParameterError("mesh.file", "a degenerate mesh", f"a {dim}-D mesh with volume")
    return Block(
        E=E, nu=nu, width=float(extent[0]), height=float(extent[-1]),
        depth=float(extent[1]) if dim == 3 else None, element_size=float(extent.max()),
        element=kind, integration=integration,
    )  # fmt: skip


def discretise_mesh(
    mesh: Any,
    *,
    E: float,
    nu: float,
    contact: str,
    loaded: str,
    fixed: Sequence[str] = (),
    integration: str = "full",
) -> Discretisation:
    """Assemble an imported meshio mesh; its :class:`Block` is :func:`mesh_block`."""
    skfem = require_skfem()
    block = mesh_block(mesh, E=E, nu=nu, integration=integration)
    kind, cells, used = _volume(mesh)
    dim = block.dim
    points = np.asarray(mesh.points, dtype=np.float64)[:, :dim]
    lo = points[used].min(axis=0)
    # keep only the nodes of volume cells, renumbered, with the base at the origin
    index = np.full(points.shape[0], -1, dtype=np.int64)
    index[used] = np.arange(used.size)
    p = (points[used] - lo).T
    t = index[cells].T
    mesh_type = {"quad": skfem.MeshQuad, "triangle": skfem.MeshTri, "hex": skfem.MeshHex}[kind]
    if kind == "hex":
        import meshio
        from skfem.io.meshio import from_meshio  # the VTK -> scikit-fem hexahedron order

        sk = from_meshio(meshio.Mesh(p.T, [("hexahedron", t.T)]))
    else:
        sk = mesh_type(p, t)

    def facets_of(name: str, key: str) -> tuple[np.ndarray, np.ndarray]:
        nodes = index[group_nodes(mesh, name, key)]
        nodes = nodes[nodes >= 0]
        member = np.zeros(used.size, dtype=bool)
        member[nodes] = True
        facets = np.flatnonzero(np.all(member[sk.facets], axis=0))
        boundary = np.intersect1d(facets, sk.boundary_facets())
        if boundary.size == 0:
            raise ParameterError(key, name, "a group covering at least one boundary face")
        return boundary, nodes

    contact_facets, contact_nodes = facets_of(contact, "mesh.contact")
    normal = sk.p[dim - 1, contact_nodes]
    if np.ptp(normal) > 1e-9 * block.height or normal.min() > 1e-9 * block.height:
        raise ParameterError(
            "mesh.contact", contact, "a flat face at the lowest y (2-D) or z (3-D) of the mesh"
        )
    loaded_facets, _ = facets_of(loaded, "mesh.loaded")
    if np.intersect1d(loaded_facets, contact_facets).size:
        raise ParameterError("mesh.loaded", loaded, f"faces apart from the contact '{contact}'")
    held = [index[group_nodes(mesh, g, "mesh.fixed")] for g in fixed]
    held_nodes = np.unique(np.concatenate(held)) if held else np.zeros(0, np.int64)
    return assemble(sk, block, contact_facets, loaded_facets, held_nodes[held_nodes >= 0])


@dataclass(frozen=True)
class MeshSource:
    """An imported mesh and the names of its groups (``[mesh]`` of a contact scenario).

    ``mesh`` is the meshio.Mesh read from ``file``; ``nodes`` and ``contact_nodes`` count
    its volume nodes and those of the contact group (the size estimate before assembly).
    """

    file: str
    contact: str
    loaded: str
    fixed: tuple[str, ...] = ()
    mesh: Any = field(default=None, compare=False, repr=False)
    nodes: int = 0
    contact_nodes: int = 0

    @classmethod
    def of(cls, file: str, mesh: Any, contact: str, loaded: str,
           fixed: Sequence[str] = ()) -> MeshSource:  # fmt: skip
        """Check the cells and every named group of ``mesh`` (errors name the key)."""
        _, _, used = _volume(mesh)
        found = group_nodes(mesh, contact, "mesh.contact")
        group_nodes(mesh, loaded, "mesh.loaded")
        for name in fixed:
            group_nodes(mesh, name, "mesh.fixed")
        return cls(
            file, contact, loaded, tuple(fixed), mesh, int(used.size),
            int(np.intersect1d(found, used).size),
        )  # fmt: skip

    def discretise(self, block: Block) -> Discretisation:
        """Assemble the mesh with ``block``'s material (:func:`discretise_mesh`)."""
        return discretise_mesh(
            self.mesh, E=block.E, nu=block.nu, contact=self.contact, loaded=self.loaded,
            fixed=self.fixed, integration=block.integration,
        )  # fmt: skip

    def check_group(self, name: str) -> None:
        """Raise ParameterError (listing the groups present) unless ``name`` is a group."""
        group_nodes(self.mesh, name, "group")

    def points_in(self, name: str, disc: Discretisation) -> np.ndarray:
        """(P,) True at the contact points of ``disc`` (assembled from this mesh) whose facet
        has all its nodes in the group ``name``."""
        _, _, used = _volume(self.mesh)
        nodes = group_nodes(self.mesh, name, "law_region.group")
        nodes = np.searchsorted(used, nodes[np.isin(nodes, used)])  # the assembled numbering
        return points_on_nodes(disc, nodes)


def points_on_nodes(disc: Discretisation, nodes: np.ndarray) -> np.ndarray:
    """(P,) True at the contact points whose facet's nodes all belong to ``nodes``.

    A point's facet nodes are the columns of its row of ``disc.interp[0]`` (the x dofs
    whose shape functions are nonzero at the point: those of its facet; the shape functions
    of the other nodes of the element vanish there up to round-off)."""
    member = np.zeros(disc.nodes.shape[1], dtype=bool)
    member[np.asarray(nodes, dtype=np.int64)] = True
    node_of = np.full(disc.n_dofs, -1, dtype=np.int64)
    node_of[disc.dofs[0]] = np.arange(disc.nodes.shape[1])
    rows = disc.interp[0].tocoo()
    facet = np.abs(rows.data) > 1e-9  # round-off values of the nodes off the facet dropped
    outside = facet & ~member[node_of[rows.col]]
    inside = np.ones(disc.n_points, dtype=bool)
    inside[rows.row[outside]] = False
    return inside
