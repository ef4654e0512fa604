"""The law kernel stays readable: short functions, results read by name (issue 21 item 5)."""

from __future__ import annotations

import ast
from pathlib import Path

import frictionlab.subloading.kernels as kernels

TREE = ast.parse(Path(kernels.__file__).read_text())


def test_no_function_of_the_kernel_is_longer_than_100_lines() -> None:
    lengths = {n.name: n.end_lineno - n.lineno + 1 for n in ast.walk(TREE)
               if isinstance(n, ast.FunctionDef) and n.end_lineno is not None}  # fmt: skip
    assert max(lengths.values()) <= 100, sorted(lengths.items(), key=lambda kv: -kv[1])[:3]


def test_no_result_is_read_by_position() -> None:
    """A call's result is never indexed or sliced (res[13], f(...)[:2]); arrays are indexed
    by name-bound indices only (P[row, P_ANGLE], out[i, 0])."""
    arrays = {"dt_arr"}  # the loops' one array read with a literal index (shared dt)
    bad = []
    for node in ast.walk(TREE):
        if not isinstance(node, ast.Subscript):
            continue
        by_call = isinstance(node.value, ast.Call)
        literal = isinstance(node.slice, ast.Constant) and isinstance(node.value, ast.Name)
        if by_call or (literal and node.value.id not in arrays):
            bad.append(ast.unparse(node))
    assert not bad, bad
