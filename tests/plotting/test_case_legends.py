"""The figures every simulate run (each sweep case) draws place their legends without
matplotlib's ``loc="best"`` search: its cost grows with the points drawn, and past one
second it printed a UserWarning ("Creating legend with loc='best' can be slow") per case."""

from __future__ import annotations

import warnings
from pathlib import Path

import matplotlib.legend
import pytest
from tests.sweep.support import BASE

from frictionlab.cli import main

ROTATION = """\
[law]
surface = "coulomb"
alpha_n = 1000.0
alpha_t = 1000.0
mu_s = 0.5
mu_k = 0.3
u = 100.0
kappa = 1.0
[initial]
normal_traction = 1.0
[[program]]
kind = "slide"
velocity = 0.1
distance = 0.1
direction_deg = [0.0, 90.0]
steps = 10
"""


@pytest.mark.parametrize("scenario", [BASE.format(steps=10), ROTATION])
def test_case_figures_never_search_for_the_best_legend_place(
    scenario: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def refuse(self: matplotlib.legend.Legend, *args: object, **kwargs: object) -> None:
        raise AssertionError(f"legend of '{self.axes.get_ylabel()}' searches for loc='best'")

    monkeypatch.setattr(matplotlib.legend.Legend, "_find_best_position", refuse)
    path = tmp_path / "s.toml"
    path.write_text(scenario)
    out = tmp_path / "out"
    with warnings.catch_warnings():
        warnings.simplefilter("error", UserWarning)
        assert main(["simulate", str(path), "--out", str(out)]) == 0
    assert (out / "friction.png").is_file()
