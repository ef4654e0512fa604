"""simulate(): the tribometer tests of issue 3 against closed forms and independent runs."""

from __future__ import annotations

import numpy as np
import pytest

import frictionlab.driver.stepping as stepping
from frictionlab.driver import (
    Cycle,
    DriverSettings,
    Hold,
    InitialConditions,
    NormalStep,
    Reverse,
    Slide,
    Table,
    Traction,
    Turn,
    simulate,
    slide_hold_slide,
)
from frictionlab.errors import ParameterError
from frictionlab.subloading import Status, SubloadingParams, update

from .support import MU_K, MU_S, mu_ss, ratchet_per_cycle, recovered, set_a

HOLDS = np.array([1.0, 10.0, 100.0, 1000.0, 1e4])


def test_slide_hold_slide_for_many_hold_times_in_one_run() -> None:
    h = simulate(set_a(), slide_hold_slide(0.1, 1.0, HOLDS, steps=500, hold_steps=4))
    assert h.success and h.n_points == HOLDS.size
    slide1, hold, slide2 = h.segments
    mu0 = h.F[slide1.last_row]
    # during the hold the traction is held exactly (no relaxation) and mu recovers in closed form
    np.testing.assert_array_equal(
        h.traction[hold.rows], np.broadcast_to(h.traction[slide1.last_row], (5, 5, 3))
    )
    expected = [recovered(float(mu0[i]), HOLDS[i]) for i in range(HOLDS.size)]
    np.testing.assert_allclose(h.F[hold.last_row], expected, rtol=1e-13)
    np.testing.assert_allclose(h.time[hold.last_row] - h.time[slide1.last_row], HOLDS, rtol=1e-14)
    assert np.all(h.status[hold.first_row : hold.last_row + 1] == Status.STICK)
    peaks = h.friction_ratio[slide2.rows].max(axis=0)
    assert np.all(np.diff(peaks) > 0) and np.all(peaks <= MU_S)
    assert np.all(peaks > h.friction_ratio[slide1.last_row])


def test_one_point_per_run_equals_the_vectorised_run() -> None:
    params = set_a()
    together = simulate(params, slide_hold_slide(0.1, 0.5, HOLDS[:3], steps=100))
    for i, t in enumerate(HOLDS[:3]):
        alone = simulate(params, slide_hold_slide(0.1, 0.5, float(t), steps=100))
        np.testing.assert_allclose(
            alone.traction[:, 0], together.traction[:, i], rtol=1e-14, atol=1e-16
        )


def test_steady_friction_matches_mu_ss_for_per_point_velocities() -> None:
    V = np.array([1e-4, 1e-3, 1e-2, 1e-1, 1.0])
    h = simulate(set_a(), (Slide(velocity=V, distance=5.0, steps=2500),))
    np.testing.assert_allclose(h.friction_ratio[-1], [mu_ss(v) for v in V], rtol=1e-6)
    np.testing.assert_allclose(h.time[-1], 5.0 / V, rtol=1e-12)
    np.testing.assert_allclose(h.R[-1], 1.0, atol=1e-9)


def test_per_point_parameters_sweep() -> None:
    mu_s = np.array([0.35, 0.5, 0.65])
    h = simulate(set_a(mu_s=mu_s, xi=0.0), (Slide(velocity=0.1, distance=8.0, steps=2000),))
    np.testing.assert_allclose(h.friction_ratio[-1], MU_K, rtol=1e-9)  # xi = 0: mu -> mu_k
    peaks = h.friction_ratio.max(axis=0)
    assert np.all(np.diff(peaks) > 0) and np.all(peaks < mu_s)


def test_reverse_is_the_mirror_image_of_sliding_the_other_way() -> None:
    params = set_a()
    h = simulate(params, (Slide(velocity=0.1, distance=0.2, steps=200), Reverse(steps=2000)))
    back = simulate(
        params,
        (Slide(velocity=0.1, distance=0.2, direction_deg=180.0, steps=200), Reverse(steps=2000)),
    )
    np.testing.assert_allclose(h.slip[-1], 0.0, rtol=0, atol=1e-13)  # 2200 summed steps
    np.testing.assert_allclose(back.traction[..., 0], -h.traction[..., 0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(back.F, h.F, rtol=1e-15)
    np.testing.assert_allclose(back.R, h.R, rtol=1e-15)
    first_back = h.segments[1].first_row
    # 1e-4 m steps: elastic unloading (R drops) right after the reversal
    assert h.status[first_back, 0] == Status.STICK
    assert h.R[first_back, 0] < h.R[first_back - 1, 0]


def test_displacement_cycles_turning_points_alternate_and_decay() -> None:
    h = simulate(set_a(), (Cycle(amplitude=0.05, velocity=0.1, cycles=4, steps=400),))
    rows = np.concatenate([[100 + 400 * c, 300 + 400 * c] for c in range(4)])
    tp = h.traction[rows, 0, 0]
    assert np.all(np.sign(tp) == np.tile([1.0, -1.0], 4))
    assert np.all(np.diff(np.abs(tp)) < 0)
    np.testing.assert_allclose(h.slip[rows, 0, 0], np.tile([0.05, -0.05], 4), atol=1e-15)
    assert np.all(np.diff(h.dissipation[:, 0]) >= 0.0)


@pytest.mark.parametrize("steps", [1, 50])
def test_ratcheting_under_traction_cycles_is_exact(steps: int) -> None:
    params = set_a(kappa=0.0, xi=0.0)
    R_max = 0.8
    h = simulate(params, (Traction(traction=(R_max * MU_S, 0.0), cycles=4, steps=steps),))
    assert h.success
    residual = h.slip[2 * steps * np.arange(1, 5), 0, 0]
    per_cycle = np.diff(np.concatenate([[0.0], residual]))
    np.testing.assert_allclose(per_cycle, ratchet_per_cycle(R_max), rtol=1e-9)
    np.testing.assert_allclose(h.traction[steps :: 2 * steps, 0, 0], R_max * MU_S, rtol=1e-12)


def test_traction_control_in_two_directions_reaches_the_target() -> None:
    params = set_a(orthotropy=(1.0, 0.6), rotation=(0.03, -0.02))
    target = np.array([[0.2, 0.1], [-0.1, 0.15]])
    h = simulate(params, (Traction(traction=target, steps=20, duration=5.0),))
    assert h.success and h.n_points == 2
    np.testing.assert_allclose(h.traction[-1, :, :2], target, rtol=1e-11)
    # the slip found is the one that produces the traction: replaying it gives it back
    state = InitialConditions().state(params, 2)
    for k in range(1, h.n_rows):
        du = np.zeros((2, 3))
        du[:, :2] = h.slip[k] - h.slip[k - 1]
        state = update(params, state, du, 0.25).state
    np.testing.assert_allclose(state.traction, h.traction[-1], rtol=1e-11)


def test_unreachable_traction_fails_and_keeps_the_history() -> None:
    h = simulate(
        set_a(),
        (
            Slide(velocity=0.1, distance=0.5, steps=50),
            Traction(traction=(0.6, 0.0), steps=10),
        ),
    )
    assert not h.success
    assert "segment #2 (traction)" in h.message and "gross sliding" in h.message
    assert h.segments[0].last_row == 50  # the slide is complete
    assert h.n_rows >= 51 and np.all(h.friction_ratio[51:, 0] < MU_S)
    assert h.work["refined_for_failure"] >= 1


def test_normal_steps() -> None:
    params = set_a(alpha_n=2500.0)
    prog = (
        Slide(velocity=0.1, distance=1.0, steps=100),
        NormalStep(traction=2.0, steps=4, duration=1.0),
        NormalStep(traction_change=-0.5),
        NormalStep(approach=-2e-3),  # 2e-3 m opening > 1.5 Pa / 2500 Pa/m: separation
        NormalStep(approach=1e-3),  # still open
        NormalStep(traction=1.0),  # re-close onto 1 Pa
    )
    h = simulate(params, prog)
    assert h.success
    ends = [s.last_row for s in h.segments]
    np.testing.assert_allclose(h.traction[ends[1], 0, 2], 2.0, rtol=1e-14)
    np.testing.assert_allclose(h.traction[ends[2], 0, 2], 1.5, rtol=1e-14)
    assert h.status[ends[3], 0] == Status.OPEN and np.all(h.traction[ends[3], 0] == 0.0)
    assert h.status[ends[4], 0] == Status.OPEN
    np.testing.assert_allclose(h.traction[ends[5], 0, 2], 1.0, rtol=1e-12)
    # approach bookkeeping: 1.5 Pa of loading is 6e-4 m; then -2e-3 + 1e-3 m; then re-closing
    np.testing.assert_allclose(h.approach[ends[2], 0], 0.5 / 2500.0, rtol=1e-12)
    np.testing.assert_allclose(h.approach[ends[4], 0], 0.5 / 2500.0 - 1e-3, rtol=1e-12)
    np.testing.assert_allclose(h.slip[ends[5]], h.slip[ends[0]], rtol=0, atol=0)  # no sliding


def test_table_segment_equals_the_same_slide() -> None:
    params = set_a()
    x = np.linspace(0.0, 0.3, 61)
    t = x / 0.05
    table = Table(
        time=t, slip=np.column_stack([x * 0.6, x * 0.8]), normal_traction=np.full(61, 1.0)
    )
    a = simulate(params, (table,))
    b = simulate(
        params,
        (
            Slide(
                velocity=0.05,
                distance=0.3,
                direction_deg=np.degrees(np.arctan2(0.8, 0.6)),
                steps=60,
            ),
        ),
    )
    np.testing.assert_allclose(a.traction, b.traction, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(a.time, b.time, rtol=1e-12)


def _coarse_vs_fine(accuracy: float | None) -> float:
    params = set_a()

    def prog(steps: int) -> tuple:  # type: ignore[type-arg]
        return (
            Slide(velocity=0.1, distance=1.0, steps=50),
            Turn(angle_deg=90.0, distance=0.05, steps=steps),
        )

    fine = simulate(params, prog(8000))
    coarse = simulate(params, prog(8), settings=DriverSettings(accuracy=accuracy))
    assert coarse.success
    rows_f = fine.segments[1].first_row - 1 + 1000 * np.arange(9)
    rows_c = coarse.segments[1].first_row - 1 + np.arange(9)
    return float(np.max(np.abs(coarse.traction[rows_c, 0] - fine.traction[rows_f, 0])))


def test_accuracy_control_makes_a_coarse_run_agree_with_a_fine_run() -> None:
    """A 90 degree turn in 8 steps: step doubling refines it to the fine-step answer."""
    assert _coarse_vs_fine(None) > 1e-3  # the coarse run alone is visibly off
    assert _coarse_vs_fine(1e-5) < 1e-4


def test_accuracy_control_records_its_work() -> None:
    params = set_a(F_integrator="backward_euler")  # first order in the step: refinement needed
    h = simulate(
        params,
        (Slide(velocity=0.1, distance=0.2, steps=4),),
        settings=DriverSettings(accuracy=1e-4),
    )
    assert h.work["refined_for_accuracy"] >= 1
    assert h.work["substeps"] == int(h.substeps.sum()) > 8
    assert h.work["solves"] == int(h.solves.sum()) > h.work["substeps"]
    assert h.work["iterations"] == int(h.iterations.sum()) > 0


def test_failed_local_solves_are_substepped(monkeypatch: pytest.MonkeyPatch) -> None:
    """A law that fails on increments larger than 3e-4 m: the driver halves until it passes."""
    real = stepping.update

    def fragile(params, state, du, dt, raise_on_failure=True):  # type: ignore[no-untyped-def]
        res = real(params, state, du, dt, raise_on_failure=raise_on_failure)
        too_big = np.abs(du[:, 0]) > 3e-4
        if not too_big.any():
            return res
        status = np.where(too_big, Status.FAILED, res.status).astype(np.int8)
        return type(res)(**{**res.__dict__, "status": status})

    monkeypatch.setattr(stepping, "update", fragile)
    h = simulate(set_a(), (Slide(velocity=0.1, distance=0.02, steps=10),))
    monkeypatch.undo()
    fine = simulate(set_a(), (Slide(velocity=0.1, distance=0.02, steps=80),))
    assert h.success and h.work["refined_for_failure"] == 10
    np.testing.assert_array_equal(h.substeps[1:], 8)  # 2e-3 m -> 8 substeps of 2.5e-4 m
    np.testing.assert_allclose(h.traction[1:], fine.traction[8::8], rtol=1e-13)


def test_a_failure_that_substepping_cannot_cure_stops_the_run(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    real = stepping.update

    def broken(params, state, du, dt, raise_on_failure=True):  # type: ignore[no-untyped-def]
        res = real(params, state, du, dt, raise_on_failure=raise_on_failure)
        if state.plastic_slip[0] < 0.01:
            return res
        return type(res)(
            **{**res.__dict__, "status": np.full(state.n_points, Status.FAILED, np.int8)}
        )

    monkeypatch.setattr(stepping, "update", broken)
    h = simulate(
        set_a(),
        (Slide(velocity=0.1, distance=0.1, steps=100),),
        settings=DriverSettings(max_halvings=3),
    )
    assert not h.success and "segment #1 (slide)" in h.message and "local solve" in h.message
    k = h.n_rows - 1
    assert 0 < k < 100 and h.plastic_slip[-1, 0] >= 0.01 > h.plastic_slip[-2, 0]
    assert h.time.shape == (h.n_rows, 1) and h.segments[0].last_row == k


def test_progress_callback_and_input_validation() -> None:
    for compiled, expected in ((False, [(k, 5) for k in range(1, 6)]), (True, [(5, 5)])):
        calls: list[tuple[int, int]] = []  # every step; the compiled loop's blocks of steps
        simulate(
            set_a(),
            (Slide(velocity=0.1, distance=0.01, steps=5),),
            progress=lambda d, t: calls.append((d, t)),  # noqa: B023
            settings=DriverSettings(compiled=compiled),
        )
        assert calls == expected
    with pytest.raises(ParameterError, match="accuracy"):
        simulate(set_a(), (Hold(duration=1.0),), settings=DriverSettings(accuracy=-1.0))
    with pytest.raises(ParameterError, match="number of points"):
        simulate(set_a(mu_s=[0.5, 0.6]), (Hold(duration=[1.0, 2.0, 3.0]),))
    with pytest.raises(ParameterError, match="program"):
        simulate(set_a(), ())


def test_closed_surface_programme() -> None:
    params = SubloadingParams(
        surface="modified_cam_clay", F_s=1.0, F_k=0.6, M=0.5, kappa=1.0, xi=1e-3
    )
    h = simulate(
        params,
        (Slide(velocity=0.1, distance=20.0, steps=4000),),
        InitialConditions(normal_traction=0.2),
    )
    F_ss = (0.1 + 1e-3) / (0.1 / 0.6 + 1e-3 / 1.0)
    assert h.F[-1, 0] == pytest.approx(F_ss, rel=1e-7)
    assert h.friction_ratio[-1, 0] == pytest.approx(0.5 * np.sqrt(F_ss / 0.2 - 1.0), rel=1e-7)
