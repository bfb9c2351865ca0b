"""WAMIT mean drift forces, ``.8`` (momentum conservation) or ``.9`` (pressure integration) -> :class:`DriftTable`.

Source convention, converted here once: each line is ``PER BETA1 BETA2 I MOD PHA RE IM``. ``PER`` is read as
for the ``.4`` (:class:`marinesim.vessel.wamit.Settings`: the ``.cfg`` beside the file says period, frequency or
wavenumber; WAMIT's default is the period in s); rows with ``PER <= 0`` (WAMIT's zero- and infinite-period
limits) carry no drift and are skipped. ``BETA1``, ``BETA2`` are the directions two waves travel towards, degrees
from the body x axis (marinesim's ``beta_rel``); the mean drift of one wave train is the diagonal ``BETA1 ==
BETA2``, real (``RE``; ``IM`` is zero there); rows with ``BETA1 != BETA2`` (bidirectional cross terms) are left
out. Modes: 1 surge and 2 sway per ``rho g A^2 ULEN``, 6 yaw per ``rho g A^2 ULEN^2``; a ``.9`` also gives
heave, roll and pitch (3-5) and, with negative numbers -4..-6, the moments in body axes (MSS's ``wamit2vessel``
reads these as such): station keeping needs 1, 2 and 6 only, the rest are left out with a note. WAMIT's axes are
x forward, y to port, z up, forces on the body: the table's manoeuvring axes (y to starboard, z down) take
``X = F1, Y = -F2, N = -M6``. ``ULEN`` and ``g`` come from the ``.gdf`` beside the file, ``rho`` from the
``.frc``, unless given.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from marinesim.constants import RHO_SEAWATER
from marinesim.errors import FileFormatError, ParameterError, require_positive
from marinesim.formats import check_file
from marinesim.tokens import by_content, parse_float, parse_int, read_text
from marinesim.vessel.drift import DriftTable, make_drift_table
from marinesim.vessel.wamit import Settings, frc_rho
from marinesim.vessel.wamit_rows import check_modulus, next_period

COLUMNS = "PER BETA1 BETA2 I MOD PHA RE IM"
DRIFT_MODES = (1, 2, 6)
"""WAMIT modes read: surge force, sway force, yaw moment."""
WAMIT_TO_MANOEUVRING = np.array([1.0, -1.0, -1.0])
"""WAMIT (x forward, y port, z up) -> manoeuvring axes (x forward, y starboard, z down): X, Y, N."""


def read_drift(path: Path, ulen: float | None = None, rho: float | None = None, g: float | None = None
               ) -> DriftTable:
    """Read a WAMIT ``.8`` or ``.9`` file's mean drift (module docstring) into a :class:`DriftTable`.

    ``ulen`` (m), ``rho`` (kg/m^3) and ``g`` (m/s^2) override the run's own values, which otherwise come from
    the ``.gdf`` (ULEN, GRAV) and ``.frc`` (RHO) beside the file, else 1 m, 1025 kg/m^3 and 9.80665 m/s^2 (with
    a note). A (period, heading) cell without its modes 1, 2 and 6 is a :class:`FileFormatError` naming it.
    """
    path = Path(path)
    check_file(path)
    settings = Settings.beside(path, ulen=ulen)
    notes = list(settings.notes)
    if g is not None:
        settings.g = require_positive("g", g)
    if rho is None:
        rho = frc_rho(path.with_suffix(".frc"))
        if rho is None:
            rho = RHO_SEAWATER
            notes.append(f"rho not found (no .frc beside the file): assumed {RHO_SEAWATER:g} kg/m^3")
    rho = require_positive("rho", rho)
    if any(settings.xbody):
        x, y, _, phi = settings.xbody
        raise FileFormatError(path, None, f"{settings.placed_by} places the body at ({x:g}, {y:g}) m, turned "
                                          f"{phi:g} deg, in WAMIT's global frame: drift tables of such runs "
                                          "(moments about the global origin) are not supported")

    periods, headings, values, row_notes = _read_rows(path, settings.header_lines)
    notes += row_notes
    settings.check_headings(path, headings)
    omega = settings.omega(periods, path)
    # nondimensional -> N/m^2 and N m/m^2, then WAMIT's y-port / z-up axes -> the manoeuvring y-starboard / z-down
    scale = rho * settings.g * np.array([settings.ulen, settings.ulen, settings.ulen**2])
    coefficients = values * scale * WAMIT_TO_MANOEUVRING
    notes.append(settings.describe() + f", rho = {rho:g} kg/m^3")
    try:
        return make_drift_table(omega, np.radians(headings), coefficients, source=str(path), notes=tuple(notes))
    except ParameterError as error:
        raise FileFormatError(path, None, f"{error} (the file covers heading(s) "
                                          f"{', '.join(f'{h:g}' for h in headings)} deg)") from None


@by_content
def _read_rows(path: Path, header_lines: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """Periods (file order, monotonic), headings (deg, increasing), nondimensional values (period, heading, 3:
    modes 1, 2, 6) and notes of the eight-column file ``path``."""
    periods: list[float] = []
    period_line: list[int] = []
    headings: set[float] = set()
    cells: dict[tuple[int, float], dict[int, float]] = {}
    cell_line: dict[tuple[int, float], int] = {}
    skipped_limits = cross = 0
    other_modes: set[int] = set()
    notes: list[str] = []
    lines = read_text(path).splitlines()
    first = next((n for n, text in enumerate(lines, 1) if text.strip()), 0)
    for number, text in enumerate(lines, 1):
        parts = text.split()
        if not parts:
            continue
        if number <= header_lines or (number == first and not _is_number(parts[0])):
            notes.append(f"header line {number} of {path.name} skipped")
            continue
        if len(parts) != 8:
            raise FileFormatError(path, number, f"expected 8 columns {COLUMNS}, got {len(parts)}")
        per = parse_float(path, number, parts[0], "PER (period, frequency or wavenumber)")
        beta1 = parse_float(path, number, parts[1], "BETA1 (heading, degrees)")
        beta2 = parse_float(path, number, parts[2], "BETA2 (heading, degrees)")
        mode = parse_int(path, number, parts[3], "I (mode number)")
        modulus, _, re, im = (parse_float(path, number, parts[k], name)
                              for k, name in zip(range(4, 8), ("MOD", "PHA", "RE", "IM")))
        for name, beta, token in (("BETA1", beta1, parts[1]), ("BETA2", beta2, parts[2])):
            if not -360.0 <= beta <= 360.0:
                raise FileFormatError(path, number, f"{name} must be a heading in -360..360 deg, got {token}")
        check_modulus(path, number, modulus, re, im)
        if per <= 0.0:
            skipped_limits += 1
            continue
        if next_period(path, number, parts[0], per, periods):
            period_line.append(number)
        if beta1 != beta2:
            cross += 1
            continue
        if mode not in DRIFT_MODES:
            other_modes.add(mode)
            continue
        key = (len(periods) - 1, beta1)
        headings.add(beta1)
        cell = cells.setdefault(key, {})
        cell_line.setdefault(key, number)
        if mode in cell:
            raise FileFormatError(path, number, f"mode {mode} given twice for PER {parts[0]}, BETA {parts[1]}")
        cell[mode] = re
    if not cells:
        raise FileFormatError(path, None, f"no mean drift lines ({COLUMNS} with BETA1 = BETA2 and I = 1, 2 or 6)")
    ordered = sorted(headings)
    values = np.zeros((len(periods), len(ordered), 3))
    for p, per in enumerate(periods):
        for h, beta in enumerate(ordered):
            cell = cells.get((p, beta))
            if cell is None:
                raise FileFormatError(path, period_line[p], f"PER {per:g} has no mean drift lines for BETA {beta:g} "
                                                            "(every period needs every heading's modes 1, 2 and 6)")
            missing = [m for m in DRIFT_MODES if m not in cell]
            if missing:
                raise FileFormatError(path, cell_line[(p, beta)], f"mode(s) {', '.join(map(str, missing))} missing "
                                                                  f"for PER {per:g}, BETA {beta:g}")
            values[p, h] = [cell[m] for m in DRIFT_MODES]
    if skipped_limits:
        notes.append(f"{skipped_limits} line(s) with PER <= 0 (zero/infinite period limits) skipped")
    if cross:
        notes.append(f"{cross} line(s) with BETA1 != BETA2 (bidirectional cross terms) left out: the mean drift "
                     "of one wave train is the diagonal")
    if other_modes:
        notes.append(f"modes {', '.join(map(str, sorted(other_modes)))} left out: station keeping uses surge, sway "
                     "and yaw (1, 2, 6)")
    return np.array(periods), np.array(ordered), values, notes


def _is_number(text: str) -> bool:
    try:
        float(text.replace("D", "E").replace("d", "e"))
    except ValueError:
        return False
    return True
