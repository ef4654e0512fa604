"""The one ``on_invalid`` vocabulary: what to do with contacts violating Eq 1.

``"error"`` stops with a :class:`~frictionlab.errors.ValidityError` naming the contact;
``"drop"`` leaves the offending contacts out (no load, no friction; their fraction is
reported); ``"mask"`` marks the direction (or hierarchy level) ``valid = False`` with
NaN coefficients. The same words mean the same in TOML, on the command line and in
Python.
"""

from __future__ import annotations

import warnings

from frictionlab.errors import ParameterError

__all__ = ["DEPRECATED_ON_INVALID", "ON_INVALID", "check_on_invalid"]

ON_INVALID = ("error", "drop", "mask")
#: Old Python spellings, accepted for one release with a DeprecationWarning.
DEPRECATED_ON_INVALID = {"raise": "error"}


def check_on_invalid(
    value: object, allowed: tuple[str, ...] = ON_INVALID, *, stacklevel: int = 4
) -> str:
    """``value`` as one of ``allowed``; an old spelling warns and gives the new one.

    ``stacklevel`` 4 points the warning at the caller of a dataclass or of a function that
    checks its options in a helper.
    """
    if isinstance(value, str) and value in DEPRECATED_ON_INVALID:
        new = DEPRECATED_ON_INVALID[value]
        warnings.warn(
            f'on_invalid="{value}" is deprecated: write "{new}" (the same meaning)',
            DeprecationWarning,
            stacklevel=stacklevel,
        )
        return new
    if value not in allowed:
        raise ParameterError("on_invalid", value, f"one of {allowed}")
    return str(value)
