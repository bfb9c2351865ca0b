"""Whitespace-separated numbers read with their line numbers, for the text file readers (RAO tables, panel meshes).

Every failure raises :class:`FileFormatError` naming the file, the line and what was expected. A reader wrapped in
:func:`by_content` parses a file once per process while its bytes stay the same.
"""

from __future__ import annotations

import copy
import functools
import hashlib
import math
import threading
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from marinesim.errors import FileFormatError
from marinesim.formats import check_file
from marinesim.recent import Newest

T = TypeVar("T")
PARSED_KEPT = 8
"""How many parsed files each reader wrapped in :func:`by_content` keeps, the newest asked."""


def by_content(read: Callable[..., T]) -> Callable[..., T]:
    """``read(path, ...)`` kept per process by the path as given, the file's bytes and the other arguments (the
    newest :data:`PARSED_KEPT`): a session, a study or a test suite that loads a vessel again parses her files once.
    Each call gets its own copy; a file that fails is read again, and its error raised again, each time; a file that
    changes while it is parsed is not kept."""
    kept: Newest[tuple, T] = Newest(PARSED_KEPT)
    lock = threading.Lock()

    @functools.wraps(read)
    def reader(path: str | Path, *args, **kwargs) -> T:
        path = Path(path)
        check_file(path)
        digest = _digest(path)
        if digest is None:
            return read(path, *args, **kwargs)  # its own error, with its words
        key = (str(path), digest, args, tuple(sorted(kwargs.items())))
        with lock:
            found = key in kept
            if found:
                value = kept.get(key, lambda: None)
        if not found:
            value = read(path, *args, **kwargs)
            if _digest(path) == digest:
                with lock:
                    kept.get(key, lambda: value)
        return copy.deepcopy(value)
    return reader


def _digest(path: Path) -> bytes | None:
    """The SHA-256 of the file's bytes; None if it cannot be read."""
    try:
        return hashlib.sha256(path.read_bytes()).digest()
    except OSError:
        return None


def read_text(path: Path) -> str:
    """The file's text; unreadable or non-text files are refused as a format error."""
    check_file(path)
    try:
        return path.read_text(encoding="utf-8", errors="strict")
    except UnicodeDecodeError as error:
        raise FileFormatError(path, None, f"not a text file ({error.reason} at byte {error.start})") from None
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read: {error.strerror}") from None


def parse_float(path: Path, line: int, text: str, expected: str) -> float:
    """``text`` as a finite float (Fortran ``D`` exponents accepted), or a format error."""
    try:
        value = float(text.replace("D", "E").replace("d", "e"))
    except ValueError:
        raise FileFormatError(path, line, f"expected {expected}, got {text!r}") from None
    if not math.isfinite(value):
        raise FileFormatError(path, line, f"expected {expected} (a finite number), got {text!r}")
    return value


def parse_int(path: Path, line: int, text: str, expected: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise FileFormatError(path, line, f"expected {expected} (an integer), got {text!r}") from None


class Tokens:
    """A stream of the tokens of ``lines[start:]``, each remembering its (1-based) line number."""

    def __init__(self, path: Path, lines: list[str], start: int = 0) -> None:
        self.path = path
        self._items = [(number, token) for number, text in enumerate(lines[start:], start + 1)
                       for token in text.split()]
        self._next = 0

    @property
    def line(self) -> int:
        """Line number of the next token (or of the last line at the end)."""
        if self._next < len(self._items):
            return self._items[self._next][0]
        return self._items[-1][0] if self._items else 1

    @property
    def remaining(self) -> int:
        """How many tokens are left."""
        return len(self._items) - self._next

    def at_end(self) -> bool:
        return self._next >= len(self._items)

    def _take(self, expected: str) -> tuple[int, str]:
        if self.at_end():
            raise FileFormatError(self.path, self.line, f"file ends early: expected {expected}")
        item = self._items[self._next]
        self._next += 1
        return item

    def float(self, expected: str) -> float:
        line, text = self._take(expected)
        return parse_float(self.path, line, text, expected)

    def int(self, expected: str) -> int:
        line, text = self._take(expected)
        return parse_int(self.path, line, text, expected)


def leading_numbers(text: str) -> list[str]:
    """The words of a line up to the first that is not a finite number (Fortran ``D`` exponents accepted): what a
    Fortran list-directed READ takes from it; the rest (``0   IMASS``, ``200.0  (HBOT)``) is a comment."""
    words = text.split()
    for k, word in enumerate(words):
        try:
            finite = math.isfinite(float(word.replace("D", "E").replace("d", "e")))
        except ValueError:
            finite = False
        if not finite:
            return words[:k]
    return words
