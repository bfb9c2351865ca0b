"""NEMOH v3 QTF results, ``results/QTF/OUT_QTFM_N.dat`` (difference frequency) -> mean drift :class:`DriftTable`.

Layout relied on (NEMOH v3's QTF postprocessor): one header line ``w1[rad/s] w2[rad/s] beta1[deg] beta2[deg]
DOF MOD(QTF)/rho/g PHASE(QTF)[deg] Re(QTF)/rho/g Im(QTF)/rho/g`` (the first two named ``f1[Hz] f2[Hz]`` or
``T1[s] T2[s]`` when ``Nemoh.cal`` asks for frequencies in Hz or periods), then one row of these nine numbers
per (w1, w2 <= w1, beta1, beta2, DOF). The mean drift of one wave train is the diagonal ``w1 == w2``,
``beta1 == beta2``, real (``Re``; ``Im`` is zero there): the other rows (slowly varying difference-frequency
terms, bidirectional cross terms) are left out. ``DOF`` numbers the generalised forces of ``Nemoh.cal``: the
reader takes the force along x, the force along y and the moment about z by their definitions there.
NEMOH's ``QTFM_DUOK.dat`` and the other one-contribution files (radians, dimensional) and the sum-frequency
``OUT_QTFP_N.dat`` are refused.

Source convention, converted here once (:func:`nemoh_to_manoeuvring`):

* The values are divided by ``rho g`` of the run: times ``rho g`` of ``Nemoh.cal`` (in the project folder,
  two above ``results/QTF``; ``rho`` and ``g`` given here override it) they are N/m^2 (forces) and N m/m^2 (moments)
  per unit wave amplitude squared.
* NEMOH's axes are x, y horizontal and z up (right-handed): for a mesh with x forward, y points to port. The
  manoeuvring axes (y to starboard, z down) take ``X = F_x``, ``Y = -F_y``, ``N = -M_z``. The moment is about
  the point of its definition in ``Nemoh.cal`` (given in the notes). NEMOH's time factor ``exp(-i w t)`` does
  not matter on the real diagonal.
* ``beta`` is the direction the waves travel towards, degrees from the x axis (NEMOH's incident potential
  varies as ``exp(i k (x cos beta + y sin beta))``): marinesim's ``beta_rel``. NEMOH's QTF solver prints it in
  radians with three decimals before the postprocessor turns it into degrees (180 deg reads 180.023), so the
  headings are rounded to 0.1 deg.
* Frequencies in Hz become ``2 pi f``, periods ``2 pi / T``; the file prints three decimals.

Left out, with a note: heave, roll and pitch (station keeping uses surge, sway and yaw).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError, require_positive
from marinesim.formats import check_file
from marinesim.tokens import leading_numbers, parse_float, parse_int, read_text
from marinesim.vessel.drift import DriftLoads, DriftTable, drift_table, wrapped_heading
from marinesim.vessel.nemoh import project_root, read_settings

COLUMNS = "w1 w2 beta1 beta2 DOF MOD/rho/g PHASE Re/rho/g Im/rho/g"
NEMOH_TO_MANOEUVRING = np.array([1.0, -1.0, -1.0])
"""NEMOH (x, y, z up) -> manoeuvring axes (y starboard, z down): X, Y, N."""
FREQUENCY_KINDS = {"w1": "rad/s", "f1": "Hz", "t1": "s"}
"""The first header word (lower case, before its unit) -> what the frequency columns hold."""
HEADING_DECIMALS = 1
"""Headings are rounded to 0.1 deg (NEMOH prints them through radians with three decimals: within 0.03 deg)."""
MAX_ROWS = 50_000_000


def read_nemoh_drift(path: str | Path, *, rho: float | None = None, g: float | None = None,
                     axisymmetric: bool = False) -> DriftTable:
    """The mean drift table of NEMOH's ``OUT_QTFM_N.dat`` (module docstring).

    ``rho`` (kg/m^3) and ``g`` (m/s^2) override those of ``Nemoh.cal``; without ``Nemoh.cal`` in the project
    folder both must be given (the DOFs are then taken as NEMOH's usual force list: 1 F_x, 2 F_y, 6 M_z). The
    headings must cover the circle (0..180 deg is completed by the port/starboard mirror); ``axisymmetric=True``
    says the body is symmetric about the vertical through its moment point (a spar, a buoy) and makes the circle
    from the headings given (:func:`marinesim.vessel.aqwa_drift.turned_round`). A malformed file is a
    :class:`FileFormatError` naming the line.
    """
    path = Path(path)
    return drift_table(path, nemoh_drift_loads(path, rho=rho, g=g), axisymmetric=axisymmetric)


def nemoh_to_manoeuvring(values: np.ndarray) -> np.ndarray:
    """NEMOH's surge, sway and yaw drift (..., 3) in its z-up axes -> the manoeuvring axes: Y and N change sign."""
    return np.asarray(values, dtype=float) * NEMOH_TO_MANOEUVRING


def nemoh_drift_loads(path: str | Path, *, rho: float | None = None, g: float | None = None) -> DriftLoads:
    """The drift loads of ``OUT_QTFM_N.dat`` at the headings it gives, in the manoeuvring axes (N/m^2, N m/m^2)."""
    path = Path(path)
    check_file(path)
    if "QTFP" in path.name.upper():
        raise FileFormatError(path, None, "a sum-frequency QTF (OUT_QTFP): the mean drift is the diagonal of the "
                                          "difference-frequency OUT_QTFM_N.dat")
    notes: list[str] = []
    root: Path | None
    try:
        root = project_root(path)
    except FileFormatError:
        root = None
    if root is None:
        if rho is None or g is None:
            raise FileFormatError(path, None, "no Nemoh.cal in the file's folder or the two above it (the project "
                                              "folder): give rho and g, the values are divided by the run's rho g")
        dofs, point = {1: 0, 2: 1, 6: 2}, None
        notes.append("no Nemoh.cal: DOF 1, 2, 6 taken as F_x, F_y, M_z (NEMOH's usual force list)")
    else:
        cal = root / "Nemoh.cal"
        settings = read_settings(cal)
        dofs, point = _forces(cal)
        if rho is None:
            rho = settings.rho
        else:
            notes.append(f"rho {rho:g} kg/m^3 given (Nemoh.cal says {settings.rho:g})")
        if g is None:
            g = settings.g
        else:
            notes.append(f"g {g:g} m/s^2 given (Nemoh.cal says {settings.g:g})")
    rho, g = require_positive("rho", rho), require_positive("g", g)
    omega, headings, values, row_notes = _read_rows(path, dofs)
    where = (f"the vertical through ({point[0]:g}, {point[1]:g}) m (Nemoh.cal's moment point)" if point is not None
             else "NEMOH's moment point (no Nemoh.cal)")
    notes.insert(0, f"NEMOH OUT_QTFM_N diagonal times rho g = {rho:g} * {g:g}; Y and N sign-changed from NEMOH's "
                    f"z-up axes; yaw moment about {where}; beta = wave travel direction from x")
    return DriftLoads(omega, headings, nemoh_to_manoeuvring(values * rho * g), tuple(notes + row_notes))


def _forces(cal: Path) -> tuple[dict[int, int], tuple[float, float, float]]:
    """{DOF number of the QTF file: 0 F_x, 1 F_y, 2 M_z} and the moment's point (m) from ``Nemoh.cal``'s list of
    generalised forces (after the body's DOFs: ``TYPE nx ny nz x y z``, type 1 force, 2 moment)."""
    lines = read_text(cal).splitlines()
    count_line = 18  # after the 6 DOFs of the one body read_settings accepts (lines 12-17)
    words = leading_numbers(lines[count_line - 1]) if len(lines) >= count_line else []
    if not words:
        raise FileFormatError(cal, count_line, "expected the number of resulting generalised forces")
    count = parse_int(cal, count_line, words[0], "the number of generalised forces")
    wanted = {(1, (1.0, 0.0, 0.0)): 0, (1, (0.0, 1.0, 0.0)): 1, (2, (0.0, 0.0, 1.0)): 2}
    dofs: dict[int, int] = {}
    point = (0.0, 0.0, 0.0)
    for k in range(count):
        number = count_line + 1 + k
        words = leading_numbers(lines[number - 1]) if len(lines) >= number else []
        if len(words) < 7:
            raise FileFormatError(cal, number, "expected a generalised force TYPE nx ny nz x y z")
        kind = parse_int(cal, number, words[0], "force TYPE (1 force, 2 moment)")
        axis = tuple(parse_float(cal, number, w, "force axis") for w in words[1:4])
        index = wanted.get((kind, axis))
        if index is not None and index not in dofs.values():
            dofs[k + 1] = index
            if index == 2:
                point = tuple(parse_float(cal, number, w, "moment point (m)") for w in words[4:7])
    missing = [name for name, index in (("force along x", 0), ("force along y", 1), ("moment about z", 2))
               if index not in dofs.values()]
    if missing:
        raise FileFormatError(cal, count_line, f"no generalised {', '.join(missing)} among the {count} forces")
    return dofs, point


def _read_rows(path: Path, dofs: dict[int, int]) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """Frequencies (rad/s, increasing), headings (deg in [-180, 180], increasing), values / (rho g) (n_w, n_b, 3:
    F_x, F_y, M_z in NEMOH's axes) and notes of the diagonal rows."""
    lines = read_text(path).splitlines()
    first = next((n for n, text in enumerate(lines, 1) if text.strip()), None)
    if first is None:
        raise FileFormatError(path, None, "empty file: expected the header line and the QTF rows")
    kind = _frequency_kind(path, first, lines[first - 1])
    cells: dict[tuple[float, float], dict[int, float]] = {}
    cell_line: dict[tuple[float, float], int] = {}
    frequency_line: dict[float, int] = {}
    off_diagonal = cross = rows = 0
    other: set[int] = set()
    shown: dict[float, float] = {}
    for number, text in enumerate(lines[first:], first + 1):
        words = text.split()
        if not words:
            continue
        if len(words) != 9:
            raise FileFormatError(path, number, f"expected 9 columns {COLUMNS}, got {len(words)}")
        w1, w2 = (parse_float(path, number, w, f"frequency ({kind})") for w in words[:2])
        beta1, beta2 = (parse_float(path, number, w, "beta (deg)") for w in words[2:4])
        dof = parse_int(path, number, words[4], "DOF (generalised force number)")
        modulus, _, re, im = (parse_float(path, number, w, name) for w, name in
                              zip(words[5:], ("MOD(QTF)/rho/g", "PHASE(QTF) (deg)", "Re(QTF)/rho/g", "Im(QTF)/rho/g")))
        rows += 1
        if rows > MAX_ROWS:
            raise FileFormatError(path, number, "more QTF rows than any NEMOH run writes")
        if w1 <= 0.0 or w2 <= 0.0:
            raise FileFormatError(path, number, f"frequencies must be > 0, got {words[0]} {words[1]}")
        for word, beta in ((words[2], beta1), (words[3], beta2)):
            if not -360.0 <= beta <= 360.0:
                raise FileFormatError(path, number, f"beta must be a heading in -360..360 deg, got {word}")
        if dof < 1:
            raise FileFormatError(path, number, f"DOF must be >= 1, got {dof}")
        if abs(math.hypot(re, im) - modulus) > 1e-4 * max(modulus, 1e-30):
            raise FileFormatError(path, number, f"MOD {modulus:g} disagrees with |Re + i Im| = {math.hypot(re, im):g}")
        if w1 != w2:
            off_diagonal += 1
            continue
        heading = wrapped_heading(round(beta1, HEADING_DECIMALS), shown)
        if heading != wrapped_heading(round(beta2, HEADING_DECIMALS), shown):
            cross += 1
            continue
        if dof not in dofs:
            other.add(dof)
            continue
        omega = _omega(kind, w1)
        key = (omega, heading)
        frequency_line.setdefault(omega, number)
        cell = cells.setdefault(key, {})
        cell_line.setdefault(key, number)
        if dofs[dof] in cell:
            raise FileFormatError(path, number, f"DOF {dof} at {words[0]} {kind}, beta {words[2]} deg given twice")
        cell[dofs[dof]] = re
    if not cells:
        raise FileFormatError(path, None, f"no mean drift rows ({COLUMNS} with w1 = w2, beta1 = beta2 and DOF "
                                          f"{', '.join(map(str, sorted(dofs)))})")
    frequencies = sorted({w for w, _ in cells})
    headings = sorted({b for _, b in cells})
    names = {index: dof for dof, index in dofs.items()}
    values = np.zeros((len(frequencies), len(headings), 3))
    for i, omega in enumerate(frequencies):
        for j, heading in enumerate(headings):
            cell = cells.get((omega, heading))
            if cell is None:
                raise FileFormatError(path, frequency_line[omega], f"no mean drift rows for beta {heading:g} deg at "
                                                                   f"{omega:.6g} rad/s (every frequency needs every "
                                                                   "heading)")
            missing = [names[k] for k in range(3) if k not in cell]
            if missing:
                raise FileFormatError(path, cell_line[(omega, heading)], f"DOF {', '.join(map(str, missing))} missing "
                                                                         f"for {omega:.6g} rad/s, beta {heading:g} deg")
            values[i, j] = [cell[k] for k in range(3)]
    notes = []
    if off_diagonal:
        notes.append(f"{off_diagonal} row(s) with w1 != w2 (slowly varying difference-frequency terms) left out: "
                     "the mean drift is the diagonal")
    if cross:
        notes.append(f"{cross} row(s) with beta1 != beta2 (bidirectional cross terms) left out")
    if other:
        notes.append(f"DOF {', '.join(map(str, sorted(other)))} left out: station keeping uses surge, sway and yaw")
    return np.array(frequencies), np.array(headings), values, notes


def _frequency_kind(path: Path, number: int, header: str) -> str:
    """What the frequency columns hold (``rad/s``, ``Hz``, ``s``), from the header line; other files refused."""
    lower = header.lower()
    words = lower.split()
    if not words or words[0].split("[")[0] not in FREQUENCY_KINDS:
        raise FileFormatError(path, number, f"expected NEMOH's QTF header ({COLUMNS}), got {header.strip()[:60]!r}")
    if "[rad]" in lower.replace(" [", "["):
        raise FileFormatError(path, number, "beta in radians: a one-contribution QTF file (QTFM_DUOK.dat, "
                                            "QTFM_HASBO.dat ...); read the total OUT_QTFM_N.dat")
    if "rho/g" not in lower:
        raise FileFormatError(path, number, "expected the values divided by rho g (MOD(QTF)/rho/g ... in the header)")
    return FREQUENCY_KINDS[words[0].split("[")[0]]


def _omega(kind: str, value: float) -> float:
    """The frequency column's ``value`` (``kind``: rad/s, Hz or s) in rad/s."""
    if kind == "Hz":
        return 2.0 * math.pi * value
    if kind == "s":
        return 2.0 * math.pi / value
    return value
