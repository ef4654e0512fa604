"""Size estimates made before a run: one line naming the key, from the sizes alone.

The figures are checked against hand counts of what the code allocates (dense arrays of
known shapes), and the refusals against the machine size passed in explicitly.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

from frictionlab.app import budget
from frictionlab.contact.linear import cost
from frictionlab.errors import InputError, ParameterError
from frictionlab.subloading import SubloadingParams, check_normal_capacity, check_snap_back
from frictionlab.subloading.surfaces import g_function
from frictionlab.sweep.cases import MAX_CASES, check_case_count, expand_grid

GB = 10**9


def test_contact_estimate_is_the_solvers_own_and_grows_with_the_3d_fill() -> None:
    """One estimate: budget's is contact.linear.cost; 3-D nested-dissection fill grows
    like n^(4/3), so doubling a large mesh takes 2^(4/3) the memory."""
    n, m = 10_000, 300
    c = cost(n, m, 2)
    assert budget.contact_solver_estimate(n, m, 2) == (c["bytes"], c["setup"], c["per_solve"])
    a, b = cost(1e10, 0, 3)["bytes"], cost(2e10, 0, 3)["bytes"]
    assert b / a == pytest.approx(2.0 ** (4.0 / 3.0), rel=0.02)


def test_contact_meshes_of_the_review_are_refused_the_example_is_not() -> None:
    # the review's 1.99e6-node 2-D block (2000 x 995 nodes): ~14 GB of factors
    with pytest.raises(InputError, match=r"\[block\].element_size .* 1\.99e\+06 nodes"):
        budget.check_contact_size(2000 * 995, 2000, 2, 54, memory=16 * GB)
    # a 363k-node 3-D block (72 x 72 x 70 nodes): ~70 GB of factors
    with pytest.raises(InputError, match="3-D mesh"):
        budget.check_contact_size(72 * 72 * 70, 72 * 72, 3, 54, memory=64 * GB)
    budget.check_contact_size(41 * 11, 41, 2, 54, memory=8 * GB)  # the bundled PMMA block
    budget.check_contact_size(33**3, 33**2, 3, 17, memory=16 * GB)  # the 32^3-hex benchmark


def test_lattice_time_samples_refused_by_memory_naming_the_key() -> None:
    with pytest.raises(InputError, match=r"\[lattice\].time_samples = 1000000000 .* memory"):
        budget.check_lattice_size(10**9, 8, 2000, 2, memory=64 * GB)
    budget.check_lattice_size(400, 8, 2000, 2, memory=8 * GB)  # the default settings


def test_calibration_steps_refused_by_time_then_memory() -> None:
    key = "[[data]] #1.program #1.steps"
    runs = 2 * 9 * 30 * 7
    with pytest.raises(InputError, match=r"#1\.steps makes 1e\+07 steps.* beyond the 1 day"):
        budget.check_calibration_size([(10**7, key)], 6, 100, runs, memory=64 * GB)
    with pytest.raises(InputError, match=r"#1\.steps makes 1e\+12 steps.* memory"):
        budget.check_calibration_size([(10**12, key)], 6, 100, runs, memory=64 * GB)
    # the bundled example: ~420 steps over one curve
    budget.check_calibration_size([(200, key), (60, "b"), (60, "c")], 6, 100, runs, memory=GB)


def test_a_million_case_grid_is_refused_before_it_is_expanded() -> None:
    grid = {"law.mu_s": list(range(1000)), "law.mu_k": list(range(1000))}
    start = time.perf_counter()
    with pytest.raises(InputError, match=r"\[grid\] makes 1e\+06 cases, more than max_cases"):
        expand_grid(grid)
    assert time.perf_counter() - start < 0.5
    assert len(expand_grid({"a.b": list(range(10))}, max_cases=10)) == 10
    check_case_count(MAX_CASES, "x")
    with pytest.raises(InputError, match="max_cases = 100000"):
        check_case_count(MAX_CASES + 1, "[[case]]")


CLOSED = ("cam_clay", "modified_cam_clay", "tear", "parabola")


@pytest.mark.parametrize("surface", CLOSED)
def test_no_closed_surface_reaches_past_f_n_equal_to_F(surface: str) -> None:
    """g >= g(0) = 1 on its domain, so f_n = F / g(chi) <= F on the surface (Eq 48)."""
    chi = np.linspace(0.0, 1.99, 400)
    g, _ = g_function(surface, chi)
    assert g[0] == pytest.approx(1.0, abs=1e-15)
    assert np.all(g[np.isfinite(g)] >= 1.0 - 1e-15)


def _closed(F_k: float) -> SubloadingParams:
    return SubloadingParams(
        surface="modified_cam_clay", F_s=2e6, F_k=F_k, M=0.6, alpha_n=5e11, alpha_t=5e11,
        u=2e6, kappa=1e9, xi=0.05,
    )  # fmt: skip


def test_normal_capacity_blames_F_k_or_the_traction() -> None:
    check_normal_capacity(_closed(1.2e6), 1e6)
    with pytest.raises(ParameterError, match=r"F_k = 800000.0 .* normal traction 1e\+06 Pa"):
        check_normal_capacity(_closed(0.8e6), 1e6)
    with pytest.raises(ParameterError, match=r"pressure = 1000000.0 .* below F_k = 800000"):
        check_normal_capacity(_closed(0.8e6), 1e6, "pressure")
    cone = SubloadingParams(mu_s=0.6, mu_k=0.4, alpha_n=1e9, alpha_t=1e9, u=1e4, kappa=1.0)
    check_normal_capacity(cone, 1e30)  # the cone carries any normal traction


def test_snap_back_check_takes_one_traction_for_per_point_laws() -> None:
    """A scalar traction with a per-point law is that traction at every point (no ValueError)."""
    law = SubloadingParams(
        mu_s=[0.6, 0.7], mu_k=0.4, alpha_n=1e9, alpha_t=[1e9, 1e3], u=1e4, kappa=1e3
    )
    check_snap_back(law, 1.0)
    with pytest.raises(ParameterError, match=r"alpha_t = 1000\.0"):  # point 2 fails at 1e6 Pa
        check_snap_back(law, 1e6)
