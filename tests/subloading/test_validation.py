"""Bad input is rejected with a ParameterError naming the field."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ConvergenceError, ParameterError
from frictionlab.subloading import SubloadingParams, initial_state, update

from .support import fresh, set_a, set_b


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"alpha_n": 0.0}, "alpha_n"),
        ({"alpha_n": -5.0}, "alpha_n"),
        ({"alpha_t": 0.0}, "alpha_t"),
        ({"mu_k": 0.6}, "mu_k"),  # mu_k > mu_s
        ({"mu_k": 0.0}, "mu_k"),
        ({"u": 0.0}, "u"),
        ({"kappa": -1.0}, "kappa"),
        ({"xi": -1e-3}, "xi"),
        ({"m": 0.0}, "m"),
        ({"n": -1.0}, "n"),
        ({"rotation": (0.3, 0.0)}, "rotation"),  # |beta| = mu_k
        ({"rotation": (0.25, 0.2)}, "rotation"),  # |beta| > mu_k
        ({"rotation": (0.1, 0.0, 0.0)}, "rotation"),  # three components
        ({"orthotropy": (1.0, 0.0)}, "orthotropy"),
        ({"alpha_t": float("nan")}, "alpha_t"),
        ({"mu_s": float("inf")}, "mu_s"),
        ({"u": [100.0, np.nan]}, "u"),
        ({"surface": "cone"}, "surface"),
        ({"U_law": "tanh"}, "U_law"),
        ({"F_integrator": "rk4"}, "F_integrator"),
        ({"recovery_form": "exp"}, "recovery_form"),
        ({"open_recovery": "sometimes"}, "open_recovery"),
        ({"orthotropy_convention": "square"}, "orthotropy_convention"),
        ({"mu_s": None}, "mu_s"),
        ({"F_s": 1.0}, "F_s"),  # closed-surface field on the cone
        ({"u": [1.0, 2.0], "kappa": [1.0, 2.0, 3.0]}, "parameter arrays"),
        ({"tear_k": 0.0}, "tear_k"),
        ({"alpha_t": "stiff"}, "alpha_t"),
    ],
)
def test_cone_parameters_rejected(changes: dict[str, object], field: str) -> None:
    with pytest.raises(ParameterError) as info:
        set_a(**changes)
    assert info.value.field == field
    assert field in str(info.value) and "allowed" in str(info.value)


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"F_k": 1.2}, "F_k"),  # F_k > F_s
        ({"M": 0.0}, "M"),
        ({"M": None}, "M"),
        ({"mu_s": 0.5}, "mu_s"),
        ({"rotation": (0.5, 0.0)}, "rotation"),  # |beta| >= M
    ],
)
def test_closed_parameters_rejected(changes: dict[str, object], field: str) -> None:
    with pytest.raises(ParameterError) as info:
        set_b(**changes)
    assert info.value.field == field


def test_rotation_bound_uses_the_principal_axes_of_orthotropy() -> None:
    # C = (1, 0.2), mu_k = 0.3: the kinetic cone has radius 0.3 along e*_1 and 0.06 along
    # e*_2. beta = 0.1 along e*_2 puts the origin outside it (friction against the sliding
    # direction when sliding along -beta), whichever contact-frame axis e*_2 is.
    with pytest.raises(ParameterError) as info:
        set_a(orthotropy=(1.0, 0.2), rotation=(0.0, 0.1))  # e*_2 = e_2
    assert info.value.field == "rotation"
    with pytest.raises(ParameterError) as info:  # e*_1 = e_2, so e*_2 = -e_1
        set_a(orthotropy=(1.0, 0.2), orthotropy_angle=np.pi / 2, rotation=(0.1, 0.0))
    assert info.value.field == "rotation"
    # beta = 0.1 along e*_1 (radius 0.3) is inside, with the axes turned or not
    set_a(orthotropy=(1.0, 0.2), rotation=(0.1, 0.0))
    set_a(orthotropy=(1.0, 0.2), orthotropy_angle=np.pi / 2, rotation=(0.0, 0.1))
    # per-point angles: the second point is turned so that beta lies along e*_2
    with pytest.raises(ParameterError):
        set_a(orthotropy=(1.0, 0.2), orthotropy_angle=[0.0, np.pi / 2], rotation=(0.1, 0.0))


def test_snap_back_condition_rejected_for_the_cone() -> None:
    # alpha_t <= f_n kappa (mu_s/mu_k - 1): 10 <= 20 * 1 * (0.5/0.3 - 1) = 13.3
    params = set_a(alpha_t=10.0)
    with pytest.raises(ParameterError, match="snap-back") as info:
        initial_state(params, normal_traction=20.0)
    assert info.value.field == "alpha_t"
    initial_state(params, normal_traction=10.0)  # 10 > 6.67: accepted


def test_snap_back_condition_rejected_for_a_closed_surface() -> None:
    params = set_b(alpha_t=0.1, kappa=10.0)
    with pytest.raises(ParameterError, match="snap-back"):
        initial_state(params, normal_traction=0.2)


def test_closed_surface_normal_traction_must_stay_inside_the_kinetic_surface() -> None:
    with pytest.raises(ParameterError, match="F_k"):
        initial_state(set_b(), normal_traction=0.6)


def test_initial_state_rejects_bad_values() -> None:
    params = set_a()
    with pytest.raises(ParameterError, match="normal_traction"):
        initial_state(params, normal_traction=0.0)
    with pytest.raises(ParameterError, match="normal_traction"):
        initial_state(params, normal_traction=np.nan)
    with pytest.raises(ParameterError, match="F"):
        initial_state(params, normal_traction=1.0, F=0.6)
    with pytest.raises(ParameterError, match="tangential_traction"):
        initial_state(params, normal_traction=1.0, tangential_traction=(0.6, 0.0))
    with pytest.raises(ParameterError, match="points"):
        initial_state(params, normal_traction=np.ones(3), tangential_traction=np.zeros((4, 2)))


def test_update_rejects_bad_increments() -> None:
    params = set_a()
    state = fresh(params, n=2)
    with pytest.raises(ParameterError, match="slip_increment"):
        update(params, state, np.zeros((3, 3)), 0.1)
    with pytest.raises(ParameterError, match="slip_increment"):
        update(params, state, np.zeros(3), 0.1)
    with pytest.raises(ParameterError, match="slip_increment"):
        update(params, state, np.array([[np.nan, 0, 0], [0, 0, 0]]), 0.1)
    with pytest.raises(ParameterError, match="time_increment"):
        update(params, state, np.zeros((2, 3)), -0.1)
    with pytest.raises(ParameterError, match="time_increment"):
        update(params, state, np.zeros((2, 3)), np.inf)
    with pytest.raises(ParameterError, match="time_increment"):
        update(params, state, np.zeros((2, 3)), np.zeros(3))
    per_point = set_a(u=np.array([100.0, 200.0, 300.0]))
    with pytest.raises(ParameterError, match="params"):
        update(per_point, state, np.zeros((2, 3)), 0.1)


def test_failed_point_is_reported_by_status_and_mask_never_nan() -> None:
    # Normal loading of a closed surface beyond F makes the point inadmissible.
    params = set_b()
    state = initial_state(params, normal_traction=np.array([0.2, 0.2]))
    du = np.array([[1e-5, 0.0, 0.0], [1e-5, 0.0, 5e-3]])  # second point: f_n -> 5.2 > F
    with pytest.raises(ConvergenceError) as info:
        update(params, state, du, 0.0)
    assert info.value.mask.tolist() == [False, True]
    result = info.value.result
    assert result.status.tolist() == [1, 3]  # SLIP, FAILED
    assert np.all(np.isfinite(result.traction)) and np.all(np.isfinite(result.tangent))
    np.testing.assert_array_equal(result.traction[1], state.traction[1])  # kept
    quiet = update(params, state, du, 0.0, raise_on_failure=False)
    assert not quiet.success and "failed 1" in quiet.message


def test_params_are_immutable_and_arrays_read_only() -> None:
    u = np.array([100.0, 200.0])
    params = set_a(u=u)
    u[0] = -1.0  # the caller's array is copied
    assert params.u[0] == 100.0
    with pytest.raises(ValueError):
        params.u[0] = 5.0
    with pytest.raises(AttributeError):
        params.mu_s = 0.6  # type: ignore[misc]


def test_multiply_convention_is_a_reparametrisation() -> None:
    a = set_a(orthotropy=(1.0, 0.6))
    b = set_a(orthotropy=(1.0, 0.6**-2), orthotropy_convention="multiply")
    np.testing.assert_allclose(b.orthotropy, a.orthotropy, rtol=1e-15)
    assert isinstance(b, SubloadingParams) and b.orthotropy_convention == "divide"


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("where", ["slip", "time"])
def test_update_refuses_non_finite_increments_even_beside_huge_ones(bad: float, where: str) -> None:
    """Finiteness is checked through the sum first; a NaN or infinity is never let through."""
    params = set_a()
    state = initial_state(params, 1.0, (0.0, 0.0), n_points=3)
    du = np.zeros((3, 3))
    dt = np.array([1e-3, 1e-3, 1e-3])
    if where == "slip":
        du[0, 0], du[1, 0], du[2, 1] = 1e308, 1e308, bad
    else:
        dt[:] = [1e308, 1e308, bad]
    with pytest.raises(ParameterError) as info:
        update(params, state, du, dt, raise_on_failure=False)
    assert info.value.field == ("slip_increment" if where == "slip" else "time_increment")


def test_update_accepts_finite_increments_whose_sum_overflows() -> None:
    params = set_a()
    state = initial_state(params, 1.0, (0.0, 0.0), n_points=2)
    dt = np.array([1e308, 1e308])  # finite, the sum is not: still a valid input
    res = update(params, state, np.zeros((2, 3)), dt, raise_on_failure=False)
    assert res.state.n_points == 2
