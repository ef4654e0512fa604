"""The lattice at a nominal pressure: [contact] pressure and stiffness_per_area.

Closed form (Winkler foundation of stiffness k per area under a sinusoid
``z = a cos(theta)`` pressed by a rigid flat): the springs with ``theta < theta0`` are
compressed by ``a (cos theta - cos theta0)``, so the contact fraction is ``theta0 / pi``
and the nominal pressure ``p = k a (sin theta0 - theta0 cos theta0) / pi``; full contact
when ``p / k >= a``, where the mean compression is ``p / k``.
"""

from __future__ import annotations

import math
import tomllib

import pytest

from frictionlab.errors import InputError
from frictionlab.roughness.lattice import friction_polar
from frictionlab.schema.roughness import parse_roughness

AMPLITUDE = 1e-6
KAPPA = 1e13  # Pa/m

BASE = f"""mu0 = 0.3
[lower]
kind = "sinusoid"
amplitude = {AMPLITUDE}
wavelengths = [1e-4]
[upper]
kind = "flat"
[sliding]
beta_deg = [0.0]
"""


def _contact_fraction(pressure: float, extra: str = "") -> float:
    text = BASE + extra + f"[contact]\npressure = {pressure!r}\nstiffness_per_area = {KAPPA}\n"
    scenario = parse_roughness(tomllib.loads(text))
    polar = friction_polar(scenario.lower, scenario.upper, scenario.mu0, scenario.beta_deg,
                           settings=scenario.settings)  # fmt: skip
    return float(polar.contact_fraction_mean[0])


@pytest.mark.parametrize("theta0", [math.pi / 6, math.pi / 3, 2 * math.pi / 3])
def test_partial_contact_matches_the_winkler_sinusoid(theta0: float) -> None:
    pressure = KAPPA * AMPLITUDE * (math.sin(theta0) - theta0 * math.cos(theta0)) / math.pi
    # 2000 stations per period: the fraction is resolved to one station (5e-4)
    assert _contact_fraction(pressure) == pytest.approx(theta0 / math.pi, abs=1.5e-3)


def test_the_mapping_does_not_depend_on_the_spring_stiffness() -> None:
    theta0 = math.pi / 3
    pressure = KAPPA * AMPLITUDE * (math.sin(theta0) - theta0 * math.cos(theta0)) / math.pi
    stiff = _contact_fraction(pressure, "[lattice]\nk_c = 7.5\n")
    assert stiff == pytest.approx(theta0 / math.pi, abs=1.5e-3)


def test_full_contact_limit() -> None:
    # p / k = 1.5 a > a: every spring compressed
    assert _contact_fraction(1.5 * KAPPA * AMPLITUDE) == 1.0
    assert _contact_fraction(0.9 * KAPPA * AMPLITUDE) < 1.0


def test_load_per_spring_is_pressure_times_k_c_over_stiffness() -> None:
    text = BASE + "[lattice]\nk_c = 2.0\n[contact]\npressure = 3e6\nstiffness_per_area = 1e12\n"
    assert parse_roughness(tomllib.loads(text)).settings.load == pytest.approx(6e-6)


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        ("[contact]\npressure = 1e6\n", ["stiffness_per_area", "missing"]),
        ("[contact]\nstiffness_per_area = 1e12\n", ["stiffness_per_area", "pressure"]),
        (
            "load = 1e-9\n[contact]\npressure = 1e6\nstiffness_per_area = 1e12\n",
            ["[sliding].load", "pressure"],
        ),
        (
            '[contact]\nmodel = "lattice"\npressure = [1e6, 1e6]\nstiffness_per_area = 1e12\n',
            ["pressure", "twice"],
        ),
        ('[contact]\nmodel = ["elastic", "elastic"]\n', ["model", "distinct"]),
        (
            "[contact]\npressure = [1e6, 2e6]\nstiffness_per_area = 1e12\n"
            "[multiscale]\ncutoffs = [1e-5]\n",
            ["[multiscale]", "list"],
        ),
    ],
)
def test_pressure_keys_are_checked(extra: str, words: list[str]) -> None:
    text = BASE.replace("beta_deg = [0.0]\n", "beta_deg = [0.0]\n" + extra.split("[contact]")[0])
    text += "[contact]" + extra.split("[contact]", 1)[1] if "[contact]" in extra else ""
    with pytest.raises(InputError) as info:
        parse_roughness(tomllib.loads(text))
    for word in words:
        assert word in str(info.value)
