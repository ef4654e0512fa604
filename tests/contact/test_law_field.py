"""Law parameters along the interface: [law_table] and [[law_region]] (contact.law_field)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from frictionlab.app.contact import discretise_scenario, run_contact_scenario, scenario_law
from frictionlab.contact.law_field import LawRegion, LawTable
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import format_toml
from frictionlab.schema.contact import parse_contact
from frictionlab.schema.scenario import law_table
from frictionlab.subloading import SubloadingParams

P, ALPHA, W = 1.0e6, 5.0e11, 0.1  # Pa, Pa/m, m
MU_LEFT, MU_RIGHT = 0.3, 0.6


def _scenario(tmp_path: Path, **extra: Any) -> dict[str, Any]:
    """A 100 mm x 25 mm block (8 x 2 quads) slid rigidly by 3 um in 6 steps.

    The law is in its Coulomb limit (no softening or recovery, u large: a sharp
    transition) so that a point slides at |f_t| = mu f_n once its elastic slip
    alpha_t d reaches mu p.
    """
    data: dict[str, Any] = {
        "block": {"E": 3.0e9, "nu": 0.35, "width": W, "height": 0.025, "element_size": 0.0125},
        "law": {"alpha_n": ALPHA, "alpha_t": ALPHA, "mu_s": MU_RIGHT, "mu_k": MU_RIGHT,
                "u": 1.0e9, "kappa": 0.0, "xi": 0.0},
        "normal": {"pressure": P, "steps": 1},
        "program": [{"kind": "slide", "velocity": 1e-5, "distance": 3e-6, "steps": 6}],
        "solver": {"drive": "rigid"},
    }  # fmt: skip
    data.update(extra)
    return data


def _run(tmp_path: Path, data: dict[str, Any]):  # type: ignore[no-untyped-def]
    history = run_contact_scenario(parse_contact(data, base_dir=tmp_path))
    assert history.success, history.message
    return history


def test_two_mu_regions_slide_where_and_when_the_closed_form_says(tmp_path: Path) -> None:
    region = {"x": [0.0, W / 2], "mu_s": MU_LEFT, "mu_k": MU_LEFT}
    h = _run(tmp_path, _scenario(tmp_path, law_region=[region]))
    left = h.x <= W / 2
    assert left.sum() == 8  # the region ends on a node: 4 facets x 2 Gauss points
    # a uniform pressure (the rigidly driven block is in uniaxial strain)
    np.testing.assert_allclose(h.traction_n[-1], P, rtol=1e-9)
    # each part starts sliding at the drive displacement d_i = mu_i p / alpha_t:
    # 0.6 um (left) and 1.2 um (right); at d = 1 um the left slides, the right sticks
    k = int(np.flatnonzero(np.isclose(h.top_displacement, 1.0e-6))[0])
    assert np.all(h.R[k, left] > 0.99)
    np.testing.assert_allclose(h.R[k, ~left], ALPHA * 1.0e-6 / (MU_RIGHT * P), rtol=1e-3)
    closed = MU_LEFT * P * W / 2 + ALPHA * 1.0e-6 * W / 2
    assert abs(h.tangential_force[k]) == pytest.approx(closed, rel=1e-3)
    # gross sliding: Q = sum_i mu_i P_i, and each point at its own |f_t| = mu f_n
    assert abs(h.tangential_force[-1]) == pytest.approx((MU_LEFT + MU_RIGHT) * P * W / 2, 1e-6)
    mu_local = np.where(left, MU_LEFT, MU_RIGHT)
    np.testing.assert_allclose(np.abs(h.traction_t[-1]) / h.traction_n[-1], mu_local, rtol=1e-6)


def test_a_constant_field_equals_the_scalar_law(tmp_path: Path) -> None:
    """The per-point parameters run the per-point loop, the scalar law the lanes (inline
    elementary functions): the same numbers to rounding, the same statuses and iterations."""
    softening = {"mu_k": 0.4, "u": 2.0e6, "kappa": 1.0e5, "xi": 0.05}
    (tmp_path / "mu_s.csv").write_text(f"x [m],mu_s\n0,{MU_RIGHT}\n0.04,{MU_RIGHT}\n{W},"
                                       f"{MU_RIGHT}\n")  # fmt: skip
    scalar = _scenario(tmp_path)
    scalar["law"].update(softening)
    scalar["solver"] = {}  # the top drive: a non-uniform interface
    field = {**scalar, "law_table": {"mu_s": "mu_s.csv"},
             "law_region": [{"x": [0.0, W], "kappa": 1.0e5}]}  # fmt: skip
    scenario = parse_contact(field, base_dir=tmp_path)
    resolved = scenario_law(scenario, discretise_scenario(scenario))
    assert resolved.per_point and np.shape(resolved.mu_s) == (16,)
    a, b = _run(tmp_path, scalar), _run(tmp_path, field)
    for name in ("tangential_force", "normal_force", "traction_t", "traction_n", "R", "F",
                 "plastic_slip", "slip"):  # fmt: skip
        want = np.asarray(getattr(a, name))
        scale = max(float(np.abs(want).max()), 1e-300)
        np.testing.assert_allclose(getattr(b, name), want, rtol=1e-12, atol=1e-12 * scale,
                                   err_msg=name)  # fmt: skip
    for name in ("status", "iterations"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def test_bridge_region_takes_the_fitted_rotation(tmp_path: Path) -> None:
    """beta = (0.1, 0) in the left half: there the steady friction along e_1 is mu +- 0.1."""
    fitted = SubloadingParams(alpha_n=ALPHA, alpha_t=ALPHA, mu_s=MU_RIGHT, mu_k=MU_RIGHT,
                              u=1.0e9, kappa=0.0, xi=0.0, rotation=(0.1, 0.0))  # fmt: skip
    text = format_toml({"law": law_table(fitted)})
    (tmp_path / "fitted_law.toml").write_text(text)
    region = {"x": [0.0, W / 2], "bridge": "fitted_law.toml"}
    h = _run(tmp_path, _scenario(tmp_path, law_region=[region]))
    q = abs(h.tangential_force[-1])
    assert abs(q - MU_RIGHT * P * W) == pytest.approx(0.1 * P * W / 2, rel=1e-6)


def test_table_interpolation_is_linear_and_refuses_points_outside() -> None:
    xy = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    table = LawTable("mu_s", xy, 0.2 + 0.1 * xy[:, 0] + 0.3 * xy[:, 1])
    points = np.array([[0.25, 0.5], [1.0, 1.0], [0.7, 0.1]])
    np.testing.assert_allclose(table.at(points), 0.2 + 0.1 * points[:, 0] + 0.3 * points[:, 1])
    with pytest.raises(ParameterError, match=r"outside"):
        table.at(np.array([[1.5, 0.5]]))
    line = LawTable("kappa", [0.0, 2.0, 1.0], [0.0, 20.0, 10.0])  # sorted on input
    np.testing.assert_allclose(line.at(np.array([[0.5], [1.5]])), [5.0, 15.0])
    with pytest.raises(ParameterError, match="y"):
        LawRegion({"mu_s": 0.3}, y=(0.0, 1.0)).contains(np.array([[0.5]]))


@pytest.mark.parametrize(
    ("extra", "files", "message"),
    [
        ({"law_region": [{"x": [0.0, 0.05], "mu_k": 0.7}]}, {},
         r"\[\[law_region\]\] #1: with the \[law\] values, mu_k = 0.7"),
        ({"law_region": [{"x": [0.05, 0.0], "mu_s": 0.7}]}, {}, r"\[\[law_region\]\] #1.x"),
        ({"law_region": [{"x": [0.0, 0.05], "F_s": 1.0}]}, {}, r"#1.F_s is not a parameter"),
        ({"law_region": [{"x": [0.0, 0.05]}]}, {}, "at least one law value"),
        ({"law_region": [{"y": [0.0, 0.05], "mu_s": 0.7}]}, {}, "3-D block"),
        ({"law_table": {"mu_s": "missing.csv"}}, {}, r"\[law_table\].mu_s = 'missing.csv'"),
        ({"law_table": {"mu_s": "t.csv"}}, {"t.csv": "x [m],kappa\n0,1\n1,1\n"},
         r"\[law_table\].mu_s = 't.csv': allowed a table with the columns x, mu_s"),
        ({"law_table": {"mu_s": "t.csv"}}, {"t.csv": "x [mm],mu_s\n0,1\n1,1\n"}, r"\[mm\]"),
        ({"law_table": {"mu_k": "t.csv"}}, {"t.csv": "x,mu_k\n0,0.5\n0.1,0.9\n"},
         r"\[law_table\].mu_k = 't.csv': with the \[law\] values, mu_k = 0.9"),
        ({"law_table": {"mu_s": "t.csv"}}, {"t.csv": "x,mu_s\n0,0.7\n0,0.7\n"}, "distinct x"),
        ({"law_region": [{"x": [0.0, 0.05], "mu_s": 0.7}], "law": {"alpha_n": 1e11,
          "mu_s": 0.0, "mu_k": 0.0}}, {}, "frictionless"),
    ],
)  # fmt: skip
def test_bad_fields_are_one_line_naming_the_key(
    tmp_path: Path, extra: dict[str, Any], files: dict[str, str], message: str
) -> None:
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    with pytest.raises((InputError, ParameterError), match=message) as info:
        parse_contact(_scenario(tmp_path, **extra), base_dir=tmp_path)
    assert "\n" not in str(info.value)


def test_a_table_short_of_the_contact_face_is_refused_before_running(tmp_path: Path) -> None:
    (tmp_path / "t.csv").write_text("x [m],mu_s\n0,0.7\n0.05,0.7\n")
    scenario = parse_contact(_scenario(tmp_path, law_table={"mu_s": "t.csv"}), base_dir=tmp_path)
    with pytest.raises(InputError, match=r"\[law_table\].mu_s \('t.csv'\).*outside"):
        scenario_law(scenario, discretise_scenario(scenario))


def test_a_3d_table_is_interpolated_over_x_and_y(tmp_path: Path) -> None:
    """Samples of a linear mu_s(x, y) on a 3 x 3 grid: exact at every contact point."""
    x, y = np.meshgrid([0.0, 0.01, 0.02], [0.0, 0.01, 0.02])
    pairs = zip(x.ravel(), y.ravel(), strict=True)
    rows = "\n".join(f"{a},{b},{0.5 + 3.0 * a + 4.0 * b}" for a, b in pairs)
    (tmp_path / "mu.csv").write_text("x [m],y [m],mu_s\n" + rows + "\n")
    data = _scenario(tmp_path, law_table={"mu_s": "mu.csv"})
    data["block"] = {"E": 3.0e9, "nu": 0.3, "width": 0.02, "depth": 0.02, "height": 0.01,
                     "element_size": 0.005}  # fmt: skip
    data["law"]["mu_k"] = 0.4
    scenario = parse_contact(data, base_dir=tmp_path)
    disc = discretise_scenario(scenario)
    law = scenario_law(scenario, disc)
    xy = disc.contact_xy
    np.testing.assert_allclose(law.mu_s, 0.5 + 3.0 * xy[:, 0] + 4.0 * xy[:, 1], rtol=1e-12)


def test_normal_capacity_of_a_per_point_closed_surface_at_one_traction() -> None:
    """A field of F_k on a closed surface: the one nominal pressure is checked at every point."""
    from frictionlab.subloading import check_normal_capacity

    law = SubloadingParams(surface="modified_cam_clay", F_s=[3e6, 3e6], F_k=[2e6, 0.5e6], M=0.5)
    check_normal_capacity(law, 0.4e6)
    with pytest.raises(ParameterError, match=r"F_k = 500000"):
        check_normal_capacity(law, 1.0e6)


def test_a_region_whose_F_k_is_below_the_pressure_is_refused_before_the_run(
    tmp_path: Path,
) -> None:
    """A closed surface softened to F_k carries at most f_n = F_k: a region with its own
    F_k below the nominal pressure P is refused when the scenario is read, naming the
    region and the key (a region above P, and the [law]'s own F_k, pass)."""
    closed = {
        "surface": "modified_cam_clay",
        "alpha_n": ALPHA,
        "alpha_t": ALPHA,
        "F_s": 3.0 * P,
        "F_k": 2.0 * P,
        "M": 0.5,
        "u": 1.0e9,
        "kappa": 0.0,
        "xi": 0.0,
    }
    parse_contact(_scenario(tmp_path, law=closed, law_region=[
        {"x": [0.0, 0.05], "F_k": 1.5 * P}]), base_dir=tmp_path)  # fmt: skip
    data = _scenario(tmp_path, law=closed, law_region=[
        {"x": [0.0, 0.05], "F_k": 1.5 * P}, {"x": [0.05, W], "F_k": 0.5 * P}])  # fmt: skip
    with pytest.raises(
        (InputError, ParameterError), match=r"\[\[law_region\]\] #2\.F_k = 500000"
    ) as info:
        parse_contact(data, base_dir=tmp_path)
    assert "\n" not in str(info.value)
