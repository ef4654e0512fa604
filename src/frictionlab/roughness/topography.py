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
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np

from frictionlab.errors import InputError, ParameterError
from frictionlab.roughness.generators import from_array
from frictionlab.roughness.surface import SampledHeightMap, SampledProfile

__all__ = ["DETREND_MODES", "PERIODICITY_MODES", "from_topography", "read_surface"]

PERIODICITY_MODES = ("require", "assume", "mirror")
DETREND_MODES = ("none", "center", "height", "curvature")


def from_topography(
    topography: Any,
    *,
    periodicity: str,
    detrend: str,
    fill_missing: bool = False,
    gradient: str = "fd",
) -> SampledProfile | SampledHeightMap:
    """Convert a SurfaceTopography line scan or topography to a frictionlab surface (SI).

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
    """
    if periodicity not in PERIODICITY_MODES:
        raise ParameterError("periodicity", periodicity, f"one of {PERIODICITY_MODES}")
    if detrend not in DETREND_MODES:
        raise ParameterError("detrend", detrend, f"one of {DETREND_MODES}")
    if not hasattr(topography, "heights") or not hasattr(topography, "physical_sizes"):
        raise ParameterError("topography", type(topography).__name__, "a SurfaceTopography object")
    if not getattr(topography, "is_uniform", False):
        raise ParameterError(
            "topography", "non-uniform line scan", "uniformly sampled data (resample it first)"
        )
    if topography.dim not in (1, 2):
        raise ParameterError("topography.dim", topography.dim, "1 (line scan) or 2 (topography)")
    if periodicity == "require":
        if not topography.is_periodic:
            raise ParameterError(
                "periodicity",
                "require",
                "a topography that declares itself periodic; this one does not: choose "
                "periodicity='assume' (use the data as one period) or 'mirror'",
            )
        if detrend in ("height", "curvature"):
            raise ParameterError(
                "detrend",
                detrend,
                "'none' or 'center' for a periodic topography (removing a tilt breaks periodicity)",
            )
    if topography.unit is None:
        raise ParameterError("unit", None, "a length unit on the topography (e.g. 'um')")
    if topography.has_undefined_data:
        n_bad = int(np.count_nonzero(np.ma.getmaskarray(topography.heights())))
        if not fill_missing:
            raise ParameterError(
                "heights",
                f"{n_bad} undefined (NaN) values",
                "complete data; pass fill_missing=True to fill them by harmonic interpolation",
            )
        topography = topography.interpolate_undefined_data()
    if detrend != "none":
        topography = topography.detrend(detrend_mode=detrend)
    try:
        topography = topography.to_unit("m")
    except (KeyError, ValueError) as exc:
        raise ParameterError("unit", topography.unit, f"a known length unit ({exc})") from None
    heights = np.array(np.ma.getdata(topography.heights()), dtype=np.float64)
    sizes = [float(s) for s in np.ravel(topography.physical_sizes)]
    if periodicity == "mirror":
        for axis in range(heights.ndim):
            heights = np.concatenate([heights, np.flip(heights, axis=axis)], axis=axis)
            sizes[axis] *= 2.0
    return from_array(heights, sizes if heights.ndim == 2 else sizes[0], gradient=gradient)


def read_surface(
    path: str | os.PathLike[str],
    *,
    periodicity: str,
    detrend: str,
    fill_missing: bool = False,
    gradient: str = "fd",
    format: str | None = None,
    channel: int | None = None,
    unit: str | None = None,
    physical_sizes: float | tuple[float, ...] | None = None,
) -> SampledProfile | SampledHeightMap:
    """Read a measured surface file with SurfaceTopography and convert it (file I/O here only).

    ``format`` forces a reader (SurfaceTopography format id such as ``"x3p"``); ``channel``
    selects a data channel (default: the file's default channel); ``unit`` and
    ``physical_sizes`` supply metadata the file lacks (an error if the file has them).
    The other arguments are those of :func:`from_topography`. Unreadable, unknown or
    corrupt files raise :class:`~frictionlab.errors.InputError`.
    """
    from SurfaceTopography import open_topography

    name = os.fspath(path)
    try:
        reader = open_topography(name, format=format)
    except FileNotFoundError:
        raise InputError(f"cannot read surface file '{name}': no such file") from None
    except Exception as exc:  # SurfaceTopography raises several exception types here
        raise InputError(f"cannot read surface file '{name}': {_describe(exc)}") from None
    kwargs: dict[str, Any] = {}
    if channel is not None:
        last = len(reader.channels) - 1
        if not (0 <= channel <= last):
            raise InputError(f"channel = {channel} is invalid for '{name}': allowed 0 to {last}")
        kwargs["channel_index"] = channel
    if unit is not None:
        kwargs["unit"] = unit
    if physical_sizes is not None:
        kwargs["physical_sizes"] = physical_sizes
    try:
        topography = reader.topography(**kwargs)
    except Exception as exc:
        raise InputError(f"cannot read surface file '{name}': {_describe(exc)}") from None
    try:
        return from_topography(
            topography,
            periodicity=periodicity,
            detrend=detrend,
            fill_missing=fill_missing,
            gradient=gradient,
        )
    except ParameterError as exc:
        raise InputError(f"surface file '{name}': {exc}") from None


def _describe(exc: Exception) -> str:
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0]}" if text else type(exc).__name__
