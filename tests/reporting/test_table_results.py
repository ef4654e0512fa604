"""Every table result has columns(), units() and to_dataframe() (the TableResult mixin).

The frame is the table written as CSV and read back by pandas; each column is the
attribute it names; the repr is one line without arrays.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from frictionlab._frames import TableResult
from frictionlab.bridge.fit import DirectionalFriction, fit_anisotropy
from frictionlab.calibration.fit import FitResult
from frictionlab.contact.history import ContactHistory
from frictionlab.io.tables import write_csv_atomic
from frictionlab.subloading import SubloadingParams, initial_state, update
from frictionlab.subloading.return_map import Status

pd = pytest.importorskip("pandas")


def _round_trip(result: TableResult, tmp_path: Path) -> None:
    frame = result.to_dataframe()
    path = write_csv_atomic(tmp_path / "t.csv", result.columns(), result.units())
    pd.testing.assert_frame_equal(frame, pd.read_csv(path), check_dtype=False)
    text = repr(result)
    assert text.startswith(f"{type(result).__name__}(") and "\n" not in text
    assert "array" not in text and len(text) < 500


def params() -> SubloadingParams:
    return SubloadingParams(
        alpha_n=1e12, alpha_t=1e12, mu_s=0.5, mu_k=0.3, u=1e6, kappa=1e4, xi=1e-2
    )


def test_step_result_rows_are_points(tmp_path: Path) -> None:
    p = params()
    state = initial_state(p, [1e6, 2e6, 1e6])
    slip = np.array([[1e-9, 0.0, 0.0], [0.0, 2e-9, 0.0], [0.0, 0.0, -1.0]])  # the last opens
    result = update(p, state, slip, 1e-3, raise_on_failure=False)
    frame = result.to_dataframe()
    np.testing.assert_array_equal(frame["traction_1 [Pa]"], result.traction[:, 0])
    np.testing.assert_array_equal(frame["dissipation [J/m^2]"], result.dissipation)
    assert list(frame["point [-]"]) == [1, 2, 3]
    assert list(frame["status [-]"]) == [Status(int(c)).name.lower() for c in result.status]
    assert frame["status [-]"].iloc[2] == "open"
    _round_trip(result, tmp_path)


def test_anisotropy_fit_rows_are_directions(tmp_path: Path) -> None:
    beta = np.arange(0.0, 360.0, 30.0)
    rad = np.radians(beta)
    polar = DirectionalFriction(beta, 0.4 * np.cos(rad), 0.4 * np.sin(rad))  # isotropic
    fit = fit_anisotropy(polar)
    frame = fit.to_dataframe()
    np.testing.assert_array_equal(frame["beta_deg [deg]"], beta)
    np.testing.assert_allclose(frame["data_x [-]"], 0.4 * np.cos(rad), rtol=0, atol=1e-15)
    np.testing.assert_allclose(frame["misfit [-]"], 0.0, atol=1e-9)  # the law is isotropic
    _round_trip(fit, tmp_path)


def test_fit_result_rows_are_parameters(tmp_path: Path) -> None:
    # only the fields columns() reads are set: the table is a view of them
    fit = object.__new__(FitResult)
    for name, value in {
        "params": params(), "names": ("mu_s", "kappa"), "values": np.array([0.5, 2e4]),
        "start": np.array([0.4, 1e4]), "stderr": np.array([0.01, math.inf]),
    }.items():  # fmt: skip
        object.__setattr__(fit, name, value)
    frame = fit.to_dataframe()
    assert list(frame["parameter [-]"]) == ["mu_s", "kappa"]
    assert list(frame["unit [-]"]) == ["-", "1/m"]  # the cone's kappa: per metre of slip
    # an infinite stderr (not identified) is undefined: NaN in the frame, empty in the CSV
    np.testing.assert_allclose(frame["relative_stderr [-]"], [0.02, math.nan])
    path = write_csv_atomic(tmp_path / "t.csv", fit.columns(), fit.units())
    pd.testing.assert_frame_equal(frame, pd.read_csv(path), check_dtype=False)


def test_contact_history_rows_are_steps(tmp_path: Path) -> None:
    S, P = 3, 4
    steps = np.arange(S, dtype=float)
    grid = np.zeros((S, P))
    x = np.linspace(0.0, 0.3, P)
    hist = ContactHistory(
        time=steps, stage=np.array([0, 1, 1]), top_displacement=1e-6 * steps,
        top_displacement_y=np.zeros(S), top_shear=np.zeros(S), top_shear_y=np.zeros(S),
        tangential_force=np.array([0.0, 1.0, 2.0]), tangential_force_y=np.zeros(S),
        normal_force=np.array([0.0, 4.0, 4.0]), iterations=np.array([0, 3, 2]),
        cuts=np.zeros(S, dtype=int), residuals=[[] for _ in range(S)], x=x, y=np.zeros(P),
        weight=np.full(P, 0.1), slip=grid, slip_y=grid, approach=grid, plastic_slip=grid,
        traction_t=grid, traction_t_y=grid, traction_n=grid, R=grid, F=grid,
        status=np.zeros((S, P), dtype=np.int8), nodes=np.array([[0.0, 0.4], [0.0, 0.1]]),
        cells=np.zeros((3, 0), dtype=int), dof_x=np.zeros(0, dtype=int),
        dof_y=np.zeros(0, dtype=int),
    )  # fmt: skip
    frame = hist.to_dataframe()
    assert "top_shear_y [Pa]" not in frame  # a 2-D block has no y columns
    np.testing.assert_array_equal(frame["friction_ratio [-]"], [0.0, 0.25, 0.5])  # Q/P, 0 at P=0
    np.testing.assert_array_equal(frame["tangential_force [N/m]"], [0.0, 1.0, 2.0])
    np.testing.assert_array_equal(frame["slip_front [m]"], 0.0)  # every point sticks
    _round_trip(hist, tmp_path)
