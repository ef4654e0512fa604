"""The law seen by the calibration: measured curves, fitted parameters, the driver in the loop.

A :class:`Curve` is one tribometer record (time [s], friction ratio |f_t|/f_n, optionally
slip [m]) together with the loading programme and initial contact that produced it. The
model value at a sample is the driver's friction ratio interpolated linearly in time
between its recorded steps, so the data may be sampled more or less densely than the
programme's steps.

:func:`evaluate_columns` runs K parameter sets ("columns") of one curve as K contact
points of ONE vectorised driver run: the law takes every parameter per point, so the
K - 1 finite-difference perturbations of a Jacobian cost about one run.

Pure computation: no file I/O, no printing.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from frictionlab.driver import DriverSettings, History, InitialConditions, Program, simulate
from frictionlab.errors import ConvergenceError, ParameterError
from frictionlab.subloading import SubloadingParams

__all__ = [
    "FITTABLE",
    "LOG_BOUNDS",
    "Curve",
    "FitSpace",
    "best_offset",
    "evaluate_columns",
    "model_at_samples",
    "program_duration",
]

#: Parameters that can be fitted -> True when fitted in log space (rate constants and
#: moduli, which span decades and must stay positive).
FITTABLE: dict[str, bool] = {
    "mu_s": False,
    "mu_k": False,
    "F_s": False,
    "F_k": False,
    "M": False,
    "m": False,
    "n": False,
    "u": True,
    "kappa": True,
    "xi": True,
    "alpha_n": True,
    "alpha_t": True,
}

#: Physical range of each parameter fitted as ln x, used where ``[fit] bounds`` leaves an
#: end open: u [1/m] (R reaches 1 within 1e-12 m to 100 m of slip), kappa [1/m]
#: (softening over 1e-10 m to 1 km), xi [1/s] (recovery in 1 us to 3e4 years), alpha_n,
#: alpha_t [Pa/m] (1 kPa to 1e8 GPa per m: soft foams to stiff asperity contacts). A fit
#: that runs to one of these ends has not been determined by the data.
LOG_BOUNDS: dict[str, tuple[float, float]] = {
    "u": (1e-2, 1e12),
    "kappa": (1e-3, 1e10),
    "xi": (1e-12, 1e6),
    "alpha_n": (1e3, 1e17),
    "alpha_t": (1e3, 1e17),
}


@dataclass(frozen=True)
class Curve:
    """One measured curve and the loading that produced it.

    Attributes
    ----------
    name:
        How the curve is named in messages and reports (e.g. the file name).
    time:
        (n,) sample times [s] from the start of ``program``, increasing.
    friction_ratio:
        (n,) measured |f_t|/f_n [-].
    program, initial:
        The loading programme and initial contact, as in a simulate scenario (one point).
    weight:
        Weight of the curve's squared residuals (default 1).
    slip:
        (n,) measured slip [m], or None (used for plots only).
    segment_weights:
        Optional weight of each segment's samples (one per segment of ``program``), for
        example to let short restart peaks count as much as long holds.
    time_offset:
        When the data's t = 0 falls in the programme's time [s] (model time = t + offset).
    offset_bounds:
        ``(low, high)`` [s] to estimate the offset from the data instead: a nuisance
        parameter, profiled out for every law the fit tries (:func:`best_offset`);
        ``time_offset`` is then unused. Not with ``segment_weights`` (the segment a sample
        falls in would move during the fit).
    """

    name: str
    time: np.ndarray
    friction_ratio: np.ndarray
    program: Program
    initial: InitialConditions = field(default_factory=InitialConditions)
    weight: float = 1.0
    slip: np.ndarray | None = None
    segment_weights: tuple[float, ...] | None = None
    time_offset: float = 0.0
    offset_bounds: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        sw = self.segment_weights
        if sw is not None:
            if len(sw) != len(self.program):
                raise ParameterError("segment_weights", list(sw),
                                     f"one weight per segment ({len(self.program)})")  # fmt: skip
            if not all(np.isfinite(w) and w >= 0 for w in sw) or not any(w > 0 for w in sw):
                raise ParameterError("segment_weights", list(sw), "weights >= 0, one > 0")
        if not np.isfinite(self.time_offset):
            raise ParameterError("time_offset", self.time_offset, "a finite time [s]")
        ob = self.offset_bounds
        if ob is not None:
            if len(ob) != 2 or not (np.isfinite(ob[0]) and np.isfinite(ob[1]) and ob[0] < ob[1]):
                raise ParameterError(
                    "time_offset_bounds", list(ob), "[low, high] finite times [s], low < high"
                )
            if sw is not None:
                raise ParameterError(
                    "segment_weights",
                    list(sw),
                    "none with time_offset = 'fit' (the "
                    "segment of each sample would move with the fitted offset)",
                )

    @property
    def n_samples(self) -> int:
        return int(self.time.size)

    @property
    def model_time(self) -> np.ndarray:
        """(n,) the samples' times on the programme's clock [s]."""
        return self.time + self.time_offset

    def segment_of_samples(self) -> np.ndarray:
        """(n,) 0-based segment of ``program`` in which each sample falls."""
        ends = np.cumsum(segment_durations(self.program))
        return np.minimum(np.searchsorted(ends, self.model_time, side="left"), len(ends) - 1)

    def sample_weights(self) -> np.ndarray:
        """(n,) weight of each sample's squared residual (curve weight x segment weight)."""
        w = np.full(self.n_samples, float(self.weight))
        if self.segment_weights is not None:
            w *= np.asarray(self.segment_weights, dtype=np.float64)[self.segment_of_samples()]
        return w


@dataclass(frozen=True)
class FitSpace:
    """The fitted parameters and the space the optimiser works in.

    ``theta = ln(x)`` for the parameters of :data:`FITTABLE` marked True, ``theta = x``
    otherwise. ``lower`` and ``upper`` are the physical bounds (``upper`` may be inf).
    """

    names: tuple[str, ...]
    lower: np.ndarray
    upper: np.ndarray

    @property
    def log(self) -> np.ndarray:
        return np.array([FITTABLE[n] for n in self.names], dtype=bool)

    def to_theta(self, x: Any) -> np.ndarray:
        x = np.asarray(x, dtype=np.float64)
        with np.errstate(divide="ignore"):
            return np.where(self.log, np.log(np.where(self.log, x, 1.0)), x)

    def from_theta(self, theta: Any) -> np.ndarray:
        theta = np.asarray(theta, dtype=np.float64)
        with np.errstate(over="ignore"):  # a huge trial step gives inf: an invalid law
            return np.where(self.log, np.exp(np.where(self.log, theta, 0.0)), theta)

    def theta_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        return self.to_theta(self.lower), self.to_theta(self.upper)

    def jacobian_factor(self, x: Any) -> np.ndarray:
        """dx/dtheta at ``x`` (x for log parameters, 1 otherwise)."""
        return np.where(self.log, np.asarray(x, dtype=np.float64), 1.0)


def with_values(
    base: SubloadingParams, names: Sequence[str], values: np.ndarray
) -> SubloadingParams:
    """``base`` with ``names`` set to ``values``: shape (p,) (shared) or (p, K) (per point)."""
    return base.replace(**{name: values[j] for j, name in enumerate(names)})


def model_at_samples(history: History, time: np.ndarray) -> np.ndarray:
    """(K, n) friction ratio of each point of ``history`` interpolated at ``time`` [s]."""
    ratio = history.friction_ratio
    return np.stack(
        [np.interp(time, history.time[:, k], ratio[:, k]) for k in range(history.n_points)]
    )


def evaluate_columns(
    base: SubloadingParams,
    names: Sequence[str],
    columns: np.ndarray,
    curve: Curve,
    *,
    accuracy: float | None = None,
    max_halvings: int = 10,
    offsets: list[float] | None = None,
    law: SubloadingParams | None = None,
) -> np.ndarray:
    """(K, n) model friction ratio at the curve's samples for K parameter sets.

    ``law``: the law of ``columns`` when the caller has built it already (:func:`checked_law`).

    A curve with ``offset_bounds`` is compared at the offset that fits the first column
    best (:func:`best_offset`); that offset is appended to ``offsets`` when given.

    ``columns`` is (p, K): column k gives the values of ``names`` for contact point k;
    the K points run together in one driver run. Raises
    :class:`~frictionlab.errors.ParameterError` when a column is not a valid law and
    :class:`~frictionlab.errors.ConvergenceError` when the run fails.
    """
    columns = np.asarray(columns, dtype=np.float64)
    k = columns.shape[1]
    params = law
    if params is None:
        params = with_values(base, names, columns if k > 1 else columns[:, 0])
    history = simulate(
        params,
        curve.program,
        curve.initial,
        n_points=k,
        settings=DriverSettings(accuracy=accuracy, max_halvings=max_halvings),
        peak_accuracy=None,  # the samples are interpolated: peaks between steps are not used
    )
    if not history.success:
        raise ConvergenceError(
            f"curve '{curve.name}': the driver failed ({history.message})",
            mask=np.ones(k, dtype=bool),
        )
    if curve.offset_bounds is None:
        return model_at_samples(history, curve.model_time)
    # the offset of the first column (the base law) serves every column: the columns after
    # it are the Jacobian's perturbations, taken at the base's optimal offset
    offset = best_offset(history.time[:, 0], history.friction_ratio[:, 0], curve)
    if offsets is not None:
        offsets.append(offset)
    return model_at_samples(history, curve.time + offset)


#: Grid points of the first, coarse search of :func:`best_offset`.
OFFSET_GRID = 401


def best_offset(model_time: np.ndarray, model_ratio: np.ndarray, curve: Curve) -> float:
    """The time offset [s] within ``curve.offset_bounds`` that minimises the curve's
    weighted squared misfit to a model run ``(model_time, model_ratio)``.

    The misfit is not convex in the offset (a peak can match either of two peaks), so a
    grid of :data:`OFFSET_GRID` points over the bounds comes first, then Brent's bounded
    method (:func:`scipy.optimize.minimize_scalar`) between the best point's neighbours.
    The model is interpolated linearly between its steps.
    """
    from scipy.optimize import minimize_scalar

    assert curve.offset_bounds is not None
    lo, hi = curve.offset_bounds
    weights = curve.sample_weights()

    def misfit(offset: float) -> float:
        r = np.interp(curve.time + offset, model_time, model_ratio) - curve.friction_ratio
        return float(weights @ (r * r))

    grid = np.linspace(lo, hi, OFFSET_GRID)
    values = np.array([misfit(o) for o in grid])
    k = int(np.argmin(values))
    a, b = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    found = minimize_scalar(misfit, bounds=(a, b), method="bounded",
                            options={"xatol": 1e-12 * max(hi - lo, 1.0)})  # fmt: skip
    best = float(found.x)
    return best if misfit(best) <= values[k] else float(grid[k])


def checked_law(
    base: SubloadingParams, names: Sequence[str], values: np.ndarray
) -> SubloadingParams | None:
    """The law of ``values`` ((p,) or (p, K) per point), or None when it is not valid
    (physical bounds of SubloadingParams)."""
    try:
        return with_values(base, names, values)
    except ParameterError:
        return None


def valid_column(base: SubloadingParams, names: Sequence[str], values: np.ndarray) -> bool:
    """True when ``values`` (p,) make a valid law (physical bounds of SubloadingParams)."""
    return checked_law(base, names, values) is not None


def segment_durations(program: Program) -> list[float]:
    """Time [s] of each segment of a one-point programme."""
    from frictionlab.driver.program import Table, plan_program

    out = []
    for seg, plan in zip(program, plan_program(program, 1), strict=True):
        resolved = plan.resolved
        if isinstance(seg, Table):
            out.append(float(seg.time[-1] - seg.time[0]))
        elif "duration" in resolved:
            out.append(float(np.max(resolved["duration"])))
        elif plan.kind == "cycle":
            amplitude, velocity = resolved["amplitude"], resolved["velocity"]
            out.append(float(np.max(4.0 * amplitude * resolved["cycles"] / velocity)))
        else:
            out.append(0.0)
    return out


def program_duration(program: Program) -> float:
    """Total time [s] of a one-point programme (the sum of its segments' durations)."""
    return float(sum(segment_durations(program)))
