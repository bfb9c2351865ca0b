"""WAMIT ``.4`` motion RAOs (numeric output) -> :class:`RaoTable`.

Source convention, converted here once: each line is ``PER BETA I MOD PHA RE IM``; ``PER`` is
the period in s (``IPERIO = 1``, the default), the frequency in rad/s (``IPERIO = 2``) or the
infinite-depth wavenumber ``K ULEN`` (``IPERIO = 3``), as the ``.cfg`` beside the file says;
``BETA`` is the direction the waves travel towards, degrees from the body x axis (already
marinesim's ``beta_rel``); the time factor is ``exp(+i w t)`` with phase lead (marinesim's own).
Translations are per wave amplitude A; rotations per ``A / ULEN``, so rad/m = value / ULEN.
``ULEN`` and ``g`` come from the ``.gdf`` of the same name, ``rho`` from the ``.frc``.
Lines with zero modulus carry a dummy phase (90 deg): only ``RE`` and ``IM`` are used. The
reference point is the origin of WAMIT's body coordinates.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.constants import G, RHO_SEAWATER
from marinesim.errors import FileFormatError, ParameterError, require_within
from marinesim.hull.gdf import read_gdf_header
from marinesim.vessel.rao import ROTATIONS, RaoTable, make_table
from marinesim.tokens import parse_float, parse_int, read_text

COLUMNS = "PER BETA I MOD PHA RE IM"
ULEN_RANGE_M = (0.01, 1000.0)
"""WAMIT's length scale (m): 1 or a body dimension, from a tank model's to the largest vessel's."""
PERIOD_KINDS = {1: "period (s)", 2: "frequency (rad/s)", 3: "wavenumber K*ULEN (infinite depth)"}


def read_wamit(path: str | Path, *, ulen: float | None = None, period_kind: int | None = None) -> RaoTable:
    """Read a WAMIT ``.4`` file; ``ulen`` and ``period_kind`` (IPERIO) override the files beside it."""
    path = Path(path)
    notes: list[str] = []
    g, gdf_ulen = _gdf_settings(path.with_suffix(".gdf"))
    if ulen is None:
        ulen = gdf_ulen
        if ulen is None:
            ulen = 1.0
            notes.append("ULEN not found (no .gdf beside the file): assumed 1 m; check the pitch "
                         "and roll long-wave limits")
    require_within("WAMIT ULEN", ulen, *ULEN_RANGE_M, "m")
    if period_kind is None:
        period_kind = _iperio(path.with_suffix(".cfg"))
    if period_kind not in PERIOD_KINDS:
        raise ParameterError(f"WAMIT IPERIO {period_kind} is not supported (supported: "
                             + ", ".join(f"{k} = {v}" for k, v in PERIOD_KINDS.items()) + ")")
    rho = _frc_rho(path.with_suffix(".frc"))
    if rho is None:
        rho = RHO_SEAWATER
        notes.append(f"rho not found (no .frc beside the file): assumed {RHO_SEAWATER:g} kg/m^3")

    periods, headings, values = _read_rows(path)
    if period_kind == 1:
        omega = 2.0 * math.pi / periods
    elif period_kind == 2:
        omega = periods.copy()
    else:
        omega = np.sqrt(g * periods / ulen)
    order = np.argsort(omega)
    values = values[:, order]
    values[..., list(ROTATIONS)] /= ulen
    try:
        return make_table(omega[order], np.radians(headings), [0.0], values[None], reference_point=(0.0, 0.0, 0.0),
                          rho=rho, g=g, source=str(path), source_format="wamit",
                          notes=tuple(notes) + (f"PER column read as {PERIOD_KINDS[period_kind]}, "
                                                f"ULEN = {ulen:g} m, g = {g:g} m/s^2",))
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like a ``.4`` file: a first line of seven numbers."""
    text = head.decode("utf-8", errors="replace")
    first = next((line for line in text.splitlines() if line.strip()), "").split()
    try:
        [float(part) for part in first]
    except ValueError:
        return False
    return len(first) == 7


def _read_rows(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Periods (file order, monotonic), headings (deg, increasing) and values (heading, period, 6)."""
    periods: list[float] = []
    headings: list[float] = []
    cells: dict[tuple[int, int], dict[int, complex]] = {}
    first_line: dict[tuple[int, int], int] = {}
    for number, text in enumerate(read_text(path).splitlines(), 1):
        parts = text.split()
        if not parts:
            continue
        if len(parts) != 7:
            raise FileFormatError(path, number, f"expected 7 columns {COLUMNS}, got {len(parts)}")
        per = parse_float(path, number, parts[0], "PER (period, frequency or wavenumber)")
        beta = parse_float(path, number, parts[1], "BETA (heading, degrees)")
        dof = parse_int(path, number, parts[2], "I (mode 1..6)")
        modulus, _, re, im = (parse_float(path, number, parts[k], name)
                              for k, name in zip(range(3, 7), ("MOD", "PHA", "RE", "IM")))
        if per <= 0.0:
            raise FileFormatError(path, number, f"PER must be > 0 (zero and infinite frequency rows "
                                                f"carry no RAO), got {parts[0]}")
        if not -360.0 <= beta <= 360.0:
            raise FileFormatError(path, number, f"BETA must be a heading in -360..360 deg, got {parts[1]}")
        if not 1 <= dof <= 6:
            raise FileFormatError(path, number, f"I must be a rigid-body mode 1..6 (one body), got {dof}")
        if abs(math.hypot(re, im) - modulus) > 1e-4 * max(modulus, 1e-30):
            raise FileFormatError(path, number, f"MOD {modulus:g} disagrees with |RE + i IM| = "
                                                f"{math.hypot(re, im):g}")
        if not periods or per != periods[-1]:
            if per in periods:
                raise FileFormatError(path, number, f"PER {parts[0]} appears again after other periods "
                                                    "(duplicate or unsorted)")
            if len(periods) >= 2 and (per - periods[-1]) * (periods[-1] - periods[-2]) < 0:
                raise FileFormatError(path, number, f"PER {parts[0]} breaks the order of the periods "
                                                    "(must be monotonic)")
            periods.append(per)
        p = len(periods) - 1
        if beta not in headings:
            if p > 0:
                raise FileFormatError(path, number, f"BETA {parts[1]} was not among the headings of the "
                                                    "first period")
            if headings and beta < headings[-1]:
                raise FileFormatError(path, number, f"BETA {parts[1]} breaks the order of the headings "
                                                    "(must increase)")
            headings.append(beta)
        h = headings.index(beta)
        cell = cells.setdefault((p, h), {})
        first_line.setdefault((p, h), number)
        if dof in cell:
            raise FileFormatError(path, number, f"mode {dof} given twice for PER {parts[0]}, BETA {parts[1]}")
        cell[dof] = complex(re, im)
    if not periods:
        raise FileFormatError(path, None, f"no data lines ({COLUMNS})")
    values = np.zeros((len(headings), len(periods), 6), dtype=complex)
    for p in range(len(periods)):
        for h in range(len(headings)):
            cell = cells.get((p, h))
            if cell is None:
                raise FileFormatError(path, None, f"no lines for PER {periods[p]:g}, BETA {headings[h]:g}")
            missing = [m for m in range(1, 7) if m not in cell]
            if missing:
                raise FileFormatError(path, first_line[(p, h)], f"modes {missing} missing for "
                                                                f"PER {periods[p]:g}, BETA {headings[h]:g}")
            values[h, p] = [cell[m] for m in range(1, 7)]
    return np.array(periods), np.array(headings), values


def _gdf_settings(gdf: Path) -> tuple[float, float | None]:
    """(g, ULEN) from the ``.gdf`` beside the file; (G, None) if there is none."""
    if not gdf.is_file():
        return G, None
    header = read_gdf_header(gdf)
    return header.g, header.ulen


def _iperio(cfg: Path) -> int:
    """IPERIO from a WAMIT ``.cfg`` (``IPERIO=2``); WAMIT's default 1 (periods) without one."""
    if not cfg.is_file():
        return 1
    for number, text in enumerate(read_text(cfg).splitlines(), 1):
        key, _, value = text.partition("=")
        if key.strip().upper() == "IPERIO":
            return parse_int(cfg, number, value.split()[0] if value.split() else "", "IPERIO")
    return 1


def _frc_rho(frc: Path) -> float | None:
    """RHO from the third line of a ``.frc`` (IALTFRC 1 or 2 layout), or None if there is none."""
    if not frc.is_file():
        return None
    lines = read_text(frc).splitlines()
    if len(lines) < 3 or not lines[2].split():
        raise FileFormatError(frc, 3, "expected RHO")
    rho = parse_float(frc, 3, lines[2].split()[0], "RHO (kg/m^3)")
    if rho <= 0:
        raise FileFormatError(frc, 3, f"RHO must be > 0, got {rho:g}")
    return rho
