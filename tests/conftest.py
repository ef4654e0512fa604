"""Shared fixtures: validation of written summaries against the published JSON Schema."""

from __future__ import annotations

import json
from collections.abc import Callable
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
