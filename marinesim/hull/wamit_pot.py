"""WAMIT's run files: the configuration (``.cfg``) and the potential control file (``.pot``), which gives the
water depth, the headings and where each body sits in WAMIT's global frame.

``XBODY(1..4)`` are the body origin's global x, y, z (m; z up, the free surface at z = 0: ZBODY < 0 puts the
origin below it) and the angle of the body's x axis from the global X axis (deg, anticlockwise). WAMIT refers
phases to the incident wave at the global origin and headings to the global X axis, and a ``.gdf`` is in body
coordinates: the RAO readers refer them to the body origin (:func:`marinesim.vessel.wamit.table_from`), and a
hull read from a ``.gdf`` is moved by ``ZBODY`` so the free surface is its z = 0 (:mod:`marinesim.hull.gdf`).

Two layouts: the old (``IALTPOT = 1`` in the ``.cfg``; one body), whose fourth line holds ``HBOT XBODY(1..4)``,
and WAMIT 6/7's (``IALTPOT = 2``): title, ``HBOT``, ``IRAD IDIFF``, ``NPER``, the periods, ``NBETA``, the
headings (``NBETA < 0``: ``BETA1 DBETA``, then ``-NBETA`` headings in steps), ``NBODY``, then per body the
``.gdf`` name, ``XBODY(1..4)`` and ``IMODE(1..6)``. What follows the values on a line is a comment.
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
class PotBody:
    """One body of a ``.pot``: ``gdf`` (its ``.gdf`` file's name as the ``.pot`` gives it; empty in the old form)
    and ``xbody`` (x, y, z in m, angle in deg)."""

    gdf: str
    xbody: tuple[float, float, float, float]

    def names(self, gdf: Path) -> bool:
        """Whether this body's ``.gdf`` is the file ``gdf`` (its name, any folder, any case)."""
        return bool(self.gdf) and self.gdf.replace("\\", "/").rsplit("/", 1)[-1].lower() == gdf.name.lower()


@dataclass(frozen=True)
class Pot:
    """``depth`` (m, inf for WAMIT's infinite depth, NaN unknown), the ``bodies`` in the file's order (none where
    the file stops after HBOT: a body is then taken at the global origin) and the ``headings`` (deg; None where
    the file does not list them)."""

    depth: float
    bodies: tuple[PotBody, ...] = ()
    headings: tuple[float, ...] | None = None


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
    return read_pot_of(pot) if pot.is_file() else None


def read_pot_of(pot: Path) -> Pot:
    """The ``.pot`` at ``pot``, its form from the ``.cfg`` of the same name beside it."""
    return read_pot(pot, read_cfg(pot.with_suffix(".cfg")).get("IALTPOT", (0, "2"))[1] == "1")


def placement(gdf: Path) -> tuple[Path, int, PotBody] | None:
    """(the ``.pot``, the body's number from 1, the body) of the run that places the body of the ``.gdf`` file
    ``gdf``: the ``.pot`` of the same name (its one body, or the body it names ``gdf``), else a ``.pot`` beside
    it that names ``gdf`` among its bodies; None where no ``.pot`` places it. Where no ``.pot`` of the same name
    places it, two that put it at different heights (ZBODY: the mesh's only placement) are refused."""
    found: tuple[Path, int, PotBody] | None = None
    same = gdf.with_suffix(".pot")
    others = sorted(p for p in gdf.parent.glob("*") if p.suffix.lower() == ".pot" and p.is_file() and p != same)
    for pot_path in ([same] if same.is_file() else []) + others:
        if pot_path != same and gdf.name.lower() not in read_text(pot_path).lower():
            continue
        pot = read_pot_of(pot_path)
        n = next((n for n, body in enumerate(pot.bodies, 1) if body.names(gdf)), None)
        if n is None and pot_path == same and len(pot.bodies) == 1:
            n = 1
        if n is None:
            continue
        if pot_path == same:
            return pot_path, n, pot.bodies[n - 1]
        if found is None:
            found = (pot_path, n, pot.bodies[n - 1])
        elif found[2].xbody[2] != pot.bodies[n - 1].xbody[2]:
            raise FileFormatError(pot_path, None, f"places {gdf.name} at XBODY {pot.bodies[n - 1].xbody}, "
                                                  f"{found[0].name} at {found[2].xbody}: which run is it?")
    return found


def read_pot(path: Path, old_form: bool) -> Pot:
    """The ``.pot`` at ``path``; ``old_form`` for ``IALTPOT = 1``. Flaws name the line."""
    lines = read_text(path).splitlines()
    reads = [(number, [parse_float(path, number, word, "a number") for word in leading_numbers(text)] or None, text)
             for number, text in enumerate(lines, 1) if number > 1 and text.strip()]
    if old_form:
        for number, values, _ in reads:
            if values is not None and len(values) == 5:
                return Pot(_depth(values[0]), (PotBody("", tuple(values[1:])),))
        raise FileFormatError(path, None, "HBOT XBODY(1..4) not found: expected a line of five numbers (IALTPOT = 1)")
    cursor = _Cursor(path, reads)
    depth = _depth(cursor.take(1, "HBOT (water depth, m; <= 0 for infinite)")[0])
    if cursor.at == len(reads):
        return Pot(depth)  # HBOT alone: the rest of the run's controls are not needed to read its outputs
    cursor.take(2, "IRAD IDIFF")
    headings: list[float] = []
    for name in ("NPER", "NBETA"):
        count = int(cursor.take(1, name)[0])
        if abs(count) > MAX_LIST:
            raise FileFormatError(path, cursor.last, f"{name} {count}: at most {MAX_LIST}")
        if count:
            values = cursor.take(count if count > 0 else 2, "the list of " + ("periods" if name == "NPER"
                                                                               else "headings"))
            if name == "NBETA":
                headings = values if count > 0 else [values[0] + k * values[1] for k in range(-count)]
    count = int(cursor.take(1, "NBODY")[0])
    if not 1 <= count <= MAX_LIST:
        raise FileFormatError(path, cursor.last, f"NBODY must be 1..{MAX_LIST}, got {count}")
    bodies = []
    for n in range(1, count + 1):
        name = cursor.text(f"the .gdf file's name of body {n}")
        bodies.append(PotBody(name, tuple(cursor.take(4, f"XBODY(1..4) of body {n}"))))
        if n < count:
            cursor.take(6, f"IMODE(1..6) of body {n}")
    return Pot(depth, tuple(bodies), tuple(headings))


class _Cursor:
    """Reads values line by line as Fortran's list-directed READ does: each read starts on a new line and takes
    as many lines as its values need."""

    def __init__(self, path: Path, reads: list[tuple[int, list[float] | None, str]]) -> None:
        self.path, self.reads, self.at, self.last = path, reads, 0, None

    def take(self, count: int, what: str) -> list[float]:
        values: list[float] = []
        while len(values) < count:
            if self.at >= len(self.reads):
                raise FileFormatError(self.path, None, f"file ends early: expected {what}")
            self.last, line, _ = self.reads[self.at]
            self.at += 1
            if line is None or not line:
                raise FileFormatError(self.path, self.last, f"expected {what}")
            values += line
        return values[:count]

    def text(self, what: str) -> str:
        """The first word of the next line (a file name)."""
        if self.at >= len(self.reads):
            raise FileFormatError(self.path, None, f"file ends early: expected {what}")
        self.last, _, line = self.reads[self.at]
        self.at += 1
        return line.split()[0]


def _depth(hbot: float) -> float:
    return math.inf if hbot <= 0.0 else hbot
