"""The command-line entry points."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from frictionlab import __version__
from frictionlab.cli import main
from frictionlab.commands.example import EXAMPLES, starter_text


def test_module_entry_point_reports_the_version() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "frictionlab", "--version"], capture_output=True, text=True
    )
    assert out.returncode == 0 and __version__ in out.stdout


def test_no_command_is_bad_usage() -> None:
    assert main([]) == 2
    assert main(["no-such-command"]) == 2
    assert main(["simulate"]) == 2  # missing scenario and --out


def _run(*args: str, module: bool) -> subprocess.CompletedProcess[str]:
    head = [sys.executable, "-m", "frictionlab"] if module else [str(SCRIPT)]
    return subprocess.run([*head, *args], capture_output=True, text=True, timeout=120)


SCRIPT = Path(sys.executable).with_name("frictionlab")


@pytest.mark.skipif(not SCRIPT.exists(), reason="the frictionlab script is not installed here")
@pytest.mark.parametrize("args", [("--help",), ("example", "nope")])  # exit 0, exit 2
def test_python_dash_m_behaves_like_the_script(args: tuple[str, ...]) -> None:
    a, b = _run(*args, module=True), _run(*args, module=False)
    assert (a.returncode, a.stdout, a.stderr) == (b.returncode, b.stdout, b.stderr)


def test_help_points_to_docs_examples_and_scenarios(capsys) -> None:
    assert main(["--help"]) == 0
    text = capsys.readouterr().out
    assert "docs/" in text and "frictionlab example" in text and "scenarios" in text
    assert main(["demo", "--help"]) == 0
    assert "report.html" in capsys.readouterr().out.split("options:")[0]


def test_unknown_key_suggests_the_nearest(tmp_path: Path, capsys) -> None:
    path = tmp_path / "s.toml"
    path.write_text(starter_text("simulate").replace("mu_k =", "muk ="))
    assert main(["simulate", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "unknown key [law].muk (did you mean 'mu_k'?)" in err and err.count("\n") == 1


def test_example_lists_and_rejects_with_a_hint(capsys) -> None:
    assert main(["example"]) == 0
    assert set(capsys.readouterr().out.split()) >= set(EXAMPLES)
    assert main(["example", "roughnes"]) == 2
    assert "did you mean 'roughness'?" in capsys.readouterr().err


@pytest.mark.parametrize("name", list(EXAMPLES))
def test_every_example_runs_as_printed(name: str, tmp_path: Path, capsys) -> None:
    assert main(["example", name]) == 0
    printed = capsys.readouterr().out
    command = next(line for line in printed.splitlines() if "--out" in line).split()[1:]
    assert command[0] == "frictionlab", "the first lines say how to run it"
    folder = tmp_path / "work"
    assert main(["example", name, "--write", str(folder)]) == 0
    assert (folder / f"{name}.toml").read_text() == printed  # --write writes what is printed
    kind, scenario = command[1], folder / command[2]
    out = tmp_path / "out"
    plots = [] if kind == "calibrate" else ["--no-plots"]
    assert main([kind, str(scenario), "--out", str(out), "--quiet", *plots]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary.get("success", True) is True


#: A child process running the console command's entry with an exit handler, buffered
#: output and (with "thread") a non-daemon thread still writing when main() returns.
_RUN = """
import atexit, sys, threading, time
marks = sys.argv[1]
atexit.register(lambda: open(marks + ".atexit", "w").write("ran"))
if sys.argv[2] == "thread":
    def late():
        time.sleep(0.5)
        open(marks + ".thread", "w").write("done")
    threading.Thread(target=late).start()
sys.argv = ["frictionlab", "example", "nope"]
from frictionlab.cli import run
print("buffered line", end="")  # block-buffered into a pipe: lost unless flushed
run()
"""


@pytest.mark.parametrize("thread", ["none", "thread"])
def test_quick_exit_keeps_the_exit_code_handlers_output_and_threads(
    tmp_path: Path, thread: str
) -> None:
    marks = str(tmp_path / "m")
    out = subprocess.run([sys.executable, "-c", _RUN, marks, thread], capture_output=True,
                         text=True, timeout=120)  # fmt: skip
    assert out.returncode == 2, out.stderr  # "example nope": bad input
    assert "buffered line" in out.stdout and "is unknown" in out.stderr
    assert Path(marks + ".atexit").read_text() == "ran"
    if thread == "thread":
        assert Path(marks + ".thread").read_text() == "done"
