"""Where a sweep's cases run: a local process pool or a Dask cluster.

:func:`run_tasks` yields the :class:`~frictionlab.app.sweep_task.TaskResult` of each
case as it finishes. Both executors keep the sweep's promises:

* **local pool**: every worker process dies with the sweep's own process (Linux
  ``PR_SET_PDEATHSIG``, and on every system a thread that polls the parent's id), so a
  ``kill -9`` of the sweep leaves no worker finishing cases for nothing; a worker that
  dies is a failed case, not a crash;
* **Dask** (``--scheduler ADDRESS``): :func:`probe_scheduler` checks, before the sweep
  writes anything, that a Dask scheduler answers at the address (a Dask server sends its
  handshake as soon as a connection is accepted: a silent listener, an HTTP or SSH server
  is refused at once instead of hanging or being read as a huge frame). A scheduler lost
  during the run raises :class:`SchedulerError` (exit 1, one line): the cases not yet
  finished have no record, so they stay ``pending`` and a re-run finishes them.
  distributed's own log lines and warnings are kept off the terminal.
"""

from __future__ import annotations

import contextlib
import logging
import os
import signal
import socket
import sys
import threading
import time
import warnings
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING
from urllib.parse import urlsplit

from frictionlab.errors import FrictionlabError, InputError

if TYPE_CHECKING:
    from frictionlab.app.sweep_task import Task, TaskResult

__all__ = ["SchedulerError", "probe_scheduler", "run_tasks"]

#: Seconds a scheduler has to send its handshake after accepting a connection.
PROBE_TIMEOUT = 5.0
#: Bytes a Dask handshake carries (a msgpack key of ``Comm.handshake_info``).
_HANDSHAKE_KEY = b"pickle-protocol"
#: Seconds between two checks of the parent's id in a pool worker.
PARENT_POLL = 0.5
#: Loggers of distributed and of the libraries it logs through.
_QUIET_LOGGERS = ("distributed", "tornado", "asyncio", "bokeh")

_PR_SET_PDEATHSIG = 1


class SchedulerError(FrictionlabError):
    """The Dask scheduler cannot be used or was lost: a computation failure (exit 1)."""


def run_tasks(
    tasks: Sequence[Task], scheduler: str | None, workers: int | None
) -> Iterator[TaskResult]:
    """Results in order of completion (a lost worker is a failed case, not a crash)."""
    if not tasks:
        return iter(())
    if scheduler is not None:
        return _on_dask(tasks, scheduler)
    return _on_pool(tasks, workers or min(os.cpu_count() or 1, len(tasks)))


# ---------------------------------------------------------------------------- local pool


def die_with_parent(parent: int) -> None:
    """Pool initializer: end this process when ``parent`` (the sweep) ends.

    Linux delivers SIGKILL at the parent's death (``PR_SET_PDEATHSIG``); a daemon thread
    polls the parent's id every :data:`PARENT_POLL` s as well (other systems, and a
    parent that died before the first line of this function).
    """
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
    if os.getppid() != parent:
        os._exit(1)

    def watch() -> None:
        while True:
            time.sleep(PARENT_POLL)
            if os.getppid() != parent:
                os._exit(1)

    threading.Thread(target=watch, name="frictionlab-parent-watch", daemon=True).start()


def _on_pool(tasks: Sequence[Task], workers: int) -> Iterator[TaskResult]:
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    from frictionlab.app.sweep_task import run_task

    context = multiprocessing.get_context("spawn")  # no fork of a threaded parent
    pool = ProcessPoolExecutor(
        max_workers=workers,
        mp_context=context,
        initializer=die_with_parent,
        initargs=(os.getpid(),),
    )
    try:
        futures = {pool.submit(run_task, task): task for task in tasks}
        for future in as_completed(futures):
            yield _result(futures[future], future.result)
    finally:  # on Ctrl-C: drop the queued cases (a re-run does them), let running ones end
        pool.shutdown(wait=True, cancel_futures=True)


def _result(task: Task, get: Callable[[], TaskResult]) -> TaskResult:
    from frictionlab.app.sweep_task import TaskResult

    try:
        return get()
    except Exception as exc:  # the worker died or the cluster lost the task
        return TaskResult(task.case_id, False, f"worker lost: {type(exc).__name__}: {exc}", 0.0, {})


# ---------------------------------------------------------------------------------- Dask


def _host_port(address: str) -> tuple[str, int] | None:
    """``(host, port)`` of a ``tcp://`` (or scheme-less) address; None for other schemes."""
    text = address if "://" in address else f"tcp://{address}"
    parts = urlsplit(text)
    if parts.scheme != "tcp":
        return None
    try:
        port = parts.port
    except ValueError:
        raise InputError(f"--scheduler {address}: the port is not a number 0..65535") from None
    if not parts.hostname or port is None:
        raise InputError(f"--scheduler {address}: allowed an address like tcp://HOST:PORT")
    return parts.hostname, port


def probe_scheduler(address: str, timeout: float | None = None) -> None:
    """Raise :class:`SchedulerError` (one line) unless a Dask scheduler answers at ``address``.

    Only ``tcp://`` addresses are probed (TLS and other transports are left to the
    client). A Dask server writes its handshake on accept; anything else (no answer
    within ``timeout`` s, default :data:`PROBE_TIMEOUT`; other bytes; a closed
    connection) is not a scheduler.
    """
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise InputError(
            "--scheduler needs dask.distributed: pip install 'frictionlab[dask]'"
        ) from None
    target = _host_port(address)
    if target is None:
        return
    timeout = PROBE_TIMEOUT if timeout is None else timeout
    where = f"--scheduler {address}"
    try:
        sock = socket.create_connection(target, timeout=timeout)
    except TimeoutError:
        raise SchedulerError(f"{where}: no answer within {timeout:g} s") from None
    except OSError as exc:
        raise SchedulerError(f"{where}: cannot connect: {exc.strerror or exc}") from None
    received = b""
    deadline = time.monotonic() + timeout
    try:
        with sock:
            while _HANDSHAKE_KEY not in received and len(received) < 4096:
                left = deadline - time.monotonic()
                if left <= 0:
                    break
                sock.settimeout(left)
                chunk = sock.recv(4096)
                if not chunk:
                    break
                received += chunk
                if len(received) >= 8 and int.from_bytes(received[:8], "little") > 2**20:
                    break  # a Dask frame opens with its (small) header length
    except TimeoutError:
        pass
    except OSError as exc:
        raise SchedulerError(f"{where}: connection failed: {exc.strerror or exc}") from None
    if _HANDSHAKE_KEY in received:
        return
    if not received:
        what = "accepted the connection but sent nothing"
        what += f" within {timeout:g} s" if time.monotonic() >= deadline else " and closed it"
    else:
        shown = received[:24].decode("ascii", "replace").splitlines()[0] if received else ""
        what = f"answered with something else ({shown!r}...)"
    raise SchedulerError(f"{where}: not a Dask scheduler: it {what}")


@contextlib.contextmanager
def quiet_distributed() -> Iterator[None]:
    """Keep distributed's log lines and warnings off the terminal for the block."""
    import distributed  # noqa: F401  (its loggers exist once it is imported)

    loggers = [
        logger
        for name, logger in list(logging.root.manager.loggerDict.items())
        if isinstance(logger, logging.Logger) and name.split(".")[0] in _QUIET_LOGGERS
    ]
    saved = [(logger, logger.disabled) for logger in loggers]
    for logger in loggers:  # each child logger has its own level: disable them all
        logger.disabled = True
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            yield
    finally:
        for logger, disabled in saved:
            logger.disabled = disabled


def _on_dask(tasks: Sequence[Task], address: str) -> Iterator[TaskResult]:
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise InputError(
            "--scheduler needs dask.distributed: pip install 'frictionlab[dask]'"
        ) from None
    with quiet_distributed():
        yield from _dask_results(tasks, address)


def _dask_results(tasks: Sequence[Task], address: str) -> Iterator[TaskResult]:
    from distributed import Client, as_completed

    from frictionlab.app.sweep_task import run_task

    where = f"--scheduler {address}"
    try:
        client = Client(address, timeout="10s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise SchedulerError(f"{where}: cannot connect: {exc}") from None
    done = 0
    try:
        futures = client.map(run_task, list(tasks), key=[f"sweep-{t.case_id}" for t in tasks])
        by_key = {f.key: t for f, t in zip(futures, tasks, strict=True)}
        for future in as_completed(futures):
            if future.status == "cancelled" or client.status not in ("running", "newly-created"):
                # never cancelled by the sweep: the scheduler went away (or dropped the task)
                raise SchedulerError(
                    f"{where}: lost the Dask scheduler after {done} of {len(tasks)} cases; "
                    "the unfinished cases are left pending: run the same command again to "
                    "finish them"
                )
            done += 1
            yield _result(by_key[future.key], future.result)
    finally:
        with contextlib.suppress(Exception):
            client.close(timeout=2)
