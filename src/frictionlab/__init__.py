"""frictionlab: anisotropic friction.

Two published models and the bridge between them:

* the subloading-friction constitutive law of Hashiguchi & Ozaki (2008), in
  :mod:`frictionlab.subloading`;
* the lattice-spring roughness model (ALSFM / H-ALSFM) of Berardo & Pugno, in
  :mod:`frictionlab.roughness`.

``import frictionlab`` is cheap and has no side effect: the main entry points listed in
:data:`__all__` are loaded on first use (PEP 562), and numba (with its compile cache,
:mod:`frictionlab._compile_cache`) only when a kernel module is first imported.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from frictionlab._version import __version__
from frictionlab.errors import (
    ConvergenceError,
    FrictionlabError,
    InputError,
    ParameterError,
    ValidityError,
)

#: The curated top-level API: name -> the module that defines it (imported on first use).
_LAZY: dict[str, str] = {
    # the law
    "SubloadingParams": "frictionlab.subloading",
    "ContactState": "frictionlab.subloading",
    "StepResult": "frictionlab.subloading",
    "initial_state": "frictionlab.subloading",
    "update": "frictionlab.subloading",
    # loading programmes and the driver
    "InitialConditions": "frictionlab.driver",
    "Program": "frictionlab.driver",
    "Slide": "frictionlab.driver",
    "Hold": "frictionlab.driver",
    "Reverse": "frictionlab.driver",
    "Turn": "frictionlab.driver",
    "Cycle": "frictionlab.driver",
    "NormalStep": "frictionlab.driver",
    "Traction": "frictionlab.driver",
    "SpringSlider": "frictionlab.driver",
    "History": "frictionlab.driver",
    "simulate": "frictionlab.driver",
    "simulate_spring_slider": "frictionlab.driver",
    "DriverSettings": "frictionlab.driver",
    # scenario files
    "load_scenario": "frictionlab.io.scenario",
    "run_scenario": "frictionlab.app.simulate",
    # roughness, bridge, calibration, contact
    "LatticeSettings": "frictionlab.roughness",
    "FrictionPolar": "frictionlab.roughness",
    "friction_polar": "frictionlab.roughness",
    "read_surface": "frictionlab.roughness",
    "fit_anisotropy": "frictionlab.bridge",
    "fitted_law": "frictionlab.bridge",
    "Curve": "frictionlab.calibration",
    "fit_law": "frictionlab.calibration",
    "Block": "frictionlab.contact",
    "NormalLoad": "frictionlab.contact",
    "run_contact": "frictionlab.contact",
    "SolverSettings": "frictionlab.contact",
}

__all__ = [
    "Block",
    "ContactState",
    "ConvergenceError",
    "Curve",
    "Cycle",
    "DriverSettings",
    "FrictionPolar",
    "FrictionlabError",
    "History",
    "Hold",
    "InitialConditions",
    "InputError",
    "LatticeSettings",
    "NormalLoad",
    "NormalStep",
    "ParameterError",
    "Program",
    "Reverse",
    "Slide",
    "SolverSettings",
    "SpringSlider",
    "StepResult",
    "SubloadingParams",
    "Traction",
    "Turn",
    "ValidityError",
    "__version__",
    "fit_anisotropy",
    "fit_law",
    "fitted_law",
    "friction_polar",
    "initial_state",
    "load_scenario",
    "read_surface",
    "run_contact",
    "run_scenario",
    "simulate",
    "simulate_spring_slider",
    "update",
]

if TYPE_CHECKING:  # for type checkers and IDEs; at run time these come from __getattr__
    from frictionlab.app.simulate import run_scenario
    from frictionlab.bridge import fit_anisotropy, fitted_law
    from frictionlab.calibration import Curve, fit_law
    from frictionlab.contact import Block, NormalLoad, SolverSettings, run_contact
    from frictionlab.driver import (
        Cycle,
        DriverSettings,
        History,
        Hold,
        InitialConditions,
        NormalStep,
        Program,
        Reverse,
        Slide,
        SpringSlider,
        Traction,
        Turn,
        simulate,
        simulate_spring_slider,
    )
    from frictionlab.io.scenario import load_scenario
    from frictionlab.roughness import FrictionPolar, LatticeSettings, friction_polar, read_surface
    from frictionlab.subloading import (
        ContactState,
        StepResult,
        SubloadingParams,
        initial_state,
        update,
    )


#: Former top-level names (not in ``__all__``): their module warns on each use.
_DEPRECATED: dict[str, str] = {"TractionControl": "frictionlab.driver"}


def __getattr__(name: str) -> Any:
    """Import a top-level name's module on first use (PEP 562)."""
    if name in _DEPRECATED:
        return getattr(importlib.import_module(_DEPRECATED[name]), name)
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'frictionlab' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # later look-ups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
