"""numba kernels run by the Python interpreter: the one reference mechanism for every kernel.

:func:`interpret` executes the source of some modules of one package once more, in one
fresh namespace, with numba's decorators replaced by the identity and ``prange`` by
``range`` (whether the module writes ``@njit`` or ``@numba.njit``): every function is
then plain Python with ``math`` and NumPy semantics, the equivalent of
``NUMBA_DISABLE_JIT=1`` for those modules inside one process. Imports from numba, from
:mod:`frictionlab._jit` and from the package itself are dropped (the listed modules share
the namespace, so each must be listed after those it uses). Used by
:mod:`frictionlab.subloading.interpreted` and :mod:`frictionlab.roughness.interpreted`
(tests and benchmarks; slow by design).
"""

from __future__ import annotations

import ast
import sys
import types
from collections.abc import Sequence
from pathlib import Path
from typing import Any

__all__ = ["interpret"]


def _identity_decorator(*args: Any, **kwargs: Any) -> Any:
    """Stands for ``njit`` / ``njit(...)``: returns the function unchanged."""
    if len(args) == 1 and callable(args[0]) and not kwargs:
        return args[0]
    return lambda func: func


#: Stands for the ``numba`` module inside interpreted sources.
_NUMBA = types.SimpleNamespace(njit=_identity_decorator, prange=range)


def interpret(folder: Path, modules: Sequence[str], package: str) -> dict[str, Any]:
    """The namespace of ``modules`` (file names in ``folder``, the package ``package``)
    executed in order without numba."""
    module = types.ModuleType(f"{package}._interpreted")
    sys.modules[module.__name__] = module  # dataclasses look their module up
    namespace = module.__dict__
    namespace.update(numba=_NUMBA, njit=_identity_decorator, prange=range)
    for name in modules:
        tree = ast.parse((folder / name).read_text(), filename=name)
        tree.body = [
            node
            for node in tree.body
            if not (
                isinstance(node, ast.ImportFrom)
                and (
                    node.module in ("numba", "frictionlab._jit")
                    or (node.module or "").startswith(package + ".")
                )
            )
        ]
        exec(compile(tree, str(folder / name), "exec"), namespace)
    return namespace
