"""Run a loading programme through the law: :func:`simulate` -> :class:`History`.

Every recorded step is one step of a segment's plan (see
:mod:`frictionlab.driver.program`); inside it the driver substeps automatically where
the local solve fails or where a requested ``accuracy`` is not met (step doubling, see
:mod:`frictionlab.driver.stepping`). N points run together in one vectorised programme,
with per-point parameters and per-point segment values.

Array layout of :class:`History`: **time first**, ``(rows, N, ...)``; by default every
step is recorded, ``rows = steps + 1`` (row 0 is the initial state); a
:class:`~frictionlab.driver.recorder.Recording` records every k-th step or chosen points
and can stream the rows to a sink (``History.steps`` gives each row's step).
``History.point(i)`` gives the 1-D series of one point. Peaks, path lengths and
per-segment figures over every step are in ``History.stats`` and ``SegmentRecord.stats``.

Physics only: no file I/O and no printing; progress goes to an optional callback.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from frictionlab.driver import stepping
from frictionlab.driver.compiled_steps import compiled_steps
from frictionlab.driver.extrema import (
    DEFAULT_PEAK_ACCURACY,
    PeakTracker,
    RefinedPeaks,
    check_peak_accuracy,
)
from frictionlab.driver.program import (
    NormalStep,
    Segment,
    Table,
    _NormalPlan,
    plan_program,
    program_points,
)
from frictionlab.driver.recorder import Recorder, Recording, RunStats, SegmentStats
from frictionlab.driver.stepping import OutputPool, StepWork, advance
from frictionlab.errors import ParameterError
from frictionlab.subloading import (
    ContactState,
    Status,
    SubloadingParams,
    check_snap_back,
    initial_state,
)
from frictionlab.subloading.state import _snap_back_failures

__all__ = [
    "STATUS_INITIAL",
    "DriverSettings",
    "History",
    "InitialConditions",
    "ProgressCallback",
    "Recording",
    "RunStats",
    "SegmentRecord",
    "count_points",
    "simulate",
    "status_labels",
]

_STATE_ARRAYS = ("traction", "F", "R", "plastic_slip", "gap")  # a state's arrays but its frame
#: Status code of row 0 (the initial state) in :attr:`History.status`.
STATUS_INITIAL = -1
_LABELS = {STATUS_INITIAL: "initial", **{int(s): s.name.lower() for s in Status}}

#: ``progress(done, total)``: steps done and total steps (the total can grow when a
#: traction-controlled segment with ``max_step`` starts).
ProgressCallback = Callable[[int, int], None]


_CODES = np.array(sorted(_LABELS))
_TEXTS = np.array([_LABELS[int(c)] for c in _CODES], dtype=object)


def status_labels(status: np.ndarray) -> np.ndarray:
    """Text labels (``initial``, ``stick``, ``slip``, ``open``, ``failed``) of status codes
    (one table look-up per array; KeyError for an unknown code)."""
    codes = np.asarray(status, dtype=int)
    pos = np.searchsorted(_CODES, codes).clip(0, len(_CODES) - 1)
    unknown = _CODES[pos] != codes
    if unknown.any():
        raise KeyError(int(codes[unknown].flat[0]))
    return _TEXTS[pos]


@dataclass(frozen=True)
class InitialConditions:
    """The contact before the programme starts (a virgin, fully recovered contact by default).

    ``normal_traction`` [Pa] > 0, scalar or (N,); ``tangential_traction`` (f_t1, f_t2) [Pa],
    shape (2,) or (N, 2); ``F`` the initial size (mu for the cone), default the static
    value. See :func:`frictionlab.subloading.initial_state`.
    """

    normal_traction: Any = 1.0
    tangential_traction: Any = (0.0, 0.0)
    F: Any = None

    def sizes(self) -> set[int]:
        out = set()
        fn = np.asarray(self.normal_traction)
        ft = np.asarray(self.tangential_traction)
        if fn.ndim == 1:
            out.add(fn.shape[0])
        if ft.ndim == 2:
            out.add(ft.shape[0])
        if self.F is not None and np.ndim(self.F) == 1:
            out.add(int(np.shape(self.F)[0]))
        return out

    def state(self, params: SubloadingParams, n_points: int) -> ContactState:
        return initial_state(
            params,
            self.normal_traction,
            self.tangential_traction,
            F=self.F,
            n_points=n_points,
        )


@dataclass(frozen=True)
class SegmentRecord:
    """Where a segment sits in a :class:`History`.

    ``index`` is 1-based (as ``[[program]] #index``); rows ``first_row..last_row``
    (inclusive) are its recorded steps, row ``first_row - 1`` is the state it started
    from. ``resolved`` holds its values with every default filled (arrays (N,)).
    ``stats``: its start, peak and final figures over every step (not only the recorded
    ones) for every point; None for histories built without them.
    """

    index: int
    kind: str
    first_row: int
    last_row: int
    resolved: dict[str, Any]
    is_hold: bool = False
    stats: SegmentStats | None = None

    @property
    def rows(self) -> slice:
        """Rows of the segment including the starting row."""
        return slice(self.first_row - 1, self.last_row + 1)


@dataclass(frozen=True)
class History:
    """The recorded response of N points to a programme (time first: ``(rows, N, ...)``).

    Attributes
    ----------
    time:
        (rows, N) time [s] (per point: per-point velocities give per-point times).
    slip:
        (rows, N, 2) imposed tangential slip (counter body relative to body) in the
        contact frame, accumulated from 0 [m].
    approach:
        (rows, N) accumulated normal approach [m] (positive closes).
    traction:
        (rows, N, 3) (f_t1, f_t2, f_n) [Pa]; f_n > 0 in compression.
    F, R:
        (rows, N) size of the sliding-yield surface (mu for the cone) and the normal
        sliding-yield ratio.
    plastic_slip:
        (rows, N) accumulated plastic slip u^p [m].
    dissipation:
        (rows, N) accumulated plastic work sum of f . Delta u^p [J/m^2]: >= 0 without a
        rotation vector; with beta != 0 the term f_n beta . Delta u^p can make it negative.
        Deprecated name: use :attr:`plastic_work` (the same array).
    status:
        (rows, N) :class:`~frictionlab.subloading.Status` code of each step (OPEN when
        the step ends open, else SLIP if any substep slid); row 0 holds ``STATUS_INITIAL`` (-1).
    segment:
        (rows,) 1-based segment index of each row (0 for the initial row).
    substeps, solves:
        (rows,) substeps taken and calls of the law's update for each step.
    iterations:
        (rows, N) local Newton iterations of each step (all solves, rejected ones too).
    segments:
        One :class:`SegmentRecord` per segment reached.
    final_state:
        The :class:`~frictionlab.subloading.ContactState` after the last recorded step.
    success, message:
        Whether the whole programme ran; why not otherwise (the history then stops at
        the last completed step).
    work:
        Totals: steps, substeps, solves, iterations, steps refined for a failed local solve
        or for accuracy, steps where the accuracy could not be met, and the law calls of
        the peak refinement (``peak_solves``).
    extra, extra_units:
        Additional (rows, N) series with their units (the spring-slider's load point,
        slider velocity and spring force).
    warnings:
        One line per segment that reached, by approach or sliding, a normal traction at
        which the no-snap-back condition fails: the local solution may not be unique there.
    step:
        (rows,) the programme step of each row (0 for the initial state); None means
        every step was recorded (row = step).
    points:
        0-based indices of the recorded points, or None for all: the arrays' N axis then
        holds these points only.
    stats:
        :class:`~frictionlab.driver.recorder.RunStats`: peaks, path length and final
        values over every step and every point (None for histories built without them).
    thinned:
        True when rows were dropped beyond the recording's ``every`` to bound the memory
        (a run streamed to a sink with ``keep_rows``): these rows suit plots, not analysis.
    peaks:
        :class:`~frictionlab.driver.extrema.RefinedPeaks`: the segment peaks located between
        steps (``peak_accuracy``); ``stats`` and the segments' stats report these values.
        The recorded rows stay on the step grid.
    """

    time: np.ndarray
    slip: np.ndarray
    approach: np.ndarray
    traction: np.ndarray
    F: np.ndarray
    R: np.ndarray
    plastic_slip: np.ndarray
    dissipation: np.ndarray
    status: np.ndarray
    segment: np.ndarray
    substeps: np.ndarray
    solves: np.ndarray
    iterations: np.ndarray
    segments: tuple[SegmentRecord, ...]
    final_state: ContactState
    success: bool
    message: str
    work: dict[str, int]
    extra: dict[str, np.ndarray] = field(default_factory=dict)
    extra_units: dict[str, str] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    step: np.ndarray | None = None
    points: np.ndarray | None = None
    stats: RunStats | None = None
    thinned: bool = False
    peaks: RefinedPeaks = field(default_factory=RefinedPeaks.empty)

    @property
    def plastic_work(self) -> np.ndarray:
        """(rows, N) accumulated plastic work sum of f . Delta u^p [J/m^2] (may be < 0)."""
        return self.dissipation

    @property
    def steps(self) -> np.ndarray:
        """(rows,) the programme step of each row."""
        return np.arange(self.n_rows) if self.step is None else self.step

    @property
    def point_numbers(self) -> np.ndarray:
        """(N,) 1-based numbers of the recorded points."""
        return (np.arange(self.n_points) if self.points is None else self.points) + 1

    @property
    def n_points(self) -> int:
        return int(self.traction.shape[1])

    @property
    def n_rows(self) -> int:
        return int(self.traction.shape[0])

    @property
    def friction_ratio(self) -> np.ndarray:
        """(rows, N) |f_t| / f_n (0 where the contact is open)."""
        ft = np.hypot(self.traction[..., 0], self.traction[..., 1])
        fn = self.traction[..., 2]
        return np.where(fn > 0, ft / np.where(fn > 0, fn, 1.0), 0.0)

    @property
    def path_length(self) -> np.ndarray:
        """(rows, N) tangential slip distance travelled (sum of |Delta slip|) [m].

        Summed over the recorded rows: with ``every > 1`` a curved path is cut short;
        ``stats.path_length`` sums every step.
        """
        steps = np.hypot(*np.moveaxis(np.diff(self.slip, axis=0), -1, 0))
        return np.concatenate([np.zeros((1, self.n_points)), np.cumsum(steps, axis=0)])

    @property
    def is_planar(self) -> bool:
        """True when slip and traction stay on the e_1 axis (a 1-D programme)."""
        return bool(np.all(self.slip[..., 1] == 0.0) and np.all(self.traction[..., 1] == 0.0))

    def __repr__(self) -> str:
        return (
            f"History({self.n_points} points x {self.n_rows} rows, "
            f"{len(self.segments)} segments, success={self.success})"
        )

    def to_dataframe(self, cone: bool = True) -> Any:
        """The history as a long-format :class:`pandas.DataFrame`, as in ``history.csv``.

        One row per point and recorded step (point-major); titles ``name [unit]``
        (``time [s]``, ``traction_1 [Pa]``, ...). ``cone=False`` gives F in Pa (closed
        sliding-yield surfaces). pandas is imported on call.
        """
        from frictionlab.driver.table import history_dataframe

        return history_dataframe(self, cone)

    def point(self, i: int) -> dict[str, np.ndarray]:
        """The series of point ``i`` as 1-D arrays (vectors split into components)."""
        out = {
            "time": self.time[:, i],
            "slip_1": self.slip[:, i, 0],
            "slip_2": self.slip[:, i, 1],
            "approach": self.approach[:, i],
            "traction_1": self.traction[:, i, 0],
            "traction_2": self.traction[:, i, 1],
            "traction_n": self.traction[:, i, 2],
            "friction_ratio": self.friction_ratio[:, i],
            "R": self.R[:, i],
            "F": self.F[:, i],
            "plastic_slip": self.plastic_slip[:, i],
            "plastic_work": self.dissipation[:, i],
            "dissipation": self.dissipation[:, i],
            "status": self.status[:, i],
        }
        for key, arr in self.extra.items():
            out[key] = arr[:, i]
        return out


def count_points(
    params: SubloadingParams,
    program: Sequence[Segment] = (),
    initial: InitialConditions | ContactState | None = None,
    n_points: int | None = None,
    extra_sizes: set[int] | None = None,
) -> int:
    """The number of points N implied by every per-point input (ParameterError if they disagree)."""
    sizes = set(extra_sizes or ()) | program_points(program)
    if params.per_point:
        sizes.add(params.n_points)
    if isinstance(initial, ContactState):
        sizes.add(initial.n_points)
    elif initial is not None:
        sizes |= initial.sizes()
    if n_points is not None:
        if isinstance(n_points, bool) or not isinstance(n_points, int) or n_points < 1:
            raise ParameterError("n_points", n_points, "an integer >= 1")
        sizes.add(n_points)
    if len(sizes) > 1:
        raise ParameterError(
            "number of points", sorted(sizes), "one common N for every per-point value"
        )
    return sizes.pop() if sizes else 1


def _history_from_rows(rows: dict[str, np.ndarray], rec: Recorder, **kw: Any) -> History:
    """A :class:`History` from the recorder's kept rows."""
    return History(
        time=rows["time"],
        slip=rows["slip"],
        approach=rows["approach"],
        traction=rows["traction"],
        F=rows["F"],
        R=rows["R"],
        plastic_slip=rows["plastic_slip"],
        dissipation=rows["plastic_work"],
        status=rows["status"],
        segment=rows["segment"],
        substeps=rows["substeps"],
        solves=rows["solves"],
        iterations=rows["iterations"],
        step=rows["step"],
        points=rec.kept_points,
        stats=rec.stats,
        thinned=rec.thinned,
        **kw,
    )


def _count_work(work: dict[str, int], w: StepWork, completed: bool = True) -> None:
    """Add one step's counters to the totals (a failed step counts its solves too)."""
    work["steps"] += int(completed)
    work["substeps"] += w.substeps
    work["solves"] += w.solves
    work["iterations"] += int(w.iterations.sum())
    work["refined_for_failure"] += int(w.refined_for_failure)
    work["refined_for_accuracy"] += int(w.refined_for_accuracy)
    work["accuracy_unmet"] += int(w.accuracy_unmet)


#: The deepest substepping: 2**-60 of a step is below the float64 resolution of its
#: time (2**-52 relative), so deeper halvings only spend time.
MAX_HALVINGS = 60


def _check_accuracy(accuracy: float | None, max_halvings: int) -> None:
    if accuracy is not None and not (isinstance(accuracy, int | float) and accuracy > 0):
        raise ParameterError("accuracy", accuracy, "a number > 0 (or None: no accuracy control)")
    if (
        isinstance(max_halvings, bool)
        or not isinstance(max_halvings, int)
        or not 0 <= max_halvings <= MAX_HALVINGS
    ):
        raise ParameterError("max_halvings", max_halvings, f"an integer from 0 to {MAX_HALVINGS}")


@dataclass(frozen=True)
class DriverSettings:
    """How the driver integrates a programme (``settings=`` of :func:`simulate` and
    :func:`~frictionlab.driver.simulate_spring_slider`).

    ``accuracy``: when given, a step is accepted only when one full step and two half
    steps agree to within it (friction-ratio units for tractions, and for R and F/F_s;
    :func:`~frictionlab.driver.stepping.step_error`); ``max_halvings``: the deepest
    substepping, at most ``2**max_halvings`` substeps per step. ``compiled``: run the
    steps of segments that prescribe no traction in one compiled loop where the run
    allows it (:mod:`~frictionlab.driver.compiled_steps`: the same numbers as the Python
    steps), and the peak refinement's step doubling in one compiled call; False runs
    every step and every refinement trial in Python (the reference).
    """

    accuracy: float | None = None
    max_halvings: int = 10
    compiled: bool = True

    def __post_init__(self) -> None:
        _check_accuracy(self.accuracy, self.max_halvings)
        if not isinstance(self.compiled, bool):
            raise ParameterError("compiled", self.compiled, "true or false")


#: Marks a deprecated keyword that was not passed.
_UNSET: Any = object()


def driver_settings(
    settings: DriverSettings | None, accuracy: Any, max_halvings: Any, where: str
) -> DriverSettings:
    """``settings``, or one built from the deprecated ``accuracy=``/``max_halvings=``
    keywords (a DeprecationWarning; passing both forms is an error)."""
    given = {k: v for k, v in (("accuracy", accuracy), ("max_halvings", max_halvings))
             if v is not _UNSET}  # fmt: skip
    if not given:
        return settings if settings is not None else DriverSettings()
    if settings is not None:
        raise ParameterError(
            f"{where}: {', '.join(given)}", list(given.values()), "settings= alone"
        )
    import warnings

    warnings.warn(
        f"{where}({', '.join(f'{k}=' for k in given)}) is deprecated: pass "
        f"settings=DriverSettings({', '.join(f'{k}=...' for k in given)})",
        DeprecationWarning,
        stacklevel=3,
    )
    return DriverSettings(**given)


def simulate(
    params: SubloadingParams,
    program: Sequence[Segment],
    initial: InitialConditions | ContactState | None = None,
    *,
    n_points: int | None = None,
    settings: DriverSettings | None = None,
    progress: ProgressCallback | None = None,
    recording: Recording | None = None,
    accuracy: Any = _UNSET,
    max_halvings: Any = _UNSET,
    peak_accuracy: float | None = DEFAULT_PEAK_ACCURACY,
) -> History:
    """Run ``program`` for N contact points and record its steps.

    Parameters
    ----------
    params:
        Law parameters, shared or per point.
    program:
        Segments (see :mod:`frictionlab.driver.program`).
    initial:
        :class:`InitialConditions` (default: f_n = 1 Pa, virgin contact) or a
        :class:`~frictionlab.subloading.ContactState` to continue from.
    n_points:
        N, when it does not follow from per-point inputs.
    settings:
        :class:`DriverSettings` (accuracy control, deepest substepping); default
        ``DriverSettings()``.
    accuracy, max_halvings:
        Deprecated (one release): use ``settings=DriverSettings(...)``.
    progress:
        ``progress(done, total)`` after every step (after every block of at most
        :data:`~frictionlab.driver.compiled_steps.PROGRESS_STEPS` steps of the compiled loop).
    recording:
        Which steps and points to record and where the rows go (a streaming ``sink``);
        default: every step of every point, kept in memory. See
        :class:`~frictionlab.driver.recorder.Recording`.
    peak_accuracy:
        Relative accuracy of the reported peaks of the friction ratio (overall and per
        segment): a segment's largest sample that is a turn is refined between its
        neighbouring steps (:mod:`~frictionlab.driver.extrema`). None reports the largest
        sample.

    Returns
    -------
    History
        ``success`` is False (with the reason in ``message``) when a step failed even at
        the deepest substepping; the history then holds every step completed before it.
        Invalid inputs raise :class:`~frictionlab.errors.ParameterError` before any step.
    """
    chosen = driver_settings(settings, accuracy, max_halvings, "simulate")
    accuracy, max_halvings = chosen.accuracy, chosen.max_halvings
    peak_accuracy = check_peak_accuracy(peak_accuracy)
    init = InitialConditions() if initial is None else initial
    n = count_points(params, program, init, n_points)
    state = init if isinstance(init, ContactState) else init.state(params, n)
    plans = plan_program(program, n)
    _check_prescribed_normal_tractions(params, program)
    total = sum(p.estimated_steps for p in plans)
    warnings: list[str] = []
    rec = Recorder(state, recording, [p.estimated_steps for p in plans])
    records: list[tuple[int, str, dict[str, Any], bool, SegmentStats]] = []
    work = dict.fromkeys(
        ("steps", "substeps", "solves", "iterations", "refined_for_failure",
         "refined_for_accuracy", "accuracy_unmet"), 0,
    )  # fmt: skip
    success, message = True, f"completed {len(plans)} segments"
    pool = OutputPool(n)
    direct = stepping.slip_steps(params, pool, accuracy)
    compiled = compiled_steps(direct, rec, n) if chosen.compiled else None
    tracker = None if peak_accuracy is None else PeakTracker(n)
    refined: list[RefinedPeaks] = []
    checked: dict[bytes, dict[int, str]] = {}  # the snap-back check of reached tractions
    for index, plan in enumerate(plans, start=1):
        estimated = plan.estimated_steps
        steps = plan.begin(state.traction)
        target = plan.target if isinstance(plan, _NormalPlan) else None  # not a tangential one
        if target is not None:  # a normal traction prescribed by a change: check it now
            check_snap_back(params, target, f"program[{index}].traction_change")
        total += steps - estimated
        rec.begin_segment(index, plan.kind)
        if tracker is not None:
            tracker.begin_segment(state, rec.stats.time, rec.stats.slip, rec.stats.path_length)
        failed = False
        last = steps - 1
        runs = None if compiled is None else plan.slip_runs()
        k = -1
        while k + 1 < steps:
            k += 1
            if runs is not None:  # every step it can, in the compiled loop
                assert compiled is not None
                state, k = compiled.run(runs, k, steps, state, rec, tracker, work, progress, total)
                if k == steps:
                    break
            control = plan.control(k)
            quick = None
            if direct is not None and control.ft_target is None and control.fn_target is None:
                quick = direct.step(state, control)
            if quick is not None:  # one solve, no substeps: advance's result, cheaper
                before, (state, du) = state, quick
                out = pool.sets[0] if state.traction is pool.sets[0]["traction"] else pool.sets[1]
                iterations = out["iterations"].astype(np.int64)
                work["steps"] += 1
                work["substeps"] += 1
                work["solves"] += 1
                work["iterations"] += sum(iterations.tolist()) if n <= 16 else int(iterations.sum())
                rose = rec.add(state, control.dt, du, out["diss"], out["status"], 1, 1,
                               iterations, k == last)  # fmt: skip
                if rose and tracker is not None:
                    tracker.observe(k, before, state, control, rec.stats.time, rec.stats.slip,
                                    rec.stats.path_length)  # fmt: skip
                if progress is not None:
                    progress(work["steps"], total)
                continue
            outcome, w = advance(
                params, state, control, accuracy=accuracy, max_halvings=max_halvings, pool=pool
            )
            _count_work(work, w, completed=outcome.ok)
            if not outcome.ok:
                success, failed = False, True
                message = (
                    f"segment #{index} ({plan.kind}), step {k + 1} of {steps}: {outcome.reason}"
                )
                break
            before, state = state, outcome.state
            rose = rec.add(state, control.dt, outcome.du, outcome.dissipation, outcome.status,
                           w.substeps, w.solves, w.iterations, k == last)  # fmt: skip
            if rose and tracker is not None:
                tracker.observe(k, before, state, control, rec.stats.time, rec.stats.slip,
                                rec.stats.path_length)  # fmt: skip
            if progress is not None:
                progress(work["steps"], total)
        seg = rec.end_segment()
        if seg is not None and tracker is not None and not failed:
            assert peak_accuracy is not None
            found = tracker.refine(params, plan, steps, peak_accuracy, max_halvings=max_halvings,
                                   first_step=seg.first_step, index=index,
                                   compiled=chosen.compiled)  # fmt: skip
            _apply_refined(rec.stats, seg, found)
            refined.append(found)
            if tracker.failed:
                warnings.append(
                    f"segment #{index} ({plan.kind}): the peak refinement failed (the local "
                    "solve of a trial step failed even substepped): its peaks are the largest "
                    "samples, short of the true ones by up to the change over a step"
                )
            if tracker.unmet:
                warnings.append(
                    f"segment #{index} ({plan.kind}): the refined peak may miss peak_accuracy "
                    f"{peak_accuracy:g}: {tracker.unmet} of its trial substeps missed a tenth "
                    f"of it even at 2**-{max_halvings} of a step (raise max_halvings, or use "
                    "more steps)"
                )
        if seg is not None:
            reached = seg.max_normal_traction
            key = reached.tobytes()  # segments often reach the same tractions: checked once
            reasons = checked.get(key)
            if reasons is None:
                reasons = checked[key] = _snap_back_failures(params, reached)
            bad = list(reasons)  # points with a reason, in order
            if bad:
                warnings.append(
                    f"segment #{index} ({plan.kind}) reached f_n = {reached[bad[0]]:.6g} Pa "
                    f"at point {bad[0] + 1} ({len(bad)} point(s) in all), where "
                    f"{reasons[bad[0]]} fails: the local solution may not be unique"
                )
            records.append((index, plan.kind, plan.resolved, plan.is_hold, seg))
        if failed:
            break
    if success and work["accuracy_unmet"]:
        message += (
            f"; the accuracy {accuracy} was not met in {work['accuracy_unmet']} steps "
            f"even with 2**{max_halvings} substeps"
        )
    work["peak_solves"] = 0 if tracker is None else tracker.solves
    if pool.holds(state):  # the final state outlives the reused buffers: a copy of its own
        state = ContactState._trusted(  # the kernel's outputs (finite); read-only copies
            **{name: np.array(getattr(state, name)) for name in _STATE_ARRAYS}, frame=state.frame
        )
    rows = rec.finish()
    segment_records = _segment_records(rows["step"], records)
    return _history_from_rows(
        rows,
        rec,
        segments=segment_records,
        final_state=state,
        success=success,
        message=message,
        work=work,
        warnings=tuple(warnings),
        peaks=RefinedPeaks.join(refined),
    )


def _apply_refined(run: RunStats, seg: SegmentStats, found: RefinedPeaks) -> None:
    """Put a segment's refined peaks into its figures and, where larger, the run's."""
    if not len(found):
        return
    i = found.point - 1
    seg.peak_friction_ratio = seg.peak_friction_ratio.copy()
    seg.peak_time = seg.peak_time.copy()
    seg.peak_friction_ratio[i] = found.friction_ratio
    seg.peak_time[i] = found.time
    top = run.peak_step[i] == found.step  # the run's peak is this segment's sample
    j = i[top]
    run.peak_friction_ratio[j] = found.friction_ratio[top]
    run.peak_time[j] = found.time[top]
    run.peak_path_length[j] = found.path_length[top]


def _segment_records(
    steps: np.ndarray, records: list[tuple[int, str, dict[str, Any], bool, SegmentStats]]
) -> tuple[SegmentRecord, ...]:
    """Segment records with the rows of their first and last steps (always recorded)."""
    out = []
    for index, kind, resolved, is_hold, seg in records:
        first = int(np.searchsorted(steps, seg.first_step))
        last = int(np.searchsorted(steps, seg.last_step))
        out.append(SegmentRecord(index, kind, first, last, resolved, is_hold, seg))
    return tuple(out)


def _check_prescribed_normal_tractions(
    params: SubloadingParams, program: Sequence[Segment]
) -> None:
    """The no-snap-back check at every normal traction a segment prescribes.

    A closed sliding-yield surface must not bend back on itself at the prescribed normal
    traction, or the local solution of the law is not unique.

    Raises :class:`~frictionlab.errors.ParameterError` naming the segment, before any step
    (as ``initial_state`` does for the initial normal traction).
    """
    for index, seg in enumerate(program, start=1):
        if isinstance(seg, NormalStep) and seg.traction is not None:
            check_snap_back(params, seg.traction, f"program[{index}].traction")
        elif isinstance(seg, Table) and seg.normal_traction is not None:
            values = np.asarray(seg.normal_traction, dtype=np.float64)
            check_snap_back(params, values[values > 0], f"program[{index}].normal_traction")
