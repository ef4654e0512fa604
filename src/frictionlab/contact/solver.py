"""Quasi-static solution of the block-on-base contact model with adaptive load steps.

:func:`run_contact` advances the stages of :func:`~frictionlab.contact.loading.plan_stages`
with :func:`~frictionlab.contact.newton.newton_step`. A step that does not converge is
cut in half (at most ``max_cuts`` times below its nominal size); after a step that
converged in at most ``easy_iterations`` iterations the step grows by ``growth``, never
beyond the nominal size. When a step cannot be solved the run stops and the history so
far is returned with ``success = False`` and a one-line ``message``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from frictionlab.contact.block import Block
from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.history import ContactHistory
from frictionlab.contact.interface import TANGENTS, open_state, slip_map
from frictionlab.contact.linear import LINEAR_SOLVERS, estimate, make_solver
from frictionlab.contact.loading import NormalLoad, Segment, Stage, plan_stages
from frictionlab.contact.mesh import Discretisation, discretise
from frictionlab.contact.newton import newton_step
from frictionlab.contact.shapes import Base
from frictionlab.errors import ParameterError
from frictionlab.subloading import (
    ContactState,
    SubloadingParams,
    check_normal_capacity,
    check_snap_back,
)

__all__ = ["DRIVES", "SolverOptions", "SolverSettings", "check_memory", "run_contact"]

#: How the tangential displacement is imposed: on the top edge (default), or on every
#: node (a rigidly translated block: a verification case that isolates the interface).
DRIVES: tuple[str, ...] = ("top", "rigid")

#: ``progress(done, total)``: the time done, in thousandths of the programme's duration.
ProgressCallback = Callable[[int, int], None]


#: The most step cuts: 2**-60 of a step is below the float64 resolution of its time.
MAX_CUTS = 60


@dataclass(frozen=True)
class SolverOptions:
    """Newton and step control.

    Attributes
    ----------
    tolerance:
        Relative residual norm for convergence (default 1e-10).
    max_iterations:
        Newton iterations per step attempt (default 25).
    max_cuts:
        Halvings of a step below its nominal size before the run stops (default 12,
        at most :data:`MAX_CUTS`).
    easy_iterations, growth:
        A step converged within ``easy_iterations`` (default 4) lets the next one grow by
        ``growth`` (default 2), up to the nominal size.
    tangent:
        ``"consistent"`` (the law's algorithmic tangent, default) or ``"elastic"`` (its
        elastic moduli, a fixed secant-type stiffness; for comparison).
    linear_solver:
        ``"direct"`` (CHOLMOD through cvxopt, or SuperLU without it; default) or
        ``"iterative"`` (GMRES + AMG, pyamg): see
        :mod:`~frictionlab.contact.linear`.
    memory_limit:
        Bytes the run may use (the estimate of :func:`~frictionlab.contact.linear.estimate`
        is checked before meshing); None: no check.
    """

    tolerance: float = 1e-10
    max_iterations: int = 25
    max_cuts: int = 12
    easy_iterations: int = 4
    growth: float = 2.0
    tangent: str = "consistent"
    linear_solver: str = "direct"
    memory_limit: float | None = None

    def __post_init__(self) -> None:
        if self.linear_solver not in LINEAR_SOLVERS:
            raise ParameterError(
                "linear_solver", self.linear_solver, "one of " + ", ".join(LINEAR_SOLVERS)
            )
        limit = self.memory_limit
        if limit is not None and (
            isinstance(limit, bool) or not isinstance(limit, int | float) or not limit > 0
        ):
            raise ParameterError("memory_limit", limit, "a number of bytes > 0")
        if not (isinstance(self.tolerance, float | int) and 1e-15 <= self.tolerance < 1e-2):
            raise ParameterError("tolerance", self.tolerance, "1e-15 <= tolerance < 1e-2")
        for name, low, high in (
            ("max_iterations", 1, None),
            ("max_cuts", 0, MAX_CUTS),
            ("easy_iterations", 0, None),
        ):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int) or value < low:
                raise ParameterError(name, value, f"an integer >= {low}")
            if high is not None and value > high:
                raise ParameterError(name, value, f"an integer from {low} to {high}")
        if not (isinstance(self.growth, float | int) and 1.0 <= self.growth <= 10.0):
            raise ParameterError("growth", self.growth, "1 <= growth <= 10")
        if self.tangent not in TANGENTS:
            raise ParameterError("tangent", self.tangent, "one of " + ", ".join(TANGENTS))


_ROW_KEYS = (
    "time", "stage", "top_displacement", "top_displacement_y", "top_shear", "top_shear_y",
    "tangential_force", "tangential_force_y", "normal_force", "iterations", "cuts",
    "residuals", "slip", "slip_y", "approach", "plastic_slip", "traction_t", "traction_t_y",
    "traction_n", "R", "F", "status",
)  # fmt: skip


class _Recorder:
    def __init__(self, disc: Discretisation, state: ContactState, keep_u: bool = False) -> None:
        self.disc = disc
        self.u_rows: list[np.ndarray] | None = [] if keep_u else None
        self.M = slip_map(disc.dim)
        self.rows: dict[str, list[object]] = {k: [] for k in _ROW_KEYS}
        self.peak = (-1.0, np.zeros(disc.n_dofs))
        self.last_u = np.zeros(disc.n_dofs)
        zeros = np.zeros(disc.n_points, np.int8)
        self.add(0.0, 0, np.zeros(disc.n_dofs), np.zeros(2), state, zeros, 0, 0, [])

    def add(
        self,
        t: float,
        stage: int,
        u: np.ndarray,
        shear: np.ndarray,
        state: ContactState,
        status: np.ndarray,
        iterations: int,
        cuts: int,
        residuals: list[float],
    ) -> None:
        d, w = self.disc, self.disc.contact_weight
        f = -(state.traction @ self.M)  # (P, dim) on the block, global components
        three = d.dim == 3
        zero = np.zeros(d.n_points)
        Q = [0.0 - float(np.sum(w * f[:, a])) for a in range(d.dim - 1)] + [0.0]
        top = [float(np.mean(u[d.dofs[a][d.top_nodes]])) for a in range(d.dim - 1)] + [0.0]
        row = {
            "time": t,
            "stage": stage,
            "top_displacement": top[0],
            "top_displacement_y": top[1],
            "top_shear": float(shear[0]),
            "top_shear_y": float(shear[1]),
            "tangential_force": Q[0],
            "tangential_force_y": Q[1],
            "normal_force": float(np.sum(w * state.traction[:, 2])),
            "iterations": iterations,
            "cuts": cuts,
            "residuals": list(residuals),
            "slip": d.interp[0] @ u,
            "slip_y": d.interp[1] @ u if three else zero,
            "approach": -(d.interp[-1] @ u),
            "plastic_slip": state.plastic_slip,
            "traction_t": f[:, 0],
            "traction_t_y": f[:, 1] if three else zero,
            "traction_n": state.traction[:, 2],
            "R": state.R,
            "F": state.F,
            "status": np.asarray(status, dtype=np.int8),
        }
        for key, value in row.items():
            self.rows[key].append(value)
        if self.u_rows is not None:
            self.u_rows.append(u.copy())
        if float(np.hypot(Q[0], Q[1])) > self.peak[0]:
            self.peak = (float(np.hypot(Q[0], Q[1])), u.copy())
        self.last_u = u

    def history(self, success: bool, message: str, stages: list[Stage]) -> ContactHistory:
        d = self.disc
        arrays = {k: np.array(v) for k, v in self.rows.items() if k != "residuals"}
        xy = d.contact_xy
        return ContactHistory(
            **arrays,
            residuals=[list(r) for r in self.rows["residuals"]],  # type: ignore[call-overload]
            x=xy[:, 0],
            y=xy[:, 1] if d.dim == 3 else np.zeros(d.n_points),
            weight=d.contact_weight,
            nodes=d.nodes,
            cells=d.cells,
            dof_x=d.dofs[0],
            dof_y=d.dofs[1],
            displacement={"final": self.last_u.copy(), "peak": self.peak[1]},
            success=success,
            message=message,
            nodal_displacement=None if self.u_rows is None else np.array(self.u_rows),
            stages=[
                {
                    "kind": s.kind,
                    "control": s.control,
                    "start": s.start.tolist(),
                    "end": s.end.tolist(),
                    "duration": s.duration,
                    "steps": s.steps,
                }
                for s in stages
            ],
        )


def check_memory(block: Block, options: SolverOptions) -> None:
    """Refuse ``block`` when the solver's estimated storage exceeds ``memory_limit``."""
    if options.memory_limit is None:
        return
    need = estimate(block, options.linear_solver)["bytes"]
    if need > options.memory_limit:
        raise ParameterError(
            "element_size",
            block.element_size,
            f"a mesh that fits memory_limit = {options.memory_limit:.3g} bytes (this one "
            f"needs about {need:.3g} with the {options.linear_solver} solver)",
        )


#: Newton and step control, the ``settings=`` of :func:`run_contact` (one name for solver
#: settings across frictionlab); :class:`SolverOptions` is the same class.
SolverSettings = SolverOptions


def run_contact(
    block: Block,
    params: SubloadingParams | Frictionless,
    normal: NormalLoad,
    program: Sequence[Segment],
    *,
    settings: SolverOptions | None = None,
    drive: str = "top",
    progress: ProgressCallback | None = None,
    discretisation: Discretisation | None = None,
    base: Base | None = None,
    record_displacement: bool = False,
    options: SolverOptions | None = None,
) -> ContactHistory:
    """Press the block on the base, then run the tangential programme.

    Parameters
    ----------
    block, params:
        The elastic block and the interface law (shared by all contact points).
    normal, program:
        The normal phase and the tangential segments (:mod:`~frictionlab.contact.loading`).
    settings:
        Newton and step control (:class:`SolverSettings`, also named
        :class:`SolverOptions`); ``options=`` is its deprecated name (one release).
    drive:
        ``"top"`` (default) or ``"rigid"`` (every node moved along x; displacement
        control only) — see :data:`DRIVES`.
    progress:
        Called as ``progress(done, 1000)`` after every step, ``done`` the thousandths
        of the programme's time completed (the one progress convention).
    discretisation:
        A prebuilt mesh of ``block`` (else built here).
    base:
        The rigid base's shape (:class:`~frictionlab.contact.shapes.Base`; flat when
        None): the law's initial gap at the contact points.
    record_displacement:
        Keep the nodal displacement of every recorded row (for field output; memory
        rows x dofs x 8 bytes).

    Returns
    -------
    ContactHistory
        ``success`` False with a ``message`` when a step failed; the rows before it kept.
    """
    if options is not None:
        if settings is not None:
            raise ParameterError("options", options, "settings= alone (options= is its old name)")
        import warnings

        warnings.warn(
            "run_contact(options=) is deprecated: pass settings=SolverSettings(...)",
            DeprecationWarning,
            stacklevel=2,
        )
    options = settings if settings is not None else options
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - part of the extra `fem`; only slower without
        return _run(
            block, params, normal, program, options, drive, progress, discretisation, base,
            record_displacement,
        )  # fmt: skip
    # The dense blocks are small (m x m, m = contact dofs): threaded BLAS only adds
    # overhead, and a lot of it on a loaded machine.
    with threadpool_limits(limits=1, user_api="blas"):
        return _run(
            block, params, normal, program, options, drive, progress, discretisation, base,
            record_displacement,
        )  # fmt: skip


def _run(
    block: Block,
    params: SubloadingParams | Frictionless,
    normal: NormalLoad,
    program: Sequence[Segment],
    options: SolverOptions | None,
    drive: str,
    progress: ProgressCallback | None,
    discretisation: Discretisation | None,
    base: Base | None,
    record_displacement: bool = False,
) -> ContactHistory:
    opts = options or SolverOptions()
    base = base or Base()
    base.check_dim(block.dim)
    if drive not in DRIVES:
        raise ParameterError("drive", drive, "one of " + ", ".join(DRIVES))
    control, stages = plan_stages(normal, program)
    if drive == "rigid" and control != "slide":
        raise ParameterError("drive", drive, "'top' for a force-controlled programme")
    # the snap-back bound of the law at the nominal pressure (for a prescribed
    # displacement, alpha_n d bounds the pressure from above: the block is compliant)
    if discretisation is None:
        check_memory(block, opts)
    disc = discretisation if discretisation is not None else discretise(block)
    if disc.block != block:
        raise ParameterError("discretisation", "another block", "a mesh of this block")
    if (
        isinstance(params, SubloadingParams)
        and params.per_point
        and params.n_points != disc.n_points
    ):
        raise ParameterError(
            "law", f"per-point parameters of {params.n_points} points",
            f"scalars or one value per contact point ({disc.n_points})",
        )  # fmt: skip
    top_area = -float(np.sum(disc.unit_pressure))
    # a total force is applied as the uniform pressure force / top area
    to_pressure = 1.0 / top_area if normal.control == "force" else 1.0
    nominal_pressure = (
        normal.value * to_pressure
        if normal.control != "displacement"
        else normal.value * float(np.asarray(params.alpha_n))
    )
    if not isinstance(params, Frictionless):
        check_snap_back(params, nominal_pressure)
        if normal.control != "displacement":  # the mean pressure: some points carry more
            check_normal_capacity(params, nominal_pressure)

    dim = disc.dim
    if dim == 2 and any(abs(s.end[1]) > 0.0 for s in stages[1:]):
        raise ParameterError(
            "direction_deg", "not along x", "0 or 180 for a 2-D block (it slides along x)"
        )
    nodes = np.arange(disc.nodes.shape[1]) if drive == "rigid" else disc.top_nodes
    # slide_dofs[a]: the dofs moved along in-plane axis a (none under force control)
    slide_dofs = [
        disc.dofs[a][nodes] if control == "slide" else np.zeros(0, dtype=np.int64)
        for a in range(dim - 1)
    ]
    top_normal = disc.dofs[-1][disc.top_nodes]
    fixed = np.zeros(disc.n_dofs, dtype=bool)
    for dofs in slide_dofs:
        fixed[dofs] = True
    if normal.control == "displacement":
        fixed[top_normal] = True
    fixed[disc.fixed_dofs] = True
    # A normal force acts through a rigid top plate: the top face translates as one body
    # (its normal dofs tied; under tangential force control its in-plane dofs too, so
    # the plate carries the shear without tilting the block).
    ties: list[np.ndarray] = []
    if normal.control == "force":
        ties.append(top_normal)
        if control == "force":
            ties.extend(disc.dofs[a][disc.top_nodes] for a in range(dim - 1))
    # Under tangential force control nothing but friction holds the block in-plane; as
    # mu -> 0 the normal stage is singular. It is pinned (the in-plane rigid modes: the
    # plate, or single top dofs), and the pins' reactions are then kept as loads.
    if control != "force":
        pins = np.zeros(0, dtype=np.int64)
    elif normal.control == "force":
        pins = np.concatenate([disc.dofs[a][disc.top_nodes] for a in range(dim - 1)])
    else:
        pins = _pins(disc)
    pinned = fixed.copy()
    pinned[pins] = True
    pin_load = np.zeros(disc.n_dofs)

    solver = make_solver(opts.linear_solver, disc, pinned, params, ties)
    middle = 0.5 * (disc.nodes.min(axis=1) + disc.nodes.max(axis=1))
    gap0 = base.gap(disc.contact_xy, middle[: dim - 1])
    state = open_state(params, disc.n_points, dim, gap=gap0)
    u = np.zeros(disc.n_dofs)
    rec = _Recorder(disc, state, record_displacement)
    total_time = sum(s.duration for s in stages)
    t = 0.0
    pressure, shear, slide = 0.0, np.zeros(2), np.zeros(2)
    force = np.zeros(disc.n_dofs)
    for index, stage in enumerate(stages):
        if index == 1 and pins.size:
            f_now = _external(disc, normal, pressure * to_pressure, shear, dim)
            r = disc.stiffness @ u - f_now - force
            pin_load[pins] = r[pins]
            del solver  # its factors go before the next ones are made (the peak)
            solver = make_solver(opts.linear_solver, disc, fixed, params, ties)
        nominal = 1.0 / stage.steps
        h = nominal
        done = 0.0
        cuts = 0
        while done < 1.0 - 1e-12:
            h_try = min(h, 1.0 - done)
            end = stage.value(done + h_try)
            p_new, s_new, x_new = pressure, shear, slide
            if stage.kind == "normal":
                p_new = float(end[0])
            elif control == "force":
                s_new = end
            else:
                x_new = end
            guess = u.copy()
            for a, dofs in enumerate(slide_dofs):
                guess[dofs] = x_new[a]
            if normal.control == "displacement":
                guess[top_normal] = -p_new
            f_ext = _external(disc, normal, p_new * to_pressure, s_new, dim) + pin_load
            dt = h_try * stage.duration
            outcome = newton_step(
                disc,
                params,
                state,
                u,
                guess,
                f_ext,
                dt,
                solver,
                tangent=opts.tangent,
                tolerance=opts.tolerance,
                max_iterations=opts.max_iterations,
            )
            if not outcome.converged:
                cuts += 1
                h = h_try / 2.0
                if h < nominal / 2.0**opts.max_cuts:
                    message = (
                        f"Newton failed in stage {index} ({stage.kind}) at t = {t:.6g} s after "
                        f"{opts.max_cuts} step cuts: {outcome.message}"
                    )
                    return rec.history(False, message, stages)
                continue
            assert outcome.response is not None
            state = outcome.response.result.state
            force = outcome.response.force
            u = outcome.u
            pressure, shear, slide = p_new, s_new, x_new
            done += h_try
            t += dt
            rec.add(
                t,
                index,
                u,
                shear,
                state,
                outcome.response.result.status,
                outcome.iterations,
                cuts,
                outcome.residuals,
            )
            cuts = 0
            if outcome.iterations <= opts.easy_iterations:
                h = min(h_try * opts.growth, nominal)
            if progress is not None:
                progress(round(1000 * min(t / total_time, 1.0)), 1000)
    return rec.history(True, "completed", stages)


def _external(
    disc: Discretisation, normal: NormalLoad, pressure: float, shear: np.ndarray, dim: int
) -> np.ndarray:
    """Nodal loads of the top pressure [Pa] (pressure or force control) and shear [Pa]."""
    f = sum((shear[a] * disc.unit_shear[a] for a in range(dim - 1)), np.zeros(disc.n_dofs))
    if normal.control != "displacement":
        f = f + pressure * disc.unit_pressure
    return f


def _pins(disc: Discretisation) -> np.ndarray:
    """In-plane dofs fixing the rigid in-plane modes: the top node nearest the top face's
    centre (x, and y in 3-D), and in 3-D the y dof of the top node farthest from it
    along x on its row (the rotation about the normal)."""
    top = disc.top_nodes
    xy = disc.nodes[: disc.dim - 1, top]
    centre = 0.5 * (xy.min(axis=1) + xy.max(axis=1))
    k = int(np.argmin(np.sum((xy - centre[:, None]) ** 2, axis=0)))
    dofs = [disc.dofs[a][top[k]] for a in range(disc.dim - 1)]
    if disc.dim == 3:
        row = np.flatnonzero(np.isclose(xy[1], xy[1, k]))
        far = row[int(np.argmax(np.abs(xy[0, row] - xy[0, k])))]
        dofs.append(disc.dofs[1][top[far]])
    return np.array(dofs, dtype=np.int64)
