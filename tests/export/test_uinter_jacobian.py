"""UINTER's DDSDDR against central differences of UINTER itself, and its failure path.

The Jacobian is differentiated numerically through the Fortran harness: central
differences at steps h and h/2, combined by Richardson extrapolation (error O(h^4)),
at sliding, sticking and re-closing points of recorded runs, for the cone and the closed
surfaces with rotation and orthotropy. A failed local solve must keep the state, return
the elastic stiffness and ask for a quarter of the increment, which then succeeds.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frictionlab.app.simulate import run_scenario
from frictionlab.io.scenario import load_scenario
from frictionlab.subloading import kernels

from .support import build_uinter_harness, recorded_calls, records, run_uinter
from .test_uinter_harness import CLOSED, CONE, RECLOSING

ORDER = [2, 0, 1]  # law index of the Abaqus local components


def _sample(surface: str, tmp_path: Path, rng: np.random.Generator) -> np.ndarray:
    """Records of sliding, sticking and re-closing points of a recorded run."""
    cone = surface == "coulomb"
    path = tmp_path / f"{surface}.toml"
    path.write_text(RECLOSING.format(surface=surface, sizes=CONE if cone else CLOSED,
                                     fn=1.0e6 if cone else 3.0e5))  # fmt: skip
    scenario = load_scenario(path)
    with recorded_calls() as calls:
        run_scenario(scenario)
    recs = records(calls, scenario.params)
    status = np.concatenate([c["out_status"] for c in calls])
    reclosing = np.concatenate([(c["gap"] > 0.0) for c in calls]) & (status != kernels.OPEN)
    picks = []
    for mask, count in ((status == kernels.SLIP, 12), (status == kernels.STICK, 4),
                        (reclosing, 8)):  # fmt: skip
        idx = np.flatnonzero(mask)
        assert idx.size, "the programme must exercise every kind of point"
        picks.append(rng.choice(idx, size=min(count, idx.size), replace=False))
    return recs[np.concatenate(picks)]


@pytest.mark.parametrize("surface", ["coulomb", "cam_clay", "tear"])
def test_uinter_jacobian_matches_richardson_central_differences(
    surface: str, build_dir: Path, fortran: str, tmp_path: Path
) -> None:
    exe = build_uinter_harness(build_dir, fortran)
    base = _sample(surface, tmp_path, np.random.default_rng(7))
    du = base[:, 37:40]
    # step per point: small against its increment (or, at rest, against f_n/alpha_n)
    h = 1e-3 * np.maximum(np.linalg.norm(du, axis=1), 1e-3 * base[:, 23] / base[:, 1])
    assert np.all(h > 0.0)
    batch = [base]
    for scale in (1.0, 0.5):
        for j in range(3):
            for sign in (1.0, -1.0):
                rec = base.copy()
                rec[:, 37 + j] += sign * scale * h
                batch.append(rec)
    out = run_uinter(exe, np.concatenate(batch), tmp_path).reshape(len(batch), len(base), -1)
    status = out[:, :, 7]
    smooth = np.all(status == status[0], axis=0)  # no stick/slip switch within the steps
    assert smooth.sum() >= 0.5 * len(base)
    worst = 0.0
    for i in np.flatnonzero(smooth):
        J = out[0, i, 11:20].reshape(3, 3, order="F")
        fd = np.empty((3, 3))
        for j in range(3):
            k = 1 + 2 * j
            d_h = (out[k, i, :3] - out[k + 1, i, :3]) / (2.0 * h[i])
            d_h2 = (out[6 + k, i, :3] - out[6 + k + 1, i, :3]) / h[i]
            fd[:, j] = (4.0 * d_h2 - d_h) / 3.0
        err = np.abs(fd - J).max() / np.abs(J).max()
        assert np.isfinite(err)
        worst = max(worst, err)
    reclosings = int(smooth[-8:].sum())  # the last picks are re-closing points
    print(f"{surface}: {smooth.sum()} points ({reclosings} re-closing), worst {worst:.3g}")
    assert reclosings >= 2
    assert worst <= 1e-6, f"worst relative error {worst:.3g}"


def test_a_failed_local_solve_asks_for_a_quarter_step(
    build_dir: Path, fortran: str, tmp_path: Path
) -> None:
    """A closed surface loaded normally past its size: the full step fails, a quarter passes."""
    exe = build_uinter_harness(build_dir, fortran)
    alpha = 1.0e12
    F = 1.0e6
    rec = np.zeros(41)
    rec[0] = 3.0
    # modified Cam-clay, F = F_s = F_k (no softening), props as uinter.c reads them
    rec[1:15] = [alpha, alpha, F, F, 1e5, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.5, 0.5, 0.0]
    rec[15:23] = [2, 1.0, 0, 0, 0, 0, F, 0.0]
    fn = 0.9 * F
    rec[23:26] = [fn, 0.0, 0.0]
    rec[26:34] = [F, fn / F, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]  # R = f_n g(0)/F
    rec[37:40] = [0.3 * F / alpha, 1e-9, 0.0]  # f_n -> 1.2 F: outside the surface
    rec[40] = 1.0
    quarter = rec.copy()
    quarter[37:41] *= 0.25
    out = run_uinter(exe, np.stack([rec, quarter]), tmp_path)
    full, part = out
    assert full[20] == 0.25  # PNEWDT
    np.testing.assert_array_equal(full[:3], rec[23:26])  # STRESS kept
    np.testing.assert_array_equal(full[3:11], rec[26:34])  # STATEV kept
    np.testing.assert_array_equal(full[11:20], np.diag([alpha, alpha, alpha]).ravel("F"))
    assert np.all(np.isfinite(full))
    assert part[20] == 1.0 and part[7] in (kernels.STICK, kernels.SLIP)
    assert part[0] == pytest.approx(fn + 0.25 * 0.3 * F, rel=1e-12)
