"""NEMOH (v2 and v3) results -> :class:`RaoTable`: ``Motion/RAO.dat`` when NEMOH wrote it, else RAOs solved
from its coefficients.

The user names the NEMOH project folder (the one holding ``Nemoh.cal``), ``Nemoh.cal`` itself or any file
inside the project. Folder names are matched without regard to case (``Results``/``results``,
``Mesh``/``mesh``). Layout relied on:

* ``Nemoh.cal``: line 2 ``RHO``, line 3 ``G``, line 4 ``DEPTH`` (0 = infinite), line 5 ``XEFF YEFF`` (the
  point the incident wave's phase refers to), line 7 the number of bodies (one is read), then the body's
  mesh file, its point and panel counts, the number of DOFs (6) and one line per DOF ``TYPE nx ny nz x y z``
  (type 1 translation, 2 rotation about the point ``x y z``).
* ``Motion/RAO.dat`` (v3 postprocessor): a ``VARIABLES=`` line whose first name says the frequency kind
  (``w (rad/s)``, ``f (Hz)``, ``T (s)``), then for each heading a ``ZONE`` line with ``beta= <deg>`` and
  rows ``freq |X| |Y| |Z| |phi| |theta| |psi| ang(x) ... ang(psi)``: translations in m/m, rotations in
  **deg/m**, phases in degrees.
* ``results/ExcitationForce.tec``: ``VARIABLES`` line, one quoted line per force, then per heading a
  ``Zone t="Excitation force - beta = <deg> deg"`` line and rows ``freq |F1| ang(F1) ... |F6| ang(F6)``,
  phases in **radians** (NEMOH's source says so), per unit wave amplitude, N and N m.
* ``results/CA.dat`` (damping) and ``results/CM.dat`` (added mass), v3: ``Nb de frequency : N``, then per
  frequency a line ``w`` (rad/s) and six lines of six numbers, row = motion (radiation) DOF, column = force.
  Without them (v2), ``results/RadiationCoefficients.tec``: per motion DOF a ``Zone`` of rows
  ``freq A_1 B_1 ... A_6 B_6``.
* Six lines of six numbers, SI, about the rotation centre: hydrostatic stiffness ``Mechanics/Kh.dat``
  (v3) else ``mesh/KH.dat`` (it includes the gravity term); mass ``Mechanics/Inertia.dat`` (v3) else
  ``mesh/Inertia.dat``; optional ``Mechanics/Km.dat`` (added stiffness) and ``Mechanics/Badd.dat`` (added
  damping). Without a 6 x 6 mass, ``mesh/Inertia_hull.dat`` (3 x 3 about G) with the ``Mass`` (or
  ``Displacement`` times rho) and ``XG YG ZG`` of ``mesh/Hydrostatics.dat``; without either the RAOs are
  refused.

Source convention, converted here once (:func:`nemoh_to_internal`): NEMOH's time factor is
``exp(-i w t)`` (its equation of motion is ``(-w^2 (M + A) - i w B + C) X = F``, in its postprocessor), so
marinesim's RAO (``exp(+i w t)``, phase lead) is the complex conjugate. Headings ``beta`` are the direction
the waves travel towards, from the x axis (NEMOH's incident potential varies as
``exp(i k (x cos beta + y sin beta))``): marinesim's ``beta_rel``. The axes are x forward, y to port, z up;
rotations right-handed (pitch positive bow down), as marinesim's. The RAOs are solved here as
``(-w^2 (M + A^T) + i w (B^T + B_add) + C + K_m) H = conj(F)`` (``A^T``: force rows, motion columns) and
referred to the wave at the rotation centre ``r`` (NEMOH refers it to ``(XEFF, YEFF)``):
``H_r = H exp(i k . (r - eff))``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError, HeadingError, ParameterError
from marinesim.formats import check_file
from marinesim.tokens import Tokens, parse_float, read_text
from marinesim.vessel.body import RigidBody, gravity_stiffness, rigid_body_mass
from marinesim.vessel.rao import RaoTable, SolverRaos, make_table, refer_phases

ROTATION = np.array([False, False, False, True, True, True])
MAX_FREQUENCIES = 100_000
MAX_HEADINGS = 3_600
_BETA = re.compile(r"beta\s*=\s*([-+0-9.eEdD]+)", re.IGNORECASE)
FREQUENCY_KINDS = (("rad/s", "w"), ("hz", "f"), ("(s)", "T"))


@dataclass(frozen=True)
class Settings:
    """What ``Nemoh.cal`` says: ``rho``, ``g``, ``depth`` (inf = deep), ``wave_point`` (XEFF, YEFF) and the
    ``rotation_centre`` of the body's rotational DOFs."""

    rho: float
    g: float
    depth: float
    wave_point: tuple[float, float]
    rotation_centre: tuple[float, float, float]


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like a ``Nemoh.cal``."""
    text = head.decode("utf-8", errors="replace")
    return "--- Environment" in text and "Number of bodies" in text


def read_nemoh(path: str | Path, *, rigid_body: RigidBody | None = None) -> RaoTable:
    """Read the RAOs of the NEMOH project that ``path`` (folder, ``Nemoh.cal`` or a file inside) belongs to;
    ``rigid_body`` (the scenario's mass, external stiffness and damping) solves them from its coefficients."""
    path = Path(path)
    raos = read_nemoh_raos(path, rigid_body)
    extra = {"depth": raos.depth} if math.isfinite(raos.depth) else {}
    try:
        return make_table(raos.omega, np.radians(raos.headings_deg), [0.0], raos.values[None],
                          reference_point=raos.reference_point, rho=raos.rho, g=raos.g, source=str(path),
                          source_format="nemoh", notes=raos.notes, **extra)
    except HeadingError as error:
        raise FileFormatError(path, None, f"{error} (the NEMOH results cover heading(s) "
                              + ", ".join(f"{h:g}" for h in raos.headings_deg) + " deg only)") from None
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def nemoh_to_internal(values: np.ndarray) -> np.ndarray:
    """NEMOH's complex amplitudes (time factor ``exp(-i w t)``) -> marinesim's (``exp(+i w t)``): the conjugate."""
    return np.conj(values)


def read_nemoh_raos(path: str | Path, rigid_body: RigidBody | None = None) -> SolverRaos:
    """The RAOs of the project of ``path``: ``Motion/RAO.dat`` if present and the scenario gives no rigid body,
    else solved from the coefficients."""
    root = project_root(Path(path))
    settings = read_settings(root / "Nemoh.cal")
    rigid_body = rigid_body or RigidBody()
    rao_file = _child(root, "Motion", "RAO.dat")
    if rao_file is not None and not rigid_body.given:
        omega, headings, values = read_rao_dat(rao_file)
        notes = (f"RAOs read from {rao_file.relative_to(root)} (NEMOH exp(-i w t) conjugated, rotations deg/m -> "
                 "rad/m)",)
        source = str(rao_file)
    else:
        omega, headings, values, notes = solve_from_coefficients(root, settings, rigid_body)
        source = "equation of motion"
    values = refer_to_centre(values, omega, headings, settings)
    order = np.argsort(omega)
    notes = notes + (f"reference point: rotation centre {settings.rotation_centre} m; wave phase referred to it "
                     f"from NEMOH's (XEFF, YEFF) = {settings.wave_point}",)
    return SolverRaos(omega[order], headings, values[:, order], settings.rotation_centre, settings.rho, settings.g,
                      settings.depth, source, notes)


def project_root(path: Path) -> Path:
    """The folder holding ``Nemoh.cal`` for ``path`` (the folder, ``Nemoh.cal``, or a file up to two folders
    below it)."""
    if path.is_dir():
        candidates = [path]
    else:
        check_file(path)
        candidates = [path.parent, path.parent.parent, path.parent.parent.parent]
    for folder in candidates:
        if (folder / "Nemoh.cal").is_file():
            return folder
    raise FileFormatError(path, None, "not part of a NEMOH project: no Nemoh.cal in "
                          + " or ".join(str(c) for c in candidates))


def read_settings(cal: Path) -> Settings:
    """``rho``, ``g``, depth, wave point and the rotation centre from ``Nemoh.cal`` (one body, six DOFs)."""
    lines = read_text(cal).splitlines()
    if len(lines) < 20:
        raise FileFormatError(cal, len(lines) or None, "file ends early: expected the environment and one body")

    def number(line: int, what: str, index: int = 0) -> float:
        parts = lines[line - 1].split()
        if len(parts) <= index:
            raise FileFormatError(cal, line, f"expected {what}")
        return parse_float(cal, line, parts[index], what)

    rho, g, depth = number(2, "RHO (kg/m^3)"), number(3, "G (m/s^2)"), number(4, "DEPTH (m; 0 = infinite)")
    if rho <= 0.0 or g <= 0.0 or depth < 0.0:
        raise FileFormatError(cal, 2, f"RHO and G must be > 0 and DEPTH >= 0, got {rho:g} {g:g} {depth:g}")
    wave_point = (number(5, "XEFF (m)"), number(5, "YEFF (m)", 1))
    bodies = number(7, "the number of bodies")
    if bodies != 1:
        raise FileFormatError(cal, 7, f"{bodies:g} bodies: marinesim reads the RAOs of one free-floating body")
    ndof = number(11, "the number of degrees of freedom")
    if ndof != 6:
        raise FileFormatError(cal, 11, f"expected 6 degrees of freedom (surge .. yaw), got {ndof:g}")
    centre = (0.0, 0.0, 0.0)
    for k in range(6):
        line = 12 + k
        kind = number(line, "DOF type (1 translation, 2 rotation)")
        axis = [number(line, "DOF axis", i) for i in (1, 2, 3)]
        if kind != (1 if k < 3 else 2) or axis != list(np.eye(3)[k % 3]):
            raise FileFormatError(cal, line, f"DOF {k + 1} must be the {'translation' if k < 3 else 'rotation'} "
                                             f"along axis {'xyz'[k % 3]} (surge, sway, heave, roll, pitch, yaw)")
        if k == 3:
            centre = tuple(number(line, "rotation centre (m)", i) for i in (4, 5, 6))
        elif k > 3 and tuple(number(line, "rotation centre (m)", i) for i in (4, 5, 6)) != centre:
            raise FileFormatError(cal, line, "roll, pitch and yaw must turn about the same point")
    return Settings(rho, g, math.inf if depth == 0.0 else depth, wave_point, centre)


def solve_from_coefficients(root: Path, settings: Settings, rigid_body: RigidBody | None = None) -> tuple[
        np.ndarray, np.ndarray, np.ndarray, tuple[str, ...]]:
    """(omega, headings_deg, RAOs (headings, frequencies, 6) in marinesim's convention, notes) solved from the
    excitation forces, radiation coefficients, stiffness and mass of the project (module docstring); the
    scenario's ``rigid_body`` replaces the mass (and the weight's restoring in the stiffness) and adds its
    external matrices."""
    rigid_body = rigid_body or RigidBody()
    results = _folder(root, "results")
    if results is None:
        raise FileFormatError(root, None, "no Motion/RAO.dat and no results folder: run NEMOH's solver first")
    force_file = _child(results, None, "ExcitationForce.tec")
    if force_file is None:
        raise FileFormatError(results, None, "ExcitationForce.tec missing: the RAOs need NEMOH's excitation forces")
    omega, headings, forces = read_excitation(force_file)
    notes: list[str] = []
    ca, cm = _child(results, None, "CA.dat"), _child(results, None, "CM.dat")
    if ca is not None and cm is not None:
        w_b, damping = read_coefficient_dat(ca)
        w_a, added = read_coefficient_dat(cm)
        coefficients = f"{ca.name}, {cm.name}"
        _match(ca, w_b, omega, 5e-5)
        _match(cm, w_a, omega, 5e-5)
    else:
        tec = _child(results, None, "RadiationCoefficients.tec")
        if tec is None:
            raise FileFormatError(results, None, "no CA.dat and CM.dat (v3) or RadiationCoefficients.tec (v2): "
                                                 "the RAOs need NEMOH's added mass and damping")
        w_r, added, damping = read_radiation_tec(tec)
        _match(tec, w_r, omega, 1e-6)
        coefficients = tec.name
    stiffness, stiffness_file = _matrix_file(root, [("Mechanics", "Kh.dat"), ("mesh", "KH.dat")])
    if stiffness is None:
        raise FileFormatError(root, None, "no hydrostatic stiffness (Mechanics/Kh.dat or mesh/KH.dat)")
    extra_k, k_file = _matrix_file(root, [("Mechanics", "Km.dat")])
    extra_b, b_file = _matrix_file(root, [("Mechanics", "Badd.dat")])
    stiffness = stiffness + (extra_k if extra_k is not None else 0.0) + rigid_body.stiffness()
    if rigid_body.mass_kg is None:
        mass, mass_note = mass_matrix(root, settings)
    else:
        mass, mass_note = rigid_body.mass_matrix(about=settings.rotation_centre), "the scenario's mass"
        try:  # the stiffness holds the weight of NEMOH's own mass at its centre of gravity: the scenario's replaces it
            own, _ = mass_matrix(root, settings)
            stiffness = stiffness + gravity_stiffness(mass, settings.g) - gravity_stiffness(own, settings.g)
        except FileFormatError:
            notes.append("the stiffness keeps NEMOH's weight terms: the project gives no mass to say where its "
                         "centre of gravity was")
        notes.append(rigid_body.describe())
    extra_b = (extra_b if extra_b is not None else 0.0) + rigid_body.damping()
    w = omega[:, None, None]
    impedance = (-w**2 * (mass + np.swapaxes(added, 1, 2))
                 + 1j * w * (np.swapaxes(damping, 1, 2) + extra_b) + stiffness)
    for k in range(omega.size):
        if np.linalg.cond(impedance[k]) > 1e14:
            raise FileFormatError(root, None, f"the equation of motion is singular at {omega[k]:g} rad/s "
                                              "(a mode with neither mass, damping nor stiffness?)")
    values = np.linalg.solve(impedance[None], nemoh_to_internal(forces)[..., None])[..., 0]
    used = [f.relative_to(root).as_posix() for f in (stiffness_file, k_file, b_file) if f is not None]
    notes.append(f"RAOs solved from {force_file.relative_to(root).as_posix()}, {coefficients}, "
                 f"{', '.join(used)} and {mass_note} (NEMOH exp(-i w t) conjugated)")
    return omega, headings, values, tuple(notes)


def mass_matrix(root: Path, settings: Settings) -> tuple[np.ndarray, str]:
    """The body's 6 x 6 mass matrix about the rotation centre (SI) and a phrase saying where it came from."""
    mass, source = _matrix_file(root, [("Mechanics", "Inertia.dat"), ("mesh", "Inertia.dat")])
    if mass is not None:
        phrase = f"the mass matrix of {source.relative_to(root).as_posix()}"
    else:
        hull = _child(root, "mesh", "Inertia_hull.dat")
        hydro = _child(root, "mesh", "Hydrostatics.dat")
        if hull is None or hydro is None:
            raise FileFormatError(root, None, "no mass for the RAOs: NEMOH's Mechanics/Inertia.dat (6 x 6), or "
                                              "mesh/Inertia_hull.dat with mesh/Hydrostatics.dat, is needed beside "
                                              "its results")
        inertia = _read_matrix(hull, 3)
        body_mass, cog = _hydrostatics(hydro, settings.rho)
        d = np.array(cog) - np.array(settings.rotation_centre)
        mass = rigid_body_mass(body_mass, tuple(d), inertia + body_mass * (d @ d * np.eye(3) - np.outer(d, d)))
        phrase = (f"a mass of {body_mass:.6g} kg at G = ({cog[0]:g}, {cog[1]:g}, {cog[2]:g}) m "
                  f"({hydro.relative_to(root).as_posix()}) with the inertia of {hull.relative_to(root).as_posix()} "
                  "about G")
        source = hull
    diagonal = np.diag(mass)
    if np.any(diagonal <= 0.0):
        raise FileFormatError(source, None, "the mass matrix must have positive mass and inertia on its diagonal, "
                                            f"got {', '.join(f'{v:.4g}' for v in diagonal)}")
    return mass, phrase


def refer_to_centre(values: np.ndarray, omega: np.ndarray, headings_deg: np.ndarray,
                    settings: Settings) -> np.ndarray:
    """RAOs relative to the wave at (XEFF, YEFF) -> relative to the wave at the rotation centre."""
    centre, wave = settings.rotation_centre, settings.wave_point
    offset = (centre[0] - wave[0], centre[1] - wave[1])
    return refer_phases(values, omega, headings_deg, offset, settings.depth, settings.g)


def read_excitation(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``ExcitationForce.tec`` -> (omega (rad/s, file order), headings (deg), forces (headings, frequencies, 6)
    in NEMOH's convention, N and N m per m of wave amplitude)."""
    freq, headings, rows = _zones(path, 13, "freq |F1| ang(F1) .. |F6| ang(F6)")
    values = rows[..., 1::2] * np.exp(1j * rows[..., 2::2])  # phase in radians
    return _omega(path, freq), headings, values


def read_rao_dat(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``Motion/RAO.dat`` -> (omega (rad/s), headings (deg), RAOs (headings, frequencies, 6) in marinesim's
    convention)."""
    freq, headings, rows = _zones(path, 13, "freq |X| |Y| |Z| |phi| |theta| |psi| and six phases (deg)")
    amplitude = rows[..., 1:7] * np.where(ROTATION, math.pi / 180.0, 1.0)
    values = nemoh_to_internal(amplitude * np.exp(1j * np.radians(rows[..., 7:13])))
    return _omega(path, freq), headings, values


def read_coefficient_dat(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """``CA.dat`` or ``CM.dat`` -> (omega (rad/s), matrices (frequencies, 6, 6), row = motion DOF)."""
    lines = read_text(path).splitlines()
    if not lines or not lines[0].lower().startswith("nb de frequency"):
        raise FileFormatError(path, 1, "expected 'Nb de frequency : N'")
    tokens = Tokens(path, [lines[0].split(":")[-1]] + lines[1:])
    count = tokens.int("the number of frequencies")
    if not 1 <= count <= MAX_FREQUENCIES or tokens.remaining < count * 37:
        raise FileFormatError(path, 1, f"{count} frequencies: expected 1..{MAX_FREQUENCIES} and 37 numbers each "
                                       f"(the file holds {tokens.remaining})")
    omega = np.empty(count)
    matrices = np.empty((count, 6, 6))
    for i in range(count):
        omega[i] = tokens.float("frequency (rad/s)")
        for j in range(36):
            matrices[i, j // 6, j % 6] = tokens.float("coefficient")
    if not tokens.at_end():
        raise FileFormatError(path, tokens.line, "unexpected data after the last frequency (more than six DOFs?)")
    return omega, matrices


def read_radiation_tec(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``RadiationCoefficients.tec`` -> (omega (rad/s), added mass and damping (frequencies, 6, 6), row = motion)."""
    freq, _, rows = _zones(path, 13, "freq A_1 B_1 .. A_6 B_6", key=None)
    if rows.shape[0] != 6:
        raise FileFormatError(path, None, f"expected 6 zones (one per motion DOF), got {rows.shape[0]}")
    added = np.transpose(rows[..., 1::2], (1, 0, 2))
    damping = np.transpose(rows[..., 2::2], (1, 0, 2))
    return _omega(path, freq), added, damping


def _zones(path: Path, columns: int, expected: str, key: re.Pattern | None = _BETA) -> tuple[
        tuple[str, np.ndarray], np.ndarray, np.ndarray]:
    """Tecplot zones of ``path``: ((frequency kind, first column of the first zone), the zone values of ``key``
    (e.g. beta, deg), rows (zones, frequencies, columns)); every zone must list the same frequencies."""
    lines = read_text(path).splitlines()
    kind = None
    zones: list[float] = []
    data: list[list[list[float]]] = []
    for number, text in enumerate(lines, 1):
        stripped = text.strip()
        if not stripped or stripped.startswith('"') and not stripped.upper().startswith('"VARIABLES'):
            continue
        upper = stripped.upper().lstrip('"')
        if upper.startswith("VARIABLES"):
            kind = _frequency_kind(path, number, stripped)
            continue
        if upper.startswith("ZONE"):
            if key is None:
                zones.append(float(len(zones)))
                data.append([])
                continue
            match = key.search(stripped)
            if match is None:
                if data or "BETA" in upper:
                    raise FileFormatError(path, number, "expected 'beta = <deg>' in the zone title")
                continue  # a body-name zone ("Corps 1") before the first heading
            zones.append(parse_float(path, number, match.group(1), "beta (deg)"))
            data.append([])
            if len(zones) > MAX_HEADINGS:
                raise FileFormatError(path, number, f"more than {MAX_HEADINGS} zones")
            continue
        parts = stripped.split()
        if not data:
            raise FileFormatError(path, number, "data before the first ZONE line")
        if len(parts) != columns:
            raise FileFormatError(path, number, f"expected {columns} columns ({expected}), got {len(parts)} "
                                                "(only one body with six DOFs is read)")
        data[-1].append([parse_float(path, number, p, expected) for p in parts])
        if len(data[-1]) > MAX_FREQUENCIES:
            raise FileFormatError(path, number, f"more than {MAX_FREQUENCIES} frequencies in a zone")
    if not data or not data[0]:
        raise FileFormatError(path, None, f"no zones of data ({expected})")
    if kind is None:
        raise FileFormatError(path, 1, "expected a VARIABLES line naming the frequency column")
    sizes = {len(zone) for zone in data}
    if len(sizes) != 1:
        raise FileFormatError(path, None, f"zones of different lengths {sorted(sizes)}")
    rows = np.array(data)
    if np.any(rows[:, :, 0] != rows[:1, :, 0]):
        raise FileFormatError(path, None, "the zones list different frequencies")
    return (kind, rows[0, :, 0]), np.array(zones), rows


def _frequency_kind(path: Path, number: int, text: str) -> str:
    """'w', 'f' or 'T' from the first variable name of a VARIABLES line."""
    first = text.split("=", 1)[-1].strip().split('"')
    name = next((part for part in first if part.strip()), "").lower()
    for unit, kind in FREQUENCY_KINDS:
        if unit in name:
            return kind
    raise FileFormatError(path, number, f"unknown frequency column {name!r}: expected rad/s, Hz or s")


def _omega(path: Path, freq: tuple[str, np.ndarray]) -> np.ndarray:
    """Wave frequencies (rad/s, > 0, distinct) of a frequency column of ``kind``."""
    kind, values = freq
    if np.any(values <= 0.0):
        raise FileFormatError(path, None, "frequencies must be > 0 (zero and infinite frequency carry no RAO)")
    omega = {"w": values, "f": 2.0 * math.pi * values, "T": 2.0 * math.pi / values}[kind]
    if np.unique(omega).size != omega.size:
        raise FileFormatError(path, None, "a frequency is listed twice")
    return omega.astype(float)


def _match(path: Path, omega_file: np.ndarray, omega: np.ndarray, tolerance: float) -> None:
    if omega_file.size != omega.size or np.any(np.abs(omega_file - omega) > tolerance + 1e-4 * omega):
        raise FileFormatError(path, None, f"its {omega_file.size} frequencies differ from the {omega.size} of "
                                          "ExcitationForce.tec (files of different runs?)")


def _folder(parent: Path, name: str) -> Path | None:
    """The sub-folder ``name`` of ``parent``, any case."""
    if not parent.is_dir():
        return None
    return next((p for p in sorted(parent.iterdir()) if p.is_dir() and p.name.lower() == name.lower()), None)


def _child(root: Path, folder: str | None, name: str) -> Path | None:
    """The file ``folder/name`` under ``root`` (folder and name any case); None if absent."""
    parent = root if folder is None else _folder(root, folder)
    if parent is None:
        return None
    return next((p for p in sorted(parent.iterdir()) if p.is_file() and p.name.lower() == name.lower()), None)


def _matrix_file(root: Path, places: list[tuple[str, str]]) -> tuple[np.ndarray | None, Path | None]:
    """The first 6 x 6 matrix file found among ``places`` (folder, name)."""
    for folder, name in places:
        found = _child(root, folder, name)
        if found is not None:
            return _read_matrix(found, 6), found
    return None, None


def _read_matrix(path: Path, size: int) -> np.ndarray:
    tokens = Tokens(path, read_text(path).splitlines())
    if tokens.remaining != size * size:
        raise FileFormatError(path, tokens.line, f"expected a {size} x {size} matrix ({size * size} numbers), "
                                                 f"got {tokens.remaining} numbers")
    return np.array([tokens.float("matrix coefficient") for _ in range(size * size)]).reshape(size, size)


def _hydrostatics(path: Path, rho: float) -> tuple[float, tuple[float, float, float]]:
    """(mass kg, (XG, YG, ZG) m) from NEMOH's ``Hydrostatics.dat``: ``Mass =`` or rho times ``Displacement =``."""
    values: dict[str, float] = {}
    for number, text in enumerate(read_text(path).splitlines(), 1):
        for name, value in re.findall(r"([A-Za-z][A-Za-z ]*?)\s*=\s*([-+0-9.eEdD]+)", text):
            values[name.strip().lower()] = parse_float(path, number, value, name.strip())
    if not {"xg", "yg", "zg"} <= values.keys():
        raise FileFormatError(path, None, "expected XG, YG and ZG (the centre of gravity)")
    mass = values.get("mass")
    if mass is None and "displacement" in values:
        mass = rho * values["displacement"]
    if mass is None or mass <= 0.0:
        raise FileFormatError(path, None, "expected a positive 'Mass =' or 'Displacement =' (m^3)")
    return mass, (values["xg"], values["yg"], values["zg"])
