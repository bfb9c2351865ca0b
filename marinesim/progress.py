"""Progress of long work, reported to whoever is listening at the edge.

Kernels take no flag: they open a :func:`task` and advance it; nothing is shown unless the caller
(the command line: tqdm bars on a terminal, :func:`lines` into a log; a study: its own counter) installed
a :class:`Reporter` with :func:`reporting`. The reporter is a context variable, so it follows the calling
thread (and a worker started with :func:`contextvars.copy_context`) and never leaks into unrelated work.
"""

from __future__ import annotations

import contextlib
import math
import time
from contextvars import ContextVar
from typing import Iterator, Protocol, TextIO


class Bar(Protocol):
    """One task's display: advanced by a number of units, closed when the task ends."""

    def update(self, units: int) -> object: ...

    def close(self) -> object: ...


class Reporter(Protocol):
    """Makes the display of a task named ``name`` of ``total`` units (``unit`` names one)."""

    def __call__(self, name: str, total: int, unit: str) -> Bar: ...


_REPORTER: ContextVar[Reporter | None] = ContextVar("marinesim_progress", default=None)


class _Silent:
    def update(self, units: int) -> None:
        pass

    def close(self) -> None:
        pass


class _Lines:
    """One task's progress as plain lines on ``stream`` (see :func:`lines`)."""

    def __init__(self, stream: TextIO, name: str, total: int, unit: str, step: float, interval_s: float) -> None:
        self.stream, self.name, self.total, self.unit = stream, name, total, unit
        self.step, self.interval_s = step, interval_s
        self.done = self.shown = 0
        self.start = self.last = time.monotonic()

    def update(self, units: int) -> None:
        self.done += units
        if self.done >= self.total or self.done == self.shown:
            return
        now = time.monotonic()
        mark = (math.floor(self.shown / self.total / self.step + 1e-9) + 1) * self.step * self.total
        if self.done >= mark or now - self.last >= self.interval_s:
            self._write(f"{100 * self.done / self.total:.0f}% ({self.done}/{self.total} {self.unit})")
            self.shown, self.last = self.done, now

    def close(self) -> None:
        elapsed = time.monotonic() - self.start
        if self.done >= self.total:
            self._write(f"done ({self.done} {self.unit}, {elapsed:.1f} s)")
        else:
            self._write(f"stopped at {100 * self.done / self.total:.0f}% ({self.done}/{self.total} {self.unit}, "
                        f"{elapsed:.1f} s)")

    def _write(self, text: str) -> None:
        self.stream.write(f"{self.name}: {text}\n")
        self.stream.flush()


def lines(stream: TextIO, step: float = 0.1, interval_s: float = 10.0) -> Reporter:
    """A reporter writing plain lines to ``stream`` (a log: no carriage returns, no escape sequences): a task's
    share done each time it has moved on by ``step`` of its total or ``interval_s`` (s) have passed since its
    last line, ``name: 40% (400/1000 step)``, and when it ends ``name: done (1000 step, 12.3 s)`` (or ``stopped
    at`` the share it reached)."""
    def line_bar(name: str, total: int, unit: str) -> Bar:
        return _Lines(stream, name, total, unit, step, interval_s)
    return line_bar


@contextlib.contextmanager
def task(name: str, total: int, unit: str = "step") -> Iterator[Bar]:
    """A task of ``total`` units: advance it with ``.update(n)``; shown only if a reporter listens."""
    reporter = _REPORTER.get()
    bar = reporter(name, total, unit) if reporter is not None else _Silent()
    try:
        yield bar
    finally:
        bar.close()


@contextlib.contextmanager
def reporting(reporter: Reporter | None) -> Iterator[None]:
    """Show the tasks started inside the block through ``reporter`` (None: show nothing)."""
    token = _REPORTER.set(reporter)
    try:
        yield
    finally:
        _REPORTER.reset(token)
