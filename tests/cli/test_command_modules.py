"""Each command module is a thin declaration: under 100 lines, the work in frictionlab.app."""

from __future__ import annotations

import importlib
import inspect

import pytest

from frictionlab.cli import COMMANDS

#: Commands that write one output set through the pipeline (the others: demo writes a
#: report of sections, sweep a resumable folder of sets, example and bench no set).
PIPELINED = ("simulate", "roughness", "bridge", "calibrate", "contact")


@pytest.mark.parametrize("name", COMMANDS)
def test_command_module_is_under_100_lines(name: str) -> None:
    source = inspect.getsource(importlib.import_module(f"frictionlab.commands.{name}"))
    assert len(source.splitlines()) < 100


@pytest.mark.parametrize("name", PIPELINED)
def test_output_set_commands_run_through_the_pipeline(name: str) -> None:
    source = inspect.getsource(importlib.import_module(f"frictionlab.commands.{name}"))
    # add_workflow_parser and workflow_handler run the workflow through run_command
    assert any(f"{call}(" in source for call in ("add_workflow_parser", "workflow_handler"))
    assert "import check_out" not in source and "import progress_bar" not in source
