"""Shared fixtures: summaries checked against the published JSON Schema; example scripts."""

from __future__ import annotations

import json
import runpy
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

SCHEMAS = Path(__file__).resolve().parents[1] / "docs" / "schemas"


def load_schema(name: str) -> dict[str, Any]:
    """docs/schemas/<name>.schema.json."""
    return json.loads((SCHEMAS / f"{name}.schema.json").read_text())


@pytest.fixture
def check_summary() -> Callable[[Path], dict[str, Any]]:
    """Read a summary file, validate it against summary.schema.json and return it.

    Also checks what a schema cannot: every listed file exists beside the summary.
    """
    jsonschema = pytest.importorskip("jsonschema")
    validator = jsonschema.Draft202012Validator(load_schema("summary"))

    def check(path: Path) -> dict[str, Any]:
        summary = json.loads(path.read_text())
        errors = sorted(validator.iter_errors(summary), key=lambda e: list(e.path))
        assert not errors, "; ".join(f"{list(e.path)}: {e.message}" for e in errors[:3])
        missing = [name for name in summary["files"] if not (path.parent / name).is_file()]
        assert not missing, f"listed in {path.name} but not written: {missing}"
        return summary

    return check


@dataclass(frozen=True)
class ScriptRun:
    """What running a script as ``__main__`` gave: exit code and captured output."""

    returncode: int
    stdout: str
    stderr: str


@pytest.fixture
def run_script(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> Callable[..., ScriptRun]:
    """Run ``python SCRIPT ARGS...`` in this process (``runpy`` as ``__main__``).

    The script sees the same ``sys.argv`` and ``__name__`` as from a shell; only the
    interpreter start and the package import are shared with the test session (a new
    process per example would repeat them; the CLI's own subprocess tests are in
    tests/cli/test_entry.py).
    """

    def run(script: Path, *args: str) -> ScriptRun:
        monkeypatch.setattr(sys, "argv", [str(script), *args])
        capsys.readouterr()
        code: int | str | None = 0
        try:
            runpy.run_path(str(script), run_name="__main__")
        except SystemExit as done:
            code = done.code
        out = capsys.readouterr()
        return ScriptRun(code if isinstance(code, int) else 1, out.out, out.err)

    return run
