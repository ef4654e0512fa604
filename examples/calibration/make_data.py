"""Make shs_run12.csv: a synthetic tribometer export of a slide-hold-slide run.

The friction ratio is computed by the law with the TRUE parameters below through the
programme of the packaged calibrate.toml (one contact point), sampled at 10 Hz, plus
Gaussian noise of standard deviation NOISE = 0.002 (seeded; the instrument reports its
magnitude). The file mimics a lab's export: comment lines, an index column, a units row,
time in minutes, displacement in millimetres, the friction coefficient as "COF", and an
extra normal-load column that the fit ignores.

The shipped copy is frictionlab/data/examples/calibration/shs_run12.csv (`frictionlab
example calibrate --write DIR` writes it with its configuration).

Run: ``python examples/calibration/make_data.py [OUT.csv]``
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from frictionlab.driver import simulate
from frictionlab.io.atomic import write_text_atomic
from frictionlab.io.config import load_toml
from frictionlab.io.scenario import parse_initial_table, parse_program_tables
from frictionlab.subloading import SubloadingParams

HERE = Path(__file__).resolve().parent
#: The packaged example: the configuration and where its data ship.
PACKAGED = HERE.parents[1] / "src" / "frictionlab" / "data" / "examples"
#: The parameters the calibration should find (the rest as in calibrate.toml's [law]).
TRUE = {"mu_s": 0.5, "mu_k": 0.3, "u": 2.0e4, "kappa": 3000.0, "xi": 5.0e-3, "alpha_t": 5.0e11}
NOISE = 0.002
RATE_HZ = 10.0
AREA_M2 = 1.0e-5  # 10 mm^2 apparent contact, for the load column only
SEED = 12


def make(out: Path) -> Path:
    config = load_toml(PACKAGED / "calibrate.toml")
    law = {k: v for k, v in config["law"].items() if k != "surface"}
    law.update(TRUE)
    params = SubloadingParams(**law)
    data = config["data"][0]
    initial, _ = parse_initial_table(data["initial"])
    program = parse_program_tables(data["program"], PACKAGED)
    history = simulate(params, program, initial)
    assert history.success, history.message
    t_end = float(history.time[-1, 0])
    t = np.arange(0.0, t_end + 1e-9, 1.0 / RATE_HZ)
    t[-1] = min(t[-1], t_end)
    rng = np.random.default_rng(SEED)
    cof = np.interp(t, history.time[:, 0], history.friction_ratio[:, 0])
    cof = np.abs(cof + NOISE * rng.standard_normal(t.size))  # the instrument reports |COF|
    slip = np.interp(t, history.time[:, 0], history.slip[:, 0, 0])
    load = float(initial.normal_traction) * AREA_M2
    lines = [
        "# Tribometer TR-2 export, run 12 (synthetic: examples/calibration/make_data.py)",
        f"# sample rate {RATE_HZ:g} Hz; normal load {load:g} N on {AREA_M2 * 1e6:g} mm^2",
        ",Time,Displacement,Normal load,COF",
        ",min,mm,N,-",
    ]
    for i, (ti, si, ci) in enumerate(zip(t, slip, cof, strict=True)):
        lines.append(f"{i},{ti / 60.0:.8f},{si * 1e3:.6f},{load:.3f},{ci:.6f}")
    return write_text_atomic(out, "\n".join(lines) + "\n")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = PACKAGED / "calibration" / "shs_run12.csv"
    parser.add_argument("out", nargs="?", type=Path, default=default)
    print(f"wrote {make(parser.parse_args().out)}")
