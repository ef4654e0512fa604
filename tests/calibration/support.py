"""A small slide-hold-slide case at tribometer scales, and its data written as a lab export."""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np

from frictionlab.calibration import Curve
from frictionlab.driver import Hold, InitialConditions, Slide, simulate
from frictionlab.io.config import format_toml
from frictionlab.subloading import SubloadingParams

#: The true law: mu_s, mu_k [-], u, kappa [1/m], xi [1/s], alpha [Pa/m]; f_n = 1 MPa.
TRUE = dict(mu_s=0.5, mu_k=0.3, u=2.0e4, kappa=3000.0, xi=5.0e-3, alpha_n=5e11, alpha_t=5e11)
FN = 1.0e6
V = 1.0e-4  # 0.1 mm/s
PROGRAM_TABLES = [
    {"kind": "slide", "velocity": V, "distance": 6e-4, "max_step": 1e-5},
    {"kind": "hold", "duration": 30.0},
    {"kind": "slide", "velocity": V, "distance": 2e-4, "max_step": 1e-5},
    {"kind": "hold", "duration": 300.0},
    {"kind": "slide", "velocity": V, "distance": 2e-4, "max_step": 1e-5},
]
PROGRAM = (
    Slide(velocity=V, distance=6e-4, max_step=1e-5),
    Hold(duration=30.0),
    Slide(velocity=V, distance=2e-4, max_step=1e-5),
    Hold(duration=300.0),
    Slide(velocity=V, distance=2e-4, max_step=1e-5),
)
DURATION = 6.0 + 30.0 + 2.0 + 300.0 + 2.0  # s
RATE_HZ = 10.0


def true_params(**changes: float) -> SubloadingParams:
    return SubloadingParams(**{**TRUE, **changes})  # type: ignore[arg-type]


def make_curve(noise: float = 0.0, seed: int = 0, **changes: float) -> Curve:
    """The law's friction ratio at 10 Hz plus Gaussian noise of standard deviation ``noise``."""
    init = InitialConditions(normal_traction=FN)
    h = simulate(true_params(**changes), PROGRAM, init)
    assert h.success
    t = np.linspace(0.0, DURATION, int(DURATION * RATE_HZ) + 1)
    clean = np.interp(t, h.time[:, 0], h.friction_ratio[:, 0])
    rng = np.random.default_rng(seed)
    ratio = np.abs(clean + noise * rng.standard_normal(t.size))
    slip = np.interp(t, h.time[:, 0], h.slip[:, 0, 0])
    return Curve("synthetic", t, ratio, PROGRAM, init, slip=slip)


def write_export(path: Path, curve: Curve) -> Path:
    """The curve as a lab export: comments, index column, units row, min and mm, lab names."""
    lines = ["# TR-2 export", "# synthetic", ",Time,Displacement,COF", ",min,mm,-"]
    assert curve.slip is not None
    for i, (t, s, r) in enumerate(zip(curve.time, curve.slip, curve.friction_ratio, strict=True)):
        lines.append(f"{i},{float(t) / 60.0!r},{float(s) * 1e3!r},{float(r)!r}")
    path.write_text("\n".join(lines) + "\n")
    return path


def config(data_file: str, parameters: list[str], start: dict[str, float], **fit: object) -> dict:
    law = {"surface": "coulomb", **TRUE, **start}
    return {
        "title": "test calibration",
        "law": law,
        "fit": {"parameters": parameters, **fit},
        "data": [
            {
                "file": data_file,
                "columns": {"time": "Time", "slip": "Displacement", "friction_ratio": "COF"},
                "units": {"time": "min", "slip": "mm"},
                "initial": {"normal_traction": FN},
                "program": copy.deepcopy(PROGRAM_TABLES),
            }
        ],
    }


def write_config(path: Path, data: dict) -> Path:
    path.write_text(format_toml(data))
    return path
