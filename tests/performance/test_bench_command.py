"""``frictionlab bench --json``: every figure present, from one process (no timing asserted)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from frictionlab.benchmark import coulomb_return
from frictionlab.cli import main


@pytest.mark.slow
def test_bench_writes_every_figure(tmp_path: Path) -> None:
    path = tmp_path / "bench.json"
    args = ["bench", "--points", "400", "--lattice-size", "16", "--no-first-call"]
    assert main([*args, "--json", str(path)]) == 0
    data = json.loads(path.read_text())
    assert data["machine"]["cpu_count"] >= 1
    law = data["law"]
    assert law["fraction_sliding"] == 1.0 and law["timings"]["update"]["runs"] >= 5
    for key in (
        "law_over_coulomb",
        "floor_over_coulomb",
        "python_loop_over_floor",
        "speedup_over_python",
        "speedup_over_update_loop",
        "parallel_gain",
    ):
        assert np.isfinite(law[key]) and law[key] > 0.0
    assert data["lattice_partial"]["springs_per_second"] > 0.0
    driver = data["driver_overhead"]
    assert driver["points"] == 400
    for mode in ("in_memory", "streamed"):
        assert 0.0 < driver[mode]["outside_kernel_fraction"] < 1.0
    assert main([*args, "--repeats", "3"]) == 2  # fewer than 5 runs is refused


def test_coulomb_baseline_is_the_radial_return() -> None:
    traction = np.array([[0.1, 0.0, 1.0], [0.0, 0.0, 1.0]])
    du = np.array([[1e-3, 0.0, 0.0], [0.0, 1e-4, 0.0]])
    out, dlam = np.empty((2, 3)), np.empty(2)
    coulomb_return(traction, du, 1000.0, 1000.0, 0.3, out, dlam)
    np.testing.assert_allclose(out, [[0.3, 0.0, 1.0], [0.0, 0.1, 1.0]], rtol=1e-15)
    np.testing.assert_allclose(dlam, [(1.1 - 0.3) / 1000.0, 0.0], rtol=1e-15)
