"""A history computed on demand of which only the newest entries stay in memory.

Live changes in a training session (a new sea state, speed or heading) each add an entry, a
few megabytes, to a timeline that must stay queryable at any time. Keeping every entry would
grow memory with every change; :class:`Recent` keeps the two newest and the three older ones
asked for last (a blend reads an entry and the one before it, and a scan over the past reads
them in order), and recomputes the others when asked: ``compute`` is a pure function of the
index, so a recomputed entry is bit-identical to the one dropped.

:class:`Newest` keeps, by key, the few entries asked for last (a manoeuvre's knots, a frame's phasor tables):
what the next frame asks again.
"""

from __future__ import annotations

from collections.abc import Hashable
from typing import Callable, Generic, TypeVar

T = TypeVar("T")
K = TypeVar("K", bound=Hashable)


class Recent(Generic[T]):
    """Entries ``compute(index)`` for ``index = 0, 1, 2, ...``; at most five kept."""

    OLDER_KEPT = 3

    def __init__(self, compute: Callable[[int], T]) -> None:
        self._compute = compute
        self._kept: dict[int, T] = {}
        self._older: list[int] = []  # older entries asked for, the last first

    def put(self, index: int, value: T) -> None:
        """Give entry ``index`` computed elsewhere (it must equal ``compute(index)``)."""
        self._kept[index] = value

    def get(self, index: int, newest: int) -> T:
        """Entry ``index`` of a history whose newest entry is ``newest``."""
        if index not in self._kept:
            self._kept[index] = self._compute(index)
        value = self._kept[index]
        if index < newest - 1:
            self._older = [index] + [i for i in self._older if i != index][:self.OLDER_KEPT - 1]
        self._kept = {i: v for i, v in self._kept.items() if i >= newest - 1 or i in self._older}
        return value


class Newest(Generic[K, T]):
    """Entries by key, computed when first asked; the ``most`` asked for last are kept."""

    def __init__(self, most: int) -> None:
        self.most = most
        self._kept: dict[K, T] = {}

    def __contains__(self, key: object) -> bool:
        """Whether the entry of ``key`` is kept."""
        return key in self._kept

    def get(self, key: K, compute: Callable[[], T]) -> T:
        """The entry of ``key``: the one kept, else ``compute()`` (the least recently asked then dropped)."""
        if key in self._kept:
            value = self._kept.pop(key)
        else:
            value = compute()
            if len(self._kept) >= self.most:
                self._kept.pop(next(iter(self._kept)))
        self._kept[key] = value
        return value
