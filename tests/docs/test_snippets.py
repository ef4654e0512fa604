"""Every ```python snippet of the documentation runs as printed.

Snippets that read a run's output (``out/<name>/history.csv``) get it: the starter
scenario is simulated into those folders first, in a scratch working directory.
"""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import pytest

from frictionlab.cli import main

DOCS = Path(__file__).resolve().parents[2] / "docs"
_BLOCK = re.compile(r"```python\n(.*?)```", re.S)


def _snippets() -> list[tuple[str, str]]:
    out = []
    for page in sorted(DOCS.glob("*.md")):
        for i, code in enumerate(_BLOCK.findall(page.read_text(encoding="utf-8")), start=1):
            out.append((f"{page.name}#{i}", code))
    return out


@pytest.mark.slow
@pytest.mark.parametrize(("where", "code"), _snippets(), ids=[w for w, _ in _snippets()])
def test_snippet_runs(where: str, code: str, tmp_path: Path, monkeypatch) -> None:
    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    for folder in re.findall(r'"out/([^/"]+)/history\.csv"', code):
        assert main(["example", "simulate", "--write", "."]) == 0
        assert main(["simulate", "simulate.toml", "--out", f"out/{folder}", "--quiet",
                     "--no-plots"]) == 0  # fmt: skip
    exec(compile(code, where, "exec"), {"__name__": "__snippet__"})
