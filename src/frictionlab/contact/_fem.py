"""Lazy access to scikit-fem, the optional finite-element assembler (extra ``fem``)."""

from __future__ import annotations

from types import ModuleType

from frictionlab.errors import InputError

__all__ = ["require_skfem"]

INSTALL_HINT = 'pip install "frictionlab[fem]"  (or: pip install scikit-fem)'


def require_skfem() -> ModuleType:
    """Import :mod:`skfem`, or raise one clear :class:`InputError` line when it is missing."""
    try:
        import skfem
    except ImportError:
        raise InputError(
            f"the contact model needs scikit-fem, which is not installed: {INSTALL_HINT}"
        ) from None
    return skfem
