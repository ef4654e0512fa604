"""Progress off a terminal: plain log lines on the stream, no carriage returns."""

from __future__ import annotations

import io
import time

from frictionlab.commands._progress import progress_bar, progress_lines


class _Clock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_lines_every_interval_and_a_last_one() -> None:
    stream, clock = io.StringIO(), _Clock()
    with progress_lines("roughness s.toml", stream, delay=1.0, interval=10.0,
                        clock=clock) as update:  # fmt: skip
        for done in range(1, 31):
            clock.now += 1.0  # one step per second: 30 s of work
            update(done, 30)
    lines = stream.getvalue().splitlines()
    assert "\r" not in stream.getvalue()
    # first line once the delay has passed (1 s), then every 10 s, then the finish
    assert lines == [
        "frictionlab: roughness s.toml: 1/30 (3 %), 1.0 s elapsed",
        "frictionlab: roughness s.toml: 11/30 (37 %), 11.0 s elapsed",
        "frictionlab: roughness s.toml: 21/30 (70 %), 21.0 s elapsed",
        "frictionlab: roughness s.toml: 30/30 (100 %), 30.0 s elapsed",
    ]


def test_short_work_writes_nothing() -> None:
    stream, clock = io.StringIO(), _Clock()
    with progress_lines("quick", stream, clock=clock) as update:
        for done in range(1, 5):
            clock.now += 0.1
            update(done, 4)
    assert stream.getvalue() == ""


def test_a_non_tty_stream_gets_lines_and_a_disabled_one_nothing() -> None:
    stream = io.StringIO()  # isatty() is False
    with progress_bar("work", stream=stream) as update:
        update(0, 2)
        time.sleep(1.05)  # past the one-second delay
        update(1, 2)
        update(2, 2)
    lines = stream.getvalue().splitlines()
    assert "\r" not in stream.getvalue()
    assert [line.split(",")[0] for line in lines] == [
        "frictionlab: work: 1/2 (50 %)",
        "frictionlab: work: 2/2 (100 %)",
    ]
    quiet = io.StringIO()
    with progress_bar("work", enabled=False, stream=quiet) as update:
        update(1, 2)
    assert quiet.getvalue() == ""
