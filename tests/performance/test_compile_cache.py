"""numba's cache goes to a per-user directory keyed on the sources."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import frictionlab
from frictionlab import _compile_cache

PROBE = (
    "import frictionlab, numba.core.config as c; "
    "from frictionlab.subloading.surfaces import g_value; g_value(1, 1.0, 0.5); "
    "print(c.CACHE_DIR)"
)


def _run(env: dict[str, str]) -> str:
    full = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    full.update(env)
    done = subprocess.run(
        [sys.executable, "-c", PROBE], env=full, capture_output=True, text=True, check=True
    )
    return done.stdout.strip().splitlines()[-1]


def test_cache_is_written_under_the_user_cache_keyed_on_the_sources(tmp_path: Path) -> None:
    used = Path(_run({"XDG_CACHE_HOME": str(tmp_path), "FRICTIONLAB_CACHE_DIR": ""}))
    key = f"{frictionlab.__version__}-{_compile_cache.source_hash()}"
    assert used == tmp_path / "frictionlab" / "numba" / key
    assert list(used.rglob("*g_value*.nbi"))  # the compiled function was cached there


def test_unwritable_location_falls_back_and_user_setting_is_respected(tmp_path: Path) -> None:
    blocked = tmp_path / "file"
    blocked.write_text("not a directory")
    used = Path(_run({"FRICTIONLAB_CACHE_DIR": str(blocked)}))
    assert blocked not in used.parents and used.name.startswith(frictionlab.__version__)
    assert _run({"NUMBA_CACHE_DIR": str(tmp_path / "mine")}) == str(tmp_path / "mine")


def test_source_hash_changes_with_any_compiled_module(tmp_path: Path, monkeypatch) -> None:
    copy = tmp_path / "pkg"
    (copy / "sub").mkdir(parents=True)
    (copy / "a.py").write_text("x = 1\n")
    (copy / "sub" / "b.py").write_text("import numba\ny = 2\n")
    monkeypatch.setattr(_compile_cache, "_PACKAGE", copy)
    before = _compile_cache.source_hash()
    (copy / "a.py").write_text("x = 2\n")  # no kernel in it: the same cache
    assert _compile_cache.source_hash() == before
    (copy / "sub" / "b.py").write_text("import numba\ny = 3\n")
    assert _compile_cache.source_hash() != before
