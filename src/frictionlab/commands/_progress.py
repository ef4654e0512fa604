"""A terminal progress bar for long computations (tqdm), shown after one second."""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Callable, Iterator


@contextlib.contextmanager
def progress_bar(description: str, enabled: bool = True) -> Iterator[Callable[[int, int], None]]:
    """Yield a ``progress(done, total)`` callback driving a tqdm bar on stderr.

    The bar appears only when the work lasts more than a second and stderr is a
    terminal (or never when ``enabled`` is False); it is removed when done.
    """
    from tqdm import tqdm

    bar = tqdm(
        total=None,
        desc=description,
        unit="step",
        delay=1.0,
        leave=False,
        file=sys.stderr,
        disable=None if enabled else True,
        dynamic_ncols=True,
    )

    def update(done: int, total: int) -> None:
        if bar.total != total:
            bar.total = total
        bar.update(done - bar.n)

    try:
        yield update
    finally:
        bar.close()
