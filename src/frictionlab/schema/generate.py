"""Write docs/schemas/<input>.schema.json and the docs' key tables from the declarations.

``python -m frictionlab.schema`` (``make schemas``) writes them; ``--check`` only says
which files differ (exit 1). A key table is the text between ``<!-- keys:INPUT.SECTION -->``
and ``<!-- /keys -->`` in a docs page (``<!-- keys:scenario.law -->``).
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any

from frictionlab.schema.bridge import BRIDGE_FILE
from frictionlab.schema.calibrate import CALIBRATE_FILE
from frictionlab.schema.contact import CONTACT_FILE
from frictionlab.schema.core import OMIT, REQUIRED, Field, Section
from frictionlab.schema.kinds import DEFS
from frictionlab.schema.roughness import ROUGHNESS_FILE
from frictionlab.schema.scenario import SCENARIO_FILE
from frictionlab.schema.sweep import SWEEP_FILE

__all__ = ["INPUTS", "json_schema", "key_table", "main", "render"]

#: input name -> (root declaration, title of its schema)
INPUTS: dict[str, tuple[Section, str]] = {
    "scenario": (SCENARIO_FILE, "frictionlab simulate scenario (TOML)"),
    "roughness": (ROUGHNESS_FILE, "frictionlab roughness scenario (TOML)"),
    "bridge": (BRIDGE_FILE, "frictionlab bridge scenario (TOML)"),
    "calibrate": (CALIBRATE_FILE, "frictionlab calibrate configuration (TOML)"),
    "contact": (CONTACT_FILE, "frictionlab contact scenario (TOML)"),
    "sweep": (SWEEP_FILE, "frictionlab sweep file (TOML)"),
}
_MARK = re.compile(r"(<!-- keys:([\w.]+) -->\n)(.*?)(<!-- /keys -->)", re.S)


def _sections(section: Section, out: list[Section] | None = None) -> list[Section]:
    """``section`` and those below it (depth first, each once)."""
    out = [] if out is None else out
    if section not in out:
        out.append(section)
        own = [
            f for keys in (section.variants or {}).values() for f in keys if isinstance(f, Field)
        ]
        for f in (*section.fields, *own):
            if f.table is not None:
                _sections(f.table, out)
    return out


def json_schema(name: str) -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of input ``name``."""
    root, title = INPUTS[name]
    body = root.schema()
    out: dict[str, Any] = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": f"https://frictionlab.invalid/schemas/{name}.schema.json",
        "title": title,
        **body,
    }
    defs = {s.name: s.schema() for s in _sections(root) if s.ref}
    while True:  # the shared value kinds that are used, and those they use
        text = json.dumps([out, defs])
        more = {k: v for k, v in DEFS.items() if f"#/$defs/{k}" in text and k not in defs}
        if not more:
            break
        defs.update(more)
    if defs:
        out["$defs"] = dict(sorted(defs.items()))
    return out


def _default(f: Field) -> str:
    if f.default is REQUIRED:
        return "required"
    value = f.shown_default()
    if value is None or (f.default is OMIT and f.by is None):
        return ""
    return f"`{json.dumps(value)}`"


def key_table(address: str) -> str:
    """The markdown table of the keys of ``address`` (``input.section[.section...]``)."""
    name, *path = address.split(".")
    section = INPUTS[name][0]
    for part in path:
        table = section[part].table
        if table is None:
            raise KeyError(f"{address}: {part} is not a table")
        section = table
    rows = ["| key | value | unit | default | allowed | meaning |", "|---|---|---|---|---|---|"]
    for f in section.fields:
        if f.table is not None:
            kind = "array of tables" if f.many else "table"
        else:
            kind = f.kind.name if f.kind is not None else "table"
        kinds = [k for k, keys in (section.variants or {}).items()
                 if f.name in [g if isinstance(g, str) else g.name for g in keys]]  # fmt: skip
        doc = f.doc + (f" (kind: {', '.join(kinds)})" if kinds and f.name != "kind" else "")
        doc = doc.replace("|", "\\|")
        allowed = f.allowed_text().replace("|", "\\|")
        rows.append(f"| `{f.name}` | {kind} | {f.unit} | {_default(f)} | {allowed} | {doc} |")
    return "\n".join(rows) + "\n"


_NESTED = re.compile(r'"(properties|allOf|then|\$defs)"')


def _dump(obj: Any, indent: int = 0) -> str:
    """JSON with one line per key's schema (a schema holding no sub-table) or per value
    that fits in 96 characters: one line changes with one key."""
    flat = json.dumps(obj)
    if len(flat) + indent <= 96 or not isinstance(obj, dict | list) or not obj:
        return flat
    if isinstance(obj, dict) and "description" in obj and not _NESTED.search(flat):
        return flat
    pad = " " * (indent + 2)
    if isinstance(obj, dict):
        items = [f"{pad}{json.dumps(k)}: {_dump(v, indent + 2)}" for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    return "[\n" + ",\n".join(pad + _dump(v, indent + 2) for v in obj) + "\n" + " " * indent + "]"


def render(root: Path) -> dict[Path, str]:
    """Every generated file under ``root`` (the repository) with its text."""
    out = {
        root / "docs" / "schemas" / f"{name}.schema.json": _dump(json_schema(name)) + "\n"
        for name in INPUTS
    }
    for page in sorted((root / "docs").glob("*.md")):
        text = page.read_text("utf-8")
        new = _MARK.sub(lambda m: m.group(1) + key_table(m.group(2)) + m.group(4), text)
        if new != text:
            out[page] = new
    return out


def main(argv: list[str] | None = None) -> int:
    """Write the generated files (``--check``: list those that differ, exit 1 if any)."""
    args = sys.argv[1:] if argv is None else argv
    root = Path(args[args.index("--root") + 1]) if "--root" in args else Path.cwd()
    stale = [
        p for p, text in render(root).items() if not p.exists() or p.read_text("utf-8") != text
    ]
    if "--check" in args:
        for p in stale:
            print(f"stale: {p} (run make schemas)")
        return 1 if stale else 0
    for p in stale:
        p.write_text(render(root)[p], "utf-8")
        print(f"wrote {p}")
    return 0
