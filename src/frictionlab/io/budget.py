"""Work estimates before a run: refuse what this machine cannot hold, unless the user insists.

A simulation records every step of every point, so its memory and the size of
``history.csv`` grow with (recorded rows) x (points). The estimate is made from the
step counts the programme resolves to before anything runs (``steps``, ``max_step``,
``distance``) and compared with the machine's physical memory; a run beyond it is
refused with one line naming the key that sets the size and the estimate.
``[run].allow_large = true`` (or ``--set run.allow_large=true``) runs it anyway.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass

from frictionlab.errors import InputError

__all__ = ["RunEstimate", "check_grid_size", "check_run_size", "largest", "physical_memory"]

#: Peak memory of ``frictionlab simulate`` per point and recorded row [bytes] (the
#: recorder's arrays, the long-format columns, the CSV text) and per point (the
#: per-point entries of summary.json). Measured: 10^6 points x 6 rows peaked at
#: 11.6 GB resident (docs/reliability.md); these constants give 11.4 GB there.
MEMORY_PER_POINT_ROW = 900.0
MEMORY_PER_POINT = 6000.0
#: Output size per point and row (history.csv, 156 B measured) and per point
#: (summary.json, 830 B measured) [bytes].
CSV_PER_POINT_ROW = 160.0
SUMMARY_PER_POINT = 850.0
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


@dataclass(frozen=True)
class RunEstimate:
    """Recorded rows (steps + 1) and points of a run, with the key that sets the rows."""

    rows: int
    points: int
    key: str

    @property
    def memory(self) -> float:
        """Estimated peak memory [bytes]."""
        return self.points * (MEMORY_PER_POINT + float(self.rows) * MEMORY_PER_POINT_ROW)

    @property
    def output(self) -> float:
        """Estimated size of history.csv and summary.json [bytes]."""
        return self.points * (SUMMARY_PER_POINT + float(self.rows) * CSV_PER_POINT_ROW)


def largest(step_counts: Sequence[tuple[int, str]], points: int, points_key: str) -> RunEstimate:
    """The estimate of a run with segments ``(steps, key)``; names the dominant key."""
    rows = 1 + sum(s for s, _ in step_counts)
    biggest_steps, key = max(step_counts, key=lambda sk: sk[0])
    return RunEstimate(rows, points, points_key if points > biggest_steps else key)


def check_run_size(estimate: RunEstimate, allow_large: bool, memory: int | None = None) -> None:
    """Raise InputError (one line) when the run would need more than half the memory."""
    limit = MEMORY_FRACTION * (physical_memory() if memory is None else memory)
    if allow_large or estimate.memory <= limit:
        return
    raise InputError(
        f"{estimate.key} makes {estimate.rows:.4g} recorded rows x {estimate.points} point(s): "
        f"about {_size(estimate.memory)} of memory and {_size(estimate.output)} of "
        f"output files, beyond this machine ({_size(limit)} usable): allowed fewer steps or "
        "points, or [run].allow_large = true to run it anyway"
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
