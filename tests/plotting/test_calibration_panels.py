"""The calibration figure shows each sliding segment in a panel of its own (holds left out):
on one linear axis, 3 s slides vanish beside 330 s of holds."""

from __future__ import annotations

import numpy as np
from tests.calibration.support import make_curve

from frictionlab.plotting.calibration import plot_curve_fit


def test_one_panel_per_sliding_segment_with_its_own_time():
    curve = make_curve(0.0)
    model = curve.friction_ratio + 0.001
    fig = plot_curve_fit(curve, model, band=np.full(curve.n_samples, 0.002))
    titles = [ax.get_title() for ax in fig.axes if ax.get_title()]
    assert titles == ["segment 1 (slide)", "segment 3 (slide)", "segment 5 (slide)"]
    top = [ax for ax in fig.axes if ax.get_title()]
    # each panel's time axis starts at its segment's start and spans its own few seconds
    for ax, length in zip(top, (6.0, 2.0, 2.0), strict=True):
        (line,) = [ln for ln in ax.get_lines() if ln.get_label() == "fitted law"]
        t = line.get_xdata()
        assert t.min() >= -1e-9 and t.max() <= length + 1e-9 and t.max() > 0.9 * length
    assert all(len(ax.collections) == 1 for ax in top)  # the shaded band
