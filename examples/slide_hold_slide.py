"""Slide-hold-slide from Python: five hold times in one vectorised run, written to a folder.

Slides a virgin Coulomb contact to kinetic friction, holds it (one hold time per contact
point), slides again, and writes history.csv, summary.json and friction.png into the
output directory, next to a table of restart peaks against the closed-form recovery of
mu during the hold.

Run: ``python examples/slide_hold_slide.py OUT_DIR``
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from frictionlab.driver import InitialConditions, simulate, slide_hold_slide
from frictionlab.io.tables import write_csv_atomic
from frictionlab.plotting.law import plot_friction, save_figure
from frictionlab.subloading import SubloadingParams, hold_recovery


def main(out_dir: Path) -> dict[str, np.ndarray]:
    # A contact at 1 MPa: stiffness 1 MPa per um, softening over ~1 mm of slip
    params = SubloadingParams(
        surface="coulomb", alpha_n=1e12, alpha_t=1e12, mu_s=0.5, mu_k=0.3,
        u=1e5, kappa=1e3, xi=1e-3,
    )  # fmt: skip  # alpha in Pa/m, u and kappa in 1/m, xi in 1/s
    hold_time = np.array([1.0, 10.0, 100.0, 1000.0, 1e4])  # s, one per point
    program = slide_hold_slide(velocity=1e-4, distance=1e-3, hold_time=hold_time)  # 0.1 mm/s, 1 mm
    history = simulate(params, program, InitialConditions(normal_traction=1e6))
    slide, hold, again = history.segments
    mu_stop = history.F[slide.last_row]
    mu_end = history.F[hold.last_row]
    peak = history.friction_ratio[again.rows].max(axis=0)
    expected = hold_recovery(mu_stop, 0.5, 1e-3, hold_time)
    write_csv_atomic(
        out_dir / "restart_peaks.csv",
        {"hold_time": hold_time, "mu_end_of_hold": mu_end, "mu_closed_form": expected,
         "restart_peak": peak},
        {"hold_time": "s"},
        "slide-hold-slide at 1 MPa",
    )  # fmt: skip
    labels = [f"hold {t:g} s" for t in hold_time]
    save_figure(plot_friction(history, labels, "Slide-hold-slide"), out_dir / "friction.png")
    print(f"{'hold [s]':>9} {'mu end of hold':>15} {'closed form':>12} {'restart peak':>13}")
    for row in zip(hold_time, mu_end, expected, peak, strict=True):
        print(f"{row[0]:>9g} {row[1]:>15.6f} {row[2]:>12.6f} {row[3]:>13.6f}")
    print(f"wrote {out_dir / 'restart_peaks.csv'} and {out_dir / 'friction.png'}")
    return {"hold_time": hold_time, "mu_end": mu_end, "expected": expected, "peak": peak}


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir", type=Path)
    main(parser.parse_args().out_dir)
