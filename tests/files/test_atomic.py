"""Atomic writers: complete or absent, never partial; the usual file mode."""

from __future__ import annotations

import math
import os
import stat
from pathlib import Path

import pytest

from frictionlab.io.atomic import atomic_path, write_json_atomic, write_text_atomic


def test_written_file_has_the_umask_mode(tmp_path: Path) -> None:
    path = write_text_atomic(tmp_path / "a.txt", "hello")
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask
    assert path.read_text() == "hello"


def test_failure_keeps_the_previous_version_and_leaves_no_temporary(tmp_path: Path) -> None:
    target = tmp_path / "out.csv"
    write_text_atomic(target, "old\n")
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text("partial")
        raise RuntimeError("interrupted")
    assert target.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]


def test_json_refuses_nan(tmp_path: Path) -> None:
    with pytest.raises(ValueError):
        write_json_atomic(tmp_path / "s.json", {"x": math.nan})
    assert not (tmp_path / "s.json").exists()
