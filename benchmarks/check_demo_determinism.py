"""Run demo sections three times and check that their files agree bit for bit.

    python benchmarks/check_demo_determinism.py OUT [--sections law,roughness,bridge]

The three runs, each in a fresh interpreter: (1) a cold compile (an empty numba cache)
on numba's default thread count; (2) that cache warm, on one thread
(``NUMBA_NUM_THREADS=1``); (3) warm, default threads, beside a busy process competing
for the cores. Runs 2 and 3 are compared with run 1 by ``compare_outputs.py`` with no
tolerance (numbers exact, other files byte for byte; the run's timings and provenance are
left out). Writes OUT/run1 .. OUT/run3 and OUT/cache; prints one line per difference
and exits 1 when any differs, else 0. Section groups: law, roughness, bridge, contact.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from compare_outputs import VOLATILE, compare_trees  # noqa: E402

GROUPS = {
    "law": "frictionlab.demo.law:LAW_SECTIONS",
    "roughness": "frictionlab.demo.roughness:ROUGHNESS_SECTIONS",
    "bridge": "frictionlab.demo.bridge:BRIDGE_SECTIONS",
    "contact": "frictionlab.demo.contact:CONTACT_SECTIONS",
}

RUN = """
import importlib, sys
from frictionlab.demo import run_demo
builders = []
for spec in sys.argv[2:]:
    module, name = spec.split(":")
    builders += list(getattr(importlib.import_module(module), name))
run_demo(sys.argv[1], builders)
"""


def _run(out: Path, sections: list[str], env: dict[str, str]) -> None:
    specs = [GROUPS[name] for name in sections]
    subprocess.run([sys.executable, "-c", RUN, str(out), *specs], env=env, check=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--sections", default="law,roughness,bridge",
                        help="comma-separated groups: " + ", ".join(GROUPS))  # fmt: skip
    args = parser.parse_args(argv)
    sections = args.sections.split(",")
    unknown = sorted(set(sections) - set(GROUPS))
    if unknown:
        parser.error(f"--sections: unknown {unknown}; allowed {sorted(GROUPS)}")
    dropped = ("NUMBA_CACHE_DIR", "NUMBA_NUM_THREADS")
    base = {k: v for k, v in os.environ.items() if k not in dropped}
    base["FRICTIONLAB_CACHE_DIR"] = str(args.out / "cache")
    _run(args.out / "run1", sections, base)
    _run(args.out / "run2", sections, {**base, "NUMBA_NUM_THREADS": "1"})
    busy = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        _run(args.out / "run3", sections, base)
    finally:
        busy.kill()
        busy.wait()
    differ = 0
    for run in ("run2", "run3"):
        found = compare_trees(args.out / "run1", args.out / run, 0.0, VOLATILE)
        found.pop("report.html", None)  # holds the section timings
        for rel, diffs in found.items():
            for d in diffs:
                print(f"{run}/{rel}: {d}")
        differ += len(found)
    print(f"{differ} file(s) differ from the cold single run")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
