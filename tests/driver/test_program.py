"""Loading-programme segments: validation, inherited defaults, step plans (issue 3)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.driver import (
    Cycle,
    Hold,
    NormalStep,
    Reverse,
    Slide,
    Table,
    Traction,
    Turn,
    plan_program,
    slide_hold_slide,
)
from frictionlab.driver.program import Control, program_points
from frictionlab.errors import ParameterError


def controls(plan, start=None, n=1):  # type: ignore[no-untyped-def]
    start = np.array([[0.0, 0.0, 1.0]] * n) if start is None else start
    steps = plan.begin(start)
    return [plan.control(k) for k in range(steps)]


@pytest.mark.parametrize(
    ("make", "field"),
    [
        (lambda: Slide(velocity=0.0, distance=1.0), "velocity"),
        (lambda: Slide(velocity=-1.0, distance=1.0), "velocity"),
        (lambda: Slide(velocity=0.1), "slide length"),
        (lambda: Slide(velocity=0.1, distance=1.0, duration=2.0), "slide length"),
        (lambda: Slide(velocity=0.1, distance=float("nan")), "distance"),
        (lambda: Slide(velocity=0.1, distance=1.0, steps=0), "steps"),
        (lambda: Slide(velocity=0.1, distance=1.0, steps=2.5), "steps"),  # type: ignore[arg-type]
        (lambda: Slide(velocity=0.1, distance=1.0, steps=10, max_step=0.1), "steps"),
        (lambda: Slide(velocity=0.1, distance=1.0, max_step=-1.0), "max_step"),
        (lambda: Slide(velocity="fast", distance=1.0), "velocity"),
        (lambda: Hold(duration=-1.0), "duration"),
        (lambda: Cycle(amplitude=0.0, velocity=0.1), "amplitude"),
        (lambda: Cycle(amplitude=0.1, velocity=0.1, cycles=0), "cycles"),
        (lambda: Cycle(amplitude=0.1, velocity=0.1, steps=3), "steps"),
        (lambda: NormalStep(), "normal"),
        (lambda: NormalStep(approach=1e-3, traction=2.0), "normal"),
        (lambda: NormalStep(traction=-1.0), "traction"),
        (lambda: Traction(traction=(0.1, 0.2, 0.3)), "traction"),
        (lambda: Table(time=[0.0], slip=[[0.0, 0.0]]), "time"),
        (lambda: Table(time=[0.0, 1.0, 0.5], slip=np.zeros((3, 2))), "time"),
        (lambda: Table(time=[0.0, 1.0], slip=np.zeros((3, 2))), "slip"),
        (
            lambda: Table(time=[0.0, 1.0], slip=np.zeros((2, 2)), normal_traction=[1.0, 0.0]),
            "normal_traction",
        ),
    ],
)
def test_invalid_segments_name_the_field(make, field: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ParameterError) as info:
        make()
    assert info.value.field == field


def test_slide_steps_and_increments() -> None:
    [plan] = plan_program((Slide(velocity=0.2, distance=1.0, direction_deg=90.0, steps=4),), 1)
    cs = controls(plan)
    assert len(cs) == 4
    np.testing.assert_allclose(cs[0].du_t, [[0.0, 0.25]], rtol=0, atol=1e-17)
    np.testing.assert_allclose(cs[0].dt, [1.25], rtol=1e-15)  # 0.25 m at 0.2 m/s
    np.testing.assert_array_equal(cs[0].du_n, [0.0])


def test_duration_and_max_step() -> None:
    [plan] = plan_program((Slide(velocity=[0.1, 0.3], duration=2.0, max_step=0.07),), 2)
    cs = controls(plan, n=2)
    assert len(cs) == math.ceil(0.6 / 0.07)  # the fastest point sets the count
    np.testing.assert_allclose(cs[0].du_t[:, 0] * len(cs), [0.2, 0.6], rtol=1e-14)
    np.testing.assert_allclose(cs[0].dt * len(cs), [2.0, 2.0], rtol=1e-14)


def test_reverse_inherits_velocity_and_distance_and_returns_to_the_start() -> None:
    plans = plan_program(
        (Slide(velocity=0.1, distance=0.3, direction_deg=30.0, steps=3), Reverse()), 1
    )
    total = sum(c.du_t for p in plans for c in controls(p))
    np.testing.assert_allclose(total, [[0.0, 0.0]], rtol=0, atol=1e-14)  # 103 summed steps
    assert plans[1].resolved["velocity"][0] == 0.1 and plans[1].resolved["steps"] == 100
    np.testing.assert_allclose(plans[1].resolved["direction_deg"], [210.0], rtol=1e-14)


def test_reverse_without_a_preceding_slide_is_rejected() -> None:
    with pytest.raises(ParameterError, match=r"segment #1 \(reverse\) velocity"):
        plan_program((Reverse(),), 1)
    with pytest.raises(ParameterError, match=r"segment #2 \(turn\) distance"):
        plan_program((Cycle(amplitude=0.1, velocity=0.1), Turn(angle_deg=90.0)), 1)


def test_turn_is_relative_to_the_current_direction() -> None:
    prog = (Slide(velocity=0.1, distance=1.0, direction_deg=45.0), Turn(angle_deg=90.0),
            Slide(velocity=0.1, distance=1.0))  # fmt: skip
    plans = plan_program(prog, 1)
    np.testing.assert_allclose(plans[1].resolved["direction_deg"], [135.0], rtol=1e-14)
    np.testing.assert_allclose(plans[2].resolved["direction_deg"], [135.0], rtol=1e-14)


def test_cycle_is_a_triangle_wave_about_the_start() -> None:
    [plan] = plan_program((Cycle(amplitude=0.05, velocity=0.1, cycles=2, steps=10),), 1)
    cs = controls(plan)
    assert len(cs) == 2 * 12  # 10 rounded up to a multiple of 4
    position = np.cumsum([c.du_t[0, 0] for c in cs])
    np.testing.assert_allclose(
        position[[2, 8, 11, 14, 20, 23]], [0.05, -0.05, 0.0, 0.05, -0.05, 0.0], atol=1e-15
    )
    assert position.max() == pytest.approx(0.05, rel=1e-14)


def test_traction_control_cycles_go_to_the_target_and_back() -> None:
    [plan] = plan_program((Traction(traction=(0.4, 0.2), cycles=2, steps=4),), 1)
    cs = controls(plan, start=np.array([[0.1, 0.0, 1.0]]))
    targets = np.array([c.ft_target[0] for c in cs])  # type: ignore[index]
    assert len(cs) == 16
    np.testing.assert_allclose(targets[3], [0.4, 0.2], rtol=1e-15)
    np.testing.assert_allclose(targets[7], [0.1, 0.0], atol=1e-16)
    np.testing.assert_allclose(targets[0], [0.175, 0.05], rtol=1e-14)


def test_traction_control_max_step_is_resolved_at_the_segment_start() -> None:
    [plan] = plan_program((Traction(traction=(0.35, 0.0), max_step=0.1),), 1)
    assert plan.begin(np.array([[0.05, 0.0, 1.0]])) == 3


def test_normal_step_targets() -> None:
    [plan] = plan_program((NormalStep(traction_change=0.5, steps=2, duration=4.0),), 1)
    cs = controls(plan, start=np.array([[0.2, 0.0, 1.0]]))
    np.testing.assert_allclose([c.fn_target[0] for c in cs], [1.25, 1.5], rtol=1e-15)  # type: ignore[index]
    np.testing.assert_allclose(cs[0].dt, [2.0], rtol=1e-15)
    with pytest.raises(ParameterError, match="traction_change"):
        [bad] = plan_program((NormalStep(traction_change=-2.0),), 1)
        bad.begin(np.array([[0.0, 0.0, 1.0]]))


def test_table_rows_and_normal_traction_interpolation() -> None:
    seg = Table(time=[0.0, 1.0, 3.0], slip=[[0.5, 0.0], [0.6, 0.0], [0.6, 0.2]],
                normal_traction=[9.0, 2.0, 3.0], steps_per_row=2)  # fmt: skip
    [plan] = plan_program((seg,), 1)
    cs = controls(plan, start=np.array([[0.0, 0.0, 1.0]]))
    assert len(cs) == 4
    np.testing.assert_allclose(sum(c.du_t for c in cs), [[0.1, 0.2]], rtol=1e-14)
    np.testing.assert_allclose([c.dt[0] for c in cs], [0.5, 0.5, 1.0, 1.0], rtol=1e-15)
    # row 0's normal traction is replaced by the current one (1.0): 1 -> 2 -> 3
    np.testing.assert_allclose([c.fn_target[0] for c in cs], [1.5, 2.0, 2.5, 3.0], rtol=1e-15)  # type: ignore[index]


def test_halves_split_slip_time_and_interpolate_targets() -> None:
    c = Control(np.array([2.0]), np.array([[0.2, 0.0]]), np.array([0.1]),
                ft_target=np.array([[0.4, 0.0]]), fn_target=np.array([3.0]))  # fmt: skip
    a, b = c.halves(np.array([[0.0, 0.2, 1.0]]))
    np.testing.assert_allclose(a.dt + b.dt, c.dt, rtol=1e-15)
    np.testing.assert_allclose(a.du_t + b.du_t, c.du_t, rtol=1e-15)
    np.testing.assert_allclose(a.ft_target, [[0.2, 0.1]], rtol=1e-15)  # type: ignore[arg-type]
    np.testing.assert_allclose(a.fn_target, [2.0], rtol=1e-15)  # type: ignore[arg-type]
    np.testing.assert_array_equal(b.ft_target, c.ft_target)  # type: ignore[arg-type]


def test_per_point_sizes_must_agree() -> None:
    prog = (Slide(velocity=[0.1, 0.2], distance=1.0), Hold(duration=[1.0, 2.0, 3.0]))
    assert program_points(prog) == {2, 3}
    with pytest.raises(ParameterError, match="segment #2"):
        plan_program(prog, 2)


def test_segments_do_not_keep_references_to_caller_arrays() -> None:
    durations = np.array([1.0, 2.0])
    seg = Hold(duration=durations)
    durations[0] = 99.0
    assert seg.duration[0] == 1.0 and not seg.duration.flags.writeable


def test_slide_hold_slide_builder() -> None:
    prog = slide_hold_slide(0.1, 1.0, [10.0, 100.0], steps=100)
    assert [s.kind for s in prog] == ["slide", "hold", "slide"]
    assert prog[2].distance == pytest.approx(0.3) and prog[2].steps == 30


def test_traction_legs_end_exactly_on_their_targets() -> None:
    """From f_t = (1, 0) Pa to (1e-17, 0): ``a + s (b - a)`` would end at 0 (1 + (1e-17 - 1)
    rounds to 0); each leg must end on its target exactly, and the return leg on the start."""
    [plan] = plan_program((Traction(traction=(1e-17, 0.0), steps=3, cycles=2),), 1)
    steps = plan.begin(np.array([[1.0, 0.0, 5.0]]))
    ends = [plan.control(k).ft_target for k in (2, 5, 8, 11)]
    assert steps == 12
    assert [e[0, 0] for e in ends] == [1e-17, 1.0, 1e-17, 1.0]
