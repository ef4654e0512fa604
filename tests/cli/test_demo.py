"""`frictionlab demo`: one HTML page with every figure, a caption under each, parameters."""

from __future__ import annotations

import itertools
import json
import os
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path
from typing import ClassVar

import pytest

from frictionlab.cli import main
from frictionlab.demo import bundled_scenarios, default_builders


class Page(HTMLParser):
    """Checks well-formedness and collects images, captions and tables per section."""

    VOID: ClassVar[set[str]] = {"meta", "img", "br", "hr", "link", "input"}

    def __init__(self) -> None:
        super().__init__()
        self.stack: list[str] = []
        self.errors: list[str] = []
        self.images: list[str] = []
        self.figures: list[dict[str, object]] = []
        self.sections = 0
        self.tables = 0
        self._caption: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "img":
            src = dict(attrs).get("src") or ""
            self.images.append(src)
            if self.figures:
                self.figures[-1]["img"] = src
        if tag in self.VOID:
            return
        self.stack.append(tag)
        if tag == "figure":
            self.figures.append({"img": None, "caption": ""})
        elif tag == "figcaption":
            self._caption = []
        elif tag == "section":
            self.sections += 1
        elif tag == "table":
            self.tables += 1

    def handle_endtag(self, tag: str) -> None:
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"unexpected </{tag}> (open: {self.stack[-3:]})")
            return
        self.stack.pop()
        if tag == "figcaption" and self._caption is not None:
            self.figures[-1]["caption"] = "".join(self._caption).strip()
            self._caption = None

    def handle_data(self, data: str) -> None:
        if self._caption is not None:
            self._caption.append(data)


@pytest.fixture(scope="module")
def demo_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("demo")
    assert main(["demo", "--out", str(out), "--quiet"]) == 0
    return out


def test_report_is_well_formed_and_complete(demo_dir: Path) -> None:
    page = Page()
    page.feed((demo_dir / "report.html").read_text(encoding="utf-8"))
    page.close()
    assert page.errors == [] and page.stack == []
    n = len(default_builders())  # the law's 6, the roughness model's 3, the bridge, contact
    assert n == 11 and page.sections == n and page.tables == n  # one parameter table each
    assert len(page.images) >= 12
    for fig in page.figures:
        assert fig["img"] and len(str(fig["caption"]).split()) >= 8  # a real sentence
        path = demo_dir / str(fig["img"])
        assert path.is_file() and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not list(demo_dir.rglob(".*.tmp*"))


def test_every_bundled_scenario_ran_and_can_be_rerun(demo_dir: Path) -> None:
    for name in bundled_scenarios():  # in OUT/<name>/ or, run several ways, OUT/<name>/<case>/
        folders = [f for f in (demo_dir / name).rglob("*") if (f / "history.csv").is_file()]
        if (demo_dir / name / "history.csv").is_file():
            folders.append(demo_dir / name)
        assert folders, name
        for folder in folders:
            assert (folder / "scenario.toml").is_file()
            assert json.loads((folder / "summary.json").read_text())["success"] is True


def test_demo_physics_notes(demo_dir: Path) -> None:
    """The slide-hold-slide restart peaks in the demo grow with the hold time, below mu_s."""
    s = json.loads((demo_dir / "slide_hold_slide" / "summary.json").read_text())
    peaks = s["segments"][2]["peak_friction_ratio"]
    assert all(b > a for a, b in itertools.pairwise(peaks)) and max(peaks) <= 0.5


_NO_CHROMIUM = shutil.which("chromium") is None and not Path("/usr/bin/chromium").exists()


@pytest.mark.skipif(
    _NO_CHROMIUM and not os.environ.get("FRICTIONLAB_REQUIRE_CHROMIUM"),
    reason="no headless Chromium on this machine (.ci/run installs it)",
)
def test_report_opens_in_headless_chromium(demo_dir: Path, tmp_path: Path) -> None:
    assert not _NO_CHROMIUM, "FRICTIONLAB_REQUIRE_CHROMIUM is set but chromium is not installed"
    browser = shutil.which("chromium") or "/usr/bin/chromium"
    shot = tmp_path / "page.png"
    result = subprocess.run(
        [browser, "--headless", "--no-sandbox", "--disable-gpu", f"--screenshot={shot}",
         "--window-size=1200,3000", (demo_dir / "report.html").as_uri()],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr[-2000:]
    assert shot.is_file() and shot.stat().st_size > 10_000
