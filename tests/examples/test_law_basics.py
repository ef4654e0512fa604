"""examples/law_basics.py runs and its numbers agree with the closed form."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_law_basics_example() -> None:
    spec = importlib.util.spec_from_file_location("law_basics", EXAMPLES / "law_basics.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = module.main()
    # steady friction after 5 mm equals mu_ss(V), the peak lies below mu_s
    np.testing.assert_allclose(out["steady"], out["mu_ss"], rtol=1e-6)
    assert np.all(out["peak"] < out["mu_s"]) and np.all(np.diff(out["peak"]) > 0)
