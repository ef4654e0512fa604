"""Adhesion, wear and hierarchy figure families (Figs 10-14): tables and plots.

Usage::

    python examples/roughness_life.py [OUT_DIR]      # default: out/examples

Writes into OUT_DIR/roughness_life/:

* ``fig10_adhesion_<case>.csv``: adhesion (z = A sin(x/A), A = 1 um, k_t = k_c / 2):
  tangential force, mu_apparent (empty at L = 0), stretched fractions vs load per spring;
* ``fig11_wear_<case>.csv``: wedge and 2-D sinusoid wear: mu(t) to mu0 at T_w;
* ``fig12_hierarchy_<case>.csv``: mu_n of wedge and sine hierarchies;
* ``fig13_hierarchy_2d_<case>.csv``: 2-D hierarchies vs beta;
* ``fig14_hierarchy_wear.csv``: mu_i(t) of a 3-level hierarchy worn
  innermost first;
* one PNG per family (:mod:`frictionlab.plotting.roughness_life`).

All values are for mu0 = 0.3 (the paper's value).
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

from frictionlab.io.atomic import write_bytes_atomic
from frictionlab.io.tables import write_csv_atomic
from frictionlab.plotting import roughness_life as plots
from frictionlab.plotting.roughness import figure_png_bytes
from frictionlab.roughness import families


def slug(name: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")


def main(argv: list[str]) -> int:
    out = Path(argv[1] if len(argv) > 1 else "out/examples") / "roughness_life"
    adhesion = families.adhesion_cases(0.3)
    wear = families.wear_cases(0.3)
    hierarchy_1d = families.hierarchy_1d_cases(0.3)
    hierarchy_2d = families.hierarchy_2d_cases(0.3)
    life = families.hierarchy_wear_case(0.3)
    tables: list[tuple[str, object]] = [
        *((f"fig10_adhesion_{slug(k)}", v) for k, v in adhesion.items()),
        *((f"fig11_wear_{slug(k)}", v) for k, v in wear.items()),
        *((f"fig12_hierarchy_{slug(k)}", v) for k, v in hierarchy_1d.items()),
        *((f"fig13_hierarchy_2d_{slug(k)}", v) for k, v in hierarchy_2d.items()),
        ("fig14_hierarchy_wear", life),
    ]
    for name, result in tables:
        write_csv_atomic(out / f"{name}.csv", result.columns(), result.units(), name)  # type: ignore[attr-defined]
    figures = {
        "fig10_adhesion": plots.fig10_adhesion(adhesion),
        "fig11_wear": plots.fig11_wear(wear),
        "fig12_hierarchy_1d": plots.fig12_hierarchy_1d(hierarchy_1d),
        "fig13_hierarchy_2d": plots.fig13_hierarchy_2d(hierarchy_2d),
        "fig14_hierarchy_wear": plots.fig14_hierarchy_wear(life),
    }
    for name, fig in figures.items():
        write_bytes_atomic(out / f"{name}.png", figure_png_bytes(fig))
    print(f"wrote {len(tables)} tables and {len(figures)} plots to {out}")
    n = life.mu.shape[1] - 1
    print(
        f"3-level hierarchy, beta = 0: mu_{n}/mu0 = {life.mu[0, n, 0] / 0.3:.4f} unworn, "
        f"levels drop out at t = " + ", ".join(f"{t:.4g}" for t in life.dropout_time) + " s"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
