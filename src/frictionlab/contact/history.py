"""Recorded history of a contact run and the measures read from it (pure data).

Per recorded (converged) step: global quantities per unit depth of the block and, per
contact point, the interface fields. Forces are per unit depth [N/m]; the tangential
force is the friction transmitted by the interface, positive when it opposes sliding
along +x: ``Q = -int f_x dx``; the normal force ``P = int f_n dx``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["ContactHistory", "front_arrival", "slip_front"]


@dataclass
class ContactHistory:
    """Arrays over recorded steps S (rows) and contact points P (columns).

    Attributes
    ----------
    time, stage:
        (S,) time [s] and the index of the stage (0 = normal phase).
    top_displacement:
        (S,) mean x displacement of the top edge [m].
    top_shear:
        (S,) mean shear traction applied on the top [Pa] (force control; else 0).
    tangential_force, normal_force:
        (S,) Q and P [N/m].
    iterations, cuts:
        (S,) Newton iterations of the step and step cuts before it converged.
    residuals:
        Relative residual norms of every iterate, one list per step.
    x, weight:
        (P,) positions [m] and quadrature weights [m] of the contact points.
    slip, approach:
        (S, P) block displacement along x relative to the base [m] and normal approach
        ``-u_y`` [m] at the contact points.
    plastic_slip, traction_t, traction_n, R, F, status:
        (S, P) the law's state: accumulated plastic slip u^p [m], f_t1 [Pa] (on the
        block, along x), f_n [Pa], the ratio R, the size F, and the status code
        (0 stick, 1 slip, 2 open, 3 failed).
    nodes, cells, dof_x, dof_y:
        The mesh, for pictures.
    displacement:
        Nodal displacement vectors kept for pictures: ``{"final": u, "peak": u}``.
    """

    time: np.ndarray
    stage: np.ndarray
    top_displacement: np.ndarray
    top_shear: np.ndarray
    tangential_force: np.ndarray
    normal_force: np.ndarray
    iterations: np.ndarray
    cuts: np.ndarray
    residuals: list[list[float]]
    x: np.ndarray
    weight: np.ndarray
    slip: np.ndarray
    approach: np.ndarray
    plastic_slip: np.ndarray
    traction_t: np.ndarray
    traction_n: np.ndarray
    R: np.ndarray
    F: np.ndarray
    status: np.ndarray
    nodes: np.ndarray
    cells: np.ndarray
    dof_x: np.ndarray
    dof_y: np.ndarray
    displacement: dict[str, np.ndarray] = field(default_factory=dict)
    success: bool = True
    message: str = "completed"
    stages: list[dict[str, Any]] = field(default_factory=list)

    @property
    def n_rows(self) -> int:
        """Number of recorded rows (the initial row included)."""
        return int(self.time.shape[0])

    @property
    def width(self) -> float:
        """Width of the block [m] (the extent of the mesh along x)."""
        return float(np.max(self.nodes[0]) - np.min(self.nodes[0]))

    @property
    def friction_ratio(self) -> np.ndarray:
        """(S,) Q/P, 0 where the normal force is zero."""
        P = self.normal_force
        return np.divide(self.tangential_force, P, out=np.zeros_like(P), where=P > 0)

    @property
    def peak_index(self) -> int:
        """Row of the largest |Q| (the static peak of a first slide)."""
        return int(np.argmax(np.abs(self.tangential_force)))


def slip_front(history: ContactHistory, ratio: float = 0.99) -> np.ndarray:
    """(S,) extent [m] of the sliding zone grown from the trailing edge ``x = 0``.

    A point is released when it slides in the normal sliding-yield state,
    ``R >= ratio`` (the subloading law slides plastically at every R > 0, so the status
    alone does not separate the precursor zone from the sub-sliding rest), or when it
    has lifted off (open). The extent is the position of the first point that is
    neither (the full width when none is left).
    """
    sliding = ((ratio <= history.R) & (history.status == 1)) | (history.status == 2)
    width = history.width
    extent = np.empty(sliding.shape[0])
    for k, row in enumerate(sliding):
        stuck = np.flatnonzero(~row)
        extent[k] = width if stuck.size == 0 else (history.x[stuck[0]] if stuck[0] > 0 else 0.0)
    return extent


def front_arrival(history: ContactHistory, ratio: float = 0.99) -> dict[str, float] | None:
    """When the sliding zone first spans the whole interface during the first slide.

    Returns the row, the time, the top displacement, the tangential force there and its
    fraction of the peak force, or None when the front never arrives.
    """
    extent = slip_front(history, ratio)
    width = history.width
    full = np.flatnonzero(extent >= width)
    if full.size == 0:
        return None
    k = int(full[0])
    peak = float(np.max(np.abs(history.tangential_force)))
    return {
        "row": k,
        "time": float(history.time[k]),
        "top_displacement": float(history.top_displacement[k]),
        "tangential_force": float(history.tangential_force[k]),
        "fraction_of_peak": float(abs(history.tangential_force[k]) / peak) if peak > 0 else 0.0,
    }
