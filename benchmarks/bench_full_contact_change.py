"""full_contact_sums before and after a change, alternated in one process.

``roughness/full_contact.py`` of a git revision is loaded beside the current one (it
imports the current ``_kernels``); both sum the multipliers of two rough surfaces, and of
one rough surface on a flat one, for every direction. First the results are compared
bit for bit (both engines, with and without dropping invalid contacts, gradients large
enough for invalid contacts); then the numba engine is timed on gradients small enough
for none (the kernel alone, no location of the worst contact): median over the rounds of
the process CPU time and the wall time per call.

Run: ``python benchmarks/bench_full_contact_change.py --before REV [--side 512]`` from a
git checkout (``REV`` e.g. ``main``); set NUMBA_NUM_THREADS=1 for one thread.
"""

from __future__ import annotations

import argparse
import importlib.util
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType

import numpy as np

from frictionlab.roughness import full_contact as after

FIELDS = ("sum_x", "sum_y", "kept", "invalid", "worst_station", "worst_family")


def _load_revision(rev: str) -> ModuleType:
    text = subprocess.run(
        ["git", "show", f"{rev}:src/frictionlab/roughness/full_contact.py"],
        check=True, capture_output=True, text=True,
    ).stdout  # fmt: skip
    path = Path(tempfile.mkdtemp()) / "full_contact_before.py"
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location("full_contact_before", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", required=True)
    parser.add_argument("--side", type=int, default=512, help="stations per axis")
    parser.add_argument("--rounds", type=int, default=8)
    args = parser.parse_args()
    before = _load_revision(args.before)
    rng = np.random.default_rng(3)
    n = args.side**2
    g = rng.standard_normal((4, n)) * 0.6
    beta = np.radians(np.linspace(0.0, 180.0, 19))
    cb, sb = np.cos(beta), np.sin(beta)
    cases = {"rough/rough": (g[:2], g[2:]), "rough/flat": (g[:2], np.zeros((2, n)))}
    for name, (g1, g2) in cases.items():
        for engine in ("numba", "numpy"):
            for drop in (False, True):
                a, b = (m.full_contact_sums(0.5, tuple(g1), tuple(g2), cb, sb, drop=drop,
                                            engine=engine) for m in (before, after))  # fmt: skip
                for f in FIELDS:
                    same = np.array_equal(getattr(a, f), getattr(b, f))
                    assert same, f"{name} {engine} drop={drop}: {f} differs"
        print(f"{name}: bit-equal (numba and numpy engines, drop off and on)")
    for name, (g1, g2) in cases.items():
        small1, small2 = tuple(0.2 * g1), tuple(0.2 * g2)  # no invalid contact
        times: dict[str, list[tuple[float, float]]] = {"before": [], "after": []}
        for _ in range(args.rounds):
            for label, module in (("before", before), ("after", after)):
                wall, cpu = time.perf_counter(), time.process_time()
                for _ in range(20):
                    module.full_contact_sums(0.5, small1, small2, cb, sb)
                times[label].append(
                    ((time.perf_counter() - wall) / 20e-3, (time.process_time() - cpu) / 20e-3)
                )
        for label, runs in times.items():
            w, c = np.median(np.array(runs), axis=0)
            print(f"{name:12s} {label:7s} median of {args.rounds}: wall {w:7.2f} ms, "
                  f"CPU {c:7.2f} ms per call ({n} stations, {beta.size} directions)")  # fmt: skip


if __name__ == "__main__":
    main()
