"""Directions, loads, pressures and times given as lists: one line naming the key.

Every bad list (not numeric, ragged, empty, NaN, below its minimum) is refused with a
ParameterError whose message starts with the key the caller passed, never a bare NumPy
ValueError and never another key's name.
"""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.bridge.steady import steady_direction
from frictionlab.errors import ParameterError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.adhesion import adhesion_sweep
from frictionlab.roughness.elastic import pressure_sweep
from frictionlab.roughness.families import wavelength_map
from frictionlab.roughness.hierarchy import hierarchy_wear, self_similar_levels
from frictionlab.roughness.lattice import check_betas
from frictionlab.roughness.wear import WearSettings, wear_history

WEAR = WearSettings(
    wear_coefficient=1e-4, hardness=2e9, normal_load=100.0, velocity=0.1, nominal_area=1e-4
)
RAGGED = [[1.0, 2.0], [3.0]]


def _refused(key: str, call, *args, **kwargs) -> str:
    with pytest.raises(ParameterError) as info:
        call(*args, **kwargs)
    message = str(info.value)
    assert info.value.field == key
    assert message.startswith(f"{key} = ")
    assert "\n" not in message
    return message


@pytest.mark.parametrize("bad", [["a"], RAGGED, [], [0.0, np.nan], [[0.0, 1.0]], [np.inf]])
def test_finite_vector_refusals(bad) -> None:
    _refused("beta_deg", check_betas, bad)


def test_finite_vector_accepts_and_copies() -> None:
    from frictionlab._arrays import finite_vector

    given = np.array([3.0, 1.0])
    out = finite_vector("x", given, "numbers")
    out[0] = 9.0
    assert given[0] == 3.0  # never the caller's array
    assert finite_vector("x", 2, "numbers").tolist() == [2.0]
    assert finite_vector("x", [], "numbers", empty=True).shape == (0,)
    _refused("x", finite_vector, "x", [0.0, -1.0], "numbers >= 0", minimum=0.0)


def test_ragged_value_in_an_error_message() -> None:
    err = ParameterError("k", [[1, 2], [3]], "a list")
    assert str(err) == "k = [[1, 2], [3]] is invalid: allowed a list"
    long_text = str(ParameterError("k", [list(range(40)), [1]], "a list"))
    assert long_text.endswith("... is invalid: allowed a list")
    assert len(long_text) < 130


@pytest.mark.parametrize("bad", [["a", 1.0], [1.0, np.nan], [0.0, -1.0], RAGGED])
def test_wavelength_map_names_factors(bad) -> None:
    message = _refused("factors", wavelength_map, 0.3, bad, [0.0])
    assert "beta_deg" not in message


@pytest.mark.parametrize("bad", [["a"], [-1.0], [np.nan], RAGGED])
def test_wear_times(bad) -> None:
    lower = gen.wedge(30.0, 1e-3)
    _refused("times", wear_history, lower, gen.flat(), 0.3, [0.0], WEAR, times=bad)
    levels = self_similar_levels(lower, gen.flat(), 2, 10.0)
    _refused("times", hierarchy_wear, levels, 0.3, [0.0], WEAR, times=bad)


def test_loads_pressures_and_directions() -> None:
    w = gen.wedge(30.0, 1e-3)
    _refused("loads", adhesion_sweep, w, gen.flat(), 0.3, ["a"], [0.0])
    _refused("loads", adhesion_sweep, w, gen.flat(), 0.3, [1.0, np.nan], [0.0])
    surface = gen.sinusoid(1.0, [2 * np.pi, 2 * np.pi])
    _refused("pressure", pressure_sweep, surface, surface, 0.3, [0.0], ["a"], modulus=1e9)
    _refused("theta_deg", steady_direction, ["north"])
    assert steady_direction([]).shape == (0, 2)
