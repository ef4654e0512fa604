"""Mesh refinement: the global force-displacement curve converges (three meshes)."""

from __future__ import annotations

import numpy as np
from tests.contact.support import NORMAL, SLIDE, law, pmma_block

from frictionlab.contact import run_contact


def _curve(element_size: float) -> tuple[np.ndarray, np.ndarray]:
    history = run_contact(pmma_block(element_size=element_size), law(), NORMAL, SLIDE)
    assert history.success, history.message
    rows = history.stage > 0
    return history.top_displacement[rows], history.tangential_force[rows]


def test_the_global_friction_curve_converges_under_mesh_refinement() -> None:
    sizes = (0.0125, 0.00625, 0.003125)
    x_ref, q_ref = _curve(0.0015625)  # the reference: one more halving
    errors = []
    for h in sizes:
        x, q = _curve(h)
        # compare at the reference's load steps: a mesh whose Newton needs a step cut near
        # the peak (the law's response has kinks at the slip front) adds steps in between
        # but still passes through every reference displacement
        match = np.abs(x[:, None] - x_ref[None, :]) <= 1e-12 * np.max(np.abs(x_ref))
        assert np.all(match.sum(axis=0) == 1), "every reference load step is reached"
        q_at = q[np.argmax(match, axis=0)]
        errors.append(np.max(np.abs(q_at - q_ref)) / np.max(np.abs(q_ref)))
    assert errors[0] > errors[1] > errors[2], errors
    # and at a rate: each halving at least a third off the error
    assert errors[1] < 0.67 * errors[0] and errors[2] < 0.67 * errors[1], errors
