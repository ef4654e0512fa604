"""The lattice-spring friction model (ALSFM): mu_x, mu_y and mu(beta) of two rough surfaces.

The time-averaged lattice algorithm, for any pair of surfaces (profiles and height maps):

* **Lattice.** Spring stations on a regular grid over one common period cell of the two
  surfaces, at the cell centres ``((i + 1/2) dx, (k + 1/2) dy)``. Two families share the
  stations: upper-fixed springs slide on surface 1 (lower, fixed),
  lower-fixed springs slide on surface 2 (upper, moving along beta).
* **Time samples.** The upper surface is shifted by ``s_j = s_0 + (j/n) D (cos b, sin b)``
  over one relative period D along beta, starting in phase (``s_0 = 0``).
* **Per sample.** Gap ``g = f2(P - s) - f1(P)``; load balance for ``c = l0 - d``
  (bisection-free exact Newton on the piecewise-linear spring law with k_c and k_t);
  compression ``u = c - g``; compressed springs carry friction with the multipliers
  ``H(mu0, grad f1(P), beta)`` and ``H(mu0, grad f2(P - s), beta)`` (frame-free Eqs 1-4);
  sums Eqs 5-9.
* **Coefficients.** ``mu_x = <sum X>/<R_z>``, ``mu_y = <sum Y>/<R_z>``;
  ``mu = sqrt(mu_x^2 + mu_y^2)`` ("magnitude", default) or ``mu_x cos b + mu_y sin b``
  ("projection", the dissipative coefficient), option ``mu_definition``.

Options, all fields of :class:`LatticeSettings` with defaults: ``load``
(``"full"``: the full-contact limit where every spring carries the same force; or the mean
normal force per spring, N), ``control`` (``"load"``: L held and c solved each sample;
``"separation"``: c held), ``k_c`` = 1 N/m, ``k_t`` = 0 (tensile springs: they carry load,
never friction), ``stations`` (2000 per shortest period in 1-D, 64 x 64 per shortest
periods in 2-D; sampled surfaces: their own grid), ``time_samples`` = 400 per relative
period, ``travel`` (``"auto"``: exact return when the direction is commensurate, else
the ergodic average over all relative shifts), ``phase`` = in phase, ``on_invalid`` =
``"error"`` (a :class:`~frictionlab.errors.ValidityError` when a compressed contact
violates Eq 1's bound), ``"drop"`` or ``"mask"`` (one vocabulary:
:mod:`~frictionlab.roughness.validity`); ``engine`` = ``"numba"`` or ``"numpy"``;
``full_contact`` = ``"average"`` (``load="full"`` as the direct area average of
:mod:`frictionlab.roughness.full_contact`, no time sampling) or ``"lattice"``;
``snap_time_samples`` = True (return paths use whole-station shifts).
"""

from __future__ import annotations

import math
import queue
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field, fields, replace
from typing import Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frictionlab._arrays import FloatArray, finite_vector, readonly
from frictionlab._frames import TableResult
from frictionlab._jit import numba
from frictionlab.errors import ParameterError, ValidityError
from frictionlab.roughness import _kernels
from frictionlab.roughness.closed_forms import max_mu0
from frictionlab.roughness.full_contact import full_contact_sums
from frictionlab.roughness.surface import HeightMap, Surface
from frictionlab.roughness.validity import check_on_invalid

__all__ = [
    "MU_DEFINITIONS",
    "STATIONS_PER_PERIOD_1D",
    "STATIONS_PER_PERIOD_2D",
    "FrictionPolar",
    "LatticeGeometry",
    "LatticeSettings",
    "friction_polar",
    "lattice_geometry",
    "merge_polars",
]

#: Default spring stations per shortest surface period (1-D profiles).
STATIONS_PER_PERIOD_1D = 2000
#: Default spring stations per shortest surface period and axis (2-D height maps).
STATIONS_PER_PERIOD_2D = 64
#: Largest number of stations in one lattice.
MAX_STATIONS = 1 << 22
#: Largest integer ratio accepted between two periods of a common cell.
MAX_PERIOD_RATIO = 64

MU_DEFINITIONS = ("magnitude", "projection")
CONTROLS = ("load", "separation")
TRAVEL_MODES = ("auto", "return", "ergodic")
ENGINES = ("numba", "numpy")
FULL_CONTACT_METHODS = ("average", "lattice")


def _is_int(value: Any) -> bool:
    return isinstance(value, int | np.integer) and not isinstance(value, bool)


def _finite(value: Any) -> bool:
    return (
        isinstance(value, int | float | np.floating)
        and not isinstance(value, bool)
        and (math.isfinite(float(value)))
    )


@dataclass(frozen=True)
class LatticeSettings:
    """Options of the lattice computation, validated.

    Attributes
    ----------
    load:
        ``"full"`` (default): the full-contact limit, every spring carries the same force
        (the load-independent value of wedges and height-uncorrelated
        profiles). A number: the mean normal force per spring (N), held constant while sliding
        (``control="load"``); > 0 unless ``k_t`` > 0.
    control:
        ``"load"`` (default, L held, c solved per sample) or ``"separation"`` (c held).
    separation:
        ``c = l0 - d`` (m) for ``control="separation"``; the compression is ``c - gap``.
    k_c, k_t:
        Compressive and tensile spring stiffness (N/m); ``0 <= k_t <= k_c``. Tensile springs
        carry load but no friction.
    detachment:
        Cut-off elongation (m) beyond which a stretched spring detaches and carries no
        force (the paper gives no criterion). ``None`` (default): never.
        Needs ``k_t > 0``. The load balance is then not monotone; the largest offset c
        that carries the load is taken (the state reached by pulling apart from full
        contact), and a load below the pull-off force is an error.
    stations:
        Stations per common period cell: an int (1-D; in 2-D the same count on both axes)
        or (nx, ny). ``None``: 2000 per shortest period (1-D), 64 per shortest period and
        axis (2-D), or the sample grid of sampled surfaces, whichever is finer.
    time_samples:
        Samples per relative period along beta (a return path crossing the cell m times
        along x and n times along y gets ``time_samples * max(|m|, |n|)``). For the
        ergodic average: about ``time_samples`` relative shifts on a grid of
        ``sqrt(time_samples)`` per axis, rounded to the nearest divisor of the station
        count within a factor 2 (else raised to the next integer). Shifts by whole
        station spacings reuse the upper surface evaluated once.
    travel:
        ``"auto"`` (default): ``"return"`` where beta is commensurate with the cell within
        ``max_return_periods``, else ``"ergodic"``. ``"return"``: one exact relative period
        (1-D: the period along x; error if none). ``"ergodic"``: the average over all
        relative shifts in the cell (the limit of an infinitely long incommensurate path).
        A number: the travel distance (m) of a straight path sampled ``time_samples``
        times.
    max_return_periods:
        Largest m, n of a return vector (m Lx, n Ly) searched in 2-D.
    phase:
        Initial offset (x, y) (m) of the upper surface; (0, 0) is "in phase".
    mu_definition:
        ``"magnitude"`` (default) or ``"projection"``.
    on_invalid:
        ``"error"`` (default; the old spelling ``"raise"`` warns): a ValidityError when a
        compressed contact violates Eq 1's bound (raised at the first offending time
        sample); ``"mask"``: that direction gets ``valid = False`` and NaN coefficients;
        ``"drop"``: the offending contacts are left
        out (they carry neither load nor friction in the averages, the load balance still
        counts their springs) and their fraction of all 2 N contacts, averaged over the
        time samples, is reported per direction (``invalid_fraction``).
    full_contact:
        How ``load="full"`` is computed: ``"average"`` (default): the direct area average
        of the multipliers over both surfaces (:mod:`frictionlab.roughness.full_contact`:
        exact in full contact, where the load drops out), all directions in one pass, no
        time sampling
        (``time_samples = 0``, travel mode ``"average"``); ``"lattice"``: the time-sampled
        lattice (identical when its shifts are whole stations; kept for comparison).
    snap_time_samples:
        ``True`` (default): on a return path, the number of time samples is moved to the
        nearest count whose shifts are whole station spacings (it then divides the station
        grid along the path), so the upper surface is evaluated once and read rolled. This
        changes mu only by the quadrature error of the time average (the samples still
        cover one relative period uniformly). ``False``: exactly ``time_samples``.
    engine:
        ``"numba"`` (default, compiled kernels) or ``"numpy"`` (reference twin).
    shift_invariance:
        ``True`` (default): when either surface is flat every relative shift is the same
        configuration (a translation of the rough surface over the periodic cell), so
        each direction takes one time sample at the start phase (travel mode
        ``"invariant"``). Equal to the time-sampled average to rounding when the samples
        are whole-station shifts (the default snapping); otherwise it differs from it
        only by the interpolation error of the shifted samples. ``False``: sample the
        path anyway.
    """

    load: float | str = "full"
    control: str = "load"
    separation: float | None = None
    k_c: float = 1.0
    k_t: float = 0.0
    detachment: float | None = None
    stations: int | tuple[int, int] | None = None
    time_samples: int = 400
    travel: str | float = "auto"
    max_return_periods: int = 8
    phase: tuple[float, float] = (0.0, 0.0)
    mu_definition: str = "magnitude"
    on_invalid: str = "error"
    engine: str = "numba"
    full_contact: str = "average"
    snap_time_samples: bool = True
    shift_invariance: bool = True

    def __post_init__(self) -> None:
        if self.control not in CONTROLS:
            raise ParameterError("control", self.control, f"one of {CONTROLS}")
        if not (_finite(self.k_c) and self.k_c > 0.0):
            raise ParameterError("k_c", self.k_c, "a positive stiffness in N/m")
        if not (_finite(self.k_t) and 0.0 <= self.k_t <= self.k_c):
            raise ParameterError("k_t", self.k_t, f"0 <= k_t <= k_c = {self.k_c}")
        object.__setattr__(self, "k_c", float(self.k_c))
        object.__setattr__(self, "k_t", float(self.k_t))
        if self.detachment is not None:
            if not (_finite(self.detachment) and self.detachment > 0.0):
                raise ParameterError(
                    "detachment", self.detachment, "None or a cut-off elongation > 0 m"
                )
            if self.k_t == 0.0:
                raise ParameterError("detachment", self.detachment, "None unless k_t > 0")
            object.__setattr__(self, "detachment", float(self.detachment))
        if self.control == "load":
            if self.separation is not None:
                raise ParameterError("separation", self.separation, "None with control='load'")
            if isinstance(self.load, str):
                if self.load != "full":
                    raise ParameterError("load", self.load, "'full' or a force per spring in N")
            elif not _finite(self.load):
                raise ParameterError("load", self.load, "'full' or a finite force per spring in N")
            elif self.k_t == 0.0 and self.load <= 0.0:
                raise ParameterError("load", self.load, "> 0 N per spring (k_t = 0: no adhesion)")
            else:
                object.__setattr__(self, "load", float(self.load))
        else:
            if self.load != "full":
                raise ParameterError("load", self.load, "left at 'full' with control='separation'")
            if not _finite(self.separation):
                raise ParameterError("separation", self.separation, "a finite offset c in m")
            object.__setattr__(self, "separation", float(self.separation))  # type: ignore[arg-type]
        if self.stations is not None:
            values: Any = (self.stations,) if _is_int(self.stations) else self.stations
            if (
                not isinstance(values, tuple | list)
                or len(values) not in (1, 2)
                or not all(_is_int(v) and int(v) >= 1 for v in values)
            ):
                raise ParameterError("stations", self.stations, "an integer >= 1 or (nx, ny)")
            object.__setattr__(
                self,
                "stations",
                int(values[0]) if len(values) == 1 else (int(values[0]), int(values[1])),
            )
        if not (_is_int(self.time_samples) and self.time_samples >= 1):
            raise ParameterError("time_samples", self.time_samples, "an integer >= 1")
        if isinstance(self.travel, str):
            if self.travel not in TRAVEL_MODES:
                raise ParameterError("travel", self.travel, f"one of {TRAVEL_MODES} or a length")
        elif not (_finite(self.travel) and self.travel > 0.0):
            raise ParameterError("travel", self.travel, f"one of {TRAVEL_MODES} or a length > 0 m")
        if not (_is_int(self.max_return_periods) and self.max_return_periods >= 1):
            raise ParameterError("max_return_periods", self.max_return_periods, "an integer >= 1")
        try:
            px, py = self.phase
        except (TypeError, ValueError):
            raise ParameterError("phase", self.phase, "two offsets (x, y) in m") from None
        if not (_finite(px) and _finite(py)):
            raise ParameterError("phase", self.phase, "two finite offsets (x, y) in m")
        object.__setattr__(self, "phase", (float(px), float(py)))
        if self.mu_definition not in MU_DEFINITIONS:
            raise ParameterError("mu_definition", self.mu_definition, f"one of {MU_DEFINITIONS}")
        object.__setattr__(self, "on_invalid", check_on_invalid(self.on_invalid))
        if self.engine not in ENGINES:
            raise ParameterError("engine", self.engine, f"one of {ENGINES}")
        if self.full_contact not in FULL_CONTACT_METHODS:
            raise ParameterError(
                "full_contact", self.full_contact, f"one of {FULL_CONTACT_METHODS}"
            )
        if not isinstance(self.snap_time_samples, bool):
            raise ParameterError("snap_time_samples", self.snap_time_samples, "true or false")
        if not isinstance(self.shift_invariance, bool):
            raise ParameterError("shift_invariance", self.shift_invariance, "true or false")

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary of the settings."""
        out = asdict(self)
        out["phase"] = list(self.phase)
        if isinstance(self.stations, tuple):
            out["stations"] = list(self.stations)
        return out


@dataclass(frozen=True)
class LatticeGeometry:
    """The common period cell and the station grid of a surface pair.

    ``dimension`` is 1 when both surfaces are profiles (y plays no role), else 2. ``cell``
    is (Lx, Ly) (m), Ly = None in 1-D; ``shape`` the station counts per axis.
    """

    dimension: int
    cell: tuple[float, float | None]
    shape: tuple[int, ...]

    @property
    def n_stations(self) -> int:
        return int(np.prod(self.shape))

    def station_coordinates(self) -> tuple[FloatArray, FloatArray]:
        """Station x (column) and y (row) coordinates (m), broadcastable to ``shape``.

        1-D: x has shape (n,), y shape (1,) (zeros). 2-D: x (nx, 1), y (1, ny).
        """
        lx, ly = self.cell
        x = np.asarray((np.arange(self.shape[0]) + 0.5) * (lx / self.shape[0]), dtype=np.float64)
        if self.dimension == 1:
            return x, np.zeros(1)
        assert ly is not None
        y = np.asarray((np.arange(self.shape[1]) + 0.5) * (ly / self.shape[1]), dtype=np.float64)
        return x[:, None], y[None, :]


def _common_period(values: Sequence[float], axis: str) -> float:
    """Least common multiple of periods (m), accepting integer ratios p/q up to 64."""
    result = values[0]
    for v in values[1:]:
        ratio = v / result  # result * p == v * q with p = q * ratio
        for q in range(1, MAX_PERIOD_RATIO + 1):
            p = round(q * ratio)
            if 1 <= p <= MAX_PERIOD_RATIO and abs(p - q * ratio) <= 1e-9 * p:
                result = result * p
                break
        else:
            raise ParameterError(
                f"periods along {axis}",
                [result, v],
                f"commensurate periods (an integer ratio p/q with p, q <= {MAX_PERIOD_RATIO})",
            )
    return result


def lattice_geometry(
    lower: Surface, upper: Surface, stations: int | tuple[int, int] | None = None
) -> LatticeGeometry:
    """The common period cell of two surfaces and the station grid (see LatticeSettings)."""
    for name, s in (("lower", lower), ("upper", upper)):
        if not isinstance(s, Surface):
            raise ParameterError(name, type(s).__name__, "a Profile or HeightMap surface")
    dimension = 2 if isinstance(lower, HeightMap) or isinstance(upper, HeightMap) else 1
    xs = [s.periods[0] for s in (lower, upper) if s.periods[0] is not None]
    ys = [s.periods[1] for s in (lower, upper) if s.periods[1] is not None]
    if dimension == 1 and not xs:  # two flat surfaces: any cell, one station suffices
        return LatticeGeometry(1, (1.0, None), (1,))
    lx = _common_period([float(v) for v in xs], "x")
    ly = _common_period([float(v) for v in ys], "y") if dimension == 2 else None
    per_period = STATIONS_PER_PERIOD_1D if dimension == 1 else STATIONS_PER_PERIOD_2D
    if stations is None:
        counts = []
        for axis, length in enumerate((lx, ly)[:dimension]):
            best = 1
            for s in (lower, upper):
                period = s.periods[axis]
                if period is None:
                    continue
                assert length is not None
                grid = s.grid_shape
                per = grid[axis] if grid is not None else per_period
                best = max(best, round(per * length / period))
            counts.append(best)
        shape = tuple(counts)
    elif isinstance(stations, int):
        shape = (stations,) * dimension
    else:
        if dimension == 1:
            raise ParameterError("stations", stations, "one integer for two 1-D profiles")
        shape = (int(stations[0]), int(stations[1]))
    total = int(np.prod(shape))
    if total > MAX_STATIONS:
        raise ParameterError("stations", list(shape), f"at most {MAX_STATIONS} stations in all")
    return LatticeGeometry(dimension, (lx, ly), shape)


@dataclass(frozen=True, repr=False)
class FrictionPolar(TableResult):
    """Friction coefficients of a surface pair over sliding directions (SciPy-style result).

    Arrays are indexed like ``beta_deg``. ``mu`` follows ``settings.mu_definition``;
    ``mu_magnitude`` and ``mu_projection`` are both always given. ``mu_apparent`` is Eq 22
    (resultant friction of the compressed springs over the applied load, tensile springs
    included in the load); it equals ``mu_magnitude`` without tensile springs. It is
    ``None`` when the applied load is zero (Eq 22 is singular there; the tangential force
    is still in ``force_x``, ``force_y``). ``contact_fraction_*`` and
    ``tensile_fraction_*`` are the fractions of compressed and of stretched springs over
    the time samples (``*_min``/``*_max``: extreme sample; ``*_mean``: average over the
    period); contact is 1 in full contact. ``invalid_fraction`` is the fraction of all
    2 N contacts violating Eq 1 that ``on_invalid="drop"`` left out (time-averaged; 0
    for the other modes, where such a direction raises or is masked). ``notes``: sentences
    for the user (a numeric load that compresses every spring at every sample says so).

    Forces are time averages per spring (N; both families, ``2 N_stations`` springs):
    ``force_x``, ``force_y`` are the resisting force R^(c) of the compressed springs
    (Eqs 6-9), ``compressed_force`` their mean compressive force (so ``mu_x = force_x /
    compressed_force``). In the full-contact limit (``load="full"``) forces are per unit
    spring force (``compressed_force = 1``). ``in_contact`` is False where no spring was
    ever compressed (possible only with tensile springs at a load <= 0): there R^(c) = 0
    and ``mu_x``, ``mu_y``, ``mu*`` are NaN (undefined; use :meth:`columns` or
    :mod:`frictionlab.roughness.adhesion` for masked values).
    """

    beta_deg: FloatArray
    mu_x: FloatArray
    mu_y: FloatArray
    mu: FloatArray
    mu_magnitude: FloatArray
    mu_projection: FloatArray
    mu_apparent: FloatArray | None
    valid: NDArray[np.bool_]
    invalid_fraction: FloatArray
    contact_fraction_min: FloatArray
    contact_fraction_mean: FloatArray
    tensile_fraction_max: FloatArray
    tensile_fraction_mean: FloatArray
    force_x: FloatArray
    force_y: FloatArray
    compressed_force: FloatArray
    in_contact: NDArray[np.bool_]
    time_samples: NDArray[np.int64]
    solver_iterations_max: NDArray[np.int64]
    travel_mode: tuple[str, ...]
    travel_m: tuple[float | None, ...]
    mu0: float
    settings: LatticeSettings
    geometry: LatticeGeometry
    spring_evaluations: int
    success: bool
    message: str
    invalid_messages: tuple[str, ...] = field(default=())
    notes: tuple[str, ...] = field(default=())

    @property
    def mu_over_mu0(self) -> FloatArray:
        """mu / mu0 (requires mu0 > 0)."""
        if self.mu0 <= 0.0:
            raise ParameterError("mu0", self.mu0, "> 0 to normalise by it")
        return self.mu / self.mu0

    @property
    def tangential_force(self) -> FloatArray:
        """|R_xy^(c)|: magnitude of the resisting force of the compressed springs (N/spring)."""
        return np.asarray(np.hypot(self.force_x, self.force_y), dtype=np.float64)

    def units(self) -> dict[str, str]:
        """Units of :meth:`columns` (``-`` for dimensionless ones)."""
        force = {"tangential_force": "N", "compressed_force": "N"}
        return {k: "deg" if k == "beta_deg" else force.get(k, "-") for k in self.columns()}

    def columns(self) -> dict[str, np.ndarray]:
        """The per-direction arrays as named columns (for tables).

        Undefined values (NaN coefficients of directions without contact or violating
        Eq 1 under ``on_invalid="mask"``; ``mu_apparent`` at zero load) are masked
        (``numpy.ma``), written as empty CSV fields by :mod:`frictionlab.io.tables`.
        Forces are included for a numeric load (N per spring).
        """
        out = polar_head_columns(self)
        apparent = (
            np.ma.masked_all(self.beta_deg.shape) if self.mu_apparent is None else self.mu_apparent
        )
        out.update(
            mu_magnitude=self.mu_magnitude,
            mu_projection=self.mu_projection,
            mu_apparent=apparent,
            contact_fraction_min=self.contact_fraction_min,
            contact_fraction_mean=self.contact_fraction_mean,
            time_samples=self.time_samples,
        )
        if self.settings.on_invalid == "drop":
            out["invalid_fraction"] = self.invalid_fraction
        if not isinstance(self.settings.load, str):
            out.update(
                tangential_force=self.tangential_force,
                compressed_force=self.compressed_force,
                tensile_fraction_mean=self.tensile_fraction_mean,
                tensile_fraction_max=self.tensile_fraction_max,
            )
        return masked_columns(out)


def merge_polars(first: FrictionPolar, *others: FrictionPolar) -> FrictionPolar:
    """One polar holding the directions of several (same surfaces and settings), by beta.

    Per-direction arrays are concatenated and sorted by ``beta_deg`` (stable); work
    counters add up; invalid-direction messages are kept.
    """
    polars = (first, *others)
    for p in others:
        if p.settings != first.settings or p.mu0 != first.mu0 or p.geometry != first.geometry:
            raise ParameterError("others", "a polar of another computation", "same settings")
    order = np.argsort(np.concatenate([p.beta_deg for p in polars]), kind="stable")
    merged: dict[str, Any] = {}
    n = first.beta_deg.size
    for f in fields(FrictionPolar):
        value = getattr(first, f.name)
        if isinstance(value, np.ndarray) and value.shape == (n,):
            merged[f.name] = readonly(
                np.concatenate([getattr(p, f.name) for p in polars])[order], None
            )
        elif isinstance(value, tuple) and len(value) == n and f.name != "invalid_messages":
            values = [v for p in polars for v in getattr(p, f.name)]
            merged[f.name] = tuple(values[i] for i in order)
    merged["spring_evaluations"] = sum(p.spring_evaluations for p in polars)
    merged["invalid_messages"] = tuple(m for p in polars for m in p.invalid_messages)
    merged["notes"] = tuple(dict.fromkeys(n for p in polars for n in p.notes))
    merged["success"] = all(p.success for p in polars)
    bad = int(np.count_nonzero(~merged["valid"]))
    merged["message"] = (
        "ok" if bad == 0 else f"{bad} of {order.size} directions violate Eq 1's bound"
    )
    return replace(first, **merged)


def _cos_sin_deg(beta_deg: float) -> tuple[float, float]:
    """cos and sin of an angle in degrees, exact at multiples of 90 degrees."""
    b = math.fmod(beta_deg, 360.0)
    if b < 0.0:
        b += 360.0
    exact = {0.0: (1.0, 0.0), 90.0: (0.0, 1.0), 180.0: (-1.0, 0.0), 270.0: (0.0, -1.0)}
    if b in exact:
        return exact[b]
    r = math.radians(b)
    return math.cos(r), math.sin(r)


@dataclass(frozen=True)
class _Path:
    shifts: FloatArray  # (n, 2) upper-surface offsets (m)
    mode: str
    travel: float | None


def _return_vector(
    geometry: LatticeGeometry, beta_deg: float, limit: int
) -> tuple[int, int] | None:
    """Smallest (m, n) with (m Lx, n Ly) along beta, |m|, |n| <= limit; None if none."""
    lx, ly = geometry.cell
    assert ly is not None
    beta = math.radians(beta_deg)
    best: tuple[int, int] | None = None
    best_len = math.inf
    for m in range(-limit, limit + 1):
        for n in range(-limit, limit + 1):
            if (m == 0 and n == 0) or math.gcd(m, n) != 1:
                continue
            angle = math.atan2(n * ly, m * lx)
            diff = abs(math.remainder(angle - beta, 2.0 * math.pi))
            length = math.hypot(m * lx, n * ly)
            if diff < 1e-9 and length < best_len:
                best, best_len = (m, n), length
    return best


def _sliding_path(geometry: LatticeGeometry, beta_deg: float, settings: LatticeSettings) -> _Path:
    """Upper-surface offsets of the time samples."""
    phase = np.array(settings.phase)
    nt = settings.time_samples
    cb, sb = _cos_sin_deg(beta_deg)
    lx, ly = geometry.cell
    j = np.arange(nt)[:, None] / nt
    if not isinstance(settings.travel, str):
        d = float(settings.travel)
        return _Path(phase + j * d * np.array([cb, sb]), "explicit", d)
    if geometry.dimension == 1:
        if abs(cb) < 1e-12:
            if settings.travel == "ergodic":
                shifts = phase + j * np.array([lx, 0.0])
                return _Path(shifts, "ergodic", None)
            return _Path(phase[None, :], "static", 0.0)
        # s_x sweeps one period along x; y plays no role for profiles.
        if settings.snap_time_samples:
            j = np.arange(_snap(nt, geometry.shape[0]))[:, None] / _snap(nt, geometry.shape[0])
        step = np.array([math.copysign(lx, cb), math.copysign(lx, cb) * sb / abs(cb)])
        return _Path(phase + j * step, "return", lx / abs(cb))
    assert ly is not None
    if settings.travel in ("auto", "return"):
        vec = _return_vector(geometry, beta_deg, settings.max_return_periods)
        if vec is not None:
            m, n = vec
            total = nt * max(abs(m), abs(n))
            if settings.snap_time_samples:
                total = _snap(
                    total, math.gcd(abs(m) * geometry.shape[0], abs(n) * geometry.shape[1])
                )
            jj = np.arange(total)[:, None] / total
            return _Path(
                phase + jj * np.array([m * lx, n * ly]), "return", math.hypot(m * lx, n * ly)
            )
        if settings.travel == "return":
            raise ParameterError(
                "travel",
                "return",
                f"a direction commensurate with the cell: beta = {beta_deg:g} deg has no return "
                f"vector (m Lx, n Ly) with |m|, |n| <= {settings.max_return_periods}; use "
                "travel='ergodic' or a travel length",
            )
    target = math.sqrt(nt)
    na = _ergodic_count(target, geometry.shape[0])
    nb = _ergodic_count(target, geometry.shape[1])
    a, b = np.meshgrid(np.arange(na) / na, np.arange(nb) / nb, indexing="ij")
    shifts = phase + np.stack([a.ravel() * lx, b.ravel() * ly], axis=1)
    return _Path(shifts, "ergodic", None)


def snap_count(count: int, stations: int) -> int:
    """The divisor of ``stations`` nearest to ``count`` (ratio scale; a tie goes up).

    Time samples on a return path are whole-station shifts exactly when their number
    divides ``stations`` (the station count crossed along the path).
    """
    best = stations
    best_err = math.inf
    for d in range(1, math.isqrt(stations) + 1):
        if stations % d:
            continue
        for v in (d, stations // d):
            err = abs(math.log(v / count))
            if err < best_err - 1e-12 or (abs(err - best_err) <= 1e-12 and v > best):
                best, best_err = v, err
    return best


_snap = snap_count


def _ergodic_count(target: float, stations: int) -> int:
    """Shifts per axis of the ergodic grid: the divisor of the station count nearest to
    ``target`` (ratio scale) within a factor 2, so every shift is whole stations and the
    upper surface is read rolled, not re-evaluated; ``ceil(target)`` when there is none."""
    best, best_err = math.ceil(target), math.inf
    for d in range(max(1, math.ceil(target / 2.0)), math.floor(2.0 * target) + 1):
        err = abs(math.log(d / target))
        if stations % d == 0 and err < best_err - 1e-12:
            best, best_err = d, err
    return best


def _check_mu0(mu0: Any) -> float:
    if not (_finite(mu0) and float(mu0) >= 0.0):
        raise ParameterError("mu0", mu0, "a finite local friction coefficient >= 0")
    return float(mu0)


def polar_head_columns(polar: Any) -> dict[str, np.ndarray]:
    """The leading columns of a polar table: direction, mu components, mu, mu/mu0 (mu0 > 0).

    Shared by the lattice's and the elastic model's polars (one column layout).
    """
    out: dict[str, np.ndarray] = {
        "beta_deg": polar.beta_deg,
        "mu_x": polar.mu_x,
        "mu_y": polar.mu_y,
        "mu": polar.mu,
    }
    if polar.mu0 > 0.0:
        out["mu_over_mu0"] = polar.mu_over_mu0
    return out


def long_mu_columns(result: Any, repeats: int) -> dict[str, np.ndarray]:
    """beta_deg, mu, mu_x, mu_y (and mu/mu0 when mu0 > 0) of a (repeats, n_beta) result,
    flattened row-major: the tail of the long tables of wear and hierarchy results."""
    out: dict[str, np.ndarray] = {
        "beta_deg": np.tile(result.beta_deg, repeats),
        "mu": result.mu.ravel(),
        "mu_x": result.mu_x.ravel(),
        "mu_y": result.mu_y.ravel(),
    }
    if result.mu0 > 0.0:
        out["mu_over_mu0"] = result.mu.ravel() / result.mu0
    return out


def masked_columns(columns: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Float columns with NaN or infinite entries masked (empty CSV fields), others as they are."""
    return {
        k: np.ma.masked_invalid(v) if v.dtype.kind == "f" and not np.all(np.isfinite(v)) else v
        for k, v in columns.items()
    }


_Settings = TypeVar("_Settings")


def settings_from(
    kind: type[_Settings],
    settings: _Settings | None,
    options: dict[str, Any],
    defaults: dict[str, Any] | None = None,
) -> _Settings:
    """``settings``, or a ``kind`` built from the keyword ``options`` (not both).

    ``defaults`` fill what ``options`` leaves out; a bad option or both given raise
    :class:`ParameterError` naming the options.
    """
    if settings is None:
        try:
            return kind(**{**(defaults or {}), **options})
        except TypeError as exc:
            raise ParameterError(
                "options", sorted(options), f"fields of {kind.__name__} ({exc})"
            ) from None
    if options:
        raise ParameterError("options", sorted(options), "either settings= or keyword options")
    return settings


def polar_mu_fields(
    betas: FloatArray, mu_x: FloatArray, mu_y: FloatArray, mu_definition: str
) -> dict[str, FloatArray]:
    """The leading fields of a polar, read-only: beta_deg, mu_x, mu_y, mu and both mu's.

    ``mu_magnitude = |(mu_x, mu_y)|``, ``mu_projection = mu_x cos(beta) + mu_y sin(beta)``
    (cos and sin exact at multiples of 90 degrees); ``mu`` is the one ``mu_definition``
    names. Shared by the lattice's and the elastic model's polars.
    """
    cs = [_cos_sin_deg(float(b)) for b in betas]
    cos_b = np.array([c for c, _ in cs])
    sin_b = np.array([s for _, s in cs])
    mu_mag = np.hypot(mu_x, mu_y)
    mu_proj = mu_x * cos_b + mu_y * sin_b
    return {
        "beta_deg": readonly(betas, None),
        "mu_x": readonly(mu_x, None),
        "mu_y": readonly(mu_y, None),
        "mu": readonly(mu_mag if mu_definition == "magnitude" else mu_proj, None),
        "mu_magnitude": readonly(mu_mag, None),
        "mu_projection": readonly(mu_proj, None),
    }


def check_betas(beta_deg: ArrayLike) -> FloatArray:
    """Sliding directions [deg] as a non-empty 1-D float64 array (ParameterError otherwise)."""
    return finite_vector("beta_deg", beta_deg, "a non-empty 1-D array of finite degrees")


def friction_polar(
    lower: Surface,
    upper: Surface,
    mu0: float,
    beta_deg: ArrayLike,
    settings: LatticeSettings | None = None,
    progress: Callable[[int, int], None] | None = None,
    **options: Any,
) -> FrictionPolar:
    """Time-averaged friction coefficients of the lattice-spring model for each direction.

    Parameters
    ----------
    lower:
        Surface 1 (fixed), a Profile or HeightMap.
    upper:
        Surface 2 (moving along beta).
    mu0:
        Local Coulomb coefficient at the spring tips (>= 0). Hierarchy (Eq 29) calls
        this with the coefficient of the level below.
    beta_deg:
        Sliding directions (degrees from the x axis).
    settings, options:
        A :class:`LatticeSettings`, or its fields as keyword arguments (not both).
    progress:
        Optional callback ``progress(done, total)`` after each direction (for progress
        bars; the physics does no I/O).

    Raises
    ------
    ValidityError
        When a compressed contact violates the bound of Eq 1 (``on_invalid="error"``).
    ParameterError
        For bad arguments.
    """
    settings = settings_from(LatticeSettings, settings, options)
    m0 = _check_mu0(mu0)
    betas = check_betas(beta_deg)
    lattice = _prepare(lower, upper, settings)
    if lattice.mode == _kernels.MODE_FULL and settings.full_contact == "average":
        results = _average_directions(lattice, lower, upper, m0, betas, settings)
        if progress is not None:
            progress(betas.size, betas.size)
    else:
        results = _all_directions(lattice, lower, upper, m0, betas, settings, progress)
    mu_x = np.array([r.mu_x for r in results])
    mu_y = np.array([r.mu_y for r in results])
    messages = tuple(r.invalid for r in results if r.invalid is not None)
    n_bad = len(messages)
    notes: tuple[str, ...] = ()
    if lattice.mode == _kernels.MODE_LOAD and all(r.contact_min == 1.0 for r in results):
        notes = (
            f"load = {settings.load:g} N per spring compresses every spring at every time "
            "sample (full contact): mu differs from the limit load = 'full' only through "
            "the unequal spring forces; load = 'full' computes that limit in one pass",
        )
    return FrictionPolar(
        **polar_mu_fields(betas, mu_x, mu_y, settings.mu_definition),
        mu_apparent=None
        if settings.load == 0.0
        else readonly(np.array([r.mu_apparent for r in results]), None),
        valid=readonly(np.array([r.invalid is None for r in results]), None),
        invalid_fraction=readonly(np.array([r.invalid_fraction for r in results]), None),
        contact_fraction_min=readonly(np.array([r.contact_min for r in results]), None),
        contact_fraction_mean=readonly(np.array([r.contact_mean for r in results]), None),
        tensile_fraction_max=readonly(np.array([r.tensile_max for r in results]), None),
        tensile_fraction_mean=readonly(np.array([r.tensile_mean for r in results]), None),
        force_x=readonly(np.array([r.force_x for r in results]), None),
        force_y=readonly(np.array([r.force_y for r in results]), None),
        compressed_force=readonly(np.array([r.compressed_force for r in results]), None),
        in_contact=readonly(np.array([r.in_contact for r in results]), None),
        time_samples=readonly(np.array([r.samples for r in results], dtype=np.int64), None),
        solver_iterations_max=readonly(
            np.array([r.iterations for r in results], dtype=np.int64), None
        ),
        travel_mode=tuple(r.travel_mode for r in results),
        travel_m=tuple(r.travel for r in results),
        mu0=m0,
        settings=settings,
        geometry=lattice.geometry,
        spring_evaluations=sum(max(r.samples, 1) for r in results) * lattice.geometry.n_stations,
        success=n_bad == 0,
        message="ok" if n_bad == 0 else f"{n_bad} of {betas.size} directions violate Eq 1's bound",
        invalid_messages=messages,
        notes=notes,
    )


#: Lattices with at least this many stations compute their time samples in blocks shared
#: among numba's threads (see :data:`SAMPLE_BLOCKS`); smaller ones in one serial chain,
#: where the threads would cost more than they save (hierarchy levels, profiles).
PARALLEL_MIN_STATIONS = 1 << 16


def _all_directions(
    lattice: _Lattice,
    lower: Surface,
    upper: Surface,
    mu0: float,
    betas: FloatArray,
    settings: LatticeSettings,
    progress: Callable[[int, int], None] | None,
) -> list[_Direction]:
    """:func:`_direction` for every direction, in order (the threads work inside a sample)."""
    results: list[_Direction] = []
    for i, b in enumerate(betas):
        # shift-invariant (one sample, the same gaps in every direction): the load balance's
        # root is the same, so the previous direction's offset starts Newton at it
        start = results[-1].offset if lattice.invariant and results else math.nan
        results.append(_direction(lattice, lower, upper, mu0, float(b), settings, start))
        if progress is not None:
            progress(i + 1, betas.size)
    return results


@dataclass(frozen=True)
class _Lattice:
    """Arrays prepared once per call: stations, surface 1, surface 2 at the start phase."""

    geometry: LatticeGeometry
    xs: FloatArray
    ys: FloatArray
    z1: FloatArray
    g1: tuple[FloatArray, FloatArray]
    z2: FloatArray
    g2: tuple[FloatArray, FloatArray]
    nx: int
    ny: int
    spacing: tuple[float, float]
    mode: int
    load: float
    invariant: bool = False


@dataclass(frozen=True)
class _Direction:
    """The time-averaged outcome for one sliding direction."""

    mu_x: float
    mu_y: float
    mu_apparent: float
    contact_min: float
    contact_mean: float
    tensile_max: float
    tensile_mean: float
    force_x: float
    force_y: float
    compressed_force: float
    in_contact: bool
    samples: int
    iterations: int
    travel_mode: str
    travel: float | None
    invalid: str | None
    invalid_fraction: float = 0.0
    offset: float = math.nan  # c of the last time sample (load control)


def _average_directions(
    lat: _Lattice,
    lower: Surface,
    upper: Surface,
    mu0: float,
    betas: FloatArray,
    settings: LatticeSettings,
) -> list[_Direction]:
    """Full contact of every direction as the area average of the multipliers."""
    cs = np.array([_cos_sin_deg(float(b)) for b in betas])
    sums = full_contact_sums(
        mu0, lat.g1, lat.g2, cs[:, 0], cs[:, 1], drop=settings.on_invalid == "drop",
        engine=settings.engine,
    )  # fmt: skip
    mu_x, mu_y = sums.mu_x, sums.mu_y
    out = []
    for d, beta in enumerate(betas):
        invalid = None
        if sums.invalid[d] > 0 and settings.on_invalid != "drop":
            invalid = _invalid_message(
                lower, upper, lat.geometry, mu0, float(beta), np.array([settings.phase]),
                (0, int(sums.worst_station[d]), int(sums.worst_family[d])),
            )  # fmt: skip
            if settings.on_invalid == "error":
                raise ValidityError(invalid)
        mx = math.nan if invalid else float(mu_x[d])
        my = math.nan if invalid else float(mu_y[d])
        fraction = float(sums.invalid_fraction[d]) if settings.on_invalid == "drop" else 0.0
        out.append(
            _Direction(
                mu_x=mx,
                mu_y=my,
                mu_apparent=math.hypot(mx, my),
                contact_min=1.0,
                contact_mean=1.0,
                tensile_max=0.0,
                tensile_mean=0.0,
                force_x=mx,
                force_y=my,
                compressed_force=1.0,
                in_contact=True,
                samples=0,
                iterations=0,
                travel_mode="average",
                travel=None,
                invalid=invalid,
                invalid_fraction=fraction,
            )
        )
    return out


def _prepare(lower: Surface, upper: Surface, settings: LatticeSettings) -> _Lattice:
    geometry = lattice_geometry(lower, upper, settings.stations)
    xs, ys = geometry.station_coordinates()
    z1, g1x, g1y = (np.ascontiguousarray(a).ravel() for a in lower.evaluate(xs, ys))
    # Surface 2 at the stations minus the initial phase: reused, read rolled, for every
    # time sample whose shift is a whole number of station spacings.
    px, py = settings.phase
    z2, g2x, g2y = (np.ascontiguousarray(a).ravel() for a in upper.evaluate(xs - px, ys - py))
    if settings.control == "separation":
        mode = _kernels.MODE_SEPARATION
    elif settings.load == "full":
        mode = _kernels.MODE_FULL
        z1 = np.zeros_like(z1)  # heights play no role in the full-contact limit
        z2 = np.zeros_like(z2)
    else:
        mode = _kernels.MODE_LOAD
    nx = geometry.shape[0]
    ny = geometry.shape[1] if geometry.dimension == 2 else 1
    lx, ly = geometry.cell
    return _Lattice(
        geometry=geometry,
        xs=xs,
        ys=ys,
        z1=z1,
        g1=(g1x, g1y),
        z2=z2,
        g2=(g2x, g2y),
        nx=nx,
        ny=ny,
        spacing=(lx / nx, (ly / ny) if ly is not None else math.inf),
        mode=mode,
        load=settings.load if isinstance(settings.load, float) else 0.0,
        invariant=settings.shift_invariance and (lower.is_flat or upper.is_flat),
    )


def _direction(
    lat: _Lattice,
    lower: Surface,
    upper: Surface,
    mu0: float,
    beta: float,
    settings: LatticeSettings,
    c_start: float = math.nan,
) -> _Direction:
    """Time average over the sliding path of one direction (Eqs 5-9 and 21-22, time-averaged).

    ``c_start``: a warm start of the first sample's load balance (load control).
    """
    if lat.invariant:  # a flat face: every shift is the same configuration
        path = _Path(np.array([settings.phase], dtype=np.float64), "invariant", None)
    else:
        path = _sliding_path(lat.geometry, beta, settings)
    results = _samples(lat, upper, mu0, beta, path.shifts, settings, c_start)
    n_st = lat.geometry.n_stations
    f_sum = x_sum = y_sum = f_tot = 0.0
    fractions = np.empty(path.shifts.shape[0])
    t_max = 0.0
    t_sum = 0.0
    iterations = 0
    first_invalid: tuple[int, int, int] | None = None
    drop = settings.on_invalid == "drop"
    dropped = 0.0
    for j, res in enumerate(results):
        c_new, iters, fs, xs_, ys_, ft, n_comp, n_tens, n_inv, first, family = res
        if lat.mode == _kernels.MODE_LOAD and math.isnan(c_new):
            raise ParameterError(
                "load",
                settings.load,
                f"above the pull-off load: with detachment = {settings.detachment} m the "
                f"stretched springs cannot carry it (beta = {beta:g} deg)",
            )
        iterations = max(iterations, iters)
        f_sum += fs
        x_sum += xs_
        y_sum += ys_
        f_tot += ft
        fractions[j] = n_comp / n_st
        t_max = max(t_max, n_tens / n_st)
        t_sum += n_tens / n_st
        if n_inv and first_invalid is None and not drop:
            first_invalid = (j, first, family)
            if settings.on_invalid == "error":  # stop at once: the rest is wasted work
                raise ValidityError(
                    _invalid_message(lower, upper, lat.geometry, mu0, beta, path.shifts,
                                     first_invalid)
                )  # fmt: skip
        dropped += n_inv / (2.0 * n_st)
    n_samples = int(path.shifts.shape[0])
    per_spring = 1.0 / (2.0 * n_st * n_samples)  # time average over both families
    outcome = _Direction(
        mu_x=math.nan,
        mu_y=math.nan,
        mu_apparent=math.nan,
        contact_min=float(fractions.min()),
        contact_mean=float(fractions.mean()),
        tensile_max=t_max,
        tensile_mean=t_sum / n_samples,
        force_x=x_sum * per_spring,
        force_y=y_sum * per_spring,
        compressed_force=2.0 * f_sum * per_spring,
        in_contact=f_sum > 0.0,
        samples=n_samples,
        iterations=iterations,
        travel_mode=path.mode,
        travel=path.travel,
        invalid=None,
        invalid_fraction=dropped / n_samples if drop else 0.0,
        offset=float(results[-1][0]) if results else math.nan,
    )
    if first_invalid is not None:
        message = _invalid_message(
            lower, upper, lat.geometry, mu0, beta, path.shifts, first_invalid
        )
        if settings.on_invalid == "error":
            raise ValidityError(message)
        return replace(outcome, invalid=message)
    load = settings.load if isinstance(settings.load, float) else math.nan
    adhesive = lat.mode == _kernels.MODE_LOAD and settings.k_t > 0.0 and math.isfinite(load)
    if adhesive and load <= 0.0 and f_sum <= 0.0:
        # Zero or tensile load carried by stretched springs alone: no friction (Eq 21),
        # R^(c) = 0; mu of the compressed springs undefined; Eq 22 gives 0 for L < 0.
        return replace(outcome, mu_apparent=0.0 if load < 0.0 else math.nan)
    if adhesive and load == 0.0 and f_sum > 0.0:
        # L = 0: Eq 22 is singular (mu_apparent undefined), R^(c) and mu_c are defined.
        return replace(outcome, mu_x=x_sum / (2.0 * f_sum), mu_y=y_sum / (2.0 * f_sum))
    if f_sum <= 0.0 or f_tot == 0.0:  # no compressed spring, or zero load: undefined
        name, value = (
            ("separation", settings.separation)
            if lat.mode == _kernels.MODE_SEPARATION
            else ("load", settings.load)
        )
        raise ParameterError(
            name,
            value,
            f"a value that compresses some spring during sliding with a non-zero total load "
            f"(beta = {beta:g} deg)",
        )
    return replace(
        outcome,
        mu_x=x_sum / (2.0 * f_sum),  # Eqs 5-9: both families, R_z = 2 sum F
        mu_y=y_sum / (2.0 * f_sum),
        # Eq 22 with the applied load (exact in load control; f_tot is its sum).
        mu_apparent=math.hypot(x_sum, y_sum)
        / (2.0 * (load * n_st * n_samples if adhesive else f_tot)),
    )


#: Time samples of a large lattice (see :data:`PARALLEL_MIN_STATIONS`) are computed in this
#: many blocks of consecutive samples, the blocks shared among numba's threads. Each block
#: starts its load balance cold and warm-starts it from sample to sample; the blocks are
#: fixed by the sample count alone, so the results do not depend on the thread count.
SAMPLE_BLOCKS = 8


def _samples(
    lat: _Lattice,
    upper: Surface,
    mu0: float,
    beta: float,
    shifts: FloatArray,
    settings: LatticeSettings,
    c_start: float = math.nan,
) -> list[tuple[Any, ...]]:
    """The kernel's outcome (``SAMPLE_FIELDS``) of every time sample of one direction, in order.

    ``c_start`` warm-starts the first load balance (load control without detachment,
    whose balance has several roots).

    A block stops early at a sample that ends the computation (a load above the pull-off
    load, or a contact violating Eq 1 with ``on_invalid="error"``): the caller raises at
    the first such sample, so the samples after it are never read.
    """
    numba_engine = settings.engine == "numba"
    multipliers = _kernels.multipliers_nb if numba_engine else _kernels.multipliers_np
    cb, sb = _cos_sin_deg(beta)
    h1x, h1y, den1 = multipliers(mu0, lat.g1[0], lat.g1[1], cb, sb)
    h2_start = multipliers(mu0, lat.g2[0], lat.g2[1], cb, sb)
    # Whether a contact of surface 1 (or of surface 2 at the start phase) can violate Eq 1:
    # when none can, the compiled kernel does not read the denominators.
    check1 = bool(np.any(den1 <= 0.0))
    check2_start = bool(np.any(h2_start[2] <= 0.0))
    px, py = settings.phase
    detach = math.inf if settings.detachment is None else settings.detachment
    drop = settings.on_invalid == "drop"
    stop_invalid = settings.on_invalid == "error"
    c_cold = math.nan  # load control: no warm start
    if lat.mode == _kernels.MODE_LOAD and settings.detachment is None:
        c_cold = c_start
    if lat.mode == _kernels.MODE_SEPARATION and settings.separation is not None:
        c_cold = settings.separation

    spare: queue.SimpleQueue[Any] = queue.SimpleQueue()  # buffers reused across blocks

    def block(j0: int, j1: int) -> list[tuple[Any, ...]]:
        work = None
        if numba_engine:
            try:
                work = spare.get_nowait()
            except queue.Empty:
                work = _kernels.workspace(lat.nx, lat.ny)
        try:
            return _block(j0, j1, work)
        finally:
            if work is not None:
                spare.put(work)

    def _block(j0: int, j1: int, work: Any) -> list[tuple[Any, ...]]:
        out: list[tuple[Any, ...]] = []
        c = c_cold
        full_whole: Any = None  # full contact: a whole-station shift only permutes the sums
        for sx, sy in shifts[j0:j1]:
            whole = _whole_stations(sx - px, sy - py, lat.spacing, lat.geometry.dimension)
            if whole is not None and full_whole is not None:
                res = full_whole
            else:
                if whole is not None:
                    z2, (h2x, h2y, den2) = lat.z2, h2_start
                    kx, ky = whole[0] % lat.nx, whole[1] % lat.ny
                    check2 = check2_start
                else:
                    z2, g2x, g2y = (
                        np.ascontiguousarray(a).ravel()
                        for a in upper.evaluate(lat.xs - sx, lat.ys - sy)
                    )
                    z2 = lat.z2 if lat.mode == _kernels.MODE_FULL else z2
                    h2x, h2y, den2 = multipliers(mu0, g2x, g2y, cb, sb)
                    kx = ky = 0
                    check2 = bool(np.any(den2 <= 0.0))
                args = (
                    lat.z1, h1x, h1y, den1, z2, h2x, h2y, den2, lat.nx, lat.ny, kx, ky,
                    settings.k_c, settings.k_t, lat.mode, lat.load, c, detach, drop,
                )  # fmt: skip
                if work is None:
                    res = _kernels.sample_np(*args)
                else:
                    res = _kernels.sample_into_nb(*args, check1 or check2, *work)
                if lat.mode == _kernels.MODE_FULL and whole is not None:
                    full_whole = res
            out.append(res)
            if lat.mode == _kernels.MODE_LOAD:
                c = res[0]  # warm start of the next load balance
                if math.isnan(c):
                    break
            if res[8] and stop_invalid:
                break
        return out

    n = int(shifts.shape[0])
    if not numba_engine or lat.geometry.n_stations < PARALLEL_MIN_STATIONS:
        return block(0, n)
    step = -(-n // SAMPLE_BLOCKS)
    starts = list(range(0, n, step))
    workers = min(numba.get_num_threads(), len(starts))
    if workers < 2:
        blocks = [block(j, min(j + step, n)) for j in starts]
    else:
        with ThreadPoolExecutor(max_workers=workers) as pool:
            blocks = list(pool.map(lambda j: block(j, min(j + step, n)), starts))
    results = []
    for part in blocks:
        results.extend(part)
        if len(part) < step:  # stopped early: the caller raises at its last sample
            break
    return results


def _whole_stations(
    dx_shift: float, dy_shift: float, spacing: tuple[float, float], dimension: int
) -> tuple[int, int] | None:
    """The shift in whole station spacings (kx, ky), or None when it is not whole."""
    fx = dx_shift / spacing[0]
    kx = round(fx)
    if abs(fx - kx) > 1e-9 * max(1.0, abs(fx)):
        return None
    if dimension == 1:
        return int(kx), 0
    fy = dy_shift / spacing[1]
    ky = round(fy)
    if abs(fy - ky) > 1e-9 * max(1.0, abs(fy)):
        return None
    return int(kx), int(ky)


def _invalid_message(
    lower: Surface,
    upper: Surface,
    geometry: LatticeGeometry,
    mu0: float,
    beta_deg: float,
    shifts: FloatArray,
    first: tuple[int, int, int],
) -> str:
    """Describe the first contact that violates Eq 1: which surface, where, phi, the bound."""
    j, station, family = first
    xs, ys = geometry.station_coordinates()
    idx = np.unravel_index(station, geometry.shape)
    x = float(np.ravel(xs)[idx[0]])
    y = float(np.ravel(ys)[idx[1]]) if geometry.dimension == 2 else 0.0
    if family == 1:
        surface, px, py, name = lower, x, y, "lower surface (upper-fixed springs)"
    else:
        sx, sy = shifts[j]
        surface, px, py, name = upper, x - sx, y - sy, "upper surface (lower-fixed springs)"
    _, gx, gy = surface.evaluate(np.array([px]), np.array([py]))
    g = math.hypot(float(gx[0]), float(gy[0]))
    phi = math.atan(g)
    alpha = math.atan2(float(gy[0]), float(gx[0]))
    beta_local = math.radians(beta_deg) - alpha
    bound = float(max_mu0(phi, beta_local))
    where = f"x = {px:.6g} m" + (f", y = {py:.6g} m" if geometry.dimension == 2 else "")
    return (
        f"mu0 = {mu0:g} is outside the validity domain at beta = {beta_deg:g} deg: a contact on "
        f"the {name} at {where} has slope angle phi = {math.degrees(phi):.4g} deg facing the "
        f"sliding direction; Eq 1 requires mu0 < {bound:.6g} there (mu0 < cot(phi) = "
        f"{1.0 / math.tan(phi) if phi > 0 else math.inf:.6g} at beta' = 0)"
    )
