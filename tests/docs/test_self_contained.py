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
    # not a code name: ``sweep.spec``, ``spec.cases``, ``spec.py``
    "the specification": r"(?<![.\w])[Ss]pec(?:ification)?(?:'s)?\b(?![.]\w)",
    "a pitfall number": r"\b[Pp]itfalls?\b",
    "an issue number": r"\b[Ii]ssues? #?\d+",
    # ``A1``, ``A2`` alone are the orthotropy coefficients; as scenario ids they come named
    "a test-scenario id": r"\b(?:T\d+|AD|LD|PH|JN|RV|[ABE]\d{1,2}-BE|scenarios? [ABE]\d{1,2})\b",
    "a test number": r"\b[Tt]ests? \d+\b",
    "an open-question id": r"\bQ\d+\b",
}
PATTERN = re.compile("|".join(f"(?:{p})" for p in PATTERNS.values()))

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
    return [f for f in files if f.relative_to(ROOT).as_posix() not in HISTORY]


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
        "scenario B3",
        "as in E2-BE",
    ],
)
def test_the_patterns_catch_each_kind(text: str) -> None:
    assert PATTERN.search(text)


@pytest.mark.parametrize(
    "text",
    [
        "spectral radius",
        "respect to",
        "timespec",
        "Eq (29) of Hashiguchi & Ozaki (2008)",
        "TOML",
        "# = fh1 / A1^2",
        "see :mod:`frictionlab.sweep.spec`",
        "{spec.cases} cases",
    ],
)
def test_the_patterns_leave_ordinary_words(text: str) -> None:
    assert not PATTERN.search(text)


def test_python_scan_reads_strings_and_comments_only(tmp_path: Path) -> None:
    (tmp_path / "m.py").write_text('A1 = 1  # noqa: E501\nspec = "x"\n"""see T7"""\n# pitfall 3\n')
    found = [line for _, line in _python_text(tmp_path / "m.py") if PATTERN.search(line)]
    assert found == ['"""see T7"""', "# pitfall 3"]


def test_user_facing_text_is_self_contained() -> None:
    found = [hit for path in _user_files() for hit in find_references(path)]
    assert not found, f"{len(found)} references to documents users do not have:\n" + "\n".join(
        found
    )
