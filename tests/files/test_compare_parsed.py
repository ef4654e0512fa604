"""benchmarks/compare_parsed.py tells parsed objects apart down to the last bit, and only then."""

from __future__ import annotations

import importlib.util
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest

_PATH = Path(__file__).resolve().parents[2] / "benchmarks" / "compare_parsed.py"


@pytest.fixture(scope="module")
def canon() -> Any:
    spec = importlib.util.spec_from_file_location("compare_parsed", _PATH)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.canon


@dataclass(frozen=True)
class _Parsed:
    mu: float
    betas: np.ndarray
    inputs: dict[str, Any]


def _parsed(mu: float = 0.3, last: float = 90.0, echo: Any = (1, 2)) -> _Parsed:
    return _Parsed(mu, np.array([0.0, 45.0, last]), {"every": 1, "points": echo})


def test_equal_objects_have_equal_forms(canon: Any) -> None:
    assert canon(_parsed()) == canon(_parsed())


@pytest.mark.parametrize(
    "other",
    [
        _parsed(mu=math.nextafter(0.3, 1.0)),  # the last bit of a float
        _parsed(last=math.nextafter(90.0, 91.0)),  # the last bit of an array entry
        _parsed(echo=[1, 2]),  # a list where a tuple was
    ],
)
def test_a_difference_is_seen(canon: Any, other: _Parsed) -> None:
    assert canon(other) != canon(_parsed())


def test_temporary_and_package_folders_are_ignored(canon: Any) -> None:
    a = canon({"file": "/tmp/pytest-of-u/pytest-3/t0/s.toml", "pkg": "/x/src/frictionlab/data"})
    b = canon({"file": "/tmp/pytest-of-u/pytest-9/t0/s.toml", "pkg": "/y/src/frictionlab/data"})
    assert a == b
