"""The lattice-spring model's figure families (Figs 6a, 6b, 7, 8): tables and plots.

Usage::

    python examples/roughness_figures.py [OUT_DIR]      # default: out/examples

Writes into OUT_DIR/roughness_figures/:

* ``fig6a_wedge_cases.csv``, ``fig6b_generic_cases.csv``: mu/mu0 (and its x, y parts) vs
  beta for the six 1-D cases A-F (30/15 deg wedges, Eqs 15-16; smooth faces on the lattice);
* ``fig7_surfaces_2d.csv``: identical 2-D product sinusoids, symmetric (2 pi, 2 pi) and
  asymmetric (2 pi, 3 pi), (3 pi, 2 pi), vs beta;
* ``fig8_wavelength_map.csv``: the 25 wavelength combinations at beta = 0, 45, 90 deg;
* one PNG per family, plotted with :mod:`frictionlab.plotting.roughness`.

All values are for mu0 = 0.3 (the paper's value) in full contact.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from frictionlab.io.atomic import write_bytes_atomic
from frictionlab.io.tables import write_csv_atomic
from frictionlab.plotting.roughness import (
    figure_png_bytes,
    new_figure,
    plot_family_lines,
    plot_wavelength_map,
)
from frictionlab.roughness import families


def main(argv: list[str]) -> int:
    out = Path(argv[1] if len(argv) > 1 else "out/examples") / "roughness_figures"
    betas = np.arange(0.0, 91.0, 5.0)
    tables = {
        "fig6a_wedge_cases": families.wedge_cases(0.3, (30.0, 15.0), betas),
        "fig6b_generic_cases": families.generic_cases(0.3, (30.0, 15.0), betas),
        "fig7_surfaces_2d": families.surfaces_2d_vs_beta(0.3, betas),
        "fig8_wavelength_map": families.wavelength_map(0.3),
    }
    for name, table in tables.items():
        write_csv_atomic(out / f"{name}.csv", dict(table.columns), table.units, table.description)

    for name in ("fig6a_wedge_cases", "fig6b_generic_cases", "fig7_surfaces_2d"):
        fig = new_figure(6.5, 4.5)
        plot_family_lines(tables[name], ax=fig.add_subplot())
        write_bytes_atomic(out / f"{name}.png", figure_png_bytes(fig))

    fig = new_figure(14.0, 4.2)
    for k, beta in enumerate((0.0, 45.0, 90.0)):
        plot_wavelength_map(tables["fig8_wavelength_map"], beta, ax=fig.add_subplot(1, 3, k + 1))
    write_bytes_atomic(out / "fig8_wavelength_map.png", figure_png_bytes(fig))

    wedge = tables["fig6a_wedge_cases"]
    print(f"wrote {len(tables)} tables and 4 plots to {out}")
    print(
        "mu/mu0 at beta = 0 / 90 deg: "
        + ", ".join(
            f"{c}: {wedge[f'mu_over_mu0_{c}'][0]:.4f} / {wedge[f'mu_over_mu0_{c}'][-1]:.4f}"
            for c in "ABCDEF"
        )
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
