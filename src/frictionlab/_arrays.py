"""Small array helpers shared by the physics packages."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

__all__ = ["FloatArray", "readonly", "readonly_masked"]

#: A float64 NumPy array (the type of every physical array in the results).
FloatArray = NDArray[np.float64]


def readonly(values: ArrayLike, dtype: DTypeLike | None = np.float64) -> Any:
    """A read-only copy of ``values`` (as ``dtype``; ``dtype=None`` keeps the input's dtype).

    Results and parameters hand out such copies, so that neither the caller's arrays nor
    the object's own can be changed afterwards.
    """
    arr = np.array(values, dtype=dtype, copy=True)
    arr.setflags(write=False)
    return arr


def readonly_masked(values: ArrayLike, undefined: ArrayLike) -> np.ma.MaskedArray:
    """A read-only masked array of ``values``, masked where ``undefined`` is true.

    0.0 is stored under the mask (never NaN), so the data stay finite.
    """
    data = np.where(undefined, 0.0, values)
    out = np.ma.MaskedArray(data, mask=np.array(undefined, dtype=bool, copy=True))
    out.setflags(write=False)
    return out
