"""The one exception hierarchy for user mistakes.

Everything a user can get wrong (a bad option value, a malformed file, a scenario key that does
not exist) raises a subclass of :class:`MarinesimError`. The CLI prints such errors as one line
and exits with status 2; anything else is a bug and keeps its traceback.
"""

from __future__ import annotations

import math
import os


class MarinesimError(Exception):
    """Base class of every error a user can cause and fix."""


class ParameterError(MarinesimError, ValueError):
    """A parameter value is out of range or not a number; the message names the parameter."""


class HeadingError(ParameterError):
    """The headings of an RAO table are unusable (none, not finite, or one given twice after wrapping to
    0..360 deg); a file reader catching it adds the headings its file covers."""


class ScenarioError(MarinesimError):
    """A scenario file is unreadable, has an unknown key or an invalid value (names the key)."""


class FileFormatError(MarinesimError):
    """A data file (RAO table, mesh) is malformed; the message names the file, the line and what
    was expected there."""

    def __init__(self, path: object, line: int | None, message: str) -> None:
        self.path, self.line = path, line
        where = f"{path}, line {line}" if line is not None else f"{path}"
        super().__init__(f"{where}: {message}")


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


def require_within(name: str, value: float, low: float, high: float, unit: str = "") -> float:
    """Return ``value`` as float, or raise naming ``name`` and the range unless ``low <= value <= high``."""
    number = require_finite(name, value)
    if not low <= number <= high:
        unit = f" {unit}" if unit else ""
        raise ParameterError(f"{name} must be in {low:g}..{high:g}{unit}, got {value!r}")
    return number


MEMORY_SHARE = 0.5
"""The largest share of the machine's physical memory one allocation may plan to take."""


def physical_memory() -> int:
    """The machine's physical memory (bytes)."""
    return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")


def require_memory(what: str, needed: float) -> None:
    """Refuse, before allocating, ``what`` needing ``needed`` bytes beyond :data:`MEMORY_SHARE` of the
    machine's physical memory; the message gives both numbers."""
    available = MEMORY_SHARE * physical_memory()
    if needed > available:
        raise ParameterError(f"{what} would need {needed / 2**30:.3g} GiB of memory; this machine allows "
                             f"{available / 2**30:.3g} GiB ({MEMORY_SHARE:.0%} of {physical_memory() / 2**30:.3g} GiB)")
