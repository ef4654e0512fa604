"""Measured topographies: an adapter from SurfaceTopography to frictionlab surfaces.

Two entry points, kept apart:

* :func:`from_topography` converts a SurfaceTopography object already in memory (pure,
  no I/O) into a :class:`~frictionlab.roughness.surface.SampledProfile` (line scan) or
  :class:`~frictionlab.roughness.surface.SampledHeightMap` (topography), in metres;
* :func:`read_surface` is the **only** function here that touches files: it opens a file
  with SurfaceTopography's readers (x3p, sur, datx, opd, plu, sdf, plain text, NetCDF,
  ...; see ``SurfaceTopography.IO``) and calls :func:`from_topography`.

The two decisions that change the friction of a measured surface are explicit,
required keyword arguments, never defaults:

* ``periodicity``: the lattice needs a periodic surface.
  ``"require"``: the topography must declare itself periodic (SurfaceTopography's
  ``is_periodic``; among files only SurfaceTopography's NetCDF stores this flag),
  otherwise an error; ``"assume"``: treat the data as one period as
  they are (the jump between opposite edges becomes a steep artificial face);
  ``"mirror"``: append the mirror image along each axis, which makes the heights
  continuous across the edges (doubled size) but also makes every slope appear with
  both signs, so direction-reversal (ratchet) effects are averaged out.
* ``detrend``: ``"none"``, ``"center"`` (subtract the mean height; no effect on
  friction), ``"height"`` (subtract the best-fit plane) or ``"curvature"`` (subtract the
  best-fit quadratic), by SurfaceTopography's ``detrend``. With
  ``periodicity="require"`` only ``"none"`` and ``"center"`` are accepted: removing a
  tilt from a periodic surface breaks its periodicity.

Undefined data (NaN, e.g. optical dropouts) is refused unless ``fill_missing=True``,
which fills it by SurfaceTopography's harmonic interpolation (``interpolate_undefined_data``)
before detrending. Samples are placed at pixel centres (SurfaceTopography's positions
shifted by half a pixel; a uniform translation that does not change friction).

**Axes.** ``heights[i, j]`` is the height at ``(x_i, y_j)``: the first array axis is x
(SurfaceTopography's convention, kept for every format). A ``.npy`` array is read as is
(first index x). A plain-text matrix is read by SurfaceTopography's ``asc`` reader, which
takes each *row of the file* as a line at constant y (the layout Gwyddion and
``Topography.to_matrix`` write): save an array with ``numpy.savetxt(name, heights.T)``.
A text file of 2 or 3 values per line could also be x y [z] points: it needs
``format = "asc"`` (a matrix) or ``format = "xyz"`` (points); rows of unequal length are
refused, naming the line.
The sliding direction beta is measured from x.

**Preparation** (:func:`prepare_topography`, in this order, each optional):
``crop = (x0, x1, y0, y1)`` (m, from the scan's origin, a line scan takes (x0, x1));
``fill_missing``; ``detrend``; ``window`` (SurfaceTopography's window, e.g. ``"hann"``,
which tapers the heights to zero at the edges); conversion to metres; periodicity;
``long_cutoff`` and ``short_cutoff`` (m), SurfaceTopography's ``longcut`` and ``shortcut``
Fourier filters (circular step) on the now periodic data. :class:`PreparedSurface`
records every step, the rms height and rms slope after filtering, and warns when
``periodicity="assume"`` makes the edge step steeper than any interior step.
"""

from __future__ import annotations

import hashlib
import math
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, TypedDict, Unpack

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray
from frictionlab.errors import InputError, ParameterError
from frictionlab.io.inputs import check_input_file
from frictionlab.roughness.generators import from_array
from frictionlab.roughness.surface import SampledHeightMap, SampledProfile

__all__ = [
    "DETREND_MODES",
    "PERIODICITY_MODES",
    "FileOptions",
    "Preparation",
    "PreparedSurface",
    "from_topography",
    "prepare_topography",
    "read_prepared",
    "read_surface",
]

PERIODICITY_MODES = ("require", "assume", "mirror")
DETREND_MODES = ("none", "center", "height", "curvature")


@dataclass(frozen=True)
class PreparedSurface:
    """A measured surface ready for the lattice, with what was done to it.

    ``info``: JSON-ready provenance (source sizes and points, crop, filled points,
    detrend, window, periodicity, the scan's sizes and points before mirroring
    (``scan_sizes_m``, ``scan_points``), filters, rms height (m) and rms slope after
    filtering); ``warnings``: sentences for the user (e.g. an artificial edge step).
    """

    surface: SampledProfile | SampledHeightMap
    info: dict[str, Any] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()


class Preparation(TypedDict, total=False):
    """The optional keywords of :func:`prepare_topography` (documented there; its
    defaults apply to what is left out)."""

    fill_missing: bool
    gradient: str
    crop: tuple[float, ...] | None
    window: str | None
    short_cutoff: float | None
    long_cutoff: float | None
    allow_flattening: bool
    resample: str | int | None


class FileOptions(Preparation, total=False):
    """The optional keywords of :func:`read_prepared`: the file's reader and metadata, then
    those of :class:`Preparation`."""

    format: str | None
    channel: int | None
    unit: str | None
    physical_sizes: float | tuple[float, ...] | None


def from_topography(
    topography: Any, *, periodicity: str, detrend: str, **options: Unpack[Preparation]
) -> SampledProfile | SampledHeightMap:
    """Convert a SurfaceTopography line scan or topography to a frictionlab surface (SI).

    The surface of :func:`prepare_topography` (same arguments).
    """
    return prepare_topography(
        topography, periodicity=periodicity, detrend=detrend, **options
    ).surface


def prepare_topography(
    topography: Any,
    *,
    periodicity: str,
    detrend: str,
    fill_missing: bool = False,
    gradient: str = "fd",
    crop: tuple[float, ...] | None = None,
    window: str | None = None,
    short_cutoff: float | None = None,
    long_cutoff: float | None = None,
    allow_flattening: bool = False,
    resample: str | int | None = None,
) -> PreparedSurface:
    """Crop, fill, detrend, window, make periodic and filter a topography (module docstring).

    Parameters
    ----------
    topography:
        A uniform ``SurfaceTopography`` ``UniformLineScan`` or ``Topography`` with a length
        unit.
    periodicity:
        ``"require"``, ``"assume"`` or ``"mirror"`` (see the module docstring).
    detrend:
        ``"none"``, ``"center"``, ``"height"`` or ``"curvature"``.
    fill_missing:
        Fill undefined heights by harmonic interpolation instead of refusing them.
    gradient:
        Gradient of the sampled surface: ``"fd"`` (default) or ``"spectral"``.
    crop:
        ``(x0, x1, y0, y1)`` (m, from the scan origin; (x0, x1) for a line scan): keep the
        pixels whose centres lie inside.
    window:
        A SurfaceTopography window name (``"hann"``, ...), applied after detrending.
    short_cutoff, long_cutoff:
        Shortest and longest wavelength kept (m), ``short_cutoff < long_cutoff``; each
        must lie in the scan's resolvable range (:func:`resolvable_range`), else an error
        naming the key and the range.
    allow_flattening:
        The window and the filters must keep at least 1 % of the rms height and of the rms
        slope of the detrended data (:data:`FLATTENING_LIMIT`); ``True`` accepts less.
    resample:
        How a non-uniform line scan is put on a uniform grid (SurfaceTopography's
        ``to_uniform``, linear interpolation): ``"median"`` (pixel = the median spacing),
        ``"finest"`` (pixel = the smallest spacing) or a number of points >= 8. ``None``
        (default): a non-uniform scan is refused, naming this key.
    """
    if periodicity not in PERIODICITY_MODES:
        raise ParameterError("periodicity", periodicity, f"one of {PERIODICITY_MODES}")
    if detrend not in DETREND_MODES:
        raise ParameterError("detrend", detrend, f"one of {DETREND_MODES}")
    if not hasattr(topography, "heights") or not hasattr(topography, "physical_sizes"):
        raise ParameterError("topography", type(topography).__name__, "a SurfaceTopography object")
    resampled = None
    if not getattr(topography, "is_uniform", False):
        topography, resampled = _resample(topography, resample)
    elif resample is not None:
        _check_resample(resample)
    if topography.dim not in (1, 2):
        raise ParameterError("topography.dim", topography.dim, "1 (line scan) or 2 (topography)")
    for name, value in (("short_cutoff", short_cutoff), ("long_cutoff", long_cutoff)):
        if value is not None and not (isinstance(value, int | float) and 0.0 < value < math.inf):
            raise ParameterError(name, value, "a wavelength > 0 in m")
    if short_cutoff is not None and long_cutoff is not None and short_cutoff >= long_cutoff:
        raise ParameterError(
            "short_cutoff", short_cutoff, f"a wavelength below long_cutoff = {long_cutoff:g} m"
        )
    if periodicity == "require":
        if not topography.is_periodic:
            raise ParameterError(
                "periodicity",
                "require",
                "a topography that declares itself periodic; this one does not: choose "
                "periodicity = 'assume' (use the data as one period) or 'mirror'",
            )
        if detrend in ("height", "curvature"):
            raise ParameterError(
                "detrend",
                detrend,
                "'none' or 'center' for a periodic topography (removing a tilt breaks periodicity)",
            )
        if window is not None or crop is not None:
            raise ParameterError(
                "window" if window is not None else "crop",
                window if window is not None else list(crop or ()),
                "none with periodicity = 'require' (it breaks periodicity)",
            )
    raw_sizes = [float(v) for v in np.ravel(topography.physical_sizes)]
    if len(raw_sizes) != topography.dim or not all(v > 0 and math.isfinite(v) for v in raw_sizes):
        grid = "x".join(str(int(v)) for v in np.ravel(topography.nb_grid_pts))
        raise ParameterError(
            "physical_sizes",
            raw_sizes,
            f"{topography.dim} sizes > 0 (one per axis of the {grid} data, in `unit`)",
        )
    if topography.unit is None:
        raise ParameterError("unit", None, "a length unit for the file (e.g. unit = 'um')")
    try:
        to_metres = float(_unit_factor(topography.unit))
    except (KeyError, ValueError, TypeError):
        raise ParameterError(
            "unit", topography.unit, f"a length unit, one of {_length_units()}"
        ) from None
    info: dict[str, Any] = {
        "source_unit": str(topography.unit),
        "source_physical_sizes_m": [
            float(v) * to_metres for v in np.ravel(topography.physical_sizes)
        ],
        "source_points": [int(v) for v in np.ravel(topography.nb_grid_pts)],
    }
    if resampled is not None:
        info["resampled"] = resampled
    if crop is not None:
        topography = _crop(topography, crop, to_metres)
        info["crop_m"] = [float(v) for v in crop]
        info["cropped_points"] = [int(v) for v in np.ravel(topography.nb_grid_pts)]
    n_bad = 0
    islands = 0
    if topography.has_undefined_data:
        missing = np.ma.getmaskarray(topography.heights())
        n_bad = int(np.count_nonzero(missing))
        islands = _isolated_points(missing)
        if not fill_missing:
            raise ParameterError(
                "heights",
                f"{n_bad} undefined points",
                "complete data: set fill_missing = true to fill them by harmonic "
                "interpolation, or crop them away",
            )
        total = int(np.prod(topography.nb_grid_pts))
        if 2 * n_bad > total:  # filling would invent the surface (all-NaN: a flat one)
            raise ParameterError(
                "heights",
                f"{n_bad} of {total} points undefined",
                "at least half of the points defined for fill_missing = true (crop the "
                "defined region instead)",
            )
        topography = topography.interpolate_undefined_data()
    warnings: list[str] = []
    total_points = int(np.prod(topography.nb_grid_pts))
    info["filled_points"] = n_bad
    info["filled_fraction"] = n_bad / total_points
    if n_bad > FILL_WARNING * total_points:
        cones = (
            f"; {islands} measured points stand alone inside the gaps and become cones, "
            "steep at the pixel scale (the contact concentrates on them)"
            if islands
            else ""
        )
        warnings.append(
            f"fill_missing invented {n_bad} of {total_points} points "
            f"({100.0 * n_bad / total_points:.1f} %, above {100 * FILL_WARNING:.0f} %) by "
            "harmonic interpolation: they are smooth, so the friction of this map is "
            f"underestimated where they lie{cones}; crop the defined region instead"
        )
    if n_bad:
        info["isolated_measured_points"] = islands
    info["detrend"] = detrend
    if detrend != "none":
        topography = topography.detrend(detrend_mode=detrend)
    before = _rms(np.asarray(np.ma.getdata(topography.heights()), dtype=np.float64) * to_metres,
                  [float(s) * to_metres for s in np.ravel(topography.physical_sizes)])  # fmt: skip
    info["window"] = window
    if window is not None:
        separable = topography.dim == 2 and _non_square(topography)
        info["window_shape"] = "separable" if separable else "radial"
        try:
            if separable:  # a radial window would zero the corners of a long strip
                topography = topography.window(window=window, direction="x").window(
                    window=window, direction="y"
                )
            else:
                topography = topography.window(window=window)
            topography.heights()
        except Exception as exc:
            raise ParameterError(
                "window", window, f"a window SurfaceTopography knows ({_first(exc)})"
            ) from None
    heights = np.array(np.ma.getdata(topography.heights()), dtype=np.float64) * to_metres
    sizes = [float(s) * to_metres for s in np.ravel(topography.physical_sizes)]
    info["periodicity"] = periodicity
    if periodicity == "assume":
        step = _edge_steps(heights, sizes)
        info["edge_step_slope"] = step
        if step["edge"] > step["interior"]:
            warnings.append(
                f"periodicity = 'assume' joins opposite edges with a step of slope "
                f"{step['edge']:.3g}, steeper than any interior step ({step['interior']:.3g}): "
                "that artificial face counts as roughness; consider periodicity = 'mirror', "
                "window = 'hann' or detrend = 'height'"
            )
    # the scan itself (after crop), which figures draw instead of the mirrored double
    info["scan_sizes_m"] = list(sizes)
    info["scan_points"] = [int(v) for v in heights.shape]
    if periodicity == "mirror":
        for axis in range(heights.ndim):
            heights = np.concatenate([heights, np.flip(heights, axis=axis)], axis=axis)
            sizes[axis] *= 2.0
    info["short_cutoff_m"] = short_cutoff
    info["long_cutoff_m"] = long_cutoff
    lo, hi = resolvable_range(sizes, heights.shape)
    for key, value in (("short_cutoff", short_cutoff), ("long_cutoff", long_cutoff)):
        if value is not None and not (lo <= value <= hi):
            raise ParameterError(
                key,
                value,
                f"a wavelength in the scan's resolvable range {lo:.4g} m (twice the pixel) to "
                f"{hi:.4g} m (the period): outside it the filter removes everything or nothing",
            )
    if short_cutoff is not None or long_cutoff is not None:
        heights = band_filter(heights, sizes, short_cutoff, long_cutoff)
    after = _rms(heights, sizes)
    info["rms_kept"] = {
        k: (after[k] / before[k] if before[k] > 0.0 else 1.0) for k in ("height", "slope")
    }
    flattened = [k for k, v in info["rms_kept"].items() if v < FLATTENING_LIMIT]
    if flattened:
        text = ", ".join(f"rms {k} to {100.0 * info['rms_kept'][k]:.3g} %" for k in flattened)
        if not allow_flattening:
            raise ParameterError(
                "allow_flattening",
                False,
                f"true to accept a preparation (window, short_cutoff, long_cutoff) that "
                f"reduces the {text} of the detrended data (below "
                f"{100 * FLATTENING_LIMIT:.0f} %: the surface left is not the measured one)",
            )
        warnings.append(f"the preparation reduced the {text} (allow_flattening = true)")
    surface = from_array(heights, sizes if heights.ndim == 2 else sizes[0], gradient=gradient)
    params = surface.parameters()
    info["physical_sizes_m"] = sizes
    info["points"] = [int(v) for v in heights.shape]
    info["rms_height_m"] = params["rms_height_m"]
    info["rms_slope"] = params["rms_slope"]
    return PreparedSurface(surface, info, tuple(warnings))


#: Fraction of filled (invented) points above which a warning is given.
FILL_WARNING = 0.10
#: Smallest fraction of the rms height or slope the window and filters may keep.
FLATTENING_LIMIT = 0.01
#: ``resample`` modes of non-uniform line scans (besides a number of points).
RESAMPLE_MODES = ("median", "finest")


def resolvable_range(sizes: Sequence[float], shape: Sequence[int]) -> tuple[float, float]:
    """Wavelengths (m) a periodic scan represents: twice its finest pixel to its period.

    A filter cutoff outside ``[lo, hi]`` removes all or none of the data along every axis.
    """
    pixels = [float(s) / int(n) for s, n in zip(sizes, shape, strict=True)]
    return 2.0 * min(pixels), max(float(s) for s in sizes)


def _rms(heights: FloatArray, sizes: Sequence[float]) -> dict[str, float]:
    """rms height (about the mean) and rms slope (periodic central differences)."""
    h = np.asarray(heights, dtype=np.float64)
    slope2 = np.zeros(h.shape)
    for axis in range(h.ndim):
        d = float(sizes[axis]) / h.shape[axis]
        slope2 += ((np.roll(h, -1, axis) - np.roll(h, 1, axis)) / (2.0 * d)) ** 2
    return {"height": float(np.std(h)), "slope": float(np.sqrt(slope2.mean()))}


def _non_square(topography: Any) -> bool:
    nx, ny = (int(v) for v in topography.nb_grid_pts)
    lx, ly = (float(v) for v in topography.physical_sizes)
    return nx != ny or not math.isclose(lx, ly, rel_tol=1e-9)


def _check_resample(resample: Any) -> None:
    if isinstance(resample, str):
        if resample not in RESAMPLE_MODES:
            raise ParameterError("resample", resample, f"one of {RESAMPLE_MODES} or points >= 8")
    elif isinstance(resample, bool) or not isinstance(resample, int) or resample < 8:
        raise ParameterError("resample", resample, f"one of {RESAMPLE_MODES} or points >= 8")


def _resample(topography: Any, resample: Any) -> tuple[Any, dict[str, Any]]:
    """A non-uniform line scan on a uniform grid (SurfaceTopography's ``to_uniform``)."""
    if resample is None:
        raise ParameterError(
            "resample",
            None,
            f"one of {RESAMPLE_MODES} or a number of points for this non-uniform line scan "
            "(its points are not equally spaced; it is put on a uniform grid by linear "
            "interpolation)",
        )
    _check_resample(resample)
    x = np.asarray(topography.positions(), dtype=np.float64)
    spacing = np.diff(x)
    if spacing.size < 1 or not np.all(spacing > 0.0):
        raise ParameterError("resample", resample, "a line scan with strictly increasing positions")
    if resample == "median":
        uniform = topography.to_uniform(pixel_size=float(np.median(spacing)))
    elif resample == "finest":
        uniform = topography.to_uniform(pixel_size=float(spacing.min()))
    else:
        uniform = topography.to_uniform(nb_points=int(resample))
    points = int(np.ravel(uniform.nb_grid_pts)[0])
    return uniform, {"mode": resample, "source_points": int(x.size), "points": points}


def _length_units() -> list[str]:
    from SurfaceTopography.Support.UnitConversion import length_units

    return list(length_units)


def _unit_factor(unit: Any) -> float:
    """Metres per ``unit`` (SurfaceTopography's table; KeyError for an unknown unit)."""
    from SurfaceTopography.Support.UnitConversion import length_units, mangle_length_unit_utf8

    return float(length_units[mangle_length_unit_utf8(str(unit).strip())])


def _first(exc: Exception) -> str:
    text = str(exc).strip().splitlines()
    return text[0] if text else type(exc).__name__


def _crop(topography: Any, crop: tuple[float, ...], to_metres: float) -> Any:
    """The pixels whose centres lie inside ``crop`` (m), as a new non-periodic topography."""
    from SurfaceTopography import Topography, UniformLineScan

    dim = topography.dim
    values = [float(v) for v in crop]
    if len(values) != 2 * dim or not all(math.isfinite(v) for v in values):
        raise ParameterError(
            "crop",
            values,
            f"{2 * dim} finite lengths [x0, x1{', y0, y1' if dim == 2 else ''}] in m",
        )
    sizes = [float(v) * to_metres for v in np.ravel(topography.physical_sizes)]
    points = [int(v) for v in np.ravel(topography.nb_grid_pts)]
    slices = []
    new_sizes = []
    for axis in range(dim):
        lo, hi = values[2 * axis], values[2 * axis + 1]
        if not (0.0 <= lo < hi <= sizes[axis] * (1 + 1e-12)):
            name = "xy"[axis]
            raise ParameterError(
                "crop",
                values,
                f"0 <= {name}0 < {name}1 <= {sizes[axis]:.6g} m (the scan's size along {name})",
            )
        d = sizes[axis] / points[axis]
        centres = (np.arange(points[axis]) + 0.5) * d
        keep = np.flatnonzero((centres >= lo) & (centres <= hi))
        if keep.size < 2:
            raise ParameterError(
                "crop", values, f"a range holding at least 2 pixels along {'xy'[axis]}"
            )
        slices.append(slice(int(keep[0]), int(keep[-1]) + 1))
        new_sizes.append(keep.size * d / to_metres)
    heights = topography.heights()[tuple(slices)]
    if dim == 1:
        return UniformLineScan(heights, new_sizes[0], unit=topography.unit, periodic=False)
    return Topography(heights, tuple(new_sizes), unit=topography.unit, periodic=False)


def _edge_steps(heights: FloatArray, sizes: list[float]) -> dict[str, float]:
    """Largest slope of the step across the periodic wrap and of interior steps."""
    edge = interior = 0.0
    for axis in range(heights.ndim):
        d = sizes[axis] / heights.shape[axis]
        inner = np.abs(np.diff(heights, axis=axis))
        wrap = np.abs(np.take(heights, 0, axis=axis) - np.take(heights, -1, axis=axis))
        interior = max(interior, float(inner.max(initial=0.0)) / d)
        edge = max(edge, float(wrap.max(initial=0.0)) / d)
    return {"edge": edge, "interior": interior}


def band_filter(
    heights: ArrayLike,
    sizes: list[float] | tuple[float, ...],
    short_cutoff: float | None,
    long_cutoff: float | None,
) -> FloatArray:
    """Periodic heights (m) with only wavelengths in [short_cutoff, long_cutoff] kept.

    SurfaceTopography's ``shortcut`` and ``longcut`` filters (circular step in the
    (q_x, q_y) plane) on the heights taken as one period; None: no cut on that side.
    Pure (no I/O); the input is not modified.
    """
    from SurfaceTopography import Topography, UniformLineScan

    h = np.array(heights, dtype=np.float64)
    topo: Any = (
        UniformLineScan(h, sizes[0], periodic=True)
        if h.ndim == 1
        else Topography(h, tuple(sizes), periodic=True)
    )
    if long_cutoff is not None:
        topo = topo.longcut(cutoff_wavelength=long_cutoff)
    if short_cutoff is not None:
        topo = topo.shortcut(cutoff_wavelength=short_cutoff)
    return np.array(topo.heights(), dtype=np.float64)


def read_surface(
    path: str | os.PathLike[str],
    *,
    periodicity: str,
    detrend: str,
    **options: Unpack[FileOptions],
) -> SampledProfile | SampledHeightMap:
    """Read a measured surface file: the surface of :func:`read_prepared` (same arguments).

    Every problem, bad options included, raises :class:`~frictionlab.errors.InputError`.
    """
    try:
        prepared = read_prepared(path, periodicity=periodicity, detrend=detrend, **options)
    except ParameterError as exc:
        raise InputError(f"surface file '{os.fspath(path)}': {exc}") from None
    return prepared.surface


def _isolated_points(missing: np.ndarray) -> int:
    """Measured points whose every neighbour (4 in a map, 2 on a line) is missing."""
    defined = ~missing
    alone = defined.copy()
    for axis in range(missing.ndim):
        for shift in (1, -1):
            alone &= np.roll(missing, shift, axis=axis)
    return int(np.count_nonzero(alone))


def read_prepared(
    path: str | os.PathLike[str],
    *,
    periodicity: str,
    detrend: str,
    format: str | None = None,
    channel: int | None = None,
    unit: str | None = None,
    physical_sizes: float | tuple[float, ...] | None = None,
    **options: Unpack[Preparation],
) -> PreparedSurface:
    """Read a measured surface file with SurfaceTopography and prepare it (file I/O here only).

    ``format`` forces a reader (SurfaceTopography format id such as ``"x3p"``); ``channel``
    selects a data channel (default: the file's default channel); ``unit`` (the length
    unit of heights *and* sizes, e.g. ``"um"``) and ``physical_sizes`` (the scan's size
    along x, y, **in that unit**) supply metadata the file lacks (an error if the file
    has them). The other arguments are those of :func:`prepare_topography`; ``info``
    gains the file name, its sha256, format and channel. Unreadable, unknown or corrupt
    files raise :class:`~frictionlab.errors.InputError`; bad options a
    :class:`~frictionlab.errors.ParameterError` naming the option.
    """
    from SurfaceTopography import open_topography

    name = os.fspath(path)
    check_input_file(name, "surface file")  # a FIFO or device would block the reads below
    try:
        with open(name, "rb") as handle:
            digest = hashlib.file_digest(handle, "sha256").hexdigest()
    except FileNotFoundError:
        raise InputError(f"cannot read surface file '{name}': no such file") from None
    except OSError as exc:
        raise InputError(f"cannot read surface file '{name}': {_describe(exc)}") from None
    if os.path.getsize(name) == 0:
        raise InputError(f"cannot read surface file '{name}': the file is empty")
    if format in (None, "asc", "xyz", "matrix"):
        columns = _check_text_rows(name)
        if format is None and columns in (2, 3):
            raise ParameterError(
                "format",
                None,
                f"'asc' (a height matrix, one row per y) or 'xyz' (one x y [z] point per line) "
                f"for '{name}': a text file of {columns} values per line could be either",
            )
    if unit is not None:
        try:
            _unit_factor(unit)
        except KeyError:
            raise ParameterError("unit", unit, f"a length unit, one of {_length_units()}") from None
    try:
        reader = open_topography(name, format=format)
    except Exception as exc:  # SurfaceTopography raises several exception types here
        raise InputError(f"cannot read surface file '{name}': {_describe(exc)}") from None
    kwargs: dict[str, Any] = {}
    if channel is not None:
        last = len(reader.channels) - 1
        if not (0 <= channel <= last):
            raise ParameterError("channel", channel, f"0 to {last} for '{name}'")
        kwargs["channel_index"] = channel
    if unit is not None:
        kwargs["unit"] = unit
    if physical_sizes is not None:
        kwargs["physical_sizes"] = physical_sizes
    try:
        topography = reader.topography(**kwargs)
    except Exception as exc:
        text = _describe(exc)
        key = (
            "unit"
            if "unit" in text.lower()
            else "physical_sizes"
            if "size" in text.lower()
            else None
        )
        if key is not None:
            raise ParameterError(key, kwargs.get(key), f"accepted by '{name}' ({text})") from None
        raise InputError(f"cannot read surface file '{name}': {text}") from None
    prepared = prepare_topography(topography, periodicity=periodicity, detrend=detrend, **options)
    source = {
        "file": os.path.basename(name),
        "sha256": digest,
        "format": getattr(reader, "format", lambda: None)()
        if callable(getattr(reader, "format", None))
        else format,
        "channel": channel,
    }
    return PreparedSurface(prepared.surface, {**source, **prepared.info}, prepared.warnings)


#: Separators of the values on a row of a plain-text height matrix.
_TEXT_SEPARATORS = re.compile(r"[\s,;]+")


def _numeric_row(line: str) -> int:
    """Number of values on a row of numbers (0 if the line is not made of numbers only)."""
    tokens = [t for t in _TEXT_SEPARATORS.split(line.strip()) if t]
    try:
        for token in tokens:
            float(token)
    except ValueError:
        return 0
    return len(tokens)


def _check_text_rows(name: str) -> int:
    """Refuse a plain-text height matrix whose rows of numbers differ in length.

    Returns the number of values per row (0 for binary files and text without rows of
    numbers, which are left to the readers). Raises
    :class:`~frictionlab.errors.InputError` naming the first row of another length.
    """
    try:
        with open(name, "rb") as handle:
            head = handle.read(4096)
            if b"\0" in head:
                return 0
            raw = head + handle.read()
        text = raw.decode("utf-8")
    except (OSError, UnicodeDecodeError):
        return 0
    expected = 0
    for number, line in enumerate(text.splitlines(), start=1):
        count = _numeric_row(line)
        if count == 0:
            continue
        if expected == 0:
            expected = count
        elif count != expected:
            raise InputError(
                f"cannot read surface file '{name}': line {number} has {count} values, "
                f"expected {expected} (every row of a height matrix has the same length)"
            )
    return expected


def _describe(exc: Exception) -> str:
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0]}" if text else type(exc).__name__
