"""pytest plugin: record every schema parse/load call of a test run (see compare_parsed.py).

    PARSE_RECORD=new.json PYTHONPATH=src:benchmarks pytest -p parse_recorder -m "not slow" tests/...

Only the outermost call is recorded (a load that parses is one record): the test, the
call and its canonical result (:func:`compare_parsed.canon`) or its error message.
"""

from __future__ import annotations

import functools
import importlib
import json
import os
from typing import Any

from compare_parsed import canon, normal

_CALLS: list[Any] = []
_TEST = ["<none>"]
_DEPTH = [0]
_WRAPPED = {
    "scenario": ("parse_scenario", "parse_law_table", "parse_initial_table",
                 "parse_program_tables", "load_scenario", "law_table"),
    "roughness": ("parse_roughness", "load_roughness"),
    "bridge": ("parse_bridge", "load_bridge"),
    "calibrate": ("parse_calibrate", "load_calibrate"),
    "contact": ("parse_contact", "load_contact"),
    "sweep": ("parse_sweep", "load_sweep"),
}  # fmt: skip


def _wrap(name: str, fn: Any) -> Any:
    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        if _DEPTH[0]:
            return fn(*args, **kwargs)
        _DEPTH[0] += 1
        try:
            out = fn(*args, **kwargs)
        except Exception as exc:
            _CALLS.append([_TEST[0], name, ["error", type(exc).__name__, normal(str(exc))]])
            raise
        finally:
            _DEPTH[0] -= 1
        _CALLS.append([_TEST[0], name, json.dumps(canon(out), default=str)])
        return out

    return wrapper


for _module, _names in _WRAPPED.items():
    _mod = importlib.import_module(f"frictionlab.schema.{_module}")
    for _name in _names:
        setattr(_mod, _name, _wrap(f"{_module}.{_name}", getattr(_mod, _name)))


def pytest_runtest_setup(item: Any) -> None:
    _TEST[0] = item.nodeid


def pytest_sessionfinish(session: Any) -> None:
    if path := os.environ.get("PARSE_RECORD"):
        with open(path, "w", encoding="utf-8") as fh:
            json.dump(_CALLS, fh)
