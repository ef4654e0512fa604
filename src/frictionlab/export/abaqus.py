"""The files of ``frictionlab export abaqus``: one user-subroutine source, PROPS and STATEV.

:func:`props_vector` turns a law (:class:`~frictionlab.subloading.SubloadingParams`,
one set of values) into the 22 PROPS of ``uinter.c``; :data:`PROPS` and :data:`STATEV`
document them one by one (name, unit, meaning), :func:`write_files` writes the source,
the tables, the ``.inp`` fragments and a README into a folder. Pure text: no compiler is
needed to export.
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np

from frictionlab.errors import ParameterError
from frictionlab.export.c_core import CFLAGS, source
from frictionlab.subloading import SubloadingParams
from frictionlab.subloading.kernels import N_PARAMS
from frictionlab.subloading.return_map import (
    _FORM_CODES,
    _INTEG_CODES,
    _U_CODES,
    parameter_table,
)
from frictionlab.subloading.surfaces import SURFACE_CODES

__all__ = [
    "PROPS",
    "SOURCE_NAME",
    "STATEV",
    "props_from_row",
    "props_vector",
    "self_contained_source",
    "write_files",
]

#: Name of the single user-subroutine source written by the export.
SOURCE_NAME = "frictionlab_uinter.c"

_F_UNIT = "1 (cone) or Pa (closed surfaces)"
#: The 22 PROPS of uinter.c in order: (name, unit, meaning).
PROPS: tuple[tuple[str, str, str], ...] = (
    ("alpha_n", "Pa/m", "normal elastic contact modulus, Eq 16"),
    ("alpha_t", "Pa/m", "tangential elastic contact modulus, Eq 16"),
    ("F_s", _F_UNIT, "static size: mu_s for the cone, F_s for a closed surface, Eq 25"),
    ("F_k", _F_UNIT, "kinetic size: mu_k for the cone, F_k for a closed surface, Eq 25"),
    ("u", "1/m", "constant of U(R), Eq 28 or 30"),
    ("kappa", "F units per m", "softening rate with plastic slip, Eq 25"),
    ("xi", "F units per s", "recovery rate with time, Eq 25"),
    ("m", "1", "softening exponent, Eq 25"),
    ("n", "1", "recovery exponent, Eq 25"),
    ("beta_1", "1", "rotation vector, first tangential component (local direction 2)"),
    ("beta_2", "1", "rotation vector, second tangential component (local direction 3)"),
    ("A_1", "1", "axis factor along e*_1: C_1 (cone) or C_1 M (closed surfaces), Eq 83/95"),
    ("A_2", "1", "axis factor along e*_2: C_2 (cone) or C_2 M (closed surfaces)"),
    ("orthotropy_angle", "rad", "angle from local direction 2 to the principal axis e*_1"),
    ("surface", "code", "0 coulomb, 1 cam_clay, 2 modified_cam_clay, 3 tear, 4 parabola"),
    ("tear_k", "1", "exponent k of the tear family"),
    ("U_law", "code", "0 cot (Eq 28), 1 ln (Eq 30)"),
    ("F_integrator", "code", "0 exponential, 1 backward_euler"),
    ("recovery_form", "code", "0 one_minus: xi (1 - F/F_s)^n, 1 ratio: xi (F_s/F - 1)^n"),
    ("open_recovery", "code", "0 continue (F recovers while open), 1 frozen"),
    ("F_initial", _F_UNIT, "size F at the first call"),
    ("R_initial", "1", "ratio R at a first call that finds the contact closed"),
)

#: The 8 STATEV of uinter.c in order: (name, unit, meaning).
STATEV: tuple[tuple[str, str, str], ...] = (
    ("F", _F_UNIT, "size of the sliding-yield surface (mu for the cone)"),
    ("R", "1", "normal sliding-yield ratio, 0 <= R <= 1"),
    ("gap", "m", "opening of an open contact (0 when closed)"),
    ("plastic_slip", "m", "accumulated plastic slip, sum of |Delta u^p|"),
    ("status", "code", "last increment: 0 stick, 1 slip, 2 open (3 failed is never stored)"),
    ("iterations", "1", "Newton iterations of the last local solve"),
    ("plastic_work", "J/m^2", "accumulated plastic work, sum of f . Delta u^p"),
    ("initialised", "flag", "1 once the routine has set the initial state"),
)


def props_from_row(
    row: np.ndarray, params: SubloadingParams, F_initial: float, R_initial: float = 0.0
) -> np.ndarray:
    """The 22 PROPS from one row of the kernel's parameter table and the options."""
    props = np.empty(len(PROPS))
    props[:N_PARAMS] = row
    props[N_PARAMS:] = (
        SURFACE_CODES[params.surface],
        params.tear_k,
        _U_CODES[params.U_law],
        _INTEG_CODES[params.F_integrator],
        _FORM_CODES[params.recovery_form],
        1.0 if params.open_recovery == "frozen" else 0.0,
        F_initial,
        R_initial,
    )
    return props


def props_vector(
    params: SubloadingParams, F_initial: float | None = None, R_initial: float = 0.0
) -> np.ndarray:
    """The 22 PROPS of one law; refused (naming the key) when values differ per point."""
    table = parameter_table(params)
    cone = params.is_cone
    names = ["alpha_n", "alpha_t", "mu_s" if cone else "F_s", "mu_k" if cone else "F_k", "u",
             "kappa", "xi", "m", "n", "rotation", "rotation",
             *(["orthotropy"] * 2 if cone else ["orthotropy or M"] * 2),
             "orthotropy_angle"]  # fmt: skip
    for col in range(N_PARAMS):
        if np.any(table[:, col] != table[0, col]):
            raise ParameterError(
                f"law.{names[col]}",
                f"{table.shape[0]} values per point",
                "one value: an Abaqus interaction has one set of PROPS",
            )
    F0 = float(table[0, 2]) if F_initial is None else float(F_initial)
    return props_from_row(table[0], params, F0, R_initial)


def self_contained_source() -> str:
    """subloading.h, subloading.c and uinter.c in one file (what Abaqus compiles)."""
    parts = [
        "/* frictionlab_uinter.c -- written by `frictionlab export abaqus`: the C core of the\n"
        " * subloading-friction law and the Abaqus user interactions UINTER and VUINTER in one\n"
        f" * file. Compile with C99 and without fused multiply-adds ({' '.join(CFLAGS)}). */\n"
    ]
    for name in ("subloading.h", "subloading.c", "uinter.c"):
        text = source(name).replace('#include "subloading.h"\n', "")
        parts.append(f"/* ===== {name} ===== */\n{text}")
    return "\n".join(parts)


def _table(rows: tuple[tuple[str, str, str], ...], values: np.ndarray | None) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["position", "name", "value", "unit", "meaning"] if values is not None
                    else ["position", "name", "unit", "meaning"])  # fmt: skip
    for k, (name, unit, meaning) in enumerate(rows):
        value = [repr(float(values[k]))] if values is not None else []
        writer.writerow([k + 1, name, *value, unit, meaning])
    return buffer.getvalue()


def _data_lines(props: np.ndarray) -> str:
    """PROPS as .inp data lines: at most 8 values per line (full precision)."""
    values = [repr(float(v)) for v in props]
    return "\n".join(", ".join(values[i : i + 8]) for i in range(0, len(values), 8))


def inp_fragments(props: np.ndarray, name: str = "SUBLOADING") -> dict[str, str]:
    """``.inp`` blocks for Abaqus/Standard (UINTER) and Abaqus/Explicit (VUINTER)."""
    head = f"** frictionlab subloading-friction law: {len(PROPS)} PROPS, {len(STATEV)} STATEV\n"
    standard = (
        f"{head}*SURFACE INTERACTION, NAME={name}, USER, PROPERTIES={len(PROPS)}, "
        f"DEPVAR={len(STATEV)}, UNSYMM\n{_data_lines(props)}\n"
    )
    explicit = (
        f"{head}** penalty contact pair (VUINTER needs the penalty constraint)\n"
        f"*SURFACE INTERACTION, NAME={name}, USER, PROPERTIES={len(PROPS)}, "
        f"DEPVAR={len(STATEV)}\n{_data_lines(props)}\n"
    )
    return {"interaction_standard.inp": standard, "interaction_explicit.inp": explicit}


def _readme(props: np.ndarray, title: str) -> str:
    finite = all(math.isfinite(v) for v in props)
    return f"""# frictionlab: the subloading-friction law as an Abaqus user interaction

Written by `frictionlab export abaqus` from: {title}

Files
- `{SOURCE_NAME}`: the C core of the law (bit-identical to frictionlab's own kernel)
  and the user subroutines UINTER (Abaqus/Standard) and VUINTER (Abaqus/Explicit).
- `props.csv`: the {len(PROPS)} PROPS with their values, units and meaning, in order.
- `statev.csv`: the {len(STATEV)} solution-dependent state variables (DEPVAR), in order.
- `interaction_standard.inp`, `interaction_explicit.inp`: `*SURFACE INTERACTION` blocks
  with these PROPS; reference the interaction from your `*CONTACT PAIR`.

Run
    abaqus job=JOB input=JOB.inp user={SOURCE_NAME}

Abaqus compiles the C file with the compiler its installation is set up for. The numbers
are frictionlab's only with C99 semantics and without fused multiply-adds; with the Intel
compilers add `-fp-model precise` (Linux) or `/fp:precise` (Windows) to the C flags in
your `abaqus_v6.env`, and define `FL_FORTRAN_UPPER` on Windows, where Fortran names are
upper case without the trailing underscore.

Conventions (docs/fe-codes.md of frictionlab gives each with its source)
- local direction 1 is the contact normal, 2 and 3 the tangents; STRESS(1) is the
  normal traction, positive in compression; DRDISP(1) the increment of the overclosure;
- the law's rotation vector and orthotropy axes are fixed in the local tangent directions;
- a failed local solve keeps STRESS and STATEV, returns the elastic stiffness and sets
  PNEWDT = 0.25 (Abaqus/Standard then retries a quarter of the increment);
- DDSDDR is not symmetric in sliding: UNSYMM asks Abaqus/Standard to use it whole.
{"" if finite else "WARNING: some PROPS are not finite; Abaqus will refuse them." + chr(10)}"""


def write_files(out: Path, params: SubloadingParams, title: str, F_initial: float | None = None,
                R_initial: float = 0.0) -> list[Path]:  # fmt: skip
    """Write the export into the existing folder ``out``; returns the paths written."""
    props = props_vector(params, F_initial, R_initial)
    texts = {
        SOURCE_NAME: self_contained_source(),
        "props.csv": _table(PROPS, props),
        "statev.csv": _table(STATEV, None),
        **inp_fragments(props),
        "README.md": _readme(props, title),
    }
    paths = []
    for name, text in texts.items():
        path = out / name
        path.write_text(text, encoding="utf-8")
        paths.append(path)
    return paths
