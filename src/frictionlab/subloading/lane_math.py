"""Inline elementary functions for the lane kernel, over the ranges the cone's lanes use.

Plain arithmetic (no math-library call), so that LLVM compiles them into the packed
loops of the lanes; each is within 2 ulp of the exact value over its documented range
(tests/subloading/test_lane_math.py measures them against 80-bit long-double references):

- :func:`expm1_nonpositive`: ``expm1(x)`` for ``x <= 0`` (the ratio's and the size's
  exponentials in the return mapping: both arguments are -(positive) increments);
- :func:`expm1_small`: ``expm1(x)`` for ``|x| <= 2^-17`` (a cubic; the change of an
  exponential between two Newton iterates of the return mapping);
- :func:`atan2_first_quadrant`: ``atan2(s, y)`` for ``s, y >= 0`` (the ratio
  R = atan2(s, y)/(pi/2) of the cot law, whose s and y are a sine and a cosine);
- :func:`sincos_half_pi`: ``(cos, sin)`` of ``pi R/2`` for ``0 <= R <= 1``, with the exact
  reflection ``1 - R`` above 1/2, which keeps full relative accuracy of the cosine near
  R = 1 (libm's ``cos(pi/2 * R)`` loses it to the rounding of the product).

atan's rational core is Cephes's (S. L. Moshier): ``x + x^3 P(x^2)/Q(x^2)`` on [0, 0.66]
after the reduction at 0.66 (and the swap of s and y above 1); expm1 after the reduction
x = -k ln 2 + r, and the sine and cosine in R on [0, 1/2], are Taylor polynomials
(their truncation is below 1e-18 relative).
"""

from __future__ import annotations

import math

from frictionlab._jit import njit

__all__ = [
    "EXPM1_SMALL_MAX",
    "atan2_first_quadrant",
    "expm1_nonpositive",
    "expm1_small",
    "sincos_half_pi",
]

#: Below this argument expm1 is -1 to double precision (e^-40 = 4e-18 < 2^-53).
_EXPM1_FLOOR = -40.0
_LN2_HI = 6.93147180369123816490e-01  # the high part has 32 trailing zero bits
_LN2_LO = 1.90821492927058770002e-10
_INV_LN2 = 1.44269504088896338700e00

# expm1(r) = r + r^2 (E2 + r (E3 + ...)), E_k = 1/k!, on |r| <= ln 2/2 (truncation below
# 2e-19 relative)
_E2, _E3, _E4, _E5, _E6, _E7, _E8, _E9, _E10, _E11, _E12, _E13, _E14 = (
    1.0 / math.factorial(k) for k in range(2, 15)
)

_AP0, _AP1, _AP2, _AP3, _AP4 = (
    -8.750608600031904122785e-1, -1.615753718733365076637e1, -7.500855792314704667340e1,
    -1.228866684490136173410e2, -6.485021904942025371773e1,
)  # fmt: skip
_AQ0, _AQ1, _AQ2, _AQ3, _AQ4 = (
    2.485846490142306297962e1, 1.650270098316988542046e2, 4.328810604912902668951e2,
    4.853903996359136964868e2, 1.945506571482613964425e2,
)  # fmt: skip
_MOREBITS = 6.123233995736765886130e-17  # pi/2 - double(pi/2)
_TAN_3PI_8 = 2.41421356237309504880
_PI_2 = 1.5707963267948966
_PI_4 = 0.7853981633974483

# sin(pi x/2) = x (S0 + x^2 (S1 + ...)), cos(pi x/2) = 1 + x^2 (C1 + x^2 (C2 + ...)):
# S_k = (-1)^k (pi/2)^(2k+1)/(2k+1)!, C_k = (-1)^k (pi/2)^(2k)/(2k)!
_S = tuple((-1.0) ** k * (math.pi / 2) ** (2 * k + 1) / math.factorial(2 * k + 1) for k in range(9))
_C = tuple((-1.0) ** k * (math.pi / 2) ** (2 * k) / math.factorial(2 * k) for k in range(10))
_S0, _S1, _S2, _S3, _S4, _S5, _S6, _S7, _S8 = _S
_C1, _C2, _C3, _C4, _C5, _C6, _C7, _C8, _C9 = _C[1:]


@njit(cache=True, inline="always")
def _expm1_core(r):  # fmt: skip
    """expm1 on [-ln 2/2, ln 2/2] (Taylor, Horner)."""
    p = _E10 + r * (_E11 + r * (_E12 + r * (_E13 + r * _E14)))
    p = _E6 + r * (_E7 + r * (_E8 + r * (_E9 + r * p)))
    p = _E2 + r * (_E3 + r * (_E4 + r * (_E5 + r * p)))
    return r + r * r * p


@njit(cache=True, inline="always")
def _pow2_neg(k):  # fmt: skip
    """2^-k for a whole number 0 <= k < 64 (products of powers of two: exact), by selects
    that vectorise, where a table lookup would not; 1 for any other k."""
    k = k if 0.0 <= k < 64.0 else 0.0
    scale = 1.0
    on = k >= 32.0
    scale, k = (scale * 2.0**-32, k - 32.0) if on else (scale, k)
    on = k >= 16.0
    scale, k = (scale * 2.0**-16, k - 16.0) if on else (scale, k)
    on = k >= 8.0
    scale, k = (scale * 2.0**-8, k - 8.0) if on else (scale, k)
    on = k >= 4.0
    scale, k = (scale * 0.0625, k - 4.0) if on else (scale, k)
    on = k >= 2.0
    scale, k = (scale * 0.25, k - 2.0) if on else (scale, k)
    return scale * 0.5 if k >= 1.0 else scale


@njit(cache=True, inline="always")
def expm1_nonpositive(x):  # fmt: skip
    """``expm1(x)`` for ``x <= 0``.

    x = -k ln 2 + r with |r| <= ln 2/2; expm1(x) = 2^-k expm1(r) + (2^-k - 1), where
    2^-k - 1 is exact and the sum rounds once.
    """
    x = x if x > _EXPM1_FLOOR else _EXPM1_FLOOR
    k = math.floor(0.5 - x * _INV_LN2)  # round(-x/ln 2), 0 <= k <= 58
    r = (x + k * _LN2_HI) + k * _LN2_LO
    scale = _pow2_neg(k)
    return scale * _expm1_core(r) + (scale - 1.0)


#: The range |x| <= 2^-17 of :func:`expm1_small`.
EXPM1_SMALL_MAX = 2.0**-17


@njit(cache=True, inline="always")
def expm1_small(x):  # fmt: skip
    """``expm1(x)`` for ``|x| <= EXPM1_SMALL_MAX`` (either sign): ``x + x^2/2 + x^3/6``.

    The truncation ``x^4/24`` is below ``|x| 2^-51/24 < 2^-55 |x|`` (a sixth of an ulp); the
    lanes use it for the change of an exponential between two nearby Newton iterates.
    """
    return x + x * x * (0.5 + x * (1.0 / 6.0))


@njit(cache=True, inline="always")
def atan2_first_quadrant(s, y):  # fmt: skip
    """``atan2(s, y)`` for ``s >= 0``, ``y >= 0`` (0 at s = y = 0, as libm)."""
    big = s > y  # atan2(s, y) = pi/2 - atan(y/s)
    num = y if big else s
    den = s if big else y
    x = num / den if den > 0.0 else 0.0  # in [0, 1]
    mid = x > 0.66  # atan(x) = pi/4 + atan((x - 1)/(x + 1))
    t = (x - 1.0) / (x + 1.0) if mid else x
    z = t * t
    p = (((_AP0 * z + _AP1) * z + _AP2) * z + _AP3) * z + _AP4
    q = ((((z + _AQ0) * z + _AQ1) * z + _AQ2) * z + _AQ3) * z + _AQ4
    a = t + t * (z * p / q)
    a = (_PI_4 + (a + 0.5 * _MOREBITS)) if mid else a
    return (_PI_2 + (_MOREBITS - a)) if big else a


@njit(cache=True, inline="always")
def _sin_half_pi(x):  # fmt: skip
    """sin(pi x/2) for 0 <= x <= 1/2."""
    z = x * x
    tail = _S5 + z * (_S6 + z * (_S7 + z * _S8))
    tail = z * (_S1 + z * (_S2 + z * (_S3 + z * (_S4 + z * tail))))
    return x * _S0 + x * tail


@njit(cache=True, inline="always")
def _cos_half_pi(x):  # fmt: skip
    """cos(pi x/2) for 0 <= x <= 1/2."""
    z = x * x
    tail = _C5 + z * (_C6 + z * (_C7 + z * (_C8 + z * _C9)))
    return 1.0 + z * (_C1 + z * (_C2 + z * (_C3 + z * (_C4 + z * tail))))


@njit(cache=True, inline="always")
def sincos_half_pi(R):  # fmt: skip
    """``(cos(pi R/2), sin(pi R/2))`` for ``0 <= R <= 1``."""
    upper = R > 0.5
    x = 1.0 - R if upper else R  # exact for R in [1/2, 1]
    s = _sin_half_pi(x)
    c = _cos_half_pi(x)
    return (s if upper else c), (c if upper else s)
