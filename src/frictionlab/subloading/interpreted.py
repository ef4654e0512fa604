"""The law's kernels run by the Python interpreter: the readable per-point definition.

:func:`load` executes the source of ``surfaces.py``, ``evolution.py`` and ``kernels.py``
once more, in one fresh namespace, with numba's decorators replaced by the identity and
``prange`` by ``range``: every function — ``_point`` and all the scalar helpers it
calls — is then plain Python with ``math`` semantics (the equivalent of
``NUMBA_DISABLE_JIT=1`` for these three modules, inside one process). It serves

* the tests, which check that the compiled kernels (serial and parallel, with and
  without the tangent) agree with this per-point definition on random inputs, and
* the benchmark, as one of its two per-point Python baselines (the other is a loop of
  one-point ``update()`` calls).

Slow by design (tens of microseconds per point); never used by the library itself.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path
from typing import Any

__all__ = ["load", "step_points"]

_MODULES = ("surfaces.py", "evolution.py", "kernels.py")


def _identity_decorator(*args: Any, **kwargs: Any) -> Any:
    """Stands for ``njit`` / ``njit(...)``: returns the function unchanged."""
    if len(args) == 1 and callable(args[0]) and not kwargs:
        return args[0]
    return lambda func: func


@functools.cache
def load() -> dict[str, Any]:
    """The namespace holding the interpreted kernels (built once per process)."""
    namespace: dict[str, Any] = {"__name__": "frictionlab.subloading._interpreted"}
    here = Path(__file__).parent
    for name in _MODULES:
        tree = ast.parse((here / name).read_text(), filename=name)
        body = []
        for node in tree.body:
            if isinstance(node, ast.ImportFrom) and (
                node.module in ("numba", "frictionlab._jit")
                or (node.module or "").startswith("frictionlab.subloading")
            ):
                continue  # numba's names are replaced below; sibling names share the namespace
            body.append(node)
        tree.body = body
        namespace["njit"] = _identity_decorator
        namespace["prange"] = range
        exec(compile(tree, str(here / name), "exec"), namespace)
    return namespace


def step_points(*args: Any) -> None:
    """The per-point reference loop :func:`kernels.step_points_by_point`, interpreted
    (the arguments of :func:`kernels.step_points`)."""
    load()["step_points_by_point"](*args)
