"""RAOs solved from a WAMIT force set: ``.1`` (added mass, damping), ``.3`` (exciting forces), ``.hst``
(hydrostatic stiffness) and the body's mass from the ``.frc``, as WAMIT's own ``.4`` would give them.

The user names any file of the set (``[vessel] rao = "tanker.3"``, or ``.1``, ``.hst``, ``.frc``): the
others are the files of the same name beside it, as WAMIT writes them. For each frequency ``w`` and
heading, the equation of motion in WAMIT's (and marinesim's) ``exp(+i w t)`` convention,

    (-w^2 (M + A) + i w (B + B_ext) + C + C_ext) X = F,

is solved for the motions ``X`` per unit wave amplitude at the body origin (m/m, rad/m). WAMIT's
normalisation (user manual, "Output": ``A = Abar rho L^k``, ``B = Bbar rho w L^k`` with k = 3, 4, 5 for
translation-translation, mixed and rotation-rotation pairs; ``C = Cbar rho g L^(k-1)``;
``F = Fbar rho g A L^m`` with m = 2 for forces and 3 for moments; ``L = ULEN``) is undone here, once,
with ``rho`` from the ``.frc``, ``g`` and ``ULEN`` from the ``.gdf``. ``M``, ``B_ext``, ``C_ext`` come from
the ``.frc`` (:mod:`marinesim.vessel.wamit_frc`) in SI, or from the scenario
(:class:`~marinesim.vessel.body.RigidBody`): its mass replaces the ``.frc``'s (which is then not needed), its
external matrices add to the ``.frc``'s. The PER column, header lines, modes above 6 and the body of a run of
several are read as for the ``.4`` (:mod:`marinesim.vessel.wamit`); the zero- and infinite-frequency lines of the
``.1`` (PER <= 0) carry no RAO and are skipped. Body n of several takes its mass from the scenario and is solved
in its own modes with the other bodies held still (WAMIT's ``.4`` of the run has the coupled motions).

The files are checked against each other, as WAMIT writes them for one run: the ``.1`` and ``.3`` have the same
periods, the ``.3`` the headings the ``.pot`` lists, the ``.1`` the diagonal pair of each of the body's modes at
every period, and the ``.hst`` every pair of the body's modes (zeros included); a file that does not fit is
refused, naming it and what it lacks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from marinesim.constants import RHO_SEAWATER
from marinesim.errors import FileFormatError
from marinesim.tokens import parse_float, parse_int, read_text
from marinesim.vessel.body import RigidBody, gravity_stiffness, rigid_body_mass
from marinesim.vessel.rao import DOFS, RaoTable
from marinesim.vessel.wamit import Settings, frc_form, frc_rho, sniff_forces, table_from
from marinesim.vessel.wamit_rows import RIGID_MODES, ignored_modes_note, read_rows
from marinesim.vessel.wamit_frc import ForceControl, read_frc

SET = (".1", ".3", ".hst", ".frc")
"""The files of a WAMIT force set, in the order they are read."""
NO_FRC = ForceControl(form=0, rho=None, vcg=0.0, cog=None, radii=None, mass=None, damping=np.zeros((6, 6)),
                      stiffness=np.zeros((6, 6)))
"""What a force set without a ``.frc`` has (its mass then comes from the scenario)."""
ONLY_RHO = -1
"""The ``form`` of a ``.frc`` read for its rho only (body n of a run of several: its mass, centre of gravity and
external matrices are the scenario's)."""
ROTATION = np.arange(RIGID_MODES) >= 3
PAIR_POWER = ROTATION[:, None].astype(int) + ROTATION[None, :].astype(int)
"""0, 1, 2: how many of the mode pair (i, j) are rotations; WAMIT's length exponents build on it."""

sniff = sniff_forces


@dataclass(frozen=True)
class ForceSet:
    """A WAMIT force set in SI, per unit wave amplitude, about the body origin: ``omega`` (rad/s, file order),
    ``headings_deg`` (wave travel direction from body x), ``mass`` (6, 6), ``added`` and ``damping`` (the
    radiation matrices, frequencies x 6 x 6), ``stiffness`` (hydrostatic, 6 x 6), ``forces`` (exciting,
    headings x frequencies x 6, ``exp(+i w t)``), ``frc`` (with the external matrices), ``rho``,
    ``settings`` and ``notes``."""

    omega: np.ndarray
    periods: np.ndarray
    headings_deg: np.ndarray
    mass: np.ndarray
    added: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    forces: np.ndarray
    frc: ForceControl
    rho: float
    settings: Settings
    notes: tuple[str, ...]


def read_wamit_forces(path: str | Path, *, ulen: float | None = None, rigid_body: RigidBody | None = None,
                      body: str | None = None) -> RaoTable:
    """RAOs (internal convention) solved from the WAMIT ``.1``, ``.3``, ``.hst`` and ``.frc`` named like ``path``;
    ``rigid_body`` (the scenario's) gives the mass instead of the ``.frc`` and adds its external matrices; ``body``
    (number or ``.gdf`` name) picks one body of several."""
    path = Path(path)
    rigid_body = rigid_body or RigidBody()
    fs = read_force_set(path, ulen=ulen, rigid_body=rigid_body, body=body)
    notes = list(fs.notes)
    stiffness = fs.stiffness + fs.frc.stiffness + rigid_body.stiffness()
    if rigid_body.mass_kg is not None:
        wamit_gravity, note = _run_gravity(path, fs)
        if wamit_gravity is not None:
            stiffness = stiffness + gravity_stiffness(fs.mass, fs.settings.g) - wamit_gravity
        notes.append(note)
    motions = solve_motions(path.with_suffix(".frc"), fs.omega, fs.mass, fs.added,
                            fs.damping + fs.frc.damping + rigid_body.damping(), stiffness, fs.forces, fs.periods)
    order = np.argsort(fs.omega)
    source = (f"the mass of {path.with_suffix('.frc').name} (IALTFRC {fs.frc.form}, {fs.mass[0, 0]:.6g} kg)"
              if rigid_body.mass_kg is None else "the scenario's mass")
    notes.append(f"RAOs solved from {path.with_suffix('.1').name}, {path.with_suffix('.3').name}, "
                 f"{path.with_suffix('.hst').name} with {source}" + _external(fs.frc))
    if rigid_body.given:
        notes.append(rigid_body.describe())
    if fs.settings.bodies > 1:
        notes.append(f"body {fs.settings.body} solved alone, the other bodies held still (their masses are not "
                     "read): the run's .4 has the motions of the bodies coupled")
    if path.with_suffix(".4").is_file():
        notes.append(f"{path.with_suffix('.4').name} beside holds WAMIT's own RAOs of this set")
    return table_from(path, fs.omega[order], fs.headings_deg, motions[:, order], rho=fs.rho, settings=fs.settings,
                      notes=tuple(notes) + (fs.settings.describe(),), source_format="wamit-forces")


def read_force_set(path: str | Path, *, ulen: float | None = None, rigid_body: RigidBody | None = None,
                   body: str | None = None) -> ForceSet:
    """The ``.1``, ``.3``, ``.hst`` and ``.frc`` named like ``path``, checked against each other and WAMIT's
    normalisation undone (module docstring); ``body`` picks one body of several. With the scenario's mass
    (``rigid_body``) the ``.frc`` is optional: it then gives only rho and the external matrices."""
    path = Path(path)
    given = rigid_body is not None and rigid_body.mass_kg is not None
    files = {suffix: path.with_suffix(suffix) for suffix in SET}
    if given and not files[".frc"].is_file():
        del files[".frc"]
    missing = [f.name for f in files.values() if not f.is_file()]
    if missing:
        raise FileFormatError(path, None, "RAOs from WAMIT forces need " + ", ".join(f.name for f in files.values())
                              + " side by side; missing: " + ", ".join(missing))
    settings = Settings.beside(files[".3"], ulen=ulen, body=body)
    if settings.bodies > 1 and not given:
        raise FileFormatError(path, None, f"body {settings.body} of a run of several: its mass is not read from "
                                          f"{files['.frc'].name} (a run's .frc holds one body); give mass_kg, cog_m "
                                          "and radii_of_gyration_m in the scenario's [vessel], or read the run's .4")
    notes = list(settings.notes)
    if settings.bodies > 1 and ".frc" in files:  # not this body's mass, centre of gravity or external matrices
        try:
            rho = frc_rho(files[".frc"])
        except FileFormatError:  # a layout of several bodies: not read here
            rho = None
        frc = replace(NO_FRC, form=ONLY_RHO, rho=rho)
        notes.append(f"{files['.frc'].name} read for rho only: body {settings.body}'s mass, centre of gravity and "
                     "external matrices are the scenario's")
    else:
        frc = read_frc(files[".frc"], frc_form(path.with_suffix(".cfg"))) if ".frc" in files else NO_FRC
    rho = frc.rho if frc.rho is not None else RHO_SEAWATER
    if ".frc" not in files:
        notes.append(f"no {path.with_suffix('.frc').name}: rho {RHO_SEAWATER:g} kg/m^3 assumed for WAMIT's "
                     "normalisation (it scales the hydrodynamic terms against the scenario's mass)")
    offset = settings.mode_offset
    per_1, added, damping, coefficient_notes = read_coefficients(files[".1"], settings.header_lines, offset)
    stiffness, stiffness_notes = read_hydrostatics(files[".hst"], settings.header_lines, offset)
    periods, headings, forces, force_notes = read_rows(files[".3"], header_lines=settings.header_lines,
                                                       what="force mode", offset=offset)
    settings.check_headings(files[".3"], headings)
    notes += coefficient_notes + stiffness_notes + force_notes
    at = _match_periods(files[".3"], periods, files[".1"], per_1)
    omega = settings.omega(periods, files[".3"])
    mass, mass_notes = ((rigid_body.mass_matrix(about=(0.0, 0.0, settings.xbody[2])), []) if given
                        else mass_matrix(files[".frc"], frc, rho))
    added, damping, stiffness, forces = dimensional(rho, settings.g, settings.ulen, omega, added[at], damping[at],
                                                    stiffness, forces)
    return ForceSet(omega=omega, periods=periods, headings_deg=headings, mass=mass, added=added, damping=damping,
                    stiffness=stiffness, forces=forces, frc=frc, rho=rho, settings=settings,
                    notes=tuple(notes + mass_notes))


def dimensional(rho: float, g: float, ulen: float, omega: np.ndarray, added: np.ndarray, damping: np.ndarray,
                stiffness: np.ndarray, forces: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """WAMIT's normalisation undone (module docstring): added mass and damping (frequencies, 6, 6), stiffness
    (6, 6) and exciting forces (..., frequencies, 6) in SI, at the frequencies ``omega`` (rad/s)."""
    length = ulen ** (3 + PAIR_POWER)
    return (added * rho * length, damping * rho * omega[:, None, None] * length,
            stiffness * rho * g * ulen ** (2 + PAIR_POWER), forces * rho * g * ulen ** np.where(ROTATION, 3, 2))


def read_coefficients(path: Path, header_lines: int = 0, offset: int = 0) -> tuple[
        np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """The ``.1`` file: positive PER values (file order), nondimensional added mass and damping of the modes
    ``offset + 1 .. offset + 6``, both (periods, 6, 6), and notes. Lines ``PER I J Abar Bbar``; pairs not listed
    are zero (WAMIT omits them), but each mode's diagonal pair is there at every period; PER <= 0 (the zero and
    infinite frequency limits, ``PER I J Abar``) are skipped."""
    periods: list[float] = []
    at: dict[float, int] = {}
    values: list[np.ndarray] = []
    seen: set[tuple[int, int, int]] = set()
    ignored: set[int] = set()
    for number, parts in _data_lines(path, header_lines):
        per = parse_float(path, number, parts[0], "PER (period, frequency or wavenumber)")
        if per <= 0.0:
            if len(parts) not in (4, 5):
                raise FileFormatError(path, number, f"expected 4 columns PER I J Abar (zero or infinite frequency), "
                                                    f"got {len(parts)}")
            continue
        if len(parts) != 5:
            raise FileFormatError(path, number, f"expected 5 columns PER I J Abar Bbar, got {len(parts)}")
        i, j = (parse_int(path, number, parts[k], name) for k, name in ((1, "I (mode)"), (2, "J (mode)")))
        a, b = (parse_float(path, number, parts[k], name) for k, name in ((3, "Abar (added mass)"),
                                                                         (4, "Bbar (damping)")))
        if min(i, j) < 1:
            raise FileFormatError(path, number, f"modes I, J must be >= 1, got {i} {j}")
        if not (offset < i <= offset + RIGID_MODES and offset < j <= offset + RIGID_MODES):
            ignored.update(m for m in (i, j) if not offset < m <= offset + RIGID_MODES)
            continue
        i, j = i - offset, j - offset
        if per not in at:
            if periods and (len(periods) >= 2 and (per - periods[-1]) * (periods[-1] - periods[-2]) < 0):
                raise FileFormatError(path, number, f"PER {parts[0]} breaks the order of the periods (must be "
                                                    "monotonic)")
            at[per] = len(periods)
            periods.append(per)
            values.append(np.zeros((2, RIGID_MODES, RIGID_MODES)))
        elif at[per] != len(periods) - 1:
            raise FileFormatError(path, number, f"PER {parts[0]} appears again after other periods")
        if (at[per], i, j) in seen:
            raise FileFormatError(path, number, f"I J = {i + offset} {j + offset} given twice for PER {parts[0]}")
        seen.add((at[per], i, j))
        values[at[per]][:, i - 1, j - 1] = (a, b)
    if not periods:
        raise FileFormatError(path, None, "no lines PER I J Abar Bbar with PER > 0 (only zero or infinite "
                                          "frequencies, or an empty file)")
    for k, per in enumerate(periods):
        missing = [m + offset for m in range(1, RIGID_MODES + 1) if (k, m, m) not in seen]
        if missing:
            raise FileFormatError(path, None, f"PER {per:g} has no added mass and damping of mode(s) "
                                              f"{', '.join(map(str, missing))} (no line I = J): a cut file, or a run "
                                              "with those modes fixed (IMODE = 0)? Free bodies are solved here: read "
                                              "that run's .4")
    table = np.array(values)
    notes = [ignored_modes_note(path, ignored, offset)] if ignored else []
    return np.array(periods), table[:, 0], table[:, 1], notes


def read_hydrostatics(path: Path, header_lines: int = 0, offset: int = 0) -> tuple[np.ndarray, list[str]]:
    """The ``.hst`` file: nondimensional hydrostatic stiffness (6, 6) of the modes ``offset + 1 .. offset + 6`` from
    lines ``I J Cbar``, and notes. WAMIT writes every pair of modes, zeros included: a pair missing is refused."""
    stiffness = np.zeros((RIGID_MODES, RIGID_MODES))
    seen: set[tuple[int, int]] = set()
    ignored: set[int] = set()
    for number, parts in _data_lines(path, header_lines):
        if len(parts) != 3:
            raise FileFormatError(path, number, f"expected 3 columns I J Cbar, got {len(parts)}")
        i, j = (parse_int(path, number, parts[k], name) for k, name in ((0, "I (mode)"), (1, "J (mode)")))
        value = parse_float(path, number, parts[2], "Cbar (hydrostatic stiffness)")
        if min(i, j) < 1:
            raise FileFormatError(path, number, f"modes I, J must be >= 1, got {i} {j}")
        if not (offset < i <= offset + RIGID_MODES and offset < j <= offset + RIGID_MODES):
            ignored.update(m for m in (i, j) if not offset < m <= offset + RIGID_MODES)
            continue
        if (i, j) in seen:
            raise FileFormatError(path, number, f"I J = {i} {j} given twice")
        seen.add((i, j))
        stiffness[i - offset - 1, j - offset - 1] = value
    if not seen:
        raise FileFormatError(path, None, "no lines I J Cbar")
    modes = range(offset + 1, offset + RIGID_MODES + 1)
    missing = [(i, j) for i in modes for j in modes if (i, j) not in seen]
    if missing:
        rows = sorted({i for i, _ in missing if all((i, j) in missing for j in modes)})
        whole = f" (no rows of mode(s) {', '.join(map(str, rows))})" if rows else ""
        raise FileFormatError(path, None, f"{len(missing)} of the {RIGID_MODES ** 2} pairs I J of modes "
                                          f"{offset + 1}-{offset + RIGID_MODES} missing, first {missing[0][0]} "
                                          f"{missing[0][1]}{whole}: WAMIT writes every pair, zeros included (a cut "
                                          "file?)")
    return stiffness, [ignored_modes_note(path, ignored, offset)] if ignored else []


def mass_matrix(frc_path: Path, frc: ForceControl, rho: float) -> tuple[np.ndarray, list[str]]:
    """The body's 6 x 6 mass matrix (SI, about the body origin) and notes (:func:`run_mass`); refused unless its
    mass and inertia are positive (the RAOs are solved with it)."""
    mass, notes = run_mass(frc_path, frc, rho)
    diagonal = np.diag(mass)
    if not np.all(np.isfinite(mass)) or np.any(diagonal <= 0.0):
        raise FileFormatError(frc_path, None, "the mass matrix must have positive mass and inertia on its "
                                              f"diagonal, got {', '.join(f'{v:.4g}' for v in diagonal)}")
    return mass, notes


def run_mass(frc_path: Path, frc: ForceControl, rho: float) -> tuple[np.ndarray, list[str]]:
    """The 6 x 6 mass matrix of the ``.frc`` (SI, about the body origin; zero radii of gyration give zero inertia)
    and notes. Form 2 gives it; form 1 makes it from the displaced mass ``rho V`` and centre of buoyancy of the
    ``.gdf`` beside, ``VCG`` and the radii of gyration (:mod:`marinesim.vessel.wamit_frc`)."""
    if frc.form == 2:
        if frc.mass is None:
            raise FileFormatError(frc_path, None, "IMASS = 0: the .frc gives no mass matrix, and the RAOs need "
                                                  "the body's mass; give it (IMASS = 1)")
        mass = frc.mass
        notes: list[str] = []
    else:
        from marinesim.hull import hydrostatics, load_hull

        gdf = frc_path.with_suffix(".gdf")
        if not gdf.is_file():
            raise FileFormatError(frc_path, None, f"IALTFRC = 1 takes the mass as rho times the displaced volume: "
                                                  f"{gdf.name} beside it is needed to compute that volume")
        hydro = hydrostatics(load_hull(gdf), rho)
        xb, yb, _ = hydro.centre_of_buoyancy_m
        mass = rigid_body_mass(rho * hydro.volume_m3, (xb, yb, frc.vcg),
                               rho * hydro.volume_m3 * frc.radii * np.abs(frc.radii))
        notes = [f"{frc_path.name} (IALTFRC 1): mass rho V = {mass[0, 0]:.6g} kg from the displaced volume of "
                 f"{gdf.name} ({hydro.volume_m3:.6g} m^3), centre of gravity ({xb:.4g}, {yb:.4g}, {frc.vcg:.4g}) m, "
                 f"rho {rho:g} kg/m^3 assumed (the RAOs do not depend on it); no external damping or stiffness "
                 "in this form"]
    return mass, notes


def solve_motions(frc_path: Path, omega: np.ndarray, mass: np.ndarray, added: np.ndarray, damping: np.ndarray,
                  stiffness: np.ndarray, forces: np.ndarray, periods: np.ndarray) -> np.ndarray:
    """Motions (headings, frequencies, 6) from the equation of motion at each ``omega`` (rad/s);
    ``added`` and ``damping`` (frequencies, 6, 6), ``stiffness`` (6, 6), ``forces`` (headings, frequencies, 6)
    per unit wave amplitude, all SI."""
    w = omega[:, None, None]
    impedance = -w**2 * (mass + added) + 1j * w * damping + stiffness
    for k in range(omega.size):
        if np.linalg.cond(impedance[k]) > 1e14:
            raise FileFormatError(frc_path, None, f"the equation of motion is singular at PER {periods[k]:g} "
                                                  "(a mode with neither mass, damping nor stiffness?)")
    return np.linalg.solve(impedance[None], forces[..., None])[..., 0]


def _data_lines(path: Path, header_lines: int) -> list[tuple[int, list[str]]]:
    """(line number, words) of the non-empty lines after ``header_lines`` and after a first line of text."""
    rows = [(number, text.split()) for number, text in enumerate(read_text(path).splitlines(), 1)
            if number > header_lines and text.split()]
    if rows and not _numeric(rows[0][1][0]):
        rows = rows[1:]
    return rows


def _numeric(text: str) -> bool:
    try:
        float(text.replace("D", "E").replace("d", "e"))
    except ValueError:
        return False
    return math.isfinite(float(text.replace("D", "E").replace("d", "e")))


def _run_gravity(path: Path, fs: ForceSet) -> tuple[np.ndarray | None, str]:
    """The gravity terms (6 x 6, SI) WAMIT put in the ``.hst``: a mass ``rho V`` at the ``.frc``'s centre of
    gravity (the ``.frc``'s own mass where it gives one, which a free body's equals), or None with a note where
    no ``.frc`` says where that centre was; and the note saying what replaced them."""
    frc_path = path.with_suffix(".frc")
    if not frc_path.is_file() or fs.frc.form == ONLY_RHO:
        return None, (f"the gravity terms of {path.with_suffix('.hst').name} are kept as WAMIT computed them: without "
                      f"{frc_path.name} the centre of gravity of its run is unknown, so the scenario's cog_m sets the "
                      "mass matrix only")
    if fs.frc.mass is not None or fs.frc.form == 1:
        mass, _ = run_mass(frc_path, fs.frc, fs.rho)  # its weight only: zero radii of gyration are no matter
    elif not any(fs.frc.cog):
        mass = np.zeros((6, 6))
    else:
        return None, (f"the gravity terms of {path.with_suffix('.hst').name} are kept as WAMIT computed them: "
                      f"{frc_path.name} gives its centre of gravity but no mass (IMASS = 0)")
    return gravity_stiffness(mass, fs.settings.g), (
        f"the gravity terms of {path.with_suffix('.hst').name} (WAMIT's, for the centre of gravity in "
        f"{frc_path.name}) replaced by the scenario's mass at its cog_m")


def _match_periods(path_3: Path, periods: np.ndarray, path_1: Path, per_1: np.ndarray) -> np.ndarray:
    """Index into the ``.1`` periods of each ``.3`` period; a period either file lacks is refused."""
    at = np.empty(periods.size, dtype=int)
    for k, per in enumerate(periods):
        close = np.flatnonzero(np.isclose(per_1, per, rtol=1e-6, atol=0.0))
        if close.size != 1:
            raise FileFormatError(path_3, None, f"PER {per:g} has no added mass and damping in {path_1.name} "
                                                "(the files are of different runs?)")
        at[k] = close[0]
    lacking = [per for per in per_1 if not np.isclose(periods, per, rtol=1e-6, atol=0.0).any()]
    if lacking:
        raise FileFormatError(path_3, None, f"{len(lacking)} of the {per_1.size} periods of {path_1.name} missing "
                              f"(PER {', '.join(f'{p:g}' for p in lacking[:4])}{', ...' if len(lacking) > 4 else ''}"
                              f"): it has {periods.size}; a cut file, or a file of another run?")
    return at


def _external(frc: ForceControl) -> str:
    """The external matrices of ``frc`` in words (diagonal terms), for the notes."""
    words = []
    for name, matrix in (("damping", frc.damping), ("stiffness", frc.stiffness)):
        terms = [f"{DOFS[j]} {matrix[j, j]:.4g}" for j in range(RIGID_MODES) if matrix[j, j]]
        if np.any(matrix):
            words.append(f"external {name} " + (", ".join(terms) if terms else "(off-diagonal terms)") + " (SI)")
    return "; " + "; ".join(words) if words else "; no external damping or stiffness"
