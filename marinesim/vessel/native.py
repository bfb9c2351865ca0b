"""marinesim's own RAO table: plain text/CSV, easy to write by hand or from a spreadsheet.

```
# Anything after '#' is a comment.
vessel = Box barge 20 x 8 x 2 m            # optional settings, "key = value", before the table
reference_point_m = 0, 0, 0                # in the vessel's own frame (metadata)
rho_kg_m3 = 1025
g_m_s2 = 9.80665
phase = lead                               # lead (default) or lag: the response's phase
speed_kn,heading_deg,period_s,surge_amp_m_m,surge_phase_deg,...,yaw_amp_deg_m,yaw_phase_deg
0,180,10.0,0.51,90.0,...
```

The header row names the columns and, by their suffixes, the units:

* frequency: ``omega_rad_s``, ``freq_hz`` or ``period_s`` (one of them);
* speed (optional): ``speed_m_s`` or ``speed_kn``;
* ``heading_deg``: the direction the waves travel towards, relative to the bow
  (0 following, 90 towards port, 180 head seas: marinesim's ``beta_rel``);
* per DOF (surge, sway, heave, roll, pitch, yaw): ``<dof>_amp_m_m`` for translations,
  ``<dof>_amp_deg_m`` or ``<dof>_amp_rad_m`` for rotations, and ``<dof>_phase_deg``.

Phases follow ``x(t) = amp cos(w t + phase)`` for the wave ``cos(w t)`` at the reference point
(lead) unless ``phase = lag``. Columns are separated by commas, or by blanks when the header
has no comma. Rows form a full grid: one block of frequencies (monotonic, the same list in
every block) per speed and heading. Headings 0..180 are mirrored to port.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.atomic import atomic_path
from marinesim.constants import KNOT
from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.rao import DOFS, ROTATIONS, RaoTable, make_table
from marinesim.tokens import by_content, parse_float, read_text

FREQUENCY_COLUMNS = {"omega_rad_s": lambda v: v, "freq_hz": lambda v: 2.0 * math.pi * v,
                     "period_s": lambda v: 2.0 * math.pi / v}
SPEED_COLUMNS = {"speed_m_s": 1.0, "speed_kn": KNOT}
SETTINGS = ("vessel", "reference_point_m", "rho_kg_m3", "g_m_s2", "phase")


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes hold a header row (``heading_deg`` and a ``*_phase_deg`` column)."""
    return any("heading_deg" in line and "_phase_deg" in line
               for line in head.decode("utf-8", errors="replace").splitlines())


@by_content
def read_native(path: str | Path) -> RaoTable:
    """Read a native RAO table (format in the module docstring)."""
    path = Path(path)
    settings: dict[str, tuple[int, str]] = {}
    header: list[str] | None = None
    rows: list[tuple[int, list[str]]] = []
    separator: str | None = None
    for number, raw in enumerate(read_text(path).splitlines(), 1):
        text = raw.split("#", 1)[0].strip()
        if not text:
            continue
        if header is None and "=" in text:
            key, _, value = (part.strip() for part in text.partition("="))
            if key not in SETTINGS:
                raise FileFormatError(path, number, f"unknown setting {key!r} (known: {', '.join(SETTINGS)})")
            settings[key] = (number, value)
        elif header is None:
            separator = "," if "," in text else None
            header = [name.strip() for name in text.split(separator)]
            header_line = number
        else:
            rows.append((number, [cell.strip() for cell in text.split(separator)]))
    if header is None:
        raise FileFormatError(path, None, "no header row (e.g. heading_deg,omega_rad_s,surge_amp_m_m,...)")
    columns = _columns(path, header_line, header)
    if not rows:
        raise FileFormatError(path, None, "no data rows after the header")
    return _table(path, settings, columns, rows, len(header))


def _columns(path: Path, line: int, header: list[str]) -> dict[str, int]:
    """Map of the recognised column names to their positions; refuses unknown or missing ones."""
    known = {"heading_deg", *FREQUENCY_COLUMNS, *SPEED_COLUMNS}
    for dof in DOFS:
        known.add(f"{dof}_phase_deg")
        known.update({f"{dof}_amp_deg_m", f"{dof}_amp_rad_m"} if DOFS.index(dof) in ROTATIONS
                     else {f"{dof}_amp_m_m"})
    columns: dict[str, int] = {}
    for position, name in enumerate(header):
        if name not in known:
            raise FileFormatError(path, line, f"unknown column {name!r}")
        if name in columns:
            raise FileFormatError(path, line, f"column {name!r} given twice")
        columns[name] = position
    need = ["heading_deg"] + [f"{dof}_phase_deg" for dof in DOFS]
    for name in need:
        if name not in columns:
            raise FileFormatError(path, line, f"missing column {name!r}")
    for group, what in ((FREQUENCY_COLUMNS, "frequency"), (SPEED_COLUMNS, "speed")):
        present = [name for name in group if name in columns]
        if len(present) > 1 or (what == "frequency" and not present):
            raise FileFormatError(path, line, f"give exactly one {what} column of {', '.join(group)}")
    for j, dof in enumerate(DOFS):
        if not any(name.startswith(f"{dof}_amp_") for name in columns):
            unit = "deg_m" if j in ROTATIONS else "m_m"
            raise FileFormatError(path, line, f"missing column '{dof}_amp_{unit}'")
        if f"{dof}_amp_deg_m" in columns and f"{dof}_amp_rad_m" in columns:
            raise FileFormatError(path, line, f"give one amplitude column for {dof}")
    return columns


def _table(path: Path, settings: dict[str, tuple[int, str]], columns: dict[str, int],
           rows: list[tuple[int, list[str]]], width: int) -> RaoTable:
    frequency_name = next(name for name in FREQUENCY_COLUMNS if name in columns)
    speed_name = next((name for name in SPEED_COLUMNS if name in columns), None)
    sign = _phase_sign(path, settings)
    blocks: dict[tuple[float, float], list[tuple[int, float, np.ndarray]]] = {}
    order: list[tuple[float, float]] = []
    for number, cells in rows:
        if len(cells) != width:
            raise FileFormatError(path, number, f"expected {width} columns as in the header, got {len(cells)}")
        value = {name: parse_float(path, number, cells[i], name) for name, i in columns.items()}
        speed = value[speed_name] * SPEED_COLUMNS[speed_name] if speed_name else 0.0
        heading = value["heading_deg"]
        if not -180.0 <= heading <= 360.0:
            raise FileFormatError(path, number, f"heading_deg must be in -180..360, got {heading:g}")
        if speed < 0:
            raise FileFormatError(path, number, f"{speed_name} must be >= 0, got {cells[columns[speed_name]]}")
        frequency = value[frequency_name]
        if frequency <= 0:
            raise FileFormatError(path, number, f"{frequency_name} must be > 0, got {frequency:g}")
        rao = np.empty(6, dtype=complex)
        for j, dof in enumerate(DOFS):
            amp_name = next(name for name in columns if name.startswith(f"{dof}_amp_"))
            amp = value[amp_name]
            if amp < 0:
                raise FileFormatError(path, number, f"{amp_name} must be >= 0, got {amp:g}")
            if amp_name.endswith("deg_m"):
                amp = math.radians(amp)
            rao[j] = amp * np.exp(1j * sign * math.radians(value[f"{dof}_phase_deg"]))
        key = (speed, heading)
        if key not in blocks:
            order.append(key)
            blocks[key] = []
        elif order[-1] != key:
            raise FileFormatError(path, number, f"speed {speed:g} m/s, heading {heading:g} deg appears again "
                                                "after another block (duplicate or unsorted rows)")
        block = blocks[key]
        if block and (frequency == block[-1][1]
                      or len(block) >= 2 and (frequency - block[-1][1]) * (block[-1][1] - block[-2][1]) < 0):
            raise FileFormatError(path, number, f"{frequency_name} {frequency:g} repeats or breaks the order "
                                                "of the frequencies (must be monotonic, no duplicates)")
        block.append((number, frequency, rao))
    first = [f for _, f, _ in blocks[order[0]]]
    for key in order:
        these = blocks[key]
        for (number, frequency, _), expected in zip(these, first):
            if frequency != expected:
                raise FileFormatError(path, number, f"{frequency_name} {frequency:g} differs from the first "
                                                    f"block's {expected:g}: every block lists the same frequencies")
        if len(these) != len(first):
            raise FileFormatError(path, these[-1][0], f"block has {len(these)} frequencies, the first has {len(first)}")
    speeds = sorted({s for s, _ in order})
    headings = sorted({h for _, h in order})
    values = np.zeros((len(speeds), len(headings), len(first), 6), dtype=complex)
    filled = np.zeros((len(speeds), len(headings)), dtype=bool)
    for (s, h), block in blocks.items():
        i, j = speeds.index(s), headings.index(h)
        values[i, j] = [rao for _, _, rao in block]
        filled[i, j] = True
    if not filled.all():
        i, j = np.argwhere(~filled)[0]
        raise FileFormatError(path, None, f"no rows for speed {speeds[i]:g} m/s, heading {headings[j]:g} deg: "
                                          "the rows must form a full speed x heading grid")
    omega = FREQUENCY_COLUMNS[frequency_name](np.array(first))
    order_w = np.argsort(omega)
    reference = _setting_floats(path, settings, "reference_point_m", 3, (0.0, 0.0, 0.0))
    rho = _setting_floats(path, settings, "rho_kg_m3", 1, (1025.0,))[0]
    g = _setting_floats(path, settings, "g_m_s2", 1, (9.80665,))[0]
    notes = (f"vessel: {settings['vessel'][1]}",) if "vessel" in settings else ()
    try:
        return make_table(omega[order_w], np.radians(headings), np.array(speeds), values[:, :, order_w],
                          reference_point=reference, rho=rho, g=g, source=str(path), source_format="native",
                          notes=notes)
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def _phase_sign(path: Path, settings: dict[str, tuple[int, str]]) -> float:
    line, value = settings.get("phase", (0, "lead"))
    if value not in ("lead", "lag"):
        raise FileFormatError(path, line, f"phase must be 'lead' or 'lag', got {value!r}")
    return 1.0 if value == "lead" else -1.0


def _setting_floats(path: Path, settings: dict[str, tuple[int, str]], key: str, count: int,
                    default: tuple[float, ...]) -> tuple[float, ...]:
    if key not in settings:
        return default
    line, text = settings[key]
    parts = text.replace(",", " ").split()
    if len(parts) != count:
        raise FileFormatError(path, line, f"{key} takes {count} number(s), got {text!r}")
    numbers = tuple(parse_float(path, line, part, key) for part in parts)
    if key != "reference_point_m" and numbers[0] <= 0:
        raise FileFormatError(path, line, f"{key} must be > 0, got {text!r}")
    return numbers


def write_native(table: RaoTable, path: str | Path) -> None:
    """Write ``table`` (every speed and heading of the full circle) in the native format.

    Amplitudes and phases with 10 significant digits; rotations in deg/m.
    """
    names = ["speed_m_s", "heading_deg", "omega_rad_s"]
    for j, dof in enumerate(DOFS):
        names += [f"{dof}_amp_{'deg_m' if j in ROTATIONS else 'm_m'}", f"{dof}_phase_deg"]
    lines = ["# marinesim RAO table (docs: marinesim/vessel/native.py)",
             f"# source: {table.source_format} {table.source}",
             "reference_point_m = " + ", ".join(f"{v:.10g}" for v in table.reference_point),
             f"rho_kg_m3 = {table.rho:.10g}", f"g_m_s2 = {table.g:.10g}", "phase = lead", ",".join(names)]
    scale = np.array([1.0, 1.0, 1.0, 180.0 / math.pi, 180.0 / math.pi, 180.0 / math.pi])
    for s, speed in enumerate(table.speed):
        for b, beta in enumerate(table.beta):
            for w, omega in enumerate(table.omega):
                h = table.values[s, b, w]
                cells = [speed, math.degrees(beta), omega]
                for j in range(6):
                    cells += [abs(h[j]) * scale[j], math.degrees(np.angle(h[j]))]
                lines.append(",".join(f"{c:.10g}" for c in cells))
    with atomic_path(path) as temp:
        temp.write_text("\n".join(lines) + "\n", encoding="utf-8")
