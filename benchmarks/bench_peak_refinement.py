"""Cost and accuracy of the driver's peak refinement (``[run] peak_accuracy``).

One point, two 68.5-degree turns of 15 steps each (slip per step ~27 elastic slips): the
refined peak of each segment needs trial steps of hundreds of substeps. Prints, warm
(after one run that compiles), the process CPU time of the run with and without the
refinement (median of ``--repeats``), the refinement's law calls (``work["peak_solves"]``,
when the code reports it), the load average, and the refined peaks beside the largest
samples of a run of 3000 steps per segment at the driver's accuracy 1e-7 (slow: skipped
with ``--no-reference``).

Run: ``PYTHONPATH=src python benchmarks/bench_peak_refinement.py``; for the code of
another checkout, put its ``src`` on ``PYTHONPATH`` instead.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from frictionlab.driver import DriverSettings, Turn, simulate
from frictionlab.subloading import SubloadingParams

PARAMS = SubloadingParams(surface="coulomb", alpha_n=1000.0, alpha_t=1000.0, mu_s=0.5,
                          mu_k=0.3, u=100.0, kappa=1.0, xi=1e-3, rotation=(0.0046, 0.0),
                          orthotropy=(1.0, 0.593))  # fmt: skip


def program(per_segment: int) -> tuple[Turn, Turn]:
    return (
        Turn(68.5, velocity=0.1, distance=0.2, steps=per_segment),
        Turn(68.5, steps=per_segment),
    )


def cpu(peak_accuracy: float | None) -> tuple[float, object]:
    t0 = time.process_time()
    h = simulate(PARAMS, program(15), settings=DriverSettings(accuracy=None),
                 peak_accuracy=peak_accuracy)  # fmt: skip
    return time.process_time() - t0, h


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-reference", action="store_true")
    args = parser.parse_args()
    cpu(1e-4)  # compiles
    refined = statistics.median(cpu(1e-4)[0] for _ in range(args.repeats))
    sampled = statistics.median(cpu(None)[0] for _ in range(args.repeats))
    _, h = cpu(1e-4)
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    print(f"run with refinement {refined:.3f} CPU s, without {sampled:.3f} CPU s "
          f"(load {load}); refinement law calls {h.work.get('peak_solves', 'n/a')}")  # fmt: skip
    print("refined peaks", np.array2string(h.peaks.friction_ratio, precision=9))
    print("largest samples", np.array2string(h.peaks.sampled_friction_ratio, precision=9))
    if not args.no_reference:
        ref = simulate(PARAMS, program(3000), settings=DriverSettings(accuracy=1e-7),
                       peak_accuracy=None)  # fmt: skip
        peaks = [ref.friction_ratio[s.first_row : s.last_row + 1, 0].max() for s in ref.segments]
        print("reference (3000 steps per segment, accuracy 1e-7)",
              np.array2string(np.array(peaks), precision=9))  # fmt: skip
        print("relative error of the refined peaks", np.array2string(
            h.peaks.friction_ratio / np.array(peaks) - 1, precision=2))  # fmt: skip


if __name__ == "__main__":
    main()
