"""The demo: run the bundled scenarios and write a one-page HTML report.

:func:`run_demo` calls a sequence of *section builders*, each a function
``builder(ctx: DemoContext) -> Section`` that runs what it needs, writes its files under
``ctx.out_dir`` and returns a :class:`~frictionlab.io.report.Section` whose figure paths
are relative to ``ctx.out_dir``. The law's sections are in
:mod:`frictionlab.demo.law` (:data:`~frictionlab.demo.law.LAW_SECTIONS`); other parts
of frictionlab add theirs to :func:`default_builders` (e.g. a roughness section).

Bundled scenarios live in ``frictionlab/data/scenarios/*.toml`` (package data) and are
read with :mod:`importlib.resources`.
"""

from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any, TypeVar

from frictionlab._progress import ProgressFactory, no_progress
from frictionlab.io.report import Report, Section, format_value

__all__ = [
    "EXTRAS",
    "DemoContext",
    "SectionBuilder",
    "bundled_scenario",
    "bundled_scenarios",
    "check_extras",
    "default_builders",
    "law_rows",
    "load_bundled",
    "run_demo",
]

#: Optional extras the demo's sections import: module -> (extra, what needs it).
EXTRAS: dict[str, tuple[str, str]] = {
    "skfem": ("fem", "the finite-element contact section (scikit-fem)"),
    "threadpoolctl": ("fem", "the finite-element contact section (threadpoolctl)"),
}


def law_rows(params: Any, keys: Sequence[tuple[str, str]]) -> list[tuple[str, str, str]]:
    """Rows ``(key, value, unit)`` of a report's law table: ``keys`` are ``(key, unit)``
    pairs of ``params`` (a SubloadingParams); the value is that of the first point."""
    import numpy as np

    return [(key, format_value(float(np.ravel(getattr(params, key))[0])), unit)
            for key, unit in keys]  # fmt: skip


@dataclass
class DemoContext:
    """What a section builder gets: where to write, how to report progress and messages."""

    out_dir: Path
    progress: ProgressFactory = no_progress
    log: Callable[[str], None] = lambda message: None
    timings: dict[str, float] = field(default_factory=dict)


SectionBuilder = Callable[[DemoContext], Section]


def bundled_scenarios() -> list[str]:
    """Names of the bundled scenarios (file stems)."""
    folder = resources.files("frictionlab") / "data" / "scenarios"
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


@contextlib.contextmanager
def bundled_scenario(name: str, folder: str = "scenarios") -> Iterator[Path]:
    """A filesystem path to the bundled scenario ``name`` (e.g. ``"slide_hold_slide"``) of
    ``frictionlab/data/<folder>``."""
    ref = resources.files("frictionlab") / "data" / folder / f"{name}.toml"
    with resources.as_file(ref) as path:
        yield Path(path)


_T = TypeVar("_T")


def load_bundled(name: str, folder: str, load: Callable[[Path], _T]) -> tuple[_T, str]:
    """The bundled scenario ``name`` of ``frictionlab/data/<folder>`` read by ``load`` (a
    path -> scenario), and its text (the demo copies it next to the results)."""
    with bundled_scenario(name, folder) as path:
        return load(path), path.read_text(encoding="utf-8")


def default_builders() -> list[SectionBuilder]:
    """The demo's sections, in report order."""
    from frictionlab.demo.bridge import BRIDGE_SECTIONS
    from frictionlab.demo.contact import CONTACT_SECTIONS
    from frictionlab.demo.law import LAW_SECTIONS
    from frictionlab.demo.roughness import ROUGHNESS_SECTIONS

    return [*LAW_SECTIONS, *ROUGHNESS_SECTIONS, *BRIDGE_SECTIONS, *CONTACT_SECTIONS]


TITLE = (
    "frictionlab demo: the subloading-friction law in tribometer tests and the lattice-spring "
    "roughness model"
)
INTRO = (
    "Each section runs bundled scenarios (frictionlab/data/scenarios/*.toml; a copy sits next to "
    "its results, and `frictionlab simulate <copy> --out DIR` reruns it) through the "
    "subloading-friction law of Hashiguchi & Ozaki (2008), shows the response and compares "
    "it with the law's closed forms (docs/theory.md). SI units throughout; tractions per unit "
    "area in Pa. Two sections compute the figure families of the lattice-spring "
    "roughness model (mu versus sliding direction, adhesion, wear, hierarchy) and a third "
    "applies it to a measured topography file; their figures and tables sit in roughness/. "
    "The last section bridges the two: a law fitted "
    "to a roughness polar (frictionlab bridge; its files sit in bridge/)."
)


def check_extras(builders: Sequence[SectionBuilder] | None = None) -> None:
    """Raise :class:`~frictionlab.errors.InputError` (one line) when a module an optional
    extra provides is missing, before anything is computed. Only the default sections and
    the contact builders need the extras."""
    import importlib.util

    from frictionlab.errors import InputError

    if builders is not None:
        from frictionlab.demo.contact import CONTACT_SECTIONS

        if not any(b in CONTACT_SECTIONS for b in builders):
            return
    for module, (extra, needed_by) in EXTRAS.items():
        if importlib.util.find_spec(module) is None:
            raise InputError(
                f"frictionlab demo needs the optional extra '{extra}' for {needed_by}: "
                f"pip install 'frictionlab[{extra}]' (module '{module}' is not installed)"
            )


def run_demo(
    out_dir: str | os.PathLike[str],
    builders: Sequence[SectionBuilder] | None = None,
    progress: ProgressFactory | None = None,
    log: Callable[[str], None] | None = None,
) -> Path:
    """Run every section builder and write ``out_dir/report.html``; return its path.

    The optional extras are checked first (:func:`check_extras`): nothing is computed or
    written when one is missing."""
    check_extras(builders)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    chosen = list(builders) if builders is not None else default_builders()
    ctx = DemoContext(out, progress or no_progress, log or (lambda message: None))
    report = Report(TITLE, INTRO)
    for i, build in enumerate(chosen, start=1):
        start = time.perf_counter()
        name = (build.__doc__ or build.__name__).strip().splitlines()[0]
        ctx.log(f"[{i}/{len(chosen)}] {name} ...")
        section = build(ctx)
        report.add_section(section)
        ctx.timings[section.title] = time.perf_counter() - start
        ctx.log(f"[{i}/{len(chosen)}] done in {ctx.timings[section.title]:.1f} s")
    return report.write(out / "report.html")
