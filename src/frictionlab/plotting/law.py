"""Plots of the subloading-friction law driven by loading programmes and machines.

Every function imports matplotlib lazily, draws on ``ax`` (or a new figure) and returns
what it drew on. Axes labels carry SI units.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from frictionlab.plotting._ticks import readable_log_ticks
from frictionlab.plotting.save import save_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from frictionlab.driver import History
    from frictionlab.subloading import SubloadingParams

__all__ = [
    "new_figure",
    "plot_friction",
    "plot_healing",
    "plot_pressure_dependence",
    "plot_ratcheting",
    "plot_restart_peaks",
    "plot_spring_slider",
    "plot_stability_map",
    "plot_steady_friction",
    "plot_traction_path",
    "save_figure",
    "spaced_ticks",
]


def new_figure(
    ncols: int = 1, width: float = 6.0, height: float = 4.0
) -> tuple[Figure, list[Axes]]:
    """A figure with ``ncols`` side-by-side axes (no pyplot state)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width * ncols, height), layout="constrained")
    axes = [fig.add_subplot(1, ncols, i + 1) for i in range(ncols)]
    return fig, axes


def _labels(labels: Sequence[str], n: int) -> list[str | None]:
    return [(labels[i] if i < len(labels) and labels[i] else None) for i in range(n)]


def _colors(n: int, numbers: np.ndarray | None = None) -> list[Any]:
    """One colour per point: tab10 for up to 10, else viridis of the point number
    (``numbers``, 1-based, default 1..n), which :func:`_point_colorbar` explains."""
    from matplotlib import colormaps

    if n <= 10:
        return [colormaps["tab10"](i) for i in range(n)]
    num = np.arange(1.0, n + 1.0) if numbers is None else np.asarray(numbers, dtype=np.float64)
    span = float(num.max() - num.min()) or 1.0
    return list(colormaps["viridis"]((num - num.min()) / span))  # one vectorised call


#: Above this many points the plots draw an evenly spaced subset (first and last
#: included) and say so in the legend: a million curves would take hours to draw.
MAX_CURVES = 40


def shown_points(n: int) -> np.ndarray:
    """Indices of the points a plot draws: all up to :data:`MAX_CURVES`, else a subset."""
    if n <= MAX_CURVES:
        return np.arange(n)
    return np.unique(np.round(np.linspace(0.0, n - 1, MAX_CURVES)).astype(int))


#: Most per-curve legend entries; above it the curves' colours are explained by a colour bar
#: of the point number instead (40 entries overflow the axes).
MAX_LEGEND_CURVES = 10


def _legend_names(names: list[str | None], shown: np.ndarray) -> list[str | None]:
    """Per-point legend names, or none at all when more than :data:`MAX_LEGEND_CURVES` show."""
    if shown.size > MAX_LEGEND_CURVES:
        return [None] * len(names)
    return names


def _point_colorbar(fig: Figure, axes: Any, numbers: np.ndarray, shown: np.ndarray) -> None:
    """A colour bar "point number" for the viridis colours of many curves (none for few).

    ``numbers``: the 1-based numbers of the history's points (a streamed run keeps only
    some of them), as coloured by :func:`_colors`.
    """
    if shown.size <= MAX_LEGEND_CURVES:
        return
    from matplotlib import colormaps
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize

    low, high = float(np.min(numbers)), float(np.max(numbers))
    norm = Normalize(low, high if high > low else low + 1.0)
    mappable = ScalarMappable(norm=norm, cmap=colormaps["viridis"])
    fig.colorbar(mappable, ax=axes, label="point number", fraction=0.05, pad=0.02)


def _note_subset(ax: Axes, n: int, shown: np.ndarray) -> bool:
    """Add a legend entry "k of n points shown" when a subset is drawn; True then."""
    if shown.size >= n:
        return False
    ax.plot([], [], " ", label=f"{shown.size} of {n} points shown (evenly spaced)")
    return True


def _point_styles(
    fig: Figure, axes: list[Axes], note_ax: Axes, history: Any, labels: Sequence[str]
) -> tuple[list[str | None], list[Any], np.ndarray, bool]:
    """Legend names, colours and the points shown of a per-point figure; notes a subset on
    ``note_ax`` and adds the point-number colour bar to ``axes`` (many points)."""
    n = history.n_points
    names = _labels(labels, n)
    colors = _colors(n, history.point_numbers)
    shown_idx = shown_points(n)
    names = _legend_names(names, shown_idx)
    subset = _note_subset(note_ax, n, shown_idx)
    _point_colorbar(fig, axes, history.point_numbers, shown_idx)
    return names, colors, shown_idx, subset


def _log_time(t: np.ndarray) -> bool:
    """A logarithmic time axis when the run spans many decades (long holds, slow slides)."""
    positive = t[t > 0]
    return bool(positive.size) and float(positive.max() / positive.min()) > 1e4


def plot_friction(
    history: History, labels: Sequence[str] = (), title: str = "", fig: Figure | None = None
) -> Figure:
    """Friction ratio against slip (left) and against time (right), holds marked.

    1-D programmes show the signed ratio f_t1/f_n against the slip along e_1 (loops
    after reversals); 2-D programmes show |f_t|/f_n against the slip distance travelled.
    Holds are shaded on the time axis and marked with a dot on the slip axis.
    """
    if fig is None:
        fig, (ax_s, ax_t) = new_figure(2, 5.5, 4.0)
    else:
        ax_s, ax_t = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    planar = history.is_planar
    fn = history.traction[..., 2]
    ratio = (
        np.where(fn > 0, history.traction[..., 0] / np.where(fn > 0, fn, 1.0), 0.0)
        if planar
        else history.friction_ratio
    )
    x = history.slip[..., 0] if planar else history.path_length
    log_time = _log_time(history.time)
    names, colors, shown_idx, subset = _point_styles(fig, [ax_s, ax_t], ax_t, history, labels)
    for i in shown_idx:
        ax_s.plot(x[:, i], ratio[:, i], color=colors[i], lw=1.2, label=names[i])
        shown = history.time[:, i] > 0 if log_time else slice(None)
        ax_t.plot(history.time[shown, i], ratio[shown, i], color=colors[i], lw=1.2, label=names[i])
    marked = False
    for seg in history.segments:
        if not seg.is_hold:
            continue
        for i in shown_idx:
            t0, t1 = history.time[seg.first_row - 1, i], history.time[seg.last_row, i]
            ax_t.axvspan(t0, t1, color="0.6", alpha=0.15, lw=0, label=None if marked else "hold")
            ax_s.plot(x[seg.last_row, i], ratio[seg.last_row, i], "o", color=colors[i], ms=4,
                      mfc="white", label=None if marked else "hold")  # fmt: skip
            marked = True
    if log_time:
        ax_t.set_xscale("log")
    y_label = "friction ratio f_t1/f_n [-]" if planar else "friction ratio |f_t|/f_n [-]"
    ax_s.set_xlabel("slip along e_1 [m]" if planar else "slip distance [m]")
    ax_s.set_ylabel(y_label)
    ax_t.set_xlabel("time [s] (log scale)" if log_time else "time [s]")
    ax_t.set_ylabel(y_label)
    for ax in (ax_s, ax_t):
        ax.grid(alpha=0.3)
    if any(names) or marked or subset:
        ax_t.legend(fontsize=8, loc="best")
    if title:
        fig.suptitle(title)
    readable_log_ticks(fig)
    return fig


def _yield_curve(params: SubloadingParams, F: float, fn: float, i: int = 0) -> np.ndarray:
    """(2, K) tangential tractions / f_n on the sliding-yield curve f(f) = F at f_n (Eq 22)."""
    from frictionlab.subloading import g_inverse

    axes = np.broadcast_to(params.axis_factors, (max(params.n_points, i + 1), 2))[i]
    beta = np.broadcast_to(params.rotation, (max(params.n_points, i + 1), 2))[i]
    angle = float(np.broadcast_to(params.orthotropy_angle, (max(params.n_points, i + 1),))[i])
    if params.is_cone:
        w = F * fn
    else:
        if F / fn < 1.0:
            return np.zeros((2, 0))
        w = float(g_inverse(params.surface, np.array(F / fn), params.tear_k)) * fn
    s = np.linspace(0.0, 2.0 * math.pi, 241)
    p1, p2 = w * axes[0] * np.cos(s), w * axes[1] * np.sin(s)
    c, sn = math.cos(angle), math.sin(angle)
    f1 = c * p1 - sn * p2 + fn * beta[0]
    f2 = sn * p1 + c * p2 + fn * beta[1]
    return np.vstack([f1, f2]) / fn


def plot_traction_path(
    history: History,
    params: SubloadingParams | None = None,
    labels: Sequence[str] = (),
    ax: Axes | None = None,
) -> Axes:
    """Path of the tangential traction in the contact plane, (f_t1, f_t2)/f_n.

    With ``params``, the static (F_s) and kinetic (F_k) sliding-yield curves of point 1
    at its initial normal traction are drawn for reference.
    """
    if ax is None:
        ax = new_figure(1, 5.5, 5.0)[1][0]
    n = history.n_points
    fn = history.traction[..., 2]
    safe = np.where(fn > 0, fn, 1.0)
    r1 = np.where(fn > 0, history.traction[..., 0] / safe, 0.0)
    r2 = np.where(fn > 0, history.traction[..., 1] / safe, 0.0)
    names = _labels(labels, n)
    colors = _colors(n, history.point_numbers)
    if params is not None and fn[0, 0] > 0:
        for value, style, name in (
            (float(np.ravel(params.static)[0]), "--", "static yield curve (F_s)"),
            (float(np.ravel(params.kinetic)[0]), ":", "kinetic yield curve (F_k)"),
        ):
            curve = _yield_curve(params, value, float(fn[0, 0]))
            if curve.size:
                ax.plot(curve[0], curve[1], style, color="0.35", lw=1.0, label=name)
    shown_idx = shown_points(n)
    names = _legend_names(names, shown_idx)
    _note_subset(ax, n, shown_idx)
    if ax.figure is not None:
        _point_colorbar(ax.figure, ax, history.point_numbers, shown_idx)  # type: ignore[arg-type]
    for i in shown_idx:
        ax.plot(r1[:, i], r2[:, i], color=colors[i], lw=1.2, label=names[i])
        ax.plot(r1[-1, i], r2[-1, i], "o", color=colors[i], ms=4)
    ax.set_aspect("equal", adjustable="datalim")
    ax.axhline(0.0, color="0.8", lw=0.8)
    ax.axvline(0.0, color="0.8", lw=0.8)
    ax.set_xlabel("f_t1 / f_n [-]")
    ax.set_ylabel("f_t2 / f_n [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    return ax


def plot_spring_slider(
    history: History, labels: Sequence[str] = (), fig: Figure | None = None
) -> Figure:
    """Spring-slider: friction ratio (left) and slider speed / V (right) against load-point travel."""  # noqa: E501
    if fig is None:
        fig, (ax_f, ax_v) = new_figure(2, 5.5, 4.0)
    else:
        ax_f, ax_v = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    n = history.n_points
    load = history.extra["load_point"]
    speed = history.extra["velocity"]
    V = np.asarray(history.segments[0].resolved["velocity"]) if history.segments else np.ones(n)
    ratio = history.friction_ratio
    names, colors, shown_idx, subset = _point_styles(fig, [ax_f, ax_v], ax_f, history, labels)
    for i in shown_idx:
        ax_f.plot(load[:, i], ratio[:, i], color=colors[i], lw=1.0, label=names[i])
        rel = np.abs(speed[:, i]) / (V[i] if V[i] > 0 else 1.0)
        ax_v.plot(load[:, i], np.maximum(rel, 1e-6), color=colors[i], lw=1.0, label=names[i])
    ax_v.set_yscale("log")
    ax_f.set_xlabel("load-point travel V t [m]")
    ax_f.set_ylabel("friction ratio |f_t|/f_n [-]")
    ax_v.set_xlabel("load-point travel V t [m]")
    ax_v.set_ylabel("slider speed / V [-]")
    for ax in (ax_f, ax_v):
        ax.grid(alpha=0.3)
    if any(names) or subset:
        ax_f.legend(fontsize=8, loc="best")
    readable_log_ticks(fig)
    return fig


def _log_x_finish(ax: Axes, xlabel: str, ylabel: str) -> Axes:
    """Log x axis, labels, grid, legend and readable log ticks: the end of the law's
    log-x figures."""
    ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    readable_log_ticks(ax.figure)
    return ax


def plot_steady_friction(
    velocity: np.ndarray,
    simulated: np.ndarray,
    curve_velocity: np.ndarray,
    curve: np.ndarray,
    bounds: tuple[float, float] | None = None,
    ax: Axes | None = None,
) -> Axes:
    """Steady friction against sliding velocity: simulated points and the closed form mu_ss(V)."""
    if ax is None:
        ax = new_figure(1, 5.5, 4.0)[1][0]
    ax.plot(curve_velocity, curve, "-", color="0.3", lw=1.2, label="closed form mu_ss(V)")
    ax.plot(velocity, simulated, "o", color="C3", label="simulated (end of slide)")
    if bounds is not None:
        ax.axhline(bounds[0], color="0.6", ls=":", lw=1.0, label="mu_k")
        ax.axhline(bounds[1], color="0.6", ls="--", lw=1.0, label="mu_s")
    return _log_x_finish(ax, "sliding velocity V [m/s]", "steady friction ratio [-]")


def plot_restart_peaks(
    hold_time: np.ndarray,
    peak: np.ndarray,
    recovered: np.ndarray,
    curve_time: np.ndarray,
    curve: np.ndarray,
    mu_s: float,
    ax: Axes | None = None,
) -> Axes:
    """Restart peak and mu at the end of the hold against hold time, with the closed form."""
    if ax is None:
        ax = new_figure(1, 5.5, 4.0)[1][0]
    ax.plot(
        curve_time, curve, "-", color="0.3", lw=1.2, label="closed form mu(t_h) (hold recovery)"
    )
    ax.plot(hold_time, recovered, "s", color="C0", mfc="white", label="mu at the end of the hold")
    ax.plot(hold_time, peak, "o", color="C3", label="restart peak of |f_t|/f_n")
    ax.axhline(mu_s, color="0.6", ls="--", lw=1.0, label="mu_s")
    return _log_x_finish(ax, "hold time t_h [s]", "friction ratio [-]")


def plot_healing(
    hold_time: np.ndarray,
    delta_mu: np.ndarray,
    point: np.ndarray,
    rate: float | None,
    intercept: float | None,
    labels: Sequence[str] = (),
    ax: Axes | None = None,
    recovery: tuple[float, float, float, float] | None = None,
) -> Axes:
    """Restart peak minus friction before the hold against log10 hold time, with the fit line.

    ``recovery``: (A, mu_0, tau [s], friction before) of the law's recovery form, drawn as
    ``A - (A - mu_0) exp(-t_h/tau)`` minus the friction before (dashed).
    """
    if ax is None:
        ax = new_figure(1, 5.5, 4.0)[1][0]
    points = np.unique(point)
    colors = _colors(points.size)
    many = points.size > 1 and points.size == hold_time.size  # one hold per point
    if many:
        ax.plot(hold_time, delta_mu, "o", color="C3", label="restart peak - friction before")
    else:
        for c, p in zip(colors, points, strict=True):
            mine = point == p
            name = labels[p - 1] if p - 1 < len(labels) and labels[p - 1] else f"point {p}"
            ax.plot(hold_time[mine], delta_mu[mine], "o", color=c, label=name)
    if rate is not None and intercept is not None:
        t = np.geomspace(hold_time[hold_time > 0].min(), hold_time.max(), 50)
        ax.plot(t, intercept + rate * np.log10(t), "-", color="0.3", lw=1.0,
                label=f"least squares: {rate:.4g} per decade")  # fmt: skip
    if recovery is not None:
        a, mu_0, tau, before = recovery
        t = np.geomspace(hold_time[hold_time > 0].min() / 3, hold_time.max() * 3, 80)
        ax.plot(t, a - (a - mu_0) * np.exp(-t / tau) - before, "--", color="C0", lw=1.2,
                label=f"law's recovery form: tau = {tau:.3g} s")  # fmt: skip
    return _log_x_finish(ax, "hold time t_h [s]", "delta mu = restart peak - friction before [-]")


def plot_ratcheting(
    cycle: np.ndarray, residual: np.ndarray, per_cycle: float, ax: Axes | None = None
) -> Axes:
    """Residual slip after each traction cycle against the closed form n * Delta u (Eq 29)."""
    if ax is None:
        ax = new_figure(1, 5.5, 4.0)[1][0]
    ax.plot(
        cycle,
        cycle * per_cycle * 1e3,
        "-",
        color="0.3",
        label="(2/(pi u)) ln sec(pi R_max/2) per cycle",
    )
    ax.plot(cycle, residual * 1e3, "o", color="C3", label="simulated residual slip")
    ax.set_xlabel("cycle [-]")
    ax.set_ylabel("residual slip [mm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return ax


def plot_pressure_dependence(
    results: Mapping[str, tuple[np.ndarray, np.ndarray]],
    curves: Mapping[str, tuple[np.ndarray, np.ndarray]],
    ax: Axes | None = None,
) -> Axes:
    """Steady friction coefficient against f_n/F for each closed surface (points) and the
    closed forms mu = M g^-1(F/f_n) (lines)."""
    if ax is None:
        ax = new_figure(1, 6.0, 4.5)[1][0]
    colors = _colors(len(results))
    for color, (name, (x, mu)) in zip(colors, results.items(), strict=True):
        cx, cmu = curves[name]
        ax.plot(cx, cmu, "-", color=color, lw=1.0)
        ax.plot(x, mu, "o", color=color, ms=4, label=name)
    ax.set_xlabel("normal traction / F [-]")
    ax.set_ylabel("steady friction |f_t|/f_n [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, title="points: simulated, lines: closed form")
    return ax


def spaced_ticks(values: np.ndarray, keep: float, min_decades: float = 0.12) -> list[float]:
    """Positive ``values`` to label on a log axis: ``keep`` and those at least
    ``min_decades`` (in log10) from every label already chosen, smallest first."""
    chosen = [float(keep)]
    for v in sorted(float(x) for x in values if x > 0):
        if all(abs(np.log10(v / c)) >= min_decades for c in chosen):
            chosen.append(v)
    return sorted(chosen)


def plot_stability_map(
    ratio: np.ndarray, oscillation: np.ndarray, velocity: float, ax: Axes | None = None
) -> Axes:
    """Friction oscillation in the late part of the run against k / k_c."""
    if ax is None:
        ax = new_figure(1, 5.5, 4.0)[1][0]
    ax.plot(ratio, np.maximum(oscillation, 1e-16), "o-", color="C3")
    ax.axvline(1.0, color="0.4", ls="--", lw=1.0, label="predicted boundary k = k_c")
    ax.set_xscale("log")
    ax.set_yscale("log")
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    values = np.unique(np.concatenate([ratio, [1.0]]))
    labelled = spaced_ticks(values, keep=1.0)
    ax.set_xticks(labelled)  # labels far enough apart to be read
    ax.set_xticks([v for v in values if v not in labelled], minor=True)  # the rest unlabelled
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("machine stiffness k / k_c [-]")
    ax.set_ylabel("peak-to-peak friction ratio, last quarter [-]")
    ax.set_title(f"V = {velocity:g} m/s", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    readable_log_ticks(ax.figure)
    return ax
