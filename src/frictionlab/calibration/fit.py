"""Fit law parameters to measured curves: bounded least squares with the driver in the loop.

The residual of sample i of curve c is ``sqrt(w_c) (model_i - data_i)`` in friction-ratio
units; :func:`fit_law` minimises half their sum of squares with
:func:`scipy.optimize.least_squares` (trust-region reflective, bounded). Rate constants
and moduli (u, kappa, xi, alpha_n, alpha_t) are fitted as ``ln x`` so that steps are
relative and they stay positive.

The Jacobian is by forward differences in that space, with every perturbation run as an
extra contact point of ONE driver run per curve (the base point included, so base and
perturbations share the driver's substepping). ``jacobian="naive"`` runs them one by one
(the baseline of benchmarks/bench_calibration.py).

Uncertainty (the usual linearisation at the optimum): ``cov_theta = s^2 (J^T J)^-1`` with
``s^2 = 2 cost / (n - p)``, mapped to physical units by the delta method
(``dx = x dtheta`` for log parameters). A parameter is *poorly identified* when its
relative standard error exceeds 50 % or its correlation with another fitted parameter
exceeds 0.9 in magnitude; for those :func:`~frictionlab.calibration.profile.profile_likelihood`
gives the profile of the cost.

Pure computation: progress goes to an optional callback.
"""

from __future__ import annotations

import time as _time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from scipy.optimize import least_squares

from frictionlab._frames import TableResult
from frictionlab.calibration.model import (
    FITTABLE,
    LOG_BOUNDS,
    Curve,
    FitSpace,
    checked_law,
    evaluate_columns,
    valid_column,
    with_values,
)
from frictionlab.errors import ConvergenceError, FrictionlabError, ParameterError
from frictionlab.subloading import SubloadingParams

__all__ = [
    "CORRELATION_LIMIT",
    "RELATIVE_STDERR_LIMIT",
    "FitResult",
    "Objective",
    "fit_law",
    "make_space",
]

#: |correlation| above which two parameters are called poorly identified.
CORRELATION_LIMIT = 0.9
#: Relative standard error above which a parameter is called poorly identified.
RELATIVE_STDERR_LIMIT = 0.5
#: Relative forward-difference step in theta (the law's local solve converges to 1e-13).
FD_STEP = 1e-6
#: Residual of every sample for a trial law that is invalid or whose run fails: larger
#: than any plausible misfit in friction-ratio units, so the trust region shrinks.
PENALTY = 10.0

#: ``progress(done, total)``: driver runs done and an upper estimate of the total.
ProgressCallback = Callable[[int, int], None]


def make_space(
    params: SubloadingParams,
    names: Sequence[str],
    bounds: Mapping[str, tuple[float, float]] | None = None,
) -> FitSpace:
    """The :class:`FitSpace` of ``names`` with ``bounds`` (default: the physical range).

    Raises :class:`ParameterError` naming the parameter for an unknown or repeated name, a
    parameter the surface does not use, bounds that are not low < high, or a start
    outside its bounds.
    """
    if not names:
        raise ParameterError("fit.parameters", [], "at least one parameter to fit")
    if len(set(names)) != len(names):
        raise ParameterError("fit.parameters", list(names), "each parameter once")
    bounds = dict(bounds or {})
    for key in bounds:
        if key not in names:
            raise ParameterError(f"fit.bounds.{key}", bounds[key], "bounds of a fitted parameter")
    lower, upper = [], []
    for name in names:
        if name not in FITTABLE:
            raise ParameterError("fit.parameters", name, "one of " + ", ".join(FITTABLE))
        value = getattr(params, name)
        if value is None:
            raise ParameterError(
                "fit.parameters", name, f"a parameter of surface '{params.surface}'"
            )
        if np.ndim(value) != 0:
            raise ParameterError(f"law.{name}", value, "a single value (not per point) to fit")
        start = float(value)
        lo, hi = bounds.get(name, (0.0, np.inf))
        if not lo < hi:
            raise ParameterError(f"fit.bounds.{name}", [lo, hi], "[low, high] with low < high")
        if FITTABLE[name] and lo < 0:
            raise ParameterError(f"fit.bounds.{name}", [lo, hi], f"low >= 0 ({name} > 0)")
        if FITTABLE[name]:  # an open end: the physical range (ln x stays finite)
            lo = lo if lo > 0 else min(LOG_BOUNDS[name][0], start / 10.0)
            hi = hi if np.isfinite(hi) else max(LOG_BOUNDS[name][1], start * 10.0)
        if FITTABLE[name] and start <= 0:
            raise ParameterError(f"law.{name}", start, f"{name} > 0 to fit it (fitted as ln)")
        if not lo < start < hi:
            raise ParameterError(
                f"law.{name}", start, f"a start strictly inside fit.bounds.{name} = [{lo}, {hi}]"
            )
        lower.append(lo)
        upper.append(hi)
    return FitSpace(tuple(names), np.array(lower), np.array(upper))


class Objective:
    """Residuals and their Jacobian for the least-squares fit (counts driver runs)."""

    def __init__(
        self,
        base: SubloadingParams,
        curves: Sequence[Curve],
        space: FitSpace,
        *,
        jacobian: str = "batched",
        accuracy: float | None = None,
        max_halvings: int = 10,
        progress: ProgressCallback | None = None,
        total: int = 0,
    ) -> None:
        if jacobian not in ("batched", "naive"):
            raise ParameterError("jacobian", jacobian, "'batched' or 'naive'")
        self.base = base
        self.curves = tuple(curves)
        self.space = space
        self.jacobian = jacobian
        self.accuracy = accuracy
        self.max_halvings = max_halvings
        self.progress = progress
        self.total = total
        self.runs = 0
        self.sqrt_w = [np.sqrt(c.sample_weights()) for c in self.curves]
        self.n_residuals = sum(c.n_samples for c in self.curves)
        self.offsets: list[float | None] = []

    def _tick(self) -> None:
        self.runs += 1
        if self.progress is not None:
            self.total = max(self.total, self.runs)
            self.progress(self.runs, self.total)

    def _run(
        self,
        columns: np.ndarray,
        curve: Curve,
        offsets: list[float] | None = None,
        law: SubloadingParams | None = None,
    ) -> np.ndarray:
        self._tick()
        return evaluate_columns(
            self.base,
            self.space.names,
            columns,
            curve,
            accuracy=self.accuracy,
            max_halvings=self.max_halvings,
            offsets=offsets,
            law=law,
        )

    def model(self, x: np.ndarray, law: SubloadingParams | None = None) -> list[np.ndarray]:
        """Model friction ratio of every curve at physical values ``x`` (p,) (``law``: their
        law, when built already); the offsets of the curves that fit theirs are left in
        :attr:`offsets` (None for the others)."""
        models, self.offsets = [], []
        for c in self.curves:
            found: list[float] = []
            models.append(self._run(x[:, None], c, found, law)[0])
            self.offsets.append(found[0] if found else None)
        return models

    def offset_columns(self, x: np.ndarray) -> np.ndarray:
        """(n, q) Jacobian of the weighted residuals with respect to the q fitted offsets
        at law ``x`` and the offsets of the last :meth:`model` call: the model's slope in
        time at each sample (central differences on the interpolated run)."""
        fitted = [j for j, o in enumerate(self.offsets) if o is not None]
        out = np.zeros((self.n_residuals, len(fitted)))
        starts = np.cumsum([0] + [c.n_samples for c in self.curves])
        for col, j in enumerate(fitted):
            curve, offset = self.curves[j], self.offsets[j]
            assert offset is not None and curve.offset_bounds is not None
            h = 1e-6 * max(float(np.ptp(curve.time)), 1e-300)
            ahead, behind = (
                self._run(x[:, None], replace(curve, time_offset=offset + d, offset_bounds=None))[0]
                for d in (h, -h)
            )
            out[starts[j] : starts[j + 1], col] = self.sqrt_w[j] * (ahead - behind) / (2 * h)
        return out

    def residuals(self, theta: np.ndarray) -> np.ndarray:
        x = self.space.from_theta(theta)
        law = checked_law(self.base, self.space.names, x)
        if law is None:
            return np.full(self.n_residuals, PENALTY)
        try:
            models = self.model(x, law)
        except FrictionlabError:
            return np.full(self.n_residuals, PENALTY)
        return self._stack(models)

    def _stack(self, models: Sequence[np.ndarray]) -> np.ndarray:
        return np.concatenate(
            [
                w * (m - c.friction_ratio)
                for w, m, c in zip(self.sqrt_w, models, self.curves, strict=True)
            ]
        )

    def steps(self, theta: np.ndarray) -> np.ndarray:
        """Forward-difference steps in theta: away from an upper bound and invalid laws."""
        _, hi = self.space.theta_bounds()
        h = FD_STEP * np.maximum(1.0, np.abs(theta))
        inside = theta + h < hi
        trials = np.repeat(theta[:, None], theta.size, axis=1)
        trials[np.arange(theta.size), np.arange(theta.size)] += h
        values = self.space.from_theta(trials[:, inside].T).T
        if values.shape[1] and valid_column(self.base, self.space.names, values):
            return np.where(inside, h, -h)  # every step inside: one check as per-point laws
        for j in range(theta.size):
            trial = theta.copy()
            trial[j] += h[j]
            if trial[j] >= hi[j] or not valid_column(
                self.base, self.space.names, self.space.from_theta(trial)
            ):
                h[j] = -h[j]
        return h

    def jac(self, theta: np.ndarray) -> np.ndarray:
        """(n, p) Jacobian of the residuals with respect to theta.

        When the batched run fails (one perturbed law does not run), the columns run one by
        one and a failing perturbation is taken in the opposite direction.
        """
        h = self.steps(theta)
        p = theta.size
        blocks = []
        for w, curve in zip(self.sqrt_w, self.curves, strict=True):
            columns = self._columns(theta, h)
            values = None
            if self.jacobian == "batched":
                try:
                    values = self._run(columns, curve)
                except FrictionlabError:
                    values = None
            if values is None:
                found: list[float] = []
                base = self._run(columns[:, [0]], curve, found)[0]
                rows = [base]
                # the perturbations at the base's offset, as in the batched run
                alone = replace(curve, time_offset=found[0], offset_bounds=None) if found else curve
                for k in range(1, p + 1):
                    rows.append(self._column_or_flip(theta, h, k - 1, alone))
                values = np.stack(rows)
            blocks.append(w[:, None] * (values[1:] - values[0]).T / h)
        return np.vstack(blocks)

    def _columns(self, theta: np.ndarray, h: np.ndarray) -> np.ndarray:
        """(p, p + 1) physical values: the base, then theta + h_j e_j for each j."""
        p = theta.size
        thetas = np.repeat(theta[:, None], p + 1, axis=1)
        thetas[np.arange(p), np.arange(1, p + 1)] += h
        return self.space.from_theta(thetas.T).T

    def _column_or_flip(self, theta: np.ndarray, h: np.ndarray, j: int, curve: Curve) -> np.ndarray:
        """Model of perturbation j; on failure the opposite step (``h[j]`` is flipped)."""
        for attempt in range(2):
            trial = theta.copy()
            trial[j] += h[j]
            x = self.space.from_theta(trial)
            try:
                return self._run(x[:, None], curve)[0]
            except FrictionlabError as exc:
                if attempt == 1:
                    raise ConvergenceError(
                        f"curve '{curve.name}': the driver fails on both sides of "
                        f"{self.space.names[j]} = {self.space.from_theta(theta)[j]:.6g} "
                        f"({exc})",
                        mask=np.ones(1, dtype=bool),
                    ) from None
                h[j] = -h[j]
        raise AssertionError("unreachable")  # pragma: no cover


_CONE_UNITS = {"mu_s": "-", "mu_k": "-", "u": "1/m", "kappa": "1/m", "xi": "1/s"}
_CLOSED_UNITS = {"F_s": "Pa", "F_k": "Pa", "M": "-", "u": "1/m", "kappa": "Pa/m", "xi": "Pa/s"}


def parameter_unit(name: str, cone: bool) -> str:
    """The unit of a law parameter (``-`` for dimensionless ones)."""
    table = _CONE_UNITS if cone else _CLOSED_UNITS
    return table.get(name, "Pa/m" if name.startswith("alpha") else "-")


@dataclass(frozen=True, repr=False)
class FitResult(TableResult):
    """Outcome of :func:`fit_law`.

    Attributes
    ----------
    params:
        The fitted law (the start law with the fitted values).
    names, values, start:
        Fitted parameter names, their fitted and starting values (physical units).
    stderr:
        (p,) standard errors (inf where the data do not determine the parameter).
    covariance, correlation:
        (p, p) covariance (physical units) and correlation matrix (NaN where undefined).
    cost:
        Half the weighted sum of squared residuals at the optimum.
    n_points:
        Number of data samples (residuals); ``dof = n_points - p``.
    residuals:
        Unweighted model - data of every curve at the optimum.
    models:
        Model friction ratio of every curve at its samples, at the optimum.
    success, message, nfev, njev, runs, seconds:
        The optimiser's status, function and Jacobian evaluations, driver runs, wall time.
    theta_jacobian:
        (n, p) weighted-residual Jacobian in the fitted space at the optimum.
    profiles:
        Profiles (:class:`~frictionlab.calibration.profile.Profile`) by name, once computed.
    weights:
        Per curve, the (n,) weight of each sample's squared residual.
    starts:
        Starting points tried (the best one is kept).
    offsets, offset_stderr:
        Per curve, the fitted time offset [s] and its standard error (None for a curve
        with a fixed offset). The law's standard errors account for the fitted offsets.
    """

    params: SubloadingParams
    names: tuple[str, ...]
    values: np.ndarray
    start: np.ndarray
    stderr: np.ndarray
    covariance: np.ndarray
    correlation: np.ndarray
    cost: float
    n_points: int
    residuals: tuple[np.ndarray, ...]
    models: tuple[np.ndarray, ...]
    success: bool
    message: str
    nfev: int
    njev: int
    runs: int
    seconds: float
    space: FitSpace
    theta_jacobian: np.ndarray
    profiles: dict[str, Any] = field(default_factory=dict)
    weights: tuple[np.ndarray, ...] = ()
    starts: int = 1
    offsets: tuple[float | None, ...] = ()
    offset_stderr: tuple[float | None, ...] = ()

    @property
    def dof(self) -> int:
        """Samples less the fitted parameters (the law's and the fitted time offsets)."""
        return self.n_points - len(self.names) - sum(o is not None for o in self.offsets)

    @property
    def residual_variance(self) -> float:
        """s^2 = 2 cost / (n - p), the variance of one weighted residual."""
        return 2.0 * self.cost / self.dof if self.dof > 0 else float("inf")

    @property
    def relative_stderr(self) -> np.ndarray:
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.abs(self.stderr / self.values)

    def columns(self) -> dict[str, np.ndarray]:
        """One row per fitted parameter: its unit (text), start, value, stderr, relative
        stderr (masked where infinite: the data do not identify the parameter)."""
        cone = self.params.is_cone
        return {
            "parameter": np.array(self.names, dtype=object),
            "unit": np.array([parameter_unit(n, cone) for n in self.names], dtype=object),
            "start": np.asarray(self.start, dtype=np.float64),
            "value": np.asarray(self.values, dtype=np.float64),
            # an unidentified parameter's infinite stderr is undefined: masked (empty in CSV)
            "stderr": np.ma.masked_invalid(np.asarray(self.stderr, dtype=np.float64)),
            "relative_stderr": np.ma.masked_invalid(
                np.asarray(self.relative_stderr, dtype=np.float64)
            ),
        }

    def units(self) -> dict[str, str]:
        """All ``-``: each row's unit is in the ``unit`` column."""
        return dict.fromkeys(self.columns(), "-")

    def poorly_identified(self) -> list[str]:
        """Names with relative stderr > 50 % or |correlation| > 0.9 with another parameter."""
        out = []
        for j, name in enumerate(self.names):
            corr = np.delete(np.abs(self.correlation[j]), j)
            strong = bool(np.any(np.nan_to_num(corr, nan=0.0) > CORRELATION_LIMIT))
            if (
                not np.isfinite(self.stderr[j])
                or self.relative_stderr[j] > RELATIVE_STDERR_LIMIT
                or strong
            ):
                out.append(name)
        return out

    def not_identified(self) -> list[str]:
        """Names the data do not bound: an undetermined direction (infinite stderr), a value
        at an end of its bounds, or a profile whose 95 % interval is open on a side.

        Their fitted values are arbitrary within what the data allow; report them as not
        identified, not as estimates.
        """
        lo, hi = self.space.theta_bounds()
        theta = self.space.to_theta(self.values)
        span = np.where(np.isfinite(hi - lo), hi - lo, np.maximum(1.0, np.abs(theta)))
        at_bound = (theta - lo <= 1e-6 * span) | (hi - theta <= 1e-6 * span)
        out = []
        for j, name in enumerate(self.names):
            prof = self.profiles.get(name)
            open_profile = prof is not None and None in prof.interval
            if not np.isfinite(self.stderr[j]) or at_bound[j] or open_profile:
                out.append(name)
        return out

    def bands(self, level: float = 0.95) -> tuple[tuple[np.ndarray, np.ndarray], ...]:
        """Per curve, the half-widths (confidence, prediction) of the fitted curve at its
        samples for a two-sided ``level``: ``z sqrt(g_i^T cov_theta g_i)`` with g_i the
        model's gradient in the fitted space, and with the residual variance s^2/w added
        for a new measurement. Infinite where a parameter is not determined; NaN at samples
        of weight 0."""
        from scipy.special import ndtri  # the normal quantile without importing scipy.stats

        if not 0 < level < 1:
            raise ParameterError("band_level", level, "a number in (0, 1)")
        z = float(ndtri(0.5 + 0.5 * level))
        s2 = self.residual_variance
        jac = self.theta_jacobian
        _, sv, vt = np.linalg.svd(jac, full_matrices=False)
        keep = sv > 1e-10 * sv[0] if sv.size and sv[0] > 0 else np.zeros(sv.size, dtype=bool)
        cov_theta = s2 * (vt[keep].T / sv[keep] ** 2) @ vt[keep]
        out = []
        row = 0
        undetermined = not bool(np.all(np.isfinite(self.stderr)))
        for model, w in zip(self.models, self.weights, strict=True):
            n = model.size
            counted = w > 0  # a sample of weight 0 keeps no gradient in the weighted Jacobian
            root = np.sqrt(np.where(counted, w, 1.0))
            g = jac[row : row + n] / root[:, None]
            row += n
            var = np.einsum("ij,jk,ik->i", g, cov_theta, g)
            conf = np.where(counted, z * np.sqrt(np.maximum(var, 0.0)), np.nan)
            pred = np.where(counted, z * np.sqrt(np.maximum(var, 0.0) + s2 / root**2), np.nan)
            if undetermined:
                conf = np.full(n, np.inf)
                pred = np.full(n, np.inf)
            out.append((conf, pred))
        return tuple(out)

    def worst_identified(self, limit: int) -> list[str]:
        """Up to ``limit`` poorly identified names, the largest relative stderr first."""
        poor = self.poorly_identified()
        rel = {n: float(np.nan_to_num(self.relative_stderr[self.names.index(n)], nan=np.inf))
               for n in poor}  # fmt: skip
        return sorted(poor, key=lambda n: -rel[n])[:limit]

    def strong_correlations(self) -> list[tuple[str, str, float]]:
        """Pairs with |correlation| > 0.9, strongest first."""
        pairs = []
        p = len(self.names)
        for a in range(p):
            for b in range(a + 1, p):
                c = float(self.correlation[a, b])
                if np.isfinite(c) and abs(c) > CORRELATION_LIMIT:
                    pairs.append((self.names[a], self.names[b], c))
        return sorted(pairs, key=lambda t: -abs(t[2]))


def uncertainty(
    jac_theta: np.ndarray,
    cost: float,
    space: FitSpace,
    x: np.ndarray,
    nuisance: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(stderr, covariance, correlation, nuisance stderr) in physical units from the
    Jacobian in theta.

    ``cov_theta = s^2 (J^T J)^-1``, s^2 = 2 cost/(n - p); directions that the data do not
    determine (singular values below 1e-10 of the largest) get an infinite stderr.
    ``nuisance`` (n, q): Jacobian columns of parameters fitted beside the law (the time
    offsets); they join J, so the law's covariance is the marginal one, and their own
    standard errors come back last.
    """
    q = 0 if nuisance is None else nuisance.shape[1]
    full = jac_theta if nuisance is None else np.hstack([jac_theta, nuisance])
    n, p = jac_theta.shape
    s2 = 2.0 * cost / (n - p - q) if n > p + q else np.inf
    _, sv, vt = np.linalg.svd(full, full_matrices=False)
    keep = sv > 1e-10 * sv[0] if sv.size and sv[0] > 0 else np.zeros(p + q, dtype=bool)
    inv = (vt[keep].T / sv[keep] ** 2) @ vt[keep]
    undetermined = np.zeros(p + q, dtype=bool)
    if not keep.all():
        undetermined = np.any(np.abs(vt[~keep]) > 1e-8, axis=0)
    cov_all = s2 * inv
    extra = np.where(undetermined[p:], np.inf, np.sqrt(np.maximum(np.diag(cov_all)[p:], 0.0)))
    undetermined = undetermined[:p]
    cov_theta = cov_all[:p, :p]
    factor = space.jacobian_factor(x)
    cov = cov_theta * np.outer(factor, factor)
    var = np.diag(cov).copy()
    stderr = np.where(undetermined, np.inf, np.sqrt(np.maximum(var, 0.0)))
    with np.errstate(divide="ignore", invalid="ignore"):
        d = np.sqrt(np.diag(cov_theta))
        corr = cov_theta / np.outer(d, d)
    corr[undetermined, :] = np.nan
    corr[:, undetermined] = np.nan
    np.fill_diagonal(corr, 1.0)
    return stderr, cov, corr, extra


def fit_law(
    params: SubloadingParams,
    curves: Sequence[Curve],
    names: Sequence[str],
    bounds: Mapping[str, tuple[float, float]] | None = None,
    *,
    jacobian: str = "batched",
    max_nfev: int = 100,
    xtol: float = 1e-10,
    ftol: float = 1e-12,
    gtol: float = 1e-12,
    accuracy: float | None = None,
    max_halvings: int = 10,
    progress: ProgressCallback | None = None,
    starts: int = 1,
    seed: int = 0,
) -> FitResult:
    """Fit ``names`` of ``params`` (the start; other keys stay fixed) to ``curves``.

    Parameters
    ----------
    params:
        The starting law; parameters not in ``names`` keep their values.
    curves:
        Measured curves with their programmes (one point each).
    names:
        Parameters to fit (keys of :data:`~frictionlab.calibration.model.FITTABLE`).
    bounds:
        Optional physical bounds ``name -> (low, high)``; default the physical range
        (0, inf).
    jacobian:
        ``"batched"`` (default: all perturbations in one driver run per curve) or
        ``"naive"`` (one run per perturbation).
    max_nfev, xtol, ftol, gtol:
        Passed to :func:`scipy.optimize.least_squares`.
    accuracy, max_halvings:
        The driver's step control (see :func:`frictionlab.driver.simulate`).
    progress:
        ``progress(done, total)`` after every driver run.
    starts, seed:
        Starting points: the given law, and ``starts - 1`` more from a scrambled Halton
        sequence (:mod:`scipy.stats.qmc`, seeded) over the bounds in the fitted space; the
        lowest cost is kept.

    Raises
    ------
    ParameterError
        Bad names or bounds, no curve, or fewer samples than parameters.
    ConvergenceError
        When the driver fails at the starting law.
    """
    if not curves:
        raise ParameterError("data", 0, "at least one curve")
    space = make_space(params, names, bounds)
    x0 = np.array([float(getattr(params, n)) for n in names])
    n_samples = sum(c.n_samples for c in curves)
    if n_samples <= len(names):
        raise ParameterError("data", f"{n_samples} samples", f"more than {len(names)} samples")
    p = len(names)
    per_nfev = len(curves) * (2 if jacobian == "batched" else p + 2)
    obj = Objective(
        params, curves, space, jacobian=jacobian, accuracy=accuracy,
        max_halvings=max_halvings, progress=progress, total=max_nfev * per_nfev,
    )  # fmt: skip
    start = _time.perf_counter()
    obj.model(x0)  # fail early, with the driver's message, when the start does not run
    if isinstance(starts, bool) or not isinstance(starts, int) or not 1 <= starts <= 1000:
        raise ParameterError("fit.starts", starts, "an integer in 1..1000")
    lo, hi = space.theta_bounds()
    res = None

    def valid(theta: np.ndarray) -> bool:
        return valid_column(params, names, space.from_theta(theta))

    for theta0 in _starting_points(space, x0, starts, seed, valid):
        trial = least_squares(
            obj.residuals, theta0, jac=obj.jac, bounds=(lo, hi), method="trf",
            x_scale="jac", xtol=xtol, ftol=ftol, gtol=gtol, max_nfev=max_nfev,
        )  # fmt: skip
        if res is None or trial.cost < res.cost:
            res = trial
    assert res is not None
    x = space.from_theta(res.x)
    fitted = with_values(params, names, x)
    try:
        models = obj.model(x)
    except FrictionlabError as exc:  # pragma: no cover - the optimum ran inside the fit
        raise ConvergenceError(f"the fitted law does not run: {exc}", mask=np.ones(1)) from None
    r = obj._stack(models)
    cost = 0.5 * float(r @ r)
    offsets = tuple(obj.offsets)
    jac = obj.jac(res.x)
    nuisance = obj.offset_columns(x) if any(o is not None for o in offsets) else None
    stderr, cov, corr, nuisance_stderr = uncertainty(jac, cost, space, x, nuisance)
    it = iter(nuisance_stderr)
    offset_stderr = tuple(None if o is None else float(next(it)) for o in offsets)
    return FitResult(
        params=fitted,
        names=tuple(names),
        values=x,
        start=x0,
        stderr=stderr,
        covariance=cov,
        correlation=corr,
        cost=cost,
        n_points=n_samples,
        residuals=tuple(m - c.friction_ratio for m, c in zip(models, curves, strict=True)),
        models=tuple(models),
        success=bool(res.success),
        message=str(res.message),
        nfev=int(res.nfev),
        njev=int(res.njev or 0),
        runs=obj.runs,
        seconds=_time.perf_counter() - start,
        space=space,
        theta_jacobian=jac,
        weights=tuple(c.sample_weights() for c in curves),
        starts=starts,
        offsets=offsets,
        offset_stderr=offset_stderr,
    )


def _starting_points(
    space: FitSpace,
    x0: np.ndarray,
    starts: int,
    seed: int,
    valid: Callable[[np.ndarray], bool] = lambda theta: True,
) -> list[np.ndarray]:
    """The start in theta, then ``starts - 1`` scrambled-Halton points inside the bounds that
    make a ``valid`` law (mu_k <= mu_s, ...): the sequence is drawn on until it has them
    (at most 50 times as many draws)."""
    theta0 = space.to_theta(x0)
    points = [theta0]
    if starts > 1:
        from scipy.stats import qmc  # only here: importing scipy.stats costs ~0.5 CPU s

        lo, hi = space.theta_bounds()
        # an open end (linear parameters): a decade around the start
        lo = np.where(np.isfinite(lo), lo, theta0 - 10.0 * np.maximum(1.0, np.abs(theta0)))
        hi = np.where(np.isfinite(hi), hi, theta0 + 10.0 * np.maximum(1.0, np.abs(theta0)))
        width = hi - lo
        halton = qmc.Halton(d=theta0.size, scramble=True, seed=seed)
        for _ in range(50 * (starts - 1)):
            # strictly inside: least_squares needs an interior start
            theta = lo + width * (1e-6 + (1 - 2e-6) * halton.random(1)[0])
            if valid(theta):
                points.append(theta)
                if len(points) == starts:
                    break
    return points
