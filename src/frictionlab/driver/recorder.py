"""What a simulation keeps: recorded rows, streamed chunks and running figures.

:class:`Recording` says which rows are recorded (every k-th step of each segment, its
first and last steps always; chosen points only) and where they go: to a ``sink``
callable, in chunks of ``chunk_rows`` rows as they are computed, and to the
:class:`~frictionlab.driver.simulate.History` returned in memory (every recorded row,
or, with ``keep_rows``, at most about that many rows, thinned evenly with the segment
ends kept).

:class:`Recorder` does the bookkeeping for the driver. Whatever is recorded, it updates
running figures on *every* step for *every* point (:class:`RunStats`: peak friction
ratio and when it happened, the slip path length, per-segment start, peak and final
values), so the summaries do not depend on ``every``. Its memory is bounded by
``chunk_rows + keep_rows`` rows whatever the number of steps when a sink and
``keep_rows`` are given.

A chunk handed to the sink is a dict of arrays, time first, valid only during the call:
``step``, ``segment``, ``kind``, ``substeps`` (rows,); ``point`` (m,) 1-based point
numbers; ``time``, ``approach``, ``F``, ``R``, ``plastic_slip``, ``plastic_work``,
``status``, ``iterations`` (rows, m); ``slip`` (rows, m, 2); ``traction`` (rows, m, 3).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from frictionlab.driver._running import accumulate, accumulate_row, slip_lengths
from frictionlab.errors import ParameterError

__all__ = ["Recorder", "Recording", "RowSink", "RunStats", "SegmentStats"]

#: ``sink(chunk)``: receives each chunk of recorded rows (see the module docstring).
RowSink = Callable[[dict[str, np.ndarray]], None]

#: Per-point series of a row: name -> (trailing shape, dtype).
POINT_FIELDS: dict[str, tuple[tuple[int, ...], Any]] = {
    "time": ((), np.float64),
    "slip": ((2,), np.float64),
    "approach": ((), np.float64),
    "traction": ((3,), np.float64),
    "F": ((), np.float64),
    "R": ((), np.float64),
    "plastic_slip": ((), np.float64),
    "plastic_work": ((), np.float64),
    "status": ((), np.int8),
    "iterations": ((), np.int64),
}
#: Bytes of one recorded row per point (the fields above).
ROW_BYTES = 97
#: Largest chunk of rows [bytes] the recorder buffers before handing it on.
CHUNK_BYTES = 8 * 2**20
#: Per-row values shared by the points.
ROW_FIELDS = ("step", "segment", "substeps", "solves")
_INTERNAL = ("_index", "_end")  # recorded-row counter; segment end (kept when thinning)
_ALIGN = 64  # bytes: start of each field in the recorder's block of rows (a cache line)


def _ratio(traction: np.ndarray) -> np.ndarray:
    """|f_t| / f_n, 0 where open."""
    fn = traction[:, 2]
    out = np.hypot(traction[:, 0], traction[:, 1])
    closed = fn > 0.0
    np.divide(out, fn, out=out, where=closed)
    out[~closed] = 0.0
    return out


@dataclass(frozen=True)
class Recording:
    """What :func:`~frictionlab.driver.simulate.simulate` records.

    every:
        Record every k-th step of each segment (its first and last steps always, so
        segment records and the healing analysis stay exact); 1 records every step.
    points:
        0-based indices of the points to record (ascending, no duplicates), or None for
        all. The summaries (:class:`RunStats`) cover every point regardless.
    sink:
        ``sink(chunk)`` called with each chunk of recorded rows as it fills (for example a
        CSV writer), so the rows need not stay in memory.
    chunk_rows:
        Most rows per chunk handed to the sink (fewer for many points: a chunk holds at
        most about :data:`CHUNK_BYTES`).
    keep_rows:
        With a sink: the most rows the returned History keeps in memory (thinned evenly:
        every 2^j-th recorded row plus each segment's ends; ``History.thinned`` tells).
        None keeps every recorded row.
    keep_points:
        With a sink: positions among the recorded points that the returned History keeps
        (for plots of a few curves); None keeps them all.
    """

    every: int = 1
    points: Sequence[int] | None = None
    sink: RowSink | None = None
    chunk_rows: int = 1024
    keep_rows: int | None = None
    keep_points: Sequence[int] | None = None

    def checked_points(self, n: int) -> np.ndarray | None:
        """The recorded points as an int64 array (None: all); ParameterError if invalid."""
        for name, v, low in (("every", self.every, 1), ("chunk_rows", self.chunk_rows, 1)):
            if isinstance(v, bool) or not isinstance(v, int | np.integer) or v < low:
                raise ParameterError(name, v, f"an integer >= {low}")
        k = self.keep_rows
        if k is not None and (isinstance(k, bool) or not isinstance(k, int | np.integer) or k < 2):
            raise ParameterError("keep_rows", k, "an integer >= 2, or None (keep every row)")
        if self.points is None:
            return None
        pts = list(self.points)
        if not pts:
            raise ParameterError("points", pts, "at least one point index")
        for p in pts:
            if isinstance(p, bool) or not isinstance(p, int | np.integer) or not 0 <= p < n:
                raise ParameterError("points", p, f"integer point indices 0..{n - 1}")
        if len(set(pts)) != len(pts):
            dup = next(p for p in pts if pts.count(p) > 1)
            raise ParameterError("points", dup, "each point once (a duplicate)")
        if pts != sorted(pts):
            raise ParameterError("points", pts, "indices in ascending order")
        return np.asarray(pts, dtype=np.int64)


@dataclass
class SegmentStats:
    """Running figures of one segment, per point ((N,) arrays), over every step.

    ``start_*`` at the state the segment starts from; ``peak_*`` over its steps (the
    first step where the largest friction ratio occurs); ``final_*`` after its last step;
    ``max_normal_traction`` [Pa] over its steps; ``final_F``, ``final_R`` after its last
    step. Times [s].
    """

    first_step: int
    last_step: int
    start_friction_ratio: np.ndarray
    start_time: np.ndarray
    peak_friction_ratio: np.ndarray
    peak_time: np.ndarray
    final_friction_ratio: np.ndarray
    final_time: np.ndarray
    max_normal_traction: np.ndarray
    final_F: np.ndarray | None = None
    final_R: np.ndarray | None = None


@dataclass
class RunStats:
    """Running figures of a whole run, per point ((N,) arrays), updated on every step.

    ``peak_*``: the largest friction ratio (row 0, the initial state, included; the first
    step where it occurs), its step, time [s] and the slip path length travelled by then
    [m]. ``path_length`` [m]: sum of |Delta slip_t| over every step. ``time``, ``slip``
    (N, 2), ``approach``, ``plastic_work`` [J/m^2]: the values after the last step.
    """

    steps: int
    time: np.ndarray
    slip: np.ndarray
    approach: np.ndarray
    plastic_work: np.ndarray
    path_length: np.ndarray
    friction_ratio: np.ndarray
    peak_friction_ratio: np.ndarray
    peak_step: np.ndarray
    peak_time: np.ndarray
    peak_path_length: np.ndarray
    segments: list[SegmentStats] = field(default_factory=list)


class Recorder:
    """Records rows (as a :class:`Recording` asks) and keeps :class:`RunStats` for N points."""

    def __init__(
        self, state: Any, recording: Recording | None = None, planned: Sequence[int] = ()
    ) -> None:
        """``planned``: the estimated steps of each segment, to size the store of every row
        at once (:meth:`reserve`) instead of a first chunk that is then copied."""
        rec = recording or Recording()
        n = state.n_points
        self.recording = rec
        self.selected = rec.checked_points(n)
        sel = self.selected
        self.m = n if sel is None else int(sel.size)
        self.every = int(rec.every)
        self.chunk = max(1, min(int(rec.chunk_rows), CHUNK_BYTES // (ROW_BYTES * self.m)))
        self.keep = None if rec.keep_rows is None or rec.sink is None else int(rec.keep_rows)
        self.sink = rec.sink
        self.points = (np.arange(n) if sel is None else sel) + 1
        kp = None if rec.sink is None or rec.keep_points is None else rec.keep_points
        self.keep_points = None if kp is None else np.asarray(kp, dtype=np.int64)
        if self.keep_points is not None and (
            self.keep_points.ndim != 1
            or np.any(self.keep_points < 0)
            or np.any(self.keep_points >= self.m)
        ):
            raise ParameterError("keep_points", kp, f"positions 0..{self.m - 1}")
        #: 0-based indices of the points the returned History holds (None: all N).
        self.kept_points = sel
        if self.keep_points is not None:
            base = np.arange(n) if sel is None else sel
            self.kept_points = base[self.keep_points]
        #: Every recorded row stays in memory: rows are written once into arrays that
        #: grow (by doubling, or to ``reserve``); chunks go to the sink as views of them.
        self.store_all = self.keep is None and self.keep_points is None
        self.sent = 0  # rows of the store already handed to the sink
        first = self.planned_rows(planned) if self.store_all and planned else self.chunk
        self.buf = self._alloc(max(first, 1))
        self.kind_names: list[str] = ["initial"]
        self.fill = 0
        self.kept: list[dict[str, np.ndarray]] = []
        self.kept_rows = 0
        self.stride = 1
        self.recorded = 0  #: rows recorded so far (sent to the sink)
        self.max_held_rows = 0  #: most rows held at once (buffer + kept), for tests
        self.thinned = False
        ratio = _ratio(state.traction)
        zeros = np.zeros(n)
        self.stats = RunStats(
            steps=0, time=zeros.copy(), slip=np.zeros((n, 2)), approach=zeros.copy(),
            plastic_work=zeros.copy(), path_length=zeros.copy(), friction_ratio=ratio,
            peak_friction_ratio=ratio.copy(), peak_step=np.zeros(n, dtype=np.int64),
            peak_time=zeros.copy(), peak_path_length=zeros.copy(),
        )  # fmt: skip
        self.state = state
        self._last = (np.full(n, -1, dtype=np.int8), np.zeros(n, dtype=np.int64), 0, 0, 0)
        self._last_recorded = True
        self._lengths: tuple[np.ndarray | None, np.ndarray] = (None, np.empty(0))
        self._seg: SegmentStats | None = None
        self._seg_index = 0
        self._seg_k = 0
        self._write_row(0, 0, True)

    def _alloc(self, rows: int) -> dict[str, np.ndarray]:
        """Empty rows of every field, carved from one block of memory: one large block is
        backed by huge pages where the system offers them, so that writing the rows into
        fresh memory costs few page faults (separate arrays of a few MiB mostly did not)."""
        shapes = [(name, (rows, self.m, *shape), np.dtype(dt))
                  for name, (shape, dt) in POINT_FIELDS.items()]  # fmt: skip
        shapes += [(name, (rows,), np.dtype(np.int64)) for name in (*ROW_FIELDS, *_INTERNAL)]
        offsets, size = [], 0
        for _, shape, dt in shapes:
            offsets.append(size)
            size += -(-math.prod(shape) * dt.itemsize // _ALIGN) * _ALIGN
        block = np.empty(size, dtype=np.uint8)
        return {
            name: block[start : start + math.prod(shape) * dt.itemsize].view(dt).reshape(shape)
            for (name, shape, dt), start in zip(shapes, offsets, strict=True)
        }

    def reserve(self, rows: int) -> None:
        """Make room for ``rows`` recorded rows in all (an estimate: more still fit)."""
        if self.store_all and rows > self.buf["step"].shape[0]:
            self._grow(rows)

    def _grow(self, rows: int) -> None:
        new = self._alloc(rows)
        for k, v in self.buf.items():
            new[k][: self.fill] = v[: self.fill]
        self.buf = new

    def planned_rows(self, counts: Sequence[int]) -> int:
        """Rows recorded for segments of ``counts`` steps (row 0 included)."""
        e = self.every
        return 1 + sum(c // e + 2 for c in counts if c > 0)

    # ------------------------------------------------------------------ segments
    def begin_segment(self, index: int, kind: str) -> None:
        """Start segment ``index`` (1-based) of kind ``kind``."""
        s = self.stats
        while len(self.kind_names) <= index:
            self.kind_names.append("")
        self.kind_names[index] = kind
        n = s.time.shape[0]
        self._seg_index = index
        self._seg_k = 0
        self._seg = SegmentStats(
            first_step=s.steps + 1, last_step=s.steps,
            start_friction_ratio=s.friction_ratio, start_time=s.time.copy(),
            peak_friction_ratio=np.full(n, -np.inf), peak_time=s.time.copy(),
            final_friction_ratio=s.friction_ratio, final_time=s.time.copy(),
            max_normal_traction=np.full(n, -np.inf),
        )  # fmt: skip

    def end_segment(self) -> SegmentStats | None:
        """Close the current segment; its stats (None when it completed no step)."""
        seg, self._seg = self._seg, None
        if seg is None or seg.last_step < seg.first_step:
            return None
        if not self._last_recorded:  # the segment's last step: always recorded
            status, iters, _, substeps, solves = self._last
            self._write_row(self._seg_index, substeps, True, status, iters, solves)
        else:
            self._mark_end()
        seg.final_friction_ratio = self.stats.friction_ratio
        seg.final_time = self.stats.time.copy()
        seg.final_F = np.array(self.state.F, dtype=np.float64)
        seg.final_R = np.array(self.state.R, dtype=np.float64)
        self.stats.segments.append(seg)
        return seg

    # ------------------------------------------------------------------ steps
    def add(self, state: Any, dt: Any, du: np.ndarray, work: np.ndarray, status: np.ndarray,
            substeps: int, solves: int, iterations: np.ndarray, last: bool) -> bool:  # fmt: skip
        """One completed step of the current segment (``last``: the segment's last step);
        True when the segment's peak friction ratio rose at some point."""
        s = self.stats
        seg = self._seg
        assert seg is not None
        s.steps += 1
        seg.last_step = s.steps
        ratio = np.empty(s.time.shape[0])
        if type(dt) is np.ndarray and dt.ndim == 1 and dt.dtype == np.float64:
            dts = dt  # the driver's (N,) increments: no conversion
        else:
            dts = np.atleast_1d(np.asarray(dt, dtype=np.float64))
        k = self._seg_k
        self._seg_k = k + 1
        self.state = state
        recorded = k == 0 or last or (k + 1) % self.every == 0
        dpath = self._slip_lengths(du)
        if recorded and self.selected is None:  # one pass: running figures and the row
            b, j = self.buf, self.fill
            rose = accumulate_row(
                s.steps, dts, du, dpath, work, state.traction, state.F, state.R, state.plastic_slip,
                status, iterations, s.time, s.slip, s.approach, s.plastic_work, s.path_length,
                ratio, s.peak_friction_ratio, s.peak_step, s.peak_time, s.peak_path_length,
                seg.peak_friction_ratio, seg.peak_time, seg.max_normal_traction,
                b["time"][j], b["slip"][j], b["approach"][j], b["plastic_work"][j],
                b["traction"][j], b["F"][j], b["R"][j], b["plastic_slip"][j], b["status"][j],
                b["iterations"][j],
            )  # fmt: skip
            s.friction_ratio = ratio
            self._row_meta(self._seg_index, substeps, k == 0 or last, False, solves)
            self._last_recorded = True
            return bool(rose)
        rose = accumulate(
            s.steps, dts, du, dpath, work,
            state.traction, s.time, s.slip, s.approach, s.plastic_work, s.path_length,
            ratio, s.peak_friction_ratio, s.peak_step, s.peak_time, s.peak_path_length,
            seg.peak_friction_ratio, seg.peak_time, seg.max_normal_traction,
        )  # fmt: skip
        s.friction_ratio = ratio
        if recorded:
            self._write_row(self._seg_index, substeps, k == 0 or last, status, iterations, solves)
            self._last_recorded = True
        else:
            self._last = (status, iterations, 0, substeps, solves)
            self._last_recorded = False
        return bool(rose)

    def _slip_lengths(self, du: np.ndarray) -> np.ndarray:
        """|du_t| per point; kept for the next step when ``du`` is read-only (the driver's
        increments: a plan repeats its own, so it is measured once per segment)."""
        held, lengths = self._lengths
        if du is not held:
            lengths = slip_lengths(du, np.empty(du.shape[0]))
            self._lengths = (du if not du.flags.writeable else None, lengths)
        return lengths

    def _write_row(self, segment: int, substeps: int, end: bool, status: Any = None,
                   iterations: Any = None, solves: int = 0) -> None:  # fmt: skip
        b, j, s, st = self.buf, self.fill, self.stats, self.state
        sel = self.selected
        if sel is None:
            b["time"][j] = s.time
            b["slip"][j] = s.slip
            b["approach"][j] = s.approach
            b["plastic_work"][j] = s.plastic_work
            b["traction"][j] = st.traction
            b["F"][j] = st.F
            b["R"][j] = st.R
            b["plastic_slip"][j] = st.plastic_slip
            if status is None:
                b["status"][j] = -1
                b["iterations"][j] = 0
            else:
                b["status"][j] = status
                b["iterations"][j] = iterations
        else:
            b["time"][j] = s.time[sel]
            b["slip"][j] = s.slip[sel]
            b["approach"][j] = s.approach[sel]
            b["plastic_work"][j] = s.plastic_work[sel]
            b["traction"][j] = st.traction[sel]
            b["F"][j] = st.F[sel]
            b["R"][j] = st.R[sel]
            b["plastic_slip"][j] = st.plastic_slip[sel]
            if status is None:
                b["status"][j] = -1
                b["iterations"][j] = 0
            else:
                b["status"][j] = status[sel]
                b["iterations"][j] = iterations[sel]
        self._row_meta(segment, substeps, end, status is None, solves)

    def _row_meta(self, segment: int, substeps: int, end: bool, initial: bool, solves: int) -> None:
        """The per-row values of the row being written; then hand on or grow as needed."""
        b, j = self.buf, self.fill
        b["step"][j] = self.stats.steps
        b["segment"][j] = segment
        b["substeps"][j] = substeps
        b["solves"][j] = solves
        b["_index"][j] = self.recorded
        b["_end"][j] = end or initial
        self.recorded += 1
        self.fill = j + 1
        if self.store_all:
            if self.sink is not None and self.fill - self.sent >= self.chunk:
                self._send()
            if self.fill == self.buf["step"].shape[0]:
                self._grow(2 * self.fill)
        elif self.fill == self.chunk:
            self.flush()

    def _send(self) -> None:
        """Hand the stored rows not yet sent to the sink (views, no copy)."""
        if self.sink is not None and self.fill > self.sent:
            self.sink(self._chunk_view(self.sent, self.fill))
        self.sent = self.fill

    def _mark_end(self) -> None:
        """Mark the last recorded row as a segment end."""
        if self.fill:
            self.buf["_end"][self.fill - 1] = 1
        elif self.kept:
            self.kept[-1]["_end"][-1] = 1

    def _chunk_view(self, start: int, stop: int) -> dict[str, np.ndarray]:
        out = {k: v[start:stop] for k, v in self.buf.items() if not k.startswith("_")}
        out["point"] = self.points
        out["kind"] = np.array(self.kind_names, dtype=object)[out["segment"]]
        return out

    def flush(self) -> None:
        """Hand the buffered rows to the sink and move them to the kept rows."""
        rows = self.fill
        if not rows:
            return
        self.max_held_rows = max(self.max_held_rows, rows + self.kept_rows)
        if self.sink is not None:
            self.sink(self._chunk_view(0, rows))
        kp = self.keep_points
        if self.keep is not None and self.stride > 1:  # thin the new rows as the kept ones
            sel = (self.buf["_index"][:rows] % self.stride == 0) | (self.buf["_end"][:rows] != 0)
            sel[-1] = True  # the newest row may yet be marked a segment end (a failed step)
        else:
            sel = slice(None)
        kept = {}
        for k, v in self.buf.items():
            part = v[:rows][sel]
            if kp is not None and k in POINT_FIELDS:
                part = part[:, kp]
            kept[k] = part.copy() if part.base is not None else part
        self.kept.append(kept)
        self.kept_rows += int(self.kept[-1]["step"].size)
        self.fill = 0
        if self.keep is not None and self.kept_rows > self.keep:
            self._thin()
        elif self.keep is not None and len(self.kept) > 16:  # few rows each: merge them
            self.kept = [self._merged()]

    def _thin(self) -> None:
        """Halve the kept rows (every 2*stride-th recorded row and segment ends stay)."""
        assert self.keep is not None
        merged = self._merged()
        while merged["step"].size > self.keep:
            self.stride *= 2
            keep = (merged["_index"] % self.stride == 0) | (merged["_end"] != 0)
            keep[-1] = True  # the newest row may yet be marked a segment end
            if keep.all():
                break
            merged = {k: v[keep] for k, v in merged.items()}
            self.thinned = True
        self.kept = [merged]
        self.kept_rows = int(merged["step"].size)

    def _merged(self) -> dict[str, np.ndarray]:
        """The kept rows as one set of arrays (the chunks are freed field by field)."""
        names = list(self.kept[0]) if self.kept else list(self.buf)
        out = {}
        for name in names:
            out[name] = np.concatenate([c.pop(name) for c in self.kept])
        self.kept = []
        return out

    def finish(self) -> dict[str, np.ndarray]:
        """Flush the last rows; the kept rows (time first) and their per-row values."""
        if self.store_all:
            self._send()
            self.max_held_rows = self.buf["step"].shape[0]
            return {k: v[: self.fill] for k, v in self.buf.items()}
        self.flush()
        merged = self._merged()
        if self.keep is not None and merged["step"].size > self.keep:
            self.kept = [merged]
            self._thin()
            merged = self.kept[0]
        self.kept = []
        self.kept_rows = 0
        return merged
