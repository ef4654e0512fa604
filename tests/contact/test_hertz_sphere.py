"""3-D Hertz: a rigid sphere pressed into an elastic block (frictionless).

Hertz (rigid sphere of radius R on an elastic half-space, E* = E/(1 - nu^2)): contact
radius a = (3 P R / (4 E*))^(1/3), pressure p(r) = p0 sqrt(1 - r^2/a^2) with
p0 = 3 P / (2 pi a^2). Frictionless, so exact for any nu (no Dundurs coupling).

The documented mesh (docs/contact.md): a quarter model (symmetry planes x = 0 and
y = 0 through the apex: u_x = 0 and u_y = 0 there) of an 8a x 8a x 4a block, hexahedra
of a/6 over r, z <= 1.25 a graded by 2 to 2a: 11 x 11 x 11 = 1331 hexahedra.
The radius is measured from the pressure's second moment, which for the Hertz
distribution is int p r^2 dA / int p dA = (2/5) a^2: it uses every contact point and
not only the element that holds the edge.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from frictionlab.contact import Block, Hold, NormalLoad, discretise, run_contact
from frictionlab.contact.block import Refinement
from frictionlab.contact.frictionless import Frictionless
from frictionlab.contact.shapes import Base

pytestmark = pytest.mark.slow  # ~5 CPU s: a 3-D mesh of 1331 hexahedra

E, NU, R, A = 1.0e9, 0.3, 0.05, 1.0e-3
E_STAR = E / (1.0 - NU**2)
P = 4.0 * E_STAR * A**3 / (3.0 * R)  # N: the load that gives a = A
P0 = 3.0 * P / (2.0 * np.pi * A**2)
TOLERANCE = 0.02


def test_sphere_contact_radius_and_peak_pressure() -> None:
    block = Block(
        E=E, nu=NU, width=4 * A, depth=4 * A, height=4 * A, element_size=2 * A, element="hex",
        refinement=Refinement(size=A / 6, extent=1.25 * A, center=(0.0, 0.0), growth=2.0),
    )  # fmt: skip
    assert block.cells == (11, 11, 11)
    disc = discretise(block)
    x, y = disc.nodes[0], disc.nodes[1]
    symmetry = np.concatenate([disc.dofs[0][np.isclose(x, 0.0)], disc.dofs[1][np.isclose(y, 0.0)]])
    disc = dataclasses.replace(disc, fixed_dofs=np.unique(symmetry))
    history = run_contact(
        block, Frictionless(alpha_n=1.0e15), NormalLoad(force=P / 4, steps=8),
        [Hold(duration=1.0, steps=1)], discretisation=disc,
        base=Base(shape="sphere", radius=R, center=(0.0, 0.0)),
    )  # fmt: skip
    assert history.success, history.message
    k = int(np.flatnonzero(history.stage == 0)[-1])  # the end of the normal stage
    p, w = history.traction_n[k], history.weight
    r = np.hypot(history.x, history.y)
    assert 4 * np.sum(w * p) == pytest.approx(P, rel=1e-9)  # equilibrium of the quarter
    a = np.sqrt(2.5 * np.sum(w * p * r**2) / np.sum(w * p))
    assert a == pytest.approx(A, rel=TOLERANCE)
    assert r[np.argmax(p)] < A / 6  # the peak at the apex
    assert p.max() == pytest.approx(P0, rel=TOLERANCE)
    assert np.all(p[r > 1.2 * A] == 0.0)  # open beyond the contact
