"""``frictionlab bridge SCENARIO.toml --out DIR``: from two rough surfaces to a runnable law.

Computes the lattice-spring polar mu(beta) over the full circle, fits the anisotropy of the
subloading-friction law to it (:func:`frictionlab.bridge.fit_anisotropy`), builds the fitted
law, writes it as a scenario that ``frictionlab simulate`` runs as it is, runs that very
scenario (steady sliding in every direction of the polar) and compares the simulated steady
tractions with the law's closed form. Writes ``fitted_law.toml``, ``directions.csv``,
``bridge.png`` and ``summary.json`` (last; ``bridge.json`` is its deprecated copy) into
``--out``, each atomically and only after everything is computed. The workflow is
:mod:`frictionlab.app.bridge`.

Exit codes: 2 bad input (one line naming the key; nothing written), 1 failed computation
(no valid law fits, the check simulation fails, or it misses the closed form), 0 success;
a polar the law cannot express is a success with a sentence in ``summary.json`` and on the
terminal.
"""

from __future__ import annotations

import argparse

from frictionlab.commands._output import add_workflow_parser

HELP = "fit the law's anisotropy to the roughness polar mu(beta) and write a runnable law"


def add_parser(sub: argparse._SubParsersAction) -> None:
    add_workflow_parser(
        sub,
        "bridge",
        HELP,
        "frictionlab.app.bridge:BRIDGE",
        "bridge scenario file (TOML)",
        "bridge.scale=roughness",
        plots=False,
        description=(
            "Compute mu(beta) of two rough surfaces over the full circle (lattice-spring "
            "model), fit the subloading-friction law's orthotropy and rotation vector to it, "
            "check the fitted law by simulated steady sliding, and write summary.json, "
            "fitted_law.toml (runnable by `frictionlab simulate`), directions.csv and "
            "bridge.png into --out (bridge.json: a deprecated copy of summary.json)."
        ),
    )
