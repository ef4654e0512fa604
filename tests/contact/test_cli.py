"""`frictionlab contact`: end to end, bad input (one line, exit 2), failure (exit 1)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main
from frictionlab.demo.contact import bundled_contact_scenario
from frictionlab.io.tables import read_csv

SMALL = [
    "--set", "block.element_size=0.0125",
    "--set", "program.1.steps=10", "--set", "program.3.steps=5",
]  # fmt: skip


def test_bundled_example_end_to_end(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], check_summary
) -> None:
    out = tmp_path / "run"
    with bundled_contact_scenario("pmma_block") as path:
        assert main(["contact", str(path), "--out", str(out), "--quiet", *SMALL]) == 0
    names = {p.name for p in out.iterdir()}
    assert names == {"global.csv", "interface.csv", "summary.json", "friction.png",
                     "interface_map.png", "deformed_mesh.png"}  # fmt: skip
    summary = check_summary(out / "summary.json")  # against docs/schemas/summary.schema.json
    assert summary["success"] is True
    assert summary["provenance"]["inputs"][0]["path"] == str(path)
    assert summary["inputs"]["block"]["element_size"] == 0.0125
    assert summary["inputs"]["solver"]["tangent"] == "consistent"  # defaults echoed
    g = read_csv(out / "global.csv")
    assert g.units["tangential_force"] == "N/m"
    # equilibrium: the interface carries the applied pressure times the width
    sliding = g["stage"] > 0
    np.testing.assert_allclose(g["normal_force"][sliding], 1.0e6 * 0.1, rtol=1e-8)
    # the friction ratio is the ratio of the two force columns
    np.testing.assert_allclose(
        g["friction_ratio"][sliding], g["tangential_force"][sliding] / g["normal_force"][sliding]
    )
    peak = float(np.max(g["friction_ratio"]))
    assert 0.4 < peak <= 0.6  # between mu_k and mu_s
    i = read_csv(out / "interface.csv")
    n_points = 2 * 8  # 8 bottom facets, 2 Gauss points each
    assert len(i["x"]) == len(g["time"]) * n_points
    assert set(np.unique(i["status"])) <= {"stick", "slip", "open"}
    assert summary["results"]["peak_friction_ratio"] == pytest.approx(peak)
    assert len(summary["solver"]["iterations_per_step"]) == len(g["time"])


@pytest.mark.parametrize(
    ("override", "key"),
    [
        ("block.nu=0.5", "[block].nu"),
        ("block.E=-3e9", "[block].E"),
        ("block.element='hex'", "[block].element"),
        ("normal.pressure=-1.0", "[normal].pressure"),
        ("law.mu_k=0.7", "[law].mu_k"),
        ("law.alpha_t=1e6", "alpha_t"),
        ("program.1.velocity=0", "velocity"),
        ("program.2.kind='jump'", "[[program]] #2.kind"),
        ("solver.tangent='secant'", "[solver].tangent"),
        ("solver.tolerance=0.5", "[solver].tolerance"),
        ("block.size=1", "[block].size"),
        ("normal.force=1e5", "not pressure and force"),
        ("block.integration='reduced'", "[block].integration"),
        ("block.refinement.size=1e-3", "refinement.extent"),
        ("base.center=[0.05, 0.0]", "[base].center"),
        ("base.shape='cylinder'", "[base].radius"),
        ("solver.linear_solver='cg'", "[solver].linear_solver"),
        ("solver.memory_limit=1e3", "[block].element_size"),
        ("output.fields=1", "[output].fields"),
        ("law.mu_s=0", "mu_s (= 0.0)"),
        ("law.mu_k=0", "[law].mu_k"),
    ],
)
def test_bad_input_is_one_line_naming_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], override: str, key: str
) -> None:
    out = tmp_path / "run"
    with bundled_contact_scenario("pmma_block") as path:
        code = main(["contact", str(path), "--out", str(out), "--quiet", "--set", override])
    err = capsys.readouterr().err.strip()
    assert code == 2, err
    assert len(err.splitlines()) == 1 and key in err and "Traceback" not in err, err
    assert not out.exists()  # nothing written


def test_mixed_controls_and_reverse_first_are_rejected(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    base = tmp_path / "s.toml"
    with bundled_contact_scenario("pmma_block") as path:
        text = path.read_text()
    base.write_text(text + '\n[[program]]\nkind = "traction"\ntarget = 1e5\nduration = 1.0\n')
    assert main(["contact", str(base), "--out", str(tmp_path / "a"), "--quiet"]) == 2
    assert "one kind of tangential control" in capsys.readouterr().err
    head = text.split("[[program]]")[0]
    base.write_text(head + '[[program]]\nkind = "reverse"\n')
    assert main(["contact", str(base), "--out", str(tmp_path / "b"), "--quiet"]) == 2
    assert "reverse after at least one slide" in capsys.readouterr().err


def test_a_step_newton_cannot_solve_exits_1_and_keeps_the_rows(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Force control past the peak: the interface cannot carry the target, no step solves."""
    scenario = tmp_path / "force.toml"
    with bundled_contact_scenario("pmma_block") as path:
        head = path.read_text().split("[[program]]")[0]
    scenario.write_text(
        head + '[[program]]\nkind = "traction"\ntarget = 8.0e5\nduration = 1.0\nsteps = 8\n'
        "\n[solver]\nmax_cuts = 3\nmax_iterations = 15\n"
    )
    out = tmp_path / "run"
    code = main(["contact", str(scenario), "--out", str(out), "--quiet",
                 "--set", "block.element_size=0.0125"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 1, err
    assert "computation failed" in err and "Newton failed" in err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["success"] is False
    g = read_csv(out / "global.csv")
    assert len(g["time"]) > 3  # the normal phase and the steps before the failure kept
    # below the failure the applied shear was carried: mean top shear * width = Q
    rows = g["stage"] > 0
    np.testing.assert_allclose(
        g["tangential_force"][rows], g["top_shear"][rows] * 0.1, rtol=1e-6, atol=1e-3
    )


def test_a_3d_block_end_to_end_with_a_turning_traction(tmp_path: Path) -> None:
    scenario = tmp_path / "block3d.toml"
    scenario.write_text(
        "[block]\nE = 3.0e9\nnu = 0.35\nwidth = 0.02\ndepth = 0.02\nheight = 0.01\n"
        "element_size = 0.005\n"
        "[law]\nmu_s = 0.5\nmu_k = 0.5\nalpha_n = 5e11\nalpha_t = 5e11\nu = 1e7\n"
        "kappa = 0.0\nxi = 0.0\northotropy = [1.0, 0.6]\n"
        "[normal]\npressure = 1e6\nsteps = 2\n"
        '[[program]]\nkind = "slide"\nvelocity = 1e-5\ndistance = 20e-6\n'
        "direction_deg = 45.0\nsteps = 10\n"
    )
    out = tmp_path / "run"
    assert main(["contact", str(scenario), "--out", str(out), "--quiet"]) == 0
    assert (out / "traction_path.png").is_file() and not (out / "deformed_mesh.png").exists()
    g = read_csv(out / "global.csv")
    assert g.units["tangential_force"] == "N" and "tangential_force_y" in g
    rows = g["stage"] > 0
    angle = np.degrees(np.arctan2(g["tangential_force_y"][rows], g["tangential_force"][rows]))
    assert angle[0] > 44.0 and angle[-1] < 30.0  # turned away from the 45 deg slide
    np.testing.assert_allclose(g["normal_force"][rows], 1e6 * 0.02 * 0.02, rtol=1e-8)
    i = read_csv(out / "interface.csv")
    assert {"y", "slip_y", "traction_t_y"} <= set(i)


def test_an_oblique_slide_of_a_2d_block_is_bad_input(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    with bundled_contact_scenario("pmma_block") as path:
        code = main(["contact", str(path), "--out", str(tmp_path / "r"), "--quiet",
                     "--set", "program.1.direction_deg=30.0"])  # fmt: skip
    err = capsys.readouterr().err.strip()
    assert code == 2 and "direction_deg" in err and len(err.splitlines()) == 1, err


def test_without_scikit_fem_the_command_says_how_to_install_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    import sys

    import frictionlab

    monkeypatch.setitem(sys.modules, "skfem", None)  # import skfem -> ImportError
    assert frictionlab.__version__  # the package itself does not need it
    with bundled_contact_scenario("pmma_block") as path:
        code = main(["contact", str(path), "--out", str(tmp_path / "r"), "--quiet"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and "scikit-fem" in err and "pip install" in err, err
    assert len(err.splitlines()) == 1


def test_summary_records_the_newton_residuals_of_every_step(tmp_path: Path) -> None:
    out = tmp_path / "run"
    with bundled_contact_scenario("pmma_block") as path:
        assert main(["contact", str(path), "--out", str(out), "--quiet", "--no-plots", *SMALL]) == 0
    solver = json.loads((out / "summary.json").read_text())["solver"]
    residuals = solver["relative_residuals_per_step"]
    assert len(residuals) == len(solver["iterations_per_step"])
    for its, res in zip(solver["iterations_per_step"][1:], residuals[1:], strict=True):
        assert len(res) == its + 1 and res[-1] <= 1e-10  # one per iterate, the last converged


@pytest.mark.slow
def test_bundled_cylinder_partial_slip_runs(tmp_path: Path) -> None:
    """The bundled Cattaneo-Mindlin example: exit 0, P = the given force, Q/(mu P) = 0.9
    at the end, today's column names, one interface row per point per global row."""
    out = tmp_path / "out"
    with bundled_contact_scenario("cylinder_partial_slip") as scenario:
        assert main(["contact", str(scenario), "--out", str(out), "--no-plots", "--quiet"]) == 0
    g = read_csv(out / "global.csv")
    normal, friction = g["normal_force"][-1], g["tangential_force"][-1]
    assert normal == pytest.approx(20671.0, rel=1e-9)
    assert friction / (0.5 * normal) == pytest.approx(0.9, rel=1e-4)  # the file rounds
    i = read_csv(out / "interface.csv")
    assert {"row", "x", "traction_n", "R", "status"} <= set(i.columns)
    assert len(i["row"]) == len(g["time"]) * int(np.sum(i["row"] == 0))


def test_output_fields_write_a_paraview_series(tmp_path: Path) -> None:
    """[output] fields = true writes fields/block.pvd, fields/interface.pvd and one .vtu
    per recorded row, readable by meshio, with the interface tractions summing to P."""
    meshio = pytest.importorskip("meshio")
    with bundled_contact_scenario("pmma_block") as path:
        text = path.read_text()
    scenario = tmp_path / "fields.toml"
    scenario.write_text(text + "\n[output]\nfields = true\n")
    out = tmp_path / "out"
    args = ["contact", str(scenario), "--out", str(out), "--no-plots", "--quiet",
            "--set", "block.element_size=0.0125", "--set", "program.1.steps=5"]  # fmt: skip
    assert main([*args, "--set", "program.3.steps=5"]) == 0
    g = read_csv(out / "global.csv")
    assert (out / "fields" / "block.pvd").is_file()
    last = len(g["time"]) - 1
    face = meshio.read(out / "fields" / f"interface_{last:04d}.vtu")
    block = meshio.read(out / "fields" / f"block_{last:04d}.vtu")
    assert block.point_data["displacement"].shape[1] == 3
    assert "stress" in block.cell_data
    weights = np.full(face.points.shape[0], 0.1 / face.points.shape[0])  # uniform Gauss weights
    assert np.sum(weights * face.point_data["traction_n"]) == pytest.approx(
        g["normal_force"][-1], rel=1e-9
    )


def test_mu_zero_is_the_frictionless_interface(tmp_path: Path) -> None:
    """[law] mu_s = mu_k = 0: no tangential force while the block slides (Q = 0 exactly),
    the interface carries the pressure times the width; other law keys are refused."""
    with bundled_contact_scenario("pmma_block") as path:
        text = path.read_text()
    head, rest = text.split("[law]")
    law = "[law]\nalpha_n = 5.0e11\nmu_s = 0.0\nmu_k = 0.0\n\n"
    scenario = tmp_path / "frictionless.toml"
    scenario.write_text(head + law + "[normal]" + rest.split("[normal]")[1])
    out = tmp_path / "run"
    code = main(["contact", str(scenario), "--out", str(out), "--quiet", "--no-plots",
                 "--set", "block.element_size=0.0125", "--set", "program.1.steps=3",
                 "--set", "program.3.steps=2"])  # fmt: skip
    assert code == 0
    g = read_csv(out / "global.csv")
    sliding = g["stage"] > 0
    assert np.all(np.abs(g["tangential_force"][sliding]) <= 1e-9 * g["normal_force"][sliding])
    np.testing.assert_allclose(g["normal_force"][sliding], 1.0e6 * 0.1, rtol=1e-8)
    scenario.write_text(head + law + "u = 2e6\n[normal]" + rest.split("[normal]")[1])
    assert main(["contact", str(scenario), "--out", str(tmp_path / "b"), "--quiet"]) == 2
