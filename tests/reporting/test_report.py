"""The HTML report: escaping, structure, refusal to link missing images."""

from __future__ import annotations

from html.parser import HTMLParser
from pathlib import Path

import pytest

from frictionlab.errors import FrictionlabError
from frictionlab.io.report import Report, Section

PNG = b"\x89PNG\r\n\x1a\n" + b"\x00" * 16


class Collector(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.stack: list[str] = []
        self.images: list[str] = []
        self.captions = 0
        self.errors: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "img":
            self.images.append(dict(attrs)["src"] or "")
        elif tag not in ("meta", "br"):
            self.stack.append(tag)
        self.captions += tag == "figcaption"

    def handle_endtag(self, tag: str) -> None:
        if not self.stack or self.stack.pop() != tag:
            self.errors.append(tag)

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def test_render_escapes_and_balances(tmp_path: Path) -> None:
    (tmp_path / "a.png").write_bytes(PNG)
    sec = Section("Mu < 1 & more", "intro <b>", parameters=[("mu_s", "0.5", "-")])
    sec.add_figure("a.png", 'caption with "quotes" & <tags>')
    report = Report("Title", "Intro", [sec])
    report.add_section(Section("Second", "text"))
    path = report.write(tmp_path / "report.html")
    parser = Collector()
    parser.feed(path.read_text())
    assert parser.errors == [] and parser.stack == []
    assert parser.images == ["a.png"] and parser.captions == 1
    assert "Mu < 1 & more" in "".join(parser.text)  # escaped in the file, restored by the parser
    assert "<b>" not in path.read_text()


def test_missing_image_or_caption_is_refused(tmp_path: Path) -> None:
    sec = Section("S")
    sec.add_figure("missing.png", "a caption")
    with pytest.raises(FrictionlabError, match="does not exist"):
        Report("T", sections=[sec]).write(tmp_path / "report.html")
    (tmp_path / "x.png").write_bytes(PNG)
    empty = Section("S")
    empty.add_figure("x.png", "  ")
    with pytest.raises(FrictionlabError, match="no caption"):
        Report("T", sections=[empty]).write(tmp_path / "report.html")
    outside = Section("S")
    outside.add_figure("../x.png", "c")
    with pytest.raises(FrictionlabError, match="relative"):
        Report("T", sections=[outside]).write(tmp_path / "report.html")
    assert not (tmp_path / "report.html").exists()
