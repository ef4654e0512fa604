"""One vocabulary for the traction segment of the driver and of the contact model."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import frictionlab
import frictionlab.driver as driver
import frictionlab.driver.program as program
from frictionlab.contact.loading import NormalLoad, plan_stages
from frictionlab.contact.loading import Traction as ContactTraction
from frictionlab.driver import Traction, plan_program
from frictionlab.errors import ParameterError
from frictionlab.schema.contact import SEGMENT as CONTACT_SEGMENT
from frictionlab.schema.scenario import SEGMENT as SCENARIO_SEGMENT


@pytest.mark.parametrize("where", [program, driver, frictionlab])
def test_the_former_name_warns_and_is_the_same_class(where: object) -> None:
    with pytest.warns(DeprecationWarning, match="TractionControl is deprecated.*Traction"):
        old = where.TractionControl  # type: ignore[attr-defined]
    assert old is Traction


def test_the_new_name_does_not_warn() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        assert frictionlab.Traction is driver.Traction is program.Traction


def test_both_toml_files_name_the_kind_traction() -> None:
    assert "traction" in SCENARIO_SEGMENT.variants
    assert "traction" in CONTACT_SEGMENT.variants


def _legs(seg: Traction) -> list[np.ndarray]:
    """The traction at the end of each leg of a one-point plan (start traction 0)."""
    [plan] = plan_program((seg,), 1)
    steps = plan.begin(np.array([[0.0, 0.0, 1.0]]))
    ends = [plan.control(k).ft_target[0] for k in range(steps)]  # type: ignore[index]
    return ends[seg.steps - 1 :: seg.steps]  # type: ignore[misc]


def test_zero_cycles_and_the_former_none_are_one_ramp() -> None:
    for cycles in (0, None):
        seg = Traction(traction=(0.3, 0.0), cycles=cycles, steps=2)  # type: ignore[arg-type]
        assert seg.cycles == 0
        legs = _legs(seg)
        assert len(legs) == 1
        np.testing.assert_array_equal(legs[0], [0.3, 0.0])
    assert Traction(traction=(0.3, 0.0)).cycles == 0


def test_cycles_count_full_cycles_in_both_models() -> None:
    # driver: n cycles start -> target -> start; contact: a ramp, then n cycles +-target
    n = 3
    legs = _legs(Traction(traction=(0.3, 0.0), cycles=n, steps=2))
    assert len(legs) == 2 * n
    np.testing.assert_array_equal(legs[-1], [0.0, 0.0])
    _, stages = plan_stages(
        NormalLoad(pressure=1.0), (ContactTraction(target=0.3, duration=1.0, cycles=n),)
    )
    ends = [s.end[0] for s in stages[1:]]
    assert len(ends) == 1 + 2 * n
    assert ends[-1] == 0.3 and ends[1] == -0.3


@pytest.mark.parametrize("bad", [-1, 1.5, True, "2", 10_001])
def test_cycles_have_one_rule_in_both_models(bad: object) -> None:
    for make in (
        lambda: Traction(traction=(0.3, 0.0), cycles=bad),  # type: ignore[arg-type]
        lambda: ContactTraction(target=0.3, duration=1.0, cycles=bad),  # type: ignore[arg-type]
    ):
        with pytest.raises(ParameterError, match=r"cycles.*0 <= cycles <= 1e4"):
            make()


def test_numpy_integers_are_cycles_in_both_models() -> None:
    assert Traction(traction=(0.3, 0.0), cycles=np.int64(2)).cycles == 2  # type: ignore[arg-type]
    assert ContactTraction(target=0.3, duration=1.0, cycles=np.int64(2)).cycles == 2  # type: ignore[arg-type]
