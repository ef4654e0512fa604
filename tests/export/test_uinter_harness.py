"""UINTER driven by a Fortran harness that plays Abaqus/Standard's part.

Every call of the law made by `frictionlab simulate` on every bundled scenario (and on
the closed surfaces, and on a separation and re-closing programme) is replayed through
UINTER with the documented argument list: the tractions, the state variables and, where
the run asked for it, the consistent tangent must agree with the run to 1e-10.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import frictionlab
from frictionlab.app.simulate import run_scenario
from frictionlab.io.scenario import load_scenario
from frictionlab.subloading import kernels

from .support import (
    build_uinter_harness,
    build_vuinter_harness,
    recorded_calls,
    records,
    run_checked,
    run_uinter,
)

BUNDLED = Path(frictionlab.__file__).parent / "data" / "scenarios"
SCENARIOS = sorted(p.name for p in BUNDLED.glob("*.toml"))
RECLOSING = """
[law]
surface = "{surface}"
alpha_n = 1.0e12
alpha_t = 1.0e12
{sizes}
u = 1.0e5
kappa = 1000.0
xi = 0.01
rotation = [0.05, -0.02]
orthotropy = [1.0, 0.8]
orthotropy_angle = 0.3

[initial]
normal_traction = {fn}

[[program]]
kind = "slide"
velocity = 1.0e-4
distance = 2.0e-6
steps = 40

[[program]]
kind = "normal"
approach = -3.0e-6
steps = 2

[[program]]
kind = "hold"
duration = 10.0
steps = 5

[[program]]
kind = "normal"
approach = 3.5e-6
steps = 3

[[program]]
kind = "slide"
velocity = 1.0e-4
distance = 2.0e-6
direction_deg = 120.0
steps = 40
"""
CLOSED = "F_s = 1.0e6\nF_k = 0.6e6\nM = 0.5"
CONE = "mu_s = 0.5\nmu_k = 0.3"


def _cases() -> list[tuple[str, str, list[str]]]:
    cases = [(name, name, []) for name in SCENARIOS]
    for surface in ("cam_clay", "tear", "parabola"):
        cases.append((f"pressure {surface}", "pressure.toml", [f"law.surface={surface}"]))
    return cases


def _replay(scenario, build_dir: Path, fortran: str, work: Path) -> int:  # type: ignore[no-untyped-def]
    with recorded_calls() as calls:
        history = run_scenario(scenario)
    assert history.success
    exe = build_uinter_harness(build_dir, fortran)
    recs = records(calls, scenario.params)
    got = run_uinter(exe, recs, work)
    want_traction = np.concatenate([c["out_traction"] for c in calls])
    status = np.concatenate([c["out_status"] for c in calls])
    failed = status == kernels.FAILED
    scale = np.abs(want_traction).max()
    np.testing.assert_allclose(got[:, [1, 2, 0]], want_traction, rtol=1e-10, atol=1e-10 * scale)
    for col, key in ((3, "out_F"), (4, "out_R"), (5, "out_gap")):
        want = np.concatenate([c[key] for c in calls])
        np.testing.assert_allclose(got[:, col], want, rtol=1e-10, atol=1e-300, err_msg=key)
    # status in STATEV(5) (kept from the start where the solve failed: PNEWDT = 0.25)
    np.testing.assert_array_equal(got[~failed, 7], status[~failed])
    np.testing.assert_array_equal(got[:, 20] == 0.25, failed)
    # the consistent tangent, where the run computed it (traction control)
    order = [2, 0, 1]
    rows = []
    for c in calls:
        n = c["traction"].shape[0]
        if c["tangent_wanted"]:
            rows.append(c["out_tangent"][:, order][:, :, order].reshape(n, 9, order="F"))
        else:
            rows.append(np.full((n, 9), np.nan))
    tangent = np.concatenate(rows)
    has = ~np.isnan(tangent[:, 0])
    if has.any():
        k = np.abs(tangent[has]).max()
        np.testing.assert_allclose(got[has, 11:20], tangent[has], rtol=1e-10, atol=1e-10 * k)
    return recs.shape[0]


@pytest.mark.slow
@pytest.mark.parametrize(("label", "name", "overrides"), _cases(), ids=[c[0] for c in _cases()])
def test_uinter_reproduces_simulate_on_the_bundled_scenarios(
    label: str, name: str, overrides: list[str], build_dir: Path, fortran: str, tmp_path: Path
) -> None:
    scenario = load_scenario(BUNDLED / name, overrides)
    n = _replay(scenario, build_dir, fortran, tmp_path)
    assert n > 0


@pytest.mark.parametrize("surface", ["coulomb", "modified_cam_clay", "tear"])
def test_uinter_reproduces_separation_and_reclosing(
    surface: str, build_dir: Path, fortran: str, tmp_path: Path
) -> None:
    cone = surface == "coulomb"
    text = RECLOSING.format(surface=surface, sizes=CONE if cone else CLOSED,
                            fn=1.0e6 if cone else 3.0e5)  # fmt: skip
    path = tmp_path / "reclosing.toml"
    path.write_text(text)
    scenario = load_scenario(path)
    with recorded_calls() as calls:
        run_scenario(scenario)
    opened = any((c["out_status"] == kernels.OPEN).any() for c in calls)
    reclosed = any(((c["gap"] > 0.0) & (c["out_status"] != kernels.OPEN)).any() for c in calls)
    assert opened and reclosed
    _replay(scenario, build_dir, fortran, tmp_path)


def test_vuinter_block_equals_uinter_point_by_point(
    build_dir: Path, fortran: str, tmp_path: Path
) -> None:
    """VUINTER (one call for a block of nodes) gives UINTER's answers node by node."""
    path = tmp_path / "reclosing.toml"
    path.write_text(RECLOSING.format(surface="coulomb", sizes=CONE, fn=1.0e6))
    scenario = load_scenario(path)
    with recorded_calls() as calls:
        run_scenario(scenario)
    recs = records(calls, scenario.params)
    recs = recs[recs[:, 40] == recs[0, 40]]  # one time increment for the whole block
    uinter = run_uinter(build_uinter_harness(build_dir, fortran), recs, tmp_path)
    exe = build_vuinter_harness(build_dir)
    (tmp_path / "block.bin").write_bytes(
        np.concatenate([[float(len(recs))], recs.ravel()]).astype("<f8").tobytes()
    )
    run_checked([str(exe), str(tmp_path / "block.bin"), str(tmp_path / "block.out")])
    block = np.fromfile(tmp_path / "block.out", dtype="<f8").reshape(len(recs), 14)
    ok = uinter[:, 20] == 1.0  # failed points: VUINTER cannot cut the increment
    assert ok.sum() >= 50
    np.testing.assert_array_equal(block[ok, :11], uinter[ok, :11])
    np.testing.assert_array_equal(block[ok, 11], uinter[ok, 21])


def test_uinter_first_call_sets_the_initial_state(
    build_dir: Path, fortran: str, tmp_path: Path
) -> None:
    """STATEV all zero: F = F_initial, and the opening from RDISP(1) - DRDISP(1) < 0."""
    from frictionlab.export.abaqus import props_vector
    from frictionlab.subloading import ContactState, SubloadingParams, update

    params = SubloadingParams(mu_s=0.5, mu_k=0.3, alpha_n=1e12, alpha_t=1e12, u=1e5,
                              kappa=1e3, xi=1e-3, rotation=(0.05, 0.0))  # fmt: skip
    gap, approach, slip = 1e-6, 1.5e-6, (2e-7, -1e-7)
    rec = np.zeros(41)
    rec[0] = 3.0
    rec[1:23] = props_vector(params, F_initial=0.45)
    rec[34] = approach - gap  # RDISP(1): the overclosure at the end of the increment
    rec[37:40] = [approach, *slip]
    rec[40] = 0.5
    got = run_uinter(build_uinter_harness(build_dir, fortran), rec[None], tmp_path)[0]
    start = ContactState(
        traction=np.zeros((1, 3)), F=np.array([0.45]), R=np.zeros(1),
        plastic_slip=np.zeros(1), gap=np.array([gap]), frame=np.eye(3)[None],
    )  # fmt: skip
    want = update(params, start, np.array([[*slip, approach]]), 0.5)
    np.testing.assert_array_equal(got[[1, 2, 0]], want.traction[0])
    assert (got[3], got[4], got[5], got[10]) == (want.state.F[0], want.state.R[0], 0.0, 1.0)
    assert got[0] == pytest.approx(1e12 * (approach - gap), rel=1e-9)
