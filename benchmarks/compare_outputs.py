"""Compare two output trees (e.g. two ``frictionlab demo --out`` folders) file by file.

    python benchmarks/compare_outputs.py OLD NEW [--rtol 0] [--ignore-key KEY ...]

Reports, per relative path: files only in one tree; CSV files whose columns or values
differ (numbers compared as floats, within ``--rtol``; the ``#`` comment lines as text);
JSON files whose values differ, ignoring the keys that change from run to run
(:data:`VOLATILE`: provenance, timings) and the folders the trees and the package live
in; other files (PNG, HTML, TOML) compared byte for byte. Exit 0 when nothing differs
beyond the byte-compared files, else 1. Each difference is one line.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import re
import sys
from pathlib import Path
from typing import Any

#: JSON keys whose values change from run to run (wall-clock timings, provenance).
VOLATILE = frozenset(
    {
        "provenance",
        "elapsed_seconds",
        "seconds",
        "seconds_check",
        "seconds_fit",
        "seconds_polar",
        "wall_time_s",
        "created_utc",
        "timestamp",
        "timings",
    }
)

#: Where a path names the installed package (differs between checkouts).
_PACKAGE = re.compile(r"[^\s\"',]*/frictionlab/(?=data/)")


def _normal(text: str, root: Path) -> str:
    text = text.replace(str(root), "<out>")
    return _PACKAGE.sub("<frictionlab>/", text)


def _number(cell: str) -> float | None:
    try:
        return float(cell)
    except ValueError:
        return None


def _same(a: str, b: str, rtol: float) -> bool:
    if a == b:
        return True
    x, y = _number(a), _number(b)
    if x is None or y is None:
        return False
    if math.isnan(x) and math.isnan(y):
        return True
    return abs(x - y) <= rtol * max(abs(x), abs(y))


def compare_csv(old: str, new: str, rtol: float) -> list[str]:
    """Differences between two CSV texts: comment lines, header, row count, cells."""

    def split(text: str) -> tuple[list[str], list[list[str]]]:
        lines = text.splitlines()
        comments = [line for line in lines if line.startswith("#")]
        body = "\n".join(line for line in lines if not line.startswith("#"))
        return comments, list(csv.reader(io.StringIO(body)))

    (c_old, r_old), (c_new, r_new) = split(old), split(new)
    out = []
    if c_old != c_new:
        out.append(f"comment lines differ: {c_old[:2]} -> {c_new[:2]}")
    if not r_old or not r_new or r_old[0] != r_new[0]:
        return [*out, f"columns differ: {r_old[:1]} -> {r_new[:1]}"]
    if len(r_old) != len(r_new):
        out.append(f"rows: {len(r_old) - 1} -> {len(r_new) - 1}")
    cells = 0
    first = ""
    for i, (a_row, b_row) in enumerate(zip(r_old[1:], r_new[1:], strict=False), start=1):
        for j, (a, b) in enumerate(zip(a_row, b_row, strict=False)):
            if not _same(a, b, rtol):
                cells += 1
                first = first or f"row {i} {r_old[0][j]}: {a} -> {b}"
    if cells:
        out.append(f"{cells} cell(s) differ, first {first}")
    return out


def compare_json(
    old: Any, new: Any, rtol: float, ignore: frozenset[str], where: str = ""
) -> list[str]:
    """Differences between two JSON values, ignoring the keys in ``ignore``."""
    if isinstance(old, dict) and isinstance(new, dict):
        out = []
        for key in sorted(set(old) | set(new)):
            if key in ignore:
                continue
            if key not in old or key not in new:
                side = "new" if key not in old else "old"
                out.append(f"{where}.{key}: only in {side}")
                continue
            out.extend(compare_json(old[key], new[key], rtol, ignore, f"{where}.{key}"))
        return out
    if isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            return [f"{where}: {len(old)} -> {len(new)} items ({old!r:.80} -> {new!r:.80})"]
        return [d for i, (a, b) in enumerate(zip(old, new, strict=True))
                for d in compare_json(a, b, rtol, ignore, f"{where}[{i}]")]  # fmt: skip
    if isinstance(old, float | int) and isinstance(new, float | int):
        same = _same(repr(old), repr(new), rtol) or old == new
        return [] if same else [f"{where}: {old!r} -> {new!r}"]
    return [] if old == new else [f"{where}: {old!r:.80} -> {new!r:.80}"]


def compare_trees(
    old: Path, new: Path, rtol: float = 0.0, ignore: frozenset[str] = VOLATILE
) -> dict[str, list[str]]:
    """Per relative path, the differences found (an empty dict: the trees agree)."""
    files_old = {p.relative_to(old).as_posix() for p in old.rglob("*") if p.is_file()}
    files_new = {p.relative_to(new).as_posix() for p in new.rglob("*") if p.is_file()}
    found: dict[str, list[str]] = {}
    for rel in sorted(files_old - files_new):
        found[rel] = ["only in OLD"]
    for rel in sorted(files_new - files_old):
        found[rel] = ["only in NEW"]
    for rel in sorted(files_old & files_new):
        a, b = old / rel, new / rel
        if a.suffix == ".csv":
            diffs = compare_csv(
                _normal(a.read_text("utf-8"), old), _normal(b.read_text("utf-8"), new), rtol
            )
        elif a.suffix == ".json":
            ja = json.loads(_normal(a.read_text("utf-8"), old))
            jb = json.loads(_normal(b.read_text("utf-8"), new))
            diffs = compare_json(ja, jb, rtol, ignore)
        else:
            diffs = [] if a.read_bytes() == b.read_bytes() else ["bytes differ"]
        if diffs:
            found[rel] = diffs
    return found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old", type=Path)
    parser.add_argument("new", type=Path)
    parser.add_argument("--rtol", type=float, default=0.0, help="relative tolerance of numbers")
    parser.add_argument("--ignore-key", action="append", default=[], help="JSON key to skip")
    args = parser.parse_args(argv)
    found = compare_trees(args.old, args.new, args.rtol, VOLATILE | set(args.ignore_key))
    data_diffs = 0
    for rel, diffs in found.items():
        for d in diffs:
            print(f"{rel}: {d}")
        data_diffs += diffs != ["bytes differ"]
    n = len({*args.old.rglob("*")}) if args.old.is_dir() else 0
    print(f"{len(found)} file(s) differ ({data_diffs} in data or file lists) of ~{n} paths")
    return 1 if data_diffs else 0


if __name__ == "__main__":
    sys.exit(main())
