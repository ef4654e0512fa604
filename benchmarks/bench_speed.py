"""The speed figures of ``frictionlab bench``; writes benchmarks/results/speed.json.

Run: ``python benchmarks/bench_speed.py [--points N] [--lattice-size N]``.
"""

from __future__ import annotations

import sys
from pathlib import Path

from frictionlab.cli import main

if __name__ == "__main__":
    out = Path(__file__).parent / "results"
    out.mkdir(exist_ok=True)
    raise SystemExit(main(["bench", "--json", str(out / "speed.json"), *sys.argv[1:]]))
