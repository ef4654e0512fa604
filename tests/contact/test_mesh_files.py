"""Meshes in (gmsh .msh, Abaqus .inp through meshio) and fields out (.vtu + .pvd)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import meshio
import numpy as np
import pytest

from frictionlab.contact import Block, NormalLoad, Slide, run_contact
from frictionlab.contact.fields import field_frames
from frictionlab.contact.imported import discretise_mesh
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.mesh_files import read_mesh, write_field_series

from .support import law

E, NU, W, H, NX, NY = 3.0e9, 0.3, 0.1, 0.025, 8, 2
PRESSURE = 1.0e6
NORMAL = NormalLoad(pressure=PRESSURE, steps=2)
PROGRAM = [Slide(velocity=1e-5, distance=30e-6, steps=15)]


def _grid() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Nodes, quads (counter-clockwise), bottom and top lines of a NX x NY block."""
    x, y = np.meshgrid(np.linspace(0, W, NX + 1), np.linspace(0, H, NY + 1))
    points = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])

    def node(i: int, j: int) -> int:
        return j * (NX + 1) + i

    quads = np.array(
        [[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
         for j in range(NY) for i in range(NX)]
    )  # fmt: skip
    bottom = np.array([[node(i, 0), node(i + 1, 0)] for i in range(NX)])
    top = np.array([[node(i, NY), node(i + 1, NY)] for i in range(NX)])
    return points, quads, bottom, top


def write_gmsh(path: Path) -> Path:
    """A gmsh 2.2 file with physical groups block (2-D), contact and top (1-D)."""
    points, quads, bottom, top = _grid()
    tags = [np.full(len(quads), 1), np.full(NX, 2), np.full(NX, 3)]
    mesh = meshio.Mesh(
        points,
        [("quad", quads), ("line", bottom), ("line", top)],
        cell_data={"gmsh:physical": tags, "gmsh:geometrical": tags},
        field_data={
            "block": np.array([1, 2]),
            "contact": np.array([2, 1]),
            "top": np.array([3, 1]),
        },
    )
    meshio.write(path, mesh, file_format="gmsh22", binary=False)
    return path


def _native():  # type: ignore[no-untyped-def]
    block = Block(E=E, nu=NU, width=W, height=H, element_size=W / NX)
    return run_contact(block, law(kappa=0.0), NORMAL, PROGRAM)


def test_gmsh_mesh_imported_and_run(tmp_path: Path) -> None:
    path = write_gmsh(tmp_path / "block.msh")
    text = path.read_text()
    assert "$PhysicalNames" in text and '"contact"' in text
    disc = discretise_mesh(read_mesh(path), E=E, nu=NU, contact="contact", loaded="top")
    assert disc.n_points == 2 * NX and disc.nodes.shape == (2, (NX + 1) * (NY + 1))
    imported = run_contact(disc.block, law(kappa=0.0), NORMAL, PROGRAM, discretisation=disc)
    native = _native()
    assert imported.success and native.success
    np.testing.assert_allclose(imported.normal_force[-1], PRESSURE * W, rtol=1e-9)
    np.testing.assert_allclose(
        imported.tangential_force, native.tangential_force, rtol=1e-8, atol=1e-6
    )
    np.testing.assert_allclose(imported.traction_n, native.traction_n, rtol=1e-8, atol=1e-3)


def test_abaqus_node_sets_select_the_surfaces(tmp_path: Path) -> None:
    points, quads, bottom, top = _grid()
    mesh = meshio.Mesh(
        points[:, :2],
        [("quad", quads)],
        point_sets={"BASE": np.unique(bottom), "TOP": np.unique(top)},
    )
    path = tmp_path / "block.inp"
    meshio.write(path, mesh, file_format="abaqus")
    disc = discretise_mesh(read_mesh(path), E=E, nu=NU, contact="BASE", loaded="TOP")
    imported = run_contact(disc.block, law(kappa=0.0), NORMAL, PROGRAM, discretisation=disc)
    np.testing.assert_allclose(
        imported.tangential_force, _native().tangential_force, rtol=1e-8, atol=1e-6
    )


def test_missing_group_and_bad_file_are_one_line(tmp_path: Path) -> None:
    mesh = read_mesh(write_gmsh(tmp_path / "block.msh"))
    with pytest.raises(ParameterError, match=r"mesh\.contact.*bottom.*contact, top"):
        discretise_mesh(mesh, E=E, nu=NU, contact="bottom", loaded="top")
    with pytest.raises(ParameterError, match=r"mesh\.contact.*flat face"):
        discretise_mesh(mesh, E=E, nu=NU, contact="top", loaded="contact")
    bad = tmp_path / "bad.msh"
    bad.write_text("$MeshFormat\nnot a mesh\n")
    with pytest.raises(InputError, match="cannot read the mesh file") as info:
        read_mesh(bad)
    assert "\n" not in str(info.value)


def test_vtu_series_reads_back_with_equilibrium(tmp_path: Path) -> None:
    """The written fields satisfy the block's equilibrium identities, read back by
    meshio: with the virtual displacements v = y e_y and v = y e_x (in the FE space),
    int sigma_yy dV = -p W H and int sigma_xy dV = Q H (top load times the height), so
    the volume means are -p and Q/W; the interface tractions integrate to P."""
    block = Block(E=E, nu=NU, width=W, height=H, element_size=W / NX)
    history = run_contact(block, law(kappa=0.0), NORMAL, PROGRAM, record_displacement=True)
    from frictionlab.contact import discretise

    frames = field_frames(history, discretise(block))
    pvd = write_field_series(tmp_path, "block", [(f.time, f.block) for f in frames])
    write_field_series(tmp_path, "interface", [(f.time, f.interface) for f in frames])
    entries = ET.parse(pvd).getroot().findall("./Collection/DataSet")
    assert len(entries) == history.n_rows
    assert [float(e.get("timestep", "nan")) for e in entries] == pytest.approx(history.time)
    last = meshio.read(tmp_path / entries[-1].get("file", ""))
    stress = last.cell_data["stress"][0].reshape(-1, 3, 3)
    area = W / NX * H / NY  # uniform cells
    mean = stress.sum(axis=0) * area / (W * H)
    assert mean[1, 1] == pytest.approx(-PRESSURE, rel=1e-6)
    assert mean[0, 1] == pytest.approx(history.tangential_force[-1] / W, rel=1e-6)
    u = last.point_data["displacement"]
    assert u.shape == (history.nodes.shape[1], 3)
    assert np.all(u[:, 2] == 0.0)
    face = meshio.read(tmp_path / "interface_0001.vtu")
    P = np.sum(history.weight * face.point_data["traction_n"])
    assert np.isclose(P, history.normal_force[1], rtol=1e-12)
    assert set(np.unique(face.point_data["status"])) <= {0, 1, 2, 3}
