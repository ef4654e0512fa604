"""A one-page HTML report built from sections (title, text, figures with captions, parameters).

Figures are PNG files stored next to ``report.html`` (in its directory or below it) and
linked with relative paths, so the output directory can be moved or zipped as a whole.
Under each figure the report links the data it was drawn from (:func:`data_files`), and
one environment block at the top gives the versions, platform and time of the run.
:meth:`Report.write` refuses to write a report whose images are missing or whose
figures have no caption. Other parts of frictionlab append their own sections with
:meth:`Report.add_section`.
"""

from __future__ import annotations

import html
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from frictionlab._version import __version__
from frictionlab.errors import FrictionlabError
from frictionlab.io.atomic import write_text_atomic

__all__ = ["Figure", "Report", "Section", "data_files", "format_value"]

#: Data files linked under a figure.
DATA_SUFFIXES = (".csv", ".json", ".toml")


@dataclass(frozen=True)
class Figure:
    """An image of the report: ``path`` relative to the report's directory, one caption."""

    path: str
    caption: str
    alt: str = ""


@dataclass
class Section:
    """A section of the report.

    ``parameters`` are rows ``(name, value, unit)`` shown in a table under the figures;
    ``law`` are the rows of the constitutive law the section ran with: the report shows the
    first section's law table in full and, in later sections, links to it and lists only
    the rows that differ (a law with other keys is shown in full); ``notes`` are extra
    paragraphs (e.g. measured numbers) after the intro.
    """

    title: str
    intro: str = ""
    figures: list[Figure] = field(default_factory=list)
    parameters: list[tuple[str, str, str]] = field(default_factory=list)
    law: list[tuple[str, str, str]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    anchor: str = ""

    def add_figure(self, path: str, caption: str, alt: str = "") -> None:
        self.figures.append(Figure(path, caption, alt))


_CSS = """
body { font-family: system-ui, -apple-system, 'Segoe UI', sans-serif; max-width: 1100px;
       margin: 2em auto; padding: 0 1em; color: #222; line-height: 1.45; }
h1 { border-bottom: 2px solid #444; padding-bottom: .2em; }
h2 { margin-top: 2.2em; border-bottom: 1px solid #bbb; }
figure { margin: 1.2em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: .95em; color: #333; margin-top: .3em; }
table.params { border-collapse: collapse; font-size: .9em; margin: .8em 0; }
table.params td, table.params th { border: 1px solid #ccc; padding: .2em .6em; text-align: left; }
table.params th { background: #f2f2f2; }
nav ol { columns: 2; }
p.meta, p.data { color: #666; font-size: .9em; }
p.data { margin: .2em 0 0; }
details.env { margin: .8em 0; font-size: .9em; }
"""


class Report:
    """An HTML report: a title, an introduction and an ordered list of sections."""

    def __init__(self, title: str, intro: str = "", sections: Iterable[Section] = ()) -> None:
        self.title = title
        self.intro = intro
        self.sections: list[Section] = list(sections)

    def add_section(self, section: Section) -> Section:
        """Append a section (returned for chaining)."""
        self.sections.append(section)
        return section

    def render(
        self,
        data: dict[str, list[str]] | None = None,
        environment: dict[str, str] | None = None,
    ) -> str:
        """The HTML text (well-formed HTML5, all text escaped).

        ``data`` maps a figure's path to the data files linked under it (see
        :meth:`write`); ``environment`` gives the rows of the environment block.
        """
        e = html.escape
        data = data or {}
        out = [
            "<!DOCTYPE html>",
            '<html lang="en">',
            "<head>",
            '<meta charset="utf-8">',
            '<meta name="viewport" content="width=device-width, initial-scale=1">',
            f"<title>{e(self.title)}</title>",
            f"<style>{_CSS}</style>",
            "</head>",
            "<body>",
            f"<h1>{e(self.title)}</h1>",
        ]
        if self.intro:
            out.append(f"<p>{e(self.intro)}</p>")
        out.append(f'<p class="meta">frictionlab {e(__version__)}</p>')
        if environment:
            out.append('<details class="env"><summary>Environment of this run</summary>')
            out.append('<table class="params">')
            for key, value in environment.items():
                out.append(f"<tr><td>{e(key)}</td><td>{e(value)}</td></tr>")
            out.append("</table></details>")
        anchors = self._anchors()
        base: tuple[str, str, dict[str, tuple[str, str]]] | None = None  # id, title, rows
        out.append("<nav><ol>")
        for sec, anchor in zip(self.sections, anchors, strict=True):
            out.append(f'<li><a href="#{anchor}">{e(sec.title)}</a></li>')
        out.append("</ol></nav>")
        for sec, anchor in zip(self.sections, anchors, strict=True):
            out.append(f'<section id="{anchor}">')
            out.append(f"<h2>{e(sec.title)}</h2>")
            if sec.intro:
                out.append(f"<p>{e(sec.intro)}</p>")
            for note in sec.notes:
                out.append(f"<p>{e(note)}</p>")
            for fig in sec.figures:
                alt = fig.alt or fig.caption
                out.append("<figure>")
                out.append(f'<img src="{e(fig.path)}" alt="{e(alt)}">')
                out.append(f"<figcaption>{e(fig.caption)}</figcaption>")
                links = data.get(fig.path, [])
                if links:
                    items = ", ".join(f'<a href="{e(f)}">{e(f)}</a>' for f in links)
                    out.append(f'<p class="data">Data: {items}</p>')
                out.append("</figure>")
            if sec.law:
                rows = {name: (value, unit) for name, value, unit in sec.law}
                if base is None or not set(base[2]) <= set(rows):
                    table_id = f"law-{anchor}"
                    out.append(f'<p class="law" id="{table_id}">Law parameters:</p>')
                    out += _table(sec.law, "law parameter")
                    if base is None:
                        base = (table_id, sec.title, rows)
                else:
                    changed = [(n, v, u) for n, (v, u) in rows.items() if base[2].get(n) != (v, u)]
                    link = f'<a href="#{base[0]}">{e(base[1])}</a>'
                    if changed:
                        out.append(f'<p class="law">Law parameters: as in {link}, except:</p>')
                        out += _table(changed, "law parameter")
                    else:
                        out.append(f'<p class="law">Law parameters: as in {link}.</p>')
            if sec.parameters:
                out += _table(sec.parameters, "parameter")
            out.append("</section>")
        out += ["</body>", "</html>", ""]
        return "\n".join(out)

    def _anchors(self) -> list[str]:
        seen: set[str] = set()
        out = []
        for i, sec in enumerate(self.sections, start=1):
            base = sec.anchor or "".join(c if c.isalnum() else "-" for c in sec.title.lower())
            anchor = base.strip("-") or f"section-{i}"
            while anchor in seen:
                anchor = f"{anchor}-{i}"
            seen.add(anchor)
            out.append(anchor)
        return out

    def check(self, directory: str | os.PathLike[str]) -> None:
        """Raise if a figure's file is missing from ``directory`` or a caption is empty."""
        root = Path(directory)
        for sec in self.sections:
            for fig in sec.figures:
                if not fig.caption.strip():
                    raise FrictionlabError(f"figure {fig.path} in '{sec.title}' has no caption")
                if Path(fig.path).is_absolute() or ".." in Path(fig.path).parts:
                    raise FrictionlabError(
                        f"figure path {fig.path} must be relative, inside the report directory"
                    )
                if not (root / fig.path).is_file():
                    raise FrictionlabError(
                        f"figure {fig.path} of '{sec.title}' does not exist in {root}"
                    )

    def write(self, path: str | os.PathLike[str]) -> Path:
        """Check the figures and write the report atomically to ``path``.

        Each figure links its data files (:func:`data_files`); the environment block
        holds the versions, platform and UTC time (:func:`~frictionlab.io.provenance.provenance`).
        """
        from frictionlab.io.provenance import provenance

        target = Path(path)
        root = target.parent
        self.check(root)
        data = {
            fig.path: data_files(root, fig.path) for sec in self.sections for fig in sec.figures
        }
        return write_text_atomic(target, self.render(data, environment(provenance())))


def _table(rows: Iterable[tuple[str, str, str]], head: str) -> list[str]:
    """HTML lines of a parameter table (escaped)."""
    e = html.escape
    out = ['<table class="params">', f"<tr><th>{e(head)}</th><th>value</th><th>unit</th></tr>"]
    for name, value, unit in rows:
        out.append(f"<tr><td>{e(name)}</td><td>{e(value)}</td><td>{e(unit)}</td></tr>")
    out.append("</table>")
    return out


def data_files(root: str | os.PathLike[str], figure: str) -> list[str]:
    """The data a figure was drawn from, as paths relative to ``root``.

    Files beside the figure with its stem (``fig.csv``, ``fig_case.csv`` for ``fig.png``);
    otherwise every data file (CSV, JSON, TOML) beside it; otherwise those one folder
    below (a figure summarising several runs).
    """
    base = Path(root)
    image = base / figure
    folder, stem = image.parent, image.stem

    def rel(paths: Iterable[Path]) -> list[str]:
        return sorted(p.relative_to(base).as_posix() for p in paths)

    beside = [p for p in folder.glob("*") if p.suffix in DATA_SUFFIXES and p.is_file()]
    named = [p for p in beside if p.stem == stem or p.stem.startswith(stem + "_")]
    if named:
        return rel(named)
    if beside:
        return rel(beside)
    return rel(p for p in folder.glob("*/*") if p.suffix in DATA_SUFFIXES and p.is_file())


def environment(prov: dict[str, object]) -> dict[str, str]:
    """Rows of the report's environment block from a provenance block."""
    deps = prov.get("dependencies", {})
    command = prov.get("command", [])
    rows = {
        "frictionlab": str(prov.get("frictionlab_version", "")),
        "Python": str(prov.get("python", "")),
        "platform": str(prov.get("platform", "")),
        "written (UTC)": str(prov.get("timestamp", "")),
        "command": " ".join(str(a) for a in command) if isinstance(command, list) else "",
    }
    if isinstance(deps, dict):
        rows.update({name: str(version) for name, version in deps.items()})
    return rows


def format_value(value: object) -> str:
    """Compact text for a parameter value (``%g`` for floats, lists in brackets)."""
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(format_value(v) for v in value) + "]"
    return str(value)
