"""Surface generators: flat, wedges (saw-tooth), smooth wedges, sinusoids, user functions,
sampled arrays and self-affine random surfaces.

Every generator returns an immutable :class:`~frictionlab.roughness.surface.Profile`
(1-D, extruded along y) or :class:`~frictionlab.roughness.surface.HeightMap` (2-D).
Lengths are in m, angles in degrees (names ending in ``_deg``).

Wedge geometry: the rising face (angle phi_r, slope +tan phi_r) starts
at the valley x = 0 and spans the horizontal length ``a = lambda tan phi_f / (tan phi_r +
tan phi_f)``; the falling face (angle phi_f, slope -tan phi_f) spans ``lambda - a``. So each
face holds the horizontal share ``psi/(1+psi)`` and ``1/(1+psi)`` of the period with
``psi = tan phi_f / tan phi_r`` (the weights of Eq 14), and equally spaced springs land on
the faces in these proportions.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray
from frictionlab.errors import ParameterError
from frictionlab.roughness.surface import (
    Evaluation,
    FunctionHeightMap,
    FunctionProfile,
    HeightMap,
    Profile,
    SampledHeightMap,
    SampledProfile,
    _as_float_array,
    _check_positive,
)

__all__ = [
    "FlatProfile",
    "ProductSineMap",
    "ScaledHeightMap",
    "ScaledProfile",
    "SineProfile",
    "SmoothWedgeProfile",
    "WedgeProfile",
    "flat",
    "from_array",
    "from_function",
    "scaled",
    "self_affine",
    "sinusoid",
    "smooth_wedge",
    "wedge",
]


def _floats(value: Any, name: str) -> list[float]:
    """A scalar or a sequence of numbers as a list of floats."""
    try:
        return [float(v) for v in np.ravel(np.asarray(value, dtype=np.float64))]
    except (TypeError, ValueError):
        raise ParameterError(name, value, "numbers") from None


def _face_angles(angles_deg: Any, name: str = "angles_deg") -> tuple[float, float]:
    """(rising, falling) face angles in degrees, each strictly inside (0, 90)."""
    values = [angles_deg] if np.ndim(angles_deg) == 0 else list(np.ravel(angles_deg))
    if len(values) not in (1, 2):
        raise ParameterError(name, angles_deg, "one angle (symmetric) or two (rising, falling)")
    try:
        out = [float(v) for v in values]
    except (TypeError, ValueError):
        raise ParameterError(name, angles_deg, "numbers in degrees") from None
    for v in out:
        if not (math.isfinite(v) and 0.0 < v < 90.0):
            raise ParameterError(name, angles_deg, "0 < angle < 90 degrees")
    if len(out) == 1:
        out = out * 2
    return out[0], out[1]


@dataclass(frozen=True, eq=False)
class FlatProfile(Profile):
    """A flat surface: zero height and slope; it fits any period."""

    kind: ClassVar[str] = "flat"

    @property
    def length(self) -> None:
        return None

    @property
    def max_slope(self) -> float:
        return 0.0

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        return np.zeros(x.shape), np.zeros(x.shape)


@dataclass(frozen=True, eq=False)
class WedgeProfile(Profile):
    """Saw-tooth profile of straight faces (Fig 2).

    Parameters
    ----------
    angles_deg:
        (rising, falling) face angles in degrees, each in (0, 90); one value gives a
        symmetric wedge.
    wavelength:
        The period (m).
    """

    kind: ClassVar[str] = "wedge"
    angles_deg: tuple[float, float]
    wavelength: float
    _tan: tuple[float, float] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "angles_deg", _face_angles(self.angles_deg))
        object.__setattr__(self, "wavelength", _check_positive("wavelength", self.wavelength))
        rise, fall = self.angles_deg
        object.__setattr__(
            self, "_tan", (math.tan(math.radians(rise)), math.tan(math.radians(fall)))
        )

    @property
    def length(self) -> float:
        return self.wavelength

    @property
    def rise_length(self) -> float:
        """Horizontal length of the rising face (m); its share of the period is Eq 14's."""
        t1, t2 = self._tan
        return self.wavelength * t2 / (t1 + t2)

    @property
    def height(self) -> float:
        """Peak-to-valley height (m)."""
        return self.rise_length * self._tan[0]

    @property
    def max_slope(self) -> float:
        return max(self._tan)

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        t1, t2 = self._tan
        a = self.rise_length
        xm = np.mod(x, self.wavelength)
        rising = xm < a
        z = np.where(rising, xm * t1, self.height - (xm - a) * t2)
        return z, np.where(rising, t1, -t2)

    def parameters(self) -> dict[str, Any]:
        return {"angles_deg": list(self.angles_deg), "wavelength_m": self.wavelength}


@dataclass(frozen=True, eq=False)
class SmoothWedgeProfile(Profile):
    """A smooth asymmetric profile with the mean face slopes of a wedge ("generic" 1-D roughness).

    Each face is a half cosine: rising ``z = h/2 (1 - cos(pi x / a))`` on [0, a], falling
    ``z = h/2 (1 + cos(pi (x - a) / b))`` on [a, lambda] with ``b = lambda - a``. The face
    lengths a, b and the height h are those of :class:`WedgeProfile` with the same
    angles, so the mean |slope| of each face is tan(angle) and each face keeps its Eq 14
    share; the profile is C1 (zero slope at peak and valley). With equal angles it is a
    sinusoid of slope amplitude (pi/2) tan(angle).
    """

    kind: ClassVar[str] = "smooth_wedge"
    angles_deg: tuple[float, float]
    wavelength: float
    _wedge: WedgeProfile = field(init=False, repr=False)

    def __post_init__(self) -> None:
        wedge = WedgeProfile(self.angles_deg, self.wavelength)
        object.__setattr__(self, "angles_deg", wedge.angles_deg)
        object.__setattr__(self, "wavelength", wedge.wavelength)
        object.__setattr__(self, "_wedge", wedge)

    @property
    def length(self) -> float:
        return self.wavelength

    @property
    def max_slope(self) -> float:
        return 0.5 * math.pi * self._wedge.max_slope

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        a = self._wedge.rise_length
        b = self.wavelength - a
        h = self._wedge.height
        xm = np.mod(x, self.wavelength)
        rising = xm < a
        arg_r = np.pi * xm / a
        arg_f = np.pi * (xm - a) / b
        z = np.where(rising, 0.5 * h * (1.0 - np.cos(arg_r)), 0.5 * h * (1.0 + np.cos(arg_f)))
        g = np.where(
            rising, 0.5 * h * np.pi / a * np.sin(arg_r), -0.5 * h * np.pi / b * np.sin(arg_f)
        )
        return z, g

    def parameters(self) -> dict[str, Any]:
        return {"angles_deg": list(self.angles_deg), "wavelength_m": self.wavelength}


@dataclass(frozen=True, eq=False)
class SineProfile(Profile):
    """``z = A sin(2 pi x / lambda)`` (A, lambda in m)."""

    kind: ClassVar[str] = "sinusoid"
    amplitude: float
    wavelength: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "amplitude", _check_positive("amplitude", self.amplitude))
        object.__setattr__(self, "wavelength", _check_positive("wavelength", self.wavelength))

    @property
    def length(self) -> float:
        return self.wavelength

    @property
    def max_slope(self) -> float:
        return 2.0 * math.pi * self.amplitude / self.wavelength

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        k = 2.0 * np.pi / self.wavelength
        return self.amplitude * np.sin(k * x), self.amplitude * k * np.cos(k * x)

    def parameters(self) -> dict[str, Any]:
        return {"amplitude_m": self.amplitude, "wavelength_m": self.wavelength}


@dataclass(frozen=True, eq=False)
class ProductSineMap(HeightMap):
    """``z = A sin(2 pi x / lambda_x) sin(2 pi y / lambda_y)`` (A, lambdas in m)."""

    kind: ClassVar[str] = "sinusoid"
    amplitude: float
    wavelengths: tuple[float, float]

    def __post_init__(self) -> None:
        object.__setattr__(self, "amplitude", _check_positive("amplitude", self.amplitude))
        try:
            lx, ly = self.wavelengths
        except (TypeError, ValueError):
            raise ParameterError("wavelengths", self.wavelengths, "two lengths in m") from None
        object.__setattr__(
            self,
            "wavelengths",
            (_check_positive("wavelengths[0]", lx), _check_positive("wavelengths[1]", ly)),
        )

    @property
    def physical_sizes(self) -> tuple[float, float]:
        return self.wavelengths

    @property
    def max_slope(self) -> float:
        return 2.0 * math.pi * self.amplitude / min(self.wavelengths)

    def evaluate(self, x: ArrayLike, y: ArrayLike | None = None) -> Evaluation:
        xa = _as_float_array(x, "x")
        ya = _as_float_array(0.0 if y is None else y, "y")
        kx = 2.0 * np.pi / self.wavelengths[0]
        ky = 2.0 * np.pi / self.wavelengths[1]
        sx, cx = np.sin(kx * xa), np.cos(kx * xa)
        sy, cy = np.sin(ky * ya), np.cos(ky * ya)
        a = self.amplitude
        return a * sx * sy, (a * kx) * cx * sy, (a * ky) * sx * cy

    def parameters(self) -> dict[str, Any]:
        return {"amplitude_m": self.amplitude, "wavelengths_m": list(self.wavelengths)}


# --------------------------------------------------------------------------- factories


def flat() -> FlatProfile:
    """A flat surface (slope 0 everywhere)."""
    return FlatProfile()


def wedge(angles_deg: float | Sequence[float], wavelength: float) -> WedgeProfile:
    """Symmetric (one angle) or asymmetric (rising, falling) wedge / saw-tooth profile."""
    return WedgeProfile(_face_angles(angles_deg), wavelength)


def smooth_wedge(angles_deg: float | Sequence[float], wavelength: float) -> SmoothWedgeProfile:
    """Smooth (half-cosine) profile with the mean face slopes of a wedge; see the class."""
    return SmoothWedgeProfile(_face_angles(angles_deg), wavelength)


def sinusoid(
    amplitude: float, wavelengths: float | Sequence[float]
) -> SineProfile | ProductSineMap:
    """One wavelength: ``A sin(2 pi x/l)`` profile; two: ``A sin(2 pi x/lx) sin(2 pi y/ly)`` map."""
    values = _floats(wavelengths, "wavelengths")
    if len(values) == 1:
        return SineProfile(amplitude, values[0])
    if len(values) == 2:
        return ProductSineMap(amplitude, (values[0], values[1]))
    raise ParameterError("wavelengths", wavelengths, "one value (1-D) or two values (2-D)")


def from_function(
    function: Callable[..., ArrayLike],
    gradient: Callable[..., Any],
    periods: float | Sequence[float],
) -> FunctionProfile | FunctionHeightMap:
    """A surface from a periodic function and its gradient.

    One period: ``function(x)`` and ``gradient(x) = f'(x)`` give a profile. Two periods:
    ``function(x, y)`` and ``gradient(x, y) = (g_x, g_y)`` give a height map. Both must
    be vectorised with NumPy broadcasting; periodicity is checked on a sample grid.
    """
    values = _floats(periods, "periods")
    if len(values) == 1:
        return FunctionProfile(function, gradient, values[0])
    if len(values) == 2:
        return FunctionHeightMap(function, gradient, (values[0], values[1]))
    raise ParameterError("periods", periods, "one period (1-D) or two periods (2-D), in m")


def from_array(
    heights: ArrayLike,
    physical_sizes: float | Sequence[float],
    *,
    gradient: str = "fd",
    fill_missing: bool = False,
) -> SampledProfile | SampledHeightMap:
    """A periodic surface from sampled heights (m) on a uniform grid.

    Parameters
    ----------
    heights:
        Shape (n,) for a profile or (nx, ny) for a height map (index order x, y); the
        samples sit at the pixel centres.
    physical_sizes:
        The period(s) (m): one value for a profile, (Lx, Ly) for a map.
    gradient:
        ``"fd"`` (periodic central differences, default) or ``"spectral"``.
    fill_missing:
        Undefined heights (NaN) are an error unless True; then they are filled by
        harmonic interpolation (SurfaceTopography's ``interpolate_undefined_data``,
        periodic).
    """
    arr = np.array(heights, dtype=np.float64, copy=True)
    sizes = _floats(physical_sizes, "physical_sizes")
    if arr.ndim != len(sizes) or arr.ndim not in (1, 2):
        raise ParameterError(
            "physical_sizes", physical_sizes, f"one size per axis of heights (shape {arr.shape})"
        )
    if np.any(np.isinf(arr)):
        raise ParameterError("heights", "infinite values", "finite heights or NaN for missing")
    if np.any(np.isnan(arr)):
        if not fill_missing:
            n_bad = int(np.count_nonzero(np.isnan(arr)))
            raise ParameterError(
                "heights",
                f"{n_bad} undefined (NaN) values",
                "finite heights; pass fill_missing=True to fill them by harmonic interpolation",
            )
        arr = _fill_missing(arr, sizes)
    if arr.ndim == 1:
        return SampledProfile(arr, sizes[0], gradient)
    return SampledHeightMap(arr, (sizes[0], sizes[1]), gradient)


def _fill_missing(heights: FloatArray, sizes: list[float]) -> FloatArray:
    """Harmonic fill of NaN samples on a periodic grid (SurfaceTopography's imputation)."""
    from SurfaceTopography import Topography, UniformLineScan

    if np.all(np.isnan(heights)):
        raise ParameterError("heights", "all values undefined", "at least one defined height")
    masked = np.ma.masked_invalid(heights)
    if heights.ndim == 1:
        topo: Any = UniformLineScan(masked, sizes[0], periodic=True)
    else:
        topo = Topography(masked, tuple(sizes), periodic=True)
    return np.asarray(topo.interpolate_undefined_data().heights(), dtype=np.float64)


def self_affine(
    hurst: float,
    physical_sizes: float | Sequence[float],
    points: int | Sequence[int],
    *,
    rng: np.random.Generator,
    rms_height: float | None = None,
    rms_slope: float | None = None,
    short_cutoff: float | None = None,
    long_cutoff: float | None = None,
) -> SampledProfile | SampledHeightMap:
    """A periodic self-affine random surface (Fourier filtering of white noise).

    The power spectrum is ``C(q) ~ q^-(1+2H)`` (1-D) or ``q^-2(1+H)`` (2-D, isotropic)
    between the wavevectors of ``long_cutoff`` (roll-off: constant below it; default: the
    period) and ``short_cutoff`` (zero above it; default: two samples). The result is
    zero-mean and scaled to exactly one of ``rms_height`` (m) or ``rms_slope``; gradients
    are spectral.

    Parameters
    ----------
    hurst:
        Hurst exponent H, 0 < H <= 1.
    physical_sizes, points:
        Period(s) (m) and sample counts (>= 8 each): one value each for a profile, two
        for a map.
    rng:
        The random generator (required: no global random state).
    """
    if not isinstance(rng, np.random.Generator):
        raise ParameterError("rng", type(rng).__name__, "a numpy.random.Generator")
    if not (isinstance(hurst, int | float) and 0.0 < float(hurst) <= 1.0):
        raise ParameterError("hurst", hurst, "0 < hurst <= 1")
    sizes = _floats(physical_sizes, "physical_sizes")
    counts = [points] if np.ndim(points) == 0 else list(np.ravel(points))
    if len(sizes) not in (1, 2) or len(counts) != len(sizes):
        raise ParameterError("points", points, "one count per physical size (1 or 2 axes)")
    lengths = [_check_positive(f"physical_sizes[{i}]", s) for i, s in enumerate(sizes)]
    shape = []
    for i, n in enumerate(counts):
        if isinstance(n, bool) or not isinstance(n, int | np.integer) or int(n) < 8:
            raise ParameterError(f"points[{i}]", n, "an integer >= 8")
        shape.append(int(n))
    if (rms_height is None) == (rms_slope is None):
        raise ParameterError("rms_height/rms_slope", (rms_height, rms_slope), "exactly one of them")
    target = _check_positive(
        "rms_height" if rms_height is not None else "rms_slope",
        rms_height if rms_height is not None else rms_slope,
    )
    dims = len(shape)
    qs = np.meshgrid(
        *[2.0 * np.pi * np.fft.fftfreq(n, L / n) for n, L in zip(shape, lengths, strict=True)],
        indexing="ij",
    )
    q = np.sqrt(sum(qi**2 for qi in qs))
    q_long = (
        2.0 * np.pi / (_check_positive("long_cutoff", long_cutoff) if long_cutoff else max(lengths))
    )
    q_nyq = min(np.pi * n / L for n, L in zip(shape, lengths, strict=True))
    q_short = 2.0 * np.pi / _check_positive("short_cutoff", short_cutoff) if short_cutoff else q_nyq
    if q_short <= q_long:
        raise ParameterError(
            "short_cutoff", short_cutoff, "shorter than long_cutoff and the period"
        )
    exponent = -(1.0 + 2.0 * hurst) if dims == 1 else -2.0 * (1.0 + hurst)
    psd = np.zeros(q.shape)
    band = (q > 0.0) & (q <= q_short * (1.0 + 1e-12))
    for axis, n in enumerate(shape):
        if n % 2 == 0:  # drop Nyquist modes: their derivative is not defined on the grid
            index = [slice(None)] * dims
            index[axis] = slice(n // 2, n // 2 + 1)
            band[tuple(index)] = False
    psd[band] = np.maximum(q[band], q_long) ** exponent
    noise = np.fft.fftn(rng.standard_normal(shape))
    spectrum = noise * np.sqrt(psd)
    heights = np.real(np.fft.ifftn(spectrum))
    heights -= heights.mean()
    if rms_slope is not None:
        slopes = [np.real(np.fft.ifftn(1j * qi * spectrum)) for qi in qs]
        current = float(np.sqrt(np.mean(sum(s**2 for s in slopes))))
    else:
        current = float(np.sqrt(np.mean(heights**2)))
    if current == 0.0:
        raise ParameterError("short_cutoff", short_cutoff, "a band that contains Fourier modes")
    heights *= target / current
    if dims == 1:
        return SampledProfile(heights, lengths[0], "spectral")
    return SampledHeightMap(heights, (lengths[0], lengths[1]), "spectral")


# --------------------------------------------------------------------------- scaling


@dataclass(frozen=True, eq=False)
class ScaledProfile(Profile):
    """``z(x) = v f(x / h)`` of a base profile f: heights scaled by v, lengths by h.

    The slopes scale by ``v / h``. See :func:`scaled`.
    """

    kind: ClassVar[str] = "scaled"
    base: Profile
    vertical: float
    horizontal: float

    @property
    def length(self) -> float | None:
        return None if self.base.length is None else self.base.length * self.horizontal

    @property
    def max_slope(self) -> float:
        return self.base.max_slope * self.vertical / self.horizontal

    def profile(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        z, g = self.base.profile(np.asarray(x, dtype=np.float64) / self.horizontal)
        return self.vertical * z, (self.vertical / self.horizontal) * g

    def parameters(self) -> dict[str, Any]:
        return {
            "base": self.base.describe(),
            "vertical": self.vertical,
            "horizontal": self.horizontal,
        }


@dataclass(frozen=True, eq=False)
class ScaledHeightMap(HeightMap):
    """``z(x, y) = v f(x / h, y / h)`` of a base height map f. See :func:`scaled`."""

    kind: ClassVar[str] = "scaled"
    base: HeightMap
    vertical: float
    horizontal: float

    @property
    def physical_sizes(self) -> tuple[float, float]:
        lx, ly = self.base.physical_sizes
        return (lx * self.horizontal, ly * self.horizontal)

    @property
    def max_slope(self) -> float:
        return self.base.max_slope * self.vertical / self.horizontal

    @property
    def grid_shape(self) -> tuple[int, ...] | None:
        return self.base.grid_shape

    def evaluate(self, x: ArrayLike, y: ArrayLike | None = None) -> Evaluation:
        xa = _as_float_array(x, "x") / self.horizontal
        ya = _as_float_array(0.0 if y is None else y, "y") / self.horizontal
        z, gx, gy = self.base.evaluate(xa, ya)
        slope = self.vertical / self.horizontal
        return self.vertical * z, slope * gx, slope * gy

    def parameters(self) -> dict[str, Any]:
        return {
            "base": self.base.describe(),
            "vertical": self.vertical,
            "horizontal": self.horizontal,
        }


def scaled(
    surface: Profile | HeightMap, vertical: float = 1.0, horizontal: float = 1.0
) -> Profile | HeightMap:
    """The surface ``z = v f(x/h, y/h)``: heights scaled by ``vertical``, lengths by ``horizontal``.

    Slopes scale by ``v / h``. Used by wear (heights scaled by the reduction coefficient
    B: ``z(t) = B z0`` above the fixed valley) and by hierarchies
    (self-similar levels, Eq 28: ``v = h``). ``vertical`` in [0, inf), ``horizontal`` > 0.
    ``vertical = 0`` gives a flat surface (a :class:`FlatProfile`, or a
    :class:`ScaledHeightMap` of zero heights keeping the map's periods). Wedges, smooth
    wedges, sinusoids and sampled surfaces come back as their own kind (a wedge keeps its
    face shares with angles ``arctan((v/h) tan phi)``); other surfaces are wrapped
    (:class:`ScaledProfile`, :class:`ScaledHeightMap`).
    """
    try:
        v, h = float(vertical), float(horizontal)
    except (TypeError, ValueError):
        raise ParameterError("vertical/horizontal", (vertical, horizontal), "numbers") from None
    if not (math.isfinite(v) and v >= 0.0):
        raise ParameterError("vertical", vertical, "a finite factor >= 0")
    if not (math.isfinite(h) and h > 0.0):
        raise ParameterError("horizontal", horizontal, "a finite factor > 0")
    if isinstance(surface, FlatProfile) or (v == 1.0 and h == 1.0):
        return surface
    if v == 0.0 and isinstance(surface, Profile):
        return FlatProfile()
    if isinstance(surface, WedgeProfile | SmoothWedgeProfile) and v > 0.0:
        angles = tuple(
            math.degrees(math.atan(v / h * math.tan(math.radians(a)))) for a in surface.angles_deg
        )
        make = wedge if isinstance(surface, WedgeProfile) else smooth_wedge
        return make(angles, surface.wavelength * h)
    if isinstance(surface, SineProfile) and v > 0.0:
        return SineProfile(surface.amplitude * v, surface.wavelength * h)
    if isinstance(surface, ProductSineMap) and v > 0.0:
        lx, ly = surface.wavelengths
        return ProductSineMap(surface.amplitude * v, (lx * h, ly * h))
    if isinstance(surface, SampledProfile) and v > 0.0:
        return SampledProfile(surface.heights * v, surface.size * h, surface.gradient)
    if isinstance(surface, SampledHeightMap) and v > 0.0:
        lx, ly = surface.sizes
        return SampledHeightMap(surface.heights * v, (lx * h, ly * h), surface.gradient)
    if isinstance(surface, ScaledProfile | ScaledHeightMap):
        return scaled(surface.base, surface.vertical * v, surface.horizontal * h)
    if isinstance(surface, Profile):
        return ScaledProfile(surface, v, h)
    if isinstance(surface, HeightMap):
        return ScaledHeightMap(surface, v, h)
    raise ParameterError("surface", type(surface).__name__, "a Profile or HeightMap")
