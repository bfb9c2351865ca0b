"""ANSYS AQWA listing (``.LIS``): the position RAO tables -> :class:`RaoTable`.

Layout relied on (AQWA-LINE listings, e.g. 2020 R1; nothing else in the listing is needed):

* ``G L O B A L   P A R A M E T E R S``: lines ``WATER  DEPTH  . . . =  3.0000``,
  ``DENSITY  OF  WATER . . . =  1025.000`` and ``ACCELERATION  DUE  TO GRAVITY . . . =  9.807`` (SI).
* ``M A S S   A N D   I N E R T I A   P R O P E R T I E S   O F   S T R U C T U R E   n``:
  a line ``CENTRE OF GRAVITY  x  y  z`` (m, global axes).
* Pages headed ``H Y D R O D Y N A M I C   P A R A M E T E R S   F O R   S T R U C T U R E   n``, then
  ``(WITH RESPECT TO STRUCTURE COG)``, then the title ``R.A.O.S-VARIATION WITH WAVE DIRECTION`` (the
  ``VEL`` and ``ACC`` tables of the same title are velocities and accelerations, not read), four header
  lines and a dashed line, then for each frequency a line ``PERIOD FREQ DIRECTION`` followed by
  ``AMP PHASE`` for X, Y, Z, RX, RY, RZ, and one line per further direction carrying ``DIRECTION`` and
  the twelve numbers only. A page ends at a line ``1`` (the Fortran form feed); the table continues on
  the next page of the same title. The tables ``... VARIATION WITH WAVE PERIOD/FREQUENCY`` repeat the
  same numbers and are not read.

Source convention, converted here once (:func:`aqwa_to_internal`):

* ``DIRECTION`` is the direction the waves travel towards, degrees counter-clockwise from the global X
  axis (0 = waves travelling along +X): marinesim's ``beta_rel`` for a structure whose x axis is the
  global X axis, as in a hydrodynamic (AQWA-LINE) run. -180 and 180 are the same heading: the file
  prints both, they are checked to agree and one is kept.
* ``PHASE`` is a phase *lag* in degrees relative to the wave at the reference point: the response is
  ``A cos(w t - PHASE)``, so marinesim's (lead) RAO is ``A exp(-i PHASE)``. Evidence (the WEC-Sim
  cylinder, ``tests/test_vessel_reader_aqwa.py``): at 0.04 rad/s, waves along +X, surge prints phase +90 and
  pitch -90; marinesim's long-wave limits are surge ``-i / tanh(kh)`` (phase -90) and pitch ``+i k``.
* Rotations are in degrees per metre of wave amplitude (pitch / k -> 57.3 at long waves): converted to
  rad/m. Translations are m/m.
* The reference point is the structure's centre of gravity (the page says ``WITH RESPECT TO STRUCTURE
  COG``), in AQWA's global axes (z up from the mean free surface).

``FREQ`` is printed to 3 decimals and ``PERIOD`` to 2: the frequency is taken from whichever of the two
is the more precise (the period below 0.79 rad/s), so no frequency is off by more than 0.06 %.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from marinesim.constants import G, RHO_SEAWATER
from marinesim.errors import FileFormatError, HeadingError, ParameterError
from marinesim.tokens import parse_float, read_text
from marinesim.vessel.rao import RaoTable, SolverRaos, make_table

TITLE = "R.A.O.S-VARIATION WITH WAVE DIRECTION"
MAX_FREQUENCIES = 10_000
MAX_DIRECTIONS = 1_000
ROTATION = np.array([False, False, False, True, True, True])
_SPACED = re.compile(r"\s+")


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like an AQWA listing."""
    text = head.decode("utf-8", errors="replace").upper()
    return "AQWA" in text and ("DECK" in text or "JOB" in text)


def read_aqwa(path: str | Path, *, structure: int = 1) -> RaoTable:
    """Read the position RAOs of ``structure`` (1-based) from an AQWA ``.LIS`` listing."""
    path = Path(path)
    raos = read_aqwa_raos(path, structure=structure)
    extra = {"depth": raos.depth} if math.isfinite(raos.depth) else {}
    try:
        return make_table(raos.omega, np.radians(raos.headings_deg), [0.0], raos.values[None],
                          reference_point=raos.reference_point, rho=raos.rho, g=raos.g, source=str(path),
                          source_format="aqwa", notes=raos.notes, **extra)
    except HeadingError as error:
        raise FileFormatError(path, None, f"{error} (the listing covers direction(s) "
                              + ", ".join(f"{h:g}" for h in raos.headings_deg) + " deg only)") from None
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def aqwa_to_internal(amplitude: np.ndarray, phase_lag_deg: np.ndarray) -> np.ndarray:
    """AQWA's ``AMP`` and ``PHASE`` (..., 6) -> marinesim's complex RAO (..., 6): phase lag in degrees to
    lead (``A exp(-i PHASE)``), rotations deg/m -> rad/m."""
    values = np.asarray(amplitude, dtype=float) * np.exp(-1j * np.radians(phase_lag_deg))
    return values * np.where(ROTATION, math.pi / 180.0, 1.0)


def read_aqwa_raos(path: str | Path, *, structure: int = 1) -> SolverRaos:
    """The position RAO tables of ``structure`` in marinesim's convention, headings as the listing gives
    them (:func:`read_aqwa` makes the table: a partial one where the headings leave a gap)."""
    path = Path(path)
    if isinstance(structure, bool) or not isinstance(structure, int) or structure < 1:
        raise ParameterError(f"AQWA structure must be a number >= 1, got {structure!r}")
    lines = read_text(path).splitlines()
    notes: list[str] = []
    rho = _global(path, lines, "DENSITYOFWATER", "density of water (kg/m^3)")
    g = _global(path, lines, "ACCELERATIONDUETOGRAVITY", "gravity (m/s^2)")
    depth = _global(path, lines, "WATERDEPTH", "water depth (m)")
    if rho is None:
        rho = RHO_SEAWATER
        notes.append(f"no DENSITY OF WATER in the listing: {RHO_SEAWATER:g} kg/m^3 assumed")
    if g is None:
        g = G
        notes.append(f"no ACCELERATION DUE TO GRAVITY in the listing: {G:g} m/s^2 assumed")
    if depth is None:
        depth = math.inf
        notes.append("no WATER DEPTH in the listing: deep water assumed")
    elif depth <= 0.0:
        raise FileFormatError(path, None, f"WATER DEPTH must be > 0 m, got {depth:g}")
    cog = _centre_of_gravity(path, lines, structure)
    if cog is None:
        cog = (0.0, 0.0, 0.0)
        notes.append(f"no CENTRE OF GRAVITY of structure {structure} in the listing: reference point (0, 0, 0) "
                     "assumed")
    rows, structures = _rao_rows(path, lines, structure)
    if not rows:
        found = ", ".join(str(s) for s in sorted(structures)) or "none"
        raise FileFormatError(path, None, f"no position RAO table ({TITLE!r}) of structure {structure}; "
                                          f"structures with RAO tables: {found}")
    omega, headings, values = _assemble(path, rows)
    notes.append(f"AQWA listing, structure {structure}: position RAOs at the centre of gravity "
                 f"({cog[0]:g}, {cog[1]:g}, {cog[2]:g}) m; phase lag (deg) negated, rotations deg/m -> rad/m; "
                 f"direction = wave travel direction from the global X axis; water depth "
                 + (f"{depth:g} m" if math.isfinite(depth) else "infinite"))
    return SolverRaos(omega, headings, values, cog, float(rho), float(g), float(depth), str(path), tuple(notes))


def _squeezed(text: str) -> str:
    """``text`` upper case without spaces: AQWA's spaced-out titles become words."""
    return _SPACED.sub("", text).upper()


def _global(path: Path, lines: list[str], key: str, what: str) -> float | None:
    """The number after ``=`` on the first line whose squeezed text starts with ``key`` and dots."""
    for number, text in enumerate(lines, 1):
        squeezed = _squeezed(text)
        if squeezed.startswith(key) and "=" in text:
            value = text.rsplit("=", 1)[1].split()
            if not value:
                raise FileFormatError(path, number, f"expected the {what} after '='")
            return parse_float(path, number, value[0], what)
    return None


def _centre_of_gravity(path: Path, lines: list[str], structure: int) -> tuple[float, float, float] | None:
    """``CENTRE OF GRAVITY x y z`` of the mass section of ``structure``; None without one."""
    title = f"MASSANDINERTIAPROPERTIESOFSTRUCTURE{structure}"
    inside = False
    for number, text in enumerate(lines, 1):
        squeezed = _squeezed(text).strip("*")
        if "MASSANDINERTIAPROPERTIESOFSTRUCTURE" in squeezed:
            inside = squeezed.endswith(title) or squeezed.strip("*-").endswith(title)
            continue
        if inside and "CENTRE OF GRAVITY" in text.upper():
            parts = text.upper().split("CENTRE OF GRAVITY", 1)[1].split()
            if len(parts) < 3:
                raise FileFormatError(path, number, "expected three coordinates x y z after CENTRE OF GRAVITY")
            x, y, z = (parse_float(path, number, parts[k], f"centre of gravity {axis} (m)")
                       for k, axis in enumerate("xyz"))
            return (x, y, z)
    return None


def _rao_rows(path: Path, lines: list[str], structure: int) -> tuple[list[tuple[int, float, float, float, list[float]]],
                                                                       set[int]]:
    """(line, period, freq, direction, twelve numbers) of every row of the position RAO tables of
    ``structure``, and the structures that have such tables."""
    rows: list[tuple[int, float, float, float, list[float]]] = []
    structures: set[int] = set()
    current: int | None = None
    in_table = False
    period = freq = math.nan
    for number, text in enumerate(lines, 1):
        stripped = text.strip()
        squeezed = _squeezed(text)
        match = re.search(r"HYDRODYNAMICPARAMETERSFORSTRUCTURE(\d+)", squeezed)
        if match:
            current, in_table = int(match.group(1)), False
            continue
        if stripped == "1" or not stripped:  # page break; a blank line inside a table separates frequencies
            if stripped == "1":
                in_table = False
            continue
        if stripped.upper() == TITLE:
            if current is None:
                raise FileFormatError(path, number, "RAO table without the HYDRODYNAMIC PARAMETERS FOR "
                                                    "STRUCTURE page heading before it")
            structures.add(current)
            in_table = "header"  # until the dashed line under the units
            continue
        if in_table == "header":
            if stripped.startswith("(SECS)"):
                in_table = "units"
            continue
        if in_table == "units":
            if set(stripped) <= {"-"}:
                in_table = True
                continue
            raise FileFormatError(path, number, "expected the dashed line under the units of the RAO table")
        if in_table is not True or current != structure:
            continue
        parts = stripped.split()
        if len(parts) == 15:
            period = parse_float(path, number, parts[0], "PERIOD (s)")
            freq = parse_float(path, number, parts[1], "FREQ (rad/s)")
            parts = parts[2:]
        elif len(parts) != 13:
            if not any(line.strip() for line in lines[number:]):
                raise FileFormatError(path, number, f"the listing ends inside the RAO table: {len(parts)} numbers "
                                                    "where a row has 13 or 15 (a file cut short?)")
            in_table = False  # the table ended (another section follows on the page)
            continue
        if math.isnan(freq):
            raise FileFormatError(path, number, "direction line before the first PERIOD FREQ line")
        direction = parse_float(path, number, parts[0], "DIRECTION (deg)")
        numbers = [parse_float(path, number, p, "RAO amplitude or phase") for p in parts[1:]]
        rows.append((number, period, freq, direction, numbers))
        if len(rows) > MAX_FREQUENCIES * MAX_DIRECTIONS:
            raise FileFormatError(path, number, "more RAO rows than any listing holds")
    return rows, structures


def _assemble(path: Path, rows: list[tuple[int, float, float, float, list[float]]]) -> tuple[
        np.ndarray, np.ndarray, np.ndarray]:
    """(omega increasing, headings in [0, 360) increasing, values (headings, frequencies, 6)) of ``rows``."""
    cells: dict[tuple[float, float], tuple[int, list[float]]] = {}
    frequencies: dict[float, float] = {}
    for number, period, freq, direction, numbers in rows:
        if period <= 0.0 or freq <= 0.0:
            raise FileFormatError(path, number, f"PERIOD and FREQ must be > 0, got {period:g} {freq:g}")
        if not -360.0 <= direction <= 360.0:
            raise FileFormatError(path, number, f"DIRECTION must be in -360..360 deg, got {direction:g}")
        amplitudes = numbers[0::2]
        if min(amplitudes) < 0.0:
            raise FileFormatError(path, number, "RAO amplitudes must be >= 0")
        # the more precise of FREQ (3 decimals) and 2 pi / PERIOD (2 decimals)
        omega = 2.0 * math.pi / period if 0.0005 / freq > 0.005 / period else freq
        frequencies.setdefault(freq, omega)
        heading = round(direction % 360.0, 6) % 360.0
        key = (freq, heading)
        if key in cells:
            first_line, first = cells[key]
            if not _same(first, numbers):
                raise FileFormatError(path, number, f"direction {direction:g} deg at FREQ {freq:g} disagrees with "
                                                    f"the same heading on line {first_line}")
            continue
        cells[key] = (number, numbers)
    freqs = sorted(frequencies)
    headings = sorted({h for _, h in cells})
    if len(freqs) > MAX_FREQUENCIES or len(headings) > MAX_DIRECTIONS:
        raise FileFormatError(path, None, f"{len(freqs)} frequencies and {len(headings)} directions: more than "
                                          f"{MAX_FREQUENCIES} and {MAX_DIRECTIONS}")
    values = np.zeros((len(headings), len(freqs), 6), dtype=complex)
    for i, freq in enumerate(freqs):
        for j, heading in enumerate(headings):
            cell = cells.get((freq, heading))
            if cell is None:
                raise FileFormatError(path, None, f"no RAOs for direction {heading:g} deg at FREQ {freq:g} rad/s "
                                                  "(every frequency must list the same directions)")
            numbers = np.array(cell[1])
            values[j, i] = aqwa_to_internal(numbers[0::2], numbers[1::2])
    omega = np.array([frequencies[f] for f in freqs])
    if np.any(np.diff(omega) <= 0.0):
        raise FileFormatError(path, None, "the frequencies of the RAO table are not distinct")
    return omega, np.array(headings), values


def _same(a: list[float], b: list[float]) -> bool:
    """Whether two rows of the same heading (printed twice, as -180 and 180) agree within the print: the
    complex values within 1 % of the amplitude plus the last printed digit."""
    za = aqwa_to_internal(np.array(a[0::2]), np.array(a[1::2]))
    zb = aqwa_to_internal(np.array(b[0::2]), np.array(b[1::2]))
    scale = np.maximum(np.abs(za), np.abs(zb))
    return bool(np.all(np.abs(za - zb) <= 0.01 * scale + 1e-3))
