"""Progress of long work, reported to whoever is listening at the edge.

Kernels take no flag: they open a :func:`task` and advance it; nothing is shown unless the caller
(the command line: tqdm bars; a study: its own counter) installed a :class:`Reporter` with
:func:`reporting`. The reporter is a context variable, so it follows the calling thread (and a
worker started with :func:`contextvars.copy_context`) and never leaks into unrelated work.
"""

from __future__ import annotations

import contextlib
from contextvars import ContextVar
from typing import Iterator, Protocol


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
