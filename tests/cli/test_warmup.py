"""``frictionlab warmup`` compiles every kernel family the commands use."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import frictionlab.subloading as subloading
from frictionlab import warmup as warmup_module
from frictionlab.cli import main


def test_warmup_calls_every_surface_in_both_loops_with_and_without_tangent(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    seen: set[tuple[str, bool, bool]] = set()

    def spy(params: Any, state: Any, *, slip_increment: Any, time_increment: float,
            tangent: bool = True) -> None:  # fmt: skip
        parallel = np.asarray(slip_increment).shape[0] >= warmup_module.PARALLEL_POINTS
        seen.add((params.surface, parallel, tangent))

    monkeypatch.setattr(subloading, "update", spy)
    warmup_module._law()
    expected = {
        (s, p, t) for s in subloading.SURFACES for p in (False, True) for t in (False, True)
    }
    assert seen == expected


def test_warmup_command_reports_every_step(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[str] = []
    steps = tuple(
        (label, lambda label=label: calls.append(label)) for label, _ in warmup_module.STEPS
    )
    monkeypatch.setattr(warmup_module, "STEPS", steps)  # the wiring, not the compilation
    assert main(["warmup"]) == 0
    assert calls == [label for label, _ in steps]
    captured = capsys.readouterr()
    for label, _ in warmup_module.STEPS:
        assert label in captured.err
    assert "compiled kernels ready in" in captured.out


@pytest.mark.parametrize("points", [[3, 40], [3, warmup_module.PARALLEL_POINTS]])
def test_a_simulate_warms_the_law_loops_it_uses_and_the_driver(
    points: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    seen: set[bool] = set()

    def spy(params: Any, state: Any, *, slip_increment: Any, time_increment: float,
            tangent: bool = True) -> None:  # fmt: skip
        seen.add(np.asarray(slip_increment).shape[0] >= warmup_module.PARALLEL_POINTS)

    monkeypatch.setattr(subloading, "update", spy)
    steps = warmup_module.steps_for("simulate", points)
    assert [label for label, _ in steps][1:] == [warmup_module.STEPS[1][0]]  # the driver
    steps[0][1]()
    assert seen == ({False, True} if max(points) >= warmup_module.PARALLEL_POINTS else {False})
    assert warmup_module.steps_for("roughness") == (warmup_module.STEPS[2],)  # the lattice


def test_warmup_byte_compiles_modules_even_when_python_would_not(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The modules a first command imports are compiled once, by the warm-up."""
    package = tmp_path / "pkg"
    (package / "sub").mkdir(parents=True)
    sources = [package / "__init__.py", package / "sub" / "mod.py"]
    for source in sources:
        source.write_text("X = 1\n", encoding="utf-8")
    monkeypatch.setattr(sys, "dont_write_bytecode", True)  # PYTHONDONTWRITEBYTECODE=1
    assert "bytecode of frictionlab's modules" in dict(warmup_module.STEPS)
    warmup_module._bytecode(package)
    for source in sources:
        cached = Path(importlib.util.cache_from_source(str(source)))
        assert cached.is_file() and cached.read_bytes()[:4] == importlib.util.MAGIC_NUMBER
