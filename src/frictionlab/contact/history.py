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

from frictionlab._frames import TableResult

__all__ = ["ContactHistory", "front_arrival", "front_line", "slip_front"]


@dataclass(repr=False)
class ContactHistory(TableResult):
    """Arrays over recorded steps S (rows) and contact points P (columns).

    Attributes
    ----------
    time, stage:
        (S,) time [s] and the index of the stage (0 = normal phase).
    top_displacement, top_displacement_y:
        (S,) mean x (and y, 3-D) displacement of the top face [m].
    top_shear, top_shear_y:
        (S,) mean shear traction applied on the top along x (and y) [Pa] (force control).
    tangential_force, tangential_force_y, normal_force:
        (S,) Q (its x and y components) and P [N/m per unit depth in 2-D, N in 3-D].
    iterations, cuts:
        (S,) Newton iterations of the step and step cuts before it converged.
    residuals:
        Relative residual norms of every iterate, one list per step.
    x, y, weight:
        (P,) positions [m] (y = 0 in 2-D) and quadrature weights [m or m^2].
    slip, slip_y, approach:
        (S, P) block displacement along x (and y) relative to the base [m] and normal
        approach (``-u_y`` in 2-D, ``-u_z`` in 3-D) [m] at the contact points.
    plastic_slip, traction_t, traction_t_y, traction_n, R, F, status:
        (S, P) the law's state: accumulated plastic slip u^p [m], the traction on the
        block along x and y [Pa], f_n [Pa], the ratio R, the size F, and the status code
        (0 stick, 1 slip, 2 open, 3 failed).
    nodes, cells, dof_x, dof_y:
        The mesh, for pictures.
    displacement:
        Nodal displacement vectors kept for pictures: ``{"final": u, "peak": u}``.
    nodal_displacement:
        (S, n_dofs) nodal displacement of every row [m] when the run recorded it
        (``run_contact(record_displacement=True)``, for field output), else None.
    """

    time: np.ndarray
    stage: np.ndarray
    top_displacement: np.ndarray
    top_displacement_y: np.ndarray
    top_shear: np.ndarray
    top_shear_y: np.ndarray
    tangential_force: np.ndarray
    tangential_force_y: np.ndarray
    normal_force: np.ndarray
    iterations: np.ndarray
    cuts: np.ndarray
    residuals: list[list[float]]
    x: np.ndarray
    y: np.ndarray
    weight: np.ndarray
    slip: np.ndarray
    slip_y: np.ndarray
    approach: np.ndarray
    plastic_slip: np.ndarray
    traction_t: np.ndarray
    traction_t_y: np.ndarray
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
    nodal_displacement: np.ndarray | None = None

    @property
    def n_rows(self) -> int:
        """Number of recorded rows (the initial row included)."""
        return int(self.time.shape[0])

    @property
    def dim(self) -> int:
        """2 (plane strain) or 3."""
        return int(self.nodes.shape[0])

    @property
    def width(self) -> float:
        """Width of the block [m] (the extent of the mesh along x)."""
        return float(np.max(self.nodes[0]) - np.min(self.nodes[0]))

    @property
    def friction_ratio(self) -> np.ndarray:
        """(S,) Q/P, signed along x for a 2-D block, |Q|/P for a 3-D block; 0 where P = 0."""
        P = self.normal_force
        Q = (
            self.tangential_force
            if self.dim == 2
            else np.hypot(self.tangential_force, self.tangential_force_y)
        )
        return np.divide(Q, P, out=np.zeros_like(P), where=P > 0)

    @property
    def travel(self) -> np.ndarray:
        """(S,) top displacement along the sliding direction [m]: the direction of the
        first tangential stage (x when it has none, or in 2-D)."""
        direction = np.array([1.0, 0.0])
        for stage in self.stages[1:]:
            step = np.asarray(stage["end"], dtype=np.float64) - np.asarray(stage["start"])
            if self.dim == 3 and np.hypot(*step) > 0:
                direction = step / np.hypot(*step)
                break
        return direction[0] * self.top_displacement + direction[1] * self.top_displacement_y

    @property
    def peak_index(self) -> int:
        """Row of the largest |Q| (the static peak of a first slide)."""
        return int(np.argmax(np.hypot(self.tangential_force, self.tangential_force_y)))

    def columns(self, front_ratio: float = 0.99) -> dict[str, np.ndarray]:
        """The global table (global.csv), one row per recorded step; the slip front is
        :func:`slip_front` at ``front_ratio``; the ``_y`` columns only for a 3-D block."""
        three = self.dim == 3
        cols: dict[str, np.ndarray] = {"time": self.time, "stage": self.stage}
        cols["top_displacement"] = self.top_displacement
        if three:
            cols["top_displacement_y"] = self.top_displacement_y
        cols["top_shear"] = self.top_shear
        if three:
            cols["top_shear_y"] = self.top_shear_y
        cols["tangential_force"] = self.tangential_force
        if three:
            cols["tangential_force_y"] = self.tangential_force_y
        cols["normal_force"] = self.normal_force
        cols["friction_ratio"] = self.friction_ratio
        cols["slip_front"] = slip_front(self, front_ratio)
        cols["iterations"] = self.iterations
        cols["cuts"] = self.cuts
        return cols

    def units(self) -> dict[str, str]:
        """Units of :meth:`columns` (forces per unit depth, N/m, in 2-D; N in 3-D)."""
        force = "N/m" if self.dim == 2 else "N"
        units = {
            "time": "s", "stage": "-", "top_displacement": "m", "top_displacement_y": "m",
            "top_shear": "Pa", "top_shear_y": "Pa", "tangential_force": force,
            "tangential_force_y": force, "normal_force": force, "friction_ratio": "-",
            "slip_front": "m", "iterations": "-", "cuts": "-",
        }  # fmt: skip
        if self.dim == 2:
            return {k: v for k, v in units.items() if not k.endswith("_y")}
        return units


def front_line(history: ContactHistory) -> np.ndarray:
    """Indices of the contact points along which the front is measured, in order of x:
    every point of a 2-D block; for a 3-D block the line nearest the middle of the depth."""
    y = history.y
    if history.dim == 3 and y.size:
        middle = y[np.argmin(np.abs(y - 0.5 * (y.min() + y.max())))]
        chosen = np.flatnonzero(np.isclose(y, middle))
    else:
        chosen = np.arange(history.x.size)
    return chosen[np.argsort(history.x[chosen], kind="stable")]


def slip_front(history: ContactHistory, ratio: float = 0.99) -> np.ndarray:
    """(S,) extent [m] of the sliding zone grown from the trailing edge ``x = 0``.

    A point is released when it slides in the normal sliding-yield state,
    ``R >= ratio`` (the subloading law slides plastically at every R > 0, so the status
    alone does not separate the precursor zone from the sub-sliding rest), or when it
    has lifted off (open). Per row, the front is the step ``[0, x_f)`` released, the rest
    stuck, that misclassifies the least interface length (quadrature weights): a point
    re-closing at the lift-off edge, briefly below ``ratio``, does not pull the front back
    to the edge. The front then lies between the last point inside and the first point
    outside, where R crosses ``ratio`` on the straight line between them (an open point
    counts as R = 1). 0 when no point is released, the block's width when all are.
    Measured along :func:`front_line`.
    """
    line = front_line(history)
    x = history.x[line]
    weight = np.abs(history.weight[line])
    R = history.R[:, line]
    status = history.status[:, line]
    released = ((ratio <= R) & (status == 1)) | (status == 2)
    zero = np.zeros((R.shape[0], 1))
    # misclassified length of a front after the first k points, k = 0..P
    stuck_inside = np.hstack([zero, np.cumsum(weight * ~released, axis=1)])
    released_in = np.hstack([zero, np.cumsum(weight * released, axis=1)])
    misfit = stuck_inside + (released_in[:, -1:] - released_in)
    inside = np.argmin(misfit, axis=1)  # ties: the shortest zone
    extent = np.where(inside == 0, 0.0, history.width)
    effective = np.where(status == 2, 1.0, R)
    rows = np.flatnonzero((inside > 0) & (inside < x.size))
    k = inside[rows]
    r_in, r_out = effective[rows, k - 1], effective[rows, k]
    drop = r_in - r_out
    fraction = np.divide(r_in - ratio, drop, out=np.full(rows.size, 0.5), where=drop > 0)
    fraction = np.clip(fraction, 0.0, 1.0)
    extent[rows] = x[k - 1] + fraction * (x[k] - x[k - 1])
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
    magnitude = np.hypot(history.tangential_force, history.tangential_force_y)
    peak = float(np.max(magnitude))
    return {
        "row": k,
        "time": float(history.time[k]),
        "top_displacement": float(history.top_displacement[k]),
        "tangential_force": float(history.tangential_force[k]),
        "fraction_of_peak": float(magnitude[k] / peak) if peak > 0 else 0.0,
    }
