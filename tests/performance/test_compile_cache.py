"""numba's cache goes to a per-user directory keyed on the sources; stale copies go away."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import frictionlab
from frictionlab import _compile_cache

PROBE = (
    "import frictionlab, numba.core.config as c; "
    "from frictionlab.subloading.surfaces import g_value; g_value(1, 1.0, 0.5); "
    "print(c.CACHE_DIR)"
)


def _run(env: dict[str, str], probe: str = PROBE) -> str:
    full = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    full.update(env)
    done = subprocess.run(
        [sys.executable, "-c", probe], env=full, capture_output=True, text=True, check=True
    )
    return done.stdout.strip().splitlines()[-1]


def test_cache_is_written_under_the_user_cache_keyed_on_the_sources(tmp_path: Path) -> None:
    used = Path(_run({"XDG_CACHE_HOME": str(tmp_path), "FRICTIONLAB_CACHE_DIR": ""}))
    key = f"{frictionlab.__version__}-{_compile_cache.source_hash()}"
    assert used == tmp_path / "frictionlab" / "numba" / key
    assert list(used.rglob("*g_value*.nbi"))  # the compiled function was cached there


@pytest.mark.slow
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


KEY_A = "0.0.1-0123456789abcdef"
KEY_B = "0.0.2-fedcba9876543210"


def _stale(root: Path, name: str, files: tuple[str, ...] = ("home/x/mod.f-1.py311.nbi",)) -> Path:
    folder = root / name
    for relative in files:
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_bytes(b"")
    (folder / _compile_cache.LOCK_NAME).write_bytes(b"")
    return folder


def test_prune_removes_only_stale_unused_cache_folders(tmp_path: Path) -> None:
    current = _stale(tmp_path, "0.1.0-00000000000000aa")
    stale = _stale(tmp_path, KEY_A, ("a/b/k.nbi", "a/b/k.1.nbc"))
    foreign = _stale(tmp_path, KEY_B, ("notes.txt",))  # not only numba files: kept
    other = tmp_path / "my-folder"  # not our name pattern: kept
    other.mkdir()
    removed = _compile_cache.prune(tmp_path, keep=current.name, keep_recent=0)
    assert removed == [KEY_A]
    assert not stale.exists() and current.exists() and foreign.exists() and other.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([current.name, KEY_B, "my-folder"])


def test_prune_keeps_a_folder_in_use_and_never_raises(tmp_path: Path) -> None:
    stale = _stale(tmp_path, KEY_A)
    handle = _compile_cache.hold(stale)  # as a running process of that version does
    assert handle is not None
    try:
        assert _compile_cache.prune(tmp_path, keep="x", keep_recent=0) == []
        assert stale.exists()
    finally:
        handle.close()
    assert _compile_cache.prune(tmp_path, keep="x", keep_recent=0) == [KEY_A]
    assert _compile_cache.prune(tmp_path / "missing", keep="x") == []
    (tmp_path / "file").write_text("x")
    assert _compile_cache.prune(tmp_path / "file", keep="x") == []


def test_folder_without_lock_file_is_removed_only_when_old(tmp_path: Path) -> None:
    stale = _stale(tmp_path, KEY_A)
    (stale / _compile_cache.LOCK_NAME).unlink()  # made before lock files existed
    assert _compile_cache.prune(tmp_path, keep="x", keep_recent=0) == []  # may be in use
    old = os.stat(stale).st_mtime - 2 * _compile_cache.UNLOCKED_GRACE_S
    os.utime(stale, (old, old))
    assert _compile_cache.prune(tmp_path, keep="x", keep_recent=0) == [KEY_A]


def _used_at(folder: Path, seconds_ago: float) -> Path:
    """Give ``folder`` a last use ``seconds_ago`` (its lock file's time stamp)."""
    when = os.stat(folder).st_mtime - seconds_ago
    os.utime(folder / _compile_cache.LOCK_NAME, (when, when))
    return folder


def _keys(count: int) -> list[str]:
    return [f"0.0.{i}-{i:016x}" for i in range(count)]


def test_first_kernel_use_prunes_stale_siblings(tmp_path: Path) -> None:
    """The set-up runs when the first kernel module is imported (import frictionlab
    alone does not touch the cache: tests/performance/test_import.py): it keeps the
    most recently used siblings and removes the older ones."""
    root = tmp_path / "frictionlab" / "numba"
    keep = _compile_cache.KEEP_RECENT
    folders = [
        _used_at(_stale(root, key), 100.0 * (i + 1)) for i, key in enumerate(_keys(keep + 2))
    ]
    probe = "import frictionlab._jit, numba.core.config as c; print(c.CACHE_DIR)"
    used = Path(_run({"XDG_CACHE_HOME": str(tmp_path), "FRICTIONLAB_CACHE_DIR": ""}, probe))
    assert used.parent == root and used.exists()
    assert [f.exists() for f in folders] == [True] * keep + [False, False]
    assert (used / _compile_cache.LOCK_NAME).exists()


def test_prune_keeps_the_most_recently_used_siblings(tmp_path: Path) -> None:
    """Checkouts of different sources used in turn (parallel sessions, two installs) do not
    delete each other's compiled kernels: the newest KEEP_RECENT stale folders stay."""
    keys = _keys(6)
    ages = [50.0, 10.0, 60.0, 20.0, 40.0, 30.0]  # seconds since each folder's last use
    for key, age in zip(keys, ages, strict=True):
        _used_at(_stale(root := tmp_path, key), age)
    removed = _compile_cache.prune(root, keep="current", keep_recent=3)
    newest = sorted(keys, key=lambda k: ages[keys.index(k)])[:3]
    assert removed == sorted(set(keys) - set(newest))
    assert sorted(p.name for p in root.iterdir()) == sorted(newest)
    # using an old folder again (a process holds it) makes it recent: it survives the next prune
    oldest = newest[-1]
    _used_at(tmp_path / oldest, 1000.0)
    handle = _compile_cache.hold(tmp_path / oldest)
    assert handle is not None
    handle.close()
    assert _compile_cache.prune(root, keep="current", keep_recent=1) == sorted(
        set(newest) - {oldest}
    )


def test_the_held_lock_file_is_closed_at_exit(tmp_path: Path) -> None:
    """With every warning shown (-X dev), the lock file of the cache leaves no ResourceWarning."""
    full = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    full["FRICTIONLAB_CACHE_DIR"] = str(tmp_path)
    probe = "from frictionlab import _compile_cache as c; print(c.configure())"
    done = subprocess.run(
        [sys.executable, "-X", "dev", "-c", probe], env=full, capture_output=True, text=True,
        check=True,
    )  # fmt: skip
    assert Path(done.stdout.strip()).parent == tmp_path
    assert "ResourceWarning" not in done.stderr, done.stderr
