"""``import frictionlab`` is fast and has no side effect; the top-level API loads lazily."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import frictionlab

HEAVY = ("numba", "matplotlib", "pandas", "scipy", "numpy", "skfem", "SurfaceTopography")

_PROBE = """
import json, sys, time
start = time.perf_counter()
import frictionlab
seconds = time.perf_counter() - start
heavy = sorted(m for m in {heavy} if m in sys.modules)
mine = sorted(m for m in sys.modules if m.startswith("frictionlab"))
print(json.dumps({{"seconds": seconds, "heavy": heavy, "mine": mine}}))
"""


def _probe(tmp_path: Path) -> dict:
    """Import frictionlab in a fresh interpreter whose cache folders point into tmp_path."""
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["FRICTIONLAB_CACHE_DIR"] = str(tmp_path / "cache")
    env["XDG_CACHE_HOME"] = str(tmp_path / "xdg")
    done = subprocess.run(
        [sys.executable, "-c", _PROBE.format(heavy=HEAVY)],
        capture_output=True, text=True, env=env, check=True, timeout=120,
    )  # fmt: skip
    return json.loads(done.stdout)


def test_import_frictionlab_loads_no_heavy_dependency_and_writes_nothing(tmp_path: Path) -> None:
    found = _probe(tmp_path)
    assert found["heavy"] == []
    assert set(found["mine"]) <= {"frictionlab", "frictionlab._version", "frictionlab.errors"}
    # the compile cache is set up at the first kernel use, not at import
    assert not (tmp_path / "cache").exists() and not (tmp_path / "xdg").exists()
    assert found["seconds"] < 0.5  # a few ms idle; generous for a loaded machine


def test_the_first_kernel_module_sets_up_the_cache(tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["FRICTIONLAB_CACHE_DIR"] = str(tmp_path / "cache")
    code = "import frictionlab._jit, numba.core.config as c; print(c.CACHE_DIR)"
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True,
        timeout=120,
    )  # fmt: skip
    assert Path(done.stdout.strip()).parent == tmp_path / "cache"


@pytest.mark.parametrize("name", frictionlab.__all__)
def test_every_top_level_name_resolves(name: str) -> None:
    assert getattr(frictionlab, name) is not None
    assert name in dir(frictionlab)


def test_a_top_level_name_is_the_object_of_its_home_module() -> None:
    from frictionlab.app.simulate import run_scenario
    from frictionlab.subloading import SubloadingParams, update

    assert frictionlab.SubloadingParams is SubloadingParams
    assert frictionlab.update is update
    assert frictionlab.run_scenario is run_scenario


def test_an_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="no attribute 'not_a_name'"):
        frictionlab.not_a_name  # noqa: B018


def test_all_lists_the_errors_and_every_lazy_name() -> None:
    eager = {"ConvergenceError", "FrictionlabError", "InputError", "ParameterError",
             "ValidityError", "__version__"}  # fmt: skip
    assert set(frictionlab.__all__) == eager | set(frictionlab._LAZY)


def test_the_interpreted_kernels_stay_plain_python() -> None:
    """Kernel modules import njit from frictionlab._jit; the interpreted reference must
    still replace it (else both sides of the kernel-agreement tests are compiled)."""
    import types

    from frictionlab.subloading import interpreted

    namespace = interpreted.load()
    assert isinstance(namespace["_point"], types.FunctionType)
    assert isinstance(namespace["step_points"], types.FunctionType)
