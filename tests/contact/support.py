"""Shared small configurations of the contact tests (physical scales, small meshes)."""

from __future__ import annotations

from frictionlab.contact import Block, Hold, NormalLoad, Slide
from frictionlab.subloading import SubloadingParams

PRESSURE = 1.0e6  # Pa


def pmma_block(element_size: float = 0.0125, nu: float = 0.35, E: float = 3.0e9) -> Block:
    """A PMMA-like block, 100 mm x 25 mm."""
    return Block(E=E, nu=nu, width=0.1, height=0.025, element_size=element_size)


def law(**changes: float) -> SubloadingParams:
    """A cone law with a static peak, softening over ~10 um and recovery over ~10 s."""
    values = dict(alpha_n=5e11, alpha_t=5e11, mu_s=0.6, mu_k=0.4, u=2e6, kappa=1e5, xi=0.05)
    values.update(changes)
    return SubloadingParams(**values)  # type: ignore[arg-type]


NORMAL = NormalLoad(pressure=PRESSURE, duration=1.0, steps=2)
SLIDE = [Slide(velocity=1e-5, distance=30e-6, steps=15)]
SLIDE_HOLD_SLIDE = [
    *SLIDE,
    Hold(duration=10.0, steps=2),
    Slide(velocity=1e-5, distance=10e-6, steps=5),
]
