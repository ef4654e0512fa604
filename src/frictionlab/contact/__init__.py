"""The subloading-friction law inside a finite-element contact model (scikit-fem).

A 2-D plane-strain linear-elastic block on a rigid base, with the law at the Gauss
points of the bottom edge, pressed by a normal load and then driven by a tangential
programme (slide, hold, reverse, or traction control), solved by an implicit Newton
method with the law's consistent tangent and adaptive load steps.

Needs the optional extra ``fem`` (scikit-fem); importing this package does not import
it, the first mesh does (with a one-line message when it is missing).

Public API: :class:`Block`, :class:`NormalLoad`, :class:`Slide`, :class:`Reverse`,
:class:`Hold`, :class:`Traction`, :class:`SolverOptions`, :func:`run_contact` ->
:class:`ContactHistory`, :func:`slip_front`, :func:`front_arrival`, :func:`discretise`.
"""

from frictionlab.contact.block import ELEMENTS, Block
from frictionlab.contact.history import ContactHistory, front_arrival, slip_front
from frictionlab.contact.interface import TANGENTS
from frictionlab.contact.loading import Hold, NormalLoad, Reverse, Slide, Traction
from frictionlab.contact.mesh import Discretisation, discretise
from frictionlab.contact.solver import DRIVES, SolverOptions, SolverSettings, run_contact

__all__ = [
    "DRIVES",
    "ELEMENTS",
    "TANGENTS",
    "Block",
    "ContactHistory",
    "Discretisation",
    "Hold",
    "NormalLoad",
    "Reverse",
    "Slide",
    "SolverOptions",
    "SolverSettings",
    "Traction",
    "discretise",
    "front_arrival",
    "run_contact",
    "slip_front",
]
