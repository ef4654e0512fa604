"""The one way figures become PNG files: :data:`DPI`, rendered by Agg, written atomically.

A figure given fixed margins by :func:`fixed_layout` is drawn without a layout solve (the
constrained layout measures every axes' ticks and texts twice before drawing: about 40 %
of a small figure's drawing); after the draw :func:`figure_png_bytes` checks that every
drawn text lies inside the figure and clear of the other axes, and where one does not,
draws the figure again with the constrained layout.
"""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from frictionlab.io.atomic import write_bytes_atomic
from frictionlab.plotting._ticks import readable_log_ticks

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["DPI", "figure_png_bytes", "fixed_layout", "save_figure", "texts_fit"]

#: Resolution of every PNG frictionlab writes (dots per inch).
DPI = 120
#: Set on a figure laid out by :func:`fixed_layout` (the constrained layout is its fall-back).
_FIXED = "_frictionlab_fixed_layout"
#: Overlap tolerated between a text and a neighbour [pixels] (anti-aliasing, rounding).
_SLACK = 1.0


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
    if getattr(fig, _FIXED, False) and not texts_fit(fig):
        setattr(fig, _FIXED, False)
        fig.set_layout_engine("constrained")
        canvas.draw()
    buffer = io.BytesIO()
    imsave(buffer, canvas.buffer_rgba(), format="png", origin="upper", dpi=DPI)
    return buffer.getvalue()


def save_figure(fig: Figure, path: str | os.PathLike[str]) -> Path:
    """Write ``fig`` as PNG to ``path`` atomically and return the path."""
    return write_bytes_atomic(Path(path), figure_png_bytes(fig))


def fixed_layout(
    fig: Figure,
    left: float,
    right: float,
    top: float,
    bottom: float,
    wspace: float = 0.0,
    hspace: float = 0.0,
) -> Figure:
    """Give ``fig`` (built without a layout engine, on one grid of subplots, with no colour
    bar: one made without the engine does not move with it) fixed margins and gaps
    [inches]; :func:`figure_png_bytes` falls back to the constrained layout where
    a text would not fit. Returns ``fig``."""
    from matplotlib.gridspec import GridSpec

    width, height = fig.get_size_inches()
    specs = [ax.get_subplotspec() for ax in fig.axes]
    (grid,) = {spec.get_gridspec() for spec in specs if spec is not None} or {GridSpec(1, 1)}
    rows, cols = grid.get_geometry()
    ax_w = (width - left - right - (cols - 1) * wspace) / cols
    ax_h = (height - top - bottom - (rows - 1) * hspace) / rows
    fig.subplots_adjust(
        left=left / width, right=1.0 - right / width, bottom=bottom / height,
        top=1.0 - top / height, wspace=wspace / ax_w, hspace=hspace / ax_h,
    )  # fmt: skip
    setattr(fig, _FIXED, True)
    return fig


def _drawn_texts(fig: Figure) -> list[tuple[Any, Any]]:
    """(owner axes or None, window extent) of every non-empty text the last draw showed."""
    from matplotlib.text import Text

    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    out: list[tuple[Any, Any]] = []

    def add(owner: Any, text: Text) -> None:
        if text.get_visible() and text.get_text():
            out.append((owner, text.get_window_extent(renderer)))

    for text in fig.texts:  # the suptitle too
        add(None, text)
    for ax in fig.axes:
        for child in ax.get_children():  # titles, texts
            if isinstance(child, Text):
                add(ax, child)
        for axis in (ax.xaxis, ax.yaxis):
            add(ax, axis.label)
            add(ax, axis.offsetText)
            low, high = sorted(axis.get_view_interval())
            for tick in (*axis.majorTicks, *axis.minorTicks):
                if low <= tick.get_loc() <= high:  # drawn (ticks beyond the view are not)
                    for label in (tick.label1, tick.label2):
                        add(ax, label)
        legend = ax.get_legend()
        if legend is not None and legend.get_visible():
            out.append((ax, legend.get_window_extent(renderer)))
    return out


def texts_fit(fig: Figure) -> bool:
    """After a draw: every drawn text inside the figure, none over another axes' frame or
    another axes' texts (titles, labels, tick labels, legends)."""
    box = fig.bbox
    texts = _drawn_texts(fig)
    for owner, ext in texts:
        if (ext.x0 < box.x0 - _SLACK or ext.y0 < box.y0 - _SLACK
                or ext.x1 > box.x1 + _SLACK or ext.y1 > box.y1 + _SLACK):  # fmt: skip
            return False
        for ax in fig.axes:
            if ax is not owner and _overlap(ext, ax.bbox):
                return False
    for i, (owner, ext) in enumerate(texts):
        for other, ext2 in texts[i + 1 :]:
            if other is not owner and _overlap(ext, ext2):
                return False
    return True


def _overlap(a: Any, b: Any) -> bool:
    """Whether two boxes overlap by more than :data:`_SLACK` pixels in both directions."""
    return (min(a.x1, b.x1) - max(a.x0, b.x0) > _SLACK
            and min(a.y1, b.y1) - max(a.y0, b.y0) > _SLACK)  # fmt: skip
