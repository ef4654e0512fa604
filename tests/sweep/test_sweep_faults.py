"""A sweep under faults: no orphaned workers after kill -9, non-Dask services and a lost
Dask scheduler give one line and exit 1, with nothing written or the unfinished cases pending.

Every listener here binds 127.0.0.1 only, closes itself after at most LISTEN_S seconds and
is closed by the test as well.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from frictionlab.cli import main
from frictionlab.sweep import executors

from .support import read_sweep_table, write_sweep

#: The longest a fake listener lives [s].
LISTEN_S = 30.0


@contextlib.contextmanager
def fake_listener(answer: bytes | None) -> Iterator[int]:
    """A loopback TCP server that sends ``answer`` on accept (None: stays silent).

    Yields the port; the server stops when the block ends or after LISTEN_S seconds.
    """
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    server.settimeout(0.2)
    stop = threading.Event()
    held: list[socket.socket] = []

    def serve() -> None:
        end = time.monotonic() + LISTEN_S
        while not stop.is_set() and time.monotonic() < end:
            try:
                conn, _ = server.accept()
            except (TimeoutError, OSError):
                continue
            held.append(conn)
            if answer is not None:
                with contextlib.suppress(OSError):
                    conn.sendall(answer)
        for conn in held:
            conn.close()
        server.close()

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        yield server.getsockname()[1]
    finally:
        stop.set()
        thread.join(LISTEN_S)


ANSWERS = {
    "silent": None,  # a listener that never answers (or HTTP: it waits for a request)
    "ssh": b"SSH-2.0-OpenSSH_9.2p1\r\n",
    "http-bytes": b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n",
}


@pytest.mark.parametrize("kind", sorted(ANSWERS))
def test_a_non_dask_service_is_one_line_exit_1_and_nothing_written(
    tmp_path: Path, capsys, monkeypatch, kind: str
) -> None:
    monkeypatch.setattr(executors, "PROBE_TIMEOUT", 1.0)
    sweep = write_sweep(tmp_path, '[grid]\n"law.mu_s" = [0.5, 0.6]\n')
    out = tmp_path / "out"
    started = time.monotonic()
    with fake_listener(ANSWERS[kind]) as port:
        code = main(["sweep", str(sweep), "--out", str(out), "--quiet",
                     "--scheduler", f"tcp://127.0.0.1:{port}"])  # fmt: skip
    assert time.monotonic() - started < 20.0  # bounded: no hang on a silent listener
    err = capsys.readouterr().err
    assert code == 1, err
    assert err.count("\n") == 1 and "not a Dask scheduler" in err
    assert f"127.0.0.1:{port}" in err
    assert not out.exists()  # refused before anything was written


def test_a_closed_port_is_one_line_exit_1(tmp_path: Path, capsys) -> None:
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    sock.close()  # nothing listens there now
    sweep = write_sweep(tmp_path, '[grid]\n"law.mu_s" = [0.5]\n')
    out = tmp_path / "out"
    code = main(["sweep", str(sweep), "--out", str(out), "--scheduler", f"127.0.0.1:{port}"])
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1 and "cannot connect" in err
    assert not out.exists()


def test_probe_accepts_a_real_dask_scheduler() -> None:
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        n_workers=0, processes=False, dashboard_address=None, protocol="tcp", host="127.0.0.1"
    ) as cluster:
        executors.probe_scheduler(cluster.scheduler_address, timeout=10.0)


def _session_members(sid: int) -> list[int]:
    """Ids of the live (non-zombie) processes of session ``sid`` (Linux /proc)."""
    members = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        fields = stat.rsplit(")", 1)[1].split()
        # fields: state ppid pgrp session ...
        if fields[0] != "Z" and int(fields[3]) == sid:
            members.append(int(entry.name))
    return members


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs Linux /proc")
def test_kill_9_of_a_local_sweep_leaves_no_process_behind(tmp_path: Path) -> None:
    sweep = write_sweep(
        tmp_path, '[grid]\n"program.2.duration" = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]\n', steps=40000
    )
    out = tmp_path / "out"
    argv = [sys.executable, "-m", "frictionlab", "sweep", str(sweep), "--out", str(out),
            "--workers", "2", "--no-plots", "--quiet"]  # fmt: skip
    proc = subprocess.Popen(argv, start_new_session=True, stderr=subprocess.DEVNULL)
    sid = proc.pid
    try:
        deadline = time.monotonic() + 120
        # the sweep, its resource tracker and both workers are up
        while len(_session_members(sid)) < 4:
            assert proc.poll() is None, "the sweep ended before it could be killed"
            assert time.monotonic() < deadline, "the pool did not start in 120 s"
            time.sleep(0.05)
        time.sleep(1.0)  # the workers are into their first cases
        proc.send_signal(signal.SIGKILL)  # the parent only, as a user's kill -9 would
        proc.wait()
        end = time.monotonic() + 15.0
        while _session_members(sid) and time.monotonic() < end:
            time.sleep(0.1)
        survivors = _session_members(sid)
        assert survivors == [], f"processes of the killed sweep live on: {survivors}"
    finally:
        for pid in _session_members(sid):
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)


def _free_port() -> int:
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = int(sock.getsockname()[1])
    sock.close()
    return port


@pytest.mark.slow
def test_a_lost_scheduler_is_one_line_exit_1_and_leaves_cases_pending(tmp_path: Path) -> None:
    pytest.importorskip("distributed")
    dask = shutil.which("dask", path=str(Path(sys.executable).parent))
    if dask is None:
        pytest.skip("the dask command is not installed")
    sweep = write_sweep(
        tmp_path, '[grid]\n"program.2.duration" = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]\n', steps=20000
    )
    out = tmp_path / "out"
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    scheduler = subprocess.Popen(
        [dask, "scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard"],
        **quiet,
    )
    worker = None
    try:
        worker = subprocess.Popen(
            [dask, "worker", address, "--nworkers", "1", "--nthreads", "1", "--no-dashboard"],
            **quiet,
        )
        argv = [sys.executable, "-m", "frictionlab", "sweep", str(sweep), "--out", str(out),
                "--scheduler", address, "--no-plots", "--quiet"]  # fmt: skip
        time.sleep(2.0)
        sweep_proc = subprocess.Popen(argv, stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 150
        while not list(out.glob("cases/*/case.json")):
            assert sweep_proc.poll() is None, sweep_proc.communicate()[1]
            assert time.monotonic() < deadline, "no case finished in 150 s"
            time.sleep(0.05)
        scheduler.kill()
        scheduler.wait()
        _, err = sweep_proc.communicate(timeout=60)
    finally:
        for p in (scheduler, worker):
            if p is not None and p.poll() is None:
                p.kill()
                p.wait()
    assert sweep_proc.returncode == 1, err
    assert err.count("\n") == 1 and "lost the Dask scheduler" in err, err
    table = read_sweep_table(out)
    done = table["status"] == "ok"
    assert done.sum() >= 1 and set(table["status"][~done]) == {"pending"}
    assert "failed" not in set(table["status"])
