"""A corpus of bad inputs: each is exit 2, one line naming the key or file, nothing written.

Every case runs in-process through :func:`frictionlab.cli.main` (no subprocess) and is
rejected while the input is read, before any computation: the whole corpus takes seconds.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main

SIMULATE = """
[law]
surface = "coulomb"
mu_s = 0.5
mu_k = 0.3
kappa = 1.0
xi = 0.001
alpha_t = 1000.0
alpha_n = 1000.0
[initial]
normal_traction = 1.0
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.2
steps = 20
[[program]]
kind = "hold"
duration = 10.0
"""

OUTPUT = "[output]\n{}\n[initial]"  # an [output] table put before [initial]

FILE = '\nperiodicity = "assume"\ndetrend = "none"'
ROUGHNESS = """
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
stations = 2000
time_samples = 10
"""

# (key as written in the file, its line in the scenario): values that must be refused
SIMULATE_KEYS = {
    "mu_s": "mu_s = 0.5",
    "mu_k": "mu_k = 0.3",
    "kappa": "kappa = 1.0",
    "xi": "xi = 0.001",
    "alpha_t": "alpha_t = 1000.0",
    "alpha_n": "alpha_n = 1000.0",
    "normal_traction": "normal_traction = 1.0",
    "velocity": "velocity = 0.1",
    "distance": "distance = 0.2",
    "duration": "duration = 10.0",
}
BAD_NUMBERS = ['"x"', "-1.0", "nan", "inf", "-inf", "true", "{ a = 1 }"]
BAD_STEPS = ['"x"', "0", "-3", "2.5", "nan", "true"]

ROUGHNESS_KEYS = {
    "mu0": "mu0 = 0.3",
    "wavelength": "wavelength = 1.0e-3",
    "load": "load = 2.0e-6",
    "time_samples": "time_samples = 10",
    "stations": "stations = 2000",
}
ROUGHNESS_BAD = ['"x"', "-1.0", "nan", "inf", "true", "0"]


def _cases() -> list[object]:
    cases: list[object] = []
    for key, line in SIMULATE_KEYS.items():
        for bad in BAD_NUMBERS:
            new = line.split("=")[0] + "= " + bad
            cases.append(pytest.param("simulate", SIMULATE, line, new, key, id=f"sim-{key}={bad}"))
    for bad in BAD_STEPS:
        cases.append(
            pytest.param(
                "simulate", SIMULATE, "steps = 20", f"steps = {bad}", "steps", id=f"sim-steps={bad}"
            )
        )
    for key, line in ROUGHNESS_KEYS.items():
        for bad in ROUGHNESS_BAD:
            new = line.split("=")[0] + "= " + bad
            cases.append(
                pytest.param("roughness", ROUGHNESS, line, new, key, id=f"rough-{key}={bad}")
            )
    structural = [
        ("simulate", SIMULATE, "mu_k = 0.3", "mu_k = 0.3\nmu_z = 1", "mu_z"),
        ("simulate", SIMULATE, "[initial]", "[initial]\nspeed = 1", "speed"),
        ("simulate", SIMULATE, 'surface = "coulomb"', 'surface = "cone"', "surface"),
        ("simulate", SIMULATE, 'surface = "coulomb"', "surface = 3", "surface"),
        ("simulate", SIMULATE, 'kind = "hold"', 'kind = "nap"', "kind"),
        ("simulate", SIMULATE, 'kind = "hold"', "", "kind"),
        ("simulate", SIMULATE, "normal_traction = 1.0", "", "normal_traction"),
        ("simulate", SIMULATE, "[initial]", "[initia]", "initia"),
        ("simulate", SIMULATE, "[[program]]", "[[program]", "TOML"),
        ("simulate", SIMULATE, "mu_s = 0.5", "mu_s = 0.5\nmu_s = 0.6", "TOML"),
        ("simulate", SIMULATE, "mu_s = 0.5", "mu_s = ", "TOML"),
        ("simulate", SIMULATE, "mu_k = 0.3", "mu_k = 0.6", "mu_k"),
        ("simulate", SIMULATE, "mu_s = 0.5", "mu_s = []", "mu_s"),
        ("simulate", SIMULATE, "steps = 20", "steps = 20\nmax_step = 0.01", "max_step"),
        ("simulate", SIMULATE, "distance = 0.2", "distance = 0.2\nduration = 2.0", "distance"),
        ("simulate", SIMULATE, "[initial]", "[run]\nn_points = 0\n[initial]", "n_points"),
        ("simulate", SIMULATE, "[initial]", '[run]\naccuracy = "x"\n[initial]', "accuracy"),
        ("simulate", SIMULATE, "[initial]", "[run]\nmax_halvings = -1\n[initial]", "max_halvings"),
        ("simulate", SIMULATE, "[initial]", '[run]\nallow_large = "y"\n[initial]', "allow_large"),
        ("simulate", SIMULATE, "[initial]", "[run]\nn_points = 1e9\n[initial]", "n_points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("every = 0"), "[output].every"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("every = 2.5"), "[output].every"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format('every = "x"'), "[output].every"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("points = [2]"), "[output].points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("points = [0]"), "[output].points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("points = []"), "[output].points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("points = [1, 1]"), "[output].points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("points = [1.5]"), "[output].points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("points = 1"), "[output].points"),
        ("simulate", SIMULATE, "[initial]", OUTPUT.format("evry = 2"), "[output].evry"),
        ("simulate", SIMULATE, "steps = 20", "steps = 1000000000000", "steps"),
        ("simulate", SIMULATE, "steps = 20", "max_step = 1e-300", "max_step"),
        ("simulate", SIMULATE, "[initial]", "title = 3\n[initial]", "title"),
        ("roughness", ROUGHNESS, 'kind = "wedge"', 'kind = "pyramid"', "kind"),
        ("roughness", ROUGHNESS, "[lattice]", "[lattice]\nspeed = 3", "speed"),
        ("roughness", ROUGHNESS, "[sliding]", "[sliding]\nangle = 3", "angle"),
        ("roughness", ROUGHNESS, "mu0 = 0.3", "", "mu0"),
        ("roughness", ROUGHNESS, "mu0 = 0.3", "mu0 = 1.8", "mu0"),
        ("roughness", ROUGHNESS, "beta_deg = [0.0, 90.0]", 'beta_deg = "all"', "beta_deg"),
        ("roughness", ROUGHNESS, "beta_deg = [0.0, 90.0]", "beta_deg = [nan]", "beta_deg"),
        ("roughness", ROUGHNESS, "beta_deg = [0.0, 90.0]", "beta_deg = []", "beta_deg"),
        ("roughness", ROUGHNESS, "angles_deg = [30.0, 15.0]", "angles_deg = [30.0, 15.0, 5.0]",
         "angles_deg"),
        ("roughness", ROUGHNESS, "angles_deg = [30.0, 15.0]", "angles_deg = [95.0, 15.0]",
         "angles_deg"),
        ("roughness", ROUGHNESS, "angles_deg = [30.0, 15.0]", 'angles_deg = ["a", 15.0]',
         "angles_deg"),
        ("roughness", ROUGHNESS, "[upper]", "[upper]\nwavelength = 1", "wavelength"),
        ("roughness", ROUGHNESS, 'kind = "flat"', 'kind = "file"\npath = "missing.x3p"{file}',
         "missing.x3p"),
        ("roughness", ROUGHNESS, "[lower]", "[lowr]", "lower"),
        ("roughness", ROUGHNESS, "stations = 2000", "stations = 100000000000",
         "[lattice].stations = [100000000000]"),
        ("roughness", ROUGHNESS, "[lattice]", "[lattice]\nspeed = 3",
         "allowed keys here: engine, full_contact, k_c, k_t, max_return_periods"),
        ("roughness", ROUGHNESS, "[lattice]", "[lattice\n", "TOML"),
    ]  # fmt: skip
    structural = [(c, b, o, n.replace("{file}", FILE), k) for c, b, o, n, k in structural]
    for command, base, old, new, key in structural:
        cases.append(pytest.param(command, base, old, new, key, id=f"{command}-{key}-{new[:24]}"))
    return cases


CASES = _cases()


@pytest.mark.parametrize(("command", "base", "old", "new", "key"), CASES)
def test_bad_scenario_value(
    command: str,
    base: str,
    old: str,
    new: str,
    key: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert old in base
    scenario = tmp_path / "s.toml"
    scenario.write_text(base.replace(old, new, 1))
    out = tmp_path / "out"
    code = main([command, str(scenario), "--out", str(out), "--quiet"])
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert code == 2, captured.err
    assert len(lines) == 1 and lines[0].startswith("frictionlab: error:"), captured.err
    assert key in lines[0]
    assert "Traceback" not in captured.err and captured.out == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]


def _files(tmp_path: Path) -> dict[str, Callable[[], str]]:
    """Bad topography files for ``[upper] kind = "file"``: name -> maker (returns the path)."""

    def empty() -> str:
        (tmp_path / "empty.txt").write_bytes(b"")
        return "empty.txt"

    def directory() -> str:
        (tmp_path / "folder.txt").mkdir()
        return "folder.txt"

    def ragged() -> str:
        (tmp_path / "ragged.txt").write_text("0 1 2\n3 4\n5 6 7\n")
        return "ragged.txt"

    def garbage() -> str:
        (tmp_path / "garbage.x3p").write_bytes(b"\x00\x01not a topography")
        return "garbage.x3p"

    return {"empty": empty, "directory": directory, "ragged": ragged, "garbage": garbage}


@pytest.mark.parametrize("which", ["empty", "directory", "ragged", "garbage"])
def test_bad_topography_file(
    which: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    name = _files(tmp_path)[which]()
    before = sorted(p.name for p in tmp_path.iterdir())
    text = ROUGHNESS.replace('kind = "flat"', f'kind = "file"\npath = "{name}"\nunit = "um"{FILE}')
    (tmp_path / "s.toml").write_text(text)
    code = main(["roughness", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out")])
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert code == 2, captured.err
    assert len(lines) == 1 and name in lines[0], captured.err
    assert "Traceback" not in captured.err
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([*before, "s.toml"])


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["simulate", "{d}/missing.toml", "--out", "{d}/out"], "missing.toml"),
        (["simulate", "{d}", "--out", "{d}/out"], "cannot read"),
        (["simulate", "{d}/s.toml", "--out", "{d}/s.toml"], "not a directory"),
        (["simulate", "{d}/s.toml", "--out", ""], "--out"),
        (["simulate", "{d}/s.toml", "--out", "{d}/out", "--set", "law.mu_s"], "section.key"),
        (["simulate", "{d}/s.toml", "--out", "{d}/out", "--set", "law.mu_s=abc"], "mu_s"),
        (["simulate", "{d}/s.toml", "--out", "{d}/out", "--set", "law.mu_s=-1"], "mu_s"),
        (["simulate", "{d}/s.toml", "--out", "{d}/out", "--set", "program.9.steps=3"], "9"),
        (["roughness", "{d}/missing.toml", "--out", "{d}/out"], "missing.toml"),
        (["roughness", "{d}/s.toml", "--out", "{d}/s.toml"], "not a directory"),
    ],
)
def test_bad_command_line(
    args: list[str], message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "s.toml").write_text(SIMULATE)
    argv = [a.format(d=tmp_path) for a in args]
    code = main([*argv, "--quiet"])
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert code == 2, captured.err
    assert len(lines) == 1 and message in lines[0], captured.err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]


def test_tiny_normal_traction_fails_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """f_n = 1e-300: the law's kernel divides by an underflowed value; exit 1, no traceback."""
    (tmp_path / "s.toml").write_text(
        SIMULATE.replace("normal_traction = 1.0", "normal_traction = 1e-300")
    )
    code = main(["simulate", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out"), "--quiet",
                 "--no-plots"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 1 and "Traceback" not in err and "computation failed" in err
    assert len(err.strip().splitlines()) == 1
    assert "more than 1e+15 times the normal traction 1e-300 Pa" in err  # says why


def test_the_corpus_is_large() -> None:
    assert len(CASES) + 4 + 10 >= 150  # scenario values, topography files, command lines


def test_a_nan_in_a_table_csv_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "nan.csv").write_text("time,slip_1\n0,0\n1,nan\n")
    text = SIMULATE.replace('kind = "hold"\nduration = 10.0', 'kind = "table"\nfile = "nan.csv"')
    (tmp_path / "s.toml").write_text(text)
    code = main(["simulate", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out")])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(lines) == 1
    assert "'nan.csv'.slip" in lines[0] and "finite values" in lines[0]


@pytest.mark.parametrize("defined", [0, 1])
def test_filling_a_mostly_undefined_topography_is_refused(
    defined: int, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """All-NaN with fill_missing used to be filled flat (mu/mu0 = 1, exit 0)."""
    heights = np.full((8, 8), np.nan)
    heights.ravel()[:defined] = 1e-6
    np.savetxt(tmp_path / "nan.txt", heights)
    text = ROUGHNESS.replace(
        'kind = "flat"',
        'kind = "file"\npath = "nan.txt"\nunit = "m"\nphysical_sizes = [1e-3, 1e-3]'
        f"{FILE}\nfill_missing = true",
    ).replace("stations = 2000", "stations = [8, 8]")
    text = text.replace(
        "angles_deg = [30.0, 15.0]\nwavelength = 1.0e-3",
        "amplitude = 1e-5\nwavelengths = [1e-3, 1e-3]",
    ).replace('"wedge"', '"sinusoid"')
    (tmp_path / "s.toml").write_text(text)
    code = main(["roughness", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out")])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(lines) == 1, lines
    assert f"{64 - defined} of 64 points undefined" in lines[0] and "fill_missing" in lines[0]


def _roughness_with_file(tmp_path: Path, name: str) -> Path:
    text = ROUGHNESS.replace('kind = "flat"', f'kind = "file"\npath = "{name}"\nunit = "um"{FILE}')
    (tmp_path / "s.toml").write_text(text)
    return tmp_path / "s.toml"


@pytest.mark.parametrize(
    ("rows", "message"),
    [
        ("0 1 2\n3 4\n5 6 7\n", "line 2 has 2 values, expected 3"),
        ("# heights\n0 1 2 3\n3 4 5 6\n\n5 6 7 8\n1 2 3 4 5\n", "line 6 has 5 values, expected 4"),
        ("0,1,2\n3,4,5\n6,7,8,9\n", "line 3 has 4 values, expected 3"),
    ],
)
def test_a_ragged_text_topography_names_the_line(
    rows: str, message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "ragged.txt").write_text(rows)
    scenario = _roughness_with_file(tmp_path, "ragged.txt")
    code = main(["roughness", str(scenario), "--out", str(tmp_path / "out")])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(lines) == 1, lines
    assert "ragged.txt" in lines[0] and message in lines[0]
    assert not (tmp_path / "out").exists()


def test_an_unreadable_topography_file_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Permission denied (simulated: the tests may run as root, where chmod does not deny)."""
    from frictionlab.roughness import topography

    heights = np.zeros((4, 4))
    np.savetxt(tmp_path / "locked.txt", heights)
    real_open = open

    def denying_open(name: object, *args: object, **kwargs: object) -> object:
        if str(name).endswith("locked.txt"):
            raise PermissionError(13, "Permission denied", str(name))
        return real_open(name, *args, **kwargs)  # type: ignore[call-overload]

    monkeypatch.setattr(topography, "open", denying_open, raising=False)
    scenario = _roughness_with_file(tmp_path, "locked.txt")
    code = main(["roughness", str(scenario), "--out", str(tmp_path / "out")])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(lines) == 1, lines
    assert "locked.txt" in lines[0] and "Permission denied" in lines[0]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    ("segment", "words"),
    [
        ('kind = "normal"\ntraction = 1e-200', "cannot be told from zero"),
        ('kind = "normal"\ntraction_change = -0.9999999999999999', "cannot be told from zero"),
    ],
)
def test_a_normal_traction_target_indistinguishable_from_zero_is_one_line(
    segment: str, words: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """It used to open the contact silently (exit 0)."""
    text = SIMULATE.replace('kind = "hold"\nduration = 10.0', segment)
    (tmp_path / "s.toml").write_text(text)
    code = main(["simulate", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out"), "--quiet",
                 "--no-plots"])  # fmt: skip
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 1 and len(lines) == 1 and words in lines[0], lines
    assert "Traceback" not in lines[0]


def test_a_traction_target_max_step_asking_for_endless_steps_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Its step count is known only when the segment starts: it used to run for ever."""
    text = SIMULATE.replace(
        'kind = "hold"\nduration = 10.0', 'kind = "normal"\ntraction = 2.0\nmax_step = 1e-300'
    )
    (tmp_path / "s.toml").write_text(text)
    code = main(["simulate", str(tmp_path / "s.toml"), "--out", str(tmp_path / "out"), "--quiet"])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and "max_step" in lines[0], lines
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]


def test_a_text_file_that_could_be_a_matrix_or_points_needs_a_format(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Three values per line were read as x y z points, silently (sizes from the 'x, y')."""
    np.savetxt(tmp_path / "h.txt", np.arange(9.0).reshape(3, 3))
    scenario = _roughness_with_file(tmp_path, "h.txt")
    code = main(["roughness", str(scenario), "--out", str(tmp_path / "out")])
    lines = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(lines) == 1, lines
    assert "format" in lines[0] and "'asc'" in lines[0] and "'xyz'" in lines[0]
    assert not (tmp_path / "out").exists()
