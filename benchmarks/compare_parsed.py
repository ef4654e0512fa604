"""Compare the parsed input objects of two checkouts (behaviour of the schema parsers).

    PYTHONPATH=/work/main/src python benchmarks/compare_parsed.py dump old.json
    PYTHONPATH=src python benchmarks/compare_parsed.py dump new.json
    python benchmarks/compare_parsed.py compare old.json new.json

``dump`` parses every bundled input file (``frictionlab/data/**/*.toml`` and the starters
of ``frictionlab example --write``) with its ``load_<input>`` and writes a canonical form
of the result: dataclasses field by field, floats as hex (bit for bit), arrays as dtype,
shape and a sha1 of their bytes, errors as their class and message. ``records`` compares
two files written by the pytest plugin ``benchmarks/parse_recorder.py`` (every parse and
load call of a test run, with its result or error message). Exit 1 when anything differs.
"""

from __future__ import annotations

import dataclasses
import enum
import hashlib
import json
import re
import shutil
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path, PurePath
from typing import Any

import numpy as np

#: Paths that differ between checkouts and runs (package folder, temporary folders,
#: hashes of files a test writes with a time stamp inside).
_VOLATILE = (
    (re.compile(r"/[^\s\"',]*/src[^\s\"',/]*/frictionlab/"), "<pkg>/"),
    (re.compile(r"/tmp/pytest-of-[^/]+/pytest-\d+/"), "<tmp>/"),
    (re.compile(r"/tmp/(?:frictionlab-sweep-|tmp)\w+"), "<rnd>"),
    (re.compile(r"\b[0-9a-f]{64}\b"), "<sha256>"),
)


def normal(text: str) -> str:
    """``text`` with the volatile parts replaced."""
    for pattern, repl in _VOLATILE:
        text = pattern.sub(repl, text)
    return text


def canon(x: Any, depth: int = 0) -> Any:
    """A JSON-able canonical form of ``x`` (equal exactly when ``x`` is the same)."""
    if depth > 40:
        return "<deep>"
    if x is None or isinstance(x, bool | int):
        return x
    if isinstance(x, str):
        return normal(x)
    if isinstance(x, float):
        return ["f", x.hex()]
    if isinstance(x, np.generic):
        return ["np", type(x).__name__, canon(x.item())]
    if isinstance(x, np.ma.MaskedArray):
        return ["ma", canon(np.ma.getdata(x)), canon(np.ma.getmaskarray(x))]
    if isinstance(x, np.ndarray):
        if x.dtype == object:
            return ["ndo", list(x.shape), [canon(v, depth + 1) for v in x.ravel().tolist()]]
        digest = hashlib.sha1(np.ascontiguousarray(x).tobytes()).hexdigest()
        return ["nd", x.dtype.str, list(x.shape), x.flags.writeable, digest]
    if isinstance(x, enum.Enum):
        return ["enum", type(x).__name__, x.name]
    if isinstance(x, PurePath):
        return ["path", normal(str(x))]
    if isinstance(x, dict):
        return ["dict", [[canon(k), canon(v, depth + 1)] for k, v in x.items()]]
    if isinstance(x, list | tuple | set | frozenset):
        items = sorted(x, key=repr) if isinstance(x, set | frozenset) else x
        return [type(x).__name__, [canon(v, depth + 1) for v in items]]
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        fields = [[f.name, canon(getattr(x, f.name), depth + 1)] for f in dataclasses.fields(x)]
        return ["dc", type(x).__name__, fields]
    if callable(x) and hasattr(x, "__qualname__"):
        return ["fn", x.__qualname__]
    if hasattr(x, "__dict__"):
        return ["obj", type(x).__name__, canon(dict(vars(x)), depth + 1)]
    return ["repr", normal(repr(x))]


def dump(out: str) -> None:
    """Parse every bundled input file; write their canonical forms to ``out``."""
    import frictionlab
    from frictionlab.schema import bridge, calibrate, contact, roughness, scenario, sweep

    data = Path(frictionlab.__file__).parent / "data"
    by_folder = {"scenarios": scenario.load_scenario, "contact": contact.load_contact,
                 "bridge": bridge.load_bridge}  # fmt: skip
    by_name = {"roughness": roughness.load_roughness, "measured-file": roughness.load_roughness,
               "calibrate": calibrate.load_calibrate, "simulate": scenario.load_scenario,
               "slide-hold-slide": scenario.load_scenario,
               "slide_hold_slide_base": scenario.load_scenario}  # fmt: skip
    written = Path(tempfile.mkdtemp())
    for name in ("simulate", "slide-hold-slide", "roughness", "calibrate", "measured-file"):
        command = [sys.executable, "-m", "frictionlab", "example", name, "--write", str(written)]
        subprocess.run(command, check=True, capture_output=True)
    result = {}
    for path in [*sorted(data.rglob("*.toml")), *sorted(written.glob("*.toml"))]:
        load = by_name.get(path.stem) or by_folder.get(path.parent.name) or sweep.load_sweep
        key = str(path.relative_to(data)) if path.is_relative_to(data) else f"written/{path.name}"
        try:
            result[key] = [load.__name__, canon(load(path))]
        except Exception as exc:  # the error is part of the behaviour
            result[key] = ["error", type(exc).__name__, normal(str(exc))]
    shutil.rmtree(written)
    Path(out).write_text(json.dumps(result, default=str))
    print(f"{len(result)} files parsed ({sum(v[0] == 'error' for v in result.values())} errors)")


def compare(old: str, new: str) -> int:
    """Say which bundled files parse differently; 1 if any."""
    a, b = (json.loads(Path(p).read_text()) for p in (old, new))
    differ = sorted(k for k in a.keys() | b.keys() if a.get(k) != b.get(k))
    for key in differ:
        print(f"differs: {key}")
    print(f"{len(a)} vs {len(b)} files, {len(differ)} differ")
    return 1 if differ else 0


def records(old: str, new: str) -> int:
    """Compare two parse_recorder files test by test (the results in call order)."""
    runs = []
    for p in (old, new):
        by_test: dict[str, list[Any]] = defaultdict(list)
        for test, _, result in json.loads(normal(Path(p).read_text())):
            by_test[test].append(result)
        runs.append(by_test)
    a, b = runs
    differ = sorted(t for t in a.keys() | b.keys() if a.get(t) != b.get(t))
    for test in differ:
        print(f"differs: {test} ({len(a.get(test, []))} vs {len(b.get(test, []))} calls)")
    errors = sum(isinstance(r, list) for calls in a.values() for r in calls)
    calls = sum(len(c) for c in a.values())
    print(f"{calls} calls ({errors} errors) in {len(a)} tests; {len(differ)} tests differ")
    return 1 if differ else 0


if __name__ == "__main__":
    mode, *paths = sys.argv[1:]
    if mode == "dump":
        dump(*paths)
    else:
        sys.exit({"compare": compare, "records": records}[mode](*paths))
