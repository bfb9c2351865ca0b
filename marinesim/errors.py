"""The one exception hierarchy for user mistakes.

Everything a user can get wrong (a bad option value, a malformed file, a scenario key that does
not exist) raises a subclass of :class:`MarinesimError`. The CLI prints such errors as one line
and exits with status 2; anything else is a bug and keeps its traceback.
"""

from __future__ import annotations

import math
from pathlib import Path


class MarinesimError(Exception):
    """Base class of every error a user can cause and fix."""


class ParameterError(MarinesimError, ValueError):
    """A parameter value is out of range or not a number; the message names the parameter."""


class ScenarioError(MarinesimError):
    """A scenario file is unreadable, has an unknown key or an invalid value (names the key)."""


class FileFormatError(MarinesimError):
    """A data file (RAO table, mesh) is malformed; the message names the file, the line and what
    was expected there."""

    def __init__(self, path: object, line: int | None, message: str) -> None:
        self.path, self.line = path, line
        where = f"{path}, line {line}" if line is not None else f"{path}"
        super().__init__(f"{where}: {message}")


def missing_file(path: str | Path) -> FileFormatError:
    """The error for a ``path`` that is no file to read: a folder (said so), or nothing at all."""
    return FileFormatError(path, None, "is a folder, not a file" if Path(path).is_dir() else "no such file")


def require_finite(name: str, value: float) -> float:
    """Return ``value`` as float, or raise naming ``name`` if it is not a finite number."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number, got {value!r}") from None
    if not math.isfinite(number):
        raise ParameterError(f"{name} must be a finite number, got {value!r}")
    return number


def require_positive(name: str, value: float, allow_infinite: bool = False) -> float:
    """Return ``value`` as float, or raise naming ``name`` unless it is > 0 (and finite)."""
    if allow_infinite and value == math.inf:
        return math.inf
    number = require_finite(name, value)
    if number <= 0.0:
        raise ParameterError(f"{name} must be > 0, got {value!r}")
    return number


def require_at_least(name: str, value: float, minimum: float) -> float:
    """Return ``value`` as float, or raise naming ``name`` unless it is finite and >= minimum."""
    number = require_finite(name, value)
    if number < minimum:
        raise ParameterError(f"{name} must be >= {minimum:g}, got {value!r}")
    return number
