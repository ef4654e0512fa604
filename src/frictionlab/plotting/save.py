"""The one way figures become PNG files: :data:`DPI`, rendered by Agg, written atomically."""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import TYPE_CHECKING

from frictionlab.io.atomic import write_bytes_atomic
from frictionlab.plotting._ticks import readable_log_ticks

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["DPI", "figure_png_bytes", "save_figure"]

#: Resolution of every PNG frictionlab writes (dots per inch).
DPI = 120


def figure_png_bytes(fig: Figure) -> bytes:
    """Render ``fig`` to PNG bytes in memory (Agg); log axes get readable ticks.

    The same pixels and file as ``fig.savefig(buffer, format="png", dpi=DPI)``, drawn
    once instead of twice: with a layout engine, ``savefig`` draws the whole figure
    once to run the layout and again to render, while the canvas's own draw runs the
    layout and renders in one pass (tests/plotting/test_save.py compares the bytes).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.image import imsave

    canvas = FigureCanvasAgg(fig)
    readable_log_ticks(fig)
    fig.set_dpi(DPI)
    canvas.draw()
    buffer = io.BytesIO()
    imsave(buffer, canvas.buffer_rgba(), format="png", origin="upper", dpi=DPI)
    return buffer.getvalue()


def save_figure(fig: Figure, path: str | os.PathLike[str]) -> Path:
    """Write ``fig`` as PNG to ``path`` atomically and return the path."""
    return write_bytes_atomic(Path(path), figure_png_bytes(fig))
