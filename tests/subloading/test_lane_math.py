"""The lane kernel's inline elementary functions: within 2 ulp over the ranges used.

The reference is the same function in x86 80-bit long double (64-bit significand), whose
own error is ~2^-11 ulp of a double; libm's double result is measured beside it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab._jit import njit
from frictionlab.subloading import kernels, lane_math

LONG = np.longdouble
pytestmark = pytest.mark.skipif(
    np.finfo(LONG).nmant < 60, reason="needs an extended-precision long double reference"
)


@njit(cache=True)
def _expm1(x, out):  # fmt: skip
    for i in range(x.size):
        out[i] = lane_math.expm1_nonpositive(x[i])


@njit(cache=True)
def _expm1_small(x, out):  # fmt: skip
    for i in range(x.size):
        out[i] = lane_math.expm1_small(x[i])


@njit(cache=True, error_model="numpy")  # as in the lanes: 1/0 is inf, not an exception
def _angle_step(y, s, X, out):  # fmt: skip
    for i in range(y.size):
        out[i] = kernels._angle_step(y[i], s[i], X[i])


@njit(cache=True)
def _atan2(s, y, out):  # fmt: skip
    for i in range(s.size):
        out[i] = lane_math.atan2_first_quadrant(s[i], y[i])


@njit(cache=True)
def _sincos(R, c, s):  # fmt: skip
    for i in range(R.size):
        c[i], s[i] = lane_math.sincos_half_pi(R[i])


def _ulps(got: np.ndarray, exact: np.ndarray) -> float:
    """Largest error of ``got`` in units of the last place of the exact value."""
    unit = np.spacing(np.abs(exact.astype(np.float64))).astype(LONG)
    return float(np.max(np.abs((got.astype(LONG) - exact) / unit)))


RNG = np.random.default_rng(7)
#: The ratio's argument -pi/2 u dlam and the size's -(kappa dlam/F_k + xi dt/F_s): any x <= 0.
EXPM1_RANGES = {
    "tiny": -np.exp(RNG.uniform(np.log(1e-300), np.log(1e-8), 20_000)),
    "small": -np.exp(RNG.uniform(np.log(1e-8), np.log(0.35), 50_000)),
    "reduced": -RNG.uniform(0.3, 3.0, 50_000),
    "large": -RNG.uniform(3.0, 45.0, 50_000),
    "floor": -np.exp(RNG.uniform(np.log(40.0), np.log(1e300), 5_000)),
}


@pytest.mark.parametrize("name", list(EXPM1_RANGES))
def test_expm1_within_two_ulp(name: str) -> None:
    x = EXPM1_RANGES[name]
    got = np.empty_like(x)
    _expm1(x, got)
    exact = np.expm1(x.astype(LONG))
    assert _ulps(got, exact) <= 2.0
    assert _ulps(np.expm1(x), exact) <= 1.0  # libm, for comparison


def test_expm1_edges() -> None:
    x = np.array([0.0, -0.0, -math.log(2.0), -700.0, -np.inf])
    got = np.empty_like(x)
    _expm1(x, got)
    assert got[0] == 0.0 and got[1] == 0.0
    assert got[2] == pytest.approx(-0.5, rel=4e-16)
    assert got[3] == -1.0 and got[4] == -1.0


#: s, y >= 0: a sine and a cosine of the same angle, scaled alike (the cot law's ratio).
ANGLES = np.concatenate([RNG.uniform(0.0, np.pi / 2, 100_000),
                         np.exp(RNG.uniform(-30.0, 0.0, 20_000)),
                         np.pi / 2 - np.exp(RNG.uniform(-30.0, 0.0, 20_000))])  # fmt: skip
SCALES = np.exp(RNG.uniform(-20.0, 20.0, ANGLES.size))


def test_atan2_first_quadrant_within_two_ulp() -> None:
    s = np.sin(ANGLES) * SCALES
    y = np.cos(ANGLES) * SCALES
    got = np.empty_like(s)
    _atan2(s, y, got)
    exact = np.arctan2(s.astype(LONG), y.astype(LONG))
    assert _ulps(got, exact) <= 2.0
    assert _ulps(np.arctan2(s, y), exact) <= 1.0


def test_atan2_edges() -> None:
    s = np.array([0.0, 1.0, 0.0, 3.0, 2.0])
    y = np.array([0.0, 0.0, 1.0, 3.0, 2.0 * math.sqrt(3.0)])
    got = np.empty_like(s)
    _atan2(s, y, got)
    assert got[0] == 0.0 and got[2] == 0.0
    assert got[1] == math.pi / 2
    assert got[3] == pytest.approx(math.pi / 4, rel=2.3e-16)
    assert got[4] == pytest.approx(math.pi / 6, rel=4.5e-16)


def test_sincos_half_pi_within_two_ulp_and_the_reflection() -> None:
    R = np.concatenate([RNG.uniform(0.0, 1.0, 100_000),
                        np.exp(RNG.uniform(-40.0, -1.0, 20_000)),
                        1.0 - np.exp(RNG.uniform(-40.0, -1.0, 20_000))])  # fmt: skip
    c = np.empty_like(R)
    s = np.empty_like(R)
    _sincos(R, c, s)
    half_pi = np.arctan(LONG(1)) * 2
    upper = R > 0.5
    flip = (1.0 - R).astype(LONG)  # exact for R >= 1/2
    exact_c = np.where(upper, np.sin(half_pi * flip), np.cos(half_pi * R.astype(LONG)))
    exact_s = np.where(upper, np.cos(half_pi * flip), np.sin(half_pi * R.astype(LONG)))
    assert _ulps(c, exact_c) <= 2.0
    assert _ulps(s, exact_s) <= 2.0
    # libm's cos(pi/2 * R) loses the relative accuracy near R = 1 (the product's rounding)
    near_one = R > 1.0 - 1e-6
    assert _ulps(np.cos(np.pi / 2 * R[near_one]), exact_c[near_one]) > 1e3
    ends = np.array([0.0, 0.5, 1.0])
    c, s = np.empty(3), np.empty(3)
    _sincos(ends, c, s)
    np.testing.assert_array_equal(c[[0, 2]], [1.0, 0.0])
    np.testing.assert_array_equal(s[[0, 2]], [0.0, 1.0])
    assert c[1] == pytest.approx(math.sqrt(0.5), rel=2.3e-16) and s[1] == c[1]


def test_expm1_small_within_one_ulp_over_its_range() -> None:
    """The cubic of the lanes' follow-up step, either sign, up to 2^-17."""
    top = lane_math.EXPM1_SMALL_MAX
    magnitude = np.exp(RNG.uniform(np.log(1e-300), np.log(top), 50_000))
    x = np.concatenate([magnitude, -magnitude, [top, -top]])
    got = np.empty_like(x)
    _expm1_small(x, got)
    assert _ulps(got, np.expm1(x.astype(LONG))) <= 1.0
    assert top >= kernels.STEP_RTOL  # the lanes call it only within its range


def test_angle_step_is_the_exact_change_of_acos_to_rounding() -> None:
    """theta + step(X) against acos(cos(theta) e^-X) for every step the lanes allow,
    |X| <= ANGLE_STEP_RTOL sin^2(theta), over the whole quadrant (2 ulp of theta)."""
    theta = np.concatenate([RNG.uniform(0.0, np.pi / 2, 50_000),
                            np.exp(RNG.uniform(-12.0, 0.0, 10_000))])  # fmt: skip
    y = np.cos(theta)
    s = np.sin(theta)
    X = kernels.ANGLE_STEP_RTOL * s * s * RNG.uniform(-1.0, 1.0, theta.size)
    step = np.empty_like(theta)
    _angle_step(y, s, X, step)
    # the exact angle of the pair (y, s) as rounded, and of (y e^-X, s') on its circle:
    # s'^2 = s^2 - y^2 expm1(-2X) (well conditioned, where acos near 1 is not)
    yl, sl, Xl = y.astype(LONG), s.astype(LONG), X.astype(LONG)
    start = np.arctan2(sl, yl)
    exact = np.arctan2(np.sqrt(sl * sl - yl * yl * np.expm1(-2 * Xl)), yl * np.exp(-Xl))
    got = start + step.astype(LONG)
    assert _ulps(got, exact) <= 2.0
    zero = np.empty(1)
    _angle_step(np.array([1.0]), np.array([0.0]), np.array([0.0]), zero)
    assert zero[0] == 0.0  # no step, no 0 * inf at theta = 0
