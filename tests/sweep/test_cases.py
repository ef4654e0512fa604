"""Case expansion, ids, the sweep file, the ledger and the table (no scenario runs)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from frictionlab.errors import InputError
from frictionlab.io.config import apply_overrides
from frictionlab.sweep.cases import Case, case_id, check_key, expand_grid, override_strings
from frictionlab.sweep.figures import summary_figures
from frictionlab.sweep.ledger import is_done, make_record, read_record, write_case
from frictionlab.sweep.spec import detect_command, parse_sweep
from frictionlab.sweep.table import format_table, sweep_table


def test_grid_is_the_cartesian_product_last_key_fastest() -> None:
    combos = expand_grid({"a.x": [1, 2], "b.y": ["p", "q", "r"]})
    assert len(combos) == 6
    assert combos[0] == {"a.x": 1, "b.y": "p"} and combos[1] == {"a.x": 1, "b.y": "q"}
    assert combos[-1] == {"a.x": 2, "b.y": "r"}


def test_linked_grid_keys_share_one_axis() -> None:
    combos = expand_grid({"p.1.v+p.3.v": [1, 2], "p.2.t": [5, 6, 7]})
    assert len(combos) == 6
    assert combos[4] == {"p.1.v": 2, "p.3.v": 2, "p.2.t": 6}
    spec = parse_sweep({"base": "b.toml", "grid": {"p.1.v+p.3.v": [1, 2]}}, Path("."))
    assert spec.keys == ("p.1.v+p.3.v",)
    table = sweep_table(spec.cases, spec.keys, {}, {})
    assert table["p.1.v+p.3.v"].tolist() == [1, 2] and set(table["status"]) == {"pending"}
    with pytest.raises(InputError, match="empty key around"):
        parse_sweep({"base": "b.toml", "grid": {"p.1.v+": [1]}}, Path("."))


def test_case_id_is_deterministic_and_order_free() -> None:
    one = case_id({"law.mu_s": 0.6, "program.2.duration": 10.0})
    assert one == case_id({"program.2.duration": 10.0, "law.mu_s": 0.6})
    assert len(one) == 12 and int(one, 16) >= 0
    assert one != case_id({"law.mu_s": 0.6, "program.2.duration": 100.0})
    assert case_id({"a.b": 1}) != case_id({"a.b": "1"})


def test_bare_and_quoted_dotted_keys_give_the_same_cases() -> None:
    quoted = tomllib.loads('base = "b.toml"\n[grid]\n"program.2.duration" = [1.0, 2.0]\n')
    bare = tomllib.loads('base = "b.toml"\n[grid]\nprogram.2.duration = [1.0, 2.0]\n')
    a, b = parse_sweep(quoted, Path("/x")), parse_sweep(bare, Path("/x"))
    assert a.cases == b.cases and a.keys == ("program.2.duration",)
    assert a.base == Path("/x/b.toml")


def test_case_lists() -> None:
    data = tomllib.loads(
        'base = "b.toml"\n[[case]]\n"law.mu_s" = 0.6\n[[case]]\n"law.mu_k" = 0.2\n'
    )
    spec = parse_sweep(data, Path("."))
    assert spec.keys == ("law.mu_s", "law.mu_k")
    assert [c.overrides for c in spec.cases] == [{"law.mu_s": 0.6}, {"law.mu_k": 0.2}]


def test_linked_keys_in_a_case_list_take_the_same_value() -> None:
    data = tomllib.loads(
        'base = "b.toml"\n[[case]]\n"program.1.velocity+program.3.velocity" = 0.2\n'
        '"law.mu_s" = 0.6\n[[case]]\n"law.mu_k" = 0.2\n'
    )
    spec = parse_sweep(data, Path("."))
    assert spec.keys == ("program.1.velocity", "program.3.velocity", "law.mu_s", "law.mu_k")
    assert spec.cases[0].overrides == {
        "program.1.velocity": 0.2, "program.3.velocity": 0.2, "law.mu_s": 0.6
    }  # fmt: skip
    # the same case written without the link has the same id
    plain = tomllib.loads(
        'base = "b.toml"\n[[case]]\n"program.3.velocity" = 0.2\n"law.mu_s" = 0.6\n'
        '"program.1.velocity" = 0.2\n'
    )
    assert parse_sweep(plain, Path(".")).cases[0].id == spec.cases[0].id


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ('base = "b.toml"\n[[case]]\n"a.b+" = 1\n', "empty key around '+'"),
        ('base = "b.toml"\n[[case]]\n"a.b+c.d" = 1\n"a.b" = 2\n', "sets 'a.b' twice"),
        ('base = "b.toml"\n[grid]\n', "[grid] is empty"),
        ('base = "b.toml"\n[grid]\n"a.b" = [1]\n"a.b+c.d" = [2]\n', "sets 'a.b' twice"),
        ('base = "b.toml"\n[grid]\n"a.b+a.b" = [1]\n', "sets 'a.b' twice"),
        ('base = "b.toml"\n[grid]\n"a.b" = []\n', "non-empty list"),
        ('base = "b.toml"\nbogus = 1\n[grid]\n"a.b" = [1]\n', "unknown key bogus"),
        ('[grid]\n"a.b" = [1]\n', "base must name"),
        ('base = "b.toml"\n', "exactly one of [grid] or [[case]]"),
        ('base = "b.toml"\ncommand = "bridge"\n[grid]\n"a.b" = [1]\n', "command = 'bridge'"),
        ('base = "b.toml"\n[[case]]\n"a.b" = 1\n[[case]]\n"a.b" = 1\n', "repeats case 1"),
    ],
)
def test_bad_sweep_files(text: str, words: str) -> None:
    with pytest.raises(InputError, match=None) as err:
        parse_sweep(tomllib.loads(text), Path("."))
    assert words in str(err.value)


def test_check_key_and_override_strings_round_trip() -> None:
    base = {"law": {"mu_s": 0.5}, "program": [{"kind": "slide"}, {"kind": "hold", "duration": 1}]}
    check_key(base, "law.mu_s", "case 1")
    check_key(base, "program.2.duration", "case 1")
    with pytest.raises(InputError, match=r"no 'law\.mu_S'"):
        check_key(base, "law.mu_S", "case 1")
    with pytest.raises(InputError, match="entry number from 1 to 2"):
        check_key(base, "program.3.duration", "case 1")
    values = {"law.mu_s": 1e-05, "program.2.duration": [1.0, 10.0], "program.1.kind": 'a"b'}
    data = apply_overrides(base, override_strings(values))
    assert data["law"]["mu_s"] == 1e-05
    assert data["program"][1]["duration"] == [1.0, 10.0]
    assert data["program"][0]["kind"] == 'a"b'


def test_detect_command() -> None:
    assert detect_command({"law": {}}, None) == "simulate"
    assert detect_command({"lower": {}}, None) == "roughness"
    assert detect_command({"law": {}}, "roughness") == "roughness"
    with pytest.raises(InputError, match="cannot tell"):
        detect_command({"x": {}}, None)


def test_ledger_resume_rules(tmp_path: Path) -> None:
    case = Case(case_id({"a.b": 1}), 0, {"a.b": 1})
    assert read_record(tmp_path / case.id) is None
    ok = make_record(case, "simulate", "sha", "ok", "", 0.5, ["summary.json"])
    (tmp_path / case.id).mkdir()
    (tmp_path / case.id / "stale.csv").write_text("old")
    write_case(tmp_path / case.id, {"summary.json": b"{}"}, ok)
    assert not (tmp_path / case.id / "stale.csv").exists()
    record = read_record(tmp_path / case.id)
    assert is_done(record, case, "sha")
    assert not is_done(record, case, "other base")  # an input file changed: run again
    failed = make_record(case, "simulate", "sha", "failed", "boom", 0.1, [])
    assert not is_done(failed, case, "sha")  # failed cases are retried


def test_figures_and_table() -> None:
    simulate = {"points": [{"peak": {"friction_ratio": 0.5}, "final": {"friction_ratio": 0.3}}]}
    assert summary_figures("simulate", simulate) == {
        "peak_friction_ratio": 0.5,
        "final_friction_ratio": 0.3,
    }
    rough = summary_figures("roughness", {"results": {"mu_max": 0.4, "mu_min": 0.2}})
    assert rough["mu_max"] == 0.4 and rough["anisotropy_max_over_min"] is None
    cases = [Case("a" * 12, 0, {"k.x": 1.0}), Case("b" * 12, 1, {"k.x": 2.0})]
    records = {
        "a" * 12: {"status": "ok", "seconds": 0.1, "error": ""},
        "b" * 12: {"status": "failed", "seconds": 0.2, "error": "bad,\n news #1"},
    }
    table = sweep_table(cases, ["k.x"], records, {"a" * 12: {"peak_friction_ratio": 0.5}})
    assert list(table.columns) == ["case", "id", "status", "k.x", "peak_friction_ratio",
                                   "seconds", "error"]  # fmt: skip
    assert table["error"].tolist() == ["", "bad, news #1"]
    import io

    import pandas as pd

    back = pd.read_csv(io.StringIO(format_table(table)), keep_default_na=False)
    assert list(back.columns) == [
        "case [-]", "id [-]", "status [-]", "k.x", "peak_friction_ratio [-]", "seconds [s]",
        "error [-]",
    ]  # fmt: skip
    assert back["error [-]"].tolist() == ["", "bad, news #1"]
    assert back["status [-]"].tolist() == ["ok", "failed"]
