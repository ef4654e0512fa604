"""The elastic block of the contact model: geometry, material and mesh density.

A 2-D plane-strain, linear-elastic rectangle ``[0, width] x [0, height]`` resting on a
rigid base along its bottom edge ``y = 0``. Sliding is along +x; the trailing edge is
``x = 0`` and the leading edge ``x = width``. Units (SI): E [Pa], lengths [m].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from frictionlab.errors import ParameterError

__all__ = ["ELEMENTS", "Block"]

#: Element families: bilinear quadrilaterals or linear triangles (scikit-fem).
ELEMENTS: tuple[str, ...] = ("quad", "triangle")


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
        ``"quad"`` (bilinear, default) or ``"triangle"`` (linear, two per cell).
    """

    E: float
    nu: float
    width: float
    height: float
    element_size: float
    element: str = "quad"

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
        nx, ny = self.cells
        if (nx + 1) * (ny + 1) > 2_000_000:
            raise ParameterError(
                "element_size",
                self.element_size,
                f"a mesh of at most 2e6 nodes (this one would have {nx} x {ny} cells)",
            )

    @property
    def cells(self) -> tuple[int, int]:
        """Number of cells (n_x, n_y) along the width and the height."""
        nx = max(1, round(self.width / self.element_size))
        ny = max(1, round(self.height / self.element_size))
        return nx, ny

    @property
    def lame(self) -> tuple[float, float]:
        """Lamé constants (lambda, mu) [Pa]; in plane strain they are the 3-D ones."""
        lam = self.E * self.nu / ((1.0 + self.nu) * (1.0 - 2.0 * self.nu))
        mu = self.E / (2.0 * (1.0 + self.nu))
        return lam, mu


def _finite(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)
