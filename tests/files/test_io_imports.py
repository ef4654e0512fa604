"""io/ holds file formats only: it imports nothing outward (physics, workflows, plotting, demo).

Every import statement of every module under ``frictionlab/io`` is parsed (including the
ones inside functions); a ``frictionlab`` import must name ``frictionlab.io`` or one of
the leaf helpers in :data:`ALLOWED`.
"""

from __future__ import annotations

import ast
from pathlib import Path

import frictionlab.io

#: Leaf helpers io/ may use: errors, the version, frame helpers, and the cache folder's
#: location (pint's parsed unit definitions are cached beside the compiled kernels).
ALLOWED = (
    "frictionlab.io",
    "frictionlab.errors",
    "frictionlab._version",
    "frictionlab._frames",
    "frictionlab._compile_cache",
)

#: The old names of the input parsers, kept for one release as re-exports of
#: frictionlab.schema (the parsers themselves live there). Remove them with the shims.
PARSERS_MOVING = frozenset(
    {"scenario", "roughness_scenario", "bridge_scenario", "contact_scenario", "calibration_config"}
)

IO_DIR = Path(frictionlab.io.__file__).parent


def _imports(path: Path) -> list[tuple[int, str]]:
    """(line, module) of every absolute import in ``path``; relative ones resolved."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.extend((node.lineno, alias.name) for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:  # from . import x: inside frictionlab.io (or above it)
                base = "frictionlab.io" if node.level == 1 else "frictionlab"
                module = f"{base}.{node.module}" if node.module else base
            else:
                module = node.module or ""
            found.extend((node.lineno, f"{module}.{alias.name}") for alias in node.names)
    return sorted(found)


def _outward(path: Path) -> list[str]:
    bad = []
    for line, module in _imports(path):
        if not (module == "frictionlab" or module.startswith("frictionlab.")):
            continue  # the standard library and third-party packages
        if not any(module == a or module.startswith(a + ".") for a in ALLOWED):
            bad.append(f"{path.name}:{line} imports {module}")
    return bad


def test_io_imports_nothing_outward() -> None:
    modules = sorted(p for p in IO_DIR.glob("*.py") if p.stem not in PARSERS_MOVING)
    assert len(modules) >= 8, f"io/ modules not found under {IO_DIR}"
    bad = [line for path in modules for line in _outward(path)]
    assert not bad, "io/ must hold formats only:\n" + "\n".join(bad)


def test_the_parser_exemptions_are_still_needed() -> None:
    """An exempted parser that left io/ (or no longer imports outward) is removed above."""
    stale = [
        name
        for name in sorted(PARSERS_MOVING)
        if not (IO_DIR / f"{name}.py").exists() or not _outward(IO_DIR / f"{name}.py")
    ]
    assert not stale, f"remove from PARSERS_MOVING: {stale}"


def test_the_check_sees_an_outward_import(tmp_path: Path) -> None:
    """The parser finds outward imports at module level, inside functions and relative."""
    module = tmp_path / "m.py"
    module.write_text(
        "import numpy\nfrom frictionlab.io.atomic import write_text_atomic\n"
        "from frictionlab.errors import InputError\n"
        "def f():\n    from frictionlab.plotting.law import save_figure\n"
        "from ..driver import History\n",
        encoding="utf-8",
    )
    assert _outward(module) == [
        "m.py:5 imports frictionlab.plotting.law.save_figure",
        "m.py:6 imports frictionlab.driver.History",
    ]
