"""WAMIT's report (``.out``) -> :class:`RaoTable`: the same tables as its numeric files, in one file.

The report gives g, ULEN, the water depth and density, the body's volumes, centre of buoyancy and centre of
gravity, the hydrostatic and gravitational restoring coefficients, then per wave period (always in
seconds, whatever IPEROUT says) the added mass and damping, the exciting forces (``DIFFRACTION``, else
``HASKIND``) and, where WAMIT solved the motions, the ``RESPONSE AMPLITUDE OPERATORS``, each as modulus
and phase (whole degrees) per heading. Normalisation and convention are those of the numeric files
(:mod:`marinesim.vessel.wamit`, :mod:`marinesim.vessel.wamit_forces`): ``exp(+i w t)``, phase lead,
heading = the direction the waves travel towards, rotations per ``A / ULEN``.

With motions in the report they are the RAOs. Without them (a run without the body's mass: IMASS = 0) the
RAOs are solved from the report's forces with the scenario's mass
(:class:`~marinesim.vessel.body.RigidBody`). WAMIT's restoring coefficients hold the gravity of a mass
``rho V`` at the report's centre of gravity; the scenario's mass at its own centre replaces it
(:func:`~marinesim.vessel.body.gravity_stiffness`). Modes above 6 (other bodies, generalised modes) are
left out with a note; the zero- and infinite-period blocks carry no RAO. WAMIT 7.2 prints no water density:
its default, 1025 kg/m^3 (:data:`~marinesim.constants.RHO_SEAWATER`), is taken then, with a note.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from marinesim.constants import RHO_SEAWATER
from marinesim.errors import FileFormatError
from marinesim.formats import check_file
from marinesim.tokens import parse_float, parse_int, read_text
from marinesim.vessel.body import RigidBody, gravity_stiffness, rigid_body_mass
from marinesim.vessel.rao import ROTATIONS, RaoTable
from marinesim.vessel.wamit import Settings, table_from
from marinesim.vessel.wamit_forces import dimensional, solve_motions
from marinesim.vessel.wamit_rows import RIGID_MODES, ignored_modes_note

BANNER = b"WAMIT  Version"
SECTIONS = {"ADDED-MASS AND DAMPING COEFFICIENTS": "radiation", "DIFFRACTION EXCITING FORCES AND MOMENTS": "diffraction",
            "HASKIND EXCITING FORCES AND MOMENTS": "haskind", "RESPONSE AMPLITUDE OPERATORS": "motions"}
PERIOD = re.compile(r"^\s*Wave period \(sec\)\s*=\s*(\S+)")
OTHER_PERIOD = re.compile(r"^\s*Wave period\s*=\s*(infinite|zero)")
PLACEMENT = re.compile(r"XBODY =\s*(\S+)\s+YBODY =\s*(\S+)\s+ZBODY =\s*(\S+)\s+PHIBODY =\s*(\S+)")
RUN_LINE = re.compile(r"^\s+\d+\.\d+\s+\d\d:\d\d:\d\d\s")
"""A line of the run's log at the top (``Period  Time  RAD  DIFF``): a period the run solved."""
TITLE = re.compile(r"^[A-Z]{3,}[A-Z ,&()-]*")
HEADING = re.compile(r"^\s*Wave Heading \(deg\)\s*:\s*(\S+)\s*$")
HEADER_KEYS = {"Gravity:": "g", "Length scale:": "ulen", "Water depth:": "depth", "Water density:": "rho"}
RESTORING = {"C(3,3),C(3,4),C(3,5):": [(2, 2), (2, 3), (2, 4)], "C(4,4),C(4,5),C(4,6):": [(3, 3), (3, 4), (3, 5)],
             "C(5,5),C(5,6):": [(4, 4), (4, 5)]}


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes are WAMIT's report: its banner in the first lines."""
    return BANNER in head[:2048]


class Report:
    """What a WAMIT report holds, as read (nondimensional, file order): ``periods`` (s), ``headings``
    (deg), ``added``/``damping`` (periods, 6, 6), ``forces`` and ``motions`` (headings, periods, 6) complex
    (``motions`` None without them), ``restoring`` (6, 6), header values (``g``, ``ulen``, ``depth``,
    ``rho``, ``volume``, ``cog``; ``printed``: the header keys the report itself gives), ``bodies`` and
    ``ignored`` (modes above 6)."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.header: dict[str, float] = {}
        self.volume = math.nan
        self.cog: tuple[float, float, float] | None = None
        self.restoring = np.zeros((RIGID_MODES, RIGID_MODES))
        self.bodies = 0
        self.periods: list[float] = []
        self.rows: dict[str, dict] = {name: {} for name in SECTIONS.values()}
        self.ignored: set[int] = set()
        self.run_periods: list[float] = []
        self.xbody: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
        self.printed: set[str] = set()


def read_wamit_out(path: str | Path, *, ulen: float | None = None, rigid_body: RigidBody | None = None) -> RaoTable:
    """RAOs (internal convention) from a WAMIT report: its motions, or solved from its forces with the
    scenario's mass (``rigid_body``); ``ulen`` overrides the report's length scale."""
    path = Path(path)
    rigid_body = rigid_body or RigidBody()
    report = _parse(path)
    g, length = report.header["g"], ulen if ulen is not None else report.header["ulen"]
    rho, depth = report.header["rho"], report.header["depth"]
    settings = Settings(g, length, 1, "the report's 'Wave period (sec)'", 0, depth, (), report.xbody, path.name)
    periods = np.array(report.periods)
    omega = 2.0 * math.pi / periods
    headings = _headings(report)
    notes = [f"{path.name}: WAMIT report, {periods.size} periods, {headings.size} headings"]
    if "rho" not in report.printed:
        notes.append(f"the report prints no water density (WAMIT 7.2 does not): WAMIT's default {RHO_SEAWATER:g} "
                     "kg/m^3 assumed (it scales the forces against the scenario's mass)")
    if report.ignored:
        notes.append(ignored_modes_note(path, report.ignored))
    missing = [p for p in report.run_periods if p > 0 and not np.isclose(periods, p, rtol=1e-4).any()]
    if missing:
        notes.append(f"{len(missing)} of the {len(report.run_periods)} periods the run's log names are not in the "
                     f"report (first {missing[0]:g} s): a cut or edited report?")
    has_motions = bool(report.rows["motions"])
    if has_motions and rigid_body.mass_kg is None and not rigid_body.given:
        values = _complex(report, "motions", headings)
        values[..., list(ROTATIONS)] /= length
        notes.append("RAOs as the report gives them (phases in whole degrees)")
    else:
        values = _solve(report, omega, headings, length, rigid_body, notes)
    order = np.argsort(omega)
    return table_from(path, omega[order], headings, values[:, order], rho=rho, settings=settings,
                      notes=tuple(notes) + (settings.describe(),), source_format="wamit-out")


def _solve(report: Report, omega: np.ndarray, headings: np.ndarray, length: float, rigid_body: RigidBody,
           notes: list[str]) -> np.ndarray:
    """Motions (headings, periods, 6) from the report's forces, WAMIT's normalisation undone, with the
    scenario's mass."""
    path = report.path
    if rigid_body.mass_kg is None:
        why = ("the report holds no motions" if not report.rows["motions"] else
               "the scenario's external stiffness or damping change the motions the report gives")
        raise FileFormatError(path, None, f"{why}: give the vessel's mass_kg, cog_m and radii_of_gyration_m in "
                                          "the scenario's [vessel] to solve the RAOs from its forces")
    if report.bodies > 1:
        raise FileFormatError(path, None, f"a report of {report.bodies} bodies: RAOs are solved from one body's "
                                          "forces only (give the report with motions)")
    kind = "diffraction" if report.rows["diffraction"] else "haskind"
    if not report.rows[kind]:
        raise FileFormatError(path, None, "no exciting forces (DIFFRACTION or HASKIND) in the report")
    rho, g = report.header["rho"], report.header["g"]
    added, damping = _radiation(report)
    added, damping, stiffness, forces = dimensional(rho, g, length, omega, added, damping, report.restoring,
                                                    _complex(report, kind, headings))
    mass = rigid_body.mass_matrix(about=(0.0, 0.0, report.xbody[2]))
    if report.cog is None or not math.isfinite(report.volume):
        raise FileFormatError(path, None, "the report gives no volume or centre of gravity: its restoring "
                                          "coefficients' gravity terms cannot be replaced by the scenario's")
    wamit_mass = rigid_body_mass(rho * report.volume, report.cog, np.eye(3))
    stiffness = stiffness + gravity_stiffness(mass, g) - gravity_stiffness(wamit_mass, g)
    motions = solve_motions(path, omega, mass, added, damping + rigid_body.damping(),
                            stiffness + rigid_body.stiffness(), forces, np.array(report.periods))
    notes.append(f"RAOs solved from the report's added mass, damping, {kind} forces and restoring coefficients "
                 f"with the scenario's mass (its gravity at its own centre of gravity in place of WAMIT's "
                 f"rho V = {rho * report.volume:.6g} kg at ({', '.join(f'{v:g}' for v in report.cog)}) m)")
    notes.append(rigid_body.describe())
    return motions


def _parse(path: Path) -> Report:
    """Read the report's header and period blocks (module docstring); any flaw names the line."""
    check_file(path, "WAMIT report")
    report = Report(path)
    lines = read_text(path).splitlines()
    if not any(BANNER.decode() in line for line in lines[:20]):
        raise FileFormatError(path, None, "not a WAMIT report: no 'WAMIT  Version' banner in its first lines")
    section: str | None = None
    period: int | None = None
    heading: float | None = None
    for number, text in enumerate(lines, 1):
        stripped = text.strip()
        if not stripped:
            continue
        if match := PERIOD.match(text):
            value = parse_float(path, number, match.group(1), "the wave period (s)")
            if not value > 0:
                raise FileFormatError(path, number, f"expected a wave period > 0 s, got {match.group(1)}")
            if value in report.periods:
                raise FileFormatError(path, number, f"the period {match.group(1)} s appears twice")
            report.periods.append(value)
            period, section, heading = len(report.periods) - 1, None, None
            continue
        if OTHER_PERIOD.match(text):
            period, section, heading = None, None, None
            continue
        if stripped in SECTIONS:
            section, heading = SECTIONS[stripped], None
            continue
        if period is not None and (TITLE.match(stripped) or stripped.startswith("*")):
            section = None  # another table (drift forces, field points): not read
            continue
        if match := HEADING.match(text):
            heading = parse_float(path, number, match.group(1), "the wave heading (deg)")
            continue
        if period is None:
            if not report.header and RUN_LINE.match(text):
                report.run_periods.append(float(text.split()[0]))
            _header_line(report, number, stripped)
            continue
        if section is not None:
            _data_line(report, number, stripped.split(), section, period, heading)
    _check(report)
    return report


def _header_line(report: Report, number: int, text: str) -> None:
    """A line before the first period block: g, ULEN, depth, rho, volumes, centre of gravity, restoring."""
    path = report.path
    for key, name in HEADER_KEYS.items():
        if key in text:
            word = text.split(key, 1)[1].split()[0]
            if name == "depth" and word.lower() == "infinite":
                report.header[name] = math.inf
            else:
                report.header[name] = parse_float(path, number, word, f"{key[:-1].lower()} (a number)")
    if text.startswith("XBODY ="):
        report.bodies += 1
        match = PLACEMENT.match(text)
        if report.bodies == 1:
            if not match:
                raise FileFormatError(path, number, "expected XBODY = x YBODY = y ZBODY = z PHIBODY = angle")
            report.xbody = tuple(parse_float(path, number, word, "a coordinate") for word in match.groups())
    elif text.startswith("Volumes (VOLX,VOLY,VOLZ):") and report.bodies == 1:
        words = text.split(":", 1)[1].split()
        report.volume = float(np.mean([parse_float(path, number, w, "a volume (m^3)") for w in words[:3]]))
    elif text.startswith("Center of Gravity") and report.bodies == 1:
        words = text.split(":", 1)[1].split()
        if len(words) != 3:
            raise FileFormatError(path, number, f"expected Xg Yg Zg, got {len(words)} values")
        report.cog = tuple(parse_float(path, number, w, "a coordinate (m)") for w in words)
    else:
        for key, cells in RESTORING.items():
            if text.startswith(key) and report.bodies == 1:
                words = text[len(key):].split()
                if len(words) != len(cells):
                    raise FileFormatError(path, number, f"expected {len(cells)} values after {key}, got {len(words)}")
                for (i, j), word in zip(cells, words):
                    value = parse_float(path, number, word, "a restoring coefficient")
                    report.restoring[i, j] = value
                    if j < 5:
                        report.restoring[j, i] = value  # C(4,6), C(5,6) have no symmetric term


def _data_line(report: Report, number: int, words: list[str], section: str, period: int,
               heading: float | None) -> None:
    """A row of the current section: ``I J A B`` (radiation) or ``I Mod Pha`` (forces, motions)."""
    path = report.path
    if not words[0].lstrip("-").isdigit():
        return  # a column heading
    if section == "radiation":
        if len(words) != 4:
            raise FileFormatError(path, number, f"expected I J A(I,J) B(I,J), got {len(words)} values")
        i, j = (parse_int(path, number, w, "a mode number") for w in words[:2])
        if min(i, j) < 1:
            raise FileFormatError(path, number, f"modes must be >= 1, got {i} {j}")
        if max(i, j) > RIGID_MODES:
            report.ignored.add(max(i, j))
            return
        a, b = (parse_float(path, number, w, "a coefficient") for w in words[2:])
        report.rows[section][(period, i - 1, j - 1)] = (a, b)
        return
    if heading is None:
        raise FileFormatError(path, number, "a row before its 'Wave Heading (deg) :' line")
    if len(words) != 3:
        raise FileFormatError(path, number, f"expected I Mod Pha, got {len(words)} values")
    i = parse_int(path, number, words[0], "a mode number")
    if i < 1:
        raise FileFormatError(path, number, f"modes must be >= 1, got {i}")
    if i > RIGID_MODES:
        report.ignored.add(i)
        return
    modulus = parse_float(path, number, words[1], "a modulus")
    phase = parse_float(path, number, words[2], "a phase (deg)")
    if modulus < 0 or abs(phase) > 360:
        raise FileFormatError(path, number, f"expected a modulus >= 0 and a phase in -360..360 deg, got "
                                            f"{words[1]} {words[2]}")
    report.rows[section][(period, heading, i - 1)] = modulus * complex(math.cos(math.radians(phase)),
                                                                       math.sin(math.radians(phase)))


def _check(report: Report) -> None:
    """The header values are there and every period has its rows."""
    report.printed = set(report.header)
    report.header.setdefault("rho", RHO_SEAWATER)
    missing = [key for key, name in HEADER_KEYS.items() if name not in report.header]
    if missing:
        raise FileFormatError(report.path, None, f"the report's header lacks {', '.join(k[:-1] for k in missing)}")
    if not report.periods:
        raise FileFormatError(report.path, None, "no 'Wave period (sec) =' blocks: the report holds no results")
    if not (report.header["g"] > 0 and report.header["ulen"] > 0 and report.header["rho"] > 0):
        raise FileFormatError(report.path, None, "gravity, length scale and water density must be > 0")


def _headings(report: Report) -> np.ndarray:
    """The headings (deg, increasing) the report's motions, else forces, give at every period."""
    kind = next((k for k in ("motions", "diffraction", "haskind") if report.rows[k]), None)
    if kind is None:
        raise FileFormatError(report.path, None, "no exciting forces or motions in the report")
    return np.array(sorted({heading for (_, heading, _) in report.rows[kind]}))


def _complex(report: Report, kind: str, headings: np.ndarray) -> np.ndarray:
    """(headings, periods, 6) complex values of ``kind``; a missing cell is refused naming it."""
    rows = report.rows[kind]
    out = np.empty((headings.size, len(report.periods), RIGID_MODES), complex)
    for h, heading in enumerate(headings):
        for p, period in enumerate(report.periods):
            for i in range(RIGID_MODES):
                if (p, heading, i) not in rows:
                    raise FileFormatError(report.path, None, f"{kind}: mode {i + 1} missing at period {period:g} s, "
                                                             f"heading {heading:g} deg")
                out[h, p, i] = rows[(p, heading, i)]
    return out


def _radiation(report: Report) -> tuple[np.ndarray, np.ndarray]:
    """Nondimensional added mass and damping (periods, 6, 6); pairs the report omits are zero."""
    added = np.zeros((len(report.periods), RIGID_MODES, RIGID_MODES))
    damping = np.zeros_like(added)
    for (p, i, j), (a, b) in report.rows["radiation"].items():
        added[p, i, j], damping[p, i, j] = a, b
    empty = [report.periods[p] for p in range(len(report.periods)) if not added[p].any()]
    if empty:
        raise FileFormatError(report.path, None, f"no added mass and damping at period {empty[0]:g} s")
    return added, damping
