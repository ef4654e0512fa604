"""Fretting of a rigid cylinder on an elastic block: the Coulomb limit against the
subloading-friction law (the figure docs/img/contact_fretting.png).

A rigid cylinder (R = 50 mm) is pressed into a plane-strain block (E = 1 GPa,
nu = 0.49) with the Hertz load of a = 1 mm; the block's top (a rigid plate) is then
moved +-40 um along x twice, held for 100 s, and moved once more. Coulomb: mu = 0.6
everywhere; subloading: mu_s = 0.6 softening to mu_k = 0.4 over ~10 um of slip
(kappa) and recovering at rest (xi), with a smooth elastic-plastic transition (u).
The set-up is shared with the demo's fretting section (frictionlab.demo.fretting)::

    python examples/contact_fretting.py [--out docs/img/contact_fretting.png] [--coarse]

``--coarse`` runs the same programme on the demo's mesh (a/6) with a third of the steps
(a quick check, as in the tests; the figure in the docs is the default a/20 run).
"""

from __future__ import annotations

import argparse

import matplotlib

matplotlib.use("Agg")

from frictionlab.contact import Hold, Reverse, Slide
from frictionlab.demo.fretting import (
    AMPLITUDE,
    COULOMB,
    SUBLOADING,
    A,
    fretting_block,
    fretting_figure,
    run_fretting,
    stage_peaks,
)


def run(law: dict[str, float], coarse: bool = False):  # type: ignore[no-untyped-def]
    n = 4 if coarse else 12  # steps per amplitude of travel
    program = [
        Slide(velocity=1e-6, distance=AMPLITUDE, steps=n),
        Reverse(distance=2 * AMPLITUDE, steps=2 * n),
        Reverse(distance=2 * AMPLITUDE, steps=2 * n),
        Reverse(distance=2 * AMPLITUDE, steps=2 * n),
        Reverse(distance=AMPLITUDE, steps=n),
        Hold(duration=100.0, steps=4),
        Slide(velocity=1e-6, distance=AMPLITUDE, steps=4 * n),
    ]
    block = fretting_block(A / 6) if coarse else fretting_block()
    history = run_fretting(law, block, program)
    if not history.success:  # the rows before a failed step are kept and plotted
        print(f"stopped early: {history.message}")
    return history


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="docs/img/contact_fretting.png")
    parser.add_argument(
        "--coarse", action="store_true", help="the demo's a/6 mesh and a third of the steps"
    )
    args = parser.parse_args()
    coulomb, subloading = run(COULOMB, args.coarse), run(SUBLOADING, args.coarse)
    title = "Fretting of a rigid cylinder, a = 1 mm, +-40 um"
    fretting_figure(coulomb, subloading, 6, title).savefig(args.out, dpi=100)
    peaks = stage_peaks(subloading, (1, 3, 7))
    print(f"subloading |Q/P| peak of the first slide, second cycle, after the hold: {peaks}")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
