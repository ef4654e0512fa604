"""`frictionlab demo`: one HTML page with every figure, a caption under each, parameters."""

from __future__ import annotations

import html
import itertools
import json
import os
import re
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path
from typing import ClassVar

import numpy as np
import pytest
from matplotlib import image as mpimg

from frictionlab.cli import main
from frictionlab.demo import bundled_scenarios, default_builders

#: The whole demo runs once for this module (minutes on a 2-core machine).
pytestmark = pytest.mark.slow


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
    n = len(default_builders())  # the law's 6, the roughness model's 3, bridge, 2 of contact
    # one parameter table per section, the environment block's table and the law tables: a
    # law is shown in full once, later sections link to it and list only what differs
    text = (demo_dir / "report.html").read_text(encoding="utf-8")
    full, diff = text.count('<p class="law" id='), text.count(", except:</p>")
    linked = text.count("Law parameters: as in <a")
    assert linked >= 3 and diff <= linked and full <= 4  # cone, closed surface, bridge, contact
    assert n == 12 and page.sections == n and page.tables == n + 1 + full + diff
    assert len(page.images) >= 12
    for fig in page.figures:
        assert fig["img"] and len(str(fig["caption"]).split()) >= 8  # a real sentence
        path = demo_dir / str(fig["img"])
        assert path.is_file() and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not list(demo_dir.rglob(".*.tmp*"))
    # every figure links the data it was drawn from; one environment block
    figures = re.findall(r"<figure>(.*?)</figure>", text, re.S)
    assert len(figures) == len(page.figures)
    for block in figures:
        links = re.findall(r'<p class="data">Data: .*?href="([^"]+)"', block, re.S)
        assert links and (demo_dir / html.unescape(links[0])).is_file(), block[:200]
    assert text.count('<details class="env">') == 1


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


def test_fretting_section_softens_and_recovers(demo_dir: Path) -> None:
    """Coulomb slides at mu; the subloading law's first peak lies in (mu_k, mu_s], the next
    strokes are softened below it, and the restart after the hold recovers above them."""
    from frictionlab.io.tables import read_csv

    coulomb = read_csv(demo_dir / "fretting" / "fretting_coulomb.csv")
    assert float(np.max(np.abs(coulomb["friction_ratio"]))) == pytest.approx(0.6, rel=1e-6)
    sub = read_csv(demo_dir / "fretting" / "fretting_subloading.csv")
    peak = [float(np.max(np.abs(sub["friction_ratio"][sub["stage"] == s]))) for s in (1, 2, 3, 5)]
    assert 0.4 < peak[0] <= 0.6 and max(peak[1:3]) < peak[0] and peak[3] > max(peak[1:3])
    assert min(peak) >= 0.4 - 1e-6  # never below mu_k


_NO_CHROMIUM = shutil.which("chromium") is None and not Path("/usr/bin/chromium").exists()
_MUST_RUN = bool(os.environ.get("FRICTIONLAB_REQUIRE_CHROMIUM") or os.environ.get("CI"))

#: Injected at the top of <head> of a copy of the report: records every resource that
#: fails to load and every script error or console.error, then (on load, when every image
#: has loaded or failed) writes the counts into the DOM for --dump-dom to print.
PROBE = """<script>
window.__errors = [];
window.addEventListener("error", function (e) {
  var t = e.target;
  window.__errors.push(t && t.tagName ? "failed to load " + (t.src || t.href) : String(e.message));
}, true);
var _error = console.error;
console.error = function () {
  window.__errors.push("console.error: " + Array.prototype.join.call(arguments, " "));
  _error.apply(console, arguments);
};
window.addEventListener("load", function () {
  var images = Array.prototype.slice.call(document.images);
  var broken = images.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
  var pre = document.createElement("pre");
  pre.id = "frictionlab-probe";
  pre.textContent = JSON.stringify({images: images.length, errors: window.__errors,
    broken: broken.map(function (i) { return i.getAttribute("src"); })});
  document.body.appendChild(pre);
});
</script>"""


def _chromium(*args: str) -> subprocess.CompletedProcess[str]:
    browser = shutil.which("chromium") or "/usr/bin/chromium"
    return subprocess.run(
        [browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
         "--enable-logging=stderr", "--v=0", *args],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip


def _probe(page: Path) -> tuple[dict[str, object], list[str]]:
    """Load ``page`` in headless Chromium; the probe's findings and the console lines."""
    result = _chromium("--dump-dom", "--virtual-time-budget=10000", page.as_uri())
    assert result.returncode == 0, result.stderr[-2000:]
    found = re.search(r'<pre id="frictionlab-probe">(.*?)</pre>', result.stdout, re.S)
    assert found, "the page never finished loading (no probe output)"
    console = [line for line in result.stderr.splitlines() if ":CONSOLE" in line]
    return json.loads(html.unescape(found.group(1))), console


@pytest.mark.skipif(
    _NO_CHROMIUM and not _MUST_RUN,
    reason="no headless Chromium on this machine: the browser test runs in CI (.ci/run "
    "installs Debian's chromium) and wherever chromium is installed",
)
def test_report_opens_in_headless_chromium(demo_dir: Path, tmp_path: Path) -> None:
    assert not _NO_CHROMIUM, "CI or FRICTIONLAB_REQUIRE_CHROMIUM is set but chromium is missing"
    text = (demo_dir / "report.html").read_text(encoding="utf-8")
    assert text.count("<head>") == 1
    probe_page = demo_dir / "_browser_probe.html"  # beside the report: same relative links
    try:
        probe_page.write_text(text.replace("<head>", "<head>" + PROBE), encoding="utf-8")
        seen, console = _probe(probe_page)
        # the probe can fail: a copy with one image link broken is caught
        first = Page()
        first.feed(text)
        broken = text.replace(f'src="{first.images[0]}"', 'src="no/such/figure.png"', 1)
        probe_page.write_text(broken.replace("<head>", "<head>" + PROBE), encoding="utf-8")
        seen_broken, _ = _probe(probe_page)
    finally:
        probe_page.unlink(missing_ok=True)
    assert seen["images"] == len(first.images) >= 12
    assert seen["broken"] == [] and seen["errors"] == [] and console == []
    assert seen_broken["broken"] == ["no/such/figure.png"] and len(seen_broken["errors"]) == 1
    # the first screen, as a reader sees it, is not blank
    shot = tmp_path / "first_screen.png"
    result = _chromium(f"--screenshot={shot}", "--window-size=1280,800",
                       (demo_dir / "report.html").as_uri())  # fmt: skip
    assert result.returncode == 0 and shot.is_file(), result.stderr[-2000:]
    pixels = mpimg.imread(shot)[..., :3]
    assert pixels.shape[:2] == (800, 1280)
    ink = np.any(pixels < 0.9, axis=-1).mean()  # share of pixels darker than near-white
    assert 0.01 < ink < 0.9 and pixels.std() > 0.05, (ink, pixels.std())


def test_recorded_input_paths_exist_after_the_swap(demo_dir: Path) -> None:
    """Paths in the summaries name files of the published set, never the staging directory."""
    summaries = list(demo_dir.rglob("summary.json"))
    assert demo_dir / "bridge" / "fitted_law" / "summary.json" in summaries
    for path in summaries:
        summary = json.loads(path.read_text())
        recorded = [item["path"] for item in summary.get("provenance", {}).get("inputs", [])]
        if isinstance(summary.get("scenario"), str) and summary["scenario"]:
            recorded.append(summary["scenario"])
        for name in recorded:
            target = path.parent / name  # an absolute name replaces the folder
            assert target.is_file(), f"{path.relative_to(demo_dir)} records {name}"
    fitted = json.loads((demo_dir / "bridge" / "fitted_law" / "summary.json").read_text())
    assert fitted["scenario"] == "../fitted_law.toml"
