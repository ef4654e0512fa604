"""Exceptions of frictionlab.

Every error names the offending field, its value and the allowed range, so that a
user can fix the input without reading the code.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # numpy is imported when an error is made, not with frictionlab
    import numpy as np

__all__ = [
    "ConvergenceError",
    "FrictionlabError",
    "InputError",
    "ParameterError",
    "ValidityError",
]


class FrictionlabError(Exception):
    """Base class of all frictionlab errors."""


class ParameterError(FrictionlabError, ValueError):
    """A physical parameter or an argument is outside its allowed range.

    Parameters
    ----------
    field:
        Name of the parameter (e.g. ``"mu_k"``).
    value:
        The offending value.
    allowed:
        A human-readable description of the allowed range (e.g. ``"0 < mu_k <= mu_s"``).
    """

    def __init__(self, field: str, value: Any, allowed: str) -> None:
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{field} = {_short(value)} is invalid: allowed {allowed}")


class InputError(FrictionlabError):
    """Bad user input at the edge (configuration files, CLI arguments, data files)."""


class ValidityError(FrictionlabError, ValueError):
    """A model is used outside its domain of validity (e.g. mu0 >= cot(phi))."""


class ConvergenceError(FrictionlabError):
    """A local solve failed for some points.

    Attributes
    ----------
    mask:
        Boolean array (points,) that is True where the solve failed.
    result:
        The partial result (if any) whose failed points carry the status ``failed``.
    """

    def __init__(self, message: str, mask: np.ndarray, result: Any = None) -> None:
        import numpy as np

        self.mask = np.asarray(mask, dtype=bool)
        self.result = result
        n_failed = int(self.mask.sum())
        super().__init__(f"{message} ({n_failed} of {self.mask.size} points failed)")


def _short(value: Any) -> str:
    """Render a value compactly for an error message."""
    import numpy as np

    if isinstance(value, str):
        return repr(value)
    try:
        arr = np.asarray(value)
    except ValueError:  # a ragged nested list: no array; its text, cut to one short line
        text = str(value).replace("\n", "")
        return text if len(text) <= 80 else text[:77] + "..."
    if arr.ndim > 0 and arr.size > 6:
        return f"array(shape={arr.shape}, first={arr.ravel()[:3].tolist()}...)"
    # one line: a small 2-D array prints over several lines
    return str(value).replace("\n", "")
