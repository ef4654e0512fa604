"""The elastic block of the contact model: geometry, material and mesh density.

2-D (default): a plane-strain, linear-elastic rectangle ``[0, width] x [0, height]``
resting on a rigid base along its bottom edge ``y = 0``. 3-D (``depth`` given): a box
``[0, width] x [0, depth] x [0, height]`` of trilinear hexahedra resting on the plane
``z = 0``. Sliding is along +x by default; the trailing edge is ``x = 0`` and the
leading edge ``x = width``. Units (SI): E [Pa], lengths [m].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from frictionlab.errors import ParameterError

__all__ = ["ELEMENTS", "INTEGRATIONS", "Block", "Refinement", "graded_axis"]

#: Element families: bilinear quadrilaterals or linear triangles (2-D, scikit-fem),
#: trilinear hexahedra (3-D).
ELEMENTS: tuple[str, ...] = ("quad", "triangle", "hex")
#: Volume integration: full (2 x 2 Gauss) or selective (the volumetric part with one
#: point: no volumetric locking of quads and hexahedra as nu -> 0.5).
INTEGRATIONS: tuple[str, ...] = ("full", "selective")


@dataclass(frozen=True)
class Refinement:
    """A graded mesh: elements of ``size`` [m] in a window around the contact.

    The window spans ``center +- extent`` along each in-plane axis (x, or x and y) and
    ``[0, extent]`` above the base; outside it the element size grows by ``growth`` per
    element up to the block's ``element_size``. Tensor-product grading: the fine
    columns run through the whole block.

    Attributes
    ----------
    size:
        Element size in the window [m] > 0 (at most the block's element_size).
    extent:
        Half-width of the window and its height [m] > 0.
    center:
        In-plane centre of the window [m] (x, or (x, y) in 3-D); None: the middle of
        the bottom face.
    growth:
        Ratio of neighbouring element sizes outside the window, 1 < growth <= 2.
    """

    size: float
    extent: float
    center: tuple[float, ...] | None = None
    growth: float = 1.2

    def __post_init__(self) -> None:
        for name in ("size", "extent"):
            value = getattr(self, name)
            if not _finite(value) or value <= 0:
                raise ParameterError(f"refinement.{name}", value, f"a finite {name} > 0 [m]")
            object.__setattr__(self, name, float(value))
        if not _finite(self.growth) or not (1.0 < self.growth <= 2.0):
            raise ParameterError("refinement.growth", self.growth, "1 < growth <= 2")
        if self.center is not None:
            center = tuple(np.atleast_1d(np.asarray(self.center, dtype=np.float64)).tolist())
            if not all(math.isfinite(c) for c in center):
                raise ParameterError("refinement.center", self.center, "finite coordinates [m]")
            object.__setattr__(self, "center", center)


@dataclass(frozen=True)
class Block:
    """Plane-strain elastic block on a rigid base.

    Attributes
    ----------
    E:
        Young's modulus [Pa] > 0.
    nu:
        Poisson's ratio, 0 <= nu < 0.5.
    width, height:
        Size of the block [m] > 0 (x along the sliding direction, y normal to the base).
    element_size:
        Target edge length of the elements [m]; the mesh has ``round(width/h)`` by
        ``round(height/h)`` cells (at least 1 each).
    element:
        ``"quad"`` (bilinear, default) or ``"triangle"`` (linear, two per cell) in 2-D;
        ``"hex"`` (trilinear) in 3-D.
    depth:
        Size along y [m] of a 3-D block (None, the default: a 2-D plane-strain block).
    integration:
        ``"full"`` (default) or ``"selective"`` (one-point volumetric part; use it for
        nearly incompressible blocks, nu -> 0.5; quads and hexahedra only).
    refinement:
        A graded mesh around the contact (:class:`Refinement`); None: uniform.
    """

    E: float
    nu: float
    width: float
    height: float
    element_size: float
    element: str = "quad"
    depth: float | None = None
    integration: str = "full"
    refinement: Refinement | None = None

    def __post_init__(self) -> None:
        for name in ("E", "width", "height", "element_size"):
            value = getattr(self, name)
            if not _finite(value) or value <= 0:
                raise ParameterError(name, value, f"a finite {name} > 0")
            object.__setattr__(self, name, float(value))
        if not _finite(self.nu) or not (0.0 <= self.nu < 0.5):
            raise ParameterError("nu", self.nu, "0 <= nu < 0.5")
        object.__setattr__(self, "nu", float(self.nu))
        if self.element not in ELEMENTS:
            raise ParameterError("element", self.element, "one of " + ", ".join(ELEMENTS))
        if self.depth is not None:
            if not _finite(self.depth) or self.depth <= 0:
                raise ParameterError("depth", self.depth, "a finite depth > 0 (3-D block)")
            object.__setattr__(self, "depth", float(self.depth))
        if (self.element == "hex") != (self.depth is not None):
            raise ParameterError(
                "element",
                self.element,
                "'hex' for a 3-D block (depth given), else quad or triangle",
            )
        if self.integration not in INTEGRATIONS:
            raise ParameterError(
                "integration", self.integration, "one of " + ", ".join(INTEGRATIONS)
            )
        if self.integration == "selective" and self.element == "triangle":
            raise ParameterError(
                "integration", "selective", "'full' for triangles (quads or hex for selective)"
            )
        if self.refinement is not None:
            ref = self.refinement
            if ref.size > self.element_size:
                raise ParameterError(
                    "refinement.size", ref.size, f"<= element_size (= {self.element_size:g} m)"
                )
            if ref.center is not None and len(ref.center) != self.dim - 1:
                raise ParameterError(
                    "refinement.center", ref.center, f"{self.dim - 1} in-plane coordinate(s)"
                )
        if int(np.prod([c + 1 for c in self.cells])) > 2_000_000:
            shape = " x ".join(str(c) for c in self.cells)
            raise ParameterError(
                "element_size",
                self.element_size,
                f"a mesh of at most 2e6 nodes (this one would have {shape} cells)",
            )

    @property
    def dim(self) -> int:
        """2 (plane strain) or 3."""
        return 2 if self.depth is None else 3

    @property
    def sizes(self) -> tuple[float, ...]:
        """Extent along each axis [m]: (width, height) or (width, depth, height)."""
        if self.depth is None:
            return (self.width, self.height)
        return (self.width, self.depth, self.height)

    @property
    def cells(self) -> tuple[int, ...]:
        """Number of cells along the width and the height (2-D), or width, depth, height."""
        return tuple(len(a) - 1 for a in self.axes())

    def axes(self) -> list[np.ndarray]:
        """Node coordinates [m] along each axis (uniform, or graded by the refinement)."""
        h = self.element_size
        ref = self.refinement
        if ref is None:
            return [np.linspace(0.0, L, max(1, round(L / h)) + 1) for L in self.sizes]
        center = ref.center or tuple(L / 2.0 for L in self.sizes[:-1])
        out = [
            graded_axis(L, c, ref.extent, ref.size, h, ref.growth)
            for L, c in zip(self.sizes[:-1], center, strict=True)
        ]
        out.append(graded_axis(self.sizes[-1], 0.0, ref.extent, ref.size, h, ref.growth))
        return out

    @property
    def lame(self) -> tuple[float, float]:
        """Lamé constants (lambda, mu) [Pa]; in plane strain they are the 3-D ones."""
        lam = self.E * self.nu / ((1.0 + self.nu) * (1.0 - 2.0 * self.nu))
        mu = self.E / (2.0 * (1.0 + self.nu))
        return lam, mu


def graded_axis(
    length: float, center: float, extent: float, fine: float, coarse: float, growth: float
) -> np.ndarray:
    """Nodes on ``[0, length]``: spacing ``fine`` on ``center +- extent``, growing by
    ``growth`` per element outside, capped at ``coarse``."""
    lo, hi = max(0.0, center - extent), min(length, center + extent)
    if hi <= lo:  # the window is outside the block
        return np.linspace(0.0, length, max(1, round(length / coarse)) + 1)
    n_fine = max(1, round((hi - lo) / fine))
    core = np.linspace(lo, hi, n_fine + 1)
    step = (hi - lo) / n_fine
    right = _grow(length - hi, step, coarse, growth)
    left = _grow(lo, step, coarse, growth)
    return np.unique(np.concatenate([lo - left, core, hi + right]))


def _grow(span: float, start: float, cap: float, growth: float) -> np.ndarray:
    """Offsets (excluding 0) of nodes covering ``span`` with sizes growing from ``start``."""
    if span <= 1e-12 * max(cap, 1.0):
        return np.zeros(0)
    offsets, pos, h = [], 0.0, start
    while pos < span:
        h = min(h * growth, cap)
        pos += h
        offsets.append(pos)
    offsets_arr = np.asarray(offsets)
    if offsets_arr.size > 1 and span - offsets_arr[-2] < 0.5 * h:
        offsets_arr = offsets_arr[:-1]  # merge a thin last cell into its neighbour
    offsets_arr = offsets_arr * (span / offsets_arr[-1])
    offsets_arr[-1] = span
    return offsets_arr


def _finite(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)
