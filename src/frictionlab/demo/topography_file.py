"""The demo's measured-topography file: a ground surface written in ISO 25178-72 x3p.

The project ships ``frictionlab/data/topography/ground_demo.x3p`` (128 x 128 points over
0.5 x 0.5 mm, heights in um). It was written by :func:`write_ground_demo`, and
``python -m frictionlab.demo.topography_file PATH`` writes it again (the test suite checks
that the shipped file and a fresh one hold the same heights).

The surface imitates grinding: grooves running along y (a self-affine profile across
them, Hurst 0.8, rms slope 0.15, the same at every y up to a slow drift) on a weaker
isotropic self-affine background (rms slope 0.05), both from SurfaceTopography's
``fourier_synthesis`` with a fixed seed. Sliding across the grooves (beta = 0) meets
the steeper slopes. It is synthetic and says so in its metadata; it stands in for an
instrument file to exercise the whole path (x3p reader, units, preparation, filters).
"""

from __future__ import annotations

import sys
from importlib import resources
from pathlib import Path

import numpy as np

__all__ = ["GROUND_DEMO", "SEED", "ground_demo_heights_um", "ground_demo_path", "write_ground_demo"]

SEED = 2026
POINTS = 128
SIZE_UM = 500.0
GROUND_DEMO = "ground_demo.x3p"


def ground_demo_heights_um(seed: int = SEED) -> np.ndarray:
    """Heights (um), shape (128, 128), first axis x (across the grooves)."""
    from SurfaceTopography.Generation import fourier_synthesis

    rng = np.random.default_rng(seed)
    grooves = fourier_synthesis(
        (POINTS,), (SIZE_UM,), hurst=0.8, rms_slope=0.15, short_cutoff=4 * SIZE_UM / POINTS,
        rng=rng,
    ).heights()  # fmt: skip
    drift = fourier_synthesis(
        (POINTS,), (SIZE_UM,), hurst=0.8, rms_height=0.1, long_cutoff=SIZE_UM / 2, rng=rng
    ).heights()
    background = fourier_synthesis(
        (POINTS, POINTS), (SIZE_UM, SIZE_UM), hurst=0.8, rms_slope=0.05,
        short_cutoff=4 * SIZE_UM / POINTS, rng=rng,
    ).heights()  # fmt: skip
    return np.asarray(grooves[:, None] + drift[None, :] + background, dtype=np.float64)


def write_ground_demo(path: str | Path, seed: int = SEED) -> Path:
    """Write the demo topography as x3p (heights and sizes in um) and return the path."""
    from SurfaceTopography import Topography

    target = Path(path)
    Topography(
        ground_demo_heights_um(seed), (SIZE_UM, SIZE_UM), unit="um",
        info={"instrument": {"name": "synthetic ground surface (frictionlab demo)"}},
    ).to_x3p(str(target))  # fmt: skip
    return target


def ground_demo_path() -> Path:
    """The shipped file (inside the installed package)."""
    return Path(str(resources.files("frictionlab") / "data" / "topography" / GROUND_DEMO))


if __name__ == "__main__":  # pragma: no cover - a maintenance tool
    out = write_ground_demo(sys.argv[1] if len(sys.argv) > 1 else GROUND_DEMO)
    print(f"wrote {out} ({out.stat().st_size} bytes)")
