"""Writes four procedural, vertex-coloured visual meshes for the vessels in rao/: hulls/s175_visual.glb (the S175
container ship), hulls/semisub_visual.glb (the WAMIT semisubmersible), hulls/supply_visual.glb (the VERES
offshore supply vessel) and hulls/tanker_visual.glb (the WAMIT tanker, whose hydrodynamic hull is only its wetted
surface).

Each is written in the body frame of its RAO file (docs/CONVENTIONS.md): x forward, y to port, z up, metres,
origin at the RAO reference point, so a scenario needs only ``visual_mesh = "../hulls/NAME.glb"``. The two
VERES ships are drawn in the shipyard's frame (x from midships, z above the baseline) and moved by their
reference point (XMTN, 0, ZMTN) as marinesim's reader reports it; the semisubmersible's WAMIT origin is on the
waterline. Faces are counter-clockwise seen from outside (checked on every closed part), each face one colour.
The parts, the deckhouses and the colours are the package's ship kit (:mod:`marinesim.render.ship_kit`), from which
the viewer also draws a ship given only its hull; this script, which does not travel with the package, adds the
hull lines and the four vessels.

Run from the repository root: python hulls/make/visual_ships.py
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh

from marinesim.render.ship_kit import (ANTIFOULING, BLACK, BOOT_TOP, COLUMN_YELLOW, CONTAINER_COLOURS, CRANE_YELLOW,
                                      DECK_GREEN, DECK_GREY, DERRICK_RED, FUNNEL, HELIDECK_GREEN, LIFEBOAT, MARK_YELLOW,
                                      NAVY, SHIP_RED, STEEL, TIMBER, WHITE, WINDOW, Part, annulus, beam, box, by_height,
                                      closed, cylinder, decks_with_windows, ellipsoid, join, lattice, polygon, prism,
                                      rounded_rectangle, tiered, wheelhouse_interior)
from marinesim.vessel import read_rao

HERE = Path(__file__).resolve().parents[1]  # hulls/: the script lives in hulls/make/, outside the wheel
RAO = HERE.parent / "rao"


# ----------------------------------------------------------------------------------------------- the file

def write_glb(part: Part, path: Path) -> None:
    """One mesh, vertex-coloured: vertices are split where faces of different colours meet, so every face
    shows its own colour (faces of one colour keep sharing theirs)."""
    solid = part.solid()  # degenerate triangles (collapsed sections) dropped
    f, c = solid.f, solid.c
    vertices, faces, colours = [], [], []
    count = 0
    keys = c[:, 0].astype(np.int64) << 16 | c[:, 1].astype(np.int64) << 8 | c[:, 2]
    for key in np.unique(keys):
        group = f[keys == key]
        used, inverse = np.unique(group, return_inverse=True)
        vertices.append(part.v[used])
        faces.append(inverse.reshape(-1, 3) + count)
        colours.append(np.tile([(key >> 16) & 255, (key >> 8) & 255, key & 255, 255], (len(used), 1)))
        count += len(used)
    mesh = trimesh.Trimesh(np.concatenate(vertices).astype(np.float32), np.concatenate(faces),
                           vertex_colors=np.concatenate(colours).astype(np.uint8), process=False)
    mesh.export(path)
    print(f"{path.name}: {len(mesh.faces)} triangles, {path.stat().st_size / 1e6:.2f} MB, "
          f"x {mesh.bounds[0, 0]:.1f}..{mesh.bounds[1, 0]:.1f}, y {mesh.bounds[0, 1]:.1f}..{mesh.bounds[1, 1]:.1f}, "
          f"z {mesh.bounds[0, 2]:.1f}..{mesh.bounds[1, 2]:.1f} m (body frame)")


# ----------------------------------------------------------------------------------------------- ship hulls

def hull_from_sections(sections: Sequence[np.ndarray], side_colours, deck_rgb) -> Part:
    """A closed hull from port-side sections, aft to forward: each (k, 3) runs from the keel on the
    centreline (y = 0) round the bilge and up the side to the deck edge, all with the same k. The starboard side
    is the mirror image; the deck joins the deck edges; the first and last sections are closed with flat ends
    (the transom; a stem that ends in a point adds nothing). ``side_colours`` paints the sides (a
    :func:`by_height` painter)."""
    port = np.asarray(sections, float)
    n, k = port.shape[:2]
    starboard = port * (1.0, -1.0, 1.0)
    v = np.concatenate([port.reshape(-1, 3), starboard.reshape(-1, 3)])
    idx = np.arange(n * k).reshape(n, k)
    sb = idx + n * k
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]  # a -> b forward, a -> d up the girth
    side = [np.c_[a.ravel(), d.ravel(), c.ravel()], np.c_[a.ravel(), c.ravel(), b.ravel()]]
    a, b, c, d = sb[:-1, :-1], sb[1:, :-1], sb[1:, 1:], sb[:-1, 1:]
    side += [np.c_[a.ravel(), b.ravel(), c.ravel()], np.c_[a.ravel(), c.ravel(), d.ravel()]]
    top_p, top_s = idx[:, -1], sb[:, -1]
    deck = [np.c_[top_p[:-1], top_s[1:], top_p[1:]], np.c_[top_p[:-1], top_s[:-1], top_s[1:]]]
    ends = []
    for i, outward in ((0, -1.0), (n - 1, 1.0)):
        ring = np.r_[idx[i], sb[i][::-1]]
        centre = len(v) + len(ends)
        ends.append(v[ring].mean(axis=0))
        fan = np.c_[np.full(len(ring), centre), ring, np.roll(ring, -1)]
        tri = np.concatenate([v, ends])[fan]
        facing = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])[:, 0].sum()
        side.append(fan if facing * outward >= 0 else fan[:, ::-1])
    hull = Part.of(np.concatenate([v, ends]), np.concatenate(side), (0, 0, 0)).painted(side_colours)
    return closed(join([hull, Part.of(hull.v, np.concatenate(deck), deck_rgb)]), "hull")


def smoothstep(t):
    t = np.clip(t, 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


@dataclass
class ShipForm:
    """A ship's hull form in the shipyard's frame: x from midships (forward), z above the baseline, metres.

    Waterlines: full between ``midbody`` (aft end, forward end); forward of it the half-breadth at height z
    falls as 1 - t^p towards the stem, aft of it as w + (1 - w)(1 - t^p) towards the stern, where w is the
    transom's share of the beam at that height; p is interpolated over (keel, waterline, deck) from ``p_fwd`` and
    ``p_aft``. The stem: the keel rises from ``forefoot_x`` on a quarter ellipse to the waterline at ``lpp``/2,
    then rakes forward at ``rake_deg``. The stern: the keel rises from ``cutup_x`` to the transom's lower edge
    ``transom_z`` at ``transom_x``. Sections have a round bilge of ``bilge`` m amidships, rounder towards the ends
    but never rounder than the section is deep below the waterline (a square transom stays square).
    The deck is at ``depth``, raised by ``forecastle`` (height, from x) forward."""

    lpp: float
    beam: float
    draft: float
    depth: float
    midbody: tuple[float, float]
    p_fwd: tuple[float, float, float]
    p_aft: tuple[float, float, float]
    forefoot_x: float
    rake_deg: float
    cutup_x: float
    transom_x: float
    transom_z: float
    transom_share: float
    bilge: float
    forecastle: tuple[float, float]

    def deck_z(self, x):
        height, start = self.forecastle
        return self.depth + height * smoothstep((np.asarray(x, float) - start) / 1.5)

    def stem_x(self, z):
        """x of the stem (forward end of the waterline) at height z."""
        z = np.asarray(z, float)
        low = self.forefoot_x + (self.lpp / 2 - self.forefoot_x) * np.sqrt(1.0 - (1.0 - np.clip(z, 0, self.draft)
                                                                                   / self.draft) ** 2)
        return np.where(z <= self.draft, low, self.lpp / 2 + (z - self.draft) * math.tan(math.radians(self.rake_deg)))

    def stern_x(self, z):
        """x of the aft end of the waterline at height z (the transom above its lower edge)."""
        z = np.asarray(z, float)
        return np.where(z < self.transom_z, self.cutup_x - (self.cutup_x - self.transom_x)
                        * np.sqrt(np.clip(z, 0, None) / self.transom_z), self.transom_x)

    def keel_z(self, x):
        """Height of the hull's lowest point at x (0 on the flat keel, rising at both ends)."""
        x = np.asarray(x, float)
        table = np.linspace(0.0, self.deck_z(self.stem_top()), 400)
        fwd = np.interp(x, self.stem_x(table), table)
        aft = self.transom_z * np.clip((self.cutup_x - x) / (self.cutup_x - self.transom_x), 0, 1) ** 2
        return np.where(x > self.forefoot_x, fwd, np.where(x < self.cutup_x, aft, 0.0))

    def stem_top(self) -> float:
        return float(self.stem_x(self.depth + self.forecastle[0]))

    def half_breadth(self, x, z):
        """Half-breadth (m) of the hull at x and height z: the waterline's shape times the bilge's."""
        x, z = np.broadcast_arrays(np.asarray(x, float), np.asarray(z, float))
        levels = (0.0, self.draft, self.depth + self.forecastle[0])
        p_f, p_a = np.interp(z, levels, self.p_fwd), np.interp(z, levels, self.p_aft)
        x_a, x_f = self.midbody
        t_f = np.clip((x - x_f) / np.maximum(self.stem_x(z) - x_f, 1e-6), 0, 1)
        t_a = np.clip((x_a - x) / np.maximum(x_a - self.stern_x(z), 1e-6), 0, 1)
        share = self.transom_share * np.clip((z - self.transom_z) / (self.depth - self.transom_z), 0, 1) ** 0.35
        length = np.where(x > x_f, 1.0 - t_f ** p_f, np.where(x < x_a, share + (1 - share) * (1 - t_a ** p_a), 1.0))
        ends = np.clip(np.maximum((x - x_f) / (self.lpp / 2 - x_f), (x_a - x) / (x_a + self.lpp / 2)), 0, 1)
        b2 = self.beam / 2
        keel = self.keel_z(x)
        radius = np.minimum(self.bilge + (0.8 * b2 - self.bilge) * ends ** 1.5,  # no rounder than the section is
                            np.maximum(0.9 * (self.draft - keel), 0.05))              # deep below the waterline
        h = np.clip(z - keel, 0, None)
        bilge = np.where(h < radius, (b2 - radius + np.sqrt(np.clip(radius ** 2 - (radius - h) ** 2, 0, None))) / b2,
                         1.0)
        return b2 * np.clip(length, 0, 1) * bilge

    def sections(self, stations: np.ndarray, levels: np.ndarray) -> list[np.ndarray]:
        """Port sections at ``stations`` (x), each through the heights ``levels`` clipped to the hull there."""
        out = []
        for x in stations:
            z = np.clip(np.r_[levels, np.inf], self.keel_z(x), self.deck_z(x))
            y = self.half_breadth(np.full(z.shape, x), z)
            out.append(np.c_[np.full(len(z) + 1, x), np.r_[0.0, y], np.r_[z[0], z]])
        return out


def block_coefficient(form: ShipForm) -> float:
    """The form's displaced volume below its waterline over Lpp B T (the bulb and rudder not counted)."""
    x = np.linspace(form.transom_x, form.stem_top(), 1500)
    z = np.linspace(0.0, form.draft, 300)
    xx, zz = np.meshgrid(x, z)
    breadth = 2.0 * form.half_breadth(xx, zz) * (zz >= form.keel_z(xx))
    return float(np.trapezoid(np.trapezoid(breadth, z, axis=0), x) / (form.lpp * form.beam * form.draft))


def hull(form: ShipForm, levels: Sequence[float], paint, deck_rgb, step_mid: float = 3.0) -> Part:
    """The closed hull of ``form``, its stations dense at the ends, its heights through ``levels`` (keep the
    paint lines among them, so that each face is one colour)."""
    x_a, x_f = form.midbody
    stations = np.unique(np.round(np.r_[
        np.linspace(form.transom_x, form.cutup_x, 24), np.arange(form.cutup_x, x_f, step_mid),
        x_f + (form.stem_top() - x_f) * np.sin(np.linspace(0, np.pi / 2, 40)),
        form.forecastle[1] + np.array([-0.75, 0.0, 0.75, 1.5, 2.25])], 4))
    stations = stations[(stations >= form.transom_x) & (stations <= form.stem_top())]
    return hull_from_sections(form.sections(stations, np.asarray(levels, float)), paint, deck_rgb)


def deck_edge(form: ShipForm, x0: float, x1: float, inset: float, n: int = 40) -> np.ndarray:
    """Port deck edge from x0 to x1 (x, y, z), ``inset`` m inboard of the side."""
    x = np.linspace(x0, x1, n)
    z = form.deck_z(x)
    return np.c_[x, np.maximum(form.half_breadth(x, z) - inset, 0.0), z]


def rail(points: np.ndarray, height: float, thickness: float, rgb, both_sides: bool = True) -> Part:
    """A bulwark (thin wall) standing ``height`` on a polyline of deck points, mirrored to starboard."""
    walls = []
    for sign in ((1.0, -1.0) if both_sides else (1.0,)):
        p = points * (1.0, sign, 1.0)
        for a, b in zip(p[:-1], p[1:]):
            if np.linalg.norm(b - a) < 1e-6:
                continue
            mid_a, mid_b = a + (0, 0, height / 2), b + (0, 0, height / 2)
            walls.append(beam(mid_a, mid_b, thickness, rgb, height=height))
    return join(walls)


# ----------------------------------------------------------------------------------------------- S175

S175 = ShipForm(lpp=175.0, beam=25.4, draft=9.5, depth=15.4, midbody=(-6.0, 2.0), p_fwd=(1.4, 1.75, 2.5),
                p_aft=(1.15, 1.8, 3.4), forefoot_x=74.0, rake_deg=38.0, cutup_x=-68.0, transom_x=-91.0,
                transom_z=10.6, transom_share=0.84, bilge=3.6, forecastle=(2.6, 70.0))


def s175(reference: Sequence[float]) -> tuple[Part, dict[str, list[float]]]:
    """The S175 in the shipyard's frame (x from midships, z above the baseline) and its points there
    (``reference``, the RAO reference point, is not needed: everything is placed from the ship's lines)."""
    f = S175
    wl, boot = f.draft, f.draft + 1.6
    paint = by_height([(wl, ANTIFOULING), (boot, BOOT_TOP), (np.inf, NAVY)])
    levels = [0.0, 0.12, 0.4, 0.9, 1.6, 2.5, 3.6, 4.9, 6.3, 7.8, 9.0, wl, 10.3, boot, 12.6, 14.2, f.depth,
              f.depth + 1.3, f.depth + f.forecastle[0]]
    parts = [hull(f, levels, paint, DECK_GREEN)]
    parts.append(closed(ellipsoid((f.lpp / 2 - 1.0, 0.0, 4.2), (7.0, 2.5, 3.6), ANTIFOULING), "bulb"))
    parts.append(box((-89.8, -0.5, 1.2), (-85.6, 0.5, 7.2), ANTIFOULING))  # rudder
    deck = f.depth
    # container bays on hatch covers, forward of the accommodation to the forecastle
    rng = np.random.default_rng(175)
    bay_x = np.arange(-61.0, 68.0 - 13.5, 14.3)
    for x0 in bay_x:
        x1 = x0 + 13.3
        half = float(min(f.half_breadth(x0, deck), f.half_breadth(x1, deck))) - 1.1
        parts.append(box((x0, -half, deck), (x1, half, deck + 1.5), DECK_GREY))  # hatch cover and coaming
        rows = int(2 * (half - 0.3) // 2.5)
        tiers = 2 if x0 > 50 else 3
        for r in range(rows):
            y0 = -rows * 2.5 / 2 + r * 2.5 + 0.03
            height = tiers - (1 if rng.random() < 0.15 else 0)
            for t in range(height):
                z0 = deck + 1.5 + t * 2.6
                colour = CONTAINER_COLOURS[rng.integers(len(CONTAINER_COLOURS))]
                parts.append(box((x0 + 0.55, y0, z0), (x0 + 0.55 + 12.19, y0 + 2.44, z0 + 2.59), colour))
    # accommodation aft: four decks over the casing, the wheelhouse on top with its window band, wings to the sides
    front, aft = -66.5, -78.0
    parts.append(box((-84.0, -11.5, deck), (-62.5, 11.5, deck + 1.2), WHITE))  # casing and poop front
    parts.append(tiered(aft, front, -9.0, 9.0, deck, decks_with_windows(4, height=3.1), chamfer=1.5))
    bridge_floor = deck + 12.4
    glass = front + 1.0  # the wheelhouse front overhangs the house by a metre: the conning position 2 m behind it
    parts.append(tiered(front - 6.0, glass, -9.5, 9.5, bridge_floor, [(1.0, WHITE), (1.5, WINDOW), (0.6, WHITE)],
                        chamfer=1.0))
    parts.append(box((aft, -9.0, bridge_floor), (front - 6.0, 9.0, bridge_floor + 2.9), WHITE))  # chart room aft
    parts += wheelhouse_interior(glass, front - 5.9, np.arange(-7.8, 7.9, 1.2), 8.5, bridge_floor, (1.0, 2.5), 6.0,
                                 9.4)
    parts.append(box((front - 6.3, -9.8, bridge_floor + 3.1), (glass + 0.3, 9.8, bridge_floor + 3.4), WHITE))  # visor
    for sign in (1.0, -1.0):
        y0, y1 = sorted((sign * 9.5, sign * float(f.half_breadth(front - 1.0, deck)) + sign * 0.3))
        parts.append(box((front - 2.6, y0, bridge_floor - 0.4), (glass, y1, bridge_floor + 1.1), WHITE))  # wing
    # funnel: behind the accommodation, black top
    funnel = rounded_rectangle(-87.5, -80.0, -3.2, 3.2, 2.0)
    parts += [prism(funnel, deck, bridge_floor + 4.5, FUNNEL), prism(funnel, bridge_floor + 4.5,
                                                                            bridge_floor + 6.0, BLACK)]
    # masts: on the wheelhouse roof (yard, radar) and on the forecastle
    roof = bridge_floor + 3.4
    parts += [cylinder((front - 4.0, 0, roof), (front - 4.0, 0, roof + 8.0), 0.3, STEEL),
              beam((front - 4.0, -3.0, roof + 6.0), (front - 4.0, 3.0, roof + 6.0), 0.25, STEEL),
              box((front - 4.9, -2.2, roof + 3.0), (front - 3.1, 2.2, roof + 3.35), BLACK),
              cylinder((84.0, 0, deck + f.forecastle[0]), (84.0, 0, deck + f.forecastle[0] + 9.0), 0.35, STEEL)]
    # forecastle bulwark and breakwater
    edge = deck_edge(f, f.forecastle[1] + 1.5, f.stem_top() - 0.6, 0.15, 20)
    parts.append(rail(edge, 1.2, 0.3, WHITE))
    parts += [beam((f.forecastle[1] + 3.0, 0.0, deck + f.forecastle[0] + 0.9), (f.forecastle[1] + 1.6, sign * 8.0,
                   deck + f.forecastle[0] + 0.9), 0.3, WHITE, height=1.8) for sign in (1.0, -1.0)]
    eye = bridge_floor + 1.7
    points = {"bridge": [front - 1.0, 0.0, eye], "bridge_wing_stbd": [front - 1.3, -12.0, eye],
              "forecastle": [84.5, 0.0, deck + f.forecastle[0]], "forefoot": [f.lpp / 2 - 1.0, 0.0, 0.6],
              "bow_wl": [f.lpp / 2, 0.0, wl]}
    return join([closed(p, "part") for p in parts]), points


# ----------------------------------------------------------------------------------------------- supply vessel

SUPPLY = ShipForm(lpp=82.8, beam=19.2, draft=6.0, depth=7.8, midbody=(-24.0, 6.0), p_fwd=(1.7, 2.2, 3.2),
                  p_aft=(1.5, 3.5, 6.0), forefoot_x=30.0, rake_deg=18.0, cutup_x=-29.0, transom_x=-43.4,
                  transom_z=5.7, transom_share=0.95, bilge=1.6, forecastle=(2.8, 12.0))


def supply(reference: Sequence[float]) -> tuple[Part, dict[str, list[float]]]:
    """The platform supply vessel in the shipyard's frame; the crane is placed by body-frame numbers
    (``reference``: the RAO reference point in the shipyard's frame)."""
    f = SUPPLY
    wl, boot = f.draft, f.draft + 0.8
    paint = by_height([(wl, ANTIFOULING), (boot, BOOT_TOP), (np.inf, SHIP_RED)])
    levels = [0.0, 0.1, 0.35, 0.8, 1.4, 2.2, 3.2, 4.3, 5.2, wl, 6.4, boot, 7.3, f.depth, f.depth + 1.4,
              f.depth + f.forecastle[0]]
    parts = [hull(f, levels, paint, TIMBER, step_mid=2.0)]
    parts.append(closed(ellipsoid((f.lpp / 2 - 0.5, 0.0, 2.6), (3.4, 1.5, 2.0), ANTIFOULING), "bulb"))
    deck, fc = f.depth, f.depth + f.forecastle[0]
    # forecastle bulwark and the forward mast (navigation lights; seen from the bridge over the bow)
    fc_edge = deck_edge(f, f.forecastle[1] + 1.5, f.stem_top() - 0.3, 0.05, 24)
    parts.append(rail(fc_edge, 1.3, 0.25, SHIP_RED))
    parts += [cylinder((40.0, 0.0, fc), (40.0, 0.0, fc + 7.5), 0.25, WHITE, 8),
              beam((40.0, -1.2, fc + 6.0), (40.0, 1.2, fc + 6.0), 0.2, WHITE)]
    # cargo rails (bulwarks) along the open deck aft, from the transom to the forecastle step
    edge = deck_edge(f, f.transom_x + 0.3, f.forecastle[1] + 0.6, 0.25, 40)
    parts.append(rail(edge, 2.3, 0.5, SHIP_RED))
    # accommodation forward: front at x = 30, three decks on the forecastle, the wheelhouse on top
    front, aft = 30.0, 13.0
    bridge_floor = reference[2] + 15.0  # the bridge deck 15 m above the waterline
    tiers = decks_with_windows(3, height=(bridge_floor - fc) / 3)
    parts.append(tiered(aft, front, -8.6, 8.6, fc, tiers, chamfer=3.0))
    wheelhouse = [(0.9, WHITE), (1.7, WINDOW), (0.6, WHITE)]
    parts.append(tiered(aft + 3.0, front + 0.5, -8.0, 8.0, bridge_floor, wheelhouse, chamfer=2.0))
    parts += wheelhouse_interior(front + 0.5, aft + 3.1, np.arange(-5.4, 5.5, 1.2), 6.0, bridge_floor, (0.9, 2.6), None,
                                 7.9)
    parts.append(box((aft + 2.7, -8.3, bridge_floor + 3.2), (front + 1.0, 8.3, bridge_floor + 3.5), WHITE))
    for sign in (1.0, -1.0):
        y0, y1 = sorted((sign * 8.0, sign * 9.7))
        parts.append(box((front - 4.0, y0, bridge_floor - 0.4), (front, y1, bridge_floor + 1.1), WHITE))
        parts.append(box((aft - 2.0, sign * 5.2 - 1.2, deck), (aft + 1.5, sign * 5.2 + 1.2, bridge_floor + 1.0),
                         (210, 210, 204)))  # exhaust casings at the after end
        parts.append(box((aft - 2.2, sign * 5.2 - 1.0, bridge_floor + 1.0), (aft + 1.3, sign * 5.2 + 1.0,
                                                                             bridge_floor + 1.8), BLACK))
    roof = bridge_floor + 3.5
    mast_x = front - 6.0
    parts += [beam((mast_x, 0, roof), (mast_x, 0, roof + 7.5), 0.7, WHITE),
              beam((mast_x, -3.5, roof + 4.5), (mast_x, 3.5, roof + 4.5), 0.35, WHITE),
              box((mast_x - 1.0, -2.0, roof + 2.5), (mast_x + 1.0, 2.0, roof + 2.8), BLACK),
              box((mast_x - 0.9, -1.6, roof + 6.0), (mast_x + 0.9, 1.6, roof + 6.25), BLACK)]
    # deck cargo on the timber deck: containers, a basket, a pipe bundle
    parts += [box((-12.0, 2.0, deck), (-5.9, 4.44, deck + 2.59), (0, 84, 150)),
              box((-12.0, 4.6, deck), (-5.9, 7.04, deck + 2.59), (206, 120, 32)),
              box((-30.0, 1.0, deck), (-24.0, 5.0, deck + 1.6), (58, 112, 62)),
              box((-2.0, -6.5, deck), (4.1, -4.06, deck + 2.59), (222, 222, 216))]
    for k in range(5):
        parts.append(cylinder((-36.0, -3.6 + 0.9 * k, deck + 0.45), (-18.0, -3.6 + 0.9 * k, deck + 0.45), 0.42,
                              (90, 90, 96), sections=8))
    # knuckle-boom crane, starboard aft: pedestal at body (-20, -7.5), tip at body (-22, -16, 20)
    to_ship = np.asarray(reference, float)
    pedestal = np.array([-20.0, -7.5, 0.0]) + (to_ship[0], 0, 0)
    tip = np.array([-22.0, -16.0, 20.0]) + to_ship
    knuckle = np.array([-21.2, -9.2, 21.9]) + to_ship
    top = deck + 4.6
    parts += [cylinder((pedestal[0], pedestal[1], deck), (pedestal[0], pedestal[1], top), 1.1, CRANE_YELLOW, 16),
              box((pedestal[0] - 1.6, pedestal[1] - 1.4, top), (pedestal[0] + 1.6, pedestal[1] + 1.4, top + 1.6),
                  CRANE_YELLOW),
              box((pedestal[0] + 1.6, pedestal[1] - 1.4, top + 0.3), (pedestal[0] + 2.9, pedestal[1] - 0.1,
                                                                      top + 2.6), WINDOW)]
    heel = np.array([pedestal[0], pedestal[1] - 0.2, top + 1.2])
    parts += [beam(heel, knuckle, 1.1, CRANE_YELLOW, height=1.0, up=(1.0, 0.0, 0.0)),
              beam(knuckle + (0, 0.3, 0.0), tip, 0.8, CRANE_YELLOW, height=0.8, up=(1.0, 0.0, 0.0)),  # jib
              cylinder(heel + (0.0, 0.9, -0.4), knuckle + (0.0, 0.6, -3.0), 0.22, STEEL, 8),  # luffing ram
              cylinder(tip + (0, 0.6, -0.5), tip + (0, 0.6, -6.5), 0.05, BLACK, 6),  # the hoist wire, inboard
              box(tip + (-0.4, 0.3, -7.3), tip + (0.4, 0.9, -6.5), CRANE_YELLOW)]  # of the tip, and the hook block
    eye = bridge_floor + 1.7
    points = {"bridge": [front - 1.5, 0.0, eye], "crane_tip": list(tip), "aft_deck": [f.transom_x + 1.5, 0.0, deck],
              "manifold_stbd": [2.0, -8.6, deck + 1.0], "forecastle": [38.0, 0.0, fc]}
    return join([closed(p, "part") for p in parts]), points


# ----------------------------------------------------------------------------------------------- semisubmersible

def semisub(reference: Sequence[float]) -> tuple[Part, dict[str, list[float]]]:
    """The drilling semisubmersible in the WAMIT frame (origin on the waterline, amidships, z up): two pontoons
    115 x 20 x 8 m at y = +-30 (B 80 m, T 21 m), four columns 15 m square, a box deck 19..28 m above the
    waterline, a helideck at (-35, 25, 30), a derrick amidships and a crane with its tip at (30, -40, 45)
    (``reference``: the WAMIT origin, which is this frame's)."""
    parts = []
    for y in (30.0, -30.0):
        parts.append(prism(rounded_rectangle(-57.5, 57.5, y - 10.0, y + 10.0, 4.0), -21.0, -13.0, ANTIFOULING))
        for x in (-41.0, 41.0):  # columns: anti-fouling, a black band through the splash zone, yellow above
            plan = rounded_rectangle(x - 7.5, x + 7.5, y - 7.5, y + 7.5, 3.0, 3)
            parts += [prism(plan, z0, z1, rgb) for z0, z1, rgb in ((-13.0, -1.5, ANTIFOULING), (-1.5, 2.5, BOOT_TOP),
                                                                   (2.5, 19.0, COLUMN_YELLOW))]
    for x in (-41.0, 41.0):
        parts.append(cylinder((x, -20.0, -16.0), (x, 20.0, -16.0), 1.6, ANTIFOULING))  # transverse braces
    deck_lo, deck_hi = 19.0, 28.0
    parts.append(box((-50.0, -38.0, deck_lo), (50.0, 38.0, deck_hi), (198, 198, 192)).painted(
        by_height([(np.inf, (198, 198, 192))], top_rgb=DECK_GREEN)))
    deck = deck_hi
    # helideck on a deckhouse, port aft: octagon 22 m across the flats, surface at z = 30
    centre = (-35.0, 25.0)
    octagon = polygon(centre, 11.0 / math.cos(math.pi / 8), 8, 22.5)
    parts.append(tiered(-44.0, -26.0, 16.0, 34.0, deck, [(0.6, WHITE), (0.8, WINDOW), (0.1, WHITE)]))
    parts.append(prism(octagon, deck + 1.5, 30.0, (190, 190, 186), top_rgb=HELIDECK_GREEN))
    parts.append(annulus((*centre, 0), 5.6, 6.6, 30.0, 30.1, MARK_YELLOW))  # touchdown circle
    parts.append(annulus((*centre, 0), 10.3, 10.8, 30.0, 30.1, WHITE, n=8, turn_deg=22.5))  # perimeter line (octagonal)
    for y0, y1, x0, x1 in ((-2.2, 2.2, -1.6, -1.0), (-2.2, 2.2, 1.0, 1.6), (-0.3, 0.3, -1.0, 1.0)):  # the H
        parts.append(box((centre[0] + x0, centre[1] + y0, 30.0), (centre[0] + x1, centre[1] + y1, 30.1), WHITE))
    # accommodation block forward of the helideck, lifeboats
    parts.append(tiered(-22.0, -8.0, 12.0, 37.0, deck, decks_with_windows(3, height=3.0)))
    for x in (-20.0, -14.0):
        parts.append(ellipsoid((x, 37.8, deck + 5.0), (2.6, 1.3, 1.2), LIFEBOAT, 1))
    # drill floor on its substructure, the derrick, pipe deck
    parts.append(box((-9.0, -9.0, deck), (9.0, 9.0, deck + 9.0), (200, 200, 194)))
    floor = deck + 9.0
    parts.append(box((-10.0, -10.0, floor - 0.5), (10.0, 10.0, floor), DERRICK_RED))
    parts.append(lattice((0, 0, floor), (0, 0, floor + 55.0), 11.0, 3.5, 0.8, 0.45, DERRICK_RED, 9,
                         up=(1.0, 0.0, 0.0)))
    parts.append(box((-2.5, -2.5, floor + 55.0), (2.5, 2.5, floor + 58.0), DERRICK_RED))  # crown block
    parts.append(box((-9.0, -6.0, floor), (-2.5, 6.0, floor + 4.0), (190, 190, 184)))  # driller's cabin / doghouse
    parts.append(box((12.0, -24.0, deck), (46.0, -4.0, deck + 1.5), DECK_GREY))  # pipe deck
    parts += [box((14.0, 8.0, deck), (40.0, 26.0, deck + 6.5), (204, 204, 198)),  # mud and pump modules
              box((18.0, 11.0, deck + 6.5), (30.0, 22.0, deck + 9.0), (180, 182, 178)),
              box((-48.0, -34.0, deck), (-30.0, -20.0, deck + 4.0), (204, 204, 198)),  # stores, workshop
              box((-26.0, -30.0, deck), (-19.9, -27.56, deck + 2.59), (0, 84, 150)),
              box((-26.0, -27.3, deck), (-19.9, -24.86, deck + 2.59), (206, 120, 32))]
    for k in range(6):
        parts.append(cylinder((14.0, -22.0 + 1.2 * k, deck + 2.0), (44.0, -22.0 + 1.2 * k, deck + 2.0), 0.5,
                              (120, 88, 60), sections=8))
    # crane, starboard: pedestal at (0, -31), lattice boom to the tip (30, -40, 45)
    tip = np.array([30.0, -40.0, 45.0])
    ped = np.array([0.0, -31.0])
    parts.append(cylinder((*ped, deck), (*ped, deck + 6.0), 1.8, CRANE_YELLOW, 16))
    parts.append(box((ped[0] - 3.5, ped[1] - 2.5, deck + 6.0), (ped[0] + 3.0, ped[1] + 2.5, deck + 10.0),
                     CRANE_YELLOW))
    parts.append(box((ped[0] + 3.0, ped[1] - 2.5, deck + 7.2), (ped[0] + 4.2, ped[1] - 0.5, deck + 9.6), WINDOW))
    heel = np.array([ped[0] + 2.0, ped[1] - 0.8, deck + 8.0])
    along = (tip - heel) / np.linalg.norm(tip - heel)
    parts.append(lattice(heel, tip - along * 0.5, 2.6, 1.0, 0.45, 0.25, CRANE_YELLOW, 10, up=(0.0, 0.0, 1.0)))
    parts.append(beam(tip - along * 0.6, tip, 0.9, CRANE_YELLOW))  # boom head
    gantry = np.array([ped[0] - 2.5, ped[1], deck + 16.0])
    parts += [beam((ped[0] - 3.0, ped[1] - 2.0, deck + 10.0), gantry, 0.5, CRANE_YELLOW),
              beam((ped[0] - 3.0, ped[1] + 2.0, deck + 10.0), gantry, 0.5, CRANE_YELLOW),
              cylinder(gantry, tip - along * 0.8, 0.12, BLACK, 6),  # pendant
              cylinder(tip - along * 0.7 + (0, 0, -0.3), tip - along * 0.7 + (0, 0, -12.0), 0.08, BLACK, 6),
              box(tip - along * 0.7 + (-0.5, -0.5, -13.0), tip - along * 0.7 + (0.5, 0.5, -12.0), CRANE_YELLOW)]
    # second crane, port forward, boom resting aft
    ped2 = np.array([38.0, 31.0])
    parts += [cylinder((*ped2, deck), (*ped2, deck + 6.0), 1.8, CRANE_YELLOW, 16),
              box((ped2[0] - 3.0, ped2[1] - 2.5, deck + 6.0), (ped2[0] + 3.5, ped2[1] + 2.5, deck + 10.0),
                  CRANE_YELLOW),
              lattice((ped2[0] - 2.0, ped2[1] + 0.8, deck + 8.0), (8.0, 30.0, deck + 11.0), 2.6, 1.0, 0.45, 0.25,
                      CRANE_YELLOW, 10)]
    points = {"helideck": [-35.0, 25.0, 30.0], "crane_tip": list(tip), "pontoon_keel": [0.0, 30.0, -21.0],
              "drill_floor": [0.0, 0.0, floor], "column_top_airgap": [41.0, -30.0, deck_lo]}
    return join([closed(p, "part") for p in parts]), points


# ----------------------------------------------------------------------------------------------- tanker

TANKER = ShipForm(lpp=246.0, beam=46.0, draft=10.0, depth=22.0, midbody=(-48.0, 74.0), p_fwd=(1.95, 2.5, 3.1),
                  p_aft=(1.3, 1.95, 3.45), forefoot_x=111.0, rake_deg=12.0, cutup_x=-106.0, transom_x=-128.2,
                  transom_z=7.0, transom_share=0.72, bilge=2.6, forecastle=(2.6, 104.0))
TANKER_RED = (128, 34, 30)
TANKER_DECK = (62, 112, 70)  # the bright green of a tanker's cargo deck


def tanker(reference: Sequence[float]) -> tuple[Part, dict[str, list[float]]]:
    """The WAMIT tanker (Lpp 246 m, B 46 m, T 10 m) in the shipyard's frame: the accommodation aft with the
    bridge across the beam, the funnel behind it, the catwalk and pipe rack along the tank deck, the manifold and
    its hose cranes amidships, the foremast and forecastle."""
    f = TANKER
    wl, boot = f.draft, f.draft + 2.0
    paint = by_height([(wl, ANTIFOULING), (boot, BOOT_TOP), (np.inf, TANKER_RED)])
    levels = [0.0, 0.15, 0.5, 1.1, 1.9, 3.0, 4.4, 6.0, 7.6, 9.0, wl, 11.0, boot, 14.0, 17.0, 20.0, f.depth,
              f.depth + 1.3, f.depth + f.forecastle[0]]
    parts = [hull(f, levels, paint, TANKER_DECK, step_mid=6.0)]
    parts.append(closed(ellipsoid((f.lpp / 2 - 1.0, 0.0, 4.6), (9.0, 3.4, 4.2), ANTIFOULING), "bulb"))
    parts.append(box((-126.5, -0.7, 1.5), (-121.0, 0.7, 9.5), ANTIFOULING))  # rudder
    deck = f.depth
    # accommodation aft: six decks, the wheelhouse on top with its wings out to the ship's side
    front, aft = -100.0, -116.0
    parts.append(box((-124.0, -21.0, deck), (-98.0, 21.0, deck + 1.0), WHITE))  # poop deck
    bridge_floor = reference[2] + 30.3  # the bridge eye (points: 32 m above the waterline) 1.7 m over the floor
    tiers = decks_with_windows(5, height=(bridge_floor - deck - 1.0) / 5)
    parts.append(tiered(aft, front, -14.0, 14.0, deck + 1.0, tiers, chamfer=2.0))
    parts.append(tiered(aft + 4.0, front + 0.4, -12.5, 12.5, bridge_floor, [(1.0, WHITE), (2.0, WINDOW), (0.5, WHITE)],
                        chamfer=1.5))
    parts.append(box((aft + 3.7, -13.0, bridge_floor + 3.5), (front + 0.9, 13.0, bridge_floor + 3.8), WHITE))  # visor
    parts += wheelhouse_interior(front, aft + 4.3, np.arange(-10.5, 11.0, 2.1), 12.0, bridge_floor, (1.0, 3.0), 7.0,
                                 12.2)
    for sign in (1.0, -1.0):
        y0, y1 = sorted((sign * 12.5, sign * (f.beam / 2 + 0.4)))
        parts.append(box((front - 3.0, y0, bridge_floor - 0.4), (front, y1, bridge_floor + 1.2), WHITE))  # wing
        parts.append(box((front - 2.8, sign * (f.beam / 2 - 0.2) - 0.3, bridge_floor + 1.2),
                         (front - 0.2, sign * (f.beam / 2 - 0.2) + 0.3, bridge_floor + 2.2), WINDOW))  # wing console
    # funnel aft of the accommodation: company colours, black top
    funnel = rounded_rectangle(-123.0, -116.5, -4.0, 4.0, 2.0)
    parts += [prism(funnel, deck + 1.0, bridge_floor + 6.0, (210, 180, 60)),
              prism(funnel, bridge_floor + 6.0, bridge_floor + 8.0, BLACK)]
    # masts on the wheelhouse roof and the forecastle; a radar scanner
    roof = bridge_floor + 3.5
    parts += [cylinder((front - 6.0, 0, roof), (front - 6.0, 0, roof + 9.0), 0.35, STEEL),
              beam((front - 6.0, -3.5, roof + 7.0), (front - 6.0, 3.5, roof + 7.0), 0.3, STEEL),
              box((front - 7.0, -2.6, roof + 3.5), (front - 5.0, 2.6, roof + 3.85), BLACK),
              cylinder((116.0, 0, deck + f.forecastle[0]), (116.0, 0, deck + f.forecastle[0] + 12.0), 0.45, STEEL)]
    # the tank deck: catwalk on the centreline, a pipe rack beside it, tank hatches, the manifold and hose cranes
    parts.append(box((-98.0, -1.0, deck + 2.4), (104.0, 1.0, deck + 2.7), STEEL))  # catwalk
    for x in np.arange(-96.0, 104.0, 12.0):
        parts.append(box((x - 0.2, -0.9, deck), (x + 0.2, 0.9, deck + 2.4), STEEL))  # its stanchions
    for k in range(4):
        y = 2.0 + 0.8 * k
        parts.append(cylinder((-98.0, y, deck + 0.9), (104.0, y, deck + 0.9), 0.32, (96, 112, 96), sections=8))
    for x in np.arange(-88.0, 100.0, 24.0):
        for y in (-12.0, 12.0):
            parts.append(box((x - 1.5, y - 1.5, deck), (x + 1.5, y + 1.5, deck + 0.9), STEEL))  # tank hatches
    for sign in (1.0, -1.0):
        parts.append(box((-6.0, sign * 4.0 - 0.3, deck), (6.0, sign * 21.0 + 0.3, deck + 1.2), (96, 112, 96)))
        for x in (-4.0, 0.0, 4.0):  # the manifold's flanges at the ship's side
            parts.append(cylinder((x, sign * 19.5, deck + 1.6), (x, sign * 21.5, deck + 1.6), 0.45, STEEL, 10))
        ped = np.array([10.0, sign * 16.0])
        tip = np.array([-2.0, sign * 21.0, deck + 16.0])
        parts += [cylinder((*ped, deck), (*ped, deck + 5.0), 0.9, WHITE, 12),
                  beam((*ped, deck + 5.0), tip, 0.8, WHITE),
                  cylinder(tip, tip + (0.0, 0.0, -8.0), 0.08, BLACK, 6)]
    # forecastle: bulwark, windlasses
    edge = deck_edge(f, f.forecastle[1] + 1.5, f.stem_top() - 0.5, 0.15, 24)
    parts.append(rail(edge, 1.3, 0.3, TANKER_RED))
    fc = deck + f.forecastle[0]
    parts += [box((108.0, sign * 4.0 - 1.2, fc), (111.0, sign * 4.0 + 1.2, fc + 1.6), STEEL) for sign in (1.0, -1.0)]
    eye = bridge_floor + 1.7
    points = {"bridge": [front - 1.0, 0.0, eye], "bridge_wing_stbd": [front - 1.5, -f.beam / 2, eye],
              "bow": [f.lpp / 2 - 3.0, 0.0, fc], "manifold": [0.0, 20.0, deck + 2.0]}
    return join([closed(p, "part") for p in parts]), points


# ----------------------------------------------------------------------------------------------- main

SHIPS = (("s175_visual.glb", RAO / "s175" / "input.re1", S175, s175, "s175_hull.stl"),
         ("supply_visual.glb", RAO / "supply" / "input.re1", SUPPLY, supply, "supply_hull.stl"),
         ("semisub_visual.glb", RAO / "semisub" / "semisub.4", None, semisub, None),
         ("tanker_visual.glb", RAO / "tanker" / "tanker.4", TANKER, tanker, None))
"""File, RAO file, hull form (None: the frame's z = 0 is the waterline, not the baseline), builder, and the file for
the bare hull (for the wake, the wash and the hydrostatics; None where the RAO file's own panels serve)."""


def write_hull_stl(form: ShipForm, reference: np.ndarray, path: Path) -> None:
    """The bare hull of ``form`` in the body frame as a binary STL: 12 waterlines up to the draft, two above it."""
    levels = np.r_[np.linspace(0.0, form.draft, 13), form.draft + 0.5 * (form.depth - form.draft), form.depth]
    part = hull(form, levels, by_height([(np.inf, STEEL)]), STEEL).moved(-reference)
    mesh = trimesh.Trimesh(part.v, part.f, process=True)
    mesh.export(path)
    print(f"{path.name}: {len(mesh.faces)} triangles, watertight {mesh.is_watertight}, "
          f"volume {mesh.volume:.0f} m^3 (whole hull to the deck)")

if __name__ == "__main__":
    for name, rao, form, make, hull_file in SHIPS:
        reference = np.asarray(read_rao(rao).reference_point, float)  # (XMTN, 0, ZMTN) for VERES, 0 for WAMIT
        if rao.suffix == ".4" and form is not None:
            reference = reference + (0.0, 0.0, form.draft)  # WAMIT's origin: midships on the waterline
        model, points = make(reference)
        body = model.moved(-reference)  # into the body frame: origin at the RAO reference point
        write_glb(body, HERE / name)
        if hull_file is not None:
            write_hull_stl(form, reference, HERE / hull_file)
        draft = 0.0 if form is None else form.draft
        print(f"  RAO reference point {reference.tolist()} (drawing frame); still waterline at body z = "
              f"{draft - reference[2]:+.2f} m" + ("" if form is None else f"; Cb {block_coefficient(form):.3f}"))
        print("  points (body frame, m):")
        for key, p in points.items():
            print(f"  {key:18s} {np.round(np.asarray(p) - reference, 2).tolist()}")
