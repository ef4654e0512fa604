"""The subloading-friction law at the contact points of the block's bottom face.

Frame and signs: those of the law (:mod:`frictionlab.subloading.state`). The block is the
body, the rigid base the counter body. The contact frame of every point (rows e_1, e_2, n in
global x, y, z components; right-handed):

* 2-D: ``e_1 = +x`` (sliding direction), ``e_2 = +z`` (out of plane), ``n = -y``;
* 3-D: ``e_1 = +x``, ``e_2 = -y``, ``n = -z`` (so the law's orthotropy angle turns from
  +x toward -y, about the outward normal -z).

The slip of the base relative to the block is ``-u`` (the base does not move), so the
law's increment is ``M du`` with ``M = -S Q`` (Q the frame, S = diag(1, 1, -1): the
normal component is the approach, Eqs 2-3); in 2-D ``(du_t1, du_t2, du_n) = (-du_x, 0,
-du_y)``. The traction on the block in global components is ``-M^T f`` (Eq 9); in 2-D
``(f_x, f_y) = (f_t1, f_n)``. The out-of-plane slip of a 2-D block is zero.

Contact forces on the block: ``r_c = sum_a B_a^T (w f_a)``; their stiffness
``-d r_c/du = sum_ab B_a^T (w D_ab) B_b`` with ``D = M^T C M`` and ``C`` the law's
consistent tangent d(traction)/d(slip increment) [Pa/m].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from frictionlab.contact.frictionless import Frictionless, frictionless_update
from frictionlab.contact.mesh import Discretisation
from frictionlab.subloading import ContactState, Status, StepResult, SubloadingParams, update

__all__ = [
    "FRAMES",
    "TANGENTS",
    "InterfaceResponse",
    "contact_stiffness",
    "open_state",
    "respond",
    "slip_map",
]

#: Rows e_1, e_2, n of the contact frame (global x, y, z components) for d = 2 and 3.
FRAMES = {
    2: np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]),
    3: np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]),
}
#: Global tangents: the law's consistent tangent, or its elastic moduli C^e (Eq 16).
TANGENTS: tuple[str, ...] = ("consistent", "elastic")


def slip_map(dim: int) -> np.ndarray:
    """``M`` (3, d): the law's slip increment from the block's displacement increment."""
    return -(np.diag([1.0, 1.0, -1.0]) @ FRAMES[dim])[:, :dim]


def open_state(
    params: SubloadingParams | Frictionless,
    n_points: int,
    dim: int = 2,
    gap: np.ndarray | None = None,
) -> ContactState:
    """The virgin interface before loading: traction-free, fully recovered.

    ``F = F_s`` (or mu_s), ``R = 0``; the gap is ``gap`` [m] (the base's shape, zero by
    default: touching, so that the first compression closes it).
    """
    static = np.broadcast_to(np.asarray(params.static, dtype=np.float64), (n_points,))
    return ContactState(
        traction=np.zeros((n_points, 3)),
        F=static.copy(),
        R=np.zeros(n_points),
        plastic_slip=np.zeros(n_points),
        gap=np.zeros(n_points) if gap is None else np.array(gap, dtype=np.float64),
        frame=np.broadcast_to(FRAMES[dim], (n_points, 3, 3)),
    )


@dataclass(frozen=True)
class InterfaceResponse:
    """Law update at the contact points for one trial displacement increment."""

    result: StepResult
    force: np.ndarray  #: (n_dofs,) contact nodal forces on the block [N/m or N]
    traction: np.ndarray  #: (n_points, d) traction on the block, global components [Pa]
    moduli: np.ndarray  #: (n_points, d, d) ``D = -d f/du`` in global components [Pa/m]


def respond(
    disc: Discretisation,
    params: SubloadingParams | Frictionless,
    state: ContactState,
    du: np.ndarray,
    dt: float,
    tangent: str = "consistent",
) -> InterfaceResponse:
    """Update the law from ``state`` by the nodal displacement increment ``du`` [m].

    Open points get zero stiffness, except at the closing kink (open with zero gap):
    there the elastic moduli are used, the one-sided derivative that lets the first
    iteration of a loading step close the contact.
    """
    d = disc.dim
    M = slip_map(d)
    dug = np.column_stack([B @ du for B in disc.interp])  # (P, d)
    if isinstance(params, Frictionless):
        result = frictionless_update(params, state, dug @ M.T)
    else:
        result = update(params, state, dug @ M.T, dt, raise_on_failure=False)
    traction = -(result.traction @ M)  # (P, d) global components on the block
    w = disc.contact_weight
    force = sum(B.T @ (w * traction[:, a]) for a, B in enumerate(disc.interp))
    n = disc.n_points
    alpha_t = 0.0 if isinstance(params, Frictionless) else float(np.asarray(params.alpha_t))
    alpha_n = float(np.asarray(params.alpha_n))
    elastic = np.diag([alpha_t, alpha_t, alpha_n])
    C = np.broadcast_to(elastic, (n, 3, 3)) if tangent == "elastic" else result.tangent
    is_open = result.status == Status.OPEN
    kink = is_open & (result.state.gap <= 0.0)
    C = np.where(kink[:, None, None], elastic, np.where(is_open[:, None, None], 0.0, C))
    moduli = np.einsum("ia,pij,jb->pab", M, C, M)
    return InterfaceResponse(
        result=result, force=np.asarray(force), traction=traction, moduli=moduli
    )


def contact_stiffness(disc: Discretisation, moduli: np.ndarray) -> sp.csr_matrix:
    """The contact stiffness ``-d r_c/du = sum_ab B_a^T (w D_ab) B_b`` (n_dofs, n_dofs)."""
    w = disc.contact_weight
    out = sp.csr_matrix((disc.n_dofs, disc.n_dofs))
    for a, Ba in enumerate(disc.interp):
        for b, Bb in enumerate(disc.interp):
            out = out + Ba.T @ sp.diags(w * moduli[:, a, b]) @ Bb
    return out.tocsr()
