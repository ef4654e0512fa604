"""Small array helpers shared by the physics packages."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from frictionlab.errors import ParameterError

__all__ = ["FloatArray", "finite_vector", "readonly", "readonly_masked"]

#: A float64 NumPy array (the type of every physical array in the results).
FloatArray = NDArray[np.float64]


def finite_vector(
    name: str, values: Any, allowed: str, *, minimum: float | None = None, empty: bool = False
) -> FloatArray:
    """``values`` (a number or a sequence) as a 1-D float64 array of finite numbers.

    The one check of directions, loads and times given as lists: ParameterError naming
    ``name`` with ``allowed`` (what the caller accepts, e.g. "a non-empty 1-D array of
    finite degrees") when ``values`` is not numeric, not 1-D, empty (unless ``empty``),
    not finite or below ``minimum``.
    """
    try:
        arr = np.array(values, dtype=np.float64, ndmin=1)
    except (TypeError, ValueError):
        raise ParameterError(name, values, allowed) from None
    if (
        arr.ndim != 1
        or (arr.size == 0 and not empty)
        or not np.all(np.isfinite(arr))
        or (minimum is not None and np.any(arr < minimum))
    ):
        raise ParameterError(name, values, allowed)
    return arr


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
