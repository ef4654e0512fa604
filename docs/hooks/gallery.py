"""mkdocs hook: one gallery page per example script (examples/*.py), built from its source.

Each page shows the script's docstring as text and its full code; the tests run every
script (tests/examples, tests/roughness/cli/test_examples.py, checked by
tests/examples/test_gallery.py), so the gallery shows only code that runs.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Any

from mkdocs.structure.files import File, Files

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def scripts() -> list[Path]:
    """The gallery's scripts: every examples/*.py and examples/*/*.py."""
    return sorted(EXAMPLES.glob("*.py")) + sorted(EXAMPLES.glob("*/*.py"))


def page(script: Path) -> tuple[str, str]:
    """(title, markdown) of the gallery page of ``script``."""
    source = script.read_text(encoding="utf-8")
    doc = ast.get_docstring(ast.parse(source)) or script.stem
    title, _, rest = doc.partition("\n")
    rel = script.relative_to(ROOT).as_posix()
    body = rest.strip().replace("Usage::", "Usage:").replace("Run: ", "Run it: ")
    text = (
        f"# {title.strip().rstrip('.')}\n\n`{rel}`\n\n{body}\n\n"
        f"```python\n{source.rstrip()}\n```\n"
    )
    return title.strip().rstrip("."), text


def on_files(files: Files, config: Any) -> Files:
    """Add gallery/index.md and gallery/<name>.md (generated, never written to docs/)."""
    lines = [
        "# Gallery",
        "",
        "Every page is a script from `examples/`, shown whole; the test suite runs each one",
        "and checks its numbers, so what you see runs as shown.",
        "",
    ]
    for script in scripts():
        name = "_".join(script.relative_to(EXAMPLES).with_suffix("").parts)
        title, text = page(script)
        files.append(File.generated(config, f"gallery/{name}.md", content=text))
        lines.append(f"* [{title}]({name}.md): `{script.relative_to(ROOT).as_posix()}`")
    files.append(File.generated(config, "gallery/index.md", content="\n".join(lines) + "\n"))
    return files
