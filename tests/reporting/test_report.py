"""The HTML report: escaping, structure, refusal to link missing images."""

from __future__ import annotations

import itertools
import platform
import re
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
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


def test_figures_link_their_data_and_one_environment_block(tmp_path: Path) -> None:
    (tmp_path / "run").mkdir()
    (tmp_path / "run" / "friction.png").write_bytes(PNG)
    (tmp_path / "run" / "history.csv").write_text("time [s]\n0.0\n")
    (tmp_path / "run" / "summary.json").write_text("{}")
    (tmp_path / "fig").mkdir()
    (tmp_path / "fig" / "polar.png").write_bytes(PNG)
    (tmp_path / "fig" / "polar_case.csv").write_text("x [-]\n1\n")
    (tmp_path / "fig" / "other.csv").write_text("x [-]\n1\n")
    (tmp_path / "multi" / "a").mkdir(parents=True)
    (tmp_path / "multi" / "map.png").write_bytes(PNG)
    (tmp_path / "multi" / "a" / "history.csv").write_text("x [-]\n1\n")
    section = Section("Runs")
    section.add_figure("run/friction.png", "a caption of enough words to read as a sentence")
    section.add_figure("fig/polar.png", "a caption of enough words to read as a sentence")
    section.add_figure("multi/map.png", "a caption of enough words to read as a sentence")
    text = Report("t", sections=[section]).write(tmp_path / "report.html").read_text()
    hrefs = re.findall(r'href="([^"#]+)"', text)
    assert hrefs == ["run/history.csv", "run/summary.json", "fig/polar_case.csv",
                     "multi/a/history.csv"]  # fmt: skip
    assert all((tmp_path / h).is_file() for h in hrefs)
    assert text.count('<details class="env">') == 1
    assert f"<td>Python</td><td>{platform.python_version()}</td>" in text
    page = Collector()
    page.feed(text)
    assert page.errors == [] and page.stack == []


def test_polar_radial_axis_shows_a_small_anisotropy() -> None:
    from frictionlab.plotting.roughness import radial_limits

    beta = np.radians(np.arange(0.0, 360.0, 5.0))
    mu = 0.3 * (1.0 + 0.02 * np.cos(2.0 * beta))  # 4 % anisotropy
    lo, hi = radial_limits(mu)
    assert 0.0 < lo < mu.min() and hi > mu.max()
    drawn = mu - lo  # radius on the page
    assert drawn.max() / drawn.min() >= 3.0  # not a circle any more
    assert radial_limits(np.array([0.1, 2.0]))[0] == 0.0  # a large range keeps the origin
    lo, hi = radial_limits(np.full(4, 0.5))  # isotropic: a circle with a margin
    assert lo == pytest.approx(0.45) and hi == pytest.approx(0.55)


def test_the_restart_zoom_zooms_in_friction_too() -> None:
    from frictionlab.demo.law import _zoom_limits

    x = np.linspace(0.0, 1.3, 131)
    y = np.where(x < 0.05, 10.0 * x, 0.3 + 0.01 * np.sin(20 * x))  # a rise outside the window
    lo, hi = _zoom_limits(x, y, (0.9, 1.3))
    inside = y[x >= 0.9]
    assert lo < inside.min() and hi > inside.max() and hi - lo < 0.03  # not 0 to 0.5


def test_stability_map_labels_do_not_overlap(tmp_path: Path) -> None:
    from frictionlab.plotting.law import plot_stability_map, save_figure, spaced_ticks

    ratio = np.array([0.25, 0.5, 0.8, 0.9, 1.1, 1.25, 2.0, 4.0])
    assert spaced_ticks(ratio, keep=1.0) == [0.25, 0.5, 1.0, 2.0, 4.0]
    ax = plot_stability_map(ratio, np.geomspace(1e-1, 1e-12, ratio.size), 1e-3)
    save_figure(ax.figure, tmp_path / "map.png")
    ax.figure.draw_without_rendering()  # type: ignore[union-attr]  # tick label extents
    boxes = [t.get_window_extent() for t in ax.get_xticklabels() if t.get_text()]
    assert len(boxes) == 5
    assert all(a.x1 < b.x0 for a, b in itertools.pairwise(boxes))  # no overlap


def test_family_legends_say_what_each_case_is() -> None:
    from frictionlab.plotting.roughness import legend_label
    from frictionlab.roughness.families import CASE_DESCRIPTIONS, WEDGE_CASES

    assert set(CASE_DESCRIPTIONS) == set(WEDGE_CASES)
    assert legend_label("A") == "A: flat on symmetric teeth"
    assert legend_label("l2pi_3pi") == "wavelengths 2pi x 3pi (x, y)"
    assert legend_label("other") == "other"


def test_the_law_table_is_shown_once_and_linked(tmp_path: Path) -> None:
    cone = [("surface", "coulomb", ""), ("mu_s", "0.5", "-"), ("alpha_t", "1e+09", "Pa/m")]
    faster = [("surface", "coulomb", ""), ("mu_s", "0.6", "-"), ("alpha_t", "1e+09", "Pa/m")]
    closed = [("surface", "tear", ""), ("F_s", "1e+06", "Pa"), ("alpha_t", "2e+09", "Pa/m")]
    sections = [
        Section("First", law=cone, parameters=[("velocity", "1e-3", "m/s")]),
        Section("Same law", law=cone),
        Section("Other mu_s", law=faster),
        Section("Closed surface", law=closed),
        Section("No law"),
    ]
    text = Report("T", sections=sections).render()
    blocks = dict(re.findall(r'<section id="([^"]+)">(.*?)</section>', text, re.S))
    rows = {
        anchor: re.findall(r"<tr><td>([^<]*)</td><td>([^<]*)</td>", block)
        for anchor, block in blocks.items()
    }
    # the first law in full (then the section's own parameters), once
    assert rows["first"] == [(n, v) for n, v, _ in cone] + [("velocity", "1e-3")]
    assert text.count("<td>1e+09</td>") == 1
    # the same law: only a link to the first table, which exists
    assert rows["same-law"] == []
    link = re.search(r'as in <a href="#([^"]+)">First</a>\.', blocks["same-law"])
    assert link and f'id="{link.group(1)}"' in blocks["first"]
    # a changed value: the link and only that row
    assert rows["other-mu-s"] == [("mu_s", "0.6")]
    assert f'<a href="#{link.group(1)}">First</a>, except:' in blocks["other-mu-s"]
    # another set of keys: shown in full, no link
    assert rows["closed-surface"] == [(n, v) for n, v, _ in closed]
    assert "as in" not in blocks["closed-surface"]
    assert "Law parameters" not in blocks["no-law"]
    assert Collector().feed(text) is None
