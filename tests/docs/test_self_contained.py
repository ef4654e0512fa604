"""User-facing text is self-contained: no references to documents users do not have.

The library was built from a private specification (numbered sections, "pitfalls", open
questions, reference scenarios, issue numbers). Docstrings reach the API pages and error
messages reach users, so neither may point at it: "spec section 4", "pitfall 15", "issue 4",
"T7", "scenario AD", "test 17", "Q4". Equation numbers of the published papers are fine.
Python files are scanned in their strings and comments only (code names such as ``A1`` or
``spec`` variables are not text); Markdown, YAML and JSON files are scanned whole.
"""

from __future__ import annotations

import io
import re
import tokenize
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

#: One pattern per kind of reference to the private specification or the tracker.
PATTERNS = {
    "section sign": r"§",
    "the specification": r"\b[Ss]pec(?:ification)?(?:'s)?\b(?!\.py)",
    "a pitfall number": r"\b[Pp]itfalls?\b",
    "an issue number": r"\b[Ii]ssues? #?\d+",
    "a test-scenario id": r"\b(?:T\d+|AD|LD|PH|JN|RV|[ABE]\d{1,2}(?:-BE)?)\b",
    "a test number": r"\b[Tt]ests? \d+\b",
    "an open-question id": r"\bQ\d+\b",
}
PATTERN = re.compile("|".join(f"(?:{p})" for p in PATTERNS.values()))

#: Files being rewritten by other helpers right now: cleaned by their owners.
ALLOWLIST = {
    "src/frictionlab/subloading/kernels.py",
    "src/frictionlab/subloading/evolution.py",
    "src/frictionlab/subloading/surfaces.py",
    "src/frictionlab/subloading/interpreted.py",
    "src/frictionlab/roughness/_kernels.py",
    "src/frictionlab/roughness/full_contact.py",
    "src/frictionlab/roughness/topography.py",
    "src/frictionlab/_compile_cache.py",
    "src/frictionlab/benchmark.py",
    "src/frictionlab/driver/simulate.py",
    "src/frictionlab/driver/stepping.py",
    "src/frictionlab/io/results.py",
    "src/frictionlab/commands/simulate.py",
    "src/frictionlab/commands/sweep.py",
    "src/frictionlab/commands/roughness.py",
    "src/frictionlab/demo/topography_file.py",
    "src/frictionlab/sweep/__init__.py",
    "src/frictionlab/sweep/cases.py",
    "src/frictionlab/sweep/figures.py",
    "src/frictionlab/sweep/ledger.py",
    "src/frictionlab/sweep/spec.py",
    "src/frictionlab/sweep/table.py",
    "docs/performance.md",
}
#: The change log records history, issue numbers included.
HISTORY = {"docs/changelog.md", "CHANGELOG.md"}


def _python_text(path: Path) -> list[tuple[int, str]]:
    """(line, text) of every string and comment of a Python file (noqa codes removed)."""
    out = []
    tokens = tokenize.generate_tokens(io.StringIO(path.read_text(encoding="utf-8")).readline)
    for tok in tokens:
        if tok.type == tokenize.STRING or tok.type == tokenize.COMMENT:
            text = re.sub(r"(noqa|type: ?ignore)(\[[^\]]*\]|:[\sA-Z0-9,]*)?", "", tok.string)
            for i, line in enumerate(text.splitlines()):
                out.append((tok.start[0] + i, line))
    return out


def _user_files() -> list[Path]:
    files = [ROOT / "README.md", ROOT / "mkdocs.yml"]
    files += sorted((ROOT / "src").rglob("*.py"))
    files += sorted((ROOT / "examples").rglob("*.py"))
    for ext in ("*.md", "*.yml", "*.json"):
        files += sorted((ROOT / "docs").rglob(ext))
    for ext in ("*.toml", "*.md"):
        files += sorted((ROOT / "src" / "frictionlab" / "data").rglob(ext))
    return [f for f in files if f.relative_to(ROOT).as_posix() not in ALLOWLIST | HISTORY]


def find_references(path: Path) -> list[str]:
    """'path:line: text' for every reference to the private specification in ``path``."""
    if path.suffix == ".py":
        lines = _python_text(path)
    else:
        lines = list(enumerate(path.read_text(encoding="utf-8").splitlines(), start=1))
    rel = path.relative_to(ROOT).as_posix()
    return [f"{rel}:{n}: {line.strip()}" for n, line in lines if PATTERN.search(line)]


@pytest.mark.parametrize(
    "text",
    [
        "see spec §4.2",
        "(pitfall 15)",
        "issue 4",
        "scenarios T5-T6",
        "Fig 10 / scenario AD",
        "spec test 17",
        "(see Q4 below)",
        "ratcheting, spec A6",
        "the specification's choice",
    ],
)
def test_the_patterns_catch_each_kind(text: str) -> None:
    assert PATTERN.search(text)


@pytest.mark.parametrize(
    "text",
    ["spectral radius", "respect to", "timespec", "Eq (29) of Hashiguchi & Ozaki (2008)", "TOML"],
)
def test_the_patterns_leave_ordinary_words(text: str) -> None:
    assert not PATTERN.search(text)


def test_python_scan_reads_strings_and_comments_only(tmp_path: Path) -> None:
    (tmp_path / "m.py").write_text('A1 = 1  # noqa: E501\nspec = "x"\n"""see T7"""\n# pitfall 3\n')
    found = [line for _, line in _python_text(tmp_path / "m.py") if PATTERN.search(line)]
    assert found == ['"""see T7"""', "# pitfall 3"]


def test_allowlisted_files_exist() -> None:
    missing = [f for f in ALLOWLIST if not (ROOT / f).is_file()]
    assert not missing, f"stale allowlist entries: {missing}"


def test_user_facing_text_is_self_contained() -> None:
    found = [hit for path in _user_files() for hit in find_references(path)]
    assert not found, f"{len(found)} references to documents users do not have:\n" + "\n".join(
        found
    )
