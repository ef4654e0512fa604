"""The recorder: every k-th step, chosen points, streamed chunks, bounded memory.

References are the every-step history of the same run (``every = 1``, all points),
sliced or reduced here with plain numpy, independently of the recorder's bookkeeping.
"""

from __future__ import annotations

import tracemalloc
from types import SimpleNamespace

import numpy as np
import pytest

from frictionlab.driver import (
    Hold,
    Recording,
    Slide,
    Traction,
    Turn,
    simulate,
    slide_hold_slide,
)
from frictionlab.driver.healing import healing_analysis
from frictionlab.driver.recorder import Recorder
from frictionlab.driver.table import history_chunk
from frictionlab.errors import ParameterError

from .support import set_a

HOLDS = np.array([1.0, 30.0, 1000.0])
#: A 2-D programme (a turn makes the path longer than the chord) with a hold.
PROGRAM = (
    Slide(velocity=0.1, distance=0.05, steps=23),
    Hold(duration=HOLDS, steps=7),
    Turn(angle_deg=60.0, distance=0.04, steps=19),
)


def _expected_steps(counts: list[int], every: int) -> list[int]:
    """Programme steps recorded: 0, then per segment its 1st, every k-th and last step."""
    out, done = [0], 0
    for c in counts:
        out += [done + k for k in range(1, c + 1) if k == 1 or k == c or k % every == 0]
        done += c
    return out


@pytest.mark.parametrize("every", [2, 5, 50])
def test_every_kth_step_is_the_every_step_history_sliced(every: int) -> None:
    full = simulate(set_a(), PROGRAM)
    part = simulate(set_a(), PROGRAM, recording=Recording(every=every))
    steps = _expected_steps([23, 7, 19], every)
    np.testing.assert_array_equal(part.steps, steps)
    for name in ("time", "slip", "approach", "traction", "F", "R", "plastic_slip", "status"):
        np.testing.assert_array_equal(getattr(part, name), getattr(full, name)[steps], name)
    np.testing.assert_array_equal(part.plastic_work, full.plastic_work[steps])
    # segment rows point at their first and last steps
    for a, b in zip(part.segments, full.segments, strict=True):
        assert part.steps[a.first_row] == b.first_row and part.steps[a.last_row] == b.last_row


@pytest.mark.parametrize("every", [3, 1000])
def test_summary_figures_do_not_depend_on_every(every: int) -> None:
    """Running figures are updated on every step: identical bits for every = 1 and k."""
    full = simulate(set_a(), PROGRAM)
    part = simulate(set_a(), PROGRAM, recording=Recording(every=every, points=[0, 2]))
    a, b = full.stats, part.stats
    assert a is not None and b is not None and a.steps == b.steps == 49
    for name in ("peak_friction_ratio", "peak_step", "peak_time", "peak_path_length",
                 "path_length", "time", "slip", "plastic_work"):  # fmt: skip
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), name)
    for sa, sb in zip(full.segments, part.segments, strict=True):
        assert sa.stats is not None and sb.stats is not None
        for name in ("start_friction_ratio", "peak_friction_ratio", "peak_time",
                     "final_friction_ratio", "max_normal_traction"):  # fmt: skip
            np.testing.assert_array_equal(getattr(sa.stats, name), getattr(sb.stats, name))
    assert healing_analysis(full) == healing_analysis(part)


def test_running_figures_match_the_every_step_rows() -> None:
    """Reference: peaks, path length and segment peaks reduced from the full rows by hand
    (the sampled figures: peak_accuracy=None; the refined ones are in test_peaks.py)."""
    h = simulate(set_a(), PROGRAM, peak_accuracy=None)
    st = h.stats
    assert st is not None
    t = h.traction
    ratio = np.hypot(t[..., 0], t[..., 1]) / t[..., 2]
    k = ratio.argmax(axis=0)
    np.testing.assert_array_equal(st.peak_friction_ratio, ratio.max(axis=0))
    np.testing.assert_array_equal(st.peak_step, k)
    path = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(h.slip[:, 0], axis=0).T))])
    np.testing.assert_allclose(st.path_length, path[-1], rtol=1e-13)
    np.testing.assert_allclose(st.peak_path_length, path[k], rtol=1e-13)
    # the turn: the path is longer than the chord |slip|
    assert np.all(st.path_length > np.hypot(*st.slip.T) * 1.01)
    after = h.segments[2]
    seg = after.stats
    assert seg is not None
    rows = ratio[after.first_row : after.last_row + 1]
    np.testing.assert_array_equal(seg.peak_friction_ratio, rows.max(axis=0))
    np.testing.assert_array_equal(seg.start_friction_ratio, ratio[after.first_row - 1])
    peak_rows = after.first_row + rows.argmax(axis=0)
    np.testing.assert_array_equal(seg.peak_time, h.time[peak_rows, np.arange(3)])


def test_chosen_points_are_the_columns_of_the_full_history() -> None:
    full = simulate(set_a(), PROGRAM)
    part = simulate(set_a(), PROGRAM, recording=Recording(points=[0, 2]))
    assert part.n_points == 2 and part.stats is not None and part.stats.time.shape == (3,)
    np.testing.assert_array_equal(part.point_numbers, [1, 3])
    np.testing.assert_array_equal(part.traction, full.traction[:, [0, 2]])
    np.testing.assert_array_equal(part.point(1)["F"], full.point(2)["F"])


def test_streamed_chunks_are_the_recorded_rows() -> None:
    chunks: list[dict[str, np.ndarray]] = []

    def sink(chunk: dict[str, np.ndarray]) -> None:
        chunks.append({k: np.array(v, copy=True) for k, v in chunk.items()})

    full = simulate(set_a(), PROGRAM, recording=Recording(every=4))
    streamed = simulate(set_a(), PROGRAM, recording=Recording(every=4, sink=sink, chunk_rows=5))
    assert all(len(c["step"]) <= 5 for c in chunks)
    reference = history_chunk(full)
    for key in ("step", "segment", "kind", "time", "traction", "plastic_work", "iterations"):
        joined = np.concatenate([c[key] for c in chunks])
        np.testing.assert_array_equal(joined, reference[key], key)
    np.testing.assert_array_equal(streamed.traction, full.traction)  # no keep_rows: all kept


def test_the_last_completed_step_of_a_failed_run_is_recorded() -> None:
    prog = (
        Slide(velocity=0.1, distance=0.5, steps=50),
        Traction(traction=(0.6, 0.0), steps=10),
    )
    full = simulate(set_a(), prog)
    part = simulate(set_a(), prog, recording=Recording(every=7))
    assert not full.success and not part.success
    last = full.n_rows - 1
    assert part.steps[-1] == last
    np.testing.assert_array_equal(part.traction[-1], full.traction[-1])


def test_plastic_work_is_the_dissipation_column() -> None:
    h = simulate(set_a(rotation=(0.2, 0.0)), PROGRAM)
    assert h.plastic_work is h.dissipation
    cols = history_chunk(h)
    np.testing.assert_array_equal(cols["plastic_work"], h.dissipation)


@pytest.mark.parametrize(
    ("recording", "field"),
    [
        (Recording(every=0), "every"),
        (Recording(every=1.5), "every"),  # type: ignore[arg-type]
        (Recording(points=[3]), "points"),
        (Recording(points=[-1]), "points"),
        (Recording(points=[1, 1]), "points"),
        (Recording(points=[2, 0]), "points"),
        (Recording(points=[]), "points"),
        (Recording(points=[True]), "points"),
        (Recording(chunk_rows=0), "chunk_rows"),
        (Recording(keep_rows=1), "keep_rows"),
    ],
)
def test_bad_recordings_are_refused_before_any_step(recording: Recording, field: str) -> None:
    with pytest.raises(ParameterError) as info:
        simulate(set_a(), PROGRAM, recording=recording)
    assert info.value.field == field


# ------------------------------------------------------------------ bounded memory
def _state(x: float) -> SimpleNamespace:
    t = np.array([[x, 0.0, 1.0]])
    return SimpleNamespace(n_points=1, traction=t, F=np.ones(1), R=np.ones(1), plastic_slip=t[:, 0])


def _drive(steps: int, chunk: int, keep: int) -> tuple[Recorder, int, int]:
    """Drive a recorder with ``steps`` synthetic steps (3 segments), streaming every row."""
    written = [0]

    def sink(c: dict[str, np.ndarray]) -> None:
        written[0] += len(c["step"])

    rec = Recorder(_state(0.0), Recording(sink=sink, chunk_rows=chunk, keep_rows=keep))
    du, zero = np.array([[1e-6, 0.0, 0.0]]), np.zeros(1)
    status, iters = np.zeros(1, np.int8), np.zeros(1, np.int64)
    per_segment = steps // 3
    tracemalloc.start()
    base = tracemalloc.get_traced_memory()[0]
    for s in range(3):
        rec.begin_segment(s + 1, "slide")
        for k in range(per_segment):
            state = _state(0.3 + 1e-3 * np.sin(k))
            rec.add(state, 0.01, du, zero, status, 1, 1, iters, k == per_segment - 1)
        rec.end_segment()
    peak = tracemalloc.get_traced_memory()[1] - base
    tracemalloc.stop()
    rows = rec.finish()
    assert written[0] == 3 * per_segment + 1  # every recorded row went to the sink
    assert rows["step"].size <= keep + 6 and rows["step"][-1] == 3 * per_segment
    return rec, peak, written[0]


@pytest.mark.slow
def test_the_recorders_memory_does_not_grow_with_the_step_count() -> None:
    """Held rows never exceed chunk + keep (+ segment ends); traced memory stays flat.

    A million-step run at ~0.7 ms per driver step would take minutes, so the recorder is
    driven directly with synthetic states: 600 and 1.8e4 steps (30 times more). The
    bound on held rows does not involve the step count, so it holds for 1e6 steps too.
    """
    chunk, keep = 64, 200
    small, peak_small, _ = _drive(600, chunk, keep)
    large, peak_large, _ = _drive(18_000, chunk, keep)
    for rec in (small, large):
        assert rec.max_held_rows <= chunk + keep + 6
    assert large.thinned
    # a list-of-rows recorder would hold 30x more (>> 1 MB here); allow only small noise
    assert peak_large < peak_small + 64 * 1024, (peak_small, peak_large)


def test_a_slide_hold_slide_sweep_keeps_its_healing_analysis_when_thinned() -> None:
    prog = slide_hold_slide(0.1, 1.0, HOLDS, steps=200, hold_steps=4)
    full = simulate(set_a(), prog)
    thin = simulate(set_a(), prog, recording=Recording(sink=lambda c: None, keep_rows=20))
    assert thin.thinned and thin.n_rows < 60
    assert healing_analysis(thin) == healing_analysis(full)


@pytest.mark.parametrize("chunk", [1, 2, 3, 4, 5])
def test_a_failed_run_thinned_in_memory_still_ends_on_its_last_step(chunk: int) -> None:
    """Whatever chunk boundary the failure falls on, the last completed step stays."""
    prog = (
        Slide(velocity=0.1, distance=0.5, steps=50),
        Traction(traction=(0.6, 0.0), steps=10),
    )
    full = simulate(set_a(), prog)
    rec = Recording(every=3, sink=lambda c: None, chunk_rows=chunk, keep_rows=4)
    thin = simulate(set_a(), prog, recording=rec)
    assert thin.steps[-1] == full.n_rows - 1
    for seg in thin.segments:
        assert thin.steps[seg.last_row] == seg.stats.last_step  # type: ignore[union-attr]
        assert thin.steps[seg.first_row] == seg.stats.first_step  # type: ignore[union-attr]


def test_a_run_stopped_on_a_recorded_step_keeps_it_when_thinning() -> None:
    """The stop falls on a regular recorded row already handed on and thinned away."""
    rec = Recorder(_state(0.0), Recording(every=3, sink=lambda c: None, chunk_rows=1, keep_rows=2))
    du, zero = np.array([[1e-6, 0.0, 0.0]]), np.zeros(1)
    status, iters = np.zeros(1, np.int8), np.zeros(1, np.int64)
    rec.begin_segment(1, "slide")
    for k in range(12):  # steps 1..12 of 20 planned; recorded: 1, 3, 6, 9, 12
        rec.add(_state(0.1 * k), 0.01, du, zero, status, 1, 1, iters, False)
    seg = rec.end_segment()  # the run stopped here (a failed step 13)
    rows = rec.finish()
    assert seg is not None and seg.last_step == 12
    assert rows["step"][-1] == 12 and rows["_end"][-1] == 1
    np.testing.assert_array_equal(rows["traction"][-1], _state(1.1).traction)
