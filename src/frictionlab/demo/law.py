"""Demo sections for the subloading-friction law: one builder per tribometer test.

Each builder runs bundled scenarios through the same code path as ``frictionlab
simulate`` (outputs in ``OUT/<scenario>/``: history.csv, summary.json, plots and a copy
of the scenario file), adds figures comparing with the law's closed forms
(docs/theory.md), and returns a report section.
"""

from __future__ import annotations

import time
from collections.abc import Iterable, Sequence

import numpy as np

from frictionlab.app.simulate import run_scenario, write_results
from frictionlab.demo import DemoContext, load_bundled
from frictionlab.driver import (
    History,
    InitialConditions,
    SpringSlider,
    critical_stiffness,
    friction_oscillation,
    simulate_spring_slider,
)
from frictionlab.errors import FrictionlabError
from frictionlab.io.atomic import write_text_atomic
from frictionlab.io.report import Section, format_value
from frictionlab.io.tables import write_csv_atomic
from frictionlab.plotting.law import (
    plot_friction,
    plot_pressure_dependence,
    plot_ratcheting,
    plot_restart_peaks,
    plot_stability_map,
    plot_steady_friction,
    save_figure,
)
from frictionlab.plotting.units import show_length_in
from frictionlab.schema.scenario import Scenario, load_scenario
from frictionlab.subloading import (
    Status,
    friction_coefficient_on_yield,
    hold_recovery,
    ratcheting_slip_per_cycle,
    steady_size,
)

__all__ = [
    "LAW_SECTIONS",
    "anisotropy_section",
    "monotonic_section",
    "pressure_section",
    "reversal_section",
    "run_bundled",
    "slide_hold_slide_section",
    "stick_slip_section",
]


def _by_value(pattern: str, keys: Iterable[float], values: Iterable[float]) -> str:
    """``pattern`` (two fields: key, value) for each pair, comma separated, then a period."""
    return ", ".join(pattern.format(k, v) for k, v in zip(keys, values, strict=True)) + "."


_CONE_UNITS = {
    "alpha_n": "Pa/m", "alpha_t": "Pa/m", "mu_s": "-", "mu_k": "-", "u": "1/m",
    "kappa": "1/m", "xi": "1/s", "m": "-", "n": "-", "rotation": "-", "orthotropy": "-",
    "orthotropy_angle": "rad", "tear_k": "-",
}  # fmt: skip
_CLOSED_UNITS = {**_CONE_UNITS, "F_s": "Pa", "F_k": "Pa", "M": "-", "kappa": "Pa/m", "xi": "Pa/s"}


def run_bundled(
    ctx: DemoContext, name: str, overrides: Sequence[str] = (), subdir: str | None = None
) -> tuple[Scenario, History, str]:
    """Run the bundled scenario ``name`` into ``OUT/<subdir or name>/``; return it, its
    history and the directory relative to OUT."""
    rel = subdir or name
    scenario, text = load_bundled(name, "scenarios", lambda path: load_scenario(path, overrides))
    start = time.perf_counter()
    with ctx.progress(rel) as progress:
        history = run_scenario(scenario, progress=progress)
    elapsed = time.perf_counter() - start
    if not history.success:
        raise FrictionlabError(f"demo scenario '{rel}' failed: {history.message}")
    write_results(ctx.out_dir / rel, scenario, history, elapsed)
    header = ""
    if overrides:
        flags = " ".join(f"--set {o}" for o in overrides)
        header = f"# The demo ran this scenario with: {flags}\n"
    write_text_atomic(ctx.out_dir / rel / "scenario.toml", header + text)
    return scenario, history, rel


def _zoom_limits(x: np.ndarray, y: np.ndarray, window: tuple[float, float]) -> tuple[float, float]:
    """y-limits that fit the curves inside the x-window (with a margin), so a zoom zooms."""
    inside = y[(x >= window[0]) & (x <= window[1])]
    lo, hi = float(inside.min()), float(inside.max())
    pad = 0.08 * (hi - lo) if hi > lo else 0.01 * max(abs(hi), 1e-12)
    return lo - pad, hi + pad


def _law_rows(scenario: Scenario) -> list[tuple[str, str, str]]:
    """Law table rows (the report shows the first in full, later ones as differences)."""
    law = scenario.inputs["law"]
    units = _CONE_UNITS if scenario.params.is_cone else _CLOSED_UNITS
    rows = [("surface", str(law["surface"]), "")]
    for key, value in law.items():
        if key == "surface" or value is None or key not in units:
            continue
        rows.append((key, format_value(value), units[key]))
    return rows


def _section(title: str, scenario: Scenario, description: str | None = None) -> Section:
    """A report section with the scenario's law and parameter tables."""
    text = scenario.description if description is None else description
    return Section(title, text, law=_law_rows(scenario), parameters=_parameters(scenario))


def _parameters(scenario: Scenario) -> list[tuple[str, str, str]]:
    """Parameter table rows: the initial contact and the programme."""
    rows = []
    rows.append(
        (
            "initial normal traction f_n",
            format_value(scenario.inputs["initial"]["normal_traction"]),
            "Pa",
        )
    )
    if "program" in scenario.inputs:
        for i, seg in enumerate(scenario.inputs["program"], start=1):
            fields = ", ".join(
                f"{k} = {format_value(v)}" for k, v in seg.items() if k != "kind" and v is not None
            )
            rows.append((f"segment {i}: {seg['kind']}", fields, "SI"))
    else:
        machine = scenario.inputs["machine"]
        for key, unit in (("stiffness", "Pa/m"), ("velocity", "m/s"), ("mass", "kg/m^2"),
                          ("damping", "Pa s/m"), ("duration", "s"), ("steps", "-")):  # fmt: skip
            rows.append((f"machine {key}", format_value(machine[key]), unit))
    return rows


def _length(value: float, fmt: str = "g") -> str:
    """A length [m] in the unit that reads best: "5 mm", "0.1 um"."""
    for unit, factor in (("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9)):
        if abs(value) >= factor or unit == "nm":
            return f"{value / factor:{fmt}} {unit}"
    return f"{value:{fmt}} m"  # pragma: no cover


def _speed(value: float) -> str:
    """A speed [m/s] as "1 mm/s", "1 um/s"."""
    return _length(value) + "/s"


def _law(scenario: Scenario, name: str) -> float:
    return float(np.ravel(getattr(scenario.params, name))[0])


# --------------------------------------------------------------------------- sections
def monotonic_section(ctx: DemoContext) -> Section:
    """Monotonic sliding to kinetic friction"""
    sc, h, rel = run_bundled(ctx, "monotonic")
    V = np.asarray(h.segments[0].resolved["velocity"])
    kappa, xi, mu_s, mu_k = (_law(sc, k) for k in ("kappa", "xi", "mu_s", "mu_k"))
    simulated = h.friction_ratio[-1]
    expected = steady_size(V, kappa, xi, mu_s, mu_k)
    curve_v = np.geomspace(V.min() / 30.0, V.max() * 30.0, 200)
    distance = float(np.ravel(sc.inputs["program"][0]["distance"])[0])
    ax = plot_steady_friction(
        V, simulated, curve_v, steady_size(curve_v, kappa, xi, mu_s, mu_k), (mu_k, mu_s)
    )
    save_figure(ax.figure, ctx.out_dir / rel / "steady.png")  # type: ignore[arg-type]
    peaks = h.friction_ratio.max(axis=0)
    sec = _section("Monotonic sliding to kinetic friction", sc)
    sec.add_figure(
        f"{rel}/friction.png",
        "Friction ratio against slip (left) and time (right) at four sliding velocities: a "
        "smooth rise without a yield kink to a static peak below mu_s, then softening to a "
        "steady value that is lower at higher velocity.",
    )
    sec.add_figure(
        f"{rel}/steady.png",
        f"Steady friction at the end of the {_length(distance)} slide (points) on the closed form "
        "mu_ss(V) = (kappa V + xi)/(kappa V/mu_k + xi/mu_s) (line): the law's built-in "
        "velocity weakening between mu_s (slow) and mu_k (fast).",
    )
    rel_err = float(np.max(np.abs(simulated / expected - 1.0)))
    sec.notes.append(
        "Static peaks: " + ", ".join(f"{p:.4f}" for p in peaks) + f" (all below mu_s = {mu_s:g}). "
        "Steady friction simulated vs closed form: "
        + "; ".join(
            f"V = {v:g} m/s: {s:.6f} vs {e:.6f}"
            for v, s, e in zip(V, simulated, expected, strict=True)
        )
        + f" (largest relative difference {rel_err:.1e})."
    )
    return sec


def slide_hold_slide_section(ctx: DemoContext) -> Section:
    """Slide-hold-slide: recovery of static friction"""
    sc, h, rel = run_bundled(ctx, "slide_hold_slide")
    slide1, hold, slide2 = h.segments[:3]
    hold_time = np.asarray(hold.resolved["duration"])
    mu_s, xi = _law(sc, "mu_s"), _law(sc, "xi")
    mu0 = float(h.F[slide1.last_row, 0])
    recovered = h.F[hold.last_row]
    peaks = h.friction_ratio[slide2.rows].max(axis=0)
    curve_t = np.logspace(-0.5, 4.5, 200)
    ax = plot_restart_peaks(
        hold_time,
        peaks,
        recovered,
        curve_t,
        hold_recovery(np.asarray(mu0), mu_s, xi, curve_t),
        mu_s,
    )
    save_figure(ax.figure, ctx.out_dir / rel / "restart.png")  # type: ignore[arg-type]
    zoom = plot_friction(h, sc.labels, "Restart after the hold")
    first, second = (float(np.ravel(sc.inputs["program"][i]["distance"])[0]) for i in (0, 2))
    # slip window [m]: the end of the first slide, the hold and the restart
    window = (0.9 * first, first + second)
    zoom.axes[0].set_xlim(*window)
    show_length_in(zoom.axes[0].xaxis, "slip along e_1", *window)  # um, not 0.0009 m
    zoom.axes[0].set_ylim(*_zoom_limits(h.slip[..., 0], h.friction_ratio, window))
    save_figure(zoom, ctx.out_dir / rel / "restart_zoom.png")
    sec = _section("Slide-hold-slide: recovery of static friction", sc)
    sec.add_figure(
        f"{rel}/friction.png",
        "The whole programme for five hold times: sliding to kinetic friction, the hold "
        "(shaded; the traction stays constant) and the restart.",
    )
    sec.add_figure(
        f"{rel}/restart_zoom.png",
        "Zoom on the restart: the longer the hold, the higher the restart peak; after the "
        "peak the friction softens toward kinetic again.",
    )
    sec.add_figure(
        f"{rel}/restart.png",
        "mu at the end of the hold (squares) on the closed-form recovery "
        "mu_s - (mu_s - mu_0) exp(-xi t_h/mu_s) (line), and the restart peaks (dots): they "
        "grow with the hold time and stay below mu_s (dashed).",
    )
    sec.notes.append(
        f"mu at the stop mu_0 = {mu0:.5f}. Restart peaks: "
        + _by_value("t_h = {:g} s: {:.4f}", hold_time, peaks)
    )
    return sec


def reversal_section(ctx: DemoContext) -> Section:
    """Reversal, displacement cycles and ratcheting"""
    sc, h, rel = run_bundled(ctx, "reversal_cycles")
    sr, hr, rel_r = run_bundled(ctx, "ratcheting")
    seg = hr.segments[0]
    per_leg = int(seg.resolved["steps"]) // (2 * int(seg.resolved["cycles"]))
    cycles = np.arange(1, int(seg.resolved["cycles"]) + 1)
    residual = hr.slip[2 * per_leg * cycles, 0, 0]
    fmax = float(np.hypot(*np.asarray(seg.resolved["traction"])[0]))
    R_max = fmax / (_law(sr, "mu_s") * float(hr.traction[0, 0, 2]))
    per_cycle = float(ratcheting_slip_per_cycle(np.asarray(R_max), _law(sr, "u")))
    ax = plot_ratcheting(cycles, residual, per_cycle)
    save_figure(ax.figure, ctx.out_dir / rel_r / "ratcheting.png")  # type: ignore[arg-type]
    cyc = h.segments[2]
    q = int(cyc.resolved["steps"]) // 4
    rows = (
        cyc.first_row
        - 1
        + np.concatenate(
            [[q * (4 * c + 1), q * (4 * c + 3)] for c in range(int(cyc.resolved["cycles"]))]
        )
    )
    tp = h.traction[rows, 0, 0] / h.traction[rows, 0, 2]
    # the elastic branch right after the reversal: consecutive STICK steps and their slope
    rev = h.segments[1]
    after = np.arange(rev.first_row, rev.last_row + 1)
    stick = after[: int(np.argmax(h.status[after, 0] != int(Status.STICK)))]
    slope = (
        float(np.polyfit(h.slip[stick, 0, 0], h.traction[stick, 0, 0], 1)[0])
        if stick.size >= 2
        else float("nan")
    )
    elastic_range = (
        float(h.slip[stick[0] - 1, 0, 0] - h.slip[stick[-1], 0, 0]) if stick.size else 0.0
    )
    amplitude = float(np.ravel(sc.inputs["program"][2]["amplitude"])[0])
    max_step = float(np.ravel(sc.inputs["program"][1]["max_step"])[0])
    sec = _section("Reversal, displacement cycles and ratcheting", sc)
    sec.add_figure(
        f"{rel}/friction.png",
        "Forward slide, reversal back to the start, then four cycles of "
        f"+-{_length(amplitude)}: f_t1/f_n "
        "against slip (loops) and time. Each reversal unloads elastically and re-yields "
        "smoothly; the turning points alternate in sign and decrease toward kinetic friction. "
        f"Steps of {_length(max_step)} resolve the elastic unloading: after the first reversal "
        f"{stick.size} steps ({_length(elastic_range, '.2g')} of slip) are elastic, with slope "
        f"{slope:.4g} Pa/m (alpha_t = {_law(sc, 'alpha_t'):.4g} Pa/m).",
    )
    sec.add_figure(
        f"{rel_r}/friction.png",
        f"Traction-controlled cycles 0 -> {fmax / 1e6:g} -> 0 MPa with kappa = xi = 0: "
        "the driver solves "
        "for the slip; every cycle shifts the loop forward (ratcheting).",
    )
    sec.add_figure(
        f"{rel_r}/ratcheting.png",
        "Residual slip after each traction cycle (dots) against n (2/(pi u)) ln sec(pi R_max/2) "
        f"(line, Eq 29) for R_max = {R_max:g}.",
    )
    sec.notes.append(
        "Turning-point friction ratios of the displacement cycles: "
        + ", ".join(f"{v:+.4f}" for v in tp)
        + f". Ratcheting per cycle: simulated {np.diff(np.concatenate([[0.0], residual])).mean() * 1e6:.6f} um, "  # noqa: E501
        f"closed form {per_cycle * 1e6:.6f} um."
    )
    sec.parameters += [
        ("ratcheting scenario", f"kappa = xi = 0, traction cycles to {fmax:g}", "Pa")
    ]
    return sec


def anisotropy_section(ctx: DemoContext) -> Section:
    """Rotational and orthotropic anisotropy"""
    sr, hr, rel_r = run_bundled(ctx, "rotation")
    so, ho, rel_o = run_bundled(ctx, "orthotropy")
    kappa, xi, mu_s, mu_k = (_law(sr, k) for k in ("kappa", "xi", "mu_s", "mu_k"))
    beta = float(np.ravel(sr.params.rotation)[0])
    V = float(np.ravel(hr.segments[0].resolved["velocity"])[0])
    mss = float(steady_size(np.asarray(V), kappa, xi, mu_s, mu_k))
    final = hr.traction[-1, :, 0] / hr.traction[-1, :, 2]
    C = np.asarray(so.params.orthotropy)
    distance = float(np.ravel(sr.inputs["program"][0]["distance"])[0])
    sec = _section(
        "Rotational and orthotropic anisotropy", sr, sr.description + " " + so.description
    )
    sec.add_figure(
        f"{rel_r}/friction.png",
        f"Rotated cone (beta = {beta:g} along e_1): sliding {_length(distance)} along +e_1 "
        "and -e_1 gives different "
        "static peaks and steady values +(mu_ss + |beta|) and -(mu_ss - |beta|).",
    )
    sec.add_figure(
        f"{rel_o}/traction_path.png",
        "Orthotropic cone (C_1 = 1, C_2 = 0.6): traction paths in the contact plane for six "
        "sliding directions, then a 90 degree turn. The steady traction sits on the ellipse "
        "of semi-axes C_i mu_ss f_n, not along the sliding direction; after the turn it "
        "travels along the ellipse.",
    )
    sec.add_figure(
        f"{rel_o}/friction.png",
        "The same runs as friction ratio |f_t|/f_n against slip distance and time: the "
        "steady friction depends on the sliding direction, from C_2 mu_ss to C_1 mu_ss.",
    )
    before_turn = ho.segments[1].last_row
    sec.notes.append(
        f"Rotation: steady f_t1/f_n = {final[0]:+.5f} forward, {final[1]:+.5f} backward; closed "
        f"form +{mss + beta:.5f} and -{mss - beta:.5f}. Orthotropy, steady |f_t|/f_n: sliding "
        f"along e_1 {ho.friction_ratio[before_turn, 0]:.5f} before the turn and "
        f"{ho.friction_ratio[-1, 3]:.5f} after it (C_1 mu_ss = {C[0] * mss:.5f}); along e_2 "
        f"{ho.friction_ratio[before_turn, 3]:.5f} before and {ho.friction_ratio[-1, 0]:.5f} "
        f"after (C_2 mu_ss = {C[1] * mss:.5f})."
    )
    sec.parameters += [("orthotropy scenario", "orthotropy = [1, 0.6], beta = 0", "-")]
    return sec


_SURFACES = ("cam_clay", "modified_cam_clay", "tear", "parabola")


def pressure_section(ctx: DemoContext) -> Section:
    """Pressure dependence of the closed sliding-yield surfaces"""
    results: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    errors = []
    main: Scenario | None = None
    for surface in _SURFACES:
        sc, h, _ = run_bundled(ctx, "pressure", [f'law.surface="{surface}"'], f"pressure/{surface}")
        main = sc if surface == "modified_cam_clay" else main
        F = _law(sc, "F_s")
        M = _law(sc, "M")
        fn = h.traction[0, :, 2]
        mu = h.friction_ratio[-1]
        results[surface] = (fn / F, mu)
        x = np.linspace(0.01, 0.99, 200)
        curves[surface] = (x, friction_coefficient_on_yield(surface, x * F, np.asarray(F), M))
        expected = friction_coefficient_on_yield(surface, fn, np.asarray(F), M)
        errors.append(f"{surface} {np.max(np.abs(mu / expected - 1.0)):.1e}")
    assert main is not None
    ax = plot_pressure_dependence(results, curves)
    save_figure(ax.figure, ctx.out_dir / "pressure" / "pressure.png")  # type: ignore[arg-type]
    sec = _section("Pressure dependence of the closed sliding-yield surfaces", main)
    sec.add_figure(
        "pressure/pressure.png",
        "Steady friction coefficient against normal traction for the four closed surfaces "
        "(Cam-clay, modified Cam-clay, tear, parabola): simulated (points) on the closed "
        "forms M g^-1(F/f_n) (lines); the friction coefficient falls as the pressure rises.",
    )
    sec.add_figure(
        "pressure/modified_cam_clay/friction.png",
        "Modified Cam-clay: friction ratio against slip at ten normal tractions.",
    )
    sec.notes.append("Largest relative difference from the closed form: " + ", ".join(errors) + ".")
    return sec


def stick_slip_section(ctx: DemoContext) -> Section:
    """Stick-slip of a spring-slider"""
    sc, h, rel = run_bundled(ctx, "stick_slip")
    k = np.asarray(h.segments[0].resolved["stiffness"])[:2]  # the two slow machines
    speeds = np.asarray(sc.inputs["machine"]["velocity"], dtype=float)
    V = float(speeds[0])  # the slow machines' load-point velocity
    travel = V * float(np.ravel(sc.inputs["machine"]["duration"])[0])
    # slider mass [kg/m^2]: 10 kg/m^2 at alpha_t = 1000 Pa/m, converted like the other inputs
    # (mass ~ traction time^2 / length), so that the dynamics keep their shape
    m = 10.0 * _law(sc, "alpha_t") / 1000.0
    damping = 2.0 * 0.1 * np.sqrt(k * m)  # 10 % of critical damping
    overrides = [
        "machine.stiffness=[" + ", ".join(f"{v:.6g}" for v in k) + "]",
        f"machine.velocity=[{V!r}, {V!r}]",
        f"machine.duration=[{travel / V!r}, {travel / V!r}]",
        f"machine.mass={m}",
        "machine.damping=[" + ", ".join(f"{c:.6g}" for c in damping) + "]",
    ]
    rel_i = run_bundled(ctx, "stick_slip", overrides, "stick_slip_inertial")[2]
    # stability map: quasi-static, the slow machines' V, k from k_c/4 to 4 k_c
    fn = float(h.traction[0, 0, 2])
    kc = float(critical_stiffness(sc.params, V, fn)[0])
    factors = np.array([0.25, 0.5, 0.8, 0.9, 1.1, 1.25, 2.0, 4.0])
    with ctx.progress("stick_slip/stability_map") as progress:
        hm = simulate_spring_slider(
            sc.params, SpringSlider(stiffness=factors * kc, velocity=V), travel / V,
            steps=2000, initial=InitialConditions(normal_traction=fn), progress=progress,
        )  # fmt: skip
    if not hm.success:
        raise FrictionlabError(f"demo stability map failed: {hm.message}")
    osc = friction_oscillation(hm, 0.25)
    write_csv_atomic(
        ctx.out_dir / rel / "stability_map.csv",
        {"k_over_kc": factors, "stiffness": factors * kc, "friction_oscillation": osc},
        {"k_over_kc": "-", "stiffness": "Pa/m", "friction_oscillation": "-"},
        f"quasi-static spring-slider, V = {V} m/s, k_c = {kc:.6g} Pa/m",
    )
    ax = plot_stability_map(factors, osc, V)
    save_figure(ax.figure, ctx.out_dir / rel / "stability_map.png")  # type: ignore[arg-type]
    sec = _section("Stick-slip of a spring-slider", sc)
    sec.add_figure(
        f"{rel}/friction.png",
        "Quasi-static slider: friction ratio and slider speed against load-point travel. "
        f"Soft spring at {_speed(V)}: stick (speed far below V, friction rising as mu recovers) "
        f"and sudden slips; stiff spring, or the soft spring at {_speed(float(speeds[-1]))}: "
        "steady sliding after the first peak.",
    )
    sec.add_figure(
        f"{rel_i}/friction.png",
        f"The two slow machines with a slider mass of {m:g} kg/m^2 and 10 % of critical damping "
        "(generalized-alpha, rho_inf = 0.5): the soft machine still sticks and slips, with "
        "slips that overshoot below kinetic friction and ring; the stiff one slides steadily.",
    )
    sec.add_figure(
        f"{rel}/stability_map.png",
        f"Peak-to-peak friction in the last quarter of a {_length(travel)} pull against "
        "k/k_c: stick-slip "
        "below the critical stiffness k_c of the linear stability analysis, steady sliding "
        "above it.",
    )
    sec.notes.append(
        f"Critical stiffness at V = {_speed(V)}: k_c = {kc:.5g} Pa/m. Oscillation amplitude: "
        + _by_value("k/k_c = {:g}: {:.2e}", factors, osc)
    )
    return sec


#: The law's demo sections, in report order.
LAW_SECTIONS = (
    monotonic_section,
    slide_hold_slide_section,
    reversal_section,
    anisotropy_section,
    pressure_section,
    stick_slip_section,
)
