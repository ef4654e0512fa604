"""Tribometer files as labs write them: a corpus made from known parameters reads back to
the same curve and calibrates back to those parameters; malformed variants are refused in
one line naming the file and the line or column."""

from __future__ import annotations

import codecs
import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from frictionlab.calibration import Curve
from frictionlab.cli import main
from frictionlab.errors import InputError
from frictionlab.io.tribometer import read_tribometer

from .support import TRUE, config, make_curve, write_config

FN_N = 50.0  # normal force of the files written with forces [N]


def _num(x: float, comma: bool = False) -> str:
    text = repr(float(x))
    return text.replace(".", ",") if comma else text


def semicolon_decimal_comma_cp1252(c: Curve) -> bytes:
    """German-style export: free-text header, ';', decimal comma, minutes, a degC column."""
    assert c.slip is not None
    lines = ["Tribometer TR-3 Messdatei", "Probe: Stahl/PTFE, 23 °C", "",
             "Time (min);Displacement/mm;COF;Temperature (°C)"]  # fmt: skip
    for t, s, r in zip(c.time, c.slip, c.friction_ratio, strict=True):
        lines.append(";".join([_num(t / 60, True), _num(s * 1e3, True), _num(r, True), "23,5"]))
    return ("\r\n".join(lines) + "\r\n").encode("cp1252")


def utf16_tab_forces(c: Curve) -> bytes:
    """UTF-16 with BOM, tabs, friction and normal force in N and kN, slip in um."""
    assert c.slip is not None
    lines = ["time [s]\tslip [um]\tfriction_force [N]\tnormal_force [kN]"]
    for t, s, r in zip(c.time, c.slip, c.friction_ratio, strict=True):
        lines.append("\t".join([_num(t), _num(s * 1e6), _num(r * FN_N), _num(FN_N / 1e3)]))
    return "\n".join(lines).encode("utf-16")


def utf16_without_bom(c: Curve, byteorder: str = "le") -> bytes:
    """UTF-16 as some loggers write it, with no byte-order mark, degC in a title."""
    assert c.slip is not None
    lines = ["time [s];slip [mm];COF [-];Temperature [°C]"]
    for t, s, r in zip(c.time, c.slip, c.friction_ratio, strict=True):
        lines.append(";".join([_num(t), _num(s * 1e3), _num(r), "23.5"]))
    return ("\r\n".join(lines) + "\r\n").encode(f"utf-16-{byteorder}")


def bom_units_row(c: Curve) -> bytes:
    """UTF-8 with BOM, commas, '#' comments, an index column and a units row."""
    assert c.slip is not None
    lines = ["# TR-2 export", ",Time,Displacement,Normal load,COF", ",min,mm,N,-"]
    for i, (t, s, r) in enumerate(zip(c.time, c.slip, c.friction_ratio, strict=True)):
        lines.append(",".join([str(i), _num(t / 60), _num(s * 1e3), "50.0", _num(r)]))
    return codecs.BOM_UTF8 + ("\n".join(lines) + "\n").encode()


def pipe_in_units(c: Curve) -> bytes:
    """'|'-separated, titles 'X in unit', a force pair named as labs do."""
    assert c.slip is not None
    lines = ["Time in s|Sliding distance in mm|Friction force in N|Normal load in N"]
    for t, s, r in zip(c.time, c.slip, c.friction_ratio, strict=True):
        lines.append("|".join([_num(t), _num(s * 1e3), _num(r * FN_N), _num(FN_N)]))
    return ("\n".join(lines) + "\n").encode()


def own_history_titles(c: Curve) -> bytes:
    """frictionlab's own titles ('time [s]', 'slip_1 [m]', 'friction_ratio [-]')."""
    assert c.slip is not None
    lines = ["time [s],slip_1 [m],friction_ratio [-]"]
    for t, s, r in zip(c.time, c.slip, c.friction_ratio, strict=True):
        lines.append(",".join([_num(t), _num(s), _num(r)]))
    return ("\n".join(lines) + "\n").encode()


FORMATS: dict[str, Callable[[Curve], bytes]] = {
    "semicolon_decimal_comma_cp1252": semicolon_decimal_comma_cp1252,
    "utf16_tab_forces": utf16_tab_forces,
    "utf16le_without_bom": utf16_without_bom,
    "utf16be_without_bom": lambda c: utf16_without_bom(c, "be"),
    "bom_units_row": bom_units_row,
    "pipe_in_units": pipe_in_units,
    "own_history_titles": own_history_titles,
}


@pytest.fixture(scope="module")
def curve() -> Curve:
    return make_curve(0.0)


@pytest.mark.parametrize("fmt", FORMATS)
def test_each_lab_format_reads_back_the_curve_in_si(tmp_path: Path, curve: Curve, fmt: str):
    f = tmp_path / f"{fmt}.csv"
    f.write_bytes(FORMATS[fmt](curve))
    m = read_tribometer(f)
    np.testing.assert_allclose(m.time, curve.time, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(m.friction_ratio, curve.friction_ratio, rtol=1e-12, atol=1e-15)
    assert m.slip is not None and curve.slip is not None
    np.testing.assert_allclose(m.slip, curve.slip, rtol=1e-12, atol=1e-18)


def test_reciprocating_strokes_give_the_magnitude_and_count_strokes(tmp_path: Path, curve):
    """The second slide and hold (t in [6, 338) s) run backwards: the ratio is negative."""
    back = (curve.time >= 6.0) & (curve.time < 338.0)
    signed = np.where(back, -curve.friction_ratio, curve.friction_ratio)
    lines = ["time [s],COF"] + [
        f"{_num(t)},{_num(r)}" for t, r in zip(curve.time, signed, strict=True)
    ]
    f = tmp_path / "recip.csv"
    f.write_text("\n".join(lines) + "\n")
    m = read_tribometer(f, reciprocating=True)
    np.testing.assert_array_equal(m.friction_ratio, curve.friction_ratio)
    nonzero = curve.friction_ratio > 0
    expected = np.where(back, 1, np.where(curve.time >= 338.0, 2, 0))
    np.testing.assert_array_equal(m.stroke[nonzero], expected[nonzero])
    with pytest.raises(InputError, match=r"line \d+: column 'COF' is negative .*reciprocating"):
        read_tribometer(f)


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["semicolon_decimal_comma_cp1252", "utf16_tab_forces"])
def test_lab_files_calibrate_back_to_the_true_parameters(tmp_path: Path, curve, fmt: str):
    """Through `frictionlab calibrate`, with no column or unit keys: the titles say it all."""
    (tmp_path / "run.csv").write_bytes(FORMATS[fmt](curve))
    cfg = config("run.csv", ["mu_s", "mu_k", "kappa"], dict(mu_s=0.45, mu_k=0.33, kappa=2000.0),
                 profile=False)  # fmt: skip
    del cfg["data"][0]["columns"], cfg["data"][0]["units"]
    path = write_config(tmp_path / "calibrate.toml", cfg)
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    fit = json.loads((tmp_path / "out" / "summary.json").read_text())
    for name in ("mu_s", "mu_k", "kappa"):
        assert fit["parameters"][name]["value"] == pytest.approx(TRUE[name], rel=2e-3), name


GOOD = ["time [s],slip [mm],COF", "0,0,0.1", "1,0.1,0.2", "2,0.2,0.3", "3,0.3,0.3", "4,0.4,0.3"]


def _with(row: int, text: str) -> list[str]:
    out = list(GOOD)
    out[row] = text
    return out


MALFORMED = {
    "text in a number cell": (_with(3, "2,0.2,abc"), {}, "line 4: column 'COF' = 'abc'"),
    "a row with a field missing": (_with(4, "3,0.3"), {}, "line 5: 2 fields where"),
    "title unit against the units key": (GOOD, {"units": {"time": "min"}},
                                         "column 'time [s]': the title says 's' but the units"),
    "a length unit on time": (["time [mm],COF", *[r.rsplit(",", 2)[0] + "," +
                               r.rsplit(",", 1)[1] for r in GOOD[1:]]], {},
                              "column 'time [mm]': 'mm' is not a unit of time"),
    "units row against the title": (["time [s],slip [mm],COF", "min,mm,-", *GOOD[1:]], {},
                                     "column 'time [s]': the title says 's' but the units row"),
    "negative friction ratio": (_with(2, "1,0.1,-0.2"), {}, "line 3: column 'COF' is negative"),
    "time going back": (_with(3, "0.5,0.2,0.3"), {}, "line 4: column 'time [s]' is not strictly"),
    "two time columns": (["time [s],Time (min),slip [mm],COF", *[r.replace(",", ",0,", 1)
                                                             for r in GOOD[1:]]], {},
                         "2 columns for time: 'time [s]', 'Time (min)'"),
    "no friction column": (["time [s],slip [mm],load [N]", *GOOD[1:]], {},
                           "line 1: no friction ratio column"),
    "a mapped column that is absent": (GOOD, {"columns": {"friction_ratio": "mu_measured"}},
                                       "missing column 'mu_measured' for friction_ratio"),
    "zero normal force": (["time [s],Ft [N],Fn [N]", "0,1,10", "1,2,10", "2,3,0", "3,3,10",
                           "4,3,10"], {}, "line 4: column 'Fn [N]' = 0 N"),
    "too few samples": (GOOD[:3], {}, "only 2 samples"),
}  # fmt: skip


@pytest.mark.parametrize("case", MALFORMED)
def test_malformed_file_is_refused_in_one_line_naming_file_and_place(tmp_path: Path, case: str):
    lines, kwargs, needle = MALFORMED[case]
    f = tmp_path / "bad.csv"
    f.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError) as info:
        read_tribometer(f, **kwargs)
    message = str(info.value)
    assert message.startswith(f"file '{f}'") and "\n" not in message, message
    assert needle in message, message


def test_a_forced_encoding_that_does_not_fit_is_one_line(tmp_path: Path, curve):
    f = tmp_path / "de.csv"
    f.write_bytes(semicolon_decimal_comma_cp1252(curve))
    with pytest.raises(InputError, match=r"^file '.*de.csv': not utf-8 at byte \d+$"):
        read_tribometer(f, encoding="utf-8")


def test_a_malformed_file_through_calibrate_exits_2_with_one_line(tmp_path: Path, capsys):
    (tmp_path / "run.csv").write_text("\n".join(_with(3, "2,0.2,abc")) + "\n")
    cfg = config("run.csv", ["mu_s"], {}, profile=False)
    del cfg["data"][0]["columns"], cfg["data"][0]["units"]
    path = write_config(tmp_path / "calibrate.toml", cfg)
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "'run.csv' line 4: column 'COF' = 'abc'" in err[0], err


@pytest.mark.slow
def test_data_and_fit_keys_reach_the_reader_and_the_fit(tmp_path: Path, curve) -> None:
    """[[data]] sep, decimal, encoding, reciprocating, columns/units of a force pair,
    segment_weights, time_offset; [fit] starts, seed, band_level."""
    assert curve.slip is not None
    back = (curve.time >= 6.0) & (curve.time < 338.0)
    lines = ["t;Ft;Fn"] + [
        f"{_num(t - 1.0, True)};{_num((-r if b else r) * FN_N, True)};{_num(FN_N, True)}"
        for t, r, b in zip(curve.time, curve.friction_ratio, back, strict=True)
        if t >= 1.0
    ]  # data clock starts 1 s into the programme
    (tmp_path / "run.csv").write_bytes(("\n".join(lines) + "\n").encode("utf-16"))
    cfg = config("run.csv", ["mu_k"], dict(mu_k=0.33), profile=False, starts=2, seed=1,
                 band_level=0.9)  # fmt: skip
    data = cfg["data"][0]
    data["columns"] = {"time": "t", "friction_force": "Ft", "normal_force": "Fn"}
    data["units"] = {"time": "s", "friction_force": "N", "normal_force": "N"}
    data.update(sep=";", decimal=",", encoding="utf-16", reciprocating=True, time_offset=1.0,
                segment_weights=[1.0, 0.0, 1.0, 0.0, 1.0])  # fmt: skip
    path = write_config(tmp_path / "calibrate.toml", cfg)
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    fit = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert fit["parameters"]["mu_k"]["value"] == pytest.approx(TRUE["mu_k"], rel=1e-3)
    lines = (tmp_path / "out" / "curves.csv").read_text().splitlines()
    header = next(ln for ln in lines if not ln.startswith("#"))
    assert "confidence [-]" in header and "prediction [-]" in header
    data["segment_weights"] = [1.0, 2.0]
    bad = write_config(tmp_path / "bad.toml", cfg)
    assert main(["calibrate", str(bad), "--out", str(tmp_path / "out2"), "--quiet"]) == 2
