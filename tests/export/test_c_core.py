"""The C core (export/subloading.c) against the numba kernel, bit for bit.

Random states and increments (sliding, unloading, holds, opening and re-closing, with
rotation and orthotropy) for every surface and all 32 combinations of the options
(U law, F integrator, recovery form, open recovery, unit or general exponents). The C
core is a translation of kernels._point, so any change of kernels.py, evolution.py or
surfaces.py that is not mirrored in subloading.c fails here.
"""

from __future__ import annotations

import ctypes
import itertools

import numpy as np
import pytest

from frictionlab.export import c_core
from frictionlab.subloading import SubloadingParams, initial_state, kernels, update
from frictionlab.subloading.return_map import _FORM_CODES, _INTEG_CODES, _U_CODES
from frictionlab.subloading.surfaces import SURFACE_CODES

N = 32
OPTIONS = list(
    itertools.product(
        ("cot", "ln"),
        ("exponential", "backward_euler"),
        ("one_minus", "ratio"),
        ("continue", "frozen"),
        ((1.0, 1.0), (1.5, 0.5)),
    )
)


def _params(surface: str, option: tuple) -> SubloadingParams:
    U_law, integrator, form, open_recovery, (m, n) = option
    common = dict(
        surface=surface, alpha_n=1000.0, alpha_t=1000.0, u=100.0, kappa=1.0, xi=0.05,
        rotation=(0.04, -0.02), orthotropy=(1.0, 0.7), orthotropy_angle=0.4, U_law=U_law,
        F_integrator=integrator, recovery_form=form, open_recovery=open_recovery, m=m, n=n,
    )  # fmt: skip
    if surface == "coulomb":
        return SubloadingParams(mu_s=0.5, mu_k=0.3, **common)  # type: ignore[arg-type]
    return SubloadingParams(F_s=1.0, F_k=0.6, M=0.5, tear_k=2.0, **common)  # type: ignore[arg-type]


def _inputs(params: SubloadingParams, rng: np.random.Generator):
    """A state reached by random increments, and the increment to compare on."""
    cone = params.is_cone
    fn = rng.uniform(0.5, 1.5, N) if cone else rng.uniform(0.15, 0.35, N)
    state = initial_state(params, normal_traction=fn)
    scale = np.array([2e-4, 2e-4, 2e-5 if cone else 2e-6])
    for _ in range(3):
        du = rng.normal(size=(N, 3)) * scale
        du[rng.random(N) < 0.15, 2] = -3e-3  # open some points; they re-close later
        dt = rng.uniform(0.0, 0.5, N)
        state = update(params, state, du, dt, raise_on_failure=False).state
    du = rng.normal(size=(N, 3)) * scale
    opened = state.gap > 0.0
    # re-closing: past the opening, with tangential slip during the closing step
    du[opened, 2] = state.gap[opened] * rng.uniform(1.0, 1.5, int(opened.sum())) + 1e-6
    du[: N // 6, :2] = 0.0  # holds
    return state, du, rng.uniform(0.0, 0.5, N)


def _numba(params, state, du, dt):  # type: ignore[no-untyped-def]
    res = update(params, state, du, dt, raise_on_failure=False)
    return {
        "traction": res.traction, "F": res.state.F, "R": res.state.R, "gap": res.state.gap,
        "dlam": res.plastic_multiplier, "vp": res.plastic_slip_increment,
        "diss": res.dissipation, "tangent": res.tangent, "status": res.status,
        "iterations": res.iterations,
    }  # fmt: skip


def _c(core: ctypes.CDLL, params, state, du, dt):  # type: ignore[no-untyped-def]
    options = dict(
        surface=SURFACE_CODES[params.surface], tear_k=params.tear_k,
        u_law=_U_CODES[params.U_law], integrator=_INTEG_CODES[params.F_integrator],
        recovery=_FORM_CODES[params.recovery_form],
        open_frozen=int(params.open_recovery == "frozen"), want_tangent=1,
    )  # fmt: skip
    return c_core.step_points(core, state.traction, state.F, state.R, state.gap, du, dt,
                              params._kernel_table, options)  # fmt: skip


@pytest.mark.slow
@pytest.mark.parametrize("surface", list(SURFACE_CODES))
def test_c_core_is_bit_identical_to_the_numba_kernel(core: ctypes.CDLL, surface: str) -> None:
    seen: set[int] = set()
    reclosed = 0
    for k, option in enumerate(OPTIONS):
        params = _params(surface, option)
        state, du, dt = _inputs(params, np.random.default_rng(1000 * k + len(surface)))
        ref = _numba(params, state, du, dt)
        got = _c(core, params, state, du, dt)
        for key, value in ref.items():
            np.testing.assert_array_equal(
                got[key], value, err_msg=f"{key}, {surface}, options {option}"
            )
        seen |= set(ref["status"].tolist())
        reclosed += int(np.sum((state.gap > 0.0) & (ref["status"] != kernels.OPEN)))
    # both branches and the re-closings were exercised
    assert {kernels.STICK, kernels.SLIP} <= seen
    assert reclosed >= 32
