"""The one progress convention: ``progress(done, total)``, made by a :data:`ProgressFactory`.

A factory takes a description and returns a context manager yielding the callback (the
command line's is :func:`frictionlab.commands._progress.progress_bar`).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator

__all__ = ["Progress", "ProgressFactory", "no_progress"]

#: ``progress(done, total)``: ``done`` of ``total`` units of work are finished.
Progress = Callable[[int, int], None]

#: ``factory(description)`` -> a context manager yielding a :data:`Progress` callback.
ProgressFactory = Callable[[str], contextlib.AbstractContextManager[Progress]]


@contextlib.contextmanager
def no_progress(description: str) -> Iterator[Progress]:
    """A :data:`ProgressFactory` that reports nothing."""
    yield lambda done, total: None
