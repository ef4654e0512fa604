"""Fretting of a rigid cylinder on an elastic block: the Coulomb limit against the
subloading-friction law (the figure docs/img/contact_fretting.png).

A rigid cylinder (R = 50 mm) is pressed into a plane-strain block (E = 1 GPa,
nu = 0.49) with the Hertz load of a = 1 mm; the block's top (a rigid plate) is then
moved +-40 um along x twice, held for 100 s, and moved once more. Coulomb: mu = 0.6
everywhere; subloading: mu_s = 0.6 softening to mu_k = 0.4 over ~10 um of slip
(kappa) and recovering at rest (xi), with a smooth elastic-plastic transition (u)::

    python examples/contact_fretting.py [--out docs/img/contact_fretting.png]
"""

from __future__ import annotations

import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from frictionlab.contact import Block, Hold, NormalLoad, Reverse, Slide, run_contact
from frictionlab.contact.block import Refinement
from frictionlab.contact.shapes import Base
from frictionlab.contact.solver import SolverOptions
from frictionlab.subloading import SubloadingParams

E, NU, R, A = 1.0e9, 0.49, 0.05, 1.0e-3
P = A**2 * math.pi * E / (1 - NU**2) / (4 * R)
AMPLITUDE = 40e-6


def run(params: SubloadingParams):  # type: ignore[no-untyped-def]
    block = Block(
        E=E, nu=NU, width=40 * A, height=20 * A, element_size=4 * A,
        integration="selective", refinement=Refinement(size=A / 20, extent=1.2 * A, growth=1.3),
    )  # fmt: skip
    program = [
        Slide(velocity=1e-6, distance=AMPLITUDE, steps=12),
        Reverse(distance=2 * AMPLITUDE, steps=24),
        Reverse(distance=2 * AMPLITUDE, steps=24),
        Reverse(distance=2 * AMPLITUDE, steps=24),
        Reverse(distance=AMPLITUDE, steps=12),
        Hold(duration=100.0, steps=4),
        Slide(velocity=1e-6, distance=AMPLITUDE, steps=48),
    ]
    history = run_contact(
        block, params, NormalLoad(force=P, steps=4), program,
        base=Base("cylinder", radius=R), settings=SolverOptions(tolerance=1e-8),
    )  # fmt: skip
    if not history.success:  # the rows before a failed step are kept and plotted
        print(f"stopped early: {history.message}")
    return history


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="docs/img/contact_fretting.png")
    args = parser.parse_args()
    stiff = dict(alpha_n=1e15, alpha_t=1e15)
    coulomb = run(SubloadingParams(**stiff, mu_s=0.6, mu_k=0.6, u=1e9, kappa=0.0, xi=0.0))
    subloading = run(SubloadingParams(**stiff, mu_s=0.6, mu_k=0.4, u=2e6, kappa=1e5, xi=0.05))
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    runs = ((coulomb, "Coulomb, mu = 0.6", "--"), (subloading, "subloading, 0.6 -> 0.4", "-"))
    for history, label, style in runs:
        after_hold = history.stage >= 7
        ax.plot(history.travel[~after_hold] * 1e6, history.friction_ratio[~after_hold],
                style, lw=1.2, label=label)  # fmt: skip
        if style == "-":
            ax.plot(history.travel[after_hold] * 1e6, history.friction_ratio[after_hold],
                    "-", color="tab:red", lw=1.4, label="subloading, after 100 s")  # fmt: skip
    ax.axhline(0.0, color="0.7", lw=0.6)
    ax.set_xlabel("plate travel [um]")
    ax.set_ylabel("Q/P")
    ax.set_title("Fretting of a rigid cylinder, a = 1 mm, +-40 um")
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    peaks = [
        float(np.max(np.abs(subloading.friction_ratio[subloading.stage == s]), initial=0.0))
        for s in (1, 3, 7)
    ]
    print(f"subloading |Q/P| peak of the first slide, second cycle, after the hold: {peaks}")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
