"""HydroStar ``.rao`` motion RAOs, as HydroStar and HAMS write them, and HAMS's WAMIT-format ``.4`` -> :class:`RaoTable`.

**HydroStar layout** (one DOF per file; HAMS writes ``Output/Hydrostar_format/Motion_1.rao`` .. ``Motion_6.rao``)::

    # Constants used in computations :
    #     Water density (rho)  :  1025.0000
    #     Gravity acceleration :     9.8066
    #     Waterdepth           :    10.0000          (or "Inf.")
    #     Ref.pt incident wave : (   0.0000   0.0000)
    #            Forward speed :   0.0000  m/s
    # Reference point of body 1: (   0.0000   0.0000   0.0000)
    #   AMP/PHASE
    #RAOTYPE    :  Motion
    #COMPONENT  :  3                 (HAMS writes 33)
    #UNIT       :  m/m               (deg/m or rad/m for rotations)
    #NBHEADING    36
    #HEADING          0.00  10.00 ...
    #---w(r/s)-------------
      w  amp(heading 1..n)  phase_deg(heading 1..n)
    #ENDFILE

The reader is given one ``Motion`` file; the other five DOFs are the ``.rao`` files beside it whose header says
``#RAOTYPE : Motion`` (added mass, damping and excitation files in the same folder are skipped). Rows with
``w <= 0`` (HAMS's zero- and infinite-frequency rows, ``0`` and ``-1``, with NaN or dummy values) are skipped.

**Source convention, converted here once** (established from HAMS's source and its files; CONVENTIONS.md):

* ``w`` is the wave frequency in rad/s. ``HEADING`` is the direction the waves travel towards, degrees
  anticlockwise from the body x axis (marinesim's ``beta_rel``): in the HAMS cylinder's long-wave rows surge
  tends to ``-i`` at heading 0 and sway to ``-i`` at heading 90, as :func:`~marinesim.vessel.rao.long_wave_limit`.
* Phases lead, time factor ``exp(+i w t)``, relative to the incident wave at ``Ref.pt incident wave``: HAMS
  writes ``phase = atan2(-Re z, -Im z)`` of its internal ``exp(-i w t)`` displacement ``z``, i.e. the phase of
  ``-i conj(z)``, the same transform it applies to its WAMIT ``.3`` forces. Heave tends to phase 0, pitch to
  ``+90`` deg at heading 0. When the incident-wave point ``P`` differs from the body's reference point ``O``
  (HydroStar often has the wave at (0, 0) and the body at its CoG) the phases are re-referred to the wave at
  ``O``: ``H_O = H_P exp(-i k ((P - O) . (cos b, sin b)))`` with ``k`` from the file's depth.
* Rotations: ``#UNIT`` says deg/m or rad/m, but HAMS writes radians under a ``deg/m`` label
  (``PrintBody_CmplxVal`` converts nothing; the cylinder's long-wave pitch / k is 1.04 read as rad/m, 0.018
  read as deg/m). :func:`rotation_unit` therefore checks the label against the long-wave pitch (and roll)
  slope and overrides a label the physics contradicts, with a note.

**HAMS's WAMIT-format ``.4``** (``Output/Wamit_format/Buoy.4``) is *not* WAMIT's convention: ``SolveMotion.f90``
writes ``conj(z) / (rho g L^m)`` (m = 2 translations, 3 rotations, ``L = Reference_body_length``): motions
normalised like forces by ``rho g`` and, against the HydroStar files (and WAMIT), multiplied by ``i``. So
``H = -i V rho g L^m`` with HAMS's ``rho = 1025``, ``g = 9.80665``. :func:`read_hams_wamit` detects the
normalisation (long-wave heave ~ 1 / (rho g) instead of ~ 1) and says so in a note; the PER column is what
``Output_frequency_type`` in HAMS's ``Input/ControlFile.in`` says (1 deep-water wavenumber w^2/g, 2 finite-depth
wavenumber, 3 rad/s, 4 period, 5 wavelength).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.constants import G, RHO_SEAWATER
from marinesim.errors import FileFormatError, HeadingError, ParameterError
from marinesim.formats import check_file
from marinesim.sea.dispersion import k_from_omega
from marinesim.tokens import parse_float, parse_int, read_text
from marinesim.vessel.rao import DOFS, ROTATIONS, RaoTable, make_table, refer_phases
from marinesim.vessel.wamit_rows import read_rows

MAX_SIBLINGS = 1000
"""Most ``.rao`` files beside the given one whose headers are examined for the other DOFs."""
MAX_HEADINGS = 3600
MAX_FREQUENCIES = 100_000
HEAD_BYTES = 4096
MOTION = "motion"
SLOPE_BAND = (0.2, 5.0)
"""Long-wave |rotation| / (k |cos b| or k |sin b|) in this band means the values are in the unit tested."""

# HAMS's constants (WavDynMods.f90: DATA G, PI, RHO / 9.80665, ..., 1025)
HAMS_G = 9.80665
HAMS_RHO = 1025.0
HAMS_FREQUENCY_TYPES = {1: "deep-water wavenumber w^2/g (1/m)", 2: "finite-depth wavenumber (1/m)",
                        3: "frequency (rad/s)", 4: "period (s)", 5: "wavelength (m)"}


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes hold a HydroStar header: ``#RAOTYPE`` and ``#HEADING`` comment lines."""
    text = head.decode("utf-8", errors="replace")
    return bool(re.search(r"^#\s*RAOTYPE\s*:", text, re.M | re.I)) and bool(re.search(r"^#\s*HEADING", text, re.M | re.I))


@dataclass(frozen=True)
class RaoFile:
    """One HydroStar ``.rao`` file: its header and table as written (amplitudes as labelled, phases in deg)."""

    path: Path
    rao_type: str
    component: int  # 1..6
    unit: str
    rho: float
    g: float
    depth: float  # m; inf = deep
    wave_point: tuple[float, float]
    reference_point: tuple[float, float, float]
    speed: float
    re_im: bool
    headings_deg: np.ndarray  # (n_headings,)
    omega: np.ndarray  # (n_frequencies,), rad/s, file order, > 0
    values: np.ndarray  # (n_headings, n_frequencies) complex, unit as labelled
    skipped_rows: int


_HEADER_NUMBER = r"([-+0-9.EeDd]+)"


def read_rao_file(path: Path) -> RaoFile:
    """Parse one HydroStar ``.rao`` file (any RAOTYPE); :class:`FileFormatError` naming the line otherwise."""
    check_file(path, "RAO file")
    lines = read_text(path).splitlines()
    header: dict[str, tuple[int, str]] = {}
    headings: list[float] | None = None
    heading_line = 0
    count_line, count = 0, None
    re_im = False
    column_line = 0
    rows: list[tuple[int, list[str]]] = []
    ended = False
    for number, text in enumerate(lines, 1):
        stripped = text.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            body = stripped[1:].strip()
            upper = body.upper()
            if upper.startswith("ENDFILE"):
                ended = True
                break
            if upper.startswith("NBHEADING"):
                count_line, count = number, parse_int(path, number, body[len("NBHEADING"):].strip(" :"),
                                                      "the number of headings after #NBHEADING")
                if not 1 <= count <= MAX_HEADINGS:
                    raise FileFormatError(path, number, f"#NBHEADING must be 1..{MAX_HEADINGS}, got {count}")
            elif upper.startswith("HEADING"):
                heading_line = number
                headings = [parse_float(path, number, word, "a heading (deg)") for word in body[7:].replace(":", " ").split()]
            elif upper.startswith("RE/IM") or upper.startswith("REAL/IMAG"):
                re_im = True
            elif "W(R/S)" in upper.replace(" ", ""):
                column_line = number
            elif upper.startswith("---") and headings is not None and not column_line:
                raise FileFormatError(path, number, f"the frequency column is {body.strip('-')!r}: only w(r/s) "
                                                    "(rad/s) is supported")
            elif ":" in body:
                key, _, value = body.partition(":")
                header[" ".join(key.split()).lower()] = (number, value.strip())
            continue
        if not column_line:
            raise FileFormatError(path, number, "data before the '#---w(r/s)---' column line: not a HydroStar .rao file")
        rows.append((number, stripped.split()))
        if len(rows) > MAX_FREQUENCIES:
            raise FileFormatError(path, number, f"more than {MAX_FREQUENCIES} frequency rows")
    if "raotype" not in header:
        raise FileFormatError(path, None, "no '#RAOTYPE :' line: not a HydroStar .rao file")
    if headings is None or count is None:
        raise FileFormatError(path, None, "no '#NBHEADING' and '#HEADING' lines")
    if len(headings) != count:
        raise FileFormatError(path, heading_line, f"#HEADING lists {len(headings)} headings, #NBHEADING "
                                                  f"(line {count_line}) says {count}")
    if not column_line:
        raise FileFormatError(path, None, "no '#---w(r/s)---' column line before the table")
    if not ended:
        raise FileFormatError(path, len(lines), "file ends without '#ENDFILE' (cut short?)")
    rao_type = header["raotype"][1].split()[0].lower() if header["raotype"][1].split() else ""
    component = _component(path, header)
    unit = header.get("unit", (0, ""))[1].replace(" ", "").lower()
    rho = _header_float(path, header, "water density (rho)", RHO_SEAWATER)
    g = _header_float(path, header, "gravity acceleration", G)
    depth = _depth(path, header)
    wave_point = _header_point(path, header, "ref.pt incident wave", 2)
    reference = _header_point(path, header, "reference point of body 1", 3)
    speed = _header_float(path, header, "forward speed", 0.0)
    omega: list[float] = []
    cells: list[np.ndarray] = []
    skipped = 0
    width = 1 + 2 * count
    for number, words in rows:
        if len(words) != width:
            raise FileFormatError(path, number, f"expected {width} numbers (w, {count} amplitudes, {count} phases), "
                                                f"got {len(words)}")
        w = _number(path, number, words[0], "w (rad/s)")
        if not math.isfinite(w):
            raise FileFormatError(path, number, f"w must be a finite number, got {words[0]!r}")
        if w <= 0.0:  # HAMS's zero (0) and infinite (-1) frequency rows carry no RAO
            skipped += 1
            continue
        numbers = np.array([_number(path, number, word, "an amplitude or phase") for word in words[1:]])
        if not np.all(np.isfinite(numbers)):
            raise FileFormatError(path, number, f"non-finite value at w = {w:g} rad/s")
        first, second = numbers[:count], numbers[count:]
        if re_im:
            cells.append(first + 1j * second)
        else:
            if np.any(first < 0):
                raise FileFormatError(path, number, f"negative amplitude at w = {w:g} rad/s")
            cells.append(first * np.exp(1j * np.radians(second)))
        if omega and w <= omega[-1]:
            raise FileFormatError(path, number, f"w {w:g} rad/s after {omega[-1]:g}: frequencies must increase")
        omega.append(w)
    if not omega:
        raise FileFormatError(path, None, "no rows with w > 0 rad/s")
    return RaoFile(path, rao_type, component, unit, rho, g, depth, wave_point, reference, speed, re_im,
                   np.array(headings), np.array(omega), np.array(cells).T, skipped)


def read_hydrostar(path: str | Path) -> RaoTable:
    """Read a HydroStar/HAMS ``Motion`` ``.rao`` file and the five other DOFs beside it (module docstring)."""
    path = Path(path)
    first = read_rao_file(path)
    if first.rao_type != MOTION:
        raise FileFormatError(path, None, f"#RAOTYPE is {first.rao_type!r}: only motion RAOs are read "
                                          "(give one of the Motion_*.rao files)")
    files = {first.component: first}
    for sibling in _siblings(path):
        if not _is_motion_head(sibling):
            continue
        other = read_rao_file(sibling)
        if other.component in files:
            raise FileFormatError(sibling, None, f"DOF {other.component} ({DOFS[other.component - 1]}) is also "
                                                 f"given by {files[other.component].path.name}")
        files[other.component] = other
    missing = [DOFS[j - 1] for j in range(1, 7) if j not in files]
    if missing:
        raise FileFormatError(path, None, f"motion RAOs of {', '.join(missing)} not found beside the file "
                                          "(HydroStar writes one DOF per .rao file: give the folder all six)")
    for other in files.values():
        _check_same_grid(first, other)
    if first.speed != 0.0:
        raise FileFormatError(path, None, f"forward speed {first.speed:g} m/s: only zero-speed HydroStar tables "
                                          "are read (wave vs encounter frequency not established)")
    notes = [f"HydroStar .rao: {', '.join(files[j].path.name for j in range(1, 7))}"]
    if first.skipped_rows:
        notes.append(f"{first.skipped_rows} row(s) with w <= 0 (zero/infinite frequency) skipped")
    values = np.zeros((first.headings_deg.size, first.omega.size, 6), dtype=complex)
    for j in range(6):
        f = files[j + 1]
        scale = 1.0
        if j in ROTATIONS:
            unit, note = rotation_unit(f, files)
            scale = math.pi / 180.0 if unit == "deg/m" else 1.0
            if note:
                notes.append(note)
        elif f.unit and f.unit != "m/m":
            raise FileFormatError(f.path, None, f"#UNIT {f.unit!r} for {DOFS[j]}: expected m/m")
        values[:, :, j] = f.values * scale
    shift = np.array(first.wave_point) - np.array(first.reference_point[:2])
    if np.any(shift != 0.0):
        values = refer_phases(values, first.omega, first.headings_deg, (-shift[0], -shift[1]), first.depth, first.g)
        notes.append(f"phases re-referred from the incident-wave point ({shift[0] + first.reference_point[0]:g}, "
                     f"{shift[1] + first.reference_point[1]:g}) m to the reference point")
    notes.append(f"headings = wave travel direction from body x; phases lead (exp(+i w t)); rho {first.rho:g}, "
                 f"g {first.g:g}, depth {'infinite' if math.isinf(first.depth) else f'{first.depth:g} m'}")
    return _table(path, first.omega, first.headings_deg, values, reference=first.reference_point, rho=first.rho,
                  g=first.g, depth=first.depth, notes=notes, source_format="hydrostar")


def rotation_unit(f: RaoFile, files: dict[int, RaoFile]) -> tuple[str, str]:
    """("deg/m" or "rad/m", note) for the rotation file ``f``: its ``#UNIT`` label unless the long-wave pitch
    slope of the set (roll slope when no heading has |cos b| > 0.5) contradicts it.

    At the lowest frequency a free-floating body pitches with the wave slope, |pitch| = k |cos b| (rad/m): the
    ratio q = |value| / (k |cos b|) is about 1 for rad/m and about 57 for deg/m. A label is overridden only when
    q lies in one band and the label names the other."""
    label = {"deg/m": "deg/m", "degree/m": "deg/m", "deg": "deg/m", "rad/m": "rad/m", "radian/m": "rad/m",
             "rad": "rad/m", "": ""}.get(f.unit)
    if label is None:
        raise FileFormatError(f.path, None, f"#UNIT {f.unit!r} for {DOFS[f.component - 1]}: expected deg/m or rad/m")
    q = _long_wave_slope_ratio(files)
    measured = None
    if q is not None:
        if SLOPE_BAND[0] <= q <= SLOPE_BAND[1]:
            measured = "rad/m"
        elif SLOPE_BAND[0] * 180 / math.pi <= q <= SLOPE_BAND[1] * 180 / math.pi:
            measured = "deg/m"
    if not label:
        if measured is None:
            raise FileFormatError(f.path, None, "no #UNIT for a rotation and the long-wave slope does not tell "
                                                "deg/m from rad/m")
        return measured, f"{f.path.name}: no #UNIT; long-wave slope ratio {q:.3g} says {measured}"
    if measured is not None and measured != label:
        return measured, (f"{f.path.name}: #UNIT says {label} but the long-wave pitch/roll over the wave slope is "
                          f"{q:.3g} read as rad/m (x 57.3 as deg/m): read as {measured} (HAMS writes radians "
                          "under a deg/m label)")
    return label, ""


def _long_wave_slope_ratio(files: dict[int, RaoFile]) -> float | None:
    """|rotation| / (k |cos b|) for pitch (or / (k |sin b|) for roll) at the lowest frequency, at the heading
    where the trigonometric factor is largest (> 0.5); None if no heading qualifies."""
    for j, trig in ((5, np.cos), (4, np.sin)):
        f = files.get(j)
        if f is None:
            continue
        factor = np.abs(trig(np.radians(f.headings_deg)))
        h = int(np.argmax(factor))
        if factor[h] < 0.5:
            continue
        k = float(k_from_omega(f.omega[0], f.depth, f.g))
        return float(abs(f.values[h, 0]) / (k * factor[h]))
    return None


def read_hams_wamit(path: str | Path, *, frequency_type: int | None = None, depth: float | None = None,
                    reference_length: float | None = None) -> RaoTable:
    """Read HAMS's WAMIT-format motion file (``Output/Wamit_format/Buoy.4``), undoing HAMS's ``rho g`` normalisation
    and its extra factor ``i`` (module docstring). ``frequency_type`` (HAMS ``Output_frequency_type`` 1-5), ``depth``
    (m; <= 0 infinite) and ``reference_length`` override HAMS's ``Input/ControlFile.in``."""
    path = Path(path)
    check_file(path, "RAO file")
    control = _hams_control(path)
    notes: list[str] = []
    kind = frequency_type if frequency_type is not None else control.get("output_frequency_type")
    if kind is None:
        raise FileFormatError(path, None, "the PER column's meaning is Output_frequency_type in HAMS's "
                                          "Input/ControlFile.in, not found (looked in ../../Input, ../Input and "
                                          "beside the file): put it there or give frequency_type (1-5)")
    if kind not in HAMS_FREQUENCY_TYPES:
        raise ParameterError(f"HAMS Output_frequency_type {kind} is not one of "
                             + ", ".join(f"{k} = {v}" for k, v in HAMS_FREQUENCY_TYPES.items()))
    h = depth if depth is not None else control.get("waterdepth", -1.0)
    h = math.inf if h is None or h <= 0 else float(h)
    length = reference_length if reference_length is not None else control.get("reference_body_length", 1.0)
    if not 0.01 <= length <= 1000.0:
        raise ParameterError(f"HAMS Reference_body_length must be in 0.01..1000 m, got {length:g}")
    centre = control.get("reference_body_center", (0.0, 0.0, 0.0))
    per, headings, raw, row_notes = read_rows(path)
    notes += row_notes
    omega = _hams_omega(path, per, kind, h)
    heave = np.abs(raw[:, int(np.argmin(omega)), 2])
    normalised = bool(heave.max() < 1e-2)
    if normalised:
        scale = HAMS_RHO * HAMS_G * length ** np.where(np.arange(6) >= 3, 3.0, 2.0)
        values = -1j * raw * scale
        notes.append(f"HAMS WAMIT-format motions detected (long-wave heave {heave.max():.4g} ~ 1/(rho g) = "
                     f"{1 / (HAMS_RHO * HAMS_G):.4g}): multiplied by -i rho g L^m (rho {HAMS_RHO:g}, g {HAMS_G:g}, "
                     f"L {length:g} m; HAMS SolveMotion.f90 writes conj(z)/(rho g L^m))")
    else:
        values = raw.astype(complex)
        notes.append(f"long-wave heave {heave.max():.4g}: not HAMS's rho g normalisation; read as WAMIT's own "
                     "per-unit-amplitude convention (rotations rad/m)")
    notes.append(f"PER column read as {HAMS_FREQUENCY_TYPES[kind]} (Output_frequency_type {kind}); depth "
                 f"{'infinite' if math.isinf(h) else f'{h:g} m'}; reference point {tuple(centre)}")
    order = np.argsort(omega)
    return _table(path, omega[order], headings, values[:, order], reference=tuple(centre), rho=HAMS_RHO,
                  g=HAMS_G, depth=h, notes=notes, source_format="hams-wamit")


def is_hams_output(path: str | Path) -> bool:
    """Whether ``path`` sits in a HAMS run (a ``ControlFile.in`` in ``../../Input``, ``../Input`` or beside it) and
    its long-wave heave is HAMS's ``1/(rho g)`` normalisation: what :func:`marinesim.vessel.wamit.read_wamit`
    should check before reading a ``.4`` as WAMIT's (it would otherwise read motions 1e-4 of the true ones)."""
    path = Path(path)
    if not _hams_control(path):
        return False
    try:
        _, _, raw, _ = read_rows(path)
    except FileFormatError:
        return False
    return bool(np.abs(raw[:, :, 2]).max() < 1e-2)


def _hams_omega(path: Path, per: np.ndarray, kind: int, depth: float) -> np.ndarray:
    """Wave frequency (rad/s) of HAMS's PER column of ``kind`` (ImplementSubs.f90, CalWaveProperts)."""
    if kind == 3:
        return per.copy()
    if kind == 4:
        return 2.0 * math.pi / per
    if kind == 1:
        return np.sqrt(HAMS_G * per)
    k = per if kind == 2 else 2.0 * math.pi / per
    return np.sqrt(HAMS_G * k * (1.0 if math.isinf(depth) else np.tanh(k * depth)))


def _hams_control(path: Path) -> dict:
    """Settings of HAMS's ``ControlFile.in`` for the output file ``path``: ``output_frequency_type``, ``waterdepth``,
    ``reference_body_length``, ``reference_body_center``; empty when there is none."""
    parent = path.resolve().parent
    for candidate in (parent.parent.parent / "Input" / "ControlFile.in", parent.parent / "Input" / "ControlFile.in",
                      parent / "ControlFile.in"):
        if candidate.is_file():
            break
    else:
        return {}
    check_file(candidate, "RAO file")
    out: dict = {}
    for number, text in enumerate(read_text(candidate).splitlines(), 1):
        if "end hams control file" in text.lower():
            break  # the option lists after it repeat the keys
        words = text.split()
        if len(words) < 2 or words[0].lower() in out:
            continue
        key = words[0].lower()
        if key == "waterdepth":
            out[key] = parse_float(candidate, number, words[1], "Waterdepth (m)")
        elif key == "output_frequency_type":
            out[key] = parse_int(candidate, number, words[1], "Output_frequency_type (1-5)")
        elif key == "reference_body_length":
            out[key] = parse_float(candidate, number, words[1], "Reference_body_length (m)")
        elif key == "reference_body_center":
            if len(words) < 4:
                raise FileFormatError(candidate, number, "Reference_body_center takes three numbers")
            out[key] = tuple(parse_float(candidate, number, w, "Reference_body_center (m)") for w in words[1:4])
    return out


def _table(path: Path, omega: np.ndarray, headings_deg: np.ndarray, values: np.ndarray, *, reference, rho: float,
           g: float, depth: float, notes: list[str], source_format: str) -> RaoTable:
    """The :class:`RaoTable` of ``values`` (headings, frequencies, 6), refusals as :class:`FileFormatError`."""
    beta = np.mod(np.radians(headings_deg), 2.0 * math.pi)
    try:
        return make_table(omega, beta, [0.0], values[None], reference_point=reference, rho=rho, g=g,
                          source=str(path), source_format=source_format, notes=tuple(notes), depth=depth)
    except HeadingError as error:
        raise FileFormatError(path, None, f"{error} (the file covers heading(s) "
                              f"{', '.join(f'{h:g}' for h in headings_deg)} deg)") from None
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def _siblings(path: Path) -> list[Path]:
    """The other ``.rao`` files in ``path``'s folder (at most :data:`MAX_SIBLINGS`), sorted by name."""
    here = path.resolve()
    found = []
    for candidate in sorted(path.parent.iterdir()):
        if candidate.suffix.lower() != ".rao" or candidate.resolve() == here or not candidate.is_file():
            continue
        found.append(candidate)
        if len(found) > MAX_SIBLINGS:
            raise FileFormatError(path.parent, None, f"more than {MAX_SIBLINGS} .rao files beside {path.name}")
    return found


def _is_motion_head(path: Path) -> bool:
    try:
        with path.open("rb") as handle:
            head = handle.read(HEAD_BYTES).decode("utf-8", errors="replace")
    except OSError:
        return False
    found = re.search(r"^#\s*RAOTYPE\s*:\s*(\S+)", head, re.M | re.I)
    return bool(found) and found.group(1).lower() == MOTION


def _check_same_grid(first: RaoFile, other: RaoFile) -> None:
    if other.headings_deg.shape != first.headings_deg.shape or np.any(other.headings_deg != first.headings_deg):
        raise FileFormatError(other.path, None, f"headings differ from {first.path.name}'s")
    if other.omega.shape != first.omega.shape or np.any(np.abs(other.omega - first.omega) > 1e-9 * first.omega):
        raise FileFormatError(other.path, None, f"frequencies differ from {first.path.name}'s")
    for name in ("rho", "g", "depth", "wave_point", "reference_point", "speed"):
        if getattr(other, name) != getattr(first, name):
            raise FileFormatError(other.path, None, f"{name} {getattr(other, name)} differs from "
                                                    f"{first.path.name}'s {getattr(first, name)}")


def _component(path: Path, header: dict[str, tuple[int, str]]) -> int:
    """The DOF (1..6) of ``#COMPONENT`` ("3", or HAMS's "33")."""
    if "component" not in header:
        raise FileFormatError(path, None, "no '#COMPONENT :' line")
    number, text = header["component"]
    text = text.split()[0] if text.split() else ""
    if len(text) == 2 and text[0] == text[1]:
        text = text[0]
    value = parse_int(path, number, text, "the DOF number 1..6 after #COMPONENT")
    if not 1 <= value <= 6:
        raise FileFormatError(path, number, f"#COMPONENT must be a DOF 1..6, got {value}")
    return value


def _header_float(path: Path, header: dict[str, tuple[int, str]], key: str, default: float) -> float:
    if key not in header:
        return default
    number, text = header[key]
    found = re.match(_HEADER_NUMBER, text)
    if not found:
        raise FileFormatError(path, number, f"expected a number after '{key}', got {text!r}")
    return parse_float(path, number, found.group(1), key)


def _depth(path: Path, header: dict[str, tuple[int, str]]) -> float:
    if "waterdepth" not in header:
        return math.inf
    number, text = header["waterdepth"]
    if text.lower().startswith("inf"):
        return math.inf
    value = _header_float(path, header, "waterdepth", math.inf)
    return math.inf if value <= 0 else value


def _header_point(path: Path, header: dict[str, tuple[int, str]], key: str, size: int) -> tuple[float, ...]:
    if key not in header:
        return (0.0,) * size
    number, text = header[key]
    words = text.replace("(", " ").replace(")", " ").replace(",", " ").split()
    if len(words) != size:
        raise FileFormatError(path, number, f"'{key}' takes {size} numbers in brackets, got {text!r}")
    return tuple(parse_float(path, number, w, key) for w in words)


def _number(path: Path, line: int, text: str, expected: str) -> float:
    """A number of the table; NaN allowed (checked by the caller for rows that are kept)."""
    if text.lower() == "nan":
        return math.nan
    return parse_float(path, line, text, expected)
