"""`frictionlab contact` on an imported mesh: the [mesh] keys, end to end and bad input."""

from __future__ import annotations

import json
from pathlib import Path

import meshio
import numpy as np
import pytest

from frictionlab.app.contact import discretise_scenario
from frictionlab.cli import main
from frictionlab.errors import ParameterError
from frictionlab.io.tables import read_csv
from frictionlab.schema.contact import load_contact

from .test_mesh_files import NX, NY, PRESSURE, _grid, _native

SCENARIO = """
[mesh]
file = "block.msh"
contact = "contact"
loaded = "top"

[block]
E = 3.0e9
nu = 0.3

[law]
alpha_n = 5.0e11
alpha_t = 5.0e11
mu_s = 0.6
mu_k = 0.4
u = 2.0e6
kappa = 0.0
xi = 0.05

[normal]
pressure = 1.0e6
steps = 2

[[program]]
kind = "slide"
velocity = 1.0e-5
distance = 3.0e-5
steps = 15
"""


def write_gmsh41(path: Path) -> Path:
    """A gmsh 4.1 file (meshio's writer) with physical groups contact, top and left."""
    points, quads, bottom, top = _grid()
    left = np.array([[j * (NX + 1), (j + 1) * (NX + 1)] for j in range(NY)])
    tags = [np.full(len(quads), 1), np.full(NX, 2), np.full(NX, 3), np.full(NY, 4)]
    # gmsh 4.1 lists nodes by entity: boundary nodes on their curve, the rest on the surface
    dim_tags = np.tile([2, 1], (len(points), 1))
    for tag, lines in ((4, left), (3, top), (2, bottom)):
        dim_tags[np.unique(lines)] = [1, tag]
    mesh = meshio.Mesh(
        points,
        [("quad", quads), ("line", bottom), ("line", top), ("line", left)],
        point_data={"gmsh:dim_tags": dim_tags},
        cell_data={"gmsh:physical": tags, "gmsh:geometrical": tags},
        field_data={"block": np.array([1, 2]), "contact": np.array([2, 1]),
                    "top": np.array([3, 1]), "left": np.array([4, 1])},
    )  # fmt: skip
    meshio.write(path, mesh, file_format="gmsh", binary=False)
    return path


def test_gmsh41_mesh_runs_through_the_cli(tmp_path: Path) -> None:
    path = write_gmsh41(tmp_path / "block.msh")
    assert path.read_text().startswith("$MeshFormat\n4.1")
    (tmp_path / "run.toml").write_text(SCENARIO)
    out = tmp_path / "out"
    assert main(["contact", str(tmp_path / "run.toml"), "--out", str(out), "--quiet",
                 "--no-plots"]) == 0  # fmt: skip
    g = read_csv(out / "global.csv")
    native = _native()  # the same grid meshed by [block]
    np.testing.assert_allclose(g["normal_force"][-1], PRESSURE * 0.1, rtol=1e-9)
    np.testing.assert_allclose(g["tangential_force"], native.tangential_force, rtol=1e-8, atol=1e-6)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["inputs"]["mesh"]["contact"] == "contact"
    assert summary["mesh"]["cells"] == [NX * NY] and summary["mesh"]["contact_points"] == 2 * NX


def test_fixed_groups_hold_their_nodes(tmp_path: Path) -> None:
    write_gmsh41(tmp_path / "block.msh")
    (tmp_path / "run.toml").write_text(SCENARIO)
    scenario = load_contact(tmp_path / "run.toml", ["mesh.fixed=['left']"])
    disc = discretise_scenario(scenario)
    left = np.flatnonzero(np.isclose(disc.nodes[0], 0.0))
    assert left.size == NY + 1
    np.testing.assert_array_equal(disc.fixed_dofs, np.sort(disc.dofs[:, left].ravel()))


def _tetra_inp(path: Path) -> None:
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    meshio.write(path, meshio.Mesh(points, [("tetra", np.array([[0, 1, 2, 3]]))],
                                   point_sets={"BASE": np.array([0, 1, 2])}),
                 file_format="abaqus")  # fmt: skip


@pytest.mark.parametrize(
    ("override", "message"),
    [
        ("mesh.file='none.msh'", r"\[mesh\].file = 'none.msh': mesh file not found"),
        ("mesh.contact='bottom'",
         r"\[mesh\].contact = 'bottom' is invalid: allowed a named group of the mesh: "
         r"block, contact, left, top$"),
        ("mesh.fixed=['left', 'right']", r"\[mesh\].fixed = 'right' is invalid"),
        ("mesh.file='tet.inp'", r"\[mesh\].file = 'cells tetra' is invalid: allowed one "
         r"element family"),
        ("block.width=0.1", r"\[block\].width is set by \[mesh\].file"),
        ("mesh.loaded='contact'", r"\[mesh\].loaded = 'contact' is invalid: allowed faces "
         r"apart from the contact"),
    ],
)  # fmt: skip
def test_bad_mesh_input_is_one_line_exit_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], override: str, message: str
) -> None:
    write_gmsh41(tmp_path / "block.msh")
    _tetra_inp(tmp_path / "tet.inp")
    (tmp_path / "run.toml").write_text(SCENARIO)
    out = tmp_path / "out"
    code = main(["contact", str(tmp_path / "run.toml"), "--out", str(out), "--quiet",
                 "--set", override])  # fmt: skip
    err = capsys.readouterr().err.strip()
    assert code == 2, err
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    import re

    assert re.search(message, err.removeprefix("frictionlab: error: ")), err
    assert not out.exists() or not any(out.iterdir())


def test_law_region_by_mesh_group(tmp_path: Path) -> None:
    """A region given by a node set of the contact face holds the points of its facets."""
    from frictionlab.app.contact import scenario_law

    points, quads, bottom, top = _grid()
    half = np.unique(bottom[: NX // 2])  # the nodes of the left half of the contact face
    mesh = meshio.Mesh(points[:, :2], [("quad", quads)], point_sets={
        "BASE": np.unique(bottom), "TOP": np.unique(top), "SOFT": half})  # fmt: skip
    meshio.write(tmp_path / "block.inp", mesh, file_format="abaqus")
    text = SCENARIO.replace("block.msh", "block.inp").replace('"contact"', '"BASE"')
    region = '\n[[law_region]]\ngroup = "SOFT"\nmu_s = 0.3\nmu_k = 0.3\n'
    text = text.replace('"top"', '"TOP"') + region
    (tmp_path / "run.toml").write_text(text)
    scenario = load_contact(tmp_path / "run.toml")
    disc = discretise_scenario(scenario)
    law = scenario_law(scenario, disc)
    x = disc.contact_xy[:, 0]
    np.testing.assert_array_equal(law.mu_s, np.where(x < 0.05, 0.3, 0.6))
    np.testing.assert_array_equal(law.mu_k, np.where(x < 0.05, 0.3, 0.4))
    with pytest.raises(ParameterError, match=r"#1.group = 'HARD' .* BASE, SOFT, TOP"):
        load_contact(tmp_path / "run.toml", ["law_region.1.group='HARD'"])
