"""Writers of RAO tables, so that a table read from one program can be handed to another.

:func:`write_rao` picks the format by the extension of the output (:data:`WRITERS`); each writer
is the exact inverse of its reader's conversion (docs/CONVENTIONS.md, "Transfer functions"), and
a round trip (read -> write -> read) is exact to the precision written:

* ``.4``, WAMIT numeric output (:func:`write_wamit`), inverse of
  :func:`marinesim.vessel.wamit.read_wamit`: rows ``PER BETA I MOD PHA RE IM`` in WAMIT's own layout
  (``1X,E13.6`` for PER and BETA, ``1X,I5`` for the mode, ``1X,1PE13.6`` for the four values),
  loops as WAMIT nests them: period (increasing), heading (increasing, the table's own headings:
  0..180 for a port/starboard-mirrored table, else the whole circle), mode 1..6. PER is the period in
  s (``IPEROUT = 1``, WAMIT's default), BETA the direction the waves travel towards, deg from the
  body x axis (marinesim's ``beta_rel``); values are per wave amplitude with ``ULEN = 1`` (rotations
  in rad/m) in WAMIT's convention, time factor ``exp(+i w t)`` and phase lead in deg, which is
  marinesim's own: RE and IM are the internal RAO's real and imaginary parts. A zero value gets
  WAMIT's dummy phase 90 deg. Precision: 6 significant digits in PER and BETA, 7 in the values. The
  ``.4`` has no speed column: a table of several speeds is refused unless one of its speeds is chosen;
  nor does it carry rho, g, water depth or the reference point (WAMIT keeps them in the ``.frc``,
  ``.gdf`` and ``.pot``): a reader assumes seawater, ULEN 1, infinite depth and the origin; the
  writer's notes say which of these the table differs from.
* ``.csv``, marinesim's native table (:func:`marinesim.vessel.native.write_native`): every speed and
  heading, 10 significant digits, rotations in deg/m, phase lead (no water depth).
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from marinesim.atomic import atomic_path
from marinesim.constants import KNOT, RHO_SEAWATER
from marinesim.errors import ParameterError
from marinesim.vessel.native import write_native
from marinesim.vessel.rao import RaoTable

WRITERS = {".4": "WAMIT .4 numeric output", ".csv": "marinesim native table"}
"""Output extension -> the format written there."""
SPEED_MATCH_M_S = 0.005 * KNOT
"""A chosen speed (m/s) selects the tabulated speed within this distance (0.005 kn: the rounding of a speed in kn)."""
ZERO_PHASE_DEG = 90.0
"""The phase WAMIT prints for a value of zero modulus (readers use RE and IM only)."""
WAMIT_SIDE_FILES = (".cfg", ".gdf", ".pot", ".frc")
"""Files a WAMIT reader takes settings from when they sit beside the ``.4``."""


def write_rao(table: RaoTable, path: str | Path, *, speed: float | None = None) -> tuple[str, ...]:
    """Write ``table`` to ``path`` atomically in the format of its extension (:data:`WRITERS`); ``speed``
    (m/s) picks one speed of a multi-speed table for ``.4``, which has no speed column (``.csv`` keeps
    them all). Returns notes on what the format does not carry. An unknown extension is a
    :class:`ParameterError` naming the supported ones."""
    path = Path(path)
    if check_extension(path) == ".4":
        return write_wamit(table, path, speed=speed)
    return write_csv(table, path)


def check_extension(path: str | Path) -> str:
    """The extension (lower case) of ``path`` if :data:`WRITERS` has it, else a :class:`ParameterError` naming the
    supported ones."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in WRITERS:
        raise ParameterError(f"cannot write RAOs to {path.name}: unknown extension {path.suffix or '(none)'!r}; "
                             "supported: " + ", ".join(f"{ext} ({what})" for ext, what in WRITERS.items()))
    return suffix


def write_csv(table: RaoTable, path: str | Path) -> tuple[str, ...]:
    """Write ``table`` (every speed and heading) as a native table; returns notes on what the table loses."""
    notes = []
    if math.isfinite(table.depth):
        notes.append(f"the native table has no water depth: the table's {table.depth:g} m is not written "
                     "(a reader assumes deep water for the long-wave limits)")
    write_native(table, path)
    return tuple(notes)


def write_wamit(table: RaoTable, path: str | Path, *, speed: float | None = None) -> tuple[str, ...]:
    """Write ``table`` as a WAMIT ``.4`` (layout and conventions in the module docstring); ``speed`` (m/s)
    chooses one speed of a table of several (refused without it; ignored for a one-speed table). Returns
    notes on what the ``.4`` does not carry."""
    path = Path(path)
    notes: list[str] = []
    several = table.speed.size > 1
    if several:
        table = _one_speed(table, speed, "a WAMIT .4")
        notes.append(f"wrote speed {table.speed[0] / KNOT:g} kn only (a .4 has no speed column)")
    elif table.speed[0] != 0.0:
        notes.append(f"the table's speed {table.speed[0] / KNOT:g} kn is not written (a .4 has no speed column)")
    notes += _unwritten(table, path)
    keep = table.beta <= math.pi + 1e-9 if table.mirrored else np.ones(table.beta.size, dtype=bool)
    headings = np.degrees(table.beta[keep])
    values = table.values[0][keep]  # (heading, frequency, 6); ULEN = 1: rotations already per A / ULEN
    lines = []
    for w in range(table.omega.size - 1, -1, -1):  # increasing period
        period = _fortran_e(2.0 * math.pi / table.omega[w])
        for b, heading in enumerate(headings):
            beta = _fortran_e(heading)
            for j in range(6):
                h = complex(values[b, w, j])
                re, im = h.real + 0.0, h.imag + 0.0  # no "-0.0"
                phase = ZERO_PHASE_DEG if h == 0 else math.degrees(math.atan2(im, re))
                lines.append(f" {period} {beta} {j + 1:5d}"
                             + "".join(f" {v:13.6E}" for v in (abs(h), phase, re, im)))
    with atomic_path(path) as temp:
        temp.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return tuple(notes)


def _fortran_e(value: float) -> str:
    """``value`` as Fortran's ``E13.6`` writes it: ``0.105000E+01`` (6 significant digits), right-aligned."""
    if value == 0.0:
        return f"{'0.000000E+00':>13}"
    mantissa, exponent = f"{abs(value):.5E}".split("E")
    digits = mantissa.replace(".", "")
    text = f"{'-' if value < 0 else ''}0.{digits}E{int(exponent) + 1:+03d}"
    return f"{text:>13}"


def _one_speed(table: RaoTable, speed: float | None, where: str) -> RaoTable:
    """``table`` cut to its speed nearest ``speed`` (m/s), which must be one of its speeds; a multi-speed table
    and no ``speed`` is refused, naming the speeds."""
    listed = ", ".join(f"{s / KNOT:g}" for s in table.speed)
    if speed is None:
        raise ParameterError(f"{where} has no speed column and this table has speeds {listed} kn: choose one "
                             "(marinesim rao --speed-kn), or write .csv, which keeps them all")
    i = int(np.argmin(np.abs(table.speed - speed)))
    if abs(table.speed[i] - speed) > SPEED_MATCH_M_S:
        raise ParameterError(f"speed {speed / KNOT:g} kn is not one of the table's speeds ({listed} kn): "
                             f"{where} takes a tabulated speed, not an interpolated one")
    return replace(table, speed=table.speed[i:i + 1], values=table.values[i:i + 1])


def _unwritten(table: RaoTable, path: Path) -> list[str]:
    """Notes on what a ``.4`` cannot hold and a reader will assume instead."""
    notes = []
    if any(table.reference_point):
        notes.append("the reference point (" + ", ".join(f"{v:g}" for v in table.reference_point)
                     + ") m is not written: a .4 refers to WAMIT's body origin")
    if math.isfinite(table.depth):
        notes.append(f"water depth {table.depth:g} m is not written: give it in a .pot beside the .4 (HBOT)")
    if abs(table.rho - RHO_SEAWATER) > 1e-9:
        notes.append(f"rho {table.rho:g} kg/m^3 is not written (a .4 reader takes it from the .frc)")
    beside = [path.with_suffix(ext).name for ext in WAMIT_SIDE_FILES if path.with_suffix(ext).exists()]
    if beside:
        notes.append(f"{', '.join(beside)} beside {path.name}: a WAMIT reader takes its settings (ULEN, IPEROUT, "
                     "depth) from them; this .4 assumes ULEN 1 and periods (IPEROUT 1)")
    return notes
