"""``frictionlab calibrate CONFIG.toml --out DIR``: fit the law to tribometer curves.

Reads the starting law, the fitted parameters and the measured curves with their
programmes (:mod:`frictionlab.schema.calibrate`), fits them
(:func:`frictionlab.calibration.fit_law`), profiles the poorly identified parameters and
writes ``fitted.toml``, ``summary.json`` (``fit.json``: a deprecated copy), ``curves.csv``,
the figures and ``report.html``. The workflow is :mod:`frictionlab.app.calibrate`.

Exit codes: 2 bad input or bad data (one line naming the key or file; nothing written),
1 failed computation (the driver fails at the starting law), 0 success.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_workflow_parser

HELP = "fit the law's parameters to tribometer curves and write fitted.toml, summary.json, a report"


def add_parser(sub: argparse._SubParsersAction) -> None:
    add_workflow_parser(sub, "calibrate", HELP, "frictionlab.app.calibrate:CALIBRATE",
                        "calibration file (TOML)", "fit.profile=false or --set law.mu_s=0.6",
                        input_name="config", plots=False)  # fmt: skip
