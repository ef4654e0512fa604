"""``frictionlab example NAME``: print a commented starter scenario that runs as printed.

The starters live in ``frictionlab/data/examples/NAME.toml``. ``--write DIR`` writes the
file (and the data file it reads, for ``measured-file``) into ``DIR`` instead.
"""

from __future__ import annotations

import argparse
import difflib
from importlib import resources
from pathlib import Path

from frictionlab.errors import InputError

HELP = (
    "print a commented starter scenario (simulate, slide-hold-slide, calibrate, roughness, "
    "measured-file)"
)

#: Starter name -> (one-line description, data files it reads from frictionlab/data).
EXAMPLES: dict[str, tuple[str, tuple[str, ...]]] = {
    "simulate": ("monotonic sliding of a contact at 1 MPa (frictionlab simulate)", ()),
    "slide-hold-slide": ("healing: slide, hold, slide again (frictionlab simulate)", ()),
    "roughness": ("friction of a rough surface pair vs direction (frictionlab roughness)", ()),
    "calibrate": (
        "fit the law to a slide-hold-slide export (frictionlab calibrate; writes its data)",
        ("examples/calibration/shs_run12.csv",),
    ),
    "measured-file": (
        "a measured topography file on a flat face (frictionlab roughness)",
        ("topography/ground_demo.x3p",),
    ),
}


def add_parser(sub: argparse._SubParsersAction) -> None:
    lines = "\n".join(f"  {name:<18} {text}" for name, (text, _) in EXAMPLES.items())
    parser = sub.add_parser(
        "example",
        help=HELP,
        description=HELP + ". Save it, edit it, run it with the command in its first lines.",
        epilog=f"starters:\n{lines}\n\nexample: frictionlab example simulate > my.toml",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("name", nargs="?", help="which starter (omit to list them)")
    parser.add_argument(
        "--write",
        type=Path,
        metavar="DIR",
        help="write NAME.toml (and any data file it reads) into DIR instead of printing",
    )
    parser.set_defaults(handler=run)


def starter_text(name: str) -> str:
    """The text of starter ``name`` (InputError naming the nearest one when unknown)."""
    if name not in EXAMPLES:
        near = difflib.get_close_matches(name, list(EXAMPLES), n=1)
        hint = f" (did you mean '{near[0]}'?)" if near else ""
        raise InputError(f"example '{name}' is unknown{hint}; allowed: {', '.join(EXAMPLES)}")
    return (resources.files("frictionlab") / "data" / "examples" / f"{name}.toml").read_text(
        encoding="utf-8"
    )


def run(args: argparse.Namespace) -> int:
    from frictionlab.io.atomic import write_bytes_atomic, write_text_atomic

    if args.name is None:
        for name, (text, _) in EXAMPLES.items():
            print(f"{name:<18} {text}")
        return 0
    text = starter_text(args.name)
    if args.write is None:
        print(text, end="")
        return 0
    out: Path = args.write
    if out.exists() and not out.is_dir():
        raise InputError(f"--write {out} exists and is not a directory")
    written = [write_text_atomic(out / f"{args.name}.toml", text)]
    for data in EXAMPLES[args.name][1]:
        source = resources.files("frictionlab") / "data" / data
        written.append(write_bytes_atomic(out / Path(data).name, source.read_bytes()))
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
