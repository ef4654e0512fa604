"""Work estimates before a run: refuse what this machine cannot do, unless the user insists.

The estimate is made from the step counts the programme resolves to before anything runs
(``steps``, ``max_step``, ``distance``), the number of points and ``[output]``:

* **memory**: a programme run by ``frictionlab simulate`` streams its rows to
  ``history.csv`` (:mod:`frictionlab.driver.recorder`), so its memory is the per-point
  state and running figures plus bounded buffers, whatever the number of steps; a
  spring-slider (``[machine]``) and the Python API keep every recorded row in memory;
* **output**: ``history.csv`` grows with (recorded rows) x (recorded points), where the
  rows are every ``[output] every``-th step; ``points.csv`` with the points;
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
from dataclasses import dataclass
from pathlib import Path

from frictionlab.errors import InputError

__all__ = [
    "RunEstimate",
    "check_grid_size",
    "check_output_space",
    "check_run_size",
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
#: Output size per recorded point and row (history.csv, 156 B measured) and per point
#: (points.csv, 274 B measured; summary.json is small) [bytes].
CSV_PER_POINT_ROW = 160.0
SUMMARY_PER_POINT = 300.0
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

    @property
    def recorded_rows(self) -> float:
        """Rows written (at most): the initial row, every ``every``-th step, and the first
        and last step of each segment."""
        steps = float(self.rows - 1)
        if self.every == 1:
            return 1.0 + steps
        return 1.0 + min(steps, math.ceil(steps / self.every) + 2.0 * self.segments)

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
        return self.points * SUMMARY_PER_POINT + self.recorded_rows * self._points_out * (
            CSV_PER_POINT_ROW
        )

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
    )


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
