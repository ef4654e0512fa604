"""Tiny scenarios and sweep files for the sweep tests."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from frictionlab._frames import split_title

BASE = """\
title = "tiny slide-hold-slide"
[law]
surface = "coulomb"
alpha_n = 1000.0
alpha_t = 1000.0
mu_s = 0.5
mu_k = 0.3
u = 100.0
kappa = 1.0
xi = 0.001

[initial]
normal_traction = 1.0

[[program]]
kind = "slide"
velocity = 0.1
distance = 0.2
steps = {steps}

[[program]]
kind = "hold"
duration = 10.0
steps = 5

[[program]]
kind = "slide"
velocity = 0.1
distance = 0.05
steps = 10
"""


def write_sweep(tmp: Path, body: str, steps: int = 20) -> Path:
    """A base scenario and a sweep file (``base = "base.toml"`` + ``body``) in ``tmp``."""
    (tmp / "base.toml").write_text(BASE.format(steps=steps))
    path = tmp / "sweep.toml"
    path.write_text(f'base = "base.toml"\n{body}')
    return path


def read_sweep_table(out: Path) -> pd.DataFrame:
    """``out/sweep.csv`` by pandas, columns named without their ``[unit]``."""
    table = pd.read_csv(out / "sweep.csv", keep_default_na=False)
    return table.rename(columns=lambda title: split_title(title)[0])
