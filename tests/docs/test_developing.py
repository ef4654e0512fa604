"""The development habits the README promises: two Quick start commands, `make test` runs
everything, `make test-fast` skips the tests marked slow."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _section(text: str, title: str) -> str:
    match = re.search(rf"^## {re.escape(title)}\n(.*?)(?=^## |\Z)", text, re.M | re.S)
    assert match, f"README has no section {title!r}"
    return match.group(1)


def _recipe(makefile: str, target: str) -> str:
    match = re.search(rf"^{target}:[^\n]*\n((?:\t[^\n]*\n)*)", makefile, re.M)
    assert match, f"Makefile has no target {target!r}"
    return match.group(0)


def test_quick_start_keeps_exactly_two_commands() -> None:
    quick = _section((ROOT / "README.md").read_text(encoding="utf-8"), "Quick start")
    block = re.search(r"```\n(.*?)```", quick, re.S)
    assert block
    commands = [line.split("#")[0].strip() for line in block.group(1).splitlines()]
    assert [c for c in commands if c] == ["make demo", "make test"]


def test_make_test_runs_everything_and_test_fast_skips_slow() -> None:
    makefile = (ROOT / "Makefile").read_text(encoding="utf-8")
    assert re.search(r"^test: .*\bpytest\b", makefile, re.M)
    assert "slow" not in _recipe(makefile, "pytest")  # no marker expression: every test
    assert '-m "not slow"' in _recipe(makefile, "test-fast")
    assert "make test-fast" in _section((ROOT / "README.md").read_text("utf-8"), "Developing")
