"""Work estimates before a run: refuse what this machine cannot do, unless the user insists.

The estimate is made from the step counts the programme resolves to before anything runs
(``steps``, ``max_step``, ``distance``), the number of points and ``[output]``:

* **memory**: a programme run by ``frictionlab simulate`` streams its rows to
  ``history.csv`` (:mod:`frictionlab.driver.recorder`), so its memory is the per-point
  state and running figures plus bounded buffers, whatever the number of steps; a
  spring-slider (``[machine]``) and the Python API keep every recorded row in memory;
* **output**: ``history.csv`` grows with (recorded rows) x (recorded points), where the
  rows are every ``[output] every``-th step; ``points.csv`` with the points. A history
  beyond :data:`HISTORY_LIMIT` (1 GB) warns (:func:`history_bound`), and without ``[output]
  every`` it is recorded every k-th step, the smallest k that keeps it under;
* **time**: (steps) x (points) point updates plus a fixed cost per step.

A run needing more than half the physical memory, more output than the free space where
it is written, or more than :data:`TIME_LIMIT` of computing is refused with one line
naming the key that sets the size and the estimates. ``[run].allow_large = true`` (or
``--set run.allow_large=true``) runs it anyway.
"""

from __future__ import annotations

import math
import os
import shutil
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.errors import InputError

__all__ = [
    "RunEstimate",
    "check_calibration",
    "check_calibration_size",
    "check_contact",
    "check_contact_size",
    "check_grid_size",
    "check_lattice_size",
    "check_output_space",
    "check_roughness",
    "check_run_size",
    "history_bound",
    "largest",
    "physical_memory",
]

#: Peak memory per point and row held in memory [bytes] (the recorder's arrays, the
#: long-format columns, the CSV text) and per point. Measured before streaming:
#: 10^6 points x 6 rows peaked at 11.6 GB resident; these constants give 11.4 GB there.
MEMORY_PER_POINT_ROW = 900.0
MEMORY_PER_POINT = 6000.0
#: Peak memory per point of a streamed run [bytes]: the state, the running figures and
#: the per-point table (10^6 points x 3 steps streamed: 1.09 GB measured).
MEMORY_PER_POINT_STREAMED = 1500.0
#: Rows x points a streamed run keeps for its plots (4000 rows of at most 40 points) and
#: the bound of one streamed chunk [bytes].
STREAM_KEPT_ROWS = 4000
STREAM_KEPT_POINTS = 40
STREAM_CHUNK_BYTES = 8.0 * 2**20
#: Output size per recorded point and row (history.csv: 156 B measured on smooth test
#: histories, 224 B on 10^3 distinct points whose floats need 16-17 digits) and per point
#: (points.csv, 274 B measured; summary.json is small) [bytes].
CSV_PER_POINT_ROW = 240.0
SUMMARY_PER_POINT = 300.0
#: History size per recorded point and row of each ``[output] format`` [bytes]
#: (history.parquet: float64 columns, snappy-compressed; PARQUET measured below).
HISTORY_BYTES_PER_ROW: dict[str, float] = {"csv": CSV_PER_POINT_ROW, "parquet": 120.0}
#: The history size beyond which a run warns, and beyond which the default recording
#: (``[output] every`` not given) records every k-th step instead of every step [bytes].
HISTORY_LIMIT = 1e9
#: Computing time per point update and per step outside the kernel [s]: upper-end
#: figures of this project's benchmarks (docs/performance.md), so that the estimate
#: refuses only what is clearly out of reach.
TIME_PER_POINT_STEP = 1e-6
TIME_PER_STEP = 2e-4
#: The longest computation accepted without ``[run].allow_large`` [s] (one day).
TIME_LIMIT = 86400.0
#: Memory per grid point of a generated surface [bytes]: the heights, their spectrum
#: (complex) and the working copies of the FFT and the lattice (a conservative count).
MEMORY_PER_GRID_POINT = 100.0
#: Fraction of the physical memory a run may plan to use.
MEMORY_FRACTION = 0.5


def physical_memory() -> int:
    """The machine's physical memory [bytes] (8 GiB where it cannot be read)."""
    try:
        return int(os.sysconf("SC_PHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):  # pragma: no cover - non-POSIX
        return 8 * 2**30


def _size(n: float) -> str:
    for unit in ("B", "kB", "MB", "GB", "TB", "PB"):
        if n < 1000.0:
            return f"{n:.3g} {unit}"
        n /= 1000.0
    return f"{n:.3g} EB"


def _duration(seconds: float) -> str:
    for unit, size in (("day", 86400.0), ("hour", 3600.0), ("minute", 60.0)):
        if seconds >= size:
            value = f"{seconds / size:.3g}"
            return f"{value} {unit}" if value == "1" else f"{value} {unit}s"
    return f"{seconds:.3g} s"


@dataclass(frozen=True)
class RunEstimate:
    """Rows (steps + 1) and points of a run, with the key that sets the rows.

    ``every`` and ``recorded_points`` are ``[output]``'s (default: every step of every
    point); ``streamed``: the rows go to disk as they are computed (a programme run by
    ``frictionlab simulate``) instead of staying in memory.
    """

    rows: int
    points: int
    key: str
    every: int = 1
    recorded_points: int | None = None
    streamed: bool = False
    segments: int = 1
    history_format: str = "csv"

    @property
    def recorded_rows(self) -> float:
        """Rows written (at most): the initial row, every ``every``-th step, and the first
        and last step of each segment."""
        return self.rows_every(self.every)

    def rows_every(self, every: int) -> float:
        """:attr:`recorded_rows` when recording every ``every``-th step."""
        steps = float(self.rows - 1)
        if every == 1:
            return 1.0 + steps
        return 1.0 + min(steps, math.ceil(steps / every) + 2.0 * self.segments)

    @property
    def history(self) -> float:
        """Estimated size of the history file (history.csv or .parquet) [bytes]."""
        per_row = HISTORY_BYTES_PER_ROW[self.history_format]
        return self.recorded_rows * self._points_out * per_row

    @property
    def _points_out(self) -> float:
        return float(self.points if self.recorded_points is None else self.recorded_points)

    @property
    def memory(self) -> float:
        """Estimated peak memory [bytes]."""
        if not self.streamed:
            return self.points * (MEMORY_PER_POINT + self.recorded_rows * MEMORY_PER_POINT_ROW)
        kept = min(self.recorded_rows, STREAM_KEPT_ROWS) * min(self._points_out, STREAM_KEPT_POINTS)
        return (
            self.points * MEMORY_PER_POINT_STREAMED
            + kept * MEMORY_PER_POINT_ROW
            + STREAM_CHUNK_BYTES
        )

    @property
    def output(self) -> float:
        """Estimated size of history.csv, points.csv and summary.json [bytes]."""
        return self.points * SUMMARY_PER_POINT + self.history

    @property
    def seconds(self) -> float:
        """Estimated computing time [s] (upper-end rates: see :data:`TIME_PER_POINT_STEP`)."""
        steps = float(self.rows - 1)
        return steps * (self.points * TIME_PER_POINT_STEP + TIME_PER_STEP)

    def describe(self) -> str:
        """``KEY makes R recorded rows x P point(s): about M of memory, ...`` (one phrase)."""
        return (
            f"{self.key} makes {self.recorded_rows:.4g} recorded rows x "
            f"{int(self._points_out)} point(s): about {_size(self.memory)} of memory, "
            f"{_size(self.output)} of output files and {_duration(self.seconds)} of computing"
        )


def largest(
    step_counts: Sequence[tuple[int, str]],
    points: int,
    points_key: str,
    every: int = 1,
    recorded_points: int | None = None,
    streamed: bool = False,
    history_format: str = "csv",
) -> RunEstimate:
    """The estimate of a run with segments ``(steps, key)``; names the dominant key."""
    rows = 1 + sum(s for s, _ in step_counts)
    biggest_steps, key = max(step_counts, key=lambda sk: sk[0])
    return RunEstimate(
        rows,
        points,
        points_key if points > biggest_steps else key,
        every=every,
        recorded_points=recorded_points,
        streamed=streamed,
        segments=len(step_counts),
        history_format=history_format,
    )


def _ordinal(k: int) -> str:
    """``2nd``, ``3rd``, ``11th``, ``21st``."""
    suffix = "th" if 10 <= k % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(k % 10, "th")
    return f"{k}{suffix}"


def history_bound(
    estimate: RunEstimate, every_given: bool, limit: float | None = None
) -> tuple[int, str | None]:
    """The ``[output] every`` to record with and a warning when the history passes ``limit``.

    With ``every`` not given (``estimate.every`` = 1 then), a history beyond ``limit`` is
    recorded every k-th step, the smallest k that brings it under; with ``every`` given,
    it is kept and the warning says what would bring it under. The warning names
    ``[output] every`` and ``[output] points`` with such values. ``limit`` [bytes]:
    :data:`HISTORY_LIMIT` unless given.
    """
    limit = HISTORY_LIMIT if limit is None else limit
    if estimate.history <= limit:
        return estimate.every, None
    name = f"history.{estimate.history_format}"
    per_row = HISTORY_BYTES_PER_ROW[estimate.history_format]
    lo, hi = max(estimate.every, 1), max(int(estimate.rows), 2)
    while lo < hi:  # the smallest every under the limit (rows_every decreases with every)
        mid = (lo + hi) // 2
        if estimate.rows_every(mid) * estimate._points_out * per_row <= limit:
            hi = mid
        else:
            lo = mid + 1
    under_every = lo
    fits = estimate.rows_every(under_every) * estimate._points_out * per_row <= limit
    points = int(limit // (estimate.recorded_rows * per_row))
    size = _size(estimate.history)
    shape = f"{estimate.recorded_rows:.4g} recorded rows x {int(estimate._points_out)} point(s)"
    by_points = (
        f"[output] points listing at most {points} point(s)"
        if points >= 1
        else "no choice of [output] points alone"
    )
    if not every_given and fits:
        return under_every, (
            f"{name} would be about {size} recording every step ({shape}): recording every "
            f"{_ordinal(under_every)} step instead ([output] every = {under_every}, the "
            f"smallest that keeps it under {_size(limit)}); set [output] every = 1 to record "
            f"every step, or {by_points} to keep every step under {_size(limit)}"
        )
    every_text = f"[output] every = {under_every}" if fits else "no choice of [output] every alone"
    return estimate.every, (
        f"{name} will be about {size} ({shape}, [output] every = {estimate.every}): "
        f"{every_text} or {by_points} would keep it under {_size(limit)}"
    )


def check_points(n: int, output: Any, streamed: bool, allow_large: bool) -> None:
    """Refuse a scenario's ``n`` points alone (one step), before anything of size n exists."""
    recorded = output.recorded_points(n)
    estimate = RunEstimate(2, n, "[run].n_points", output.every, recorded, streamed)
    check_run_size(estimate, allow_large)


def scenario_estimate(
    counts: Sequence[tuple[int, str]], n: int, output: Any, streamed: bool, allow_large: bool
) -> tuple[RunEstimate, Any, tuple[str, ...]]:
    """A scenario's estimate from its segments ``(steps, key)``, refused when too large;
    ``output`` (an OutputOptions) with the history's ``every`` bounded; the warnings."""
    recorded = output.recorded_points(n)
    estimate = largest(counts, n, "[run].n_points", output.every, recorded, streamed, output.format)
    check_run_size(estimate, allow_large)  # the steps run whatever is recorded
    every, warning = history_bound(estimate, output.every_given)
    if every != output.every:  # the default recording, bounded
        output, estimate = replace(output, every=every), replace(estimate, every=every)
    return estimate, output, () if warning is None else (warning,)


def steps_key(seg: Any) -> str:
    """The key that sets a segment's step count: max_step when given, else steps."""
    return "max_step" if getattr(seg, "max_step", None) is not None else "steps"


def machine_steps(m: Any) -> int:
    """The steps of a ``[machine]`` run (a MachineRun)."""
    if m.max_step is not None:
        longest = float(np.max(np.asarray(m.duration, dtype=np.float64)))
        return max(1, math.ceil(longest / m.max_step))
    return m.steps or 1000


_OVERRIDE = "allowed fewer steps or points, or [run].allow_large = true to run it anyway"


def check_run_size(estimate: RunEstimate, allow_large: bool, memory: int | None = None) -> None:
    """Raise InputError (one line) beyond half the memory or :data:`TIME_LIMIT`."""
    limit = MEMORY_FRACTION * (physical_memory() if memory is None else memory)
    if allow_large:
        return
    if estimate.memory > limit:
        raise InputError(
            f"{estimate.describe()}: beyond this machine's memory ({_size(limit)} usable): "
            + _OVERRIDE
        )
    if estimate.seconds > TIME_LIMIT:
        raise InputError(
            f"{estimate.describe()}: beyond the {_duration(TIME_LIMIT)} a run may take "
            "unasked: " + _OVERRIDE
        )


def check_output_space(
    estimate: RunEstimate, out: Path, allow_large: bool, free: int | None = None
) -> None:
    """Raise InputError (one line) when the output would not fit where it is written.

    ``free``: the free space [bytes] (default: of the deepest existing folder of ``out``).
    """
    if allow_large:
        return
    if free is None:
        where = Path(out).absolute()
        while not where.exists() and where != where.parent:
            where = where.parent
        try:
            free = shutil.disk_usage(where).free
        except OSError:  # pragma: no cover - unreadable file system: nothing to compare
            return
    if estimate.output > free:
        raise InputError(
            f"{estimate.describe()}: more than the {_size(free)} free on the disk of {out}: "
            + _OVERRIDE.replace(
                "fewer steps or points",
                "fewer steps or points, a larger [output].every, fewer [output].points",
            )
        )


def check_grid_size(
    key: str, points: Sequence[int], allow_large: bool, memory: int | None = None
) -> None:
    """Raise InputError (one line) when a surface grid would need more than half the memory.

    ``key`` names the setting (``[lower].points``); the override is ``allow_large`` in the
    same table.
    """
    total = 1.0
    for p in points:
        total *= float(p)
    need = total * MEMORY_PER_GRID_POINT
    limit = MEMORY_FRACTION * (physical_memory() if memory is None else memory)
    if allow_large or need <= limit:
        return
    section = key.rsplit(".", 1)[0]
    raise InputError(
        f"{key} = {list(points)} makes {total:.4g} grid points: about {_size(need)} of "
        f"memory, beyond this machine ({_size(limit)} usable): allowed fewer points, or "
        f"{section}.allow_large = true to run it anyway"
    )


def _refuse_beyond(what: str, need: float, seconds: float, memory: int | None, how: str) -> None:
    """One line when ``need`` [bytes] passes half the memory or ``seconds`` :data:`TIME_LIMIT`."""
    limit = MEMORY_FRACTION * (physical_memory() if memory is None else memory)
    estimate = f"{what}: about {_size(need)} of memory and {_duration(seconds)} of computing"
    if need > limit:
        raise InputError(f"{estimate}, beyond this machine's memory ({_size(limit)} usable): {how}")
    if seconds > TIME_LIMIT:
        raise InputError(
            f"{estimate}, beyond the {_duration(TIME_LIMIT)} a run may take unasked: {how}"
        )


#: Computing time per station and time sample of the lattice model [s] (upper end of
#: docs/performance.md: 1.4e8 springs/s, two spring families per station).
TIME_PER_STATION_SAMPLE = 2e-8
#: Memory per time sample of one sliding direction [bytes]: the shifts, the per-sample
#: results kept until the direction's average (Python tuples) and the work arrays.
MEMORY_PER_SAMPLE = 600.0


def check_lattice_size(
    time_samples: int,
    max_return_periods: int,
    stations: int,
    directions: int,
    key: str = "[lattice].time_samples",
    memory: int | None = None,
) -> None:
    """Raise InputError (one line, naming ``key``) for a lattice run out of reach.

    A 2-D return path holds up to ``time_samples * max_return_periods`` samples per
    direction; each sample visits every station.
    """
    samples = float(time_samples) * float(max(1, max_return_periods))
    need = samples * MEMORY_PER_SAMPLE
    seconds = samples * float(stations) * float(directions) * TIME_PER_STATION_SAMPLE
    _refuse_beyond(
        f"{key} = {time_samples} makes up to {samples:.4g} samples x {stations} stations x "
        f"{directions} direction(s)",
        need, seconds, memory, f"allowed fewer {key.rsplit('.', 1)[-1]} or stations",
    )  # fmt: skip


def check_calibration_size(
    step_counts: Sequence[tuple[int, str]],
    parameters: int,
    max_evaluations: int,
    profile_runs: int,
    memory: int | None = None,
) -> None:
    """Raise InputError (one line) for a calibration out of reach before it starts.

    ``step_counts``: the steps of every segment of every curve with its key; the fit runs
    every curve up to ``max_evaluations * (parameters + 2)`` times (the model and its
    finite-difference Jacobian) and the profiles ``profile_runs`` times more. Each run
    keeps its rows in memory (:data:`MEMORY_PER_POINT_ROW` per step).
    """
    total = float(sum(s for s, _ in step_counts))
    steps, key = max(step_counts, key=lambda sk: sk[0])
    runs = float(max_evaluations) * (parameters + 2) + float(profile_runs)
    need = MEMORY_PER_POINT + (total + 1.0) * MEMORY_PER_POINT_ROW
    seconds = runs * total * (TIME_PER_POINT_STEP + TIME_PER_STEP)
    _refuse_beyond(
        f"{key} makes {steps:.4g} steps ({total:.4g} over all curves), run up to {runs:.4g} "
        "times by the fit and its profiles",
        need, seconds, memory,
        "allowed fewer steps (a larger max_step), fewer [fit].max_evaluations or "
        "[fit].profile_points",
    )  # fmt: skip


#: Newton iterations per step assumed by the time estimate.
NEWTON_PER_STEP = 4.0


def contact_solver_estimate(
    free_dofs: int, contact_dofs: int, dim: int, linear_solver: str = "direct"
) -> tuple[float, float, float]:
    """Memory [bytes], set-up time [s] and time per Newton solve [s] of the contact
    model's linear solver: :func:`frictionlab.contact.linear.cost` (one estimate for
    ``[solver].memory_limit`` and this check)."""
    from frictionlab.contact.linear import cost

    c = cost(free_dofs, contact_dofs, dim, linear_solver)
    return c["bytes"], c["setup"], c["per_solve"]


def check_contact_size(
    nodes: int,
    contact_nodes: int,
    dim: int,
    steps: int,
    key: str = "[block].element_size",
    memory: int | None = None,
    linear_solver: str = "direct",
) -> None:
    """Raise InputError (one line, naming ``key``) when the contact solver is out of reach.

    ``nodes``: the mesh's nodes; ``contact_nodes``: those on the contact face; ``steps``:
    the steps of the normal stage and the programme (each ~:data:`NEWTON_PER_STEP` solves).
    """
    need, setup, per_solve = contact_solver_estimate(
        nodes * dim, contact_nodes * dim, dim, linear_solver
    )
    seconds = setup + per_solve * NEWTON_PER_STEP * steps
    _refuse_beyond(
        f"{key} makes a {dim}-D mesh of {nodes:.4g} nodes with {contact_nodes:.4g} on the "
        f"contact face ({linear_solver} solver)",
        need, seconds, memory, "allowed a larger element_size or a smaller block",
    )  # fmt: skip


# --------------------------------------------- the estimates of each workflow's parsed input

#: Function evaluations of one profile point (frictionlab.calibration.profile's max_nfev).
PROFILE_EVALUATIONS = 30


def check_calibration(cfg: Any, memory: int | None = None) -> None:
    """:func:`check_calibration_size` of a parsed calibration file (``CalibrationConfig``)."""
    from frictionlab.driver.program import plan_program

    counts: list[tuple[int, str]] = []
    for k, curve in enumerate(cfg.curves, start=1):
        for j, (plan, seg) in enumerate(
            zip(plan_program(curve.program, 1), curve.program, strict=True), start=1
        ):
            key = "max_step" if getattr(seg, "max_step", None) is not None else "steps"
            counts.append((int(plan.estimated_steps), f"[[data]] #{k}.program #{j}.{key}"))
    p = len(cfg.names)
    profiled = min(cfg.profile_max, p) if cfg.profile else 0
    profile_runs = profiled * cfg.profile_points * PROFILE_EVALUATIONS * (p + 1)
    check_calibration_size(counts, p, cfg.max_evaluations, profile_runs, memory)


def check_roughness(scenario: Any, memory: int | None = None) -> None:
    """:func:`check_lattice_size` of a parsed roughness scenario (``RoughnessScenario``)."""
    from frictionlab.roughness.lattice import lattice_geometry

    settings = scenario.settings
    if not settings.time_samples:
        return
    geometry = lattice_geometry(scenario.lower, scenario.upper, settings.stations)
    check_lattice_size(
        settings.time_samples, settings.max_return_periods, geometry.n_stations,
        len(scenario.beta_deg), memory=memory,
    )  # fmt: skip


def check_contact(scenario: Any, memory: int | None = None) -> None:
    """:func:`check_contact_size` of a parsed contact scenario (``ContactScenario``)."""
    cells = scenario.block.cells
    nodes = int(math.prod(c + 1 for c in cells))
    contact = int(math.prod(c + 1 for c in cells[:-1]))  # the bottom face
    steps = scenario.normal.steps + sum(seg.steps for seg in scenario.program)
    key = f"[block].element_size = {scenario.block.element_size:g} m"
    mesh = getattr(scenario, "mesh", None)
    if mesh is not None:  # an imported mesh: its own node counts
        nodes, contact, key = mesh.nodes, mesh.contact_nodes, f"[mesh].file = {mesh.file!r}"
    check_contact_size(
        nodes, contact, scenario.block.dim, steps, key, memory=memory,
        linear_solver=scenario.options.linear_solver,
    )  # fmt: skip
