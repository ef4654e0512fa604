"""The lattice's numba kernels run by the Python interpreter (tests and benchmarks).

:func:`load` executes ``_kernels.py`` and ``full_contact.py`` once more without numba
(:func:`frictionlab._interpret.interpret`, the mechanism of
:mod:`frictionlab.subloading.interpreted`): ``sample_nb``, ``solve_offset_nb``,
``multipliers_nb``, ``_sums`` ... are then plain Python on NumPy arrays. The tests check
that the compiled kernels agree with this reading of their own source; the
``engine="numpy"`` twins (``*_np``) are a different, independent algorithm (the load
balance by sorting) offered to users. Slow by design; never used by the library itself.
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

from frictionlab._interpret import interpret

__all__ = ["load"]

_MODULES = ("_kernels.py", "full_contact.py")


@functools.cache
def load() -> dict[str, Any]:
    """The namespace holding the interpreted lattice kernels (built once per process)."""
    return interpret(Path(__file__).parent, _MODULES, "frictionlab.roughness")
