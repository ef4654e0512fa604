"""The demo report's roughness sections (Figs 6-14): generated and validated."""

from __future__ import annotations

import contextlib
import re

import numpy as np
import pytest

from frictionlab.demo.roughness_figures import FOLDER, roughness_sections
from frictionlab.io.report import Report
from frictionlab.io.tables import read_csv

FAMILIES = ("fig6a", "fig6b", "fig7", "fig8", "fig10", "fig11", "fig12", "fig13", "fig14")


@pytest.mark.slow
def test_sections_generated_and_valid(tmp_path) -> None:
    calls: list[tuple[int, int]] = []

    @contextlib.contextmanager
    def progress(description: str):
        assert "roughness" in description
        yield lambda done, total: calls.append((done, total))

    sections = roughness_sections(tmp_path, progress=progress)
    assert calls[4] == (4, 4) and calls[-1] == (5, 5)  # one step per figure family
    figures = [f for s in sections for f in s.figures]
    assert [re.match(r"roughness/(fig\d+[ab]?)_", f.path).group(1) for f in figures] == list(
        FAMILIES
    )
    for section in sections:
        assert section.title.startswith("Lattice-spring roughness")
        assert section.intro and section.parameters
    for fig in figures:
        assert (tmp_path / fig.path).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        caption = fig.caption.strip()
        assert caption.startswith("Fig ") and caption.endswith(".")
        assert caption.count(". ") == 0  # one sentence per figure
        assert "nan" not in caption.lower() and "inf" not in caption.lower()
    report = Report("roughness")
    for section in sections:
        report.add_section(section)
    html = report.write(tmp_path / "report.html").read_text()  # checks every image and caption
    assert html.count("<figure>") == len(FAMILIES)
    # the tables behind the figures sit beside them; undefined mu_a (L = 0) is an empty field
    adhesion = read_csv(tmp_path / FOLDER / "fig10_adhesion_sine_sine.csv")
    zero = adhesion["load_per_spring"] == 0.0
    assert np.all(np.ma.getmaskarray(adhesion["mu_apparent"]) == zero)
    life = read_csv(tmp_path / FOLDER / "fig14_hierarchy_wear.csv")
    np.testing.assert_allclose(life["mu_3"][-1], 0.3, rtol=1e-14)


def test_measured_section(tmp_path) -> None:
    from frictionlab.demo.roughness_figures import measured_section

    section = measured_section(tmp_path)
    assert section.title == "Lattice-spring roughness: a measured topography file"
    paths = [f.path for f in section.figures]
    assert paths == [
        f"{FOLDER}/measured_polar.png",
        f"{FOLDER}/measured_multiscale.png",
        f"{FOLDER}/measured_statistics.png",
        f"{FOLDER}/measured_models.png",
    ]
    for fig in section.figures:
        assert (tmp_path / fig.path).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        caption = fig.caption.strip()
        assert caption.endswith(".") and caption.count(". ") == 0
        assert "nan" not in caption.lower()
    table = read_csv(tmp_path / FOLDER / "measured_multiscale.csv")
    assert np.all(np.asarray(table["valid"]))
    mu = np.asarray(table["mu_over_mu0"], dtype=float).reshape(4, 3)
    assert np.all(mu >= 1.0)  # rough bands only add friction to a flat counter-face
    models = read_csv(tmp_path / FOLDER / "measured_models.csv")
    for key in ("mu_lattice", "mu_elastic"):  # rough on flat: friction rises above mu0
        assert np.all(np.asarray(models[key], dtype=float) > 0.3)
    assert "touches" in section.figures[3].caption
    assert section.parameters
