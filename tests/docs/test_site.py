"""The docs site opens from disk and every page is reachable from the navigation."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parents[2]


class _Loader(yaml.SafeLoader):
    """mkdocs.yml may hold !!python tags (none today); unknown tags load as None."""


_Loader.add_multi_constructor("", lambda loader, suffix, node: None)


def _pages(nav: Any) -> list[str]:
    if isinstance(nav, str):
        return [nav]
    if isinstance(nav, list):
        return [p for item in nav for p in _pages(item)]
    if isinstance(nav, dict):
        return [p for v in nav.values() for p in _pages(v)]
    return []


def test_pages_are_files_and_every_top_level_page_is_in_the_navigation() -> None:
    config = yaml.load((ROOT / "mkdocs.yml").read_text(), Loader=_Loader)
    # theory.md becomes theory.html, not theory/index.html (a directory listing from disk)
    assert config["use_directory_urls"] is False
    listed = set(_pages(config["nav"]))
    pages = {p.name for p in (ROOT / "docs").glob("*.md")}
    assert pages <= listed, sorted(pages - listed)
