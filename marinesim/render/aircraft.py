"""The helicopter as drawn: a medium offshore helicopter after the Sikorsky S-92, made of the ship kit's parts
(:mod:`~marinesim.render.ship_kit`), and its lights.

Dimensions (S-92A): main rotor diameter 17.17 m, four blades; fuselage length 17.32 m; overall length with the rotors
turning 20.85 m (Sikorsky's figures as Aeropedia lists them); height 4.71 m, here to the top of the rotor head; tail
rotor 3.35 m across, four blades, on the right of the pylon, the horizontal stabiliser low on the right ahead of it.
Wheels, not skids: a twin nose wheel and the main wheels under the sponsons, 3.1 m apart. An offshore operator's
livery: white over a blue belly, an orange cheat line and tail.

Body frame: x forward, y to port, z up (m), the origin at the bottom of the wheels, midway between the nose wheels
and the main wheels (the point :mod:`marinesim.offshore.helicopter` samples). The rotor blades are drawn stopped, each
45 deg off the fuselage's axis; the renderer culls back faces, so each part is closed and faces outwards.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from marinesim.render import ship_kit as kit
from marinesim.render.nav_lights import GREEN, RED, WHITE, NavLight, luminous_intensity_cd
from marinesim.render.vessel_mesh import VesselMesh, part_mesh

ROTOR_DIAMETER_M = 17.17
FUSELAGE_LENGTH_M = 17.32
OVERALL_LENGTH_M = 20.85
"""Rotors turning: from the main rotor's disc ahead to the tail rotor's disc astern."""
HEIGHT_M = 4.71
TAIL_ROTOR_DIAMETER_M = 3.35
LIVERY_BLUE = (22, 58, 132)
LIVERY_ORANGE = (236, 104, 24)
ROTOR_GREY = (86, 88, 92)
TYRE = kit.BLACK

HUB_X = -2.2
"""The main rotor's mast from the origin (m): the nose wheels 5.4 m ahead of the mast, the main wheels 1.0 m abaft.
The parts are laid out from the mast and moved by this much."""
TAIL_ROTOR = np.array([-9.75, -0.42, 3.0])
"""The tail rotor's hub from the mast (m): on the pylon's right side."""

FUSELAGE_STATIONS = np.array([  # x from the mast, the section's centre height, half-breadth, half-height (m)
    (6.75, 1.45, 0.06, 0.06), (6.66, 1.47, 0.32, 0.29), (6.45, 1.52, 0.55, 0.50), (6.10, 1.59, 0.80, 0.70),
    (5.70, 1.66, 0.98, 0.84), (5.15, 1.73, 1.10, 0.94), (4.50, 1.80, 1.20, 1.02),
    (3.00, 1.85, 1.25, 1.10), (-3.40, 1.85, 1.25, 1.10), (-5.00, 2.05, 1.02, 0.86), (-6.60, 2.35, 0.55, 0.48),
    (-9.40, 2.62, 0.32, 0.34), (-10.40, 2.78, 0.24, 0.28)])
"""The fuselage's sections from the nose to the tail boom's end: the cockpit, the cabin (2.5 m wide outside, its
floor 0.75 m over the ground), the rear ramp rising to the boom."""
SECTION_SIDES = 24
SQUARENESS = 2.6
"""The sections' superellipse exponent: 2 an ellipse, higher a boxier cabin."""

INTENSITY_CD = {"navigation": 40.0, "tail": 20.0, "anti-collision": 150.0, "landing": 100_000.0}
"""Luminous intensities (cd): the position lights' minimum ahead and astern (14 CFR 29.1391, 29.1393), the
anti-collision light's minimum (29.1401), and an assumed 100 000 cd for the landing light's beam."""


def helicopter_parts() -> list[kit.Part]:
    """The helicopter's closed parts (body frame, m; colours 0..255)."""
    parts = [_fuselage()]
    parts += [kit.ellipsoid((-0.6, side * 0.62, 3.02), (1.7, 0.48, 0.42), kit.WHITE) for side in (1.0, -1.0)]  # engines
    parts.append(kit.box((-2.1, -0.78, 2.6), (1.7, 0.78, 3.35), kit.WHITE))                               # roof fairing
    parts.append(kit.cylinder((0.0, 0.0, 3.3), (0.0, 0.0, 4.45), 0.22, kit.STEEL))                          # mast
    parts.append(kit.cylinder((0.0, 0.0, 4.3), (0.0, 0.0, HEIGHT_M), 0.45, ROTOR_GREY, sections=16))        # head
    radius = ROTOR_DIAMETER_M / 2.0
    for k in range(4):
        a = math.radians(45.0 + 90.0 * k)
        tip = (radius * math.cos(a), radius * math.sin(a), 4.5)
        parts.append(kit.beam((0.3 * math.cos(a), 0.3 * math.sin(a), 4.5), tip, 0.53, ROTOR_GREY, height=0.1))
    for side in (1.0, -1.0):
        parts.append(kit.ellipsoid((-1.0, side * 1.38, 1.0), (1.9, 0.55, 0.42), LIVERY_BLUE))                 # sponson
        parts.append(kit.cylinder((-1.0, side * 1.4, 0.42), (-1.0, side * 1.7, 0.42), 0.42, TYRE, sections=16))
        parts.append(kit.beam((-1.0, side * 1.3, 0.42), (-1.0, side * 1.3, 0.9), 0.16, kit.STEEL))
        parts.append(kit.cylinder((5.4, side * 0.08, 0.3), (5.4, side * 0.26, 0.3), 0.3, TYRE, sections=12))
    parts.append(kit.beam((5.4, 0.0, 0.3), (5.4, 0.0, 0.9), 0.14, kit.STEEL))                             # nose leg
    parts += _windows()
    parts.append(kit.beam((-9.25, 0.0, 2.45), (-10.0, 0.0, 4.1), 0.28, LIVERY_ORANGE, height=1.0))     # pylon
    parts.append(kit.beam((-7.5, 0.0, 2.6), (-7.5, -2.1, 2.6), 0.9, LIVERY_ORANGE, height=0.14))        # stabiliser
    parts.append(kit.cylinder(TAIL_ROTOR + (0.0, 0.2, 0.0), TAIL_ROTOR - (0.0, 0.1, 0.0), 0.16, ROTOR_GREY))
    for k in range(4):
        a = math.radians(45.0 + 90.0 * k)
        tip = TAIL_ROTOR + TAIL_ROTOR_DIAMETER_M / 2.0 * np.array([math.cos(a), 0.0, math.sin(a)])
        parts.append(kit.beam(TAIL_ROTOR, tip, 0.3, ROTOR_GREY, height=0.06, up=(0.0, 1.0, 0.0)))
    return [kit.closed(p.solid(), "helicopter part").moved((HUB_X, 0.0, 0.0)) for p in parts]


def helicopter_mesh() -> VesselMesh:
    """The helicopter as the vessel pass draws it: flat-shaded triangles (body frame, m), colours 0..1."""
    return part_mesh(kit.join(helicopter_parts()))


def helicopter_lights() -> tuple[NavLight, ...]:
    """The helicopter's lights as the navigation lights pass takes a ship's (body frame, m; sectors as bearings
    relative to the nose, positive to port): the position lights (14 CFR 29.1387: red to port and green to starboard
    each over 110 deg from ahead, white astern over 140 deg), the red anti-collision beacons above and below the
    fuselage (all round) and the landing light under the nose (a 20 deg beam ahead)."""
    reach = {name: range_for_intensity_nm(cd) for name, cd in INTENSITY_CD.items()}
    return (NavLight("anti-collision upper", (HUB_X - 3.3, 0.0, 3.02), RED, (0.0, 360.0), reach["anti-collision"]),
            NavLight("anti-collision lower", (HUB_X - 1.0, 0.0, 0.74), RED, (0.0, 360.0), reach["anti-collision"]),
            NavLight("port position", (HUB_X - 1.0, 1.94, 1.0), RED, (0.0, 110.0), reach["navigation"]),
            NavLight("starboard position", (HUB_X - 1.0, -1.94, 1.0), GREEN, (-110.0, 0.0), reach["navigation"]),
            NavLight("tail position", (HUB_X - 10.45, 0.0, 2.8), WHITE, (110.0, 250.0), reach["tail"]),
            NavLight("landing", (HUB_X + 5.9, 0.0, 0.85), WHITE, (-10.0, 10.0), reach["landing"]))


def range_for_intensity_nm(intensity_cd: float) -> float:
    """The range (nm) whose COLREG Annex I intensity (:func:`.nav_lights.luminous_intensity_cd`) is
    ``intensity_cd``: how a light of that intensity is given to the navigation lights pass."""
    return brentq(lambda d: luminous_intensity_cd(d) - intensity_cd, 1e-3, 100.0, xtol=1e-12)


def _fuselage() -> kit.Part:
    """The fuselage lofted through :data:`FUSELAGE_STATIONS`, closed at both ends and painted: blue belly, orange
    cheat line, white above, the windscreen dark."""
    a = 2.0 * np.pi * np.arange(SECTION_SIDES) / SECTION_SIDES
    c, s = np.cos(a), np.sin(a)
    shape_y = np.sign(c) * np.abs(c) ** (2.0 / SQUARENESS)
    shape_z = np.sign(s) * np.abs(s) ** (2.0 / SQUARENESS)
    rings = [np.c_[np.full(SECTION_SIDES, x), half_y * shape_y, z + half_z * shape_z]
             for x, z, half_y, half_z in FUSELAGE_STATIONS]
    n, k = SECTION_SIDES, len(rings)
    ends = [(x, 0.0, z) for x, z, _, _ in FUSELAGE_STATIONS[[0, -1]]]
    v = np.concatenate(rings + [np.array(ends)])
    i, j = np.arange(n), (np.arange(n) + 1) % n
    faces = []
    for ring in range(k - 1):  # the rings run aft; counter-clockwise seen from ahead, so each band faces outwards
        a0, b0, a1, b1 = ring * n + i, ring * n + j, (ring + 1) * n + i, (ring + 1) * n + j
        faces += [np.c_[a0, a1, b1], np.c_[a0, b1, b0]]
    nose, tail = k * n, k * n + 1
    faces += [np.c_[np.full(n, nose), i, j], np.c_[np.full(n, tail), (k - 1) * n + j, (k - 1) * n + i]]
    part = kit.Part.of(v, np.concatenate(faces), kit.WHITE)
    return part.painted(_livery)


def _livery(centres: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """The fuselage's paint by face (RGB 0..255): the windscreen over the cockpit's front, blue below 1.25 m, an
    orange line to 1.5 m, white above."""
    out = np.empty((len(centres), 3))
    out[:] = kit.WHITE
    out[centres[:, 2] < 1.5] = LIVERY_ORANGE
    out[centres[:, 2] < 1.25] = LIVERY_BLUE
    windscreen = (centres[:, 0] > 4.4) & (centres[:, 2] > 1.75) & (normals[:, 0] > 0.15)
    out[windscreen] = kit.WINDOW
    return out


def _windows() -> list[kit.Part]:
    """The cockpit's side windows and five cabin windows a side: dark panes standing 3 cm proud of the skin."""
    half = 1.25 * 0.985  # the cabin's half-breadth at the window line (the superellipse near its widest)
    panes = []
    for side in (1.0, -1.0):
        y = sorted((side * (half - 0.05), side * (half + 0.03)))
        panes.append(kit.box((3.6, y[0], 2.0), (4.5, y[1], 2.55), kit.WINDOW))
        for x in np.linspace(-2.6, 2.0, 5):
            panes.append(kit.box((x - 0.3, y[0], 1.75), (x + 0.3, y[1], 2.3), kit.WINDOW))
    return panes
