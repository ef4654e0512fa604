"""The command-line entry points."""

from __future__ import annotations

import subprocess
import sys

from frictionlab import __version__
from frictionlab.cli import main


def test_module_entry_point_reports_the_version() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "frictionlab", "--version"], capture_output=True, text=True
    )
    assert out.returncode == 0 and __version__ in out.stdout


def test_no_command_is_bad_usage() -> None:
    assert main([]) == 2
    assert main(["no-such-command"]) == 2
    assert main(["simulate"]) == 2  # missing scenario and --out
