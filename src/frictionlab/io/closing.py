"""The context-manager protocol of objects that hold a file until :meth:`Closing.close`."""

from __future__ import annotations

from typing import Self


class Closing:
    """``with obj:`` gives ``obj`` and closes it on the way out (also after an error)."""

    def close(self) -> None:
        """Release what the object holds (each subclass says what)."""
        raise NotImplementedError

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()
