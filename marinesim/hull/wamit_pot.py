"""WAMIT's run files: the configuration (``.cfg``) and the potential control file (``.pot``), which gives the
water depth and where body 1 sits in WAMIT's global frame.

``XBODY(1..4)`` are the body origin's global x, y, z (m; the free surface at z = 0) and the angle of the
body's x axis from the global X axis (deg, anticlockwise). WAMIT refers phases to the incident wave at the
global origin and headings to the global X axis, and a ``.gdf`` is in body coordinates: the RAO readers refer
them to the body origin (:func:`marinesim.vessel.wamit.table_from`), and a hull read from a ``.gdf`` moves up
by ``ZBODY`` so the free surface is its z = 0 (:mod:`marinesim.hull.gdf`).

Two layouts: the old (``IALTPOT = 1`` in the ``.cfg``), whose fourth line holds ``HBOT XBODY(1..4)``, and
WAMIT 6/7's (``IALTPOT = 2``): title, ``HBOT``, ``IRAD IDIFF``, ``NPER``, the periods, ``NBETA``, the
headings, ``NBODY``, then per body the ``.gdf`` name, ``XBODY(1..4)`` and ``IMODE(1..6)``. What follows the
values on a line is a comment.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from marinesim.errors import FileFormatError
from marinesim.tokens import leading_numbers, parse_float, read_text

MAX_LIST = 100_000
"""The most periods or headings a ``.pot`` may list."""


@dataclass(frozen=True)
class Pot:
    """``depth`` (m, inf for WAMIT's infinite depth, NaN unknown) and body 1's ``xbody`` (x, y, z in m, angle in
    deg; None where the file stops after HBOT: the body is then taken at the global origin)."""

    depth: float
    xbody: tuple[float, float, float, float] | None = (0.0, 0.0, 0.0, 0.0)


def read_cfg(cfg: Path) -> dict[str, tuple[int, str]]:
    """``KEY = value`` lines of a WAMIT ``.cfg`` (keys upper case) -> (line number, first word of the value);
    empty without a file."""
    if not cfg.is_file():
        return {}
    keys: dict[str, tuple[int, str]] = {}
    for number, text in enumerate(read_text(cfg).splitlines(), 1):
        key, equals, value = text.partition("=")
        words = value.split()
        if equals and key.strip() and words:
            keys[key.strip().upper()] = (number, words[0])
    return keys


def pot_beside(path: Path) -> Pot | None:
    """The ``.pot`` of the same name beside ``path`` (its form from the ``.cfg`` beside), or None."""
    pot = path.with_suffix(".pot")
    if not pot.is_file():
        return None
    return read_pot(pot, read_cfg(path.with_suffix(".cfg")).get("IALTPOT", (0, "2"))[1] == "1")


def read_pot(path: Path, old_form: bool) -> Pot:
    """The ``.pot`` at ``path``; ``old_form`` for ``IALTPOT = 1``. Flaws name the line."""
    lines = read_text(path).splitlines()
    reads = [(number, [parse_float(path, number, word, "a number") for word in leading_numbers(text)] or None)
             for number, text in enumerate(lines, 1) if number > 1 and text.strip()]
    if old_form:
        for number, values in reads:
            if len(values) == 5:
                return Pot(_depth(values[0]), tuple(values[1:]))
        raise FileFormatError(path, None, "HBOT XBODY(1..4) not found: expected a line of five numbers (IALTPOT = 1)")
    cursor = _Cursor(path, reads)
    depth = _depth(cursor.take(1, "HBOT (water depth, m; <= 0 for infinite)")[0])
    if cursor.at == len(reads):
        return Pot(depth, None)  # HBOT alone: the rest of the run's controls are not needed to read its outputs
    cursor.take(2, "IRAD IDIFF")
    for name in ("NPER", "NBETA"):
        count = int(cursor.take(1, name)[0])
        if abs(count) > MAX_LIST:
            raise FileFormatError(path, cursor.last, f"{name} {count}: at most {MAX_LIST}")
        if count:
            cursor.take(count if count > 0 else 2, "the list of " + ("periods" if name == "NPER" else "headings"))
    cursor.take(1, "NBODY")
    cursor.skip_line()  # the .gdf file's name
    return Pot(depth, tuple(cursor.take(4, "XBODY(1..4)")))


class _Cursor:
    """Reads values line by line as Fortran's list-directed READ does: each read starts on a new line and takes
    as many lines as its values need."""

    def __init__(self, path: Path, reads: list[tuple[int, list[float] | None]]) -> None:
        self.path, self.reads, self.at, self.last = path, reads, 0, None

    def take(self, count: int, what: str) -> list[float]:
        values: list[float] = []
        while len(values) < count:
            if self.at >= len(self.reads):
                raise FileFormatError(self.path, None, f"file ends early: expected {what}")
            self.last, line = self.reads[self.at]
            self.at += 1
            if line is None or not line:
                raise FileFormatError(self.path, self.last, f"expected {what}")
            values += line
        return values[:count]

    def skip_line(self) -> None:
        if self.at >= len(self.reads):
            raise FileFormatError(self.path, None, "file ends early: expected the .gdf file's name")
        self.at += 1


def _depth(hbot: float) -> float:
    return math.inf if hbot <= 0.0 else hbot
