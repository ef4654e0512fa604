"""Contact state of N points, kept in the co-rotating contact frame (Eq 81).

Arrays are points first, components last. Tangential components refer to the contact
frame (e_1, e_2, n) of each point, which rides with the contact surface; the frame
itself is stored as ``frame[i] = [e_1, e_2, n]`` (rows, global components), so that a
rigid rotation of the contact pair changes only ``frame`` (objectivity, Eqs 13, 19, 81).

Sign conventions (those of Hashiguchi & Ozaki 2008): the normal traction ``f_n`` is
positive in compression and the normal slip is positive for approach; the traction acts on
the body and the slip is that of the counter body relative to the body.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from frictionlab._jit import njit
from frictionlab.errors import ParameterError
from frictionlab.subloading.params import SubloadingParams
from frictionlab.subloading.surfaces import (
    SURFACE_CODES,
    g_inverse_scalar,
    g_value,
    potentials,
)

__all__ = [
    "ContactState",
    "check_normal_capacity",
    "check_snap_back",
    "global_traction",
    "initial_state",
    "local_increment",
    "rotate_frame",
    "snap_back_violations",
]


@dataclass(frozen=True)
class ContactState:
    """State of N contact points (all arrays read-only).

    Attributes
    ----------
    traction:
        (N, 3) ``(f_t1, f_t2, f_n)`` [Pa] in the contact frame; ``f_n >= 0``.
    F:
        (N,) size of the sliding-yield surface (mu for the cone).
    R:
        (N,) normal sliding-yield ratio, Eq (22).
    plastic_slip:
        (N,) accumulated plastic sliding u^p [m], Eq (29).
    gap:
        (N,) normal opening [m] while the contact is open (0 when closed).
    frame:
        (N, 3, 3) rows e_1, e_2, n of the co-rotating contact frame in global components.
    """

    traction: np.ndarray
    F: np.ndarray
    R: np.ndarray
    plastic_slip: np.ndarray
    gap: np.ndarray
    frame: np.ndarray

    def __post_init__(self) -> None:
        traction = _readonly_float(self.traction, "traction")
        if traction.ndim != 2 or traction.shape[1] != 3:
            raise ParameterError("traction", traction.shape, "shape (N, 3)")
        n = traction.shape[0]
        object.__setattr__(self, "traction", traction)
        for name in ("F", "R", "plastic_slip", "gap"):
            arr = _readonly_float(getattr(self, name), name)
            if arr.shape != (n,):
                raise ParameterError(name, arr.shape, f"shape ({n},)")
            object.__setattr__(self, name, arr)
        frame = _readonly_float(self.frame, "frame")
        if frame.shape != (n, 3, 3):
            raise ParameterError("frame", frame.shape, f"shape ({n}, 3, 3)")
        object.__setattr__(self, "frame", frame)

    @property
    def n_points(self) -> int:
        """Number of contact points N."""
        return int(self.traction.shape[0])

    @property
    def is_open(self) -> np.ndarray:
        """(N,) True where the contact is open (zero normal traction)."""
        return np.asarray(self.traction[:, 2] <= 0.0)

    def replace(self, **changes: Any) -> ContactState:
        """A new state with some arrays replaced."""
        values = {f.name: getattr(self, f.name) for f in fields(self)}
        values.update(changes)
        return ContactState(**values)

    @classmethod
    def _trusted(cls, **arrays: np.ndarray) -> ContactState:
        """Build a state from arrays produced by the kernel (already checked; made read-only)."""
        obj = object.__new__(cls)
        for name, arr in arrays.items():
            arr.setflags(write=False)
            object.__setattr__(obj, name, arr)
        return obj

    @classmethod
    def _views(cls, **arrays: np.ndarray) -> ContactState:
        """A state over caller-owned output buffers (kept writeable; see update's ``out``)."""
        obj = object.__new__(cls)
        for name, arr in arrays.items():
            object.__setattr__(obj, name, arr)
        return obj

    def take(self, index: Any) -> ContactState:
        """The sub-state of the points selected by ``index`` (mask or integer array)."""
        return ContactState(**{f.name: getattr(self, f.name)[index] for f in fields(self)})


def _readonly_float(value: Any, name: str) -> np.ndarray:
    arr = np.array(value, dtype=np.float64, copy=True)
    if not np.all(np.isfinite(arr)):
        raise ParameterError(name, value, "finite values (no NaN or infinity)")
    arr.setflags(write=False)
    return arr


def initial_state(
    params: SubloadingParams,
    normal_traction: Any,
    tangential_traction: Any = (0.0, 0.0),
    *,
    F: Any = None,
    n_points: int | None = None,
    frame: Any = None,
) -> ContactState:
    """A virgin (fully recovered) contact state.

    The initial ratio is ``R = f(f, beta)/F`` (Eq 22): ``|beta|/mu_s`` for the cone
    with rotation, ``f_n g(|beta|/M)/F_s`` for a closed surface. The state is checked
    for the domain of the law (``f_n < F_k`` for closed surfaces: the normal traction
    must lie inside the kinetic sliding-yield surface; ``R <= 1``) and for the
    no-snap-back condition (:func:`check_snap_back`).

    Parameters
    ----------
    params:
        The law's parameters (scalars or per point).
    normal_traction:
        f_n [Pa] > 0, scalar or (N,).
    tangential_traction:
        (f_t1, f_t2) [Pa] in the contact frame, shape (2,) or (N, 2). Default zero.
    F:
        Initial size; default the static value (F_s or mu_s): a fully recovered contact.
    n_points:
        N, when every other input is shared.
    frame:
        (3, 3) or (N, 3, 3) rows e_1, e_2, n; default the global axes.
    """
    fn = np.asarray(normal_traction, dtype=np.float64)
    ft = np.asarray(tangential_traction, dtype=np.float64)
    if ft.shape[-1:] != (2,) or ft.ndim > 2:
        raise ParameterError("tangential_traction", ft, "shape (2,) or (N, 2)")
    sizes = {a.shape[0] for a in (fn, ft[..., 0]) if a.ndim == 1}
    if params.per_point:
        sizes.add(params.n_points)
    if n_points is not None:
        if int(n_points) < 1:
            raise ParameterError("n_points", n_points, "n_points >= 1")
        sizes.add(int(n_points))
    if len(sizes) > 1:
        raise ParameterError("initial state arrays", sorted(sizes), "one common number of points N")
    n = sizes.pop() if sizes else 1
    fn = np.broadcast_to(fn, (n,)).astype(np.float64)
    ft = np.broadcast_to(ft, (n, 2)).astype(np.float64)
    if not np.all(np.isfinite(fn)) or np.any(fn <= 0.0):
        raise ParameterError("normal_traction", fn, "finite f_n > 0 (compression positive)")
    static = np.broadcast_to(params.static, (n,))
    kinetic = np.broadcast_to(params.kinetic, (n,))
    F0 = static.copy() if F is None else np.broadcast_to(np.asarray(F, np.float64), (n,)).copy()
    if not np.all(np.isfinite(F0)) or np.any(kinetic > F0) or np.any(static < F0):
        raise ParameterError("F", F0, "F_k <= F <= F_s (mu_k <= mu <= mu_s for the cone)")
    if not params.is_cone and np.any(fn >= kinetic):
        raise ParameterError(
            "normal_traction",
            fn,
            "f_n < F_k for a closed surface (the normal traction must stay inside "
            "the kinetic sliding-yield surface)",
        )
    traction = np.column_stack([ft, fn])
    R = ratio_of(params, traction, F0)
    if np.any(R > 1.0):
        outside = R > 1.0
        if not np.any(ft[outside]) and np.any(params.rotation):
            # no tangential traction: the rotation alone put the start outside (Eq 79)
            i = int(np.flatnonzero(outside)[0])
            raise ParameterError(
                "rotation",
                np.asarray(params.rotation),
                f"a rotation that keeps the initial traction inside the sliding-yield "
                f"surface (with f_t = 0 and f_n = {fn[i]:.6g} Pa: R = {R[i]:.6g} > 1)",
            )
        raise ParameterError("tangential_traction", ft, "inside the sliding-yield surface (R <= 1)")
    check_snap_back(params, fn)
    if frame is None:
        frame_arr = np.broadcast_to(np.eye(3), (n, 3, 3))
    else:
        frame_arr = np.broadcast_to(np.asarray(frame, np.float64), (n, 3, 3))
        _check_rotation("frame", frame_arr)
    return ContactState(
        traction=traction,
        F=F0,
        R=R,
        plastic_slip=np.zeros(n),
        gap=np.zeros(n),
        frame=frame_arr,
    )


def ratio_of(params: SubloadingParams, traction: np.ndarray, F: np.ndarray) -> np.ndarray:
    """R = f(f, beta)/F (Eq 22) for tractions (N, 3) in the contact frame."""
    n = traction.shape[0]
    code = SURFACE_CODES[params.surface]
    beta = np.broadcast_to(params.rotation, (n, 2))
    axes = np.broadcast_to(params.axis_factors, (n, 2))
    angle = np.broadcast_to(params.orthotropy_angle, (n,))
    c, s = np.cos(angle), np.sin(angle)
    fhat = traction[:, :2] - traction[:, 2:3] * beta
    p1 = c * fhat[:, 0] + s * fhat[:, 1]
    p2 = -s * fhat[:, 0] + c * fhat[:, 1]
    w = np.ascontiguousarray(np.hypot(p1 / axes[:, 0], p2 / axes[:, 1]))
    if params.is_cone:  # Phi = w/f_n only: the derivatives (w/f_n^2) underflow at tiny f_n
        return w / traction[:, 2] / F
    phi = np.empty(n)
    potentials(code, params.tear_k, w, np.ascontiguousarray(traction[:, 2]), phi)
    return phi / F


def snap_back_violations(params: SubloadingParams, normal_traction: Any) -> list[str]:
    """Per point: "" where the no-snap-back condition holds at ``normal_traction``, else why.

    Eq 44: near R = 1 the local problem has a unique root only if the elastic
    stiffness exceeds the softening slope: cone ``alpha_t > A_max f_n kappa (mu/mu_k - 1)^m``
    for all mu in [mu_k, mu_s]; closed surfaces ``alpha_t g'(chi*)/A_max > kappa (F/F_k -
    1)^m`` on the yield surface ``f_n g(chi*) = F`` for F in [F_k, F_s] (checked on a grid
    of 65 values of F, the end points included). Normal tractions at or above F_k on a
    closed surface are left to the domain checks.
    """
    reasons = [""] * int(np.size(normal_traction))
    for i, reason in _snap_back_failures(params, normal_traction).items():
        reasons[i] = reason
    return reasons


def _snap_back_failures(params: SubloadingParams, normal_traction: Any) -> dict[int, str]:
    """:func:`snap_back_violations` for the failing points only: point -> why (in order)."""
    fn = np.atleast_1d(np.asarray(normal_traction, dtype=np.float64))
    if fn.size == 1 and params.n_points > 1:  # one traction for every point of the law
        fn = np.broadcast_to(fn, (params.n_points,))
    n = fn.shape[0]
    # shared values stay scalars (0-d): broadcast by the arithmetic, not N copies
    alpha_t, kappa, m, static, kinetic = (
        np.asarray(v, dtype=np.float64)
        for v in (params.alpha_t, params.kappa, params.m, params.static, params.kinetic)
    )
    a_max = np.max(np.asarray(params.axis_factors, dtype=np.float64), axis=-1)
    for v in (alpha_t, kappa, m, static, kinetic, a_max):
        np.broadcast_to(v, (n,))  # per-point values for other than N points: ValueError
    out: dict[int, str] = {}
    if params.is_cone:
        slope = a_max * fn * kappa * (static / kinetic - 1.0) ** m
        for i in np.flatnonzero(~(alpha_t > slope)).tolist():
            out[i] = (
                f"alpha_t > C_max f_n kappa (mu_s/mu_k - 1)^m = {slope[i]:.6g} at f_n = "
                f"{fn[i]:.6g} Pa (no snap-back in softening: below it the local solution "
                "may not be unique)"
            )
        return out
    inside = (fn > 0.0) & (fn < kinetic)
    if not inside.any():
        return out
    alpha_t, kappa, m, static, kinetic = (
        np.broadcast_to(v, (n,)) for v in (alpha_t, kappa, m, static, kinetic)
    )
    a_max = np.broadcast_to(a_max, (n,))
    failed_at = np.empty(n)
    _closed_snap_back(
        SURFACE_CODES[params.surface], params.tear_k, np.ascontiguousarray(fn),
        np.ascontiguousarray(kinetic, dtype=np.float64),
        np.ascontiguousarray(static, dtype=np.float64),
        np.ascontiguousarray(kappa, dtype=np.float64), np.ascontiguousarray(m, dtype=np.float64),
        np.ascontiguousarray(alpha_t, dtype=np.float64), np.ascontiguousarray(a_max),
        failed_at,
    )  # fmt: skip
    for point in np.flatnonzero(~np.isnan(failed_at)).tolist():
        out[point] = (
            f"alpha_t g'(chi*)/M_max > kappa (F/F_k - 1)^m on the yield surface "
            f"(no snap-back in softening; fails at F = {failed_at[point]:.6g}, "
            f"f_n = {fn[point]:.6g}: the local solution may not be unique)"
        )
    return out


@njit(cache=True)
def _closed_snap_back(code, tear_k, fn, Fk, Fs, kappa, m, alpha_t, a_max, failed_at):  # fmt: skip
    """The closed-surface check of :func:`snap_back_violations`, compiled, per point.

    ``failed_at[i]`` = the first F of the 65-value grid on [F_k, F_s] where
    ``alpha_t g'(chi*)/A_max > kappa (F/F_k - 1)^m`` fails (chi* = g^-1(F/f_n)), NaN where
    it holds everywhere or where ``f_n`` is outside (0, F_k).
    """
    for i in range(fn.size):
        failed_at[i] = math.nan
        if not (fn[i] > 0.0 and fn[i] < Fk[i]):
            continue
        for j in range(65):
            F = Fk[i] + (Fs[i] - Fk[i]) * (j / 64.0)
            chi = g_inverse_scalar(code, F / fn[i], tear_k)
            dg = g_value(code, tear_k, chi)[1]
            softening = kappa[i] * max(F / Fk[i] - 1.0, 0.0) ** m[i]
            if not alpha_t[i] * dg / a_max[i] > softening:
                failed_at[i] = F
                break


def check_snap_back(
    params: SubloadingParams, normal_traction: Any, field_name: str = "alpha_t"
) -> None:
    """Raise ParameterError unless the no-snap-back condition holds at ``normal_traction``.

    See :func:`snap_back_violations`; ``field_name`` names the input that set the normal
    traction in the message when it is not the law (e.g. a programme segment).
    """
    failures = _snap_back_failures(params, normal_traction)
    tractions = np.atleast_1d(np.asarray(normal_traction, dtype=np.float64))
    if tractions.size == 1:  # one traction for every point of the law
        tractions = np.broadcast_to(tractions, (params.n_points,))
    n = tractions.size
    for i, reason in failures.items():
        if reason:
            alpha_t = float(np.broadcast_to(params.alpha_t, (n,))[i])
            if field_name == "alpha_t":
                raise ParameterError("alpha_t", alpha_t, reason)
            fn = float(tractions[i])
            raise ParameterError(
                field_name, fn, f"a normal traction at which alpha_t = {alpha_t:.6g} keeps {reason}"
            )


def check_normal_capacity(
    params: SubloadingParams, normal_traction: Any, field_name: str = "F_k"
) -> None:
    """Raise ParameterError when a closed surface softened to F_k cannot carry ``normal_traction``.

    A closed surface ``f_n g(chi) = F`` (Eq 48, g >= g(0) = 1) holds no point with
    ``f_n > F``, and sliding softens F toward F_k (Eq 25): a contact that slides under a
    normal traction at or above F_k leaves the surface. The message blames ``F_k``, or
    ``field_name`` when the traction is the input to blame. The cone has no such bound.
    """
    if params.is_cone:
        return
    fn, kinetic = np.broadcast_arrays(
        np.atleast_1d(np.asarray(normal_traction, dtype=np.float64)),
        np.asarray(params.kinetic, dtype=np.float64),
    )
    over = np.flatnonzero(~(fn < kinetic))
    if over.size == 0:
        return
    i = int(over[0])
    if field_name == "F_k":
        raise ParameterError(
            "F_k",
            float(kinetic[i]),
            f"F_k > the normal traction {fn[i]:.6g} Pa: a closed surface softened to F_k "
            "carries at most f_n = F_k",
        )
    raise ParameterError(
        field_name, float(fn[i]), f"a normal traction below F_k = {kinetic[i]:.6g} Pa"
    )


def _check_rotation(name: str, Q: np.ndarray) -> None:
    eye = np.eye(3)
    err = np.abs(np.einsum("...ij,...kj->...ik", Q, Q) - eye).max() if Q.size else 0.0
    det = np.linalg.det(Q)
    if not (err < 1e-10 and np.all(np.abs(det - 1.0) < 1e-10)):
        raise ParameterError(
            name, "non-orthonormal matrix", "proper rotation matrices (Q Q^T = I, det Q = 1)"
        )


def rotate_frame(state: ContactState, rotation: Any) -> ContactState:
    """Rotate the contact frame rigidly by the incremental rotation ``rotation``.

    ``rotation`` is a proper rotation matrix (3, 3) or (N, 3, 3) in global components.
    The co-rotating components of the traction (and of beta, which is fixed to the
    surface, Eq 19) are unchanged: this is the objective update of Eq (81),
    done before each increment. Only ``frame`` changes, to ``frame @ rotation.T`` (each basis vector
    is rotated).
    """
    Q = np.broadcast_to(np.asarray(rotation, dtype=np.float64), (state.n_points, 3, 3))
    if not np.all(np.isfinite(Q)):
        raise ParameterError("rotation", rotation, "finite values")
    _check_rotation("rotation", Q)
    new_frame = np.einsum("nij,nkj->nik", state.frame, Q)
    return state.replace(frame=new_frame)


def global_traction(state: ContactState) -> np.ndarray:
    """Traction vectors on the body in global components (Eq 9).

    ``f = f_t1 e1 + f_t2 e2 - f_n n``; returns (N, 3).
    """
    coeffs = state.traction * np.array([1.0, 1.0, -1.0])
    return np.einsum("ni,nij->nj", coeffs, state.frame)


def local_increment(state: ContactState, slip_increment_global: Any) -> np.ndarray:
    """Contact-frame slip increment from a global one: ``(du.e1, du.e2, -du.n)`` (Eqs 2–3)."""
    du = np.broadcast_to(np.asarray(slip_increment_global, dtype=np.float64), (state.n_points, 3))
    local = np.einsum("nij,nj->ni", state.frame, du)
    return local * np.array([1.0, 1.0, -1.0])
