"""Both load models on SurfaceTopography's example files (docs/roughness.md's table).

Usage (the files are not part of frictionlab: take them from SurfaceTopography's
repository, test/file_format_examples/, into a folder of your own)::

    PYTHONPATH=src python benchmarks/bench_example_files.py FOLDER [--limit-s 120] [--out F]

Each file is read with ``periodicity = "assume"``, ``detrend = "height"``,
``fill_missing = true`` (SurfaceTopography's default channel), then, against a flat
counter-face with mu0 = 0.3 over 36 directions and ``on_invalid = "drop"``:

* elastic: ContactMechanics at the nominal pressure p = 0.025 E* h'_rms (about 5 % of
  contact by Persson's estimate), E* = 100 GPa;
* lattice: the spring load per spring that gives the same contact area (the offset c is
  the gap quantile at that area, closed form for a flat face: one time sample).

One JSON line per file: size, points, time per model, contact area, mu range, or the
refusal (the first line of the error message). A file is given ``--limit-s`` seconds.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import signal
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.roughness import elastic_polar, flat, friction_polar
from frictionlab.roughness.topography import read_prepared

BETAS = np.arange(0.0, 360.0, 10.0)
MU0 = 0.3
MODULUS = 1e11


class _Timeout(Exception):
    pass


def _alarm(signum: int, frame: Any) -> None:
    raise _Timeout


def _first_line(exc: BaseException) -> str:
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0] if text else ''}"


def run_file(path: Path, **read: Any) -> dict[str, Any]:
    row: dict[str, Any] = {"file": path.name, "bytes": path.stat().st_size}
    if read:
        row["options"] = read
    t0 = time.perf_counter()
    try:
        prepared = read_prepared(
            path, periodicity="assume", detrend="height", fill_missing=True, **read
        )
    except Exception as exc:  # the refusal is the result
        row["refusal"] = _first_line(exc)
        return row
    surface = prepared.surface
    row["points"] = prepared.info["points"]
    row["warnings"] = list(prepared.warnings)
    row["read_s"] = time.perf_counter() - t0
    slope = float(prepared.info["rms_slope"])
    if not slope > 0.0:
        row["refusal"] = "flat after preparation (rms slope 0)"
        return row
    pressure = 0.025 * MODULUS * slope
    t0 = time.perf_counter()
    try:
        el = elastic_polar(surface, flat(), MU0, BETAS, pressure=pressure, modulus=MODULUS,
                           on_invalid="drop")  # fmt: skip
        row["elastic"] = {
            "s": time.perf_counter() - t0,
            "area": el.contact_fraction_mean,
            "mu_min": float(np.nanmin(el.mu)),
            "mu_max": float(np.nanmax(el.mu)),
            "invalid": float(np.max(el.invalid_fraction)),
        }
        area = el.contact_fraction_mean
    except Exception as exc:
        row["elastic"] = {"s": time.perf_counter() - t0, "refusal": _first_line(exc)}
        area = 0.05
    heights = np.asarray(surface.heights, dtype=np.float64).ravel()
    gap = heights.max() - heights  # flat upper face: gap up to a constant
    c = float(np.quantile(gap, min(max(area, 1.0 / gap.size), 1.0)))
    load = float(np.mean(np.clip(c - gap, 0.0, None)))
    t0 = time.perf_counter()
    try:
        if load <= 0.0:
            raise ValueError("no load at that area")
        la = friction_polar(surface, flat(), MU0, BETAS, load=load, on_invalid="drop")
        row["lattice"] = {
            "s": time.perf_counter() - t0,
            "area": float(np.mean(la.contact_fraction_mean)),
            "mu_min": float(np.nanmin(la.mu)),
            "mu_max": float(np.nanmax(la.mu)),
            "invalid": float(np.max(la.invalid_fraction)),
        }
    except Exception as exc:
        row["lattice"] = {"s": time.perf_counter() - t0, "refusal": _first_line(exc)}
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--limit-s", type=float, default=120.0)
    parser.add_argument("--out", type=Path, default=None)
    parser.add_argument("--format", default=None, help="force a reader (e.g. xyz)")
    parser.add_argument("--resample", default=None, help="median, finest or points")
    parser.add_argument("files", nargs="*", help="only these names in FOLDER")
    args = parser.parse_intermixed_args()
    read: dict[str, Any] = {}
    if args.format:
        read["format"] = args.format
    if args.resample:
        read["resample"] = int(args.resample) if args.resample.isdigit() else args.resample
    files = sorted(p for p in args.folder.iterdir() if p.is_file())
    if args.files:
        files = [p for p in files if p.name in set(args.files)]
    files.sort(key=lambda p: p.stat().st_size)
    out = open(args.out, "a") if args.out else sys.stdout  # noqa: SIM115
    signal.signal(signal.SIGALRM, _alarm)
    print(json.dumps({"load": os.getloadavg(), "cpus": os.cpu_count()}), file=out, flush=True)
    for path in files:
        signal.alarm(math.ceil(args.limit_s))
        t0 = time.perf_counter()
        try:
            row = run_file(path, **read)
        except _Timeout:
            row = {"file": path.name, "bytes": path.stat().st_size,
                   "refusal": f"not finished in {args.limit_s:g} s"}  # fmt: skip
        finally:
            signal.alarm(0)
        row["total_s"] = time.perf_counter() - t0
        row["load"] = os.getloadavg()[0]
        print(json.dumps(row), file=out, flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
