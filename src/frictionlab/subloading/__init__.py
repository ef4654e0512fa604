"""The subloading-friction constitutive law (Hashiguchi & Ozaki 2008), pure physics.

Public API:

* :class:`SubloadingParams` — validated parameters (scalars or per point);
* :func:`initial_state`, :class:`ContactState` — the state of N contact points;
* :func:`update` -> :class:`StepResult` — one implicit increment for N points;
* :func:`rotate_frame`, :func:`global_traction`, :func:`local_increment` — objectivity;
* closed forms in :mod:`~frictionlab.subloading.evolution` and
  :mod:`~frictionlab.subloading.surfaces`.
"""

from frictionlab.subloading.evolution import (
    U_function,
    hold_recovery,
    plastic_slip_for_ratio,
    ratcheting_slip_per_cycle,
    ratio_closed_form,
    steady_size,
)
from frictionlab.subloading.params import SURFACES, SubloadingParams
from frictionlab.subloading.return_map import Status, StepResult, update
from frictionlab.subloading.state import (
    ContactState,
    check_normal_capacity,
    check_snap_back,
    global_traction,
    initial_state,
    local_increment,
    rotate_frame,
    snap_back_violations,
)
from frictionlab.subloading.surfaces import (
    friction_coefficient_on_yield,
    g_function,
    g_inverse,
    yield_function,
)

__all__ = [
    "SURFACES",
    "ContactState",
    "Status",
    "StepResult",
    "SubloadingParams",
    "U_function",
    "check_normal_capacity",
    "check_snap_back",
    "friction_coefficient_on_yield",
    "g_function",
    "g_inverse",
    "global_traction",
    "hold_recovery",
    "initial_state",
    "local_increment",
    "plastic_slip_for_ratio",
    "ratcheting_slip_per_cycle",
    "ratio_closed_form",
    "rotate_frame",
    "snap_back_violations",
    "steady_size",
    "update",
    "yield_function",
]
