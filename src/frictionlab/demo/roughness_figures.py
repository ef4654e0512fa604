"""The demo report's roughness sections: the figure families of the paper's Figs 6-14.

:func:`roughness_sections` computes every family at demo-friendly resolution (a few
seconds on two cores), saves the PNGs and the CSV tables under ``out_dir/roughness/``
and returns two :class:`~frictionlab.io.report.Section` objects whose figure paths are
relative to ``out_dir`` (the report's directory), each figure with one sentence saying
what it shows, numbers measured on this run included:

* "Lattice-spring roughness: case studies, 2-D surfaces, wavelengths" (Figs 6a, 6b, 7, 8);
* "Lattice-spring roughness: adhesion, wear, hierarchy" (Figs 10-14).

:func:`measured_section` adds "Lattice-spring roughness: a measured topography file"
(the shipped x3p file: mu(beta) and scale-resolved friction, beyond the paper).

Fig 9 (validation against pins on ice) is not reproduced: its experimental values are
not available (docs/roughness.md).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab._progress import ProgressFactory, no_progress
from frictionlab.io.atomic import write_bytes_atomic
from frictionlab.io.report import Section
from frictionlab.io.tables import write_csv_atomic
from frictionlab.roughness import families
from frictionlab.roughness.lattice import LatticeSettings

__all__ = [
    "DEMO_1D",
    "DEMO_2D",
    "FOLDER",
    "MU0",
    "ProgressFactory",
    "life_section",
    "measured_section",
    "roughness_sections",
    "single_level_section",
]

#: Subdirectory of the report directory holding the roughness figures and tables.
FOLDER = "roughness"

MU0 = 0.3
#: Demo resolutions (full contact): 1-D lattices and 2-D lattices.
DEMO_1D = LatticeSettings(stations=2000, time_samples=40)
DEMO_2D = LatticeSettings(stations=32, time_samples=16)


class _Writer:
    """Saves figures and tables under ``out_dir/roughness`` and returns relative paths."""

    def __init__(self, out_dir: Path, step: Callable[[], None]) -> None:
        self.out_dir = out_dir
        self.folder = out_dir / FOLDER
        self.step = step

    def figure(self, name: str, fig: Any) -> str:
        """Save ``fig`` as ``name``.png; one step of the section's progress per figure."""
        from frictionlab.plotting.roughness import figure_png_bytes

        write_bytes_atomic(self.folder / f"{name}.png", figure_png_bytes(fig))
        self.step()
        return f"{FOLDER}/{name}.png"

    def table(self, name: str, columns: Any, units: Any, description: str) -> None:
        write_csv_atomic(self.folder / f"{name}.csv", dict(columns), units, description)

    def family(self, name: str, family: Any) -> None:
        """A figure family's table (columns, units and description attributes)."""
        self.table(name, family.columns, family.units, family.description)

    def results(self, prefix: str, results: dict[str, Any]) -> None:
        """One table per named result object, ``<prefix>_<name as a slug>.csv``."""
        for name, result in results.items():
            self.table(f"{prefix}_{_slug(name)}", result.columns(), result.units(), name)


def _single_level(writer: _Writer) -> Section:
    from frictionlab.plotting.roughness import new_figure, plot_family_lines, plot_wavelength_map

    betas = np.arange(0.0, 91.0, 5.0)
    section = Section(
        "Lattice-spring roughness: case studies, 2-D surfaces, wavelengths",
        intro=(
            "The lattice-spring model (ALSFM, Berardo & Pugno) predicts the kinetic friction "
            "coefficient mu of two rigid rough surfaces joined by vertical springs as a "
            "function of the sliding direction beta. These are the families of the paper's "
            "Figs 6-8 in full contact with the local coefficient mu0 = 0.3."
        ),
        anchor="roughness-single-level",
    )
    wedges = families.wedge_cases(MU0, (30.0, 15.0), betas)
    writer.family("fig6a_wedge_cases", wedges)
    fig = new_figure(6.5, 4.5)
    plot_family_lines(wedges, ax=fig.add_subplot())
    a0, a90 = wedges["mu_over_mu0_B"][0], wedges["mu_over_mu0_B"][-1]
    section.add_figure(
        writer.figure("fig6a_wedge_cases", fig),
        f"Fig 6a family: the six 30/15 deg wedge cases (Eqs 15-16) lose friction from "
        f"beta = 0 to 90 deg (two symmetric wedges: mu/mu0 = {a0:.3f} to {a90:.3f}), and "
        "steeper-first faces (C, E) resist more than their reversals (D, F), which coincide "
        "at 90 deg.",
    )
    generic = families.generic_cases(MU0, (30.0, 15.0), betas[::3], settings=DEMO_1D)
    writer.family("fig6b_generic_cases", generic)
    fig = new_figure(6.5, 4.5)
    plot_family_lines(generic, ax=fig.add_subplot())
    excess = float(np.min(generic["mu_over_mu0_B"] - wedges["mu_over_mu0_B"][::3]))
    section.add_figure(
        writer.figure("fig6b_generic_cases", fig),
        "Fig 6b family: smooth half-cosine faces with the same mean slopes give a higher mu "
        f"than the wedges (case B at least {excess:.3f} mu0 higher at every beta), as "
        "Jensen's inequality predicts.",
    )
    surfaces = families.surfaces_2d_vs_beta(MU0, betas, settings=DEMO_2D)
    writer.family("fig7_surfaces_2d", surfaces)
    fig = new_figure(6.5, 4.5)
    plot_family_lines(surfaces, ax=fig.add_subplot())
    sym = surfaces["mu_over_mu0_l2pi_2pi"]
    section.add_figure(
        writer.figure("fig7_surfaces_2d", fig),
        f"Fig 7 family: the symmetric 2-D surface sin x sin y is almost isotropic "
        f"(mu/mu0 varies by {np.ptp(sym):.4f}), while the asymmetric (2 pi, 3 pi) and "
        "(3 pi, 2 pi) surfaces are mirror images about beta = 45 deg.",
    )
    grid = families.wavelength_map(MU0, settings=DEMO_2D)
    writer.family("fig8_wavelength_map", grid)
    fig = new_figure(14.0, 4.2)
    for k, beta in enumerate((0.0, 45.0, 90.0)):
        plot_wavelength_map(grid, beta, ax=fig.add_subplot(1, 3, k + 1))
    fx, fy, m0 = families.wavelength_matrix(grid, 0.0)
    lo = np.unravel_index(np.argmin(m0), m0.shape)
    hi = np.unravel_index(np.argmax(m0), m0.shape)
    section.add_figure(
        writer.figure("fig8_wavelength_map", fig),
        f"Fig 8 family: shorter wavelengths (steeper slopes) raise mu, from "
        f"{np.min(m0):.3f} mu0 at ({fx[lo[0]]:g} pi, {fy[lo[1]]:g} pi) to {np.max(m0):.3f} mu0 "
        f"at ({fx[hi[0]]:g} pi, {fy[hi[1]]:g} pi) for beta = 0; beta = 90 deg is the transpose "
        "and beta = 45 deg is symmetric.",
    )
    section.parameters = [
        ("mu0", "0.3", "1"),
        ("wedge angles (steep, shallow)", "30, 15", "deg"),
        ("2-D amplitude A (wavelengths in units of A)", f"{families.FAMILY_LENGTH:g}", "m"),
        ("1-D stations per period, time samples", "2000, 40", ""),
        ("2-D stations per period and axis, time samples", "32, 16", ""),
        ("load", "full contact", ""),
    ]
    return section


def _life(writer: _Writer) -> Section:
    from frictionlab.plotting import roughness_life as plots

    section = Section(
        "Lattice-spring roughness: adhesion, wear, hierarchy",
        intro=(
            "How friction evolves over a contact's life: tensile springs (adhesion, Eqs "
            "21-22), Archard wear that scales the roughness down (Eqs 23-28), roughness on "
            "several self-similar scales where each level's coefficient is the next level's "
            "local one (Eqs 28-34), and the wear of such a hierarchy, innermost level first "
            "(Eq 35). Families of the paper's Figs 10-14, mu0 = 0.3."
        ),
        anchor="roughness-life",
    )
    adhesion = families.adhesion_cases(
        MU0, settings=LatticeSettings(stations=1000, time_samples=50)
    )
    writer.results("fig10_adhesion", adhesion)
    sine = adhesion["sine/sine"]
    zero = int(np.flatnonzero(sine.load == 0.0)[0])
    section.add_figure(
        writer.figure("fig10_adhesion", plots.fig10_adhesion(adhesion)),
        "Fig 10 family: with k_t = k_c/2 the apparent coefficient mu_a = R/L equals the "
        "non-adhesive mu above the full-contact load, rises as L falls to 0 (where it is "
        f"undefined while the friction force is still {sine.tangential_force[zero, 0]:.3g} N "
        f"per spring and {100 * sine.tensile_fraction_mean[zero, 0]:.0f}% of the springs are "
        "stretched) and is negative under tension; identical in-phase surfaces at 90 deg "
        "show no adhesion effect.",
    )
    wear = families.wear_cases(MU0, samples=11, settings=DEMO_2D)
    writer.results("fig11_wear", wear)
    w = wear["wedge/wedge"]
    section.add_figure(
        writer.figure("fig11_wear", plots.fig11_wear(wear)),
        f"Fig 11 family: Archard wear lowers mu non-linearly to exactly mu0 at the wear "
        f"time T_w (two 30 deg wedges at beta = 0: {w.mu[0, 0] / MU0:.3f} mu0 unworn, "
        f"{w.mu[w.time.size // 2, 0] / MU0:.3f} mu0 at T_w/2), most at beta = 0 in 1-D and "
        "almost independently of beta in 2-D.",
    )
    h1 = families.hierarchy_1d_cases(MU0, settings=DEMO_1D)
    writer.results("fig12_hierarchy", h1)
    rough30 = h1["wedge 30 rough/rough"]
    last_valid = int(np.flatnonzero(rough30.valid[:, 0])[-1])
    section.add_figure(
        writer.figure("fig12_hierarchy_1d", plots.fig12_hierarchy_1d(h1)),
        "Fig 12 family: mu grows with every hierarchical level, geometrically at 90 deg "
        "(Eqs 33-34) and faster at beta = 0, where two 30 deg wedges reach "
        f"{float(rough30.mu[last_valid, 0]) / MU0:.1f} mu0 at n = {last_valid}; the "
        "mean-slope wedge formulas (red dotted) underestimate the sinusoid hierarchies.",
    )
    h2 = families.hierarchy_2d_cases(MU0, settings=DEMO_2D)
    writer.results("fig13_hierarchy_2d", h2)
    a, b, sym = h2["l2pi_3pi"], h2["l3pi_2pi"], h2["l2pi_2pi"]
    n = a.n_levels
    spread = [float(np.ptp(np.ma.getdata(sym.mu[i])) / np.mean(sym.mu[i])) for i in (1, n)]
    section.add_figure(
        writer.figure("fig13_hierarchy_2d", plots.fig13_hierarchy_2d(h2)),
        "Fig 13 family: the symmetric 2-D surface is nearly isotropic with one level "
        f"({100 * spread[0]:.1f}% spread over beta) but the recursion amplifies its small "
        f"anisotropy ({100 * spread[1]:.0f}% with {n} levels), while the asymmetric "
        "(2 pi, 3 pi) and (3 pi, 2 pi) levels agree at 45 deg and differ at beta = 0 "
        f"({float(a.mu[n, 0]) / MU0:.3f} vs {float(b.mu[n, 0]) / MU0:.3f} mu0 with {n} levels).",
    )
    life = families.hierarchy_wear_case(MU0, samples_per_level=6, settings=DEMO_2D)
    writer.table("fig14_hierarchy_wear", life.columns(), life.units(), "hierarchy with wear")
    ratio = life.wear_time[1] / life.wear_time[0]
    section.add_figure(
        writer.figure("fig14_hierarchy_wear", plots.fig14_hierarchy_wear(life)),
        f"Fig 14 family: the innermost level wears first and, once flat, drops out, so "
        f"mu_{life.n_levels} falls in steps from {life.mu[0, -1, 0] / MU0:.3f} mu0 to mu0; "
        f"each level's wear time (Eq 35) is {ratio:.0f} times the previous one, like its "
        "amplitude.",
    )
    section.parameters = [
        ("mu0", "0.3", "1"),
        ("k_c, k_t", "1, 0.5", "N/m"),
        (
            "adhesion surface z = A sin(x/A)",
            f"A = {families.FAMILY_LENGTH:g}, lambda = 2 pi A",
            "m",
        ),
        ("hierarchy: outermost A, lambda", f"{families.HIERARCHY_LENGTH:g}, 2 pi A", "m"),
        ("wear coefficient K, hardness H", "1e-4, 2e9", "1, Pa"),
        ("normal load, velocity, nominal area", "10, 0.1, 1e-4", "N, m/s, m^2"),
        ("hierarchy scale ratio between levels", "10", "1"),
        ("validity", "levels beyond Eq 1's bound are masked (not drawn)", ""),
    ]
    section.notes = [
        "Loads and forces of the adhesion family are per spring (the mean over both spring "
        "families); wear times follow from the stated Archard inputs and scale every time "
        "axis only. Fig 9 (pins on ice) is not reproduced: its experimental values are not "
        "available."
    ]
    return section


#: Band edges of the measured section's scale-resolved friction (wavelengths, m).
MEASURED_CUTOFFS = (150e-6, 60e-6, 25e-6)


def _measured(writer: _Writer) -> Section:
    from frictionlab.demo.topography_file import ground_demo_path
    from frictionlab.plotting.multiscale import multiscale_figure
    from frictionlab.plotting.roughness import mirrored_scans, scenario_figure
    from frictionlab.roughness.generators import flat
    from frictionlab.roughness.lattice import friction_polar
    from frictionlab.roughness.multiscale import multiscale_friction
    from frictionlab.roughness.topography import read_prepared

    path = ground_demo_path()
    prepared = read_prepared(path, periodicity="mirror", detrend="height")
    info = prepared.info
    section = Section(
        "Lattice-spring roughness: a measured topography file",
        intro=(
            "A height map read from an instrument file (ISO 25178 x3p, read by "
            "SurfaceTopography) as a user would: the file ships with frictionlab "
            f"(data/topography/{path.name}, a synthetic ground surface with grooves along y). "
            "The tilt is removed, the map is mirrored to make it periodic, and a flat "
            "counter-face slides over it in full contact (the friction is then the area "
            "average of the local friction over both surfaces). The spectrum is then split "
            "into bands, each band one level of the hierarchical model, to see which scales "
            "make friction anisotropic."
        ),
        anchor="roughness-measured",
    )
    betas = np.arange(0.0, 360.0, 5.0)
    polar = friction_polar(prepared.surface, flat(), MU0, betas)
    writer.table("measured_polar", polar.columns(), {"beta_deg": "deg"}, f"{path.name} on flat")
    ratio = polar.mu_over_mu0
    fig = scenario_figure(
        polar, prepared.surface, flat(), title=f"{path.name} on a flat face",
        scans=mirrored_scans({"lower": info}),
    )  # fmt: skip
    section.add_figure(
        writer.figure("measured_polar", fig),
        f"Sliding across the grooves (beta = 0) gives mu/mu0 = {ratio[0]:.4f}, along them "
        f"(beta = 90 deg) {ratio[18]:.4f}: the file's rms slope {info['rms_slope']:.3f} makes "
        f"friction {100 * (ratio.max() / ratio.min() - 1):.2f}% anisotropic.",
    )
    ms = multiscale_friction(prepared.surface, flat(), MU0, [0.0, 45.0, 90.0], MEASURED_CUTOFFS)
    writer.table("measured_multiscale", ms.columns(), ms.units(), "scale-resolved friction")
    fig = multiscale_figure(ms, f"{path.name}: friction vs the scales retained")
    aniso = ms.mu[:, 0] / ms.mu[:, 2]
    share = (aniso[-1] - aniso[0]) / (aniso[-1] - 1.0)
    section.add_figure(
        writer.figure("measured_multiscale", fig),
        f"Keeping only wavelengths >= {ms.cutoff_m[0] * 1e6:.0f} um the ratio "
        f"mu(0)/mu(90) is {aniso[0]:.4f}; with every band down to the pixel scale "
        f"({ms.cutoff_m[-1] * 1e6:.1f} um) it is {aniso[-1]:.4f}: the wavelengths below "
        f"{ms.cutoff_m[0] * 1e6:.0f} um carry {100 * share:.0f}% of the anisotropy "
        "(mu(0)/mu(90) - 1).",
    )
    _measured_statistics(writer, section, prepared.surface, path.name)
    _measured_models(writer, section, prepared.surface, path.name)
    sizes = " x ".join(f"{v * 1e3:g}" for v in info["source_physical_sizes_m"])
    points = " x ".join(str(v) for v in info["source_points"])
    rms = f"{info['rms_height_m']:.3g}, {info['rms_slope']:.3g}"
    section.parameters = [
        ("file", f"{path.name} (sha256 {info['sha256'][:12]}...)", ""),
        ("scan size; points", f"{sizes}; {points}", "mm; 1"),
        ("preparation", "detrend = height, periodicity = mirror", ""),
        ("rms height, rms slope (prepared)", rms, "m, 1"),
        ("local coefficient mu0", f"{MU0:g}", "1"),
        ("band edges (wavelengths)", ", ".join(f"{c * 1e6:g}" for c in MEASURED_CUTOFFS), "um"),
        ("elastic model: nominal pressure, E*", f"{MEASURED_PRESSURE:g}, {MEASURED_MODULUS:g}",
         "Pa, Pa"),
    ]  # fmt: skip
    return section


#: The measured section's load distribution comparison: nominal pressure and E* (Pa).
MEASURED_PRESSURE = 3.0e8
MEASURED_MODULUS = 1.1e11


def _measured_statistics(writer: _Writer, section: Section, surface: Any, name: str) -> None:
    """The surface statistics of roughness.statistics (PSDs, rms slope per direction)."""
    from frictionlab.plotting.roughness import plot_statistics
    from frictionlab.roughness.statistics import surface_statistics

    stats = surface_statistics(surface)
    for table, columns in stats.tables().items():
        writer.table(f"measured_statistics_{table}", columns, {}, f"{name}: {table}")
    summary = stats.summary()
    section.add_figure(
        writer.figure("measured_statistics", plot_statistics(stats, title=name)),
        f"SurfaceTopography's statistics of the prepared map: rms height "
        f"{summary['rms_height_m'] * 1e6:.3g} um, rms slope {summary['rms_slope']:.3g}; the "
        f"slope is largest across the grooves ({summary['rms_slope_max']:.3g} at "
        f"{summary['rms_slope_max_theta_deg']:g} deg) and smallest along them "
        f"({summary['rms_slope_min']:.3g} at {summary['rms_slope_min_theta_deg']:g} deg).",
    )


def _measured_models(writer: _Writer, section: Section, surface: Any, name: str) -> None:
    """The lattice and the elastic half-space at the same pressure and contact area."""
    from frictionlab.app.roughness_models import ModelRun, model_figure
    from frictionlab.roughness.elastic import elastic_polar
    from frictionlab.roughness.generators import flat
    from frictionlab.roughness.lattice import friction_polar

    betas = np.arange(0.0, 360.0, 15.0)
    elastic = elastic_polar(surface, flat(), MU0, betas, pressure=MEASURED_PRESSURE,
                            modulus=MEASURED_MODULUS)  # fmt: skip
    area = elastic.contact_fraction_mean
    # The lattice on a flat face compresses the springs on the highest points: its
    # stiffness per area k is chosen to touch the same area, k = p / (mean compression).
    heights = np.asarray(surface.heights, dtype=np.float64)
    level = float(np.quantile(heights, 1.0 - area))
    compression = float(np.mean(np.clip(heights - level, 0.0, None)))
    kappa = MEASURED_PRESSURE / compression
    lattice = friction_polar(surface, flat(), MU0, betas, load=compression)  # k_c = 1 N/m
    runs = [
        ModelRun("lattice", MEASURED_PRESSURE, lattice,
                 float(np.mean(lattice.contact_fraction_mean))),
        ModelRun("elastic", MEASURED_PRESSURE, elastic, area),
    ]  # fmt: skip
    writer.table(
        "measured_models",
        {"beta_deg": betas, "mu_lattice": lattice.mu, "mu_elastic": elastic.mu},
        {"beta_deg": "deg"},
        f"{name}: lattice and elastic half-space at {MEASURED_PRESSURE:g} Pa",
    )
    elastic_set = elastic.states[0].pressure > 0.0
    overlap = float(np.count_nonzero(elastic_set & (heights > level))) / max(
        int(np.count_nonzero(elastic_set)), 1
    )

    def spread(mu: np.ndarray) -> float:
        return 100.0 * (float(np.max(mu)) / float(np.min(mu)) - 1.0)

    def excess(mu: np.ndarray) -> float:
        return 100.0 * (float(np.mean(mu)) / MU0 - 1.0)

    fig = model_figure(runs, MU0, f"{name}: where the load goes")
    section.add_figure(
        writer.figure("measured_models", fig),
        f"Pressed at {MEASURED_PRESSURE / 1e6:g} MPa on an elastic half-space "
        f"(E* = {MEASURED_MODULUS / 1e9:g} GPa, ContactMechanics' FFT boundary elements) the "
        f"map touches {100 * area:.2g} % of its area, and the lattice, its spring stiffness "
        f"per area set to {kappa:.3g} Pa/m to touch the same area on the highest points "
        f"({100 * overlap:.0f} % of the elastic contact points are among them), gives a mean "
        f"friction excess mu/mu0 - 1 of {excess(lattice.mu):.2f} % against "
        f"{excess(elastic.mu):.2f} % and an anisotropy mu_max/mu_min - 1 of "
        f"{spread(lattice.mu):.2f} % against {spread(elastic.mu):.2f} % (lattice first).",
    )


def _slug(name: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in name.lower()).strip("_")


def _run(
    builder: Callable[[_Writer], Section],
    out_dir: Path,
    progress: ProgressFactory | None,
    description: str,
    total: int,
) -> Section:
    with (progress or no_progress)(description) as update:
        done = 0

        def step() -> None:
            nonlocal done
            done += 1
            update(done, total)

        update(0, total)
        return builder(_Writer(Path(out_dir), step))


def single_level_section(out_dir: Path, progress: ProgressFactory | None = None) -> Section:
    """Figs 6a, 6b, 7 and 8: case studies, generic 1-D roughness, 2-D surfaces, wavelengths."""
    return _run(_single_level, out_dir, progress, "roughness: Figs 6-8", 4)


def measured_section(out_dir: Path, progress: ProgressFactory | None = None) -> Section:
    """A measured topography file: mu(beta) and scale-resolved friction."""
    return _run(_measured, out_dir, progress, "roughness: measured file", 4)


def life_section(out_dir: Path, progress: ProgressFactory | None = None) -> Section:
    """Figs 10-14: adhesion, wear, 1-D and 2-D hierarchies, hierarchy with wear."""
    return _run(_life, out_dir, progress, "roughness: Figs 10-14", 5)


def roughness_sections(out_dir: Path, progress: ProgressFactory | None = None) -> list[Section]:
    """Compute the Figs 6-14 families, save PNG and CSV files, return the report sections.

    ``out_dir`` is the report's directory (figures go to ``out_dir/roughness/``; figure
    paths in the sections are relative to ``out_dir``). ``progress(description)`` is a
    context manager yielding ``update(done, total)`` (the demo's progress bars).
    """
    return [single_level_section(out_dir, progress), life_section(out_dir, progress)]
