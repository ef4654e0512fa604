"""The subloading-friction law at the contact points of the block's bottom edge.

Frame and signs (spec §1, §4.1). The block is the body, the rigid base the counter
body. The contact frame of every point is ``e_1 = +x`` (sliding direction),
``e_2 = +z`` (out of plane) and ``n = -y`` (outward normal of the block's bottom), a
right-handed frame. The slip of the base relative to the block is ``-u`` (the base does
not move), so the law's increment is ``(du_t1, du_t2, du_n) = (-du_x, 0, -du_y)``
(``du_n`` positive when the block approaches the base) and the traction on the block is
``(f_x, f_y) = (f_t1, f_n)`` (Eq 9). The out-of-plane slip is zero, so ``f_t2`` stays 0
for laws whose orthotropy axes are aligned with x (a rotated orthotropy would need the
3-D block).

Contact forces on the block, per unit depth: ``r_c = B^T (w f)``; their stiffness
``-d r_c/du = B^T (w [[C_11, C_13], [C_31, C_33]]) B`` with ``C`` the law's
consistent tangent d(traction)/d(slip increment) [Pa/m] (spec §4.4).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from frictionlab.contact.mesh import Discretisation
from frictionlab.subloading import ContactState, Status, StepResult, SubloadingParams, update

__all__ = [
    "CONTACT_FRAME",
    "TANGENTS",
    "InterfaceResponse",
    "contact_stiffness",
    "open_state",
    "respond",
]

#: Rows e_1, e_2, n of the contact frame of every point (global x, y, z components).
CONTACT_FRAME = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
#: Global tangents: the law's consistent tangent, or its elastic moduli C^e (Eq 16).
TANGENTS: tuple[str, ...] = ("consistent", "elastic")


def open_state(params: SubloadingParams, n_points: int) -> ContactState:
    """The virgin interface before loading: touching, traction-free, fully recovered.

    ``F = F_s`` (or mu_s), ``R = 0``, zero gap: the first compression closes it.
    """
    static = np.broadcast_to(np.asarray(params.static, dtype=np.float64), (n_points,))
    return ContactState(
        traction=np.zeros((n_points, 3)),
        F=static.copy(),
        R=np.zeros(n_points),
        plastic_slip=np.zeros(n_points),
        gap=np.zeros(n_points),
        frame=np.broadcast_to(CONTACT_FRAME, (n_points, 3, 3)),
    )


@dataclass(frozen=True)
class InterfaceResponse:
    """Law update at the contact points for one trial displacement increment."""

    result: StepResult
    force: np.ndarray  #: (n_dofs,) contact nodal forces on the block [N/m]
    #: (4, n_points) tangent moduli ``C_11, C_13, C_31, C_33`` [Pa/m] in (x, y) terms
    moduli: np.ndarray


def respond(
    disc: Discretisation,
    params: SubloadingParams,
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
    dux = disc.interp_x @ du
    duy = disc.interp_y @ du
    slip = np.column_stack([-dux, np.zeros_like(dux), -duy])
    result = update(params, state, slip, dt, raise_on_failure=False)
    f = result.traction
    w = disc.contact_weight
    force = disc.interp_x.T @ (w * f[:, 0]) + disc.interp_y.T @ (w * f[:, 2])
    n = disc.n_points
    alpha_t = np.broadcast_to(np.asarray(params.alpha_t, dtype=np.float64), (n,))
    alpha_n = np.broadcast_to(np.asarray(params.alpha_n, dtype=np.float64), (n,))
    if tangent == "elastic":
        c11, c13, c31, c33 = alpha_t, np.zeros(n), np.zeros(n), alpha_n
    else:
        C = result.tangent
        c11, c13, c31, c33 = C[:, 0, 0], C[:, 0, 2], C[:, 2, 0], C[:, 2, 2]
    is_open = result.status == Status.OPEN
    kink = is_open & (result.state.gap <= 0.0)
    gone = is_open & ~kink
    c11 = np.where(kink, alpha_t, np.where(gone, 0.0, c11))
    c33 = np.where(kink, alpha_n, np.where(gone, 0.0, c33))
    c13 = np.where(is_open, 0.0, c13)
    c31 = np.where(is_open, 0.0, c31)
    moduli = np.stack([c11, c13, c31, c33])
    return InterfaceResponse(result=result, force=force, moduli=moduli)


def contact_stiffness(disc: Discretisation, moduli: np.ndarray) -> sp.csr_matrix:
    """The contact stiffness ``-d r_c/du = B^T (w C) B`` (n_dofs, n_dofs) [N/m^2]."""
    w = disc.contact_weight
    c11, c13, c31, c33 = moduli
    Bx, By = disc.interp_x, disc.interp_y
    stiffness = (
        Bx.T @ sp.diags(w * c11) @ Bx
        + Bx.T @ sp.diags(w * c13) @ By
        + By.T @ sp.diags(w * c31) @ Bx
        + By.T @ sp.diags(w * c33) @ By
    )
    return stiffness.tocsr()
