"""The Kelvin wake of a hull at a speed: A(theta), wave resistance and the field, with their grid.

Frames and units: the field is the steady free-surface elevation (m) in the vessel frame of
CONVENTIONS (x forward, y to port, origin at the hull's origin on the waterline), on a grid of
``nx`` columns along x and ``ny`` rows across y, as an array ``elevation[row(y), column(x)]``.
By default the grid starts a few cells ahead of the bow and reaches back ``nx`` cells of
``spacing = lambda0 / 16`` (lambda0 = 2 pi U^2 / g, the transverse wavelength), coarser only
when that would not reach three hull lengths, and never above lambda0 / 4. The waves (``elevation``) come
from A(theta); the local flow about the hull (``local``: the water raised at the stem and the stern and lowered
along the shoulders, :mod:`marinesim.wake.local`) is kept apart on the same grid, for the renderer to add.
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from marinesim import __version__
from marinesim.atomic import atomic_path
from marinesim.constants import G, KNOT, RHO_SEAWATER
from marinesim.errors import (FileFormatError, MarinesimError, ParameterError, require_at_least, require_memory,
                              require_positive)
from marinesim.hull import Hull, Hydrostatics, hydrostatics
from marinesim.wake.amplitude import (hull_reach, resistance_from_amplitude, resistance_quadrature, tuck_amplitude,
                                      wavenumber)
from marinesim.wake.field import wake_spectrum
from marinesim.wake.local import local_flow
from marinesim.wake.measure import kelvin_half_angle_deg, transverse_wavelength

MAX_SPEEDS = 40
"""The most different speeds one call or scenario precomputes: one a knot up to a fast ship's 40 kn."""
CELLS_PER_WAVELENGTH = 16
AHEAD_CELLS = 8
MIN_FROUDE = 0.03  # below: waves of a few cm, costly (nodes grow as 1 / Fn^2) and outside thin-ship theory
QUALITATIVE_BELOW_FROUDE = 0.1  # thin-ship waves of blunt and transom hulls are far too large below
THIN_SHIP_MAX_BEAM_LENGTH = 0.15
"""Largest waterline beam / length for which the wave resistance is reported without a caveat (thin_ship_note)."""
THIN_SHIP_MAX_BLOCK_COEFFICIENT = 0.7
"""Largest block coefficient V / (L B T) reported without a caveat (:func:`thin_ship_note`)."""
PLOTTED_ANGLES = 400  # A(theta) samples kept in the result, for plots
BYTES_PER_CELL = 60
"""Memory per grid cell: the field's half and whole (float64), the fade, the float32 copies, the local flow sampled
and the measurements' work."""
WAKE_FORMAT = 4
"""Version of the wake's numerics and of its file (``info["wake_format"]``): bumped whenever either changes."""


@dataclass(frozen=True)
class WakeGrid:
    """Grid size and, optionally, spacing (m) and how far ahead of the origin it starts (m)."""

    nx: int = 2048  # along the track
    ny: int = 1024  # across
    spacing_m: float | None = None
    front_m: float | None = None  # x of the first column (default: the bow plus AHEAD_CELLS cells)

    def resolved(self, wavelength: float, hull_length: float, bow_x: float) -> "WakeGrid":
        """This grid with spacing and front filled in for a transverse wavelength and a hull."""
        nx, ny = (int(require_at_least(n, v, 16)) for n, v in (("nx", self.nx), ("ny", self.ny)))
        spacing = self.spacing_m
        if spacing is None:
            spacing = min(max(wavelength / CELLS_PER_WAVELENGTH, 3.0 * hull_length / nx), wavelength / 4.0)
        spacing = require_positive("grid spacing", spacing)
        front = bow_x + AHEAD_CELLS * spacing if self.front_m is None else float(self.front_m)
        return replace(self, nx=nx, ny=ny, spacing_m=spacing, front_m=front)

    def axes(self) -> tuple[np.ndarray, np.ndarray]:
        """Column x (increasing, ending at the front) and row y (symmetric about 0), m."""
        x = self.front_m - self.spacing_m * np.arange(self.nx)[::-1]
        y = (np.arange(self.ny) - (self.ny - 1) / 2.0) * self.spacing_m
        return x, y


@dataclass
class Wake:
    """A computed wake: the waves and the local flow on its grid and the numbers that describe them."""

    elevation: np.ndarray  # (ny, nx) float32, m: the waves
    local: np.ndarray  # (ny, nx) float32, m: the local flow's elevation (0 where its grid does not reach)
    x: np.ndarray  # (nx,) m, vessel frame, forward
    y: np.ndarray  # (ny,) m, to port
    sec: np.ndarray  # sec(theta) samples of A, for plots
    amplitude: np.ndarray  # A(theta) there, complex, m
    info: dict = field(default_factory=dict)  # speed_m_s, froude, wave_resistance_N, ... (JSON-able)
    timings: dict = field(default_factory=dict)  # s per stage ("amplitude", "field") when computed; never saved

    def save(self, path: str | Path) -> None:
        """Write an ``.npz`` atomically: the arrays plus every entry of ``info`` (no timings: the same wake
        gives the same bytes)."""
        with atomic_path(path) as temp:
            with open(temp, "wb") as handle:
                np.savez_compressed(handle, elevation_m=self.elevation, local_m=self.local, x_m=self.x, y_m=self.y,
                                    sec_theta=self.sec,
                                    amplitude_m=self.amplitude, info_json=np.array(json.dumps(self.info)))

    @classmethod
    def load(cls, path: str | Path) -> "Wake":
        try:
            with np.load(path) as data:
                return cls(data["elevation_m"], data["local_m"], data["x_m"], data["y_m"], data["sec_theta"],
                           data["amplitude_m"], json.loads(str(data["info_json"])))
        except Exception as error:  # numpy, zipfile and zlib raise many kinds (even SyntaxError) for damaged files
            raise FileFormatError(path, None, f"not a marinesim wake file: {error}") from None


def compute_wake(hull: Hull, speed_m_s: float, grid: WakeGrid = WakeGrid(), *, rho: float = RHO_SEAWATER,
                 g: float = G, refinement: float = 1.0) -> Wake:
    """Tuck's A(theta), Michell's wave resistance, the far-field wake and the local flow of ``hull`` at
    ``speed_m_s``."""
    k0 = wavenumber(speed_m_s, g)
    wavelength = 2.0 * math.pi / k0
    statics = hydrostatics(hull, rho)
    froude = statics.froude(speed_m_s, g)
    if froude < MIN_FROUDE:
        raise ParameterError(f"Fn {froude:.3f} at {speed_m_s:.3g} m/s is below {MIN_FROUDE}: this hull makes "
                             "almost no waves so slowly, thin-ship theory does not describe them, and the "
                             "integral would take minutes")
    surface = hull.wetted()
    bow, stern = float(surface.corners[:, 0].max()), float(surface.corners[:, 0].min())
    grid = grid.resolved(wavelength, statics.froude_length_m, bow)
    require_memory(f"a wake grid of {grid.nx} x {grid.ny}", BYTES_PER_CELL * grid.nx * grid.ny)
    x, y = grid.axes()

    started = time.perf_counter()
    u, weights = resistance_quadrature(k0, hull_reach(surface))
    sec = np.cosh(u)
    a = tuck_amplitude(surface, k0, sec)
    resistance = resistance_from_amplitude(a, sec, weights, speed_m_s, rho)
    amplitude_seconds = time.perf_counter() - started

    started = time.perf_counter()
    spectrum = wake_spectrum(surface, k0, float(np.abs(x).max()), float(np.abs(y).max()), grid.spacing_m,
                             refinement)
    elevation = spectrum.on_grid(x, y) * _bow_fade(x, bow, stern)
    field_seconds = time.perf_counter() - started

    started = time.perf_counter()
    local = local_flow(surface, speed_m_s, g).sample(x, y) * _front_taper(x, grid)[None, :]
    local_seconds = time.perf_counter() - started

    info = {
        "speed_m_s": speed_m_s, "speed_kn": speed_m_s / KNOT, "froude": froude, "k0_per_m": k0,
        "transverse_wavelength_m": wavelength, "wave_resistance_N": resistance,
        "wave_resistance_coefficient": resistance / (0.5 * rho * speed_m_s**2 * statics.wetted_area_m2),
        "kelvin_half_angle_deg": None, "measured_transverse_wavelength_m": None,
        "rho_kg_m3": rho, "g_m_s2": g, "length_m": statics.froude_length_m, "wetted_area_m2": statics.wetted_area_m2,
        "grid": {"nx": grid.nx, "ny": grid.ny, "spacing_m": grid.spacing_m, "front_m": grid.front_m},
        "bow_x_m": bow, "stern_x_m": stern,
        "quadrature_nodes": len(spectrum.kx), "refinement": refinement, "hull_source": hull.source,
        "hull_sha256": hull.content_hash(), "wake_format": WAKE_FORMAT, "marinesim_version": __version__,
    }
    for key, measure in (("kelvin_half_angle_deg", lambda: kelvin_half_angle_deg(
                             elevation, x, y, wavelength, statics.froude_length_m, bow)),
                         ("measured_transverse_wavelength_m", lambda: transverse_wavelength(
                             elevation, x, y, statics.froude_length_m))):
        try:
            info[key] = measure()
        except MarinesimError as error:
            info["measurement_note"] = " ".join(filter(None, [info.get("measurement_note"), str(error)]))
    if froude < QUALITATIVE_BELOW_FROUDE:
        info["validity_note"] = (f"below Fn {QUALITATIVE_BELOW_FROUDE} thin-ship theory overpredicts the waves of a "
                                 "blunt or transom-sterned hull many times over: treat this field as qualitative")
    if x.min() > stern:
        info["grid_note"] = "the grid ends before the stern: give more columns (nx) or a larger spacing"
    kept = slice(None, None, max(1, len(sec) // PLOTTED_ANGLES))
    return Wake(elevation.astype(np.float32), local.astype(np.float32), x, y, sec[kept], a[kept], info,
                {"amplitude": amplitude_seconds, "field": field_seconds, "local": local_seconds})


def thin_ship_note(statics: Hydrostatics) -> str | None:
    """A note when the hull is outside thin-ship validity, else None: waterline beam / length above
    :data:`THIN_SHIP_MAX_BEAM_LENGTH` or block coefficient ``Cb = V / (L B T)`` (L, B at the waterline, T the
    draft; m, m^3) above :data:`THIN_SHIP_MAX_BLOCK_COEFFICIENT`. None for a body that does not cross the
    waterline (no waterline beam to judge by). ``marinesim wake`` reports it from the hull, so it is not kept in
    the wake's ``info`` (a cached wake would otherwise lack it).

    Source: Michell's integral (Michell 1898, Phil. Mag. (5) 45, 106-123) linearises the hull boundary
    condition about the centreplane, so it needs hull slopes ``dY/dx`` small: a thin ship, B/L -> 0 (Tuck
    1989, J. Austral. Math. Soc. Ser. B 30, 365-377, who finds it "quite reasonable as an engineering tool"
    for slender hulls). No published paper we found gives a sharp limit; the two numbers are marinesim's
    choice: the hulls thin-ship results are usually compared with in tanks are slender and fine, Wigley's
    (B/L 0.10, Cb 0.44) and Series 60 (B/L 0.133 at Cb 0.60), so B/L 0.15 is just above them; Cb 0.7 is
    the usual boundary between moderate and full forms, whose blunt bows (hull slopes of order one) are the
    opposite of Michell's assumption. Outside them marinesim's own numbers are implausible: Cw 0.057 for a
    box barge and 0.099 at B/L 0.5, tens of times the order 1e-3 of real hulls.
    """
    length, beam, draft = statics.waterline_length_m, statics.waterline_beam_m, statics.draft_m
    if length <= 0.0 or beam <= 0.0 or draft <= 0.0:
        return None
    ratio = beam / length
    block = statics.volume_m3 / (length * beam * draft)
    outside = []
    if ratio > THIN_SHIP_MAX_BEAM_LENGTH:
        outside.append(f"B/L {ratio:.3g} > {THIN_SHIP_MAX_BEAM_LENGTH:g}")
    if block > THIN_SHIP_MAX_BLOCK_COEFFICIENT:
        outside.append(f"block coefficient {block:.3g} > {THIN_SHIP_MAX_BLOCK_COEFFICIENT:g}")
    if not outside:
        return None
    return (f"this hull is outside thin-ship validity ({' and '.join(outside)}): Michell's wave resistance and "
            "the wake assume a thin, fine hull and may be many times too large; treat them as qualitative")


def _bow_fade(x: np.ndarray, bow: float, stern: float) -> np.ndarray:
    """0 ahead of the bow, rising smoothly to 1 at the stern: the far-field form holds behind the hull."""
    r = np.clip((bow - x) / max(bow - stern, 1e-9), 0.0, 1.0)
    return r * r * (3.0 - 2.0 * r)


def _front_taper(x: np.ndarray, grid: WakeGrid) -> np.ndarray:
    """1 from :data:`AHEAD_CELLS` cells inside the grid's front edge, falling smoothly to 0 at it: the water the
    bow raises ahead goes to the still level there, not in a step."""
    r = np.clip((grid.front_m - x) / (AHEAD_CELLS * grid.spacing_m), 0.0, 1.0)
    return r * r * (3.0 - 2.0 * r)
