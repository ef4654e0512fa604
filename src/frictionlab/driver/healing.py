"""Tribometer analysis of slide-hold-slide programmes: restart peaks and the healing rate.

For every hold followed by a sliding segment (slide, reverse or turn) and every point:
the hold time t_h [s], the friction ratio before the hold (at the stop; the traction stays
constant during a hold: the law has no relaxation), the restart peak (the largest friction
ratio of the sliding segment after the hold) and their difference delta mu. The healing rate is the
least-squares slope d(delta mu)/d log10(t_h) over every record with t_h > 0 (at least two
distinct hold times are needed).

The law itself recovers exponentially, not per decade: beside the rate,
:func:`recovery_fit` fits its form ``A - (A - mu_0) exp(-t_h / tau)`` to the restart peaks
(at least three distinct hold times), and :meth:`Healing.comparison` says which of the two
describes the points better (the smaller residual standard deviation, each with its own
degrees of freedom). A per-decade rate of saturating data depends on the chosen hold times.

``mu_s`` of the law is its static coefficient, the limit of full recovery with no slip;
the observed restart peaks stay below it (re-loading slips before the peak).
:meth:`Healing.static_note` says so with both numbers.

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

__all__ = [
    "SLIDING_KINDS",
    "Healing",
    "HealingRecord",
    "Recovery",
    "healing_analysis",
    "recovery_fit",
]

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
class Recovery:
    """The law's recovery form fitted to restart peaks: ``A - (A - mu_0) exp(-t_h / tau)``.

    ``A`` [-] the fully recovered peak, ``mu_0`` [-] the peak after no hold, ``tau`` [s];
    ``rms`` the residual standard deviation [-] (3 parameters; None with three points: the
    form then passes through every one).
    """

    A: float
    mu_0: float
    tau: float
    rms: float | None


@dataclass(frozen=True)
class Healing:
    """Every hold's record and the healing rate (None with fewer than two hold times).

    ``rate_rms``: residual standard deviation [-] of the per-decade line (2 parameters,
    None with fewer than three points); ``recovery``: :func:`recovery_fit` (None with
    fewer than three distinct hold times or where it does not converge).
    """

    records: tuple[HealingRecord, ...]
    rate_per_decade: float | None
    intercept: float | None
    rate_rms: float | None = None
    recovery: Recovery | None = None

    def comparison(self) -> str:
        """One sentence: which of the per-decade rate and the recovery form fits better."""
        if self.recovery is None or self.recovery.rms is None or self.rate_rms is None:
            return ("comparing the law's recovery form with the per-decade rate needs restart "
                    "peaks after at least four distinct hold times")  # fmt: skip
        rec, lin = self.recovery.rms, self.rate_rms
        if rec < lin:
            return (f"the law's recovery form A - (A - mu_0) exp(-t_h/tau) describes the "
                    f"restart peaks better (residual {rec:.3g}) than a rate per decade "
                    f"({lin:.3g}); a per-decade rate depends on the hold times chosen")  # fmt: skip
        return (f"a rate per decade describes the restart peaks better (residual {lin:.3g}) "
                f"than the law's recovery form ({rec:.3g})")  # fmt: skip

    def static_note(self, mu_s: float) -> str:
        """One sentence: mu_s is the law's static coefficient, not the observed peak."""
        top = max(r.restart_peak for r in self.records)
        return (f"mu_s = {mu_s:.6g} is the law's static coefficient (full recovery, no slip), "
                f"not an observed peak: the largest restart peak here is {top:.6g}")  # fmt: skip

    def as_dict(self) -> dict[str, object]:
        rec = self.recovery
        return {
            "rate_per_decade": self.rate_per_decade,
            "intercept_at_1s": self.intercept,
            "rate_rms": self.rate_rms,
            "recovery": None
            if rec is None
            else {"A": rec.A, "mu_0": rec.mu_0, "tau": rec.tau, "rms": rec.rms},
            "comparison": self.comparison(),
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


def _rms(residuals: np.ndarray, n_params: int) -> float | None:
    dof = residuals.size - n_params
    return float(np.sqrt(residuals @ residuals / dof)) if dof > 0 else None


def recovery_fit(hold_time: np.ndarray, restart_peak: np.ndarray) -> Recovery | None:
    """Least-squares ``A - (A - mu_0) exp(-t_h / tau)`` through the restart peaks (t_h >= 0;
    tau fitted as ln tau). None with fewer than three distinct hold times or no
    convergence."""
    from scipy.optimize import least_squares

    t = np.asarray(hold_time, dtype=np.float64)
    y = np.asarray(restart_peak, dtype=np.float64)
    keep = t >= 0
    t, y = t[keep], y[keep]
    if np.unique(t).size < 3:
        return None

    def residuals(p: np.ndarray) -> np.ndarray:
        a, m0, ln_tau = p
        return a - (a - m0) * np.exp(-t / np.exp(ln_tau)) - y

    positive = t[t > 0]
    span = (np.log(positive.min() / 100.0), np.log(positive.max() * 100.0)) if positive.size \
        else (-5.0, 5.0)  # fmt: skip
    bounds = ([-np.inf, -np.inf, span[0]], [np.inf, np.inf, span[1]])
    best = None
    # starts: a time constant at each hold time (the cost has one minimum per plateau)
    for tau0 in np.unique(positive) if positive.size else [1.0]:
        p0 = np.array([y.max(), y.min(), np.log(tau0)])
        res = least_squares(residuals, p0, bounds=bounds, method="trf", xtol=1e-15,
                            ftol=1e-15, gtol=1e-15)  # fmt: skip
        if res.success and (best is None or res.cost < best.cost):
            best = res
    if best is None or not np.all(np.isfinite(best.x)):
        return None
    a, m0, ln_tau = best.x
    if min(ln_tau - span[0], span[1] - ln_tau) < 1e-6:  # no time scale within the holds
        return None
    return Recovery(float(a), float(m0), float(np.exp(ln_tau)), _rms(best.fun, 3))


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
    rate_rms = None
    if slope is not None and intercept is not None:
        pos = t > 0
        rate_rms = _rms(d[pos] - (slope * np.log10(t[pos]) + intercept), 2)
    peaks = np.array([r.restart_peak for r in records])
    recovery = None
    if len({r.point for r in records}) == 1 or len({r.friction_before for r in records}) == 1:
        recovery = recovery_fit(t, peaks)
    return Healing(tuple(records), slope, intercept, rate_rms, recovery)
