"""The rigid counter-surface (base) under the block: flat, a cylinder, a sphere or a profile.

The base's shape enters as the law's initial normal gap ``g_0`` [m] at every contact
point (:attr:`ContactState.gap`, opened before loading): the block's flat bottom face
touches the base where ``g_0 = 0`` and must approach by ``g_0`` elsewhere before it
closes. The gap is shifted so that its smallest value over the contact points is zero
(the base just touches the nearest point; nothing is pre-loaded).

* ``flat`` — ``g_0 = 0`` everywhere (the default).
* ``cylinder`` (2-D) — a rigid cylinder of ``radius`` R [m], axis along z, at
  ``center``: ``g_0 = R - sqrt(R^2 - (x - x_c)^2)`` (the exact circle; Hertz's
  parabola ``(x - x_c)^2/(2R)`` to O((x - x_c)^4/R^3)).
* ``sphere`` (3-D) — the same with ``r = |(x, y) - center|``.
* ``profile`` — heights ``z(x)`` [m] of the base (2-D) given as ``(x, z)`` samples,
  linearly interpolated: ``g_0 = max z - z(x)``.

Points beyond the rim (``|x - x_c| >= R``) get the gap R (they never touch).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from frictionlab.errors import ParameterError

__all__ = ["SHAPES", "Base"]

#: Counter-surface shapes.
SHAPES: tuple[str, ...] = ("flat", "cylinder", "sphere", "profile")


@dataclass(frozen=True)
class Base:
    """The rigid base's shape.

    Attributes
    ----------
    shape:
        One of :data:`SHAPES`.
    radius:
        Radius R [m] > 0 of a cylinder or sphere.
    center:
        In-plane position of its apex [m]: x (2-D) or (x, y) (3-D); None: the middle of
        the block's bottom face.
    profile:
        ``(x, z)`` arrays [m] of a profile base (2-D), x strictly increasing.
    """

    shape: str = "flat"
    radius: float | None = None
    center: tuple[float, ...] | None = None
    profile: tuple[Any, Any] | None = None

    def __post_init__(self) -> None:
        if self.shape not in SHAPES:
            raise ParameterError("shape", self.shape, "one of " + ", ".join(SHAPES))
        curved = self.shape in ("cylinder", "sphere")
        if curved:
            r = self.radius
            if isinstance(r, bool) or not isinstance(r, int | float) or not math.isfinite(r):
                raise ParameterError("radius", r, f"a finite radius > 0 [m] for a {self.shape}")
            if r <= 0:
                raise ParameterError("radius", r, "radius > 0 [m]")
            object.__setattr__(self, "radius", float(r))
        elif self.radius is not None:
            raise ParameterError("radius", self.radius, f"unset for shape '{self.shape}'")
        if self.center is not None:
            center = tuple(float(c) for c in np.atleast_1d(np.asarray(self.center, float)))
            if not all(math.isfinite(c) for c in center):
                raise ParameterError("center", self.center, "finite coordinates [m]")
            object.__setattr__(self, "center", center)
        if self.shape == "profile":
            if self.profile is None:
                raise ParameterError("profile", None, "(x, z) samples for shape 'profile'")
            x, z = (np.array(a, dtype=np.float64) for a in self.profile)
            if x.ndim != 1 or x.shape != z.shape or x.size < 2:
                raise ParameterError("profile", x.shape, "two equal 1-D arrays of >= 2 samples")
            if not (np.all(np.isfinite(x)) and np.all(np.isfinite(z))):
                raise ParameterError("profile", "non-finite values", "finite x and z [m]")
            if not np.all(np.diff(x) > 0):
                raise ParameterError("profile", "x not increasing", "strictly increasing x")
            x.setflags(write=False)
            z.setflags(write=False)
            object.__setattr__(self, "profile", (x, z))
        elif self.profile is not None:
            raise ParameterError("profile", "given", f"unset for shape '{self.shape}'")

    def check_dim(self, dim: int) -> None:
        """Refuse a shape that does not fit a ``dim``-dimensional block."""
        if self.shape == "cylinder" and dim != 2:
            raise ParameterError("shape", "cylinder", "'sphere' for a 3-D block")
        if self.shape in ("sphere", "profile") and dim != (3 if self.shape == "sphere" else 2):
            want = "a 3-D block (depth given)" if self.shape == "sphere" else "a 2-D block"
            raise ParameterError("shape", self.shape, want)
        if self.center is not None and len(self.center) != dim - 1:
            raise ParameterError("center", self.center, f"{dim - 1} in-plane coordinate(s) [m]")

    def gap(self, xy: np.ndarray, middle: np.ndarray) -> np.ndarray:
        """Initial gap [m] at in-plane points ``xy`` (P, d - 1); ``middle`` is the centre
        of the bottom face (the default apex). Shifted to a minimum of zero."""
        xy = np.asarray(xy, dtype=np.float64)
        if self.shape == "flat":
            return np.zeros(xy.shape[0])
        if self.shape == "profile":
            x, z = self.profile  # type: ignore[misc]
            heights = np.interp(xy[:, 0], x, z)
            g = float(np.max(z)) - heights
        else:
            center = np.asarray(self.center if self.center is not None else middle, float)
            r2 = np.sum((xy - center[None, :]) ** 2, axis=1)
            R = float(self.radius)  # type: ignore[arg-type]
            g = np.where(r2 < R * R, R - np.sqrt(np.maximum(R * R - r2, 0.0)), R)
        return g - float(np.min(g))
