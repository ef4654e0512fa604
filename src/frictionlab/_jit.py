"""numba for frictionlab's kernels, with the compile cache set up first.

Every module with compiled kernels imports numba through here (``from frictionlab._jit
import njit``), never directly: the first such import points numba's cache at
frictionlab's per-user directory (:func:`frictionlab._compile_cache.configure`) before
any ``@njit(cache=True)`` function is defined. ``import frictionlab`` alone imports
neither numba nor this module.
"""

from __future__ import annotations

from frictionlab._compile_cache import configure

configure()

import numba  # noqa: E402
from numba import njit, prange  # noqa: E402

__all__ = ["njit", "numba", "prange"]
