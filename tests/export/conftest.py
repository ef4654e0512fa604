"""Fixtures of the export tests: the C core and the harnesses, built once per session.

Without a C compiler these tests skip, unless ``FRICTIONLAB_REQUIRE_CC=1`` (set by
.ci/run, which installs gcc and gfortran), where a missing compiler is a failure.
"""

from __future__ import annotations

import ctypes
import os
import shutil
from pathlib import Path

import pytest

from frictionlab.export import c_core


def require(tool: str | None, what: str) -> str:
    """``tool`` if found; otherwise skip (or fail when FRICTIONLAB_REQUIRE_CC=1)."""
    if tool:
        return tool
    message = f"{what} not found"
    if os.environ.get("FRICTIONLAB_REQUIRE_CC") == "1":
        pytest.fail(message + " (FRICTIONLAB_REQUIRE_CC=1)")
    pytest.skip(message)


@pytest.fixture(scope="session")
def core(tmp_path_factory: pytest.TempPathFactory) -> ctypes.CDLL:
    """The C core as a ctypes library (built with the system's compiler)."""
    require(c_core.compiler(), "a C compiler")
    return c_core.load_core(tmp_path_factory.mktemp("c-core"))


@pytest.fixture(scope="session")
def fortran() -> str:
    """The Fortran compiler used for the Fortran harness."""
    return require(shutil.which(os.environ.get("FC", "gfortran")), "gfortran")


@pytest.fixture(scope="session")
def build_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("export-build")
