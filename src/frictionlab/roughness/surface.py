"""Rough surfaces: 1-D profiles and 2-D periodic height maps, immutable, in SI units.

A surface is a periodic height function with its gradient:

* :class:`Profile`: ``z = f(x)`` extruded along y (1-D roughness, Eqs 10-13); the
  gradient is ``(f'(x), 0)``;
* :class:`HeightMap`: ``z = f(x, y)`` periodic in x and y (2-D roughness).

Every surface answers :meth:`Surface.evaluate` ``(x, y) -> (z, g_x, g_y)`` at any
points (m, broadcast together) and states its periods. Analytic surfaces (wedges,
sinusoids, see :mod:`frictionlab.roughness.generators`) evaluate exactly; sampled
surfaces (:class:`SampledProfile`, :class:`SampledHeightMap`) carry their heights on a
uniform grid whose samples sit at the pixel centres ``((i + 1/2) dx, (j + 1/2) dy)`` and
interpolate bilinearly between them, with gradients computed once on the grid
(``gradient="fd"``: periodic central differences, second order; ``"spectral"``: exact
derivative of the trigonometric interpolant). User functions enter through
:class:`FunctionProfile` and :class:`FunctionHeightMap`.

All arrays held by a surface are private float64 copies marked read-only.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray
from frictionlab._arrays import readonly as _readonly
from frictionlab.errors import ParameterError
from frictionlab.roughness import _kernels

__all__ = [
    "FunctionHeightMap",
    "FunctionProfile",
    "HeightMap",
    "Profile",
    "SampledHeightMap",
    "SampledProfile",
    "Surface",
]

Evaluation = tuple[FloatArray, FloatArray, FloatArray]

#: Gradient methods of sampled surfaces.
GRADIENT_METHODS = ("fd", "spectral")


class Surface(ABC):
    """A periodic rough surface (heights in m over horizontal positions in m)."""

    #: 1 for a profile extruded along y, 2 for a height map.
    ndim: ClassVar[int]
    #: Short name of the surface family (``"wedge"``, ``"sampled"``, ...).
    kind: ClassVar[str]

    @abstractmethod
    def evaluate(self, x: ArrayLike, y: ArrayLike | None = None) -> Evaluation:
        """Heights z (m) and gradient (g_x, g_y) (dimensionless) at points (x, y) (m).

        ``x`` and ``y`` broadcast together; the three results have the broadcast shape.
        """

    @property
    @abstractmethod
    def periods(self) -> tuple[float | None, float | None]:
        """Periods along x and y (m); ``None`` means any period fits (flat, or extruded)."""

    @property
    @abstractmethod
    def max_slope(self) -> float:
        """The largest gradient magnitude |grad f| (tan of the steepest face angle)."""

    @property
    def grid_shape(self) -> tuple[int, ...] | None:
        """Sample counts per period of a sampled surface, ``None`` for analytic ones."""
        return None

    @property
    def is_flat(self) -> bool:
        """True for a surface without slopes."""
        return self.max_slope == 0.0

    def parameters(self) -> dict[str, Any]:
        """The defining parameters as JSON-ready builtins (for summaries)."""
        return {}

    def describe(self) -> dict[str, Any]:
        """A JSON-ready description: kind, dimension, periods (m), parameters."""
        return {
            "kind": self.kind,
            "ndim": self.ndim,
            "periods_m": [p for p in self.periods if p is not None],
            "max_slope_deg": math.degrees(math.atan(self.max_slope)),
            **self.parameters(),
        }


class Profile(Surface):
    """A 1-D profile ``z = f(x)`` extruded along y: gradient ``(f'(x), 0)``."""

    ndim: ClassVar[int] = 1

    @property
    @abstractmethod
    def length(self) -> float | None:
        """The period along x (m); ``None`` for a flat profile."""

    @property
    def periods(self) -> tuple[float | None, float | None]:
        return (self.length, None)

    @abstractmethod
    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Heights f(x) (m) and slopes f'(x) at the points x (m), same shape as x."""

    def evaluate(self, x: ArrayLike, y: ArrayLike | None = None) -> Evaluation:
        xa = _as_float_array(x, "x")
        shape = xa.shape if y is None else np.broadcast_shapes(xa.shape, np.shape(y))
        z, gx = self.profile(xa)
        z = np.broadcast_to(z, shape).astype(np.float64, copy=True)
        gx = np.broadcast_to(gx, shape).astype(np.float64, copy=True)
        return z, gx, np.zeros(shape)


class HeightMap(Surface):
    """A 2-D height map ``z = f(x, y)`` periodic in x and y."""

    ndim: ClassVar[int] = 2

    @property
    @abstractmethod
    def physical_sizes(self) -> tuple[float, float]:
        """The periods (Lx, Ly) (m)."""

    @property
    def periods(self) -> tuple[float | None, float | None]:
        lx, ly = self.physical_sizes
        return (lx, ly)


# --------------------------------------------------------------------------- sampled


def _as_float_array(value: ArrayLike, name: str) -> FloatArray:
    try:
        arr: FloatArray = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ParameterError(name, value, "an array of real numbers") from None
    return arr


def _check_positive(name: str, value: Any) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ParameterError(name, value, "a positive length in m") from None
    if not (math.isfinite(v) and v > 0.0):
        raise ParameterError(name, value, "a positive finite length in m")
    return v


def _check_sizes(value: Any) -> tuple[float, float]:
    """Two positive lengths (Lx, Ly) in m."""
    try:
        lx, ly = value
    except (TypeError, ValueError):
        raise ParameterError("physical_sizes", value, "two lengths (Lx, Ly) in m") from None
    return (_check_positive("physical_sizes[0]", lx), _check_positive("physical_sizes[1]", ly))


def _check_heights(heights: ArrayLike, ndim: int, name: str = "heights") -> FloatArray:
    arr = _as_float_array(heights, name)
    if arr.ndim != ndim:
        raise ParameterError(f"{name}.shape", arr.shape, f"a {ndim}-D array")
    if min(arr.shape) < 3:
        raise ParameterError(f"{name}.shape", arr.shape, "at least 3 samples per axis")
    n_bad = int(np.count_nonzero(~np.isfinite(arr)))
    if n_bad:
        raise ParameterError(
            name,
            f"{n_bad} undefined (NaN or infinite) values",
            "finite heights only; fill missing data first (fill_missing=True in "
            "generators.from_array or topography.from_topography)",
        )
    return arr


def _grid_gradient(
    heights: FloatArray, spacing: tuple[float, ...], method: str
) -> list[FloatArray]:
    """Periodic gradient of grid heights along each axis (``"fd"`` or ``"spectral"``)."""
    if method not in GRADIENT_METHODS:
        raise ParameterError("gradient", method, f"one of {GRADIENT_METHODS}")
    grads = []
    for axis, d in enumerate(spacing):
        n = heights.shape[axis]
        if method == "fd":
            g = (np.roll(heights, -1, axis) - np.roll(heights, 1, axis)) / (2.0 * d)
        else:
            k = 2.0 * np.pi * np.fft.fftfreq(n, d)
            if n % 2 == 0:
                k[n // 2] = 0.0  # the Nyquist mode has no well-defined derivative
            shape = [1] * heights.ndim
            shape[axis] = n
            spectrum = np.fft.fft(heights, axis=axis)
            g = np.real(np.fft.ifft(1j * k.reshape(shape) * spectrum, axis=axis))
        grads.append(np.ascontiguousarray(g))
    return grads


@dataclass(frozen=True, eq=False)
class SampledProfile(Profile):
    """A periodic profile sampled at pixel centres ``x_i = (i + 1/2) length / n``.

    Parameters
    ----------
    heights:
        Heights (m), shape (n,), n >= 3, finite.
    size:
        The period (m).
    gradient:
        ``"fd"`` (default; periodic central differences) or ``"spectral"``.
    """

    kind: ClassVar[str] = "sampled"
    heights: FloatArray
    size: float
    gradient: str = "fd"
    _fields: FloatArray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        h = _check_heights(self.heights, 1)
        length = _check_positive("size", self.size)
        (slopes,) = _grid_gradient(h, (length / h.size,), self.gradient)
        object.__setattr__(self, "heights", _readonly(h))
        object.__setattr__(self, "size", length)
        object.__setattr__(self, "_fields", _readonly(np.stack([h, slopes])[:, :, None]))

    @property
    def length(self) -> float:
        return self.size

    @property
    def slopes(self) -> FloatArray:
        """Slopes f' at the samples (read-only view)."""
        return self._fields[1, :, 0]

    @property
    def grid_shape(self) -> tuple[int, ...]:
        return (self.heights.size,)

    @property
    def max_slope(self) -> float:
        return float(np.max(np.abs(self.slopes)))

    def positions(self) -> FloatArray:
        """Sample positions (m), at the pixel centres."""
        n = self.heights.size
        return np.asarray((np.arange(n) + 0.5) * (self.size / n), dtype=np.float64)

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        dx = self.size / self.heights.size
        flat = np.ascontiguousarray(x, dtype=np.float64).ravel()
        out = _kernels.interp_periodic_nb(self._fields, dx, 1.0, flat, np.zeros(1))
        return out[0, :, 0].reshape(x.shape), out[1, :, 0].reshape(x.shape)

    def parameters(self) -> dict[str, Any]:
        return {
            "points": int(self.heights.size),
            "length_m": self.size,
            "gradient": self.gradient,
            "rms_height_m": float(np.std(self.heights)),
            "rms_slope": float(np.sqrt(np.mean(self.slopes**2))),
        }


@dataclass(frozen=True, eq=False)
class SampledHeightMap(HeightMap):
    """A periodic height map sampled at pixel centres ``((i + 1/2) dx, (j + 1/2) dy)``.

    Parameters
    ----------
    heights:
        Heights (m), shape (nx, ny) (index order x, y), each >= 3, finite.
    sizes:
        The periods (Lx, Ly) (m).
    gradient:
        ``"fd"`` (default; periodic central differences) or ``"spectral"``.
    """

    kind: ClassVar[str] = "sampled"
    heights: FloatArray
    sizes: tuple[float, float]
    gradient: str = "fd"
    _fields: FloatArray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        h = _check_heights(self.heights, 2)
        sizes = _check_sizes(self.sizes)
        gx, gy = _grid_gradient(h, (sizes[0] / h.shape[0], sizes[1] / h.shape[1]), self.gradient)
        object.__setattr__(self, "heights", _readonly(h))
        object.__setattr__(self, "sizes", sizes)
        object.__setattr__(self, "_fields", _readonly(np.stack([h, gx, gy])))

    @property
    def physical_sizes(self) -> tuple[float, float]:
        return self.sizes

    @property
    def gradients(self) -> tuple[FloatArray, FloatArray]:
        """(g_x, g_y) at the samples (read-only views)."""
        return self._fields[1], self._fields[2]

    @property
    def grid_shape(self) -> tuple[int, ...]:
        nx, ny = self.heights.shape
        return (nx, ny)

    @property
    def max_slope(self) -> float:
        return float(np.sqrt(np.max(self._fields[1] ** 2 + self._fields[2] ** 2)))

    def positions(self) -> tuple[FloatArray, FloatArray]:
        """Sample positions x (nx,) and y (ny,) (m), at the pixel centres."""
        nx, ny = self.heights.shape
        lx, ly = self.sizes
        return (np.arange(nx) + 0.5) * (lx / nx), (np.arange(ny) + 0.5) * (ly / ny)

    def evaluate(self, x: ArrayLike, y: ArrayLike | None = None) -> Evaluation:
        xa = _as_float_array(x, "x")
        ya = _as_float_array(0.0 if y is None else y, "y")
        nx, ny = self.heights.shape
        dx, dy = self.sizes[0] / nx, self.sizes[1] / ny
        if xa.ndim == 2 and ya.ndim == 2 and xa.shape[1] == 1 and ya.shape[0] == 1:
            # Outer grid (the lattice's case): separable interpolation weights.
            out = _kernels.interp_periodic_nb(
                self._fields, dx, dy, np.ascontiguousarray(xa[:, 0]), np.ascontiguousarray(ya[0])
            )
            return out[0], out[1], out[2]
        bx, by = np.broadcast_arrays(xa, ya)
        out = _kernels.interp_points_nb(
            self._fields,
            dx,
            dy,
            np.ascontiguousarray(bx, dtype=np.float64).ravel(),
            np.ascontiguousarray(by, dtype=np.float64).ravel(),
        )
        shape = bx.shape
        return out[0].reshape(shape), out[1].reshape(shape), out[2].reshape(shape)

    def parameters(self) -> dict[str, Any]:
        gx, gy = self.gradients
        return {
            "points": list(self.grid_shape),
            "physical_sizes_m": list(self.sizes),
            "gradient": self.gradient,
            "rms_height_m": float(np.std(self.heights)),
            "rms_slope": float(np.sqrt(np.mean(gx**2 + gy**2))),
        }


# --------------------------------------------------------------------------- functions

_SLOPE_CHECK_POINTS = 512


@dataclass(frozen=True, eq=False)
class FunctionProfile(Profile):
    """A profile given by a periodic function and its derivative.

    Parameters
    ----------
    function:
        ``f(x) -> z`` (m -> m), vectorised over NumPy arrays.
    derivative:
        ``f'(x)`` (dimensionless), vectorised.
    period:
        The period (m). It is checked on a sample grid: ``f(x + period) == f(x)``
        to 1e-9 of the height range.
    """

    kind: ClassVar[str] = "function"
    function: Callable[[FloatArray], ArrayLike]
    derivative: Callable[[FloatArray], ArrayLike]
    period: float
    _max_slope: float = field(init=False, repr=False)

    def __post_init__(self) -> None:
        period = _check_positive("period", self.period)
        object.__setattr__(self, "period", period)
        x = np.asarray(
            (np.arange(_SLOPE_CHECK_POINTS) + 0.5) * (period / _SLOPE_CHECK_POINTS),
            dtype=np.float64,
        )
        z, g = self.profile(x)
        z_shift, g_shift = self.profile(x + period)
        _check_function_values("function", z, g, z_shift, g_shift)
        object.__setattr__(self, "_max_slope", float(np.max(np.abs(g))))

    @property
    def length(self) -> float:
        return self.period

    @property
    def max_slope(self) -> float:
        """Largest |f'| on a 512-point grid (an estimate)."""
        return self._max_slope

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        z = np.asarray(self.function(x), dtype=np.float64)
        g = np.asarray(self.derivative(x), dtype=np.float64)
        try:
            return np.broadcast_to(z, x.shape), np.broadcast_to(g, x.shape)
        except ValueError:
            raise ParameterError(
                "function", f"output shapes {z.shape}, {g.shape}", f"shape {x.shape}"
            ) from None

    def parameters(self) -> dict[str, Any]:
        return {"period_m": self.period}


@dataclass(frozen=True, eq=False)
class FunctionHeightMap(HeightMap):
    """A height map given by a periodic function and its gradient.

    Parameters
    ----------
    function:
        ``f(x, y) -> z`` (m), vectorised with NumPy broadcasting.
    gradient:
        ``grad(x, y) -> (g_x, g_y)`` (dimensionless), vectorised.
    sizes:
        The periods (Lx, Ly) (m), checked on a 64 x 64 grid to 1e-9 of the height range.
    """

    kind: ClassVar[str] = "function"
    function: Callable[[FloatArray, FloatArray], ArrayLike]
    gradient: Callable[[FloatArray, FloatArray], tuple[ArrayLike, ArrayLike]]
    sizes: tuple[float, float]
    _max_slope: float = field(init=False, repr=False)

    def __post_init__(self) -> None:
        sizes = _check_sizes(self.sizes)
        object.__setattr__(self, "sizes", sizes)
        n = 64
        x = ((np.arange(n) + 0.5) * sizes[0] / n)[:, None]
        y = ((np.arange(n) + 0.5) * sizes[1] / n)[None, :]
        z, gx, gy = self.evaluate(x, y)
        for shift in ((sizes[0], 0.0), (0.0, sizes[1])):
            z2, gx2, gy2 = self.evaluate(x + shift[0], y + shift[1])
            _check_function_values("function", z, np.hypot(gx, gy), z2, np.hypot(gx2, gy2))
        object.__setattr__(self, "_max_slope", float(np.max(np.hypot(gx, gy))))

    @property
    def physical_sizes(self) -> tuple[float, float]:
        return self.sizes

    @property
    def max_slope(self) -> float:
        """Largest |grad f| on a 64 x 64 grid (an estimate)."""
        return self._max_slope

    def evaluate(self, x: ArrayLike, y: ArrayLike | None = None) -> Evaluation:
        xa = _as_float_array(x, "x")
        ya = _as_float_array(0.0 if y is None else y, "y")
        shape = np.broadcast_shapes(xa.shape, ya.shape)
        z = np.asarray(self.function(xa, ya), dtype=np.float64)
        grad = self.gradient(xa, ya)
        try:
            gx, gy = (np.asarray(g, dtype=np.float64) for g in grad)
            return (
                np.broadcast_to(z, shape).copy(),
                np.broadcast_to(gx, shape).copy(),
                np.broadcast_to(gy, shape).copy(),
            )
        except (TypeError, ValueError):
            raise ParameterError(
                "function/gradient", "outputs of the wrong shape", f"arrays of shape {shape}"
            ) from None

    def parameters(self) -> dict[str, Any]:
        return {"physical_sizes_m": list(self.sizes)}


def _check_function_values(
    name: str, z: FloatArray, g: FloatArray, z_shift: FloatArray, g_shift: FloatArray
) -> None:
    if not all(np.all(np.isfinite(a)) for a in (z, g, z_shift, g_shift)):
        raise ParameterError(name, "non-finite values", "finite heights and gradients")
    scale = max(float(np.ptp(z)), float(np.max(np.abs(z))), 1e-300)
    if np.max(np.abs(z_shift - z)) > 1e-9 * scale:
        raise ParameterError(name, "not periodic", "f(x + period) == f(x) (periodic surface)")
    gscale = max(float(np.max(np.abs(g))), 1e-300)
    if np.max(np.abs(g_shift - g)) > 1e-9 * gscale:
        raise ParameterError(name, "gradient not periodic", "a periodic gradient")
