"""examples/slide_hold_slide.py and examples/stick_slip.py run and their numbers hold."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.slow
def test_slide_hold_slide_example(tmp_path: Path, run_script) -> None:  # type: ignore[no-untyped-def]
    out = run_script(EXAMPLES / "slide_hold_slide.py", str(tmp_path))
    assert out.returncode == 0, out.stderr
    rows = np.loadtxt(tmp_path / "restart_peaks.csv", delimiter=",", skiprows=1)
    hold, mu_end, closed, peak = rows.T
    np.testing.assert_array_equal(hold, [1.0, 10.0, 100.0, 1000.0, 1e4])
    np.testing.assert_allclose(mu_end, closed, rtol=1e-12)  # hold recovery in closed form
    assert np.all(np.diff(peak) > 0) and np.all(peak <= 0.5)
    assert (tmp_path / "friction.png").stat().st_size > 1000


@pytest.mark.slow
def test_stick_slip_example(tmp_path: Path, run_script) -> None:  # type: ignore[no-untyped-def]
    out = run_script(EXAMPLES / "stick_slip.py", str(tmp_path))
    assert out.returncode == 0, out.stderr
    regimes = [
        line.split()[-1] for line in out.stdout.splitlines() if line[:6].strip()[:1].isdigit()
    ]
    assert regimes == ["stick-slip", "stick-slip", "sliding", "sliding"]
    assert (tmp_path / "stick_slip.png").is_file()
