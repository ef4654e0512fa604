"""JSON Schemas of the roughness, bridge, calibrate, contact and sweep input files.

Each schema (docs/schemas/<kind>.schema.json) must accept every bundled file of its kind
and the ``frictionlab example`` starters, reject a misspelt key, and list exactly the keys
the parser reads: the expected keys come from the parser's own unknown-key message
("allowed keys here: ..."), provoked by adding a key ``zzz`` to each table in turn.
"""

from __future__ import annotations

import copy
import json
import re
import tomllib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from frictionlab.commands.example import EXAMPLES, starter_text
from frictionlab.errors import InputError
from frictionlab.io.bridge_scenario import _NOT_USED, parse_bridge_scenario
from frictionlab.io.calibration_config import parse_calibration
from frictionlab.io.contact_scenario import _SEGMENTS, parse_contact_scenario
from frictionlab.io.roughness_scenario import parse_roughness_scenario
from frictionlab.sweep.spec import parse_sweep

jsonschema = pytest.importorskip("jsonschema")
ROOT = Path(__file__).resolve().parents[2]
SCHEMAS = ROOT / "docs" / "schemas"
DATA = ROOT / "src" / "frictionlab" / "data"
KINDS = ("roughness", "bridge", "calibrate", "contact", "sweep")


def schema(name: str) -> dict[str, Any]:
    return json.loads((SCHEMAS / f"{name}.schema.json").read_text())


def load(path: Path) -> dict[str, Any]:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def bundled() -> list[tuple[str, str, Path]]:
    """(schema, label, file) for every bundled input file and starter of the five kinds."""
    files = [("bridge", p) for p in sorted((DATA / "bridge").glob("*.toml"))]
    files += [("contact", p) for p in sorted((DATA / "contact").glob("*.toml"))]
    files += [("calibrate", p) for p in sorted((ROOT / "examples").rglob("*.toml"))]
    for p in sorted((DATA / "sweeps").glob("*.toml")):
        files.append(("sweep" if "base" in load(p) else "scenario", p))
    for name in EXAMPLES:
        path = DATA / "examples" / f"{name}.toml"
        data = load(path)
        kind = "calibrate" if "fit" in data else "roughness" if "mu0" in data else "scenario"
        files.append((kind, path))
    return [(kind, p.relative_to(ROOT).as_posix(), p) for kind, p in files]


@pytest.mark.parametrize("name", KINDS)
def test_schemas_are_valid_draft_2020_12(name: str) -> None:
    jsonschema.Draft202012Validator.check_schema(schema(name))


@pytest.mark.parametrize(("kind", "label", "path"), bundled(), ids=lambda v: str(v)[-40:])
def test_every_bundled_file_matches_its_schema(kind: str, label: str, path: Path) -> None:
    jsonschema.validate(load(path), schema(kind))


def test_every_kind_has_a_bundled_file_and_the_starters_are_the_bundled_files() -> None:
    kinds = {kind for kind, _, _ in bundled()}
    assert set(KINDS) <= kinds
    for name in EXAMPLES:  # what `frictionlab example NAME` prints is the file checked above
        assert starter_text(name) == (DATA / "examples" / f"{name}.toml").read_text("utf-8")


@pytest.mark.parametrize(("kind", "label", "path"), bundled(), ids=lambda v: str(v)[-40:])
def test_a_misspelt_key_is_refused(kind: str, label: str, path: Path) -> None:
    data = load(path)
    data["titel"] = "x"
    with pytest.raises(jsonschema.ValidationError, match="titel"):
        jsonschema.validate(data, schema(kind))


# --------------------------------------------------------------------------- parser keys
Parse = Callable[[dict[str, Any]], object]


def parser_keys(parse: Parse, data: dict[str, Any], path: tuple[Any, ...]) -> set[str]:
    """The keys the parser allows in the table at ``path``, read from its unknown-key message."""
    doc = copy.deepcopy(data)
    table = doc
    for step in path:
        table = table[step]
    table["zzz"] = 1
    with pytest.raises(InputError) as info:
        parse(doc)
    found = re.search(r"allowed(?: keys here)?: (.*)$", str(info.value))
    assert found, str(info.value)
    return set(found.group(1).split(", "))


def schema_keys(s: dict[str, Any], path: tuple[Any, ...]) -> set[str]:
    node = s
    for step in path:
        node = node["items"] if isinstance(step, int) else node["properties"][step]
        if "$ref" in node:
            node = s["$defs"][node["$ref"].rsplit("/", 1)[1]]
    return set(node["properties"])


def roughness_base() -> dict[str, Any]:
    data = load(DATA / "examples" / "roughness.toml")
    data["adhesion"] = {"loads": [0.5, 1.0]}
    data["wear"] = dict.fromkeys(
        ("wear_coefficient", "hardness", "normal_load", "velocity", "nominal_area"), 1.0
    )
    data["hierarchy"] = {"levels": 1, "ratio": 10.0}
    data["multiscale"] = {"cutoffs": [1e-5]}
    return data


@pytest.mark.parametrize(
    "path",
    [(), ("sliding",), ("lattice",), ("output",), ("adhesion",), ("wear",), ("hierarchy",),
     ("multiscale",), ("lower",), ("upper",)],
)  # fmt: skip
def test_roughness_schema_keys_are_the_parser_keys(path: tuple[str, ...]) -> None:
    def parse(d: dict[str, Any]) -> object:
        return parse_roughness_scenario(d, DATA / "examples")

    s = schema("roughness")
    expected = parser_keys(parse, roughness_base(), path)
    if path in (("lower",), ("upper",)):  # per kind: the if/then rules of the surface
        kind = roughness_base()[path[0]]["kind"]
        rules = {r["if"]["properties"]["kind"]["const"]: r for r in s["$defs"]["surface"]["allOf"]}
        assert expected == set(rules[kind]["then"]["propertyNames"]["enum"])
    else:
        assert expected == schema_keys(s, path)


SURFACES = {
    "flat": {"kind": "flat"},
    "wedge": {"kind": "wedge", "angles_deg": [20.0], "wavelength": 1e-4},
    "smooth_wedge": {"kind": "smooth_wedge", "angles_deg": [20.0, 10.0], "wavelength": 1e-4},
    "sinusoid": {"kind": "sinusoid", "amplitude": 1e-6, "wavelengths": [1e-4]},
    "self_affine": {"kind": "self_affine", "hurst": 0.8, "physical_sizes": [1e-4],
                    "points": [64], "seed": 1, "rms_height": 1e-6},
    "file": load(DATA / "examples" / "measured-file.toml")["lower"],
}  # fmt: skip


@pytest.mark.parametrize("kind", list(SURFACES))
def test_every_surface_kind_lists_the_parser_keys(kind: str) -> None:
    data = load(DATA / "examples" / "measured-file.toml")
    data["lower"] = SURFACES[kind]
    data["upper"] = {"kind": "flat"} if kind != "flat" else SURFACES["sinusoid"]

    def parse(d: dict[str, Any]) -> object:
        return parse_roughness_scenario(d, DATA / "topography")  # where the file starter's map is

    rules = {
        r["if"]["properties"]["kind"]["const"]: set(r["then"]["propertyNames"]["enum"])
        for r in schema("roughness")["$defs"]["surface"]["allOf"]
    }
    assert set(rules) == set(SURFACES)
    assert parser_keys(parse, data, ("lower",)) == rules[kind]


def test_bridge_schema_keys_are_the_parser_keys() -> None:
    data = load(DATA / "bridge" / "ratchet.toml")

    def parse(d: dict[str, Any]) -> object:
        return parse_bridge_scenario(d, DATA / "bridge")

    s = schema("bridge")
    # the roughness parser reads the top level (without [law] and [bridge])
    top = parser_keys(parse, data, ()) - set(_NOT_USED) | {"law", "bridge"}
    assert top == schema_keys(s, ())
    assert parser_keys(parse, data, ("bridge",)) == schema_keys(s, ("bridge",))
    assert parser_keys(parse, data, ("law",)) == schema_keys(s, ("law",))
    assert parser_keys(parse, data, ("sliding",)) == schema_keys(s, ("sliding",))


def test_calibrate_schema_keys_are_the_parser_keys() -> None:
    data = load(DATA / "examples" / "calibrate.toml")
    folder = DATA / "examples" / "calibration"  # where its data file ships

    def parse(d: dict[str, Any]) -> object:
        return parse_calibration(d, folder)

    s = schema("calibrate")
    for path in [(), ("fit",), ("law",), ("data", 0), ("data", 0, "columns"),
                 ("data", 0, "units"), ("data", 0, "initial")]:  # fmt: skip
        assert parser_keys(parse, data, path) == schema_keys(s, path), path


def test_contact_schema_keys_are_the_parser_keys() -> None:
    data = load(DATA / "contact" / "pmma_block.toml")
    s = schema("contact")
    for path in [(), ("block",), ("law",), ("normal",), ("solver",), ("output",)]:
        doc = copy.deepcopy(data)
        doc.setdefault("solver", {})
        doc.setdefault("output", {})
        assert parser_keys(parse_contact_scenario, doc, path) == schema_keys(s, path), path
    rules = s["$defs"]["contact_segment"]["allOf"]
    assert {r["if"]["properties"]["kind"]["const"] for r in rules} == set(_SEGMENTS)
    for rule in rules:
        kind = rule["if"]["properties"]["kind"]["const"]
        doc = copy.deepcopy(data)
        doc["program"] = [{"kind": kind, "velocity": 1e-5, "distance": 1e-5, "duration": 1.0,
                           "target": 0.1}]  # fmt: skip
        keys = parser_keys(parse_contact_scenario, doc, ("program", 0))
        assert keys == set(rule["then"]["propertyNames"]["enum"]), kind


def test_sweep_schema_keys_are_the_parser_keys() -> None:
    data = load(DATA / "sweeps" / "slide_hold_slide.toml")

    def parse(d: dict[str, Any]) -> object:
        return parse_sweep(d, DATA / "sweeps")

    assert parser_keys(parse, data, ()) == schema_keys(schema("sweep"), ())
