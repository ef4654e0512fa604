"""Property-based tests: random parameters and random increment sequences."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from frictionlab.errors import ParameterError
from frictionlab.subloading import Status, SubloadingParams, initial_state, update
from frictionlab.subloading.reference import yield_value

SURFACES = ["coulomb", "cam_clay", "modified_cam_clay", "tear", "parabola"]


@st.composite
def law(draw: st.DrawFn) -> tuple[SubloadingParams, float]:
    surface = draw(st.sampled_from(SURFACES))
    kinetic = draw(st.floats(0.1, 1.0))
    static = kinetic * draw(st.floats(1.0, 2.5))
    common = dict(
        surface=surface,
        alpha_n=draw(st.floats(10.0, 1e4)),
        alpha_t=draw(st.floats(10.0, 1e4)),
        u=draw(st.floats(1.0, 1e4)),
        kappa=draw(st.floats(0.0, 5.0)),
        xi=draw(st.floats(0.0, 0.1)),
        m=draw(st.sampled_from([1.0, 1.0, 0.5, 2.0])),
        n=draw(st.sampled_from([1.0, 1.0, 0.5, 2.0])),
        orthotropy=(draw(st.floats(0.5, 1.5)), draw(st.floats(0.5, 1.5))),
        orthotropy_angle=draw(st.floats(-1.5, 1.5)),
        U_law=draw(st.sampled_from(["cot", "cot", "ln"])),
        F_integrator=draw(st.sampled_from(["exponential", "backward_euler"])),
        recovery_form=draw(st.sampled_from(["one_minus", "one_minus", "ratio"])),
        open_recovery=draw(st.sampled_from(["continue", "frozen"])),
    )
    beta_scale = draw(st.floats(0.0, 0.8))
    beta_dir = draw(st.floats(0.0, 2 * np.pi))
    if surface == "coulomb":
        beta = beta_scale * kinetic * 0.5
        rotation = (beta * np.cos(beta_dir), beta * np.sin(beta_dir))
        params = SubloadingParams(mu_s=static, mu_k=kinetic, rotation=rotation, **common)
        fn = draw(st.floats(0.1, 10.0))
    else:
        M = draw(st.floats(0.2, 1.0))
        beta = beta_scale * M * 0.5
        rotation = (beta * np.cos(beta_dir), beta * np.sin(beta_dir))
        params = SubloadingParams(F_s=static, F_k=kinetic, M=M, rotation=rotation, **common)
        fn = kinetic * draw(st.floats(0.05, 0.6))
    return params, fn


increment = st.tuples(
    st.sampled_from(["slide", "slide", "hold", "reverse", "normal", "big"]),
    st.floats(0.0, 2 * np.pi),
    st.floats(0.05, 1.0),
    st.floats(0.0, 10.0),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(law(), st.lists(increment, min_size=5, max_size=40))
def test_invariants_hold_after_every_step(setup, program) -> None:  # type: ignore[no-untyped-def]
    params, fn = setup
    try:
        state = initial_state(params, normal_traction=np.array([fn, 0.5 * fn]))
    except ParameterError:
        assume(False)
    scale = fn * float(params.static) / float(params.alpha_t)  # elastic limit slip
    if not params.is_cone:
        scale = float(params.static) / float(params.alpha_t)
    direction = np.array([1.0, 0.0])
    for kind, angle, size, dt in program:
        du = np.zeros((2, 3))
        if kind in ("slide", "big"):
            direction = np.array([np.cos(angle), np.sin(angle)])
            du[:, :2] = direction * size * scale * (50.0 if kind == "big" else 1.0)
        elif kind == "reverse":
            direction = -direction
            du[:, :2] = direction * 3.0 * size * scale
        elif kind == "normal":
            # small changes of the normal traction, sometimes opening point 0
            fn_scale = fn / float(params.alpha_n)
            du[:, 2] = fn_scale * (size - 0.5) * (4.0 if angle > 5.0 else 0.4)
        state = _checked_step(params, state, du, dt)


def _checked_step(params: SubloadingParams, old, du: np.ndarray, dt: float):  # type: ignore[no-untyped-def]
    """One update of two points, every invariant checked; the new state."""
    step = update(params, old, du, dt, raise_on_failure=False)
    for array in (step.traction, step.tangent, step.state.F, step.state.R, step.dissipation):
        assert np.all(np.isfinite(array))
    if params.is_cone:
        assert step.success, step.message
    ok = step.converged
    new = step.state
    F_k, F_s = float(params.kinetic), float(params.static)
    assert np.all(F_k * (1 - 1e-14) <= new.F) and np.all(F_s * (1 + 1e-14) >= new.F)
    assert np.all(new.R >= 0.0) and np.all(new.R <= 1.0)
    assert np.all(step.plastic_multiplier >= 0.0)
    assert np.all(step.plastic_slip_increment[:, 2] == 0.0)
    for i in range(2):
        if not ok[i]:  # only when the normal traction leaves a closed surface
            np.testing.assert_array_equal(new.traction[i], old.traction[i])
            trial_fn = old.traction[i, 2] + float(params.alpha_n) * (du[i, 2] - old.gap[i])
            assert not params.is_cone and trial_fn > F_k
            continue
        if step.status[i] == Status.OPEN:
            assert np.all(new.traction[i] == 0.0) and new.R[i] == 0.0
            continue
        f = yield_value(params, new.traction[i])
        assert abs(f - new.R[i] * new.F[i]) <= 1e-10 * new.F[i]
        if old.traction[i, 2] > 0 and old.gap[i] == 0:
            assert new.traction[i, 2] == old.traction[i, 2] + float(params.alpha_n) * du[i, 2]
        if not np.any(params.rotation):
            assert step.dissipation[i] >= 0.0
        if step.status[i] == Status.SLIP:  # flow direction at t_{n+1}: unit, tangential
            dlam = step.plastic_multiplier[i]
            vp = step.plastic_slip_increment[i, :2]
            assert abs(np.hypot(vp[0], vp[1]) - dlam) <= 1e-12 * dlam + 1e-300
    return new


reclosing_op = st.tuples(
    st.sampled_from(["slide", "open", "hold", "reclose", "reclose"]),
    st.floats(0.0, 2 * np.pi),  # direction of the tangential slip
    st.floats(0.0, 1.0),  # its size (above 0.7: 50 times larger)
    st.floats(0.0, 10.0),  # dt [s]: the opening recovers F
    st.floats(0.2, 1.6),  # re-closing normal target, in units of the size before the step
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(law(), st.floats(0.0, 1.0), st.lists(reclosing_op, min_size=4, max_size=25))
# the case at the scale of the strategy: re-closing to 1.1 F_k while sliding far, the
# opening recovering F to ~1.39 F_k (R = 1.1 with SLIP before the fix)
@example(setup=(SubloadingParams(surface="modified_cam_clay", F_s=2.0, F_k=1.0, M=1.0,
                                 alpha_n=1e3, alpha_t=1e3, u=100.0, kappa=0.0, xi=0.1), 0.5),
         size0=0.0,
         program=[("open", 0.0, 0.5, 0.0, 1.0), ("reclose", 0.0, 1.0, 10.0, 1.1)])  # fmt: skip
def test_open_and_reclose_programmes_keep_every_invariant(setup, size0, program) -> None:  # type: ignore[no-untyped-def]
    """Issue 27: open, hold and re-close (while sliding, with recovery) at random.

    The contact starts below its static size (so an opening can recover it), and a re-closing
    target is drawn relative to the size before the step: below, near and above it.
    """
    params, fn = setup
    F_k, F_s = float(params.kinetic), float(params.static)
    try:
        state = initial_state(params, normal_traction=np.array([fn, 0.5 * fn]),
                              F=F_k + size0 * (F_s - F_k))  # fmt: skip
    except ParameterError:
        assume(False)
    alpha_n = float(params.alpha_n)
    scale = (fn if params.is_cone else 1.0) * F_s / float(params.alpha_t)
    for kind, angle, size, dt, target in program:
        du = np.zeros((2, 3))
        if kind in ("slide", "reclose"):
            du[:, :2] = [np.cos(angle), np.sin(angle)]
            du[:, :2] *= size * scale * (50.0 if size > 0.7 else 1.0)
        if kind == "open":  # closed points open (f_n^tr = -size f_n), open ones open further
            du[:, 2] = -(state.traction[:, 2] * (1.0 + size) + size * fn) / alpha_n
        elif kind == "reclose":  # open points close to target * F (the cone: target * 2 f_n)
            reached = target * (2.0 * fn if params.is_cone else state.F)
            du[:, 2] = np.where(state.traction[:, 2] <= 0.0, state.gap + reached / alpha_n, 0.0)
        state = _checked_step(params, state, du, dt)
