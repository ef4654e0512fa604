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

__all__ = ["ELEMENTS", "Block"]

#: Element families: bilinear quadrilaterals or linear triangles (2-D, scikit-fem),
#: trilinear hexahedra (3-D).
ELEMENTS: tuple[str, ...] = ("quad", "triangle", "hex")


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
    """

    E: float
    nu: float
    width: float
    height: float
    element_size: float
    element: str = "quad"
    depth: float | None = None

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
    def cells(self) -> tuple[int, ...]:
        """Number of cells along the width and the height (2-D), or width, depth, height."""
        h = self.element_size
        sizes = (
            (self.width, self.height)
            if self.depth is None
            else (self.width, self.depth, self.height)
        )
        return tuple(max(1, round(L / h)) for L in sizes)

    @property
    def lame(self) -> tuple[float, float]:
        """Lamé constants (lambda, mu) [Pa]; in plane strain they are the 3-D ones."""
        lam = self.E * self.nu / ((1.0 + self.nu) * (1.0 - 2.0 * self.nu))
        mu = self.E / (2.0 * (1.0 + self.nu))
        return lam, mu


def _finite(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)
