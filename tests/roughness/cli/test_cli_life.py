"""``frictionlab roughness`` with the optional [adhesion], [wear] and [hierarchy] tables.

Modest resolutions (stated in the scenarios) keep these fast; expected values come from
the closed forms (Eqs 17-20, 33-34), limits and the spec's thresholds.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from frictionlab.cli import main
from frictionlab.io.tables import read_csv
from frictionlab.roughness import closed_forms as cf

SCENARIO = """\
mu0 = 0.3
title = "symmetric wedges, adhesion, wear and hierarchy"
[lower]
kind = "wedge"
angles_deg = [20.0]
wavelength = 1.0e-3
[upper]
kind = "wedge"
angles_deg = [20.0]
wavelength = 1.0e-3
[sliding]
beta_deg = [0.0, 90.0]
[lattice]
stations = 2000
time_samples = 20
[output]
plot_full_circle = false
[adhesion]
loads = [1.0e-3, 5.0e-5, 0.0, -1.0e-5]
[wear]
wear_coefficient = 1.0e-4
hardness = 2.0e9
normal_load = 10.0
velocity = 0.1
nominal_area = 1.0e-4
samples = 5
[hierarchy]
levels = 3
ratio = 10.0
samples_per_level = 3
"""


def run_cli(tmp_path: Path, text: str) -> tuple[int, Path]:
    scenario = tmp_path / "scenario.toml"
    scenario.write_text(text)
    out = tmp_path / "out"
    return main(["roughness", str(scenario), "--out", str(out)]), out


@pytest.mark.slow
def test_all_tables_written_beside_polar(tmp_path) -> None:
    code, out = run_cli(tmp_path, SCENARIO)
    assert code == 0
    names = {p.name for p in out.iterdir()}
    for stem in ("polar", "adhesion", "wear", "hierarchy", "hierarchy_wear"):
        assert {f"{stem}.csv", f"{stem}.png"} <= names
        assert (out / f"{stem}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    summary = json.loads((out / "summary.json").read_text())
    assert set(summary["files"]) == names

    adhesion = read_csv(out / "adhesion.csv")
    assert adhesion.units["load_per_spring"] == "N" and adhesion.units["tangential_force"] == "N"
    at_zero = adhesion["load_per_spring"] == 0.0
    assert np.all(np.ma.getmaskarray(adhesion["mu_apparent"]) == at_zero)  # empty fields
    assert list(adhesion["mu_apparent_defined"][at_zero]) == ["false", "false"]
    assert np.all(adhesion["tangential_force"][at_zero] >= 0.0)
    assert summary["adhesion"]["mu_apparent"][2] == [None, None]  # JSON null at L = 0
    # full contact at the largest load: mu_a is the wedge closed form (Eqs 19, 20)
    heavy = adhesion["load_per_spring"] == 1.0e-3
    np.testing.assert_allclose(
        np.ma.getdata(adhesion["mu_apparent"][heavy]),
        [cf.wedge_on_wedge_0deg(0.3, 20.0), cf.wedge_on_wedge_90deg(0.3, 20.0)],
        rtol=2e-3,
    )
    assert np.all(adhesion["tensile_fraction_max"][heavy] == 0.0)

    wear = read_csv(out / "wear.csv")
    assert wear.units["time_s"] == "s"
    h = 0.5e-3 * math.tan(math.radians(20.0))  # wedge height
    t_w = 2 * 1e-4 * h / 2 / (1e-4 * 10.0 / 2e9 * 0.1)  # both surfaces, Eq 27
    assert summary["wear"]["wear_time_s"] == pytest.approx(t_w, rel=1e-12)
    last = wear["time_s"] == wear["time_s"].max()
    np.testing.assert_allclose(wear["mu"][last], 0.3, rtol=1e-14)
    assert wear["time_s"].max() == pytest.approx(t_w, rel=1e-12)

    hierarchy = read_csv(out / "hierarchy.csv")
    at_90 = hierarchy["beta_deg"] == 90.0
    np.testing.assert_allclose(
        hierarchy["mu"][at_90], cf.hierarchy_wedge_on_wedge_90deg(0.3, 20.0, np.arange(4)),
        rtol=1e-4,
    )  # fmt: skip
    life = read_csv(out / "hierarchy_wear.csv")
    final = life["time_s"] == life["time_s"].max()
    np.testing.assert_allclose(life["mu_3"][final], 0.3, rtol=1e-14)
    drop = summary["hierarchy_wear"]["dropout_time_per_level_s"]
    # Eq 35: level i has heights scaled by 10^-(3-i): windows t_w/100, t_w/10, t_w
    np.testing.assert_allclose(np.diff([0.0, *drop]), [t_w / 100, t_w / 10, t_w], rtol=1e-12)


def test_inner_levels_listed_explicitly(tmp_path) -> None:
    text = SCENARIO.split("[adhesion]")[0] + (
        "[hierarchy]\nbeta_deg = [90.0]\n"
        "[[hierarchy.inner]]\n"
        'lower = { kind = "wedge", angles_deg = [20.0], wavelength = 1.0e-5 }\n'
        'upper = { kind = "wedge", angles_deg = [20.0], wavelength = 1.0e-5 }\n'
        "[[hierarchy.inner]]\n"
        'lower = { kind = "wedge", angles_deg = [20.0], wavelength = 1.0e-4 }\n'
        'upper = { kind = "flat" }\n'
    )
    code, out = run_cli(tmp_path, text)
    assert code == 0
    table = read_csv(out / "hierarchy.csv")
    mu1 = float(cf.wedge_on_wedge_90deg(0.3, 20.0))
    expected = [0.3, mu1, float(cf.flat_on_wedge_90deg(mu1, 20.0))]
    expected.append(float(cf.wedge_on_wedge_90deg(expected[-1], 20.0)))
    np.testing.assert_allclose(table["mu"], expected, rtol=1e-4)
    assert not (out / "wear.csv").exists()


def test_invalid_levels_masked_on_request(tmp_path) -> None:
    text = (
        SCENARIO.split("[adhesion]")[0]
        .replace("[20.0]", "[50.0]")
        .replace("beta_deg = [0.0, 90.0]", "beta_deg = [0.0]")
        + '[hierarchy]\nlevels = 4\nratio = 10.0\non_invalid = "mask"\n'
    )
    code, out = run_cli(tmp_path, text)
    assert code == 0
    table = read_csv(out / "hierarchy.csv")
    valid = table["valid"] == "true"
    assert not np.all(valid) and valid[0] and valid[1]
    assert np.all(np.ma.getmaskarray(table["mu"]) == ~valid)


BAD = [
    ("negative wear coefficient", SCENARIO.replace("wear_coefficient = 1.0e-4",
                                                   "wear_coefficient = -1.0e-4"),
     r"\[wear\]\.wear_coefficient"),
    ("zero hardness", SCENARIO.replace("hardness = 2.0e9", "hardness = 0.0"),
     r"\[wear\]\.hardness"),
    ("wear surfaces", SCENARIO.replace("samples = 5", 'samples = 5\nsurfaces = "middle"'),
     "surfaces"),
    ("empty load sweep", SCENARIO.replace("loads = [1.0e-3, 5.0e-5, 0.0, -1.0e-5]", "loads = []"),
     r"\[adhesion\]\.loads is empty"),
    ("load range without points", SCENARIO.replace(
        "loads = [1.0e-3, 5.0e-5, 0.0, -1.0e-5]",
        "loads = { start = 1.0, stop = -1.0, count = 0 }"), "count"),
    ("k_t above k_c", SCENARIO.replace("loads = [", "k_t = 2.0\nloads = ["), r"\[adhesion\]\.k_t"),
    ("negative detachment", SCENARIO.replace("loads = [", "detachment = -1.0\nloads = ["),
     r"\[adhesion\]\.detachment"),
    ("levels not nested", SCENARIO.replace("ratio = 10.0", "ratio = 1.0"), "ratio"),
    ("inner level not nested", SCENARIO.split("[hierarchy]")[0] + (
        "[hierarchy]\n[[hierarchy.inner]]\n"
        'lower = { kind = "wedge", angles_deg = [20.0], wavelength = 2.0e-3 }\n'
        'upper = { kind = "flat" }\n'), "strictly nested"),
    ("levels and inner", SCENARIO.replace("ratio = 10.0", "ratio = 10.0\n[[hierarchy.inner]]\n"
                                          'lower = { kind = "flat" }\nupper = { kind = "flat" }'),
     "not both"),
    ("unknown key", SCENARIO.replace("samples_per_level", "samples_per_lvl"), "unknown key"),
    ("hierarchy beyond validity", SCENARIO.replace("[20.0]", "[50.0]"),
     "hierarchy level 3 of 3.*mu_2 = 128"),
]  # fmt: skip


@pytest.mark.parametrize(("label", "text", "message"), BAD, ids=[b[0] for b in BAD])
def test_bad_input_exit_2_one_line_nothing_written(tmp_path, capsys, label, text, message) -> None:
    code, out = run_cli(tmp_path, text)
    err = capsys.readouterr().err
    assert code == 2, (label, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert re.search(message, lines[0]), lines[0]
    assert not out.exists()
