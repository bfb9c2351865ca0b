"""The procedural ship kit: parts with one colour per face (boxes, prisms, beams, cylinders, lattices, rings), the
deckhouse in tiers with its window bands, the inside of a wheelhouse that the bridge camera sees, and the ships'
colours. The viewer draws a ship from a hull alone with it (:mod:`marinesim.render.vessel_mesh`), and
hulls/make/visual_ships.py writes the shipped visual meshes (hulls/*_visual.glb) with it.

Parts are in metres, faces counter-clockwise seen from outside (the renderer culls back faces); colours are RGB
0..255, as in a mesh file and a scenario's ``topsides_rgb``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from marinesim.hull.trimesh_held import trimesh

# The colours (RGB 0..255)
ANTIFOULING = (120, 30, 24)
BOOT_TOP = (28, 28, 30)
NAVY = (28, 44, 84)
SHIP_RED = (198, 46, 32)
WHITE = (236, 236, 230)
WINDOW = (22, 30, 40)
DECK_GREEN = (86, 102, 86)
DECK_GREY = (112, 114, 110)
TIMBER = (128, 96, 64)
STEEL = (150, 152, 150)
BLACK = (24, 24, 24)
CRANE_YELLOW = (232, 178, 28)
COLUMN_YELLOW = (236, 170, 28)
DERRICK_RED = (188, 72, 40)
HELIDECK_GREEN = (62, 88, 66)
MARK_YELLOW = (240, 205, 40)
LIFEBOAT = (240, 110, 20)
FUNNEL = (196, 64, 40)
CONTAINER_COLOURS = ((0, 84, 150), (172, 36, 30), (206, 120, 32), (58, 112, 62), (150, 150, 146), (222, 222, 216),
                     (122, 72, 42), (30, 58, 118), (204, 172, 44), (96, 96, 100))


def rgb_unit(rgb: Sequence[int]) -> tuple[float, float, float]:
    """A colour of the kit (0..255) as the renderer takes it (0..1)."""
    return tuple(c / 255.0 for c in rgb)


@dataclass
class Part:
    """Triangles with shared vertices: ``v`` (n, 3) m, ``f`` (m, 3) counter-clockwise seen from outside, and one
    RGB colour per face ``c`` (m, 3) uint8."""

    v: np.ndarray
    f: np.ndarray
    c: np.ndarray

    @classmethod
    def of(cls, v, f, rgb) -> Part:
        """Vertices ``v`` and faces ``f`` (any shape that reshapes to (n, 3)) all painted ``rgb``."""
        f = np.asarray(f, np.int64).reshape(-1, 3)
        return cls(np.asarray(v, float).reshape(-1, 3), f, np.tile(np.asarray(rgb, np.uint8), (len(f), 1)))

    def moved(self, shift: Sequence[float]) -> Part:
        """Moved by ``shift`` (m)."""
        return Part(self.v + np.asarray(shift, float), self.f, self.c)

    def centres(self) -> np.ndarray:
        """The faces' centroids (m, 3)."""
        return self.v[self.f].mean(axis=1)

    def normals(self) -> np.ndarray:
        """The faces' unit normals (m, 3), outward."""
        t = self.v[self.f]
        n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12)

    def painted(self, colour_of: Callable[[np.ndarray, np.ndarray], np.ndarray]) -> Part:
        """Recoloured face by face: ``colour_of(centres (m, 3), unit normals (m, 3))`` -> (m, 3) RGB."""
        return Part(self.v, self.f, np.asarray(colour_of(self.centres(), self.normals()), np.uint8))

    def solid(self) -> Part:
        """Without its faces of no area (a section collapsed to a point, a tier's plan without a chamfer)."""
        t = self.v[self.f]
        keep = np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1) > 1e-9
        return Part(self.v, self.f[keep], self.c[keep])

    def volume(self) -> float:
        """Signed volume (m^3): positive when a closed part's faces face outwards."""
        t = self.v[self.f]
        return float(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6.0)


def join(parts: Sequence[Part]) -> Part:
    """One part of ``parts``, their vertices kept apart."""
    offsets = np.cumsum([0] + [len(p.v) for p in parts[:-1]])
    return Part(np.concatenate([p.v for p in parts]), np.concatenate([p.f + o for p, o in zip(parts, offsets)]),
                np.concatenate([p.c for p in parts]))


def closed(part: Part, what: str) -> Part:
    """``part`` after checking that it encloses its volume with outward faces (the renderer culls back faces)."""
    if part.volume() <= 0.0:
        raise AssertionError(f"{what}: faces point inwards (signed volume {part.volume():.3g} m^3)")
    return part


def box(lo: Sequence[float], hi: Sequence[float], rgb) -> Part:
    """An axis-aligned box from corner ``lo`` to corner ``hi``."""
    b = trimesh.creation.box(bounds=[lo, hi])
    return Part.of(b.vertices, b.faces, rgb)


def prism(outline: np.ndarray, z0: float, z1: float, rgb, top_rgb=None) -> Part:
    """A convex plan ``outline`` (k, 2), counter-clockwise seen from above, extruded from ``z0`` up to ``z1``."""
    outline = np.asarray(outline, float)
    k = len(outline)
    v = np.concatenate([np.c_[outline, np.full(k, z0)], np.c_[outline, np.full(k, z1)],
                        [[*outline.mean(axis=0), z0], [*outline.mean(axis=0), z1]]])
    i = np.arange(k)
    j = (i + 1) % k
    sides = np.concatenate([np.c_[i, j, k + j], np.c_[k + j, k + i, i]])
    top = np.c_[np.full(k, 2 * k + 1), k + i, k + j]
    bottom = np.c_[np.full(k, 2 * k), j, i]
    faces = np.concatenate([sides, top, bottom])
    part = Part.of(v, faces, rgb)
    if top_rgb is not None:
        part.c[len(sides):len(sides) + k] = top_rgb
    return part


def rounded_rectangle(x0: float, x1: float, y0: float, y1: float, r: float, n: int = 4) -> np.ndarray:
    """Plan outline (counter-clockwise) of a rectangle with corners rounded by ``r`` (``n`` segments each)."""
    corners = ((x1 - r, y0 + r, -90.0), (x1 - r, y1 - r, 0.0), (x0 + r, y1 - r, 90.0), (x0 + r, y0 + r, 180.0))
    pts = [(cx + r * math.cos(math.radians(a0 + 90.0 * s / n)), cy + r * math.sin(math.radians(a0 + 90.0 * s / n)))
           for cx, cy, a0 in corners for s in range(n + 1)]
    return np.array(pts)


def polygon(centre: Sequence[float], radius: float, sides: int, turn_deg: float = 0.0) -> np.ndarray:
    """A regular polygon's plan outline (counter-clockwise), ``radius`` to its corners."""
    a = np.radians(turn_deg) + 2.0 * np.pi * np.arange(sides) / sides
    return np.c_[centre[0] + radius * np.cos(a), centre[1] + radius * np.sin(a)]


def _frame(p0: np.ndarray, p1: np.ndarray, up=(0.0, 0.0, 1.0)) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A right-handed unit frame (along, side, normal) of the segment p0 -> p1."""
    along = (p1 - p0) / np.linalg.norm(p1 - p0)
    ref = np.asarray(up, float)
    if abs(np.dot(along, ref)) > 0.95:  # along ``up``: any axis across it will do
        ref = np.eye(3)[np.argmin(np.abs(along))]
    side = np.cross(ref, along)
    side /= np.linalg.norm(side)
    return along, side, np.cross(along, side)


def beam(p0: Sequence[float], p1: Sequence[float], width: float, rgb, height: float | None = None,
         up=(0.0, 0.0, 1.0)) -> Part:
    """A box of ``width`` x ``height`` (default square) section along the segment p0 -> p1."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    along, side, normal = _frame(p0, p1, up)
    length = np.linalg.norm(p1 - p0)
    half = (height or width) / 2
    b = trimesh.creation.box(bounds=[[0.0, -width / 2, -half], [length, width / 2, half]])
    rotation = np.c_[along, side, normal]  # det +1: faces keep their outward side
    return Part.of(b.vertices @ rotation.T + p0, b.faces, rgb)


def cylinder(p0: Sequence[float], p1: Sequence[float], radius: float, rgb, sections: int = 12) -> Part:
    """A capped cylinder of ``radius`` from p0 to p1."""
    c = trimesh.creation.cylinder(radius=radius, segment=[p0, p1], sections=sections)
    return Part.of(c.vertices, c.faces, rgb)


def ellipsoid(centre: Sequence[float], semi_axes: Sequence[float], rgb, subdivisions: int = 2) -> Part:
    """An ellipsoid (a bulbous bow, a lifeboat): an icosphere scaled by its three semi-axes."""
    s = trimesh.creation.icosphere(subdivisions=subdivisions)
    return Part.of(s.vertices * np.asarray(semi_axes, float) + np.asarray(centre, float), s.faces, rgb)


def lattice(p0: Sequence[float], p1: Sequence[float], w0: float, w1: float, chord: float, lacing: float, rgb,
            panels: int, up=(0.0, 0.0, 1.0)) -> Part:
    """A four-chord lattice (a crane boom, a derrick) from p0 (square section ``w0`` wide) to p1 (``w1``),
    braced on its four faces by a zigzag in ``panels`` panels and a ring at each panel point."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    along, side, normal = _frame(p0, p1, up)
    corners = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)]) / 2.0

    def node(i: int, k: int) -> np.ndarray:
        s = i / panels
        w = w0 + (w1 - w0) * s
        return p0 + (p1 - p0) * s + w * (corners[k, 0] * side + corners[k, 1] * normal)

    members = []
    for k in range(4):
        members.append(beam(node(0, k), node(panels, k), chord, rgb, up=up))
        for i in range(panels):
            a, b = (k, (k + 1) % 4) if i % 2 == 0 else ((k + 1) % 4, k)
            members.append(beam(node(i, a), node(i + 1, b), lacing, rgb, up=up))
            members.append(beam(node(i + 1, k), node(i + 1, (k + 1) % 4), lacing, rgb, up=up))
    return join(members)


def annulus(centre: Sequence[float], r_in: float, r_out: float, z0: float, z1: float, rgb, n: int = 32,
            turn_deg: float = 0.0) -> Part:
    """A flat ring (a helideck's touchdown circle) between ``r_in`` and ``r_out`` (to the corners of its ``n``
    sides), from z0 up to z1."""
    a = np.radians(turn_deg) + 2.0 * np.pi * np.arange(n) / n
    rings = [np.c_[centre[0] + r * np.cos(a), centre[1] + r * np.sin(a), np.full(n, z)]
             for r, z in ((r_out, z0), (r_out, z1), (r_in, z1), (r_in, z0))]
    v = np.concatenate(rings)
    i, j = np.arange(n), (np.arange(n) + 1) % n
    faces = []
    for ring in range(4):  # outer wall, top, inner wall, bottom: each band from ring to ring + 1
        a0, b0 = ring * n + i, ring * n + j
        nxt = ((ring + 1) % 4) * n
        faces += [np.c_[a0, b0, nxt + j], np.c_[nxt + j, nxt + i, a0]]
    return Part.of(v, np.concatenate(faces), rgb)


def by_height(bands: Sequence[tuple[float, tuple[int, int, int]]], top_rgb=None, up: float = 0.7):
    """A painter for :meth:`Part.painted`: the colour of the first band whose upper z the face's centre is
    below (the last band has no limit); faces facing up (normal z > ``up``) get ``top_rgb`` when given."""
    def colour_of(centres: np.ndarray, normals: np.ndarray) -> np.ndarray:
        out = np.empty((len(centres), 3))
        out[:] = bands[-1][1]
        for limit, rgb in reversed(bands[:-1]):
            out[centres[:, 2] < limit] = rgb
        if top_rgb is not None:
            out[normals[:, 2] > up] = top_rgb
        return out
    return colour_of



def tiered(x0, x1, y0, y1, z0, tiers: Sequence[tuple[float, tuple[int, int, int]]], chamfer: float = 0.0) -> Part:
    """A deckhouse of stacked prisms on the same plan, x0..x1 by y0..y1 with its forward corners cut by
    ``chamfer`` m: ``tiers`` (height, colour) from ``z0`` up. Window bands are tiers of their own rather than
    panels on a wall, so no face lies on another where it can be seen (the caps between tiers are inside), and an
    eye inside (the bridge camera, faces culled from behind) looks out through the band."""
    c = chamfer
    plan = np.array([(x0, y0), (x1 - c, y0), (x1, y0 + c), (x1, y1 - c), (x1 - c, y1), (x0, y1)])
    parts, z = [], z0
    for height, rgb in tiers:
        parts.append(prism(plan, z, z + height, rgb))
        z += height
    return join(parts)


def decks_with_windows(n: int, height: float = 2.8, band: float = 0.9, sill: float = 1.1, body=WHITE):
    """Tiers for :func:`tiered`: ``n`` decks, each with a window band ``band`` high ``sill`` above its floor."""
    return [t for _ in range(n) for t in ((sill, body), (band, WINDOW), (height - sill - band, body))]


def wheelhouse_interior(front: float, aft: float, mullion_ys: Sequence[float], sill_half: float, floor: float,
                        window: tuple[float, float], console_half: float | None, floor_half: float) -> list[Part]:
    """What the conning position sees inside a wheelhouse whose front windows face forward at ``x = front``:
    mullions at ``mullion_ys`` and the sill (``sill_half`` a side) over the window band ``window`` (heights above
    ``floor``), a console ``console_half`` a side below the windows (None: none), and the floor back to ``aft``."""
    frame, console, deck = (52, 56, 60), (70, 76, 82), (64, 68, 74)
    low, high = floor + window[0], floor + window[1]
    parts = [box((front - 0.35, y - 0.06, low), (front - 0.17, y + 0.06, high), frame) for y in mullion_ys]
    parts.append(box((front - 0.3, -sill_half, low), (front - 0.17, sill_half, low + 0.12), frame))
    if console_half is not None:
        parts.append(box((front - 1.9, -console_half, floor), (front - 0.6, console_half, floor + 1.1), console))
    parts.append(box((aft, -floor_half, floor), (front - 0.1, floor_half, floor + 0.04), deck))
    return parts
