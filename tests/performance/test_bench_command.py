"""``frictionlab bench --json``: every figure present, from one process (no timing asserted)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from frictionlab.benchmark import coulomb_return, coulomb_update
from frictionlab.cli import main
from frictionlab.subloading import SubloadingParams, initial_state


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
        "law_over_coulomb_like_for_like",
        "law_over_coulomb_like_for_like_threads",
        "coulomb_like_for_like_us_per_point",
        "parallel_gain",
    ):
        assert np.isfinite(law[key]) and law[key] > 0.0
    met = law["law_over_coulomb_like_for_like"] <= law["target_law_over_coulomb_like_for_like"]
    assert law["law_over_coulomb_like_for_like_target_met"] is met
    assert "speedup_over_python" not in law  # the interpreted-loop figure is retired
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


def test_like_for_like_baseline_is_the_coulomb_return_with_its_tangent() -> None:
    """Closed forms: a sliding point returned to the cone with the radial-return tangent
    (checked against central differences of the return itself), a sticking point elastic."""
    params = SubloadingParams(surface="coulomb", mu_s=0.3, mu_k=0.3, alpha_t=1e3, alpha_n=1e3)
    state = initial_state(params, normal_traction=np.array([1.0, 1.0]))
    du = np.array([[1e-3, 5e-4, 1e-4], [1e-5, 0.0, 0.0]])
    out = coulomb_update(state, du, 0.01, params._kernel_table)
    ft = 1e3 * du[0, :2]
    fn = 1.0 + 0.1
    n = ft / np.linalg.norm(ft)
    np.testing.assert_allclose(out["traction"][0], [*(0.3 * fn * n), fn], rtol=1e-14)
    np.testing.assert_allclose(out["dlam"][0], (np.linalg.norm(ft) - 0.3 * fn) / 1e3, rtol=1e-13)
    assert list(out["status"]) == [1, 0]
    np.testing.assert_allclose(out["traction"][1], [1e-2, 0.0, 1.0], rtol=1e-14)
    np.testing.assert_allclose(out["tangent"][1], np.diag([1e3, 1e3, 1e3]), rtol=1e-15)
    h = 1e-8
    for j in range(3):
        plus, minus = du[:1].copy(), du[:1].copy()
        plus[0, j] += h
        minus[0, j] -= h
        fp = coulomb_update(state.take([0]), plus, 0.01, params._kernel_table)["traction"][0]
        fm = coulomb_update(state.take([0]), minus, 0.01, params._kernel_table)["traction"][0]
        np.testing.assert_allclose(out["tangent"][0][:, j], (fp - fm) / (2 * h), rtol=1e-6,
                                   atol=1e-6)  # fmt: skip
