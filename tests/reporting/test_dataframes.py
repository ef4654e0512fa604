"""Result objects as pandas DataFrames: the same frame as pandas.read_csv of the CSV file."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frictionlab.driver import simulate, slide_hold_slide
from frictionlab.driver.table import history_columns
from frictionlab.io.tables import write_csv_atomic
from frictionlab.roughness import generators as gen
from frictionlab.roughness.adhesion import adhesion_sweep
from frictionlab.roughness.lattice import friction_polar
from frictionlab.subloading import SubloadingParams

pd = pytest.importorskip("pandas")


def params() -> SubloadingParams:
    return SubloadingParams(
        alpha_n=1e12, alpha_t=1e12, mu_s=0.5, mu_k=0.3, u=1e6, kappa=1e4, xi=1e-2
    )


def test_history_frame_is_the_csv_file(tmp_path: Path) -> None:
    program = slide_hold_slide(1e-3, 2e-5, [1.0, 10.0], steps=20, hold_steps=3)
    history = simulate(params(), program, n_points=2)
    frame = history.to_dataframe()
    cols, units = history_columns(history)
    path = write_csv_atomic(tmp_path / "history.csv", cols, units)
    pd.testing.assert_frame_equal(frame, pd.read_csv(path))
    assert len(frame) == 2 * history.n_rows and frame.attrs["units"]["time"] == "s"
    point2 = frame[frame["point [-]"] == 2]
    np.testing.assert_array_equal(point2["traction_1 [Pa]"], history.traction[:, 1, 0])
    np.testing.assert_array_equal(point2["R [-]"], history.R[:, 1])
    text = repr(history)
    assert text.startswith("History(2 points x") and len(text) < 100 and "array" not in text


def test_polar_and_adhesion_frames_match_their_tables(tmp_path: Path) -> None:
    polar = friction_polar(
        gen.wedge(20.0, 1e-4), gen.flat(), 0.3, [0.0, 90.0, 180.0],
        stations=200, time_samples=20,
    )  # fmt: skip
    frame = polar.to_dataframe()
    np.testing.assert_array_equal(frame["mu [-]"], polar.mu)
    np.testing.assert_array_equal(frame["beta_deg [deg]"], [0.0, 90.0, 180.0])
    path = write_csv_atomic(tmp_path / "polar.csv", polar.columns(), polar.units())
    pd.testing.assert_frame_equal(frame, pd.read_csv(path), check_dtype=False)
    assert repr(polar).startswith("FrictionPolar(3 rows x") and "array" not in repr(polar)
    sine = gen.sinusoid(1e-5, 1e-4)
    sweep = adhesion_sweep(sine, sine, 0.3, [0.5, 0.0], [0.0, 90.0], stations=200,
                           time_samples=20)  # fmt: skip
    frame = sweep.to_dataframe()
    assert np.isnan(frame["mu_apparent [-]"]).sum() == 2  # undefined at zero load: NaN
    path = write_csv_atomic(tmp_path / "adhesion.csv", sweep.columns(), sweep.units())
    pd.testing.assert_frame_equal(frame, pd.read_csv(path), check_dtype=False)
