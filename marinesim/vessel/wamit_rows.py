"""The rows of WAMIT's seven-column numeric output (``PER BETA I MOD PHA RE IM``: ``.4`` motions, ``.3``
forces, and the files other programs write in WAMIT's format), read with their line numbers and checked:
monotonic periods, the first period's headings for every period, modes 1-6 complete."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError
from marinesim.tokens import by_content, parse_float, parse_int, read_text

COLUMNS = "PER BETA I MOD PHA RE IM"
RIGID_MODES = 6


def check_modulus(path: Path, number: int, modulus: float, re: float, im: float) -> None:
    """A row's MOD must be ``|RE + i IM|`` (to 1e-4 of it): else the columns are not WAMIT's."""
    if abs(math.hypot(re, im) - modulus) > 1e-4 * max(modulus, 1e-30):
        raise FileFormatError(path, number, f"MOD {modulus:g} disagrees with |RE + i IM| = {math.hypot(re, im):g}")


def next_period(path: Path, number: int, token: str, per: float, periods: list[float]) -> bool:
    """Add ``per`` (written ``token``) to ``periods`` if it starts a new period: the periods of a WAMIT file are
    monotonic and each comes in one run of rows. Whether it was new."""
    if periods and per == periods[-1]:
        return False
    if per in periods:
        raise FileFormatError(path, number, f"PER {token} appears again after other periods (duplicate or unsorted)")
    if len(periods) >= 2 and (per - periods[-1]) * (periods[-1] - periods[-2]) < 0:
        raise FileFormatError(path, number, f"PER {token} breaks the order of the periods (must be monotonic)")
    periods.append(per)
    return True


@by_content
def read_rows(path: Path, *, header_lines: int = 0, what: str = "mode", offset: int = 0) -> tuple[
        np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """Periods (file order, monotonic), headings (deg, increasing), values (heading, period, 6) and notes
    of a seven-column WAMIT file (``.4`` or ``.3``); ``header_lines`` (NUMHDR) first lines are skipped, as
    is a first line that is text. The six modes read are ``offset + 1 .. offset + 6`` (one body of several:
    ``offset = 6 (n - 1)`` for body n)."""
    periods: list[float] = []
    headings: list[float] = []
    cells: dict[tuple[int, int], dict[int, complex]] = {}
    first_line: dict[tuple[int, int], int] = {}
    ignored: set[int] = set()
    notes: list[str] = []
    lines = read_text(path).splitlines()
    for number, text in enumerate(lines, 1):
        parts = text.split()
        if not parts:
            continue
        if number <= header_lines or (not periods and not cells and not _is_number(parts[0])
                                      and number == _first_nonblank(lines)):
            notes.append(f"header line {number} of {path.name} skipped")
            continue
        if len(parts) != 7:
            raise FileFormatError(path, number, f"expected 7 columns {COLUMNS}, got {len(parts)}")
        per = parse_float(path, number, parts[0], "PER (period, frequency or wavenumber)")
        beta = parse_float(path, number, parts[1], "BETA (heading, degrees)")
        dof = parse_int(path, number, parts[2], f"I ({what} number)")
        modulus, _, re, im = (parse_float(path, number, parts[k], name)
                              for k, name in zip(range(3, 7), ("MOD", "PHA", "RE", "IM")))
        if per <= 0.0:
            raise FileFormatError(path, number, f"PER must be > 0 (zero and infinite frequency rows "
                                                f"carry no RAO), got {parts[0]}")
        if not -360.0 <= beta <= 360.0:
            raise FileFormatError(path, number, f"BETA must be a heading in -360..360 deg, got {parts[1]}")
        if dof < 1:
            raise FileFormatError(path, number, f"I must be a mode number >= 1, got {dof}")
        check_modulus(path, number, modulus, re, im)
        next_period(path, number, parts[0], per, periods)
        p = len(periods) - 1
        if beta not in headings:
            if p > 0:
                raise FileFormatError(path, number, f"BETA {parts[1]} was not among the headings of the "
                                                    "first period")
            if headings and beta < headings[-1]:
                raise FileFormatError(path, number, f"BETA {parts[1]} breaks the order of the headings "
                                                    "(must increase)")
            headings.append(beta)
        if not offset < dof <= offset + RIGID_MODES:
            ignored.add(dof)
            continue
        dof -= offset
        h = headings.index(beta)
        cell = cells.setdefault((p, h), {})
        first_line.setdefault((p, h), number)
        if dof in cell:
            raise FileFormatError(path, number, f"mode {dof + offset} given twice for PER {parts[0]}, BETA {parts[1]}")
        cell[dof] = complex(re, im)
    if not periods:
        raise FileFormatError(path, None, f"no data lines ({COLUMNS})")
    values = np.zeros((len(headings), len(periods), RIGID_MODES), dtype=complex)
    for p in range(len(periods)):
        for h in range(len(headings)):
            cell = cells.get((p, h))
            if cell is None:
                raise FileFormatError(path, None, f"no lines of modes {offset + 1}-{offset + RIGID_MODES} for "
                                                  f"PER {periods[p]:g}, BETA {headings[h]:g}")
            missing = [m + offset for m in range(1, RIGID_MODES + 1) if m not in cell]
            if missing:
                raise FileFormatError(path, first_line[(p, h)], f"modes {missing} missing for "
                                                                f"PER {periods[p]:g}, BETA {headings[h]:g}")
            values[h, p] = [cell[m] for m in range(1, RIGID_MODES + 1)]
    if ignored:
        notes.append(ignored_modes_note(path, ignored, offset))
    return np.array(periods), np.array(headings), values, notes


def ignored_modes_note(path: Path, modes: set[int], offset: int = 0) -> str:
    """The note for the modes read and left out of ``path``: all but ``offset + 1 .. offset + 6``."""
    listed = ", ".join(str(m) for m in sorted(modes)[:6]) + (", ..." if len(modes) > 6 else "")
    return (f"{path.name}: modes {listed} (generalised modes or other bodies) ignored; marinesim models the "
            f"rigid-body modes {offset + 1}-{offset + RIGID_MODES} of one body")


def _is_number(text: str) -> bool:
    try:
        float(text.replace("D", "E").replace("d", "e"))
    except ValueError:
        return False
    return True


def _first_nonblank(lines: list[str]) -> int:
    return next((n for n, text in enumerate(lines, 1) if text.strip()), 0)
