"""Plots of the finite-element contact model (matplotlib imported lazily, no pyplot state).

* :func:`plot_contact_friction` — friction ratio Q/P against the top displacement;
* :func:`plot_interface_map` — space-time maps of the ratio R (with open points) and of
  the plastic slip along the interface, with the sliding-zone front;
* :func:`plot_deformed_mesh` — the 2-D mesh, displacements magnified;
* :func:`plot_traction_path` — the 3-D block's friction vector Q/P turning from the
  sliding direction.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from frictionlab.contact.history import ContactHistory, front_line, slip_front
from frictionlab.plotting.law import new_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "plot_contact_friction",
    "plot_deformed_mesh",
    "plot_interface_map",
    "plot_traction_path",
]

UM, MM = 1e6, 1e3


def plot_contact_friction(history: ContactHistory, title: str = "") -> Figure:
    """Q/P against the top displacement [um], the peak marked."""
    fig, (ax,) = new_figure(1, width=6.0, height=3.8)
    rows = history.stage > 0
    if history.dim == 2:
        x = history.top_displacement[rows] * UM
        ratio = history.friction_ratio[rows]
        label, xlabel = "block: Q/P", "top displacement [µm]"
    else:  # the magnitude against the path length of the top
        x = _travel(history)[rows] * UM
        ratio = history.friction_ratio[rows]
        label, xlabel = "block: |Q|/P", "travel of the top [µm]"
    ax.plot(x, ratio, color="C0", lw=1.6, label=label)
    k = int(np.argmax(np.abs(ratio))) if ratio.size else 0
    if ratio.size:
        ax.plot([x[k]], [ratio[k]], "o", color="C3", label=f"peak {ratio[k]:.3f}")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("friction ratio [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=9)
    return fig


def plot_interface_map(history: ContactHistory, ratio: float = 0.99, title: str = "") -> Figure:
    """Maps over the interface and the top travel: R (open points grey) and the plastic
    slip since the normal phase, with the front of the sliding zone (R >= ``ratio``)."""
    from matplotlib import colormaps

    fig, axes = new_figure(2, width=5.0, height=4.0)
    rows = np.flatnonzero(history.stage > 0)
    if rows.size == 0:
        rows = np.arange(history.n_rows)
    # progress along the programme: the path length of the top edge (holds collapse)
    travel = _travel(history)
    t = travel[rows] * UM
    # a 3-D block: the line of contact points nearest the middle of the depth
    y = history.y
    line = front_line(history)
    x = history.x[line] * MM
    R = np.ma.masked_where(history.status[rows][:, line] == 2, history.R[rows][:, line])
    cmap = colormaps["viridis"].with_extremes(bad="0.75")
    extent = (x[0], x[-1], t[0], t[-1])
    im0 = axes[0].pcolormesh(x, t, R, cmap=cmap, vmin=0.0, vmax=1.0, shading="nearest")
    fig.colorbar(im0, ax=axes[0], label="R (grey: open)")
    front = slip_front(history, ratio) * MM
    # one line per stage that moves the top: a hold's front changes at a fixed travel
    label: str | None = f"front: R ≥ {ratio:g}"
    for stage in np.unique(history.stage[rows]):
        mine = rows[history.stage[rows] == stage]
        if mine.size and np.ptp(travel[mine]) > 0:
            if mine[0] > 0 and history.stage[mine[0] - 1] > 0:
                mine = np.concatenate([[mine[0] - 1], mine])  # joined to the stage before
            axes[0].plot(front[mine], travel[mine] * UM, color="w", lw=1.2, label=label)
            label = None
    peak = history.peak_index
    if peak in rows:
        axes[0].axhline(travel[peak] * UM, color="C3", lw=1.0, ls="--", label="peak force")
    axes[0].legend(fontsize=7, loc="lower right")
    slip = (history.plastic_slip[rows] - history.plastic_slip[rows[0]])[:, line] * UM
    im1 = axes[1].pcolormesh(x, t, slip, cmap="magma", shading="nearest")
    fig.colorbar(im1, ax=axes[1], label="plastic slip [µm]")
    for ax in axes:
        where = "" if history.dim == 2 else f", y = {y[line][0] * MM:.3g} mm"
        ax.set_xlabel(f"x from the trailing edge [mm]{where}")
        ax.set_ylabel("travel of the top edge [µm]")
        ax.set_xlim(extent[0], extent[1])
    if title:
        fig.suptitle(title, fontsize=9)
    return fig


def plot_deformed_mesh(
    history: ContactHistory, which: str = "peak", magnification: float | None = None
) -> Figure:
    """The mesh at the peak (or final) step, displacements magnified to be visible."""
    from matplotlib.collections import PolyCollection

    fig, (ax,) = new_figure(1, width=7.0, height=3.2)
    u = history.displacement[which]
    ux, uy = u[history.dof_x], u[history.dof_y]
    nodes = history.nodes
    size = max(np.ptp(nodes[0]), np.ptp(nodes[1]))
    umax = float(np.max(np.hypot(ux, uy)))
    if magnification is None:
        magnification = 0.05 * size / umax if umax > 0 else 1.0
    px = (nodes[0] + magnification * ux) * MM
    py = (nodes[1] + magnification * uy) * MM
    cells = history.cells
    ref = np.stack([nodes[0][cells].T * MM, nodes[1][cells].T * MM], axis=-1)
    moved = np.stack([px[cells].T, py[cells].T], axis=-1)
    ax.add_collection(PolyCollection(list(ref), facecolors="none", edgecolors="0.8", lw=0.4))
    ax.add_collection(
        PolyCollection(list(moved), facecolors="C0", edgecolors="k", lw=0.3, alpha=0.35)
    )
    ax.axhline(0.0, color="k", lw=1.5)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(
        f"deformed mesh at the {which} step, displacements x {magnification:.3g}", fontsize=9
    )
    return fig


def plot_traction_path(history: ContactHistory, title: str = "") -> Figure:
    """The friction vector (Q_x, Q_y)/P of a 3-D block along the programme."""
    fig, (ax,) = new_figure(1, width=5.0, height=4.6)
    rows = history.stage > 0
    P = history.normal_force[rows]
    qx = history.tangential_force[rows] / P
    qy = history.tangential_force_y[rows] / P
    ax.plot(qx, qy, "o-", ms=3, color="C0", label="(Q_x, Q_y)/P")
    travel = np.array([history.top_displacement[-1], history.top_displacement_y[-1]])
    length = float(np.hypot(*travel))
    if length > 0:
        scale = float(np.max(np.hypot(qx, qy)))
        ax.plot(
            [0.0, scale * travel[0] / length],
            [0.0, scale * travel[1] / length],
            "--",
            color="0.4",
            label="sliding direction",
        )
    ax.set_xlabel("Q_x / P [-]")
    ax.set_ylabel("Q_y / P [-]")
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title or "friction vector of the block", fontsize=9)
    return fig


def _travel(history: ContactHistory) -> np.ndarray:
    """(S,) path length of the top face's mean displacement [m]."""
    step = np.hypot(np.diff(history.top_displacement), np.diff(history.top_displacement_y))
    return np.concatenate([[0.0], np.cumsum(step)])
