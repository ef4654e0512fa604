"""The sweep overview: each summary figure against the first swept key, one line per value
of the other keys (or against the case number when the first key is not numeric)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from frictionlab.plotting._ticks import readable_log_ticks
from frictionlab.plotting.roughness import new_figure

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

__all__ = ["sweep_figure"]

#: At most this many summary figures get a panel.
MAX_PANELS = 4


def sweep_figure(table: pd.DataFrame, keys: list[str], title: str = "") -> Figure:
    """One panel per summary figure (the numeric columns after the swept keys)."""
    start = 3 + len(keys)
    names = [
        c for c in table.columns[start:]
        if c not in ("seconds", "error") and table[c].notna().any()
    ][:MAX_PANELS]  # fmt: skip
    fig = new_figure(5.0 * max(1, min(len(names), 2)), 3.6 * max(1, (len(names) + 1) // 2))
    ok = table[table["status"] == "ok"]
    units = table.attrs.get("units", {})
    x_key = keys[0] if keys and _numeric(ok[keys[0]]) else None
    groups = [k for k in keys if k != x_key][:3]
    if not names:
        ax = fig.add_subplot()
        ax.text(0.5, 0.5, "no case finished", ha="center", va="center", transform=ax.transAxes)
        ax.set_axis_off()
    cols = 1 if len(names) == 1 else 2
    for i, name in enumerate(names):
        ax = fig.add_subplot((len(names) + 1) // 2, cols, i + 1)
        for label, part in ok.groupby(groups, sort=True) if groups else [("", ok)]:
            x = part[x_key].to_numpy(float) if x_key else part["case"].to_numpy(float)
            y = part[name].to_numpy(float)
            order = np.argsort(x)
            ax.plot(x[order], y[order], marker="o", label=_label(groups, label, units))
        positive = x_key is not None and bool((ok[x_key].astype(float) > 0).all())
        if positive and ok[x_key].astype(float).max() >= 100 * ok[x_key].astype(float).min():
            ax.set_xscale("log")
        ax.set_xlabel(_titled(x_key, units) if x_key else "case")
        ax.set_ylabel(_titled(name, units))
        ax.grid(alpha=0.3)
        if groups and i == 0:
            ax.legend(fontsize=7)
    failed = int((table["status"] == "failed").sum())
    note = f" ({failed} failed)" if failed else ""
    fig.suptitle(f"{title or 'sweep'}: {len(ok)} of {len(table)} cases{note}", fontsize=10)
    readable_log_ticks(fig)
    return fig


def _titled(name: str, units: Any) -> str:
    unit = units.get(name)
    return name if unit is None else f"{name} [{unit}]"


def _numeric(column: Any) -> bool:
    try:
        column.astype(float)
    except (TypeError, ValueError):
        return False
    return len(column) > 0


def _label(groups: list[str], value: Any, units: Any) -> str | None:
    if not groups:
        return None
    values = value if isinstance(value, tuple) else (value,)
    shown = (
        f"{k} = {v}" + (f" {units[k]}" if units.get(k) not in (None, "-") else "")
        for k, v in zip(groups, values, strict=False)
    )
    return ", ".join(shown)
