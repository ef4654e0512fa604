"""docs/schemas/*.json and the docs' key tables are what `make schemas` writes."""

from __future__ import annotations

import json
from pathlib import Path

from frictionlab.schema.generate import INPUTS, json_schema, key_table, render

ROOT = Path(__file__).resolve().parents[2]


def test_committed_files_are_the_generated_ones() -> None:
    stale = [p.relative_to(ROOT).as_posix() for p, text in render(ROOT).items()
             if not p.exists() or p.read_text("utf-8") != text]  # fmt: skip
    assert not stale, f"run `make schemas`: {stale}"


def test_a_changed_declaration_makes_the_files_stale(tmp_path: Path) -> None:
    (tmp_path / "docs" / "schemas").mkdir(parents=True)
    page = tmp_path / "docs" / "page.md"
    page.write_text("before\n<!-- keys:scenario.run -->\nold text\n<!-- /keys -->\nafter\n")
    files = render(tmp_path)
    assert set(files) == {tmp_path / "docs" / "schemas" / f"{n}.schema.json" for n in INPUTS} | {
        page
    }
    text = files[page]
    assert text.startswith("before\n<!-- keys:scenario.run -->\n| key |")
    assert "old text" not in text and text.endswith("<!-- /keys -->\nafter\n")
    for key in ("n_points", "accuracy", "max_halvings", "allow_large"):
        assert f"| `{key}` |" in key_table("scenario.run")


def test_the_schema_lists_the_declared_keys_with_their_ranges() -> None:
    run = json_schema("scenario")["properties"]["run"]["properties"]
    assert run["n_points"]["minimum"] == 1 and run["accuracy"]["exclusiveMinimum"] == 0
    assert json.loads(json.dumps(json_schema("sweep")))["required"] == ["base"]


def test_set_overrides_go_through_the_declarations() -> None:
    import pytest

    from frictionlab.errors import InputError
    from frictionlab.schema.calibrate import CALIBRATE
    from frictionlab.schema.core import check_overrides
    from frictionlab.schema.scenario import SCENARIO

    check_overrides(SCENARIO, ["law.mu_s=0.6", "program.2.steps=50", "machine.mass=1"])
    check_overrides(CALIBRATE, ["fit.bounds.mu_s=[0.1, 1.0]", "data.1.initial.F=0.5"])
    with pytest.raises(InputError, match=r"--set law.muk=1: unknown key \[law\].muk \(did you "
                       r"mean 'mu_k'\?\)"):  # fmt: skip
        check_overrides(SCENARIO, ["law.muk=1"])
    with pytest.raises(InputError, match=r"unknown key \[\[program\]\] #2.velocty"):
        check_overrides(SCENARIO, ["program.2.velocty=1"])
