"""The published JSON Schemas (docs/schemas/) against real outputs and scenario files."""

from __future__ import annotations

import hashlib
import json
import re
import tomllib
from importlib import resources
from pathlib import Path

import pytest

from frictionlab.cli import main
from frictionlab.commands.example import starter_text
from frictionlab.errors import InputError
from frictionlab.io.scenario import parse_scenario

jsonschema = pytest.importorskip("jsonschema")
SCHEMAS = Path(__file__).resolve().parents[2] / "docs" / "schemas"
DATA = resources.files("frictionlab") / "data"


def schema(name: str) -> dict:  # type: ignore[type-arg]
    return json.loads((SCHEMAS / f"{name}.schema.json").read_text())


def test_schemas_are_valid_draft_2020_12() -> None:
    for name in ("summary", "scenario"):
        jsonschema.Draft202012Validator.check_schema(schema(name))


def test_simulate_summary_has_the_provenance_block(tmp_path: Path, check_summary) -> None:
    scenario = tmp_path / "s.toml"
    scenario.write_text(starter_text("slide-hold-slide"))
    out = tmp_path / "out"
    assert main(["simulate", str(scenario), "--out", str(out), "--quiet", "--no-plots"]) == 0
    summary = check_summary(out / "summary.json")
    prov = summary["provenance"]
    assert prov["command"] == ["frictionlab", "simulate", str(scenario), "--out", str(out),
                               "--quiet", "--no-plots"]  # fmt: skip
    digest = hashlib.sha256(scenario.read_bytes()).hexdigest()
    assert prov["inputs"] == [{"path": str(scenario), "sha256": digest}]
    assert {"numpy", "scipy", "pandas"} <= set(prov["dependencies"])
    # the common keys, and the older names kept for one release
    files = ["history.csv", "points.csv", "peaks.csv", "healing.csv", "summary.json"]
    assert summary["files"] == summary["outputs"] == files
    assert summary["frictionlab_version"] == summary["frictionlab"]


def scenario_files() -> list[tuple[str, str]]:
    bundled = [(p.name, p.read_text()) for p in (DATA / "scenarios").iterdir()]
    starters = [(f"example {n}", starter_text(n)) for n in ("simulate", "slide-hold-slide")]
    return sorted(bundled) + starters


@pytest.mark.parametrize(("name", "text"), scenario_files(), ids=lambda v: str(v)[:24])
def test_every_bundled_scenario_matches_the_scenario_schema(name: str, text: str) -> None:
    jsonschema.validate(tomllib.loads(text), schema("scenario"))


def test_the_schema_fails_a_misspelt_key() -> None:
    data = tomllib.loads(starter_text("simulate"))
    data["law"]["muk"] = data["law"].pop("mu_k")
    with pytest.raises(jsonschema.ValidationError, match="muk"):
        jsonschema.validate(data, schema("scenario"))


def allowed_by_the_parser(mutate) -> set[str]:  # type: ignore[no-untyped-def]
    """The keys the parser allows, read from its unknown-key message."""
    data = tomllib.loads(starter_text("simulate"))
    mutate(data)
    with pytest.raises(InputError) as info:
        parse_scenario(data)
    return set(re.search(r"allowed keys here: (.*)$", str(info.value)).group(1).split(", "))


def test_schema_keys_are_the_parser_keys() -> None:
    s = schema("scenario")
    assert allowed_by_the_parser(lambda d: d.update(zzz=1)) == set(s["properties"])
    for table in ("law", "initial", "run", "output"):
        keys = allowed_by_the_parser(lambda d, t=table: d.setdefault(t, {}).update(zzz=1))
        assert keys == set(s["properties"][table]["properties"]), table
    for rule in s["$defs"]["segment"]["allOf"]:
        kind = rule["if"]["properties"]["kind"]["const"]
        keys = allowed_by_the_parser(lambda d, k=kind: d["program"][0].update(kind=k, zzz=1))
        assert keys == set(rule["then"]["propertyNames"]["enum"]), kind


def test_the_readme_scenario_matches_the_schema_and_runs(tmp_path: Path) -> None:
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text(encoding="utf-8")
    text = re.search(r"```toml\n(.*?)```", readme, re.S).group(1)  # type: ignore[union-attr]
    jsonschema.validate(tomllib.loads(text), schema("scenario"))
    (tmp_path / "s.toml").write_text(text)
    args = ["simulate", str(tmp_path / "s.toml"), "--out", str(tmp_path / "o"), "--quiet"]
    assert main([*args, "--no-plots"]) == 0
