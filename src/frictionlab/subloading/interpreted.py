"""The law's kernels run by the Python interpreter: the readable per-point definition.

:func:`load` executes the source of ``surfaces.py``, ``evolution.py`` and ``kernels.py``
once more without numba (:func:`frictionlab._interpret.interpret`, the mechanism
shared with the lattice's :mod:`frictionlab.roughness.interpreted`): every function —
``_point`` and all the scalar helpers it calls — is then plain Python with ``math``
semantics (the equivalent of ``NUMBA_DISABLE_JIT=1`` for these three modules, inside one
process). It serves

* the tests, which check that the compiled kernels (serial and parallel, with and
  without the tangent) agree with this per-point definition on random inputs, and
* the benchmark, as one of its two per-point Python baselines (the other is a loop of
  one-point ``update()`` calls).

Slow by design (tens of microseconds per point); never used by the library itself.
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

from frictionlab._interpret import interpret

__all__ = ["load", "step_points"]

_MODULES = ("surfaces.py", "evolution.py", "kernels.py")


@functools.cache
def load() -> dict[str, Any]:
    """The namespace holding the interpreted kernels (built once per process)."""
    return interpret(Path(__file__).parent, _MODULES, "frictionlab.subloading")


def step_points(*args: Any) -> None:
    """The serial :func:`kernels.step_points` loop, interpreted (same arguments)."""
    load()["step_points"](*args)
