"""The contact gallery script runs and its fretting peaks respect the law's bounds."""

from __future__ import annotations

import ast
import runpy
import sys
from pathlib import Path

import pytest

pytest.importorskip("skfem")

SCRIPT = Path(__file__).resolve().parents[2] / "examples" / "contact_fretting.py"


@pytest.mark.slow
def test_contact_fretting_py_writes_its_figure_with_peaks_between_mu_k_and_mu_s(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """ "contact_fretting.py": in gross slip Q/P of the subloading law lies in [mu_k, mu_s].

    On the script's documented ``--coarse`` setting (the demo's a/6 mesh, a third of the
    steps): the bounds are the law's, met on any mesh; the default a/20 run makes the figure.
    """
    out = tmp_path / "fretting.png"
    monkeypatch.setattr(sys, "argv", [str(SCRIPT), "--out", str(out), "--coarse"])
    with pytest.raises(SystemExit) as done:
        runpy.run_path(str(SCRIPT), run_name="__main__")
    assert done.value.code == 0
    assert out.stat().st_size > 10_000
    line = next(t for t in capsys.readouterr().out.splitlines() if "peak" in t)
    peaks = ast.literal_eval(line[line.index("[") :])
    assert len(peaks) == 3
    assert all(0.4 <= p <= 0.6 for p in peaks), peaks  # mu_k = 0.4, mu_s = 0.6
