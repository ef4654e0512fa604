"""A second corpus of hostile and tired-user inputs, each one line with the right key.

Every case failed on the code before the fix: a traceback, a hang, a wrong key blamed,
library noise on stderr or files written where they should not be. Runs in-process
through :func:`frictionlab.cli.main`; the inputs are refused before any computation
unless the case is about the run itself.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest
from tests.sweep.support import BASE, write_sweep

from frictionlab.cli import main
from frictionlab.errors import InputError
from frictionlab.io.config import load_toml
from frictionlab.io.output_set import lock_out
from frictionlab.io.tables import read_csv

SIMULATE = BASE.format(steps=20)


def _one_line(capsys: pytest.CaptureFixture[str], *words: str) -> str:
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    for word in words:
        assert word in err, err
    return err


# ------------------------------------------------------------------ files refused by type


@pytest.fixture
def fifo(tmp_path: Path) -> Path:
    if not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs here")
    path = tmp_path / "pipe.toml"
    os.mkfifo(path)
    return path


def test_a_fifo_scenario_is_refused_without_opening_it(tmp_path: Path, fifo: Path, capsys) -> None:
    assert main(["simulate", str(fifo), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "FIFO", str(fifo))
    assert not (tmp_path / "out").exists()


def test_a_directory_scenario_is_refused(tmp_path: Path, capsys) -> None:
    assert main(["roughness", str(tmp_path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "is a directory")


def test_a_fifo_table_is_refused(tmp_path: Path, fifo: Path) -> None:
    with pytest.raises(InputError, match="FIFO"):
        read_csv(fifo)


def test_a_fifo_tribometer_file_is_refused(fifo: Path) -> None:
    from frictionlab.io.tribometer import read_tribometer

    with pytest.raises(InputError, match="FIFO"):
        read_tribometer(fifo)


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero")
def test_a_device_as_topography_is_refused(tmp_path: Path) -> None:
    from frictionlab.roughness.topography import read_prepared

    with pytest.raises(InputError, match="a device"):
        read_prepared("/dev/zero", periodicity="assume", detrend="none")


def test_a_fifo_named_by_a_sweep_is_refused(tmp_path: Path, capsys) -> None:
    if not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs here")
    sweep = write_sweep(tmp_path, '[grid]\n"program.2.duration" = [1.0]\n')
    base = tmp_path / "base.toml"
    base.write_text(base.read_text() + '[[program]]\nkind = "table"\nfile = "slip.csv"\n')
    os.mkfifo(tmp_path / "slip.csv")
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out)]) == 2
    _one_line(capsys, "FIFO", "slip.csv")
    assert not out.exists()


# ------------------------------------------------------------------- one decoding rule

BOM = b"\xef\xbb\xbf"


def test_toml_with_a_bom_reads_like_without(tmp_path: Path) -> None:
    plain, marked = tmp_path / "plain.toml", tmp_path / "bom.toml"
    plain.write_text(SIMULATE)
    marked.write_bytes(BOM + SIMULATE.encode())
    assert load_toml(marked) == load_toml(plain)


def test_table_csv_with_a_bom_reads_like_without(tmp_path: Path) -> None:
    text = "time,slip_1\n0,0\n1,0.05\n"
    plain, marked = tmp_path / "plain.csv", tmp_path / "bom.csv"
    plain.write_text(text)
    marked.write_bytes(BOM + text.encode())
    a, b = read_csv(plain), read_csv(marked)
    assert list(b.columns) == list(a.columns) == ["time", "slip_1"]


def test_utf16_is_refused_by_name(tmp_path: Path, capsys) -> None:
    path = tmp_path / "s.toml"
    path.write_bytes(SIMULATE.encode("utf-16"))
    assert main(["simulate", str(path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "not UTF-8", "UTF-16")


# ------------------------------------------------------------- bounds and tracebacks


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("[run]\nmax_halvings = 1000000000\n", ("[run].max_halvings", "<= 60")),
        ("[run]\nmax_halvings = 61\n", ("[run].max_halvings", "<= 60")),
    ],
)
def test_run_bounds(tmp_path: Path, capsys, text: str, words: tuple[str, ...]) -> None:
    path = tmp_path / "s.toml"
    path.write_text(SIMULATE + text)
    assert main(["simulate", str(path), "--out", str(tmp_path / "out"), "--no-plots"]) == 2
    _one_line(capsys, *words)


def test_solver_max_cuts_is_bounded() -> None:
    from frictionlab.contact.solver import SolverOptions
    from frictionlab.errors import ParameterError

    SolverOptions(max_cuts=60)
    with pytest.raises(ParameterError, match=r"max_cuts = 2000 .* 0 to 60"):
        SolverOptions(max_cuts=2000)


def test_a_sweep_value_that_is_a_table_names_the_case_and_key(tmp_path: Path, capsys) -> None:
    sweep = write_sweep(tmp_path, '[grid]\n"law.mu_s" = [{a = 1}]\n')
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out)]) == 2
    _one_line(capsys, "sweep case 1", "[law].mu_s must be a number")
    assert not out.exists()


# ------------------------------------------------------------------- sweep's --out


@pytest.fixture
def sweep_file(tmp_path: Path) -> Path:
    return write_sweep(tmp_path, '[grid]\n"law.mu_s" = [0.5]\n')


def test_sweep_refuses_the_current_directory(
    tmp_path: Path, sweep_file: Path, capsys, monkeypatch
) -> None:
    monkeypatch.chdir(tmp_path)
    before = sorted(p.name for p in tmp_path.iterdir())
    assert main(["sweep", str(sweep_file), "--out", "."]) == 2
    _one_line(capsys, "current directory")
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_sweep_refuses_a_foreign_folder_and_leaves_it_alone(
    tmp_path: Path, sweep_file: Path, capsys
) -> None:
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "thesis.txt").write_text("four years")
    assert main(["sweep", str(sweep_file), "--out", str(folder)]) == 2
    _one_line(capsys, "thesis.txt", "--overwrite")
    assert sorted(p.name for p in folder.iterdir()) == ["thesis.txt"]


@pytest.mark.parametrize("overwrite", [[], ["--overwrite"]])
def test_sweep_refuses_the_folder_of_its_own_inputs(
    tmp_path: Path, sweep_file: Path, capsys, overwrite: list[str]
) -> None:
    before = sorted(p.name for p in tmp_path.iterdir())
    assert main(["sweep", str(sweep_file), "--out", str(tmp_path), *overwrite]) == 2
    _one_line(capsys)
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_sweep_refuses_a_folder_being_written(tmp_path: Path, sweep_file: Path, capsys) -> None:
    out = tmp_path / "out"
    with lock_out(out):  # another run holds it
        assert main(["sweep", str(sweep_file), "--out", str(out)]) == 2
    _one_line(capsys, "being written by another frictionlab run")
    assert not out.exists()


@pytest.mark.slow
def test_sweep_overwrite_starts_a_foreign_folder_afresh(tmp_path: Path, sweep_file: Path) -> None:
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "old.txt").write_text("x")
    argv = ["sweep", str(sweep_file), "--out", str(folder), "--quiet", "--no-plots"]
    assert main([*argv, "--workers", "1", "--overwrite"]) == 0
    assert not (folder / "old.txt").exists() and (folder / "sweep.csv").is_file()
    assert main([*argv, "--workers", "1"]) == 0  # a sweep's folder: resumed, no --overwrite


# ------------------------------------------------------------------ links as --out


def test_a_dangling_link_as_out_is_refused_before_the_run(tmp_path: Path, capsys) -> None:
    scenario = tmp_path / "s.toml"
    scenario.write_text(SIMULATE)
    link = tmp_path / "out"
    link.symlink_to(tmp_path / "nowhere")
    assert main(["simulate", str(scenario), "--out", str(link), "--no-plots"]) == 2
    _one_line(capsys, "symbolic link", "nowhere")
    assert link.is_symlink() and not (tmp_path / "nowhere").exists()


def test_a_linked_out_is_written_where_it_points(tmp_path: Path) -> None:
    scenario = tmp_path / "s.toml"
    scenario.write_text(SIMULATE)
    real = tmp_path / "real"
    real.mkdir()
    link = tmp_path / "out"
    link.symlink_to(real)
    for _ in range(2):
        argv = ["simulate", str(scenario), "--out", str(link), "--no-plots", "--quiet"]
        assert main(argv) == 0
        assert link.is_symlink() and (real / "summary.json").is_file()
    leftovers = [p.name for p in tmp_path.iterdir() if p.name.startswith(".")]
    assert leftovers == [], leftovers
    assert stat.S_ISDIR(os.lstat(real).st_mode)


# ------------------------------------------------------------------- the right key

CLOSED_LAW = """
[law]
surface = "modified_cam_clay"
alpha_n = 2.0e7
alpha_t = 1.0e12
F_s = 2.0e4
F_k = 1.9e4
M = 1.0
u = 1.0e4
kappa = 0.0
xi = 3000.0
rotation = [0.4, 0.0]
[initial]
normal_traction = 1.8e4
[[program]]
kind = "slide"
velocity = 1e-6
distance = 1e-6
steps = 20
"""


def test_a_rotation_that_puts_the_start_outside_blames_the_rotation(tmp_path: Path, capsys) -> None:
    """f_t = 0 was never set: at f_n = 0.9 F_s, |beta| = 0.4 gives f_n g(0.4) = 1.044 F_s."""
    path = tmp_path / "s.toml"
    path.write_text(CLOSED_LAW)
    assert main(["simulate", str(path), "--out", str(tmp_path / "out"), "--no-plots"]) == 2
    err = _one_line(capsys, "[law].rotation", "R = 1.044")
    assert "tangential_traction" not in err


def test_a_slide_at_1e300_m_per_s_draws_its_plots(tmp_path: Path, capsys) -> None:
    path = tmp_path / "s.toml"
    path.write_text(
        SIMULATE.replace("velocity = 0.1\ndistance = 0.2", "velocity = 1e300\ndistance = 0.2")
    )
    out = tmp_path / "out"
    assert main(["simulate", str(path), "--out", str(out), "--quiet"]) == 0
    assert capsys.readouterr().err == ""
    assert (out / "friction.png").read_bytes()[:4] == b"\x89PNG"


def test_a_grid_over_max_cases_is_refused_naming_the_limit(tmp_path: Path, capsys) -> None:
    values = ", ".join(f"{0.4 + 1e-4 * i!r}" for i in range(400))
    sweep = write_sweep(tmp_path, f'[grid]\n"law.mu_s" = [{values}]\n"law.xi" = [{values}]\n')
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--out", str(out)]) == 2
    _one_line(capsys, "[grid] makes 160000 cases", "max_cases = 100000")
    assert not out.exists()


# ------------------------------------------------------ sizes refused before the run

EXAMPLES = Path(__file__).resolve().parents[2] / "src" / "frictionlab" / "data" / "examples"
EXAMPLE_DATA = EXAMPLES / "calibration"


def _calibration(tmp: Path, steps: str) -> Path:
    text = (EXAMPLES / "calibrate.toml").read_text()
    head, _, tail = text.partition("max_step = 5.0e-6")
    (tmp / "shs_run12.csv").write_bytes((EXAMPLE_DATA / "shs_run12.csv").read_bytes())
    path = tmp / "calibrate.toml"
    path.write_text(head + steps + tail)
    return path


@pytest.mark.parametrize(("steps", "limit"), [("1e7", "1 day"), ("1e12", "memory")])
def test_calibration_steps_are_refused_naming_the_key(
    tmp_path: Path, capsys, steps: str, limit: str
) -> None:
    path = _calibration(tmp_path, f"steps = {int(float(steps))}")
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "[[data]] #1.program #1.steps", limit)
    assert not (tmp_path / "out").exists()


def test_the_calibration_example_passes_its_size_check(tmp_path: Path) -> None:
    from frictionlab.app.budget import check_calibration
    from frictionlab.schema.calibrate import load_calibrate as load_calibration

    check_calibration(load_calibration(_calibration(tmp_path, "max_step = 5.0e-6")))


ROUGH = """\
mu0 = 0.3
[lower]
kind = "wedge"
angles_deg = [30.0, 15.0]
wavelength = 1.0e-3
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0, 90.0]
load = 2.0e-6
[lattice]
stations = 200
time_samples = 1000000000
"""


def test_roughness_time_samples_are_refused_naming_the_key(tmp_path: Path, capsys) -> None:
    path = tmp_path / "r.toml"
    path.write_text(ROUGH)
    assert main(["roughness", str(path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "[lattice].time_samples = 1000000000", "memory")


def test_a_contact_mesh_beyond_memory_is_refused_before_meshing(
    tmp_path: Path, capsys, monkeypatch
) -> None:
    from importlib import resources

    from frictionlab.app import budget

    # a 4 GiB machine, whatever this one has: the estimate (~1e10 bytes with either
    # factorisation) is then beyond half of it on every machine the suite runs on
    monkeypatch.setattr(budget, "physical_memory", lambda: 4 * 2**30)
    text = (resources.files("frictionlab") / "data" / "contact" / "pmma_block.toml").read_text()
    path = tmp_path / "c.toml"
    path.write_text(text.replace("element_size = 0.0025", "element_size = 0.00005"))
    assert main(["contact", str(path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "[block].element_size = 5e-05 m", "1.003e+06 nodes", "memory")


def _contact(tmp: Path, old: str, new: str) -> Path:
    from importlib import resources

    text = (resources.files("frictionlab") / "data" / "contact" / "pmma_block.toml").read_text()
    assert old in text
    path = tmp / "c.toml"
    path.write_text(text.replace(old, new))
    return path


CLOSED_CONTACT_LAW = """[law]
surface = "modified_cam_clay"
alpha_n = 5.0e11
alpha_t = 5.0e11
F_s = 2.0e6
F_k = 0.8e6
M = 0.6
u = 2.0e6
kappa = 1.0e9
xi = 0.05
[normal]"""


@pytest.mark.parametrize(
    ("old", "new", "words"),
    [
        ("mu_s = 0.6", "mu_s = [0.6, 0.7]", ("[law].mu_s = [0.6, 0.7]", "one value")),
        ("pressure = 1.0e6 ", "pressure = 1.0e30 ", ("[normal].pressure = 1e+30", "[block].E")),
        (
            "pressure = 1.0e6       # Pa on the top edge",
            "displacement = 1.0",
            ("[normal].displacement = 1 m", "[block].height"),
        ),
        ("steps = 20\n", "steps = 20\n[solver]\nmax_cuts = 2000\n",
         ("[solver].max_cuts = 2000", "0 to 60")),
    ],
)  # fmt: skip
def test_contact_inputs_blame_the_key_set(
    tmp_path: Path, capsys, old: str, new: str, words: tuple[str, ...]
) -> None:
    path = _contact(tmp_path, old, new)
    assert main(["contact", str(path), "--out", str(tmp_path / "out")]) == 2
    err = _one_line(capsys, *words)
    assert "alpha_t" not in err and "Traceback" not in err


def test_a_closed_surface_below_the_pressure_blames_F_k(tmp_path: Path, capsys) -> None:
    from importlib import resources

    text = (resources.files("frictionlab") / "data" / "contact" / "pmma_block.toml").read_text()
    law = text[text.index("[law]") : text.index("[normal]") + len("[normal]")]
    path = tmp_path / "c.toml"
    path.write_text(text.replace(law, CLOSED_CONTACT_LAW))
    assert main(["contact", str(path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "[law].F_k = 800000.0", "normal traction 1e+06 Pa")


def test_a_bridge_distance_of_1e300_blames_the_distance(tmp_path: Path, capsys) -> None:
    from importlib import resources

    text = (resources.files("frictionlab") / "data" / "bridge" / "ratchet.toml").read_text()
    path = tmp_path / "b.toml"
    path.write_text(text + "distance = 1e300\n")
    assert main(["bridge", str(path), "--out", str(tmp_path / "out")]) == 2
    err = _one_line(capsys, "[bridge].distance = 1e+300 m")
    assert "normal_traction" not in err.split("allowed")[0]


@pytest.mark.parametrize(
    ("old", "new", "words"),
    [
        ("profile_points = 7", "profile_points = 10000000", ("[fit].profile_points", "<= 1001")),
    ],
)
def test_calibration_bounds(
    tmp_path: Path, capsys, old: str, new: str, words: tuple[str, ...]
) -> None:
    path = _calibration(tmp_path, "max_step = 5.0e-6")
    path.write_text(path.read_text().replace(old, new))
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, *words)


def test_sweep_max_cases_is_a_key_of_the_sweep_file(tmp_path: Path, capsys) -> None:
    sweep = write_sweep(tmp_path, 'max_cases = 2\n[grid]\n"law.mu_s" = [0.5, 0.6, 0.7]\n')
    assert main(["sweep", str(sweep), "--out", str(tmp_path / "out")]) == 2
    _one_line(capsys, "[grid] makes 3 cases, more than max_cases = 2")
