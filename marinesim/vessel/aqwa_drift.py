"""ANSYS AQWA listing (``.LIS``): the mean wave drift tables -> :class:`DriftTable`.

Layout relied on (AQWA-LINE listings, e.g. 2020 R1; nothing else in the listing is needed): pages titled
``* * * * W A V E - D R I F T   L O A D S   F O R   U N I T   W A V E   A M P L I T U D E * * 2   * * * *``, then
``* * * * F O R   S T R U C T U R E   n * * * *``, ``(WITH RESPECT TO STRUCTURE COG)`` and a header whose line
``DUE TO (RADIANS/SEC)d1 d2 ...`` lists the directions (degrees) of the page's columns; then a line ``DRIFT``
and, for each load, a label line (``SURGE(X)``, ``SWAY(Y)``, ``HEAVE(Z)``, ``ROLL(RX)``, ``PITCH(RY)``,
``YAW(RZ)``) followed by rows ``FREQ v1 v2 ...`` (rad/s, printed to 3 decimals, then one value per direction).
A page ends at a line ``1`` (the Fortran form feed) or at the row of stars that closes the deck; a page may
hold several loads, and a load whose rows run onto the next page of the same structure keeps its label.
The listing does not say whether the loads come from the far-field (momentum) or near-field (pressure)
method: they are read as printed. The job header's ``Unit System`` line, where there is one, must say
``Metric: kg, m [N]``.

Source convention, converted here once (:func:`aqwa_to_manoeuvring`):

* The values are mean loads per unit wave amplitude squared, N/m^2 (forces) and N m/m^2 (moments) in an SI
  listing: no scaling.
* AQWA's fixed reference axes are X, Y horizontal and Z up (right-handed): for a structure whose x axis is
  the global X axis, as in a hydrodynamic (AQWA-LINE) run, y points to port. The manoeuvring axes (y to
  starboard, z down) take ``X = F_X``, ``Y = -F_Y``, ``N = -M_Z``.
* ``DIRECTION`` is the direction the waves travel towards, degrees counter-clockwise from X (0 following,
  180 head seas, 90 travelling towards port): marinesim's ``beta_rel``. -180 and 180 are the same heading:
  the listing prints both (two solutions of the same waves, equal to the print's three digits where the
  load is well above the solver's noise); the first printed is kept and a note gives how far the other
  differs, as a share of the largest horizontal force (yaw: of the largest yaw moment).
* Moments are about the structure's centre of gravity (``WITH RESPECT TO STRUCTURE COG``), given in the
  notes where the listing's mass section prints it.

Left out, with a note: heave, roll and pitch drift (station keeping uses surge, sway and yaw) and the
tables of other structures.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError, ParameterError
from marinesim.tokens import parse_float, read_text
from marinesim.vessel.drift import DriftLoads, DriftTable, drift_table, wrapped_heading

TITLE = "WAVE-DRIFTLOADSFORUNITWAVEAMPLITUDE**2"
"""The drift page title, spaces removed."""
LOADS = ("SURGE(X)", "SWAY(Y)", "HEAVE(Z)", "ROLL(RX)", "PITCH(RY)", "YAW(RZ)")
"""The load labels of the listing, in AQWA's DOF order."""
READ = (0, 1, 5)
"""Indices in :data:`LOADS` of the loads read: surge, sway, yaw."""
AQWA_TO_MANOEUVRING = np.array([1.0, -1.0, -1.0])
"""AQWA (X, Y up-right-handed with Z up) -> manoeuvring axes (y starboard, z down): X, Y, N."""
SI_UNITS = "Metric: kg, m [N]"
MAX_ROWS = 10_000_000
_STRUCTURE = re.compile(r"FORSTRUCTURE(\d+)")


def read_aqwa_drift(path: str | Path, *, structure: int = 1, axisymmetric: bool = False) -> DriftTable:
    """The mean drift table of ``structure`` (1-based) in an AQWA ``.LIS`` listing (module docstring).

    The listing's directions must cover the circle (0..180 deg is completed by the port/starboard mirror);
    ``axisymmetric=True`` says the structure is symmetric about the vertical through its centre of gravity
    (a buoy, a spar) and makes the circle from the directions given (:func:`turned_round`). A malformed table
    is a :class:`FileFormatError` naming the line.
    """
    path = Path(path)
    return drift_table(path, aqwa_drift_loads(path, structure=structure), axisymmetric=axisymmetric)


def has_drift(path: str | Path) -> bool:
    """Whether the AQWA listing ``path`` prints wave-drift loads (its RAOs may come without them)."""
    return any(TITLE in _squeezed(line) for line in read_text(Path(path)).splitlines())


def aqwa_to_manoeuvring(values: np.ndarray) -> np.ndarray:
    """AQWA's surge, sway and yaw drift (..., 3) in its Z-up axes -> the manoeuvring axes: Y and N change sign."""
    return np.asarray(values, dtype=float) * AQWA_TO_MANOEUVRING


def aqwa_drift_loads(path: str | Path, *, structure: int = 1) -> DriftLoads:
    """The drift loads of ``structure`` at the directions the listing gives, in the manoeuvring axes."""
    path = Path(path)
    if isinstance(structure, bool) or not isinstance(structure, int) or structure < 1:
        raise ParameterError(f"AQWA structure must be a number >= 1, got {structure!r}")
    lines = read_text(path).splitlines()
    _check_units(path, lines)
    rows, structures, reference = _rows(path, lines, structure)
    if not rows:
        found = ", ".join(str(s) for s in sorted(structures)) or "none"
        raise FileFormatError(path, None, f"no wave-drift table ('WAVE-DRIFT LOADS FOR UNIT WAVE AMPLITUDE**2') "
                                          f"of structure {structure}; structures with one: {found}")
    omega, headings, values, notes = _assemble(path, rows)
    cog = _centre_of_gravity(lines, structure)
    where = (f"the centre of gravity ({cog[0]:g}, {cog[1]:g}, {cog[2]:g}) m" if cog is not None
             else "the centre of gravity (not printed in this listing)")
    notes.insert(0, f"AQWA listing, structure {structure}: drift loads ({reference}), moments about {where}; "
                    "Y and N sign-changed from AQWA's Z-up axes; direction = wave travel direction from the "
                    "global X axis; frequencies as printed (3 decimals)")
    return DriftLoads(omega, headings, aqwa_to_manoeuvring(values), tuple(notes))


def _squeezed(text: str) -> str:
    """``text`` upper case without spaces: AQWA's spaced-out titles become words."""
    return "".join(text.split()).upper()


def _check_units(path: Path, lines: list[str]) -> None:
    """Refuse a listing whose job header names a unit system other than SI."""
    for number, text in enumerate(lines, 1):
        if "UNIT SYSTEM" in text.upper() and ":" in text:
            units = text.split(":", 1)[1].strip()
            if units != SI_UNITS:
                raise FileFormatError(path, number, f"unit system {units!r}: only SI listings ({SI_UNITS!r}) are "
                                                    "read (drift loads in N/m^2 and N m/m^2)")
            return


def _rows(path: Path, lines: list[str], structure: int) -> tuple[list[tuple[int, float, float, int, float]],
                                                                   set[int], str]:
    """(line, frequency, direction, load index, value) of every drift value of ``structure``, the structures
    that have drift tables, and the page's reference (``WITH RESPECT TO ...``)."""
    rows: list[tuple[int, float, float, int, float]] = []
    structures: set[int] = set()
    reference = "WITH RESPECT TO STRUCTURE COG"
    inside = False
    current: int | None = None
    directions: list[float] | None = None
    load: int | None = None
    for number, text in enumerate(lines, 1):
        stripped = text.strip()
        squeezed = _squeezed(text)
        if TITLE in squeezed:
            inside, directions = True, None
            continue
        if not inside or not stripped:
            continue
        if stripped == "1" or set(stripped) == {"*"}:  # page break, or the stars closing the deck
            inside = False
            continue
        match = _STRUCTURE.search(squeezed)
        if match and squeezed.startswith("*"):
            number_now = int(match.group(1))
            if number_now != current:
                load = None  # a label does not carry over to another structure
            current = number_now
            structures.add(current)
            continue
        if squeezed.startswith("(WITHRESPECTTO"):
            reference = " ".join(stripped.strip("()").split())
            continue
        if squeezed.startswith("DUETO"):
            if "(RADIANS/SEC)" not in squeezed:
                raise FileFormatError(path, number, "expected the frequency column in (RADIANS/SEC) and the "
                                                    "directions after it")
            words = text.upper().split("(RADIANS/SEC)", 1)[1].split()
            directions = [parse_float(path, number, w, "DIRECTION (deg)") for w in words]
            if not directions:
                raise FileFormatError(path, number, "no directions after (RADIANS/SEC)")
            for word, direction in zip(words, directions):
                if not -360.0 <= direction <= 360.0:
                    raise FileFormatError(path, number, f"DIRECTION must be in -360..360 deg, got {word}")
            continue
        if squeezed in LOADS:
            load = LOADS.index(squeezed)
            continue
        if set(stripped) <= {"-", " "} or squeezed in ("DRIFT", "FORCESFREQUENCYDIRECTION(DEGREES)"):
            continue
        words = stripped.split()
        try:
            float(words[0])
        except ValueError:
            raise FileFormatError(path, number, f"unexpected line in the wave-drift table: {stripped[:60]!r} "
                                                f"(expected a load label {', '.join(LOADS)} or a row of numbers)"
                                  ) from None
        if current is None:
            raise FileFormatError(path, number, "drift row before the 'FOR STRUCTURE n' line of its page")
        if current != structure:
            continue
        if directions is None:
            raise FileFormatError(path, number, "drift row before the 'DUE TO (RADIANS/SEC)' line of directions")
        if load is None:
            raise FileFormatError(path, number, f"drift row before a load label ({', '.join(LOADS)})")
        if len(words) != 1 + len(directions):
            raise FileFormatError(path, number, f"expected FREQ and {len(directions)} value(s), one per direction "
                                                f"{', '.join(f'{d:g}' for d in directions)}; got {len(words)} numbers")
        freq = parse_float(path, number, words[0], "FREQUENCY (rad/s)")
        if freq <= 0.0:
            raise FileFormatError(path, number, f"FREQUENCY must be > 0 rad/s, got {words[0]}")
        for word, direction in zip(words[1:], directions):
            rows.append((number, freq, direction, load, parse_float(path, number, word, f"{LOADS[load]} drift")))
        if len(rows) > MAX_ROWS:
            raise FileFormatError(path, number, "more drift values than any listing holds")
    return rows, structures, reference


def _assemble(path: Path, rows: list[tuple[int, float, float, int, float]]) -> tuple[
        np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """Frequencies (rad/s, increasing), headings (deg in [-180, 180], increasing), AQWA-axes surge, sway and yaw
    (n_w, n_b, 3) and notes from the rows; each (frequency, heading) must have the three loads."""
    cells: dict[tuple[float, float, int], tuple[int, float]] = {}
    first_line: dict[float, int] = {}
    twice: dict[int, float] = {}  # load -> largest |difference| of a heading printed twice
    shown: dict[float, float] = {}
    for number, freq, direction, load, value in rows:
        heading = wrapped_heading(direction, shown)
        key = (freq, heading, load)
        first_line.setdefault(freq, number)
        if key in cells:
            twice[load] = max(twice.get(load, 0.0), abs(value - cells[key][1]))
            continue
        cells[key] = (number, value)
    freqs = sorted(first_line)
    headings = sorted({h for _, h, _ in cells})
    values = np.zeros((len(freqs), len(headings), 3))
    for i, freq in enumerate(freqs):
        for j, heading in enumerate(headings):
            for k, load in enumerate(READ):
                cell = cells.get((freq, heading, load))
                if cell is None:
                    raise FileFormatError(path, first_line[freq], f"no {LOADS[load]} drift for direction "
                                                                  f"{heading:g} deg at {freq:g} rad/s (every frequency "
                                                                  "needs surge, sway and yaw at every direction)")
                values[i, j, k] = cell[1]
    notes = []
    if twice:
        force = max(float(np.abs(values[..., :2]).max()), 1e-300)
        moment = max(float(np.abs(values[..., 2]).max()), 1e-300)
        worst_force = max((twice.get(load, 0.0) for load in READ[:2]), default=0.0) / force
        worst_moment = twice.get(READ[2], 0.0) / moment
        notes.append("a heading printed twice (-180 and 180 deg): the first kept; the other differs by up to "
                     f"{worst_force:.3g} of the largest horizontal force and {worst_moment:.3g} of the largest yaw "
                     "moment")
    other = sorted({LOADS[load] for _, _, _, load, _ in rows} - {LOADS[load] for load in READ})
    if other:
        notes.append(f"{', '.join(other)} drift left out: station keeping uses surge, sway and yaw")
    return np.array(freqs), np.array(headings), values, notes


def _centre_of_gravity(lines: list[str], structure: int) -> tuple[float, float, float] | None:
    """``CENTRE OF GRAVITY x y z`` (m) of the mass section of ``structure``; None where not printed."""
    title = f"MASSANDINERTIAPROPERTIESOFSTRUCTURE{structure}"
    inside = False
    for text in lines:
        squeezed = _squeezed(text).strip("*-")
        if "MASSANDINERTIAPROPERTIESOFSTRUCTURE" in squeezed:
            inside = squeezed.endswith(title)
            continue
        if inside and "CENTRE OF GRAVITY" in text.upper():
            words = text.upper().split("CENTRE OF GRAVITY", 1)[1].split()
            try:
                x, y, z = (float(w) for w in words[:3])
            except ValueError:
                return None
            return (x, y, z)
    return None
