"""Axes at the scale of the data; polar axes that do not start at zero say so."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.plotting.units import length_unit, show_length_in


@pytest.mark.parametrize(
    ("low", "high", "unit"),
    [(0.0, 2.0, "m"), (9e-4, 1.3e-3, "um"), (0.0, 5e-3, "mm"), (1e-9, 5e-8, "nm"),
     (0.0, 0.0, "m")],
)  # fmt: skip
def test_length_unit_puts_the_span_between_1_and_1000(low: float, high: float, unit: str):
    assert length_unit(low, high)[0] == unit


def test_restart_window_ticks_read_in_micrometres():
    """The restart zoom (0.9 to 1.3 mm of slip) read 0.0009 ... 0.0013 m, labels overlapping."""
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.add_subplot()
    ax.plot([9e-4, 1.3e-3], [0.3, 0.4])
    ax.set_xlim(9e-4, 1.3e-3)
    assert show_length_in(ax.xaxis, "slip along e_1", 9e-4, 1.3e-3) == "um"
    fig.draw_without_rendering()
    labels = [t.get_text() for t in ax.get_xticklabels() if t.get_text()]
    values = [float(s) for s in labels]
    assert ax.get_xlabel() == "slip along e_1 [um]"
    assert 3 <= len(labels) <= 7 and all(900 <= v <= 1300 for v in values), labels
    assert max(len(s) for s in labels) <= 4


def test_a_polar_that_does_not_start_at_zero_says_so_in_red():
    from matplotlib.figure import Figure

    from frictionlab.plotting.roughness import note_radial_origin

    ax = Figure().add_subplot(projection="polar")
    radius = 1.0 + 7e-4 * np.cos(2 * np.linspace(0, 2 * np.pi, 73))
    note_radial_origin(ax, 0.9995, radius)
    (text,) = ax.texts
    assert "radial axis starts at 0.9995, not 0" in text.get_text()
    assert "0.14 %" in text.get_text()
