"""Progress of long computations on stderr: a tqdm bar on a terminal, log lines elsewhere.

Both appear only once the work has lasted ``delay`` seconds (1 s). Off a terminal (a log
file, a batch job, a pipe) a bar's carriage returns would garble the file, so the work
is reported as plain lines ``frictionlab: DESCRIPTION: 12/91 (13 %), 4.2 s elapsed`` at
most every ``interval`` seconds (10 s), and a last line when it finishes.
"""

from __future__ import annotations

import contextlib
import sys
import time
from collections.abc import Callable, Iterator
from typing import TextIO

__all__ = ["progress_bar", "progress_lines"]


@contextlib.contextmanager
def progress_bar(
    description: str, enabled: bool = True, stream: TextIO | None = None
) -> Iterator[Callable[[int, int], None]]:
    """Yield a ``progress(done, total)`` callback reporting on ``stream`` (stderr).

    A tqdm bar when the stream is a terminal (removed when done), log lines
    (:func:`progress_lines`) otherwise; nothing when ``enabled`` is False.
    """
    out = sys.stderr if stream is None else stream
    if not enabled:
        yield lambda done, total: None
        return
    if not _isatty(out):
        with progress_lines(description, out) as update:
            yield update
        return
    from tqdm import tqdm

    bar = tqdm(
        total=None,
        desc=description,
        unit="step",
        delay=1.0,
        leave=False,
        file=out,
        dynamic_ncols=True,
    )

    def advance(done: int, total: int) -> None:
        if bar.total != total:
            bar.total = total
        bar.update(done - bar.n)

    try:
        yield advance
    finally:
        bar.close()


@contextlib.contextmanager
def progress_lines(
    description: str,
    stream: TextIO,
    *,
    delay: float = 1.0,
    interval: float = 10.0,
    clock: Callable[[], float] = time.monotonic,
) -> Iterator[Callable[[int, int], None]]:
    """Yield ``progress(done, total)`` writing one line per ``interval`` seconds.

    Silent for work shorter than ``delay`` seconds; once a line has been written, the
    finish (``done == total``) is written too.
    """
    start = clock()
    state = {"last": start - interval + delay, "wrote": False, "finished": False}

    def line(done: int, total: int, now: float) -> None:
        share = f" ({100.0 * done / total:.0f} %)" if total > 0 else ""
        stream.write(
            f"frictionlab: {description}: {done}/{total}{share}, {now - start:.1f} s elapsed\n"
        )
        stream.flush()
        state["last"], state["wrote"] = now, True

    def update(done: int, total: int) -> None:
        now = clock()
        finished = total > 0 and done >= total
        due = now - float(state["last"]) >= interval
        if (finished and state["wrote"] and not state["finished"]) or (due and not finished):
            line(done, total, now)
        state["finished"] = finished

    yield update


def _isatty(stream: TextIO) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # a closed or file-like stream without a terminal
        return False
