"""The docs gallery: one page per example script, and every such script is run by a test."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def load_hook():  # type: ignore[no-untyped-def]
    pytest.importorskip("mkdocs")
    spec = importlib.util.spec_from_file_location("gallery", ROOT / "docs" / "hooks" / "gallery.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_gallery_script_is_run_by_a_test() -> None:
    hook = load_hook()
    scripts = hook.scripts()
    assert {p.name for p in scripts} >= {"law_basics.py", "slide_hold_slide.py", "stick_slip.py"}
    tests = "\n".join(
        p.read_text(encoding="utf-8")
        for p in (ROOT / "tests").rglob("test_*.py")
        if p.name != Path(__file__).name
    )
    for script in scripts:
        assert f'"{script.name}"' in tests, f"no test runs {script.relative_to(ROOT)}"


def test_a_gallery_page_shows_the_whole_script() -> None:
    hook = load_hook()
    script = ROOT / "examples" / "law_basics.py"
    title, text = hook.page(script)
    assert title.startswith("Calling the subloading-friction law")
    assert script.read_text(encoding="utf-8").rstrip() in text
