"""One ``on_invalid`` vocabulary ("error" | "drop" | "mask") in Python and TOML.

Each spelling is checked for its meaning on a wedge whose steep flank (60 deg) violates
Eq 1 at beta = 0 for mu0 = 0.7 (cot 60 deg = 0.577) while beta = 90 deg stays valid;
the old spellings ("raise" in Python and [hierarchy], "mask" meaning drop in [sliding])
keep their meaning for one release and say so.
"""

from __future__ import annotations

import math
import warnings

import pytest

from frictionlab.errors import InputError, ParameterError, ValidityError
from frictionlab.roughness import generators as gen
from frictionlab.roughness.elastic import ElasticSettings
from frictionlab.roughness.hierarchy import wedge_hierarchy
from frictionlab.roughness.lattice import LatticeSettings, friction_polar
from frictionlab.schema.roughness import parse_roughness

STEEP = gen.wedge((60.0, 20.0), 1.0)
FAST = {"stations": 200, "time_samples": 10}


def polar(on_invalid: str):
    return friction_polar(STEEP, gen.flat(), 0.7, [0.0, 90.0], on_invalid=on_invalid, **FAST)


def test_error_drop_and_mask_mean_what_they_say() -> None:
    with pytest.raises(ValidityError, match=r"mu0 < 0\.57735"):
        polar("error")
    masked, dropped = polar("mask"), polar("drop")
    assert list(masked.valid) == [False, True] and math.isnan(float(masked.mu[0]))
    assert list(dropped.valid) == [True, True] and math.isfinite(float(dropped.mu[0]))
    assert 0.0 < dropped.invalid_fraction[0] < 0.5 and dropped.invalid_fraction[1] == 0.0
    # the valid direction is the same whatever the option
    assert float(masked.mu[1]) == float(dropped.mu[1])


@pytest.mark.parametrize("cls", [LatticeSettings, ElasticSettings])
def test_python_raise_is_a_deprecated_error(cls) -> None:
    kwargs = {"pressure": 1.0, "modulus": 1.0} if cls is ElasticSettings else {}
    with pytest.warns(DeprecationWarning, match='"raise" is deprecated: write "error"') as rec:
        old = cls(on_invalid="raise", **kwargs)
    assert rec[0].filename == __file__  # the warning points at the caller
    assert old == cls(on_invalid="error", **kwargs)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for value in ("error", "drop", "mask"):
            assert cls(on_invalid=value, **kwargs).on_invalid == value
    with pytest.raises(ParameterError, match=r"on_invalid = 'ignore'.*'error', 'drop', 'mask'"):
        cls(on_invalid="ignore", **kwargs)


def test_hierarchy_takes_error_or_mask() -> None:
    # phi = 60 deg flanks: mu0 = 0.3 passes level 1 but not level 2 at beta = 0
    args = (0.3, (60.0,) * 4, [0.0, 90.0], 3)
    with pytest.raises(ValidityError, match="hierarchy level"):
        wedge_hierarchy(*args, on_invalid="error")
    with pytest.warns(DeprecationWarning, match='"raise"') as rec, pytest.raises(ValidityError):
        wedge_hierarchy(*args, on_invalid="raise")
    assert rec[0].filename == __file__
    assert not wedge_hierarchy(*args, on_invalid="mask").valid[-1, 0]
    with pytest.raises(ParameterError, match=r"on_invalid = 'drop'.*'error', 'mask'"):
        wedge_hierarchy(*args, on_invalid="drop")


def scenario(sliding: str | None = None, hierarchy: str | None = None) -> dict:
    data = {
        "mu0": 0.3,
        "lower": {"kind": "wedge", "angles_deg": [30.0, 30.0], "wavelength": 1.0},
        "upper": {"kind": "flat"},
        "sliding": {"beta_deg": 0.0},
    }
    if sliding is not None:
        data["sliding"]["on_invalid"] = sliding
    if hierarchy is not None:
        data["hierarchy"] = {"levels": 2, "ratio": 10.0, "on_invalid": hierarchy}
    return data


@pytest.mark.parametrize(
    ("sliding", "meaning", "note"),
    [(None, "error", None), ("error", "error", None), ("drop", "drop", None),
     ("mask", "drop", '"mask" is deprecated: it drops')],
)  # fmt: skip
def test_toml_sliding_spellings(sliding, meaning, note) -> None:
    parsed = parse_roughness(scenario(sliding=sliding))
    assert parsed.settings.on_invalid == meaning
    notes = [w for w in parsed.warnings if "on_invalid" in w]
    assert len(notes) == (note is not None)
    if note is not None:
        assert "[sliding].on_invalid" in notes[0] and note in notes[0] and '"drop"' in notes[0]


@pytest.mark.parametrize(
    ("given", "meaning", "deprecated"),
    [("error", "error", False), ("mask", "mask", False), ("raise", "error", True)],
)
def test_toml_hierarchy_spellings(given, meaning, deprecated) -> None:
    parsed = parse_roughness(scenario(hierarchy=given))
    assert parsed.hierarchy is not None and parsed.hierarchy.on_invalid == meaning
    notes = [w for w in parsed.warnings if "on_invalid" in w]
    assert len(notes) == deprecated
    if deprecated:
        assert '[hierarchy].on_invalid = "raise" is deprecated: write "error"' in notes[0]


@pytest.mark.parametrize(
    ("data", "key"),
    [(scenario(sliding="raise"), "[sliding].on_invalid"),
     (scenario(hierarchy="drop"), "[hierarchy].on_invalid")],
)  # fmt: skip
def test_toml_refusals_name_the_key(data, key) -> None:
    with pytest.raises(InputError) as exc:
        parse_roughness(data)
    assert str(exc.value).startswith(key) and "allowed" in str(exc.value)
