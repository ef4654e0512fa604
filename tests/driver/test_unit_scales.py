"""The bundled scenarios at physical scales, and the same runs at other unit scales.

Changing the unit of traction by S (Pa -> MPa), of length by L (m -> mm) and of time by T
leaves every dimensionless result unchanged when each input is converted by its dimension:
tractions and F (closed surfaces) by S, alpha by S/L, u by 1/L, the cone's kappa by 1/L and
xi by 1/T, the closed surfaces' kappa by S/L and xi by S/T, slips by L, velocities by L/T,
durations by T, machine stiffness and damping by S/L and S T/L, mass by S T^2/L. The
friction ratio, R and the cone's F (= mu) must then be the same, step by step.
"""

from __future__ import annotations

import copy
import tomllib
from importlib import resources
from typing import Any

import numpy as np
import pytest

from frictionlab.app.simulate import run_scenario
from frictionlab.demo import bundled_scenarios
from frictionlab.io.scenario import parse_scenario


def dimensions(closed: bool) -> dict[str, dict[str, tuple[int, int, int]]]:
    """Exponents (traction, length, time) of every dimensional input, per table."""
    law = {
        "alpha_n": (1, -1, 0),
        "alpha_t": (1, -1, 0),
        "u": (0, -1, 0),
        "kappa": (1, -1, 0) if closed else (0, -1, 0),
        "xi": (1, 0, -1) if closed else (0, 0, -1),
        "F_s": (1, 0, 0),
        "F_k": (1, 0, 0),
    }
    initial = {"normal_traction": (1, 0, 0), "tangential_traction": (1, 0, 0)}
    program = {
        "velocity": (0, 1, -1),
        "distance": (0, 1, 0),
        "max_step": (0, 1, 0),
        "amplitude": (0, 1, 0),
        "duration": (0, 0, 1),
        "traction": (1, 0, 0),
        "traction_change": (1, 0, 0),
    }
    machine = {
        "stiffness": (1, -1, 0),
        "velocity": (0, 1, -1),
        "mass": (1, -1, 2),
        "damping": (1, -1, 1),
        "duration": (0, 0, 1),
    }
    return {"law": law, "initial": initial, "program": program, "machine": machine}  # fmt: skip


def rescale(data: dict[str, Any], S: float, L: float, T: float) -> dict[str, Any]:
    """The scenario with every dimensional input converted to new units."""
    out = copy.deepcopy(data)
    closed = out["law"].get("surface", "coulomb") != "coulomb"
    for table, dims in dimensions(closed).items():
        for entry in out.get(table, []) if table == "program" else [out.get(table, {})]:
            for key, (a, b, c) in dims.items():
                if key in entry:
                    factor = S**a * L**b * T**c
                    value = entry[key]
                    entry[key] = (
                        [v * factor for v in value] if isinstance(value, list) else (value * factor)
                    )
    return out


def load(name: str) -> dict[str, Any]:
    ref = resources.files("frictionlab") / "data" / "scenarios" / f"{name}.toml"
    return tomllib.loads(ref.read_text(encoding="utf-8"))


def run(data: dict[str, Any]) -> Any:
    return run_scenario(parse_scenario(data))


@pytest.mark.parametrize("name", bundled_scenarios())
def test_the_same_run_at_other_unit_scales_gives_the_same_friction(name: str) -> None:
    data = load(name)
    base = run(data)
    assert base.success
    for S, L, T in ((1e-6, 1e3, 1.0), (1e3, 1e-3, 10.0)):  # back to Pa/m/s toys; and kPa, mm, 10 s
        other = run(rescale(data, S, L, T))
        assert other.success
        np.testing.assert_allclose(other.friction_ratio, base.friction_ratio, rtol=1e-7,
                                   atol=1e-9, err_msg=f"{name} at S={S}, L={L}, T={T}")  # fmt: skip
        np.testing.assert_allclose(other.slip, base.slip * L, rtol=1e-7, atol=1e-12 * L)
        np.testing.assert_allclose(other.time, base.time * T, rtol=1e-9)


@pytest.mark.parametrize("name", bundled_scenarios())
def test_bundled_scenarios_are_at_physical_scales(name: str) -> None:
    data = load(name)
    fn = np.atleast_1d(data["initial"]["normal_traction"])
    assert np.all(fn >= 1e4) and np.all(fn <= 1e9), "normal traction: kPa to GPa"
    assert 1e9 <= data["law"]["alpha_t"] <= 1e15, "contact stiffness [Pa/m]"
    for seg in [*data.get("program", []), data.get("machine", {})]:
        if "velocity" in seg:
            assert np.all(np.abs(np.atleast_1d(seg["velocity"])) <= 1e-2), "m/s: at most 1 cm/s"
        if "distance" in seg:
            assert np.all(np.atleast_1d(seg["distance"]) <= 1e-1), "m: at most 10 cm of slip"
