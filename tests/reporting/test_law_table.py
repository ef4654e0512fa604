"""law_table writes a [law] table that the scenario parser reads back as the same law."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.io.config import format_toml, load_toml
from frictionlab.io.scenario import law_table, parse_law_table
from frictionlab.subloading import SubloadingParams

CASES = [
    SubloadingParams(mu_s=0.5, mu_k=0.3),
    SubloadingParams(
        mu_s=0.5, mu_k=0.3, u=250.0, kappa=2.0, xi=1e-4, rotation=(0.05, -0.02),
        orthotropy=(1.0, 0.6), orthotropy_angle=np.radians(30.0), U_law="ln",
        F_integrator="backward_euler", m=2.0, n=0.5,
    ),
    SubloadingParams(surface="tear", F_s=1e6, F_k=6e5, M=0.5, kappa=1e6, xi=1e2, tear_k=2.0),
    SubloadingParams(
        mu_s=[0.5, 0.6], mu_k=0.3, rotation=[[0.0, 0.1], [0.05, 0.0]],
        orthotropy=(1.0, 0.5), orthotropy_convention="multiply",
    ),
]  # fmt: skip


def _equal(a: SubloadingParams, b: SubloadingParams) -> None:
    for name in (*SubloadingParams._SCALAR_FIELDS, "rotation", "orthotropy"):
        va, vb = getattr(a, name), getattr(b, name)
        if va is None or vb is None:
            assert va is None and vb is None, name
            continue
        np.testing.assert_allclose(vb, va, rtol=1e-15, atol=1e-15, err_msg=name)
    for name in ("surface", "tear_k", "U_law", "F_integrator", "recovery_form", "open_recovery"):
        assert getattr(a, name) == getattr(b, name), name


@pytest.mark.parametrize("params", CASES)
def test_round_trip_through_toml_text(params: SubloadingParams, tmp_path) -> None:
    path = tmp_path / "law.toml"
    path.write_text(format_toml({"law": law_table(params)}))
    back, _ = parse_law_table(load_toml(path)["law"])
    _equal(params, back)


def test_format_toml_drops_none_and_keeps_floats_exact() -> None:
    text = format_toml({"a": {"x": 0.1 + 0.2, "y": None, "z": [1e-300, 3.0]}})
    assert "y" not in text
    import tomllib

    data = tomllib.loads(text)
    assert data["a"]["x"] == 0.1 + 0.2
    assert data["a"]["z"] == [1e-300, 3.0]


def test_parse_law_table_names_the_table_in_errors() -> None:
    from frictionlab.errors import InputError

    with pytest.raises(InputError, match=r"\[fit.law\]\.mu_k"):
        parse_law_table({"mu_s": 0.5}, where="[fit.law]")
