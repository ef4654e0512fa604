"""Tribometer analysis of slide-hold-slide programmes: restart peaks and the healing rate.

For every hold followed by a sliding segment (slide, reverse or turn) and every point:
the hold time t_h [s], the friction ratio before the hold (at the stop; the traction stays
constant during a hold: the law has no relaxation), the restart peak (the largest friction
ratio of the sliding segment after the hold) and their difference delta mu. The healing rate is the
least-squares slope d(delta mu)/d log10(t_h) over every record with t_h > 0 (at least two
distinct hold times are needed).

For the law with m = n = 1 the recovery during a hold is
``mu_s - (mu_s - mu_0) exp(-xi t_h / mu_s)`` (Eq 25 integrated at
constant slip); the restart peak approaches it
when the re-loading slip is short (large alpha_t and u, small kappa).

Pure computation: no file I/O.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from frictionlab.driver.simulate import History

__all__ = ["SLIDING_KINDS", "Healing", "HealingRecord", "healing_analysis"]

#: Segment kinds whose first peak after a hold is a restart peak.
SLIDING_KINDS: tuple[str, ...] = ("slide", "reverse", "turn")


@dataclass(frozen=True)
class HealingRecord:
    """One hold of one point (``point`` and ``hold_segment`` are 1-based)."""

    point: int
    hold_segment: int
    hold_time: float
    friction_before: float
    restart_peak: float
    peak_time: float

    @property
    def delta_mu(self) -> float:
        """Restart peak minus the friction ratio before the hold [-]."""
        return self.restart_peak - self.friction_before


@dataclass(frozen=True)
class Healing:
    """Every hold's record and the healing rate (None with fewer than two hold times)."""

    records: tuple[HealingRecord, ...]
    rate_per_decade: float | None
    intercept: float | None

    def as_dict(self) -> dict[str, object]:
        return {
            "rate_per_decade": self.rate_per_decade,
            "intercept_at_1s": self.intercept,
            "records": [
                {
                    "point": r.point,
                    "hold_segment": r.hold_segment,
                    "hold_time": r.hold_time,
                    "friction_before": r.friction_before,
                    "restart_peak": r.restart_peak,
                    "delta_mu": r.delta_mu,
                    "peak_time": r.peak_time,
                }
                for r in self.records
            ],
        }


def healing_rate(hold_time: np.ndarray, delta_mu: np.ndarray) -> tuple[float | None, float | None]:
    """Least-squares (slope, intercept) of delta mu against log10(t_h) (t_h > 0 only)."""
    keep = hold_time > 0
    x, y = np.log10(hold_time[keep]), delta_mu[keep]
    if np.unique(x).size < 2:
        return None, None
    design = np.column_stack([x, np.ones_like(x)])
    (slope, intercept), *_ = np.linalg.lstsq(design, y, rcond=None)
    return float(slope), float(intercept)


def healing_analysis(history: History) -> Healing | None:
    """Restart peaks and healing rate of ``history`` (None when no hold is followed by sliding).

    Uses the segments' running figures (every step, every point) when the history has
    them, so the result does not depend on which steps were recorded; otherwise the
    recorded rows.
    """
    segments = history.segments
    records = []
    for seg, after in itertools.pairwise(segments):
        if not seg.is_hold or after.kind not in SLIDING_KINDS:
            continue
        if seg.stats is not None and after.stats is not None:
            hold, slide = seg.stats, after.stats
            for i in range(hold.start_time.shape[0]):
                records.append(
                    HealingRecord(
                        point=i + 1,
                        hold_segment=seg.index,
                        hold_time=float(hold.final_time[i] - hold.start_time[i]),
                        friction_before=float(hold.start_friction_ratio[i]),
                        restart_peak=float(slide.peak_friction_ratio[i]),
                        peak_time=float(slide.peak_time[i]),
                    )
                )
            continue
        ratio = history.friction_ratio
        stop = seg.first_row - 1
        rows = slice(after.first_row, after.last_row + 1)
        for i in range(history.n_points):
            k = after.first_row + int(np.argmax(ratio[rows, i]))
            records.append(
                HealingRecord(
                    point=int(history.point_numbers[i]),
                    hold_segment=seg.index,
                    hold_time=float(history.time[seg.last_row, i] - history.time[stop, i]),
                    friction_before=float(ratio[stop, i]),
                    restart_peak=float(ratio[k, i]),
                    peak_time=float(history.time[k, i]),
                )
            )
    if not records:
        return None
    records.sort(key=lambda r: (r.point, r.hold_segment))
    t = np.array([r.hold_time for r in records])
    d = np.array([r.delta_mu for r in records])
    slope, intercept = healing_rate(t, d)
    return Healing(tuple(records), slope, intercept)
