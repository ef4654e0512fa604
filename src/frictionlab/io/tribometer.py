"""Reading a tribometer export: time, slip and friction ratio from a lab's CSV file.

Exports differ from lab to lab; :func:`read_tribometer` loads them with pandas and
accepts comment lines (``#``), an index column, extra columns, a units row right under
the header (``s``/``min``, ``m``/``mm``/``um``), and the lab's column names through a
mapping ``{"time": "Time", "slip": "Displacement", "friction_ratio": "COF"}``. Units
come from ``units = {time = "min", slip = "mm"}`` or, when not given, from the units
row; SI (s, m) otherwise. The slip column is optional (used for plots only).

Bad data are refused with one :class:`~frictionlab.errors.InputError` line naming the
file, the column and the sample: a missing or repeated column, a value that is not a
number, NaN or an empty cell, fewer than :data:`MIN_SAMPLES` samples, negative time,
time not strictly increasing, a negative friction ratio.
"""

from __future__ import annotations

import io
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from frictionlab.errors import InputError
from frictionlab.io.inputs import read_input_text

__all__ = [
    "MIN_SAMPLES",
    "SLIP_UNITS",
    "TIME_UNITS",
    "Measured",
    "read_tribometer",
]

#: Fewest samples a curve may have.
MIN_SAMPLES = 5
#: Time units -> seconds.
TIME_UNITS: dict[str, float] = {"s": 1.0, "min": 60.0}
#: Slip units -> metres.
SLIP_UNITS: dict[str, float] = {"m": 1.0, "mm": 1e-3, "um": 1e-6}
_ALIASES = {"sec": "s", "second": "s", "seconds": "s", "µm": "um", "μm": "um", "micron": "um"}
_ROLES = ("time", "slip", "friction_ratio")


@dataclass(frozen=True)
class Measured:
    """A loaded curve in SI units: time [s], friction ratio [-], slip [m] or None."""

    source: str
    time: np.ndarray
    friction_ratio: np.ndarray
    slip: np.ndarray | None
    units: dict[str, str]


def _unit_token(text: str) -> str:
    token = text.strip().strip("[]()").strip().lower()
    return _ALIASES.get(token, token)


def _numbers(where: str, name: str, cells: list[str], offset: int) -> np.ndarray:
    out = np.empty(len(cells))
    for i, cell in enumerate(cells):
        text = "" if cell is None else str(cell).strip()
        if text == "" or text.lower() == "nan":
            raise InputError(f"{where}: column '{name}' sample {i + 1 + offset} is empty or NaN")
        try:
            out[i] = float(text)
        except ValueError:
            raise InputError(
                f"{where}: column '{name}' sample {i + 1 + offset} = {text!r} is not a number"
            ) from None
        if not np.isfinite(out[i]):
            raise InputError(
                f"{where}: column '{name}' sample {i + 1 + offset} = {text} is not finite"
            )
    return out


def read_tribometer(
    path: str | os.PathLike[str],
    columns: Mapping[str, str] | None = None,
    units: Mapping[str, str] | None = None,
    where: str = "",
) -> Measured:
    """Load ``path``; ``columns`` maps roles (time, slip, friction_ratio) to the file's names.

    ``units`` gives ``time`` in ``s`` or ``min`` and ``slip`` in ``m``, ``mm`` or ``um``;
    ``where`` prefixes messages (e.g. ``"[[data]] #1.file 'run.csv'"``).
    """
    import pandas as pd

    p = Path(path)
    where = where or f"file '{p}'"
    mapping = {"time": "time", "slip": "slip", "friction_ratio": "friction_ratio"}
    mapping.update(columns or {})
    slip_required = bool(columns and "slip" in columns)
    if not p.exists() and not p.is_symlink():
        raise InputError(f"{where}: file not found")
    try:
        text = read_input_text(p)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    try:
        header = pd.read_csv(io.StringIO(text), comment="#", header=None, nrows=1, dtype=str)
        frame = pd.read_csv(
            io.StringIO(text), comment="#", dtype=str, skipinitialspace=True,
            keep_default_na=False,
        )  # fmt: skip
    except pd.errors.EmptyDataError:
        raise InputError(f"{where}: the file holds no table") from None
    except pd.errors.ParserError as exc:
        first = str(exc).strip().splitlines()[-1]
        raise InputError(f"{where}: not a readable CSV table ({first})") from None
    names = [str(v).strip() for v in header.iloc[0].tolist() if isinstance(v, str)]
    for role in _ROLES:
        name = mapping[role]
        count = names.count(name)
        if count > 1:
            raise InputError(f"{where}: column '{name}' ({role}) appears {count} times")
        if count == 0 and (role != "slip" or slip_required):
            raise InputError(
                f"{where}: missing column '{name}' for {role} (columns found: "
                f'{", ".join(n for n in names if n)}; map yours with columns = {{{role} = "..."}})'
            )
    frame.columns = [str(c).strip() for c in frame.columns]
    present = [r for r in _ROLES if mapping[r] in frame.columns]
    cells = {r: frame[mapping[r]].tolist() for r in present}
    # A units row directly under the header: its time cell is not a number.
    row_units: dict[str, str] = {}
    offset = 0
    if cells["time"] and not _is_number(cells["time"][0]):
        row_units = {r: _unit_token(str(cells[r][0])) for r in present}
        cells = {r: v[1:] for r, v in cells.items()}
        offset = 1
    chosen = _choose_units(where, mapping, units or {}, row_units)
    n = len(cells["time"])
    if n < MIN_SAMPLES:
        raise InputError(f"{where}: only {n} samples; at least {MIN_SAMPLES} are needed")
    t = _numbers(where, mapping["time"], cells["time"], offset) * TIME_UNITS[chosen["time"]]
    ratio = _numbers(where, mapping["friction_ratio"], cells["friction_ratio"], offset)
    slip = None
    if "slip" in present:
        slip = _numbers(where, mapping["slip"], cells["slip"], offset) * SLIP_UNITS[chosen["slip"]]
    if t[0] < 0:
        raise InputError(
            f"{where}: column '{mapping['time']}' sample {1 + offset} = {t[0]:g} s is negative"
        )
    steps = np.diff(t)
    if np.any(steps <= 0):
        i = int(np.flatnonzero(steps <= 0)[0])
        raise InputError(
            f"{where}: column '{mapping['time']}' is not strictly increasing at sample "
            f"{i + 2 + offset} ({t[i + 1]:g} s after {t[i]:g} s)"
        )
    if np.any(ratio < 0):
        i = int(np.flatnonzero(ratio < 0)[0])
        raise InputError(
            f"{where}: column '{mapping['friction_ratio']}' sample {i + 1 + offset} = "
            f"{ratio[i]:g} is negative (a friction ratio |f_t|/f_n is >= 0)"
        )
    return Measured(str(p), t, ratio, slip, chosen)


def _is_number(cell: object) -> bool:
    try:
        float(str(cell).strip())
    except ValueError:
        return False
    return True


def _choose_units(
    where: str, mapping: Mapping[str, str], given: Mapping[str, str], row: Mapping[str, str]
) -> dict[str, str]:
    """Units of time and slip: as given, else from the units row, else SI."""
    out = {}
    for role, table in (("time", TIME_UNITS), ("slip", SLIP_UNITS)):
        from_row = row.get(role, "")
        if role in given:
            unit = given[role]
            if from_row in table and from_row != unit:
                raise InputError(
                    f"{where}: units.{role} = '{unit}' but the file's units row says "
                    f"'{from_row}' for column '{mapping[role]}'"
                )
        elif from_row:
            if from_row not in table:
                raise InputError(
                    f"{where}: unknown unit '{from_row}' of column '{mapping[role]}' in the "
                    f"units row; give units.{role} = one of {', '.join(table)}"
                )
            unit = from_row
        else:
            unit = next(iter(table))
        out[role] = unit
    return out
