"""Input declarations: :class:`Field` and :class:`Section` (value kinds: :mod:`.kinds`).

Every key of every input file is declared once, as a :class:`Field` of a :class:`Section`
(its kind, unit, allowed range, default, per-point flag and a one-line doc). From that
one declaration come the TOML reader (one-line errors naming the key, the value and the
allowed range, with "did you mean"), the ``--set`` check, the JSON Schemas in
docs/schemas and the key tables of the docs (``python -m frictionlab.schema``).

Physical bounds stay in the physics classes: a field declared ``by=SubloadingParams``
is passed on unchecked here and its range is the class's (:func:`reraise` puts the
section in front of the class's :class:`~frictionlab.errors.ParameterError`).
"""

from __future__ import annotations

import dataclasses
import os
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

from frictionlab.errors import InputError, ParameterError
from frictionlab.io.config import REQUIRED, Table, apply_overrides, load_toml, unknown_key
from frictionlab.schema.kinds import (  # re-exported: the declarations' vocabulary
    BOOL,
    DEFS,
    INTEGER,
    NUMBER,
    NUMBERS,
    PAIRS,
    STRING,
    Kind,
    listed,
)

__all__ = [
    "BOOL", "DEFS", "DESCRIPTION", "INTEGER", "NUMBER", "NUMBERS", "OMIT", "PAIRS", "REQUIRED",
    "STRING", "TITLE", "Field", "Kind", "Section", "check_overrides", "listed", "loader", "reraise",
]  # fmt: skip


class _Omit:
    def __repr__(self) -> str:
        return "OMIT"


#: Default meaning "optional; when absent the key is not passed on" (the class's default).
OMIT: Any = _Omit()


@dataclass(frozen=True)
class Field:
    """One input key.

    ``default``: :data:`REQUIRED`, :data:`OMIT` (the owning class's default applies) or
    a value. ``low``/``high`` bound the value (``open`` says which bounds are strict:
    "low", "high", "both" or ""); ``allowed`` overrides the range text of the message.
    ``by`` names the physics class that checks the value (its bound is not restated).
    ``table``: the sub-section of a table-valued key (``many``: an array of tables).
    """

    name: str
    kind: Kind | None = None
    doc: str = ""
    unit: str = ""
    default: Any = OMIT
    choices: tuple[Any, ...] | None = None
    low: float | None = None
    high: float | None = None
    open: str = ""
    allowed: str = ""
    by: type | None = None
    per_point: bool = False
    table: Section | None = None
    many: bool = False
    json: Mapping[str, Any] | None = None

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    def check(self) -> Callable[[Any], bool] | None:
        if self.low is None and self.high is None:
            return None
        lo_open, hi_open = self.open in ("low", "both"), self.open in ("high", "both")

        def ok(v: Any) -> bool:
            if self.low is not None and (v <= self.low if lo_open else v < self.low):
                return False
            return self.high is None or (v < self.high if hi_open else v <= self.high)

        return ok

    def allowed_text(self) -> str:
        """The allowed range in words (``an integer >= 1``, ``0 < front_ratio <= 1``)."""
        if self.allowed:
            return self.allowed
        lo = "<" if self.open in ("low", "both") else "<="
        hi = "<" if self.open in ("high", "both") else "<="
        if self.low is not None and self.high is not None:
            return f"{self.low:g} {lo} {self.name} {hi} {self.high:g}"
        what = "an integer" if self.kind is INTEGER else "a number"
        if self.low is not None:
            return f"{what} {'>' if lo == '<' else '>='} {self.low:g}"
        if self.high is not None:
            return f"{what} {hi} {self.high:g}"
        if self.choices:
            return " | ".join(str(c) for c in self.choices)
        return f"see {self.by.__name__}" if self.by is not None else ""

    def shown_default(self) -> Any:
        """The default as the docs show it (the owning class's default for :data:`OMIT`)."""
        if self.default is OMIT and self.by is not None and dataclasses.is_dataclass(self.by):
            for f in dataclasses.fields(self.by):
                if f.name == self.name and f.default is not dataclasses.MISSING:
                    return f.default
            return None
        return None if self.default is OMIT else self.default

    def schema(self) -> dict[str, Any]:
        """This key's JSON Schema."""
        if self.json is not None:
            out = dict(self.json)
        elif self.table is not None:
            sub = {"$ref": f"#/$defs/{self.table.name}"} if self.table.ref else self.table.schema()
            out = {"type": "array", "items": sub} if self.many else sub
        else:
            assert self.kind is not None, self.name
            out = dict(self.kind.json)
            each: dict[str, Any] = {} if self.choices is None else {"enum": list(self.choices)}
            if self.kind in (NUMBER, INTEGER) or self.kind.entries:
                lo, hi = self.open in ("low", "both"), self.open in ("high", "both")
                if self.low is not None:
                    each["exclusiveMinimum" if lo else "minimum"] = self.low
                if self.high is not None:
                    each["exclusiveMaximum" if hi else "maximum"] = self.high
            if not self.kind.entries:
                out.update(each)
            elif "oneOf" in out:  # a value or a list of values
                one, many = out["oneOf"]
                out["oneOf"] = [{**one, **each}, {**many, "items": {**many["items"], **each}}]
            else:
                out["items"] = {**out["items"], **each}
        doc = self.doc + (f" [{self.unit}]" if self.unit else "")
        if doc and "$ref" not in out:
            out["description"] = doc
        return out


#: The ``title`` and ``description`` keys at the top of every scenario file.
TITLE = Field("title", STRING, "title of the run", "", "")
DESCRIPTION = Field("description", STRING, "free text", "", "")


@dataclass(frozen=True)
class Section:
    """One input table: its fields, in reading order.

    ``where`` is how messages name the table (``[law]``); ``variants`` maps the value of
    the ``kind`` field to the names of the fields that kind allows (tagged tables such as
    programme segments); ``required_by`` maps a kind to its required field names;
    ``exclusive`` lists pairs of keys given at most one at a time, ``one_of`` groups of
    keys given exactly one at a time (for a tagged table, in the kinds that allow them
    all); ``by`` is the class :meth:`build` makes (tagged tables: a mapping kind -> class).
    """

    name: str
    fields: tuple[Field, ...]
    doc: str = ""
    where: str = ""
    variants: Mapping[str, tuple[str | Field, ...]] | None = None
    required_by: Mapping[str, tuple[str, ...]] | None = None
    exclusive: tuple[tuple[str, str], ...] = ()  # pairs of keys that exclude each other
    one_of: tuple[tuple[str, ...], ...] = ()  # groups of keys, exactly one given
    by: Any = None  # the class built from the values (tagged tables: kind -> class)
    extra: Mapping[str, Any] | None = None  # more JSON Schema (oneOf, ...)
    ref: bool = False  # written once under $defs/<name> of the generated schema

    def __getitem__(self, name: str) -> Field:
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(name)

    def keys(self, kind: str | None = None) -> tuple[str, ...]:
        """The keys allowed (for a tagged table, those of ``kind``)."""
        return tuple(f.name for f in self.fields_of(kind))

    def fields_of(self, kind: str | None = None) -> tuple[Field, ...]:
        """The fields (for a tagged table, those of ``kind``, its own declarations first)."""
        if self.variants is None or kind is None:
            return self.fields
        own = [f if isinstance(f, Field) else self[f] for f in self.variants[kind]]
        return (self["kind"], *own)

    def table(self, data: Any, where: str | None = None) -> Table:
        """``data`` as a checked table: unknown keys are refused first (with did-you-mean)."""
        t = data if isinstance(data, Table) else Table(data, self.where if where is None else where)
        kind = None
        if self.variants is not None:
            kind = t.get("kind", str, choices=tuple(self.variants))
        allowed = self.keys(kind)
        for key in t.mapping():
            if key not in allowed:
                name = f"{t.where}.{key}" if t.where else key
                raise InputError(unknown_key(name, key, allowed))
        for key in (self.required_by or {}).get(kind or "", ()):
            if key not in t:
                raise InputError(
                    f"missing required key {t.where}.{key} (needed by kind = '{kind}')"
                )
        return t

    def read(
        self, data: Any, where: str | None = None, *, only_given: bool = False, **defaults: Any
    ) -> dict[str, Any]:
        """The typed values of the table's plain keys (sub-tables are left to the caller).

        Absent keys take the value in ``defaults``, else their default (``None`` for
        :data:`OMIT`), or are left out with ``only_given``. A missing required key is one
        line naming it.
        """
        t = self.table(data, where)
        kind = t.get("kind", str) if self.variants is not None else None
        out: dict[str, Any] = {} if kind is None else {"kind": kind}
        for f in self.fields_of(kind):
            if f.name == "kind" or f.table is not None or f.kind is None:
                continue
            if f.name in t:
                out[f.name] = f.kind.read(t, f)
            elif f.name in defaults:
                out[f.name] = defaults[f.name]
            elif f.required:
                raise InputError(f"missing required key {t.where}.{f.name}")
            elif not only_given:
                out[f.name] = None if f.default is OMIT else f.default
        at = f"{t.where}: " if t.where else ""
        for a, b in self.exclusive:
            if a in t and b in t:
                raise InputError(f"{at}give {self._name(a, t)} or {self._name(b, t)}, not both")
        for group in self._one_of(kind):
            given = [k for k in group if k in t]
            if len(given) != 1:
                names = [self._name(k, t) for k in group]
                both = ", not both" if len(group) == 2 else f", not {' and '.join(given)}"
                extra = both if given else ""
                listed = f"{', '.join(names[:-1])} or {names[-1]}"
                raise InputError(f"{at}give exactly one of {listed}{extra}")
        return out

    def _one_of(self, kind: str | None) -> tuple[tuple[str, ...], ...]:
        keys = self.keys(kind)
        return tuple(g for g in self.one_of if all(k in keys for k in g))

    def _name(self, key: str, t: Table) -> str:
        """How a message names a key: ``key (unit)``, or ``[table]``/``[[tables]]``."""
        f, where = self[key], re.fullmatch(r"\[([\w.]+)\]", t.where)
        if f.table is not None:
            name = f"{where[1]}.{key}" if where else key
            return f"[[{name}]]" if f.many else f"[{name}]"
        return f"{key} ({f.unit})" if f.unit else key

    def build(
        self, data: Any, where: str | None = None, *, only_given: bool = False,
        drop: tuple[str, ...] = (), error: type[Exception] = ParameterError, **defaults: Any,
    ) -> tuple[Any, dict[str, Any]]:  # fmt: skip
        """(the object of class ``by`` made from the table's values, the values read).

        ``defaults``: values of keys not given (as :meth:`read`); ``drop`` names keys not
        passed on. A ParameterError of the class is re-raised naming the table.
        """
        t = self.table(data, where)
        values = self.read(t, only_given=only_given, **defaults)
        kw = {k: v for k, v in {**defaults, **values}.items() if k not in drop}
        cls = self.by[kw.pop("kind")] if self.variants is not None else self.by
        return reraise(t.where, lambda: cls(**kw), error), values

    def read_top(self, data: Any) -> tuple[dict[str, Any], dict[str, Any]]:
        """The top table of an input file, checked (unknown keys refused): (its values, its
        sub-tables: a Table, a non-empty list of them for [[arrays]], None when absent)."""
        root = self.table(data, "")
        tables: dict[str, Any] = {}
        for f in self.fields:
            if f.table is None or f.json is not None:
                continue
            if not f.many:
                tables[f.name] = root.table(f.name, f.required)
            else:
                given = f.name in root or f.required
                tables[f.name] = root.tables(f.name, f.required) if given else None
                if tables[f.name] == []:
                    one = f.table.doc if f.table.doc.startswith("one ") else "one table"
                    raise InputError(f"[[{f.name}]] must hold at least {one}")
        return self.read(root), tables

    def schema(self) -> dict[str, Any]:
        """The JSON Schema of the table (tagged tables: one ``if/then`` rule per kind)."""
        out: dict[str, Any] = {"type": "object", "additionalProperties": False}
        if self.doc:
            out["description"] = self.doc
        required = [f.name for f in self.fields if f.required]
        if required:
            out["required"] = required
        out["properties"] = {f.name: f.schema() for f in self.fields}
        if self.variants is None and (rules := self._rules(self.keys())):
            out["allOf"] = rules
        if self.variants is not None:
            out["allOf"] = [self._rule(k) for k in self.variants]
            for k in self.variants:  # a key declared again by a kind: either declaration
                for f in (f for f in self.variants[k] if isinstance(f, Field)):
                    out["properties"][f.name] = {"anyOf": [self[f.name].schema(), f.schema()]}
        out.update(self.extra or {})
        return out

    def _rules(self, keys: tuple[str, ...]) -> list[dict[str, Any]]:
        """JSON Schema of the cross-key rules on ``keys``."""
        out = [{"not": {"required": list(p)}} for p in self.exclusive if set(p) <= set(keys)]
        groups = (g for g in self.one_of if set(g) <= set(keys))
        return out + [{"oneOf": [{"required": [k]} for k in g]} for g in groups]

    def _rule(self, kind: str) -> dict[str, Any]:
        then: dict[str, Any] = {"propertyNames": {"enum": list(self.keys(kind))}}
        if self.required_by and kind in self.required_by:
            then["required"] = list(self.required_by[kind])
        if self._one_of(kind):
            then["allOf"] = self._rules(self.keys(kind))
        own = {f.name: f.schema() for f in self.variants[kind] if isinstance(f, Field)}  # type: ignore[index]
        if own:
            then["properties"] = own
        return {"if": {"properties": {"kind": {"const": kind}}}, "then": then}


def run_file(name: str, fields: tuple[Field, ...], doc: str, where: str = "", **kw: Any) -> Section:
    """The top section of a run file: ``title`` and ``description``, then ``fields``."""
    return Section(name, (TITLE, DESCRIPTION, *fields), doc, where, **kw)


def reraise(
    where: str | Callable[[str], str], call: Callable[[], Any],
    error: type[Exception] = ParameterError, sep: str = ".",
) -> Any:  # fmt: skip
    """Run ``call``; re-raise a ParameterError naming its key ``where + sep + key`` (or
    ``where(key)``), as an ``error`` (ParameterError or InputError)."""
    try:
        return call()
    except ParameterError as exc:
        name = where(exc.field) if callable(where) else f"{where}{sep}{exc.field}"
        if error is not ParameterError:  # the message names the key first
            raise error(name + str(exc)[len(exc.field) :]) from None
        raise ParameterError(name, exc.value, exc.allowed) from None


def check_overrides(root: Section, overrides: Iterable[str]) -> None:
    """Refuse a ``--set section.key=value`` whose key no declaration has (did-you-mean).

    Entries of arrays of tables (``program.2.steps``) and keys below a free-form table are
    checked as far as the declarations go; the value itself is checked by the parser.
    """
    for item in overrides:
        dotted = item.split("=", 1)[0].strip()
        section: Section | None = root
        where = ""
        for part in (p.strip() for p in dotted.split(".")):
            if section is None:
                break
            if part.isdigit():  # an entry of an array of tables, counted from 1
                where = f"[{where}] #{part}"
                continue
            allowed = section.keys() if section.variants is None else _all_keys(section)
            name = f"{where}.{part}" if where else part
            if part not in allowed:
                raise InputError(f"--set {item}: " + unknown_key(name, part, allowed))
            f = section[part]
            where = f"[{part}]" if not where else name
            section = f.table if f.table is not None and f.table.fields else None


def _all_keys(section: Section) -> tuple[str, ...]:
    return tuple(dict.fromkeys(k for v in section.variants or {} for k in section.keys(v)))


def override(root: Section, data: dict[str, Any], overrides: Sequence[str]) -> dict[str, Any]:
    """``data`` with the ``--set`` overrides applied, each key checked against ``root``."""
    check_overrides(root, overrides)
    return apply_overrides(data, overrides)


T = TypeVar("T")


def loader(root: Section, parse: Callable[..., T], what: str) -> Callable[..., T]:
    """``load_<input>(path, overrides=())``: read the TOML file ``path``, apply the ``--set``
    overrides (checked against ``root``) and ``parse`` it (relative file names from the
    file's folder)."""

    def load(path: str | os.PathLike[str], overrides: Sequence[str] = ()) -> T:
        p = Path(path)
        return parse(override(root, load_toml(p), overrides), base_dir=p.parent, source=str(p))

    load.__name__ = load.__qualname__ = f"load_{root.name}"
    load.__doc__ = f"Read, override (``section.key=value``) and validate {what}."
    return load
