"""Sliding-yield surface families, Eqs (48)–(54), (67), (82)–(84), (95).

Every surface is written as a potential ``Phi(w, f_n)`` of the normal traction ``f_n``
(compression positive) and the elliptic norm of the rotated tangential traction

    w = sqrt((fhat_1 / A_1)^2 + (fhat_2 / A_2)^2),   fhat = f_t - f_n beta   (Eqs 79, 83, 84, 95)

with axis factors ``A_i = C_i`` (cone) or ``A_i = M C_i`` (closed surfaces):

* Coulomb cone, Eqs (67), (95): ``Phi = w / f_n`` (degree zero; F is mu);
* closed surfaces, Eqs (48), (82): ``Phi = f_n g(chi)`` with ``chi = w / f_n`` and g one of
  Eqs (51)–(54) (degree one; F in traction units).

The scalar kernels (``g_value``, ``potential``) are compiled with numba and used by the
return map; the NumPy functions below them are the public, vectorised views.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._jit import njit
from frictionlab.errors import ParameterError

__all__ = [
    "CAM_CLAY",
    "COULOMB",
    "MODIFIED_CAM_CLAY",
    "PARABOLA",
    "SURFACE_CODES",
    "TEAR",
    "chi_max",
    "friction_coefficient_on_yield",
    "g_function",
    "g_inverse",
    "yield_function",
]

COULOMB, CAM_CLAY, MODIFIED_CAM_CLAY, TEAR, PARABOLA = 0, 1, 2, 3, 4
SURFACE_CODES = {
    "coulomb": COULOMB,
    "cam_clay": CAM_CLAY,
    "modified_cam_clay": MODIFIED_CAM_CLAY,
    "tear": TEAR,
    "parabola": PARABOLA,
}


@njit(cache=True)
def g_value(code: int, tear_k: float, chi: float) -> tuple[float, float]:
    """g(chi) and g'(chi) of Eqs (51)–(54); (+inf, +inf) outside the domain of g."""
    if code == CAM_CLAY:
        e = math.exp(chi)
        return e, e
    if code == MODIFIED_CAM_CLAY:
        return 1.0 + chi * chi, 2.0 * chi
    if code == TEAR:
        a = 1.0 / (2.0 * tear_k + 1.0)
        base = 1.0 - a * chi * chi
        if base <= 0.0:
            return math.inf, math.inf
        g = base**-tear_k
        return g, 2.0 * a * tear_k * chi * g / base
    if code == PARABOLA:
        if chi >= 2.0:
            return math.inf, math.inf
        d = 2.0 - chi
        return 2.0 / d, 2.0 / (d * d)
    return math.nan, math.nan  # the cone has no g


@njit(cache=True)
def potential(code: int, tear_k: float, w: float, fn: float) -> tuple[float, float, float]:
    """Phi(w, f_n) and its partial derivatives (Phi_w, Phi_fn).

    Cone: Phi = w/f_n, Phi_w = 1/f_n, Phi_fn = -w/f_n^2.
    Closed: Phi = f_n g(chi), Phi_w = g'(chi), Phi_fn = g - chi g'.
    """
    if code == COULOMB:
        inv = 1.0 / fn  # one division (the kernels' costliest arithmetic)
        phi = w * inv
        return phi, inv, -phi * inv
    chi = w / fn
    g, dg = g_value(code, tear_k, chi)
    if math.isinf(g):
        return math.inf, math.inf, -math.inf
    return fn * g, dg, g - chi * dg


@njit(cache=True)
def g_values(code: int, tear_k: float, chi: np.ndarray, g: np.ndarray, dg: np.ndarray) -> None:
    """:func:`g_value` over flat arrays: ``g[i], dg[i] = g_value(code, tear_k, chi[i])``."""
    for i in range(chi.size):
        g[i], dg[i] = g_value(code, tear_k, chi[i])


@njit(cache=True)
def potentials(code: int, tear_k: float, w: np.ndarray, fn: np.ndarray, out: np.ndarray) -> None:
    """Phi(w, f_n) over flat arrays, ``out[i] = potential(code, tear_k, w[i], fn[i])[0]``.

    ``f_n <= 0`` gives 0 for ``w = 0`` and +inf otherwise (the surface is singular there).
    """
    for i in range(w.size):
        if fn[i] <= 0.0:
            out[i] = 0.0 if w[i] == 0.0 else math.inf
        else:
            out[i] = potential(code, tear_k, w[i], fn[i])[0]


# ---------------------------------------------------------------------- public NumPy API
def _code(surface: str) -> int:
    try:
        return SURFACE_CODES[surface]
    except KeyError:
        raise ParameterError("surface", surface, "one of " + ", ".join(SURFACE_CODES)) from None


def chi_max(surface: str, tear_k: float = 1.0) -> float:
    """Upper end of the domain of g: sqrt(2k+1) (tear), 2 (parabola), inf otherwise."""
    code = _code(surface)
    if code == TEAR:
        return math.sqrt(2.0 * tear_k + 1.0)
    if code == PARABOLA:
        return 2.0
    return math.inf


def g_function(surface: str, chi: ArrayLike, tear_k: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised g(chi) and g'(chi) of a closed surface (Eqs 51–54); +inf outside the domain."""
    code = _code(surface)
    if code == COULOMB:
        raise ParameterError("surface", surface, "a closed surface (the cone has no g)")
    chi = np.asarray(chi, dtype=np.float64)
    g = np.empty(chi.shape)
    dg = np.empty(chi.shape)
    g_values(code, float(tear_k), np.ascontiguousarray(chi).reshape(-1), g.reshape(-1),
             dg.reshape(-1))  # fmt: skip
    return g, dg


def g_inverse(surface: str, G: ArrayLike, tear_k: float = 1.0) -> np.ndarray:
    """chi* with g(chi*) = G for G >= 1 (the branch chi >= 0), in closed form."""
    code = _code(surface)
    G = np.asarray(G, dtype=np.float64)
    if np.any(~(G >= 1.0)):
        raise ParameterError("G", G, "G = F/f_n >= 1 (the normal traction inside the surface)")
    if code not in (CAM_CLAY, MODIFIED_CAM_CLAY, TEAR, PARABOLA):
        raise ParameterError("surface", surface, "a closed surface (the cone has no g)")
    return _g_inverse(code, G, tear_k)


def _g_inverse(code: int, G: Any, tear_k: float) -> Any:
    """chi* with g(chi*) = G >= 1 of the closed surface ``code``: on NumPy arrays here, on
    scalars compiled (:data:`g_inverse_scalar`)."""
    if code == CAM_CLAY:
        return np.log(G)
    if code == MODIFIED_CAM_CLAY:
        return np.sqrt(G - 1.0)
    if code == TEAR:
        a = 1.0 / (2.0 * tear_k + 1.0)
        return np.sqrt((1.0 - G ** (-1.0 / tear_k)) / a)
    return 2.0 * (1.0 - 1.0 / G)  # parabola


#: Scalar chi* = g^-1(G) of a closed surface (code, G >= 1, tear_k), compiled.
g_inverse_scalar = njit(cache=True)(_g_inverse)


def friction_coefficient_on_yield(
    surface: str,
    normal_traction: ArrayLike,
    F: ArrayLike,
    M: float = 1.0,
    tear_k: float = 1.0,
) -> np.ndarray:
    """Friction coefficient ``|f_t|/f_n`` on a closed sliding-yield surface.

    ``mu(f_n) = M g^{-1}(F / f_n)`` for ``0 < f_n <= F``. For the cone
    this is simply ``F`` (= mu).
    """
    fn = np.asarray(normal_traction, dtype=np.float64)
    F = np.asarray(F, dtype=np.float64)
    if _code(surface) == COULOMB:
        return np.broadcast_to(F, np.broadcast(fn, F).shape).copy()
    if np.any(~(fn > 0)) or np.any(~(fn <= F)):
        raise ParameterError("normal_traction", fn, "0 < f_n <= F")
    return M * g_inverse(surface, F / fn, tear_k)


def yield_function(
    surface: str,
    traction: ArrayLike,
    rotation: ArrayLike | tuple[float, float] = (0.0, 0.0),
    axis_factors: ArrayLike | tuple[float, float] = (1.0, 1.0),
    tear_k: float = 1.0,
) -> np.ndarray:
    """f(f, beta) of Eqs (48)/(67)/(82)/(95) for tractions ``(..., 3) = (f_t1, f_t2, f_n)``.

    ``traction`` and ``rotation`` must be given in the principal axes of orthotropy.
    Returns ``(...)``; ``f_n <= 0`` gives NaN-free 0 only for zero tangential traction,
    otherwise +inf (the surface is singular there).
    """
    code = _code(surface)
    f = np.asarray(traction, dtype=np.float64)
    fn = f[..., 2]
    fhat = f[..., :2] - fn[..., None] * np.asarray(rotation, dtype=np.float64)
    w = np.sqrt(np.sum((fhat / np.asarray(axis_factors, dtype=np.float64)) ** 2, axis=-1))
    shape = np.broadcast(w, fn).shape
    out = np.empty(shape)
    w_flat = np.ascontiguousarray(np.broadcast_to(w, shape), dtype=np.float64).reshape(-1)
    fn_flat = np.ascontiguousarray(np.broadcast_to(fn, shape), dtype=np.float64).reshape(-1)
    potentials(code, float(tear_k), w_flat, fn_flat, out.reshape(-1))
    return out
