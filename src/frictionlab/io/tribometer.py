"""Reading a tribometer export as labs write it: time, slip and friction from a text table.

:func:`read_tribometer` accepts:

* encodings by byte-order mark (UTF-8, UTF-16), else UTF-16 recognised by its NUL bytes
  (an export written without a BOM), else UTF-8, else cp1252 (Windows "latin-1");
  ``encoding`` forces one;
* the delimiter (tab, ``;``, ``,``, ``|``) sniffed from the data lines, a decimal comma
  sniffed where the delimiter is not a comma (``sep`` and ``decimal`` force them);
* free-text metadata lines before the header (skipped) and ``#`` comment lines;
* units in the column titles (``Time (min)``, ``time [s]``, ``Displacement/mm``,
  ``Friction force in N``), in a units row right under the header, or in ``units``;
  two sources that disagree are an error. Units are read by pint;
* the friction ratio as a column, or as ``friction_force`` / ``normal_force``;
* reciprocating tests (``reciprocating``): the friction ratio changes sign with each
  stroke; its magnitude is used and each sample's stroke is counted.

Columns are found by role (time, slip, friction_ratio, friction_force, normal_force):
by the name mapped in ``columns`` or, by default, a title whose name (its unit removed)
is the role or a usual synonym (``COF``, ``Displacement``, ``Normal load``...), case and
``_``/space ignored. The slip is optional (plots only).

Bad data are refused with one :class:`~frictionlab.errors.InputError` line naming the
file and the line and/or column.
"""

from __future__ import annotations

import codecs
import csv
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from frictionlab.errors import InputError
from frictionlab.io.inputs import read_input_bytes
from frictionlab.io.unit_factors import si_factor

__all__ = [
    "MIN_SAMPLES",
    "ROLES",
    "SLIP_UNITS",
    "TIME_UNITS",
    "Measured",
    "read_tribometer",
]

#: Fewest samples a curve may have.
MIN_SAMPLES = 5
#: Units the calibration input lists as examples (any unit pint knows is read).
TIME_UNITS: dict[str, float] = {"s": 1.0, "min": 60.0, "h": 3600.0, "ms": 1e-3}
SLIP_UNITS: dict[str, float] = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}
#: Column roles of a tribometer file.
ROLES = ("time", "slip", "friction_ratio", "friction_force", "normal_force")
#: SI unit and pint dimensionality of each role.
_SI = {"time": ("s", "[time]"), "slip": ("m", "[length]"), "friction_ratio": ("", ""),
       "friction_force": ("N", "[force]"), "normal_force": ("N", "[force]")}  # fmt: skip
#: Usual names of each role (compared with case, spaces and underscores removed).
_SYNONYMS = {
    "time": ("time", "t"),
    "slip": ("slip", "slip_1", "displacement", "distance", "position", "sliding distance"),
    "friction_ratio": ("friction_ratio", "friction ratio", "cof", "mu", "friction coefficient",
                       "coefficient of friction"),
    "friction_force": ("friction_force", "friction force", "tangential force", "ft"),
    "normal_force": ("normal_force", "normal force", "normal load", "load", "fn"),
}  # fmt: skip
_DELIMITERS = ("\t", ";", ",", "|")
_TITLE = re.compile(
    r"^(?P<name>.*?)\s*(?:\((?P<p>[^()]*)\)|\[(?P<b>[^\[\]]*)\]|/\s*(?P<s>[^/]+)"
    r"|\s+in\s+(?P<i>\S+))\s*$"
)
_DIMENSIONLESS = {"", "-", "1", "%"}
_DECIMAL_COMMA = re.compile(r"^\s*[-+]?\d+,\d+(?:[eE][-+]?\d+)?\s*$")


@dataclass(frozen=True)
class Measured:
    """A loaded curve in SI units: time [s], friction ratio [-] (>= 0), slip [m] or None.

    ``units``: the unit read for each role present; ``stroke``: 0-based stroke of each
    sample (all 0 unless reciprocating); ``columns``: the file's title of each role.
    """

    source: str
    time: np.ndarray
    friction_ratio: np.ndarray
    slip: np.ndarray | None
    units: dict[str, str]
    stroke: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    columns: dict[str, str] = field(default_factory=dict)


def _key(name: str) -> str:
    return re.sub(r"[\s_]+", " ", name.strip().lower())


def _split_title(title: str) -> tuple[str, str | None]:
    """(name, unit or None) of a column title in the usual forms."""
    m = _TITLE.match(title.strip())
    if m is None or not m.group("name"):
        return title.strip(), None
    unit = next(m.group(g) for g in "pbsi" if m.group(g) is not None)
    return m.group("name").strip(), unit.strip()


def _factor(unit: str, role: str, where: str) -> float:
    """The factor from ``unit`` to the role's SI unit; InputError naming ``where``."""
    si, dim = _SI[role]
    token = unit.strip()
    if role == "friction_ratio":
        if token in _DIMENSIONLESS:
            return 0.01 if token == "%" else 1.0
        raise InputError(f"{where}: unit '{unit}' of the friction ratio; it has none ('-')")
    token = token.replace("μ", "u").replace("µ", "u")
    try:
        return si_factor(token, si, dim)
    except Exception:  # pint raises several kinds for an unknown or wrong unit
        raise InputError(
            f"{where}: '{unit}' is not a unit of {role.replace('_', ' ')} ({dim.strip('[]')})"
        ) from None


def _decode(raw: bytes, encoding: str | None, where: str) -> str:
    if encoding is not None:
        try:
            return raw.decode(encoding)
        except LookupError:
            raise InputError(f"{where}: unknown encoding '{encoding}'") from None
        except UnicodeDecodeError as exc:
            raise InputError(f"{where}: not {encoding} at byte {exc.start}") from None
    if raw.startswith(codecs.BOM_UTF8):
        return raw[len(codecs.BOM_UTF8) :].decode("utf-8", errors="replace")
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return raw.decode("utf-16", errors="replace")
    utf16 = _utf16_by_nul_bytes(raw)
    if utf16 is not None:
        return raw.decode(utf16, errors="replace")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("cp1252", errors="replace")


#: Share of NUL bytes at one parity of byte position that marks UTF-16 without a BOM.
UTF16_NUL_SHARE = 0.3


def _utf16_by_nul_bytes(raw: bytes) -> str | None:
    """``"utf-16-le"`` or ``"utf-16-be"`` for UTF-16 text written without a byte-order mark,
    else None.

    A lab export is mostly ASCII (digits, separators, titles); in UTF-16 every such
    character is two bytes, one of them NUL, at odd positions (little-endian) or even ones
    (big-endian). UTF-8 and the 8-bit code pages put no NUL in text. So: among the first
    4 kB, at least :data:`UTF16_NUL_SHARE` of the bytes at one parity are NUL and at most
    1 % at the other (a character such as U+4E00 has a NUL low byte).
    """
    sample = raw[: 4096 - 4096 % 2]
    sample = sample[: len(sample) - len(sample) % 2]
    if len(sample) < 4:
        return None
    even, odd = sample[0::2].count(0) / (len(sample) / 2), sample[1::2].count(0) / (len(sample) / 2)
    if odd >= UTF16_NUL_SHARE and even <= 0.01:
        return "utf-16-le"
    if even >= UTF16_NUL_SHARE and odd <= 0.01:
        return "utf-16-be"
    return None


def _fields(line: str, sep: str) -> list[str]:
    return [c.strip() for c in next(csv.reader([line], delimiter=sep))]


def _width(lines: list[str], sep: str) -> tuple[int, float]:
    """The most common field count of ``lines`` split at ``sep`` and its share."""
    counts = np.array([len(_fields(t, sep)) for t in lines])
    values, freq = np.unique(counts, return_counts=True)
    j = int(np.argmax(freq))
    return int(values[j]), float(freq[j] / counts.size)


def _sniff(lines: list[tuple[int, str]], where: str) -> str:
    """The first delimiter that splits most of the last lines into one count of >= 2 fields."""
    tail = [text for _, text in lines[-50:]]
    for sep in _DELIMITERS:
        width, share = _width(tail, sep)
        if width >= 2 and share >= 0.8:
            return sep
    raise InputError(
        f"{where}: no delimiter (tab ; , |) splits the data lines into columns alike; "
        'give sep = "..."'
    )


def _is_number(cell: str, decimal: str) -> bool:
    text = cell.replace(decimal, ".") if decimal != "." else cell
    try:
        float(text)
    except ValueError:
        return False
    return True


def _numbers(cells: list[str], decimal: str) -> np.ndarray:
    """The cells as float64 (NumPy's conversion, correctly rounded as ``float``); NaN
    where a cell is not a number."""
    if decimal != ".":
        cells = [c.replace(decimal, ".") for c in cells]
    try:
        return np.array(cells, dtype=np.float64)
    except ValueError:  # the caller names the first cell that is not a number
        return np.array([float(c) if _is_number(c, ".") else np.nan for c in cells])


def _find_columns(
    where: str, titles: list[str], mapping: Mapping[str, str]
) -> tuple[dict[str, int], dict[str, str | None]]:
    """Index and title unit of each role found (mapped names must exist)."""
    split = [_split_title(t) for t in titles]
    index: dict[str, int] = {}
    for role in ROLES:
        wanted = mapping.get(role)
        if wanted is not None:
            hits = [i for i, t in enumerate(titles) if t == wanted.strip()]
            hits = hits or [i for i, (n, _) in enumerate(split) if _key(n) == _key(wanted)]
            if not hits:
                raise InputError(
                    f"{where}: missing column '{wanted}' for {role} (columns found: "
                    f"{', '.join(t for t in titles if t)})"
                )
        else:
            names = {_key(s) for s in _SYNONYMS[role]}
            hits = [i for i, (n, _) in enumerate(split) if _key(n) in names]
        if len(hits) > 1:
            raise InputError(f"{where}: {len(hits)} columns for {role}: "
                             f"{', '.join(repr(titles[i]) for i in hits)}; map one with "
                             f'columns.{role} = "..."')  # fmt: skip
        if hits:
            index[role] = hits[0]
    return index, {role: split[i][1] for role, i in index.items()}


def _choose_unit(role: str, title: str, sources: dict[str, str | None], where: str) -> str:
    """One unit from the title, the units row and the ``units`` key; all given must agree."""
    given = {k: v for k, v in sources.items() if v is not None and v.strip() != ""}
    if role == "friction_ratio":
        given = {k: v for k, v in given.items() if not (k == "units row" and v.strip() == "-")}
    if not given:
        return _SI[role][0] or "-"
    factors = {
        k: _factor(v, role, f"{where}: units.{role}" if k == "units key" else
                   f"{where}: column '{title}'")
        for k, v in given.items()
    }  # fmt: skip
    first = next(iter(given))
    for k, f in factors.items():
        if not np.isclose(f, factors[first], rtol=1e-12):
            raise InputError(
                f"{where}: column '{title}': the {first} says '{given[first]}' but the {k} "
                f"says '{given[k]}'"
            )
    return given[first]


def read_tribometer(
    path: str | os.PathLike[str],
    columns: Mapping[str, str] | None = None,
    units: Mapping[str, str] | None = None,
    where: str = "",
    *,
    sep: str | None = None,
    decimal: str | None = None,
    encoding: str | None = None,
    reciprocating: bool = False,
) -> Measured:
    """Load ``path`` (see the module docstring); ``columns`` maps roles to the file's titles,
    ``units`` gives a role's unit (any pint unit, ``-`` for the ratio; see
    :mod:`~frictionlab.io.unit_factors`); ``where`` prefixes messages (e.g.
    ``"[[data]] #1.file 'run.csv'"``)."""
    from frictionlab.errors import ParameterError

    p = Path(path)
    where = where or f"file '{p}'"
    mapping = dict(columns or {})
    for role in [*mapping, *(units or {})]:
        if role not in ROLES:
            raise ParameterError("columns/units role", role, f"one of {', '.join(ROLES)}")
    if not p.exists() and not p.is_symlink():
        raise InputError(f"{where}: file not found")
    try:  # FIFOs and devices are refused by their type, before anything is opened
        raw = read_input_bytes(p)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    text = _decode(raw, encoding, where)
    lines = [(i + 1, t) for i, t in enumerate(text.splitlines())
             if t.strip() and not t.lstrip().startswith("#")]  # fmt: skip
    if not lines:
        raise InputError(f"{where}: the file holds no table")
    sep = sep or _sniff(lines, where)
    rows = [(n, _fields(t, sep)) for n, t in lines]
    width = _width([t for _, t in lines[-50:]], sep)[0]
    if decimal is None:
        cells = [c for _, r in rows[-20:] for c in r]
        decimal = "," if sep != "," and any(_DECIMAL_COMMA.match(c) for c in cells) else "."

    # the data: from the first line of ``width`` fields that is mostly numbers to the end;
    # the header (and a units row) right above it, free text before
    def numeric(cells: list[str]) -> bool:
        return len(cells) == width and 2 * sum(_is_number(c, decimal) for c in cells if c) > width

    first = next((i for i, (_, cells) in enumerate(rows) if numeric(cells)), None)
    if first is None:
        raise InputError(f"{where}: no line of {width} numeric fields (sep {sep!r}, "
                         f"decimal {decimal!r})")  # fmt: skip
    above = [r for r in rows[:first] if len(r[1]) == width]
    if not above:
        raise InputError(f"{where}: no header line of {width} columns above the first "
                         f"numeric line (line {rows[first][0]})")  # fmt: skip
    for n, fields_ in rows[first:]:
        if len(fields_) != width:
            raise InputError(
                f"{where} line {n}: {len(fields_)} fields where the header has {width}"
            )
    header_line, titles = above[-1]
    units_row: list[str] | None = None
    if len(above) >= 2 and above[-1][0] > above[-2][0]:
        cand = above[-1][1]
        if all(len(c) <= 12 for c in cand) and not _find_columns(where, cand, {})[0]:
            units_row = cand
            header_line, titles = above[-2]
    index, title_units = _find_columns(where, titles, mapping)
    if "time" not in index:
        raise InputError(f"{where} line {header_line}: no time column among "
                         f"{', '.join(titles)}; map yours with columns.time = \"...\"")  # fmt: skip
    has_ratio = "friction_ratio" in index
    if not has_ratio and not {"friction_force", "normal_force"} <= set(index):
        raise InputError(
            f"{where} line {header_line}: no friction ratio column (or friction_force and "
            f"normal_force) among {', '.join(titles)}; map yours with columns.friction_ratio"
        )
    used = [r for r in ROLES if r in index and (has_ratio or r != "friction_ratio")]
    if has_ratio:
        used = [r for r in used if r not in ("friction_force", "normal_force")]
    chosen = {
        r: _choose_unit(
            r,
            titles[index[r]],
            {"title": title_units[r], "units row": None if units_row is None
             else units_row[index[r]].strip("[]() "), "units key": (units or {}).get(r)},
            where,
        )
        for r in used
    }  # fmt: skip
    data = rows[first:]
    if len(data) < MIN_SAMPLES:
        raise InputError(f"{where}: only {len(data)} samples; at least {MIN_SAMPLES} are needed")
    line_numbers = np.array([n for n, _ in data])
    values: dict[str, np.ndarray] = {}
    for r in used:
        title = titles[index[r]]
        raw_cells = [row[index[r]] for _, row in data]
        col = _numbers(raw_cells, decimal)
        bad = ~np.isfinite(col)
        if bad.any():
            j = int(np.argmax(bad))
            what = "is empty" if not raw_cells[j] else f"= {raw_cells[j]!r} is not a number"
            raise InputError(f"{where} line {line_numbers[j]}: column '{title}' {what}")
        col = col * _factor(chosen[r], r, f"{where}: column '{title}'")
        values[r] = col
    t = values["time"]
    tt = titles[index["time"]]
    if t[0] < 0:
        raise InputError(f"{where} line {line_numbers[0]}: column '{tt}' = {t[0]:g} s is negative")
    steps = np.diff(t)
    if np.any(steps <= 0):
        i = int(np.flatnonzero(steps <= 0)[0])
        raise InputError(f"{where} line {line_numbers[i + 1]}: column '{tt}' is not strictly "
                         f"increasing ({t[i + 1]:g} s after {t[i]:g} s)")  # fmt: skip
    if has_ratio:
        signed = values["friction_ratio"]
        rt = titles[index["friction_ratio"]]
    else:
        fn = values["normal_force"]
        nt = titles[index["normal_force"]]
        if np.any(fn <= 0):
            j = int(np.argmax(fn <= 0))
            raise InputError(f"{where} line {line_numbers[j]}: column '{nt}' = {fn[j]:g} N; "
                             "the normal force must be > 0 (compression)")  # fmt: skip
        signed = values["friction_force"] / fn
        rt = titles[index["friction_force"]]
    stroke = np.zeros(t.size, dtype=np.int64)
    if reciprocating:
        sign = np.sign(signed)
        nonzero = np.flatnonzero(sign)
        flips = np.zeros(t.size, dtype=np.int64)
        if nonzero.size > 1:
            change = nonzero[1:][sign[nonzero[1:]] != sign[nonzero[:-1]]]
            flips[change] = 1
        stroke = np.cumsum(flips)
        ratio = np.abs(signed)
    else:
        if np.any(signed < 0):
            j = int(np.argmax(signed < 0))
            raise InputError(
                f"{where} line {line_numbers[j]}: column '{rt}' is negative ({signed[j]:g}); "
                "a friction ratio |f_t|/f_n is >= 0 (for a reciprocating test set "
                "reciprocating = true)"
            )
        ratio = signed
    slip = values.get("slip")
    return Measured(
        source=str(p),
        time=t,
        friction_ratio=ratio,
        slip=slip,
        units={r: chosen[r] for r in used},
        stroke=stroke,
        columns={r: titles[index[r]] for r in used},
    )
