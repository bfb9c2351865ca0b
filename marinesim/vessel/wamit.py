"""WAMIT ``.4`` motion RAOs (numeric output) -> :class:`RaoTable`, and what the other WAMIT readers share.

Source convention, converted here once: each line is ``PER BETA I MOD PHA RE IM``; ``PER`` is,
as the ``.cfg`` beside the file says (``IPEROUT``, else ``IPERIO``; WAMIT's default 1), the
period in s (1), the frequency in rad/s (2), the infinite-depth wavenumber ``K ULEN`` with
``K = w^2 / g`` (3) or the finite-depth wavenumber ``nu ULEN`` with ``nu tanh(nu H) = w^2 / g``
(4; the depth ``H`` from the ``.pot``). ``IPERIN`` only says how the ``.pot`` gave them and is
not used. ``BETA`` is the direction the waves travel towards, degrees from the body x axis
(already marinesim's ``beta_rel``); the time factor is ``exp(+i w t)`` with phase lead
(marinesim's own). Translations are per wave amplitude A; rotations per ``A / ULEN``, so
rad/m = value / ULEN. ``ULEN`` and ``g`` come from the ``.gdf`` of the same name, ``rho`` from
the ``.frc``. Lines with zero modulus carry a dummy phase (90 deg): only ``RE`` and ``IM`` are
used. The reference point is the origin of WAMIT's body coordinates. A header line
(``NUMHDR = 1`` in the ``.cfg``) is skipped; modes above 6 (generalised modes, other bodies)
are ignored with a note: WAMIT solved them together, so the rigid-body RAOs are complete. A run of several
bodies (``NBODY > 1`` in the ``.pot`` of the same name) gives body n's motions as modes ``6 (n - 1) + 1 ..
6 n``: the body is named by its number or its ``.gdf`` file (``marinesim rao --body``, ``[vessel] rao_body``),
and placed by its own ``XBODY``.

A ``.3`` file (exciting forces) has the same seven columns; its values (forces per
``rho g A ULEN^2``) are far beyond any motion RAO for a ship-sized body, which is how
:func:`sniff` and :func:`read_wamit` tell it from a ``.4`` when the name does not say
(:func:`looks_like_forces`); :mod:`marinesim.vessel.wamit_forces` reads it as what it is.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.constants import G, RHO_SEAWATER
from marinesim.errors import FileFormatError, HeadingError, ParameterError, require_within
from marinesim.hull.gdf import read_gdf_header
from marinesim.hull.wamit_pot import Pot, pot_beside, read_cfg
from marinesim.vessel.wamit_frc import read_frc
from marinesim.vessel.rao import (MAX_ROTATION_RAD_M, MAX_TRANSLATION_M_M, ROTATIONS, RaoTable, make_table,
                                  refer_phases)
from marinesim.tokens import parse_int
from marinesim.vessel.wamit_rows import RIGID_MODES, read_rows

ULEN_RANGE_M = (0.01, 1000.0)
"""WAMIT's length scale (m): 1 or a body dimension, from a tank model's to the largest vessel's."""
PERIOD_KINDS = {1: "period (s)", 2: "frequency (rad/s)", 3: "wavenumber K*ULEN (infinite depth)",
                4: "wavenumber nu*ULEN (finite depth)"}
MAX_FORCE_LIKE_ROTATION = MAX_ROTATION_RAD_M * ULEN_RANGE_M[1]
"""Largest rotation value a ``.4`` can hold (per A / ULEN): the largest rotation RAO times the largest ULEN."""


def read_wamit(path: str | Path, *, ulen: float | None = None, period_kind: int | None = None,
               body: str | None = None) -> RaoTable:
    """Read a WAMIT ``.4`` file; ``ulen`` and ``period_kind`` (IPEROUT) override the files beside it, ``body``
    (number or ``.gdf`` name) picks one body of several. HAMS's WAMIT-format ``.4`` (motions over rho g,
    conjugated) is recognised and read as HAMS wrote it, with a note."""
    path = Path(path)
    from marinesim.vessel.hydrostar import is_hams_output, read_hams_wamit  # it reads rows as this module does

    if is_hams_output(path):
        if body is not None:
            raise ParameterError(f"{path}: HAMS's .4 holds one body: a body ({body!r}) is for WAMIT runs of several")
        return read_hams_wamit(path)
    settings = Settings.beside(path, ulen=ulen, period_kind=period_kind, body=body)
    notes = list(settings.notes)
    rho = frc_rho(path.with_suffix(".frc"))
    if rho is None:
        rho = RHO_SEAWATER
        notes.append(f"rho not found (no .frc beside the file): assumed {RHO_SEAWATER:g} kg/m^3")

    periods, headings, values, row_notes = read_rows(path, header_lines=settings.header_lines,
                                                     offset=settings.mode_offset)
    settings.check_headings(path, headings)
    notes += row_notes
    biggest = np.abs(values).max(axis=(0, 1))
    if looks_like_forces(biggest):
        raise FileFormatError(path, None, "values up to "
                              + ", ".join(f"{v:.4g}" for v in biggest)
                              + " (modes 1-6) are exciting forces, not motions: this is a WAMIT .3 file; "
                              "name it .3 to solve the RAOs from it with the .1, .hst and .frc beside it")
    omega = settings.omega(periods, path)
    order = np.argsort(omega)
    values = values[:, order]
    values[..., list(ROTATIONS)] /= settings.ulen
    return table_from(path, omega[order], headings, values, rho=rho, settings=settings,
                      notes=tuple(notes) + (settings.describe(),))


def table_from(path: Path, omega: np.ndarray, headings_deg: np.ndarray, values: np.ndarray, *, rho: float,
               settings: "Settings", notes: tuple[str, ...], source_format: str = "wamit") -> RaoTable:
    """The :class:`RaoTable` of ``values`` (heading, frequency, 6; internal convention) read from ``path``;
    a table the RAO model refuses (e.g. headings that cover part of the circle) is a :class:`FileFormatError`
    naming the headings the file covers."""
    extra = {"depth": settings.depth} if math.isfinite(settings.depth) else {}
    headings_deg, values = _same_headings_once(path, np.asarray(headings_deg, float), values)
    x, y, z, phi = settings.xbody
    if any(settings.xbody):
        # WAMIT's phases are relative to the wave at its global origin, its headings from its global X axis
        values = refer_phases(values, omega, headings_deg, (x, y), settings.depth, settings.g)
        headings_deg = headings_deg - phi
        notes = notes + (f"{settings.placed_by}: body origin at ({x:g}, {y:g}, {z:g}) m in WAMIT's global frame, "
                         f"its x axis at {phi:g} deg: phases referred to the wave at the body origin, headings to "
                         "its x axis",)
    try:
        return make_table(omega, np.radians(headings_deg), [0.0], values[None], reference_point=(0.0, 0.0, z),
                          rho=rho, g=settings.g, source=str(path), source_format=source_format, notes=notes,
                          **extra)
    except HeadingError as error:
        raise FileFormatError(path, None, f"{error} (the file covers heading(s) "
                              f"{', '.join(f'{h:g}' for h in headings_deg)} deg only)") from None
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None


def _same_headings_once(path: Path, headings_deg: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Headings (deg) and values (heading, frequency, 6) with a heading given twice (-180 and 180, as WAMIT
    runs over the whole circle write it) kept once; the two must agree to the file's precision."""
    wrapped = np.mod(headings_deg, 360.0)
    keep: list[int] = []
    for h, heading in enumerate(wrapped):
        twin = next((k for k in keep if np.isclose(wrapped[k], heading, rtol=0.0, atol=1e-9)), None)
        if twin is None:
            keep.append(h)
        elif not np.allclose(values[h], values[twin], rtol=1e-4, atol=1e-6 * np.abs(values).max()):
            raise FileFormatError(path, None, f"headings {headings_deg[twin]:g} and {headings_deg[h]:g} deg are the "
                                              "same waves but their values differ")
    return headings_deg[keep], values[keep]


def looks_like_forces(biggest: np.ndarray) -> bool:
    """Whether the largest |value| of each mode (6,) is beyond any motion RAO a ``.4`` can hold: then the
    seven columns are exciting forces (a ``.3``)."""
    return bool(np.any(biggest[:3] > MAX_TRANSLATION_M_M) or np.any(biggest[3:] > MAX_FORCE_LIKE_ROTATION))


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like a ``.4`` file: lines of seven numbers that are motions."""
    biggest = _head_moduli(head)
    return biggest is not None and not looks_like_forces(biggest)


def sniff_forces(head: bytes) -> bool:
    """Whether the file's first bytes look like a ``.3`` file: lines of seven numbers that are forces."""
    biggest = _head_moduli(head)
    return biggest is not None and looks_like_forces(biggest)


def _head_moduli(head: bytes) -> np.ndarray | None:
    """Largest MOD of each mode 1-6 over the complete seven-number lines of ``head``; None unless its
    first line is seven numbers."""
    lines = head.decode("utf-8", errors="replace").splitlines()
    if len(head) >= 4096 and lines:
        lines = lines[:-1]  # the last line may be cut
    biggest = np.zeros(RIGID_MODES)
    first = True
    for line in lines:
        parts = line.split()
        if not parts:
            continue
        try:
            numbers = [float(part) for part in parts]
        except ValueError:
            return None if first else biggest
        if len(numbers) != 7:
            return None if first else biggest
        first = False
        mode = int(numbers[2]) if numbers[2].is_integer() else 0
        if 1 <= mode <= RIGID_MODES and math.isfinite(numbers[3]):
            biggest[mode - 1] = max(biggest[mode - 1], abs(numbers[3]))
    return None if first else biggest


class Settings:
    """What the files beside a WAMIT output say about it: g and ULEN (``.gdf``), the kind of the PER
    column and the header lines (``.cfg``), the water depth (``.pot``)."""

    def __init__(self, g: float, ulen: float, period_kind: int, period_key: str, header_lines: int,
                 depth: float, notes: tuple[str, ...], xbody: tuple[float, float, float, float] = (0.0,) * 4,
                 placed_by: str = "", body: int = 1, bodies: int = 1, headings: tuple[float, ...] | None = None
                 ) -> None:
        self.g, self.ulen, self.period_kind, self.period_key = g, ulen, period_kind, period_key
        self.header_lines, self.depth, self.notes = header_lines, depth, notes
        self.xbody, self.placed_by = xbody, placed_by
        self.body, self.bodies, self.headings = body, bodies, headings

    @property
    def mode_offset(self) -> int:
        """How many modes come before the body's surge in the files (6 per body before it)."""
        return RIGID_MODES * (self.body - 1)

    @classmethod
    def beside(cls, path: Path, *, ulen: float | None = None, period_kind: int | None = None,
               body: str | None = None) -> "Settings":
        notes: list[str] = []
        g, gdf_ulen = _gdf_settings(path.with_suffix(".gdf"))
        if ulen is None:
            ulen = gdf_ulen
            if ulen is None:
                ulen = 1.0
                notes.append("ULEN not found (no .gdf beside the file): assumed 1 m; check the pitch "
                             "and roll long-wave limits")
        require_within("WAMIT ULEN", ulen, *ULEN_RANGE_M, "m")
        cfg = path.with_suffix(".cfg")
        keys = read_cfg(cfg)
        key = "option"
        if period_kind is None:
            period_kind, key = output_period_kind(cfg, keys)
        if period_kind not in PERIOD_KINDS:
            where = f"{cfg}: {key} {period_kind}" if key != "option" else f"WAMIT IPEROUT {period_kind}"
            raise ParameterError(f"{where} is not supported (supported: "
                                 + ", ".join(f"{k} = {v}" for k, v in PERIOD_KINDS.items()) + ")")
        header = 0
        if "NUMHDR" in keys:
            number, value = keys["NUMHDR"]
            header = parse_int(cfg, number, value, "NUMHDR (0 or 1)")
            if header not in (0, 1):
                raise FileFormatError(cfg, number, f"NUMHDR must be 0 or 1, got {header}")
        pot = pot_beside(path) or Pot(math.nan)
        number = _body_number(path, pot, body)
        xbody = pot.bodies[number - 1].xbody if pot.bodies else (0.0,) * 4
        if len(pot.bodies) > 1 or number > 1:
            first = RIGID_MODES * (number - 1) + 1
            name = f" ({pot.bodies[number - 1].gdf})" if pot.bodies else ""
            notes.append(f"body {number}{name} of a run of {len(pot.bodies) or 'several'} bodies: its modes "
                         f"{first}-{first + RIGID_MODES - 1}")
        return cls(g, ulen, period_kind, key, header, pot.depth, tuple(notes), xbody, path.with_suffix(".pot").name,
                   number, max(len(pot.bodies), number), pot.headings)

    def check_headings(self, path: Path, headings: np.ndarray) -> None:
        """Refuse headings (deg) of ``path`` other than those the run's ``.pot`` lists (where it lists them)."""
        if not self.headings:
            return
        listed = np.array(self.headings, float)
        missing = [h for h in listed if not np.isclose(headings, h, atol=1e-6).any()]
        extra = [h for h in headings if not np.isclose(listed, h, atol=1e-6).any()]
        if missing or extra:
            words = ([f"lacks heading(s) {', '.join(f'{h:g}' for h in missing)} deg"] if missing else []) + (
                [f"has heading(s) {', '.join(f'{h:g}' for h in extra)} deg"] if extra else [])
            raise FileFormatError(path, None, " and ".join(words) + f" against the {len(listed)} the run's "
                                  f"{self.placed_by} lists (a cut file, or a file of another run?)")

    def omega(self, per: np.ndarray, path: Path) -> np.ndarray:
        """The wave frequencies (rad/s) of the PER column ``per`` (> 0) of ``path``."""
        if self.period_kind == 1:
            return 2.0 * math.pi / per
        if self.period_kind == 2:
            return per.copy()
        wavenumber = per / self.ulen  # 1/m
        if self.period_kind == 3:
            return np.sqrt(self.g * wavenumber)
        if math.isnan(self.depth):
            raise FileFormatError(path, None, f"PER is the finite-depth wavenumber ({self.period_key} = 4): "
                                              f"the water depth is needed and no {path.with_suffix('.pot').name} "
                                              "beside the file gives it")
        return np.sqrt(self.g * wavenumber * np.tanh(wavenumber * self.depth))

    def describe(self) -> str:
        depth = {True: f"{self.depth:g} m", False: "infinite"}[math.isfinite(self.depth)]
        if math.isnan(self.depth):
            depth = "not given (no .pot): infinite assumed"
        return (f"PER column read as {PERIOD_KINDS[self.period_kind]} ({self.period_key}), ULEN = {self.ulen:g} m, "
                f"g = {self.g:g} m/s^2, water depth {depth}")


def _body_number(path: Path, pot: Pot, body: str | None) -> int:
    """The number (from 1) of the body ``body`` names (its number, or its ``.gdf`` file's name with or without
    ``.gdf``) among the ``.pot``'s; 1 for a run of one body. A run of several needs it named."""
    names = [b.gdf for b in pot.bodies]
    listed = ", ".join(f"{n} ({name})" for n, name in enumerate(names, 1))
    if body is None:
        if len(names) > 1:
            raise FileFormatError(path, None, f"a run of {len(names)} bodies, {listed} in "
                                              f"{path.with_suffix('.pot').name}: name the one whose motions to read "
                                              "(marinesim rao --body, [vessel] rao_body)")
        return 1
    if body.strip().isdigit():
        number = int(body)
        if number >= 1 and (not names or number <= len(names)):
            return number
    else:
        number = next((n for n, b in enumerate(pot.bodies, 1) if b.names(Path(body).with_suffix(".gdf"))), 0)
        if number:
            return number
    if len(names) == 1:
        raise FileFormatError(path, None, f"the run holds one body: a body ({body!r}) is for runs of several")
    known = f"the bodies of {path.with_suffix('.pot').name} are {listed}" if names else (
        f"without {path.with_suffix('.pot').name} beside the file, a body is named by its number 1, 2, ...")
    raise FileFormatError(path, None, f"no body {body!r}: {known}")


def output_period_kind(cfg: Path, keys: dict[str, tuple[int, str]] | None = None) -> tuple[int, str]:
    """(kind, the key that set it) of the PER column of WAMIT's outputs: ``IPEROUT``, else ``IPERIO`` (which
    sets input and output alike in v6 and v7), else WAMIT's default 1 (period)."""
    keys = read_cfg(cfg) if keys is None else keys
    for key in ("IPEROUT", "IPERIO"):
        if key in keys:
            number, value = keys[key]
            return parse_int(cfg, number, value, f"{key} (1..4)"), key
    return 1, "default"


def _gdf_settings(gdf: Path) -> tuple[float, float | None]:
    """(g, ULEN) from the ``.gdf`` beside the file; (G, None) if there is none."""
    if not gdf.is_file():
        return G, None
    header = read_gdf_header(gdf)
    return header.g, header.ulen


def frc_rho(frc: Path) -> float | None:
    """RHO of the ``.frc`` beside the file (IALTFRC 2), or None without one or in form 1 (no RHO there)."""
    if not frc.is_file():
        return None
    return read_frc(frc, frc_form(frc.with_suffix(".cfg"))).rho


def frc_form(cfg: Path) -> int | None:
    """IALTFRC from the ``.cfg`` (None without one: :func:`read_frc` tells it from the layout)."""
    keys = read_cfg(cfg)
    if "IALTFRC" not in keys:
        return None
    number, value = keys["IALTFRC"]
    return parse_int(cfg, number, value, "IALTFRC (1 or 2)")
