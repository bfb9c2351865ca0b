"""The vessel as drawn: flat-shaded triangles with colours, in the body frame (m).

A hull file that stops at the waterline (a WAMIT ``.gdf`` holds only the wetted surface) gets
topsides: each of its waterline loops (:func:`~marinesim.hull.waterplane.waterline_loops`; two for
a catamaran) extruded up by the freeboard, closed with a deck and edged with a bulwark. Paint:
anti-fouling red below the boot-top, the black boot-top band about the waterline, the scenario's
topsides colour above, a deck (the draft marks are painted by the shader: :mod:`~marinesim.render.draft_marks`).
A point on board above the deck (the bridge) gets a ship around it:
the accommodation in decks with window bands, the wheelhouse with the eye in its window band and its
wings out to the ship's sides, a funnel abaft it, a mast on its roof and a foremast; hatch covers on
the deck forward of it for a ``hatches`` deck: parts and colours of the ship kit (:mod:`~marinesim.render.ship_kit`)
that the shipped visual meshes are made of. Faces are wound counter-clockwise seen from outside,
so back-face culling hides the wheelhouse from an eye inside it (the bridge camera).
A scenario's visual mesh is drawn instead when it has one, in its own colours or these.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from marinesim.hull import Hull, VisualMesh
from marinesim.hull.waterplane import waterline_loops
from marinesim.render import ship_kit as kit

BOTTOM, BOOT_TOP, TOPSIDES, DECK = (kit.rgb_unit(c) for c in (kit.ANTIFOULING, kit.BOOT_TOP, kit.NAVY, kit.DECK_GREEN))
"""The hull's paint (0..1): below the boot-top, the boot-top, the topsides unless the scenario gives them, the deck."""
HOUSE, WINDOW, FUNNEL, HATCH = (kit.rgb_unit(c) for c in (kit.WHITE, kit.WINDOW, kit.FUNNEL, kit.DECK_GREY))
"""The superstructure's colours (0..1) that show from outside: the house, its window bands, the funnel, hatch covers."""
BOOT_TOP_M = (-0.5, 0.6)
"""The boot-top band about the still waterline (m): between the bottom's paint and the topsides'."""
DECK_HEIGHT_M = 2.8
"""The height of one deck of the accommodation (m), each with its window band (:func:`.ship_kit.decks_with_windows`)."""
OPEN_TOP_BELOW_M = 0.05
"""A hull whose highest point is this close to the waterline is taken as open at the top."""


@dataclass(frozen=True)
class VesselMesh:
    """Unindexed triangles: ``positions`` (3 t, 3) m body frame, ``normals`` and ``colours`` per corner."""

    positions: np.ndarray
    normals: np.ndarray
    colours: np.ndarray

    def vertex_data(self) -> np.ndarray:
        """(3 t, 9) float32 rows: position, normal, colour."""
        return np.hstack([self.positions, self.normals, self.colours]).astype(np.float32)

    def bounds(self) -> np.ndarray:
        """The eight corners of the body-frame bounding box (8, 3)."""
        return _box_corners(self.positions.min(axis=0), self.positions.max(axis=0))


def vessel_mesh(hull: Hull, freeboard_m: float | None = None, house_at: tuple[float, float, float] | None = None,
                topsides: tuple[float, float, float] = TOPSIDES, deck_layout: str = "flat") -> VesselMesh:
    """The drawable vessel for ``hull``; ``freeboard_m`` (default 0.6 x draft) for open hulls; a ship's
    superstructure around ``house_at`` (the bridge, body frame, m) when it lies above the deck; ``topsides`` the
    hull's colour above the boot-top; ``deck_layout`` ``flat`` or ``hatches``."""
    v, f = np.asarray(hull.vertices, float), np.asarray(hull.faces)
    triangles = [v[f]]
    draft = -float(v[:, 2].min())
    deck_z = float(v[:, 2].max())
    if deck_z < OPEN_TOP_BELOW_M:
        deck_z = freeboard_m if freeboard_m is not None else max(0.6 * draft, 1.0)
        for loop in waterline_loops(hull):
            outline = np.c_[loop, np.zeros(len(loop))]
            bulwark = _walls(outline, deck_z + 1.2, bottom=deck_z)
            triangles += [_walls(outline, deck_z), _fan(outline, deck_z), bulwark, bulwark[:, ::-1]]
    corners = np.concatenate(triangles)
    normals = _face_normals(corners)
    colours = _hull_colours(corners, normals, topsides)
    if house_at is not None and house_at[2] > deck_z + 1.0:
        ship = kit.join(_superstructure(v, house_at, deck_z, deck_layout)).solid()
        extra = ship.v[ship.f]
        corners = np.concatenate([corners, extra])
        normals = np.concatenate([normals, _face_normals(extra)])
        colours = np.concatenate([colours, np.repeat(ship.c[:, None, :] / 255.0, 3, axis=1)])
    return _flat(corners, normals, colours)


def _superstructure(v: np.ndarray, bridge: tuple[float, float, float], deck_z: float, deck_layout: str
                    ) -> list[kit.Part]:
    """The accommodation, wheelhouse, wings, funnel, masts and hatch covers around the bridge point of a hull with
    vertices ``v`` and its deck at ``deck_z`` (m)."""
    length, beam = float(np.ptp(v[:, 0])), float(np.ptp(v[:, 1]))
    bow, stern = float(v[:, 0].max()), float(v[:, 0].min())
    x0, x1, half = bridge[0] - 0.06 * length, bridge[0] + 2.0, 0.35 * beam  # the eye 2 m behind the glass
    floor = max(bridge[2] - 1.7, deck_z)               # the eye 1.7 m over the wheelhouse floor (or the deck)
    roof = floor + 3.2
    decks = int((floor - deck_z) // DECK_HEIGHT_M)
    tiers = [(floor - deck_z, kit.WHITE)] if floor - deck_z > 0.1 else []
    if decks:
        tiers = kit.decks_with_windows(decks, (floor - deck_z) / decks)
    tiers += [(1.0, kit.WHITE), (1.5, kit.WINDOW), (0.7, kit.WHITE)]
    parts = [kit.tiered(x0, x1, -half, half, deck_z, tiers)]
    mullions = np.r_[-np.arange(0.7, half - 0.4, 1.4), np.arange(0.7, half - 0.4, 1.4)]
    parts += kit.wheelhouse_interior(x1, x0 + 0.1, mullions, half - 0.3, floor, (1.0, 2.5), None, half - 0.1)
    for sign in (1.0, -1.0):
        y = sorted((sign * half, sign * (0.5 * beam + 0.3)))
        parts.append(kit.box((x1 - 3.0, y[0], floor - 0.3), (x1, y[1], floor + 1.1), kit.WHITE))  # bridge wing
    funnel = (x0 - max(0.04 * length, 3.0), x0 - 0.5)
    parts += [kit.box((funnel[0], -0.08 * beam, deck_z), (funnel[1], 0.08 * beam, roof + 3.0), kit.FUNNEL),
              kit.box((funnel[0], -0.08 * beam, roof + 3.0), (funnel[1], 0.08 * beam, roof + 4.5), kit.BLACK)]
    mast_x = 0.5 * (x0 + x1)
    parts += [kit.box((mast_x - 0.2, -0.2, roof), (mast_x + 0.2, 0.2, roof + 6.0), kit.STEEL),
              kit.box((mast_x - 0.15, -0.12 * beam, roof + 4.5), (mast_x + 0.15, 0.12 * beam, roof + 4.8), kit.STEEL)]
    fore = bow - 0.08 * length
    if fore > x1 + 5.0:
        top = deck_z + max(8.0, 0.5 * (roof - deck_z))
        parts.append(kit.box((fore - 0.25, -0.25, deck_z), (fore + 0.25, 0.25, top), kit.STEEL))  # foremast
    if deck_layout == "hatches":
        start, end = (x1 + 3.0, bow - 0.12 * length) if bridge[0] < 0.0 else (stern + 0.1 * length, x0 - 8.0)
        for a in np.arange(start, end - 10.0, 14.0):
            parts.append(kit.box((a, -0.3 * beam, deck_z), (a + 12.0, 0.3 * beam, deck_z + 1.2), kit.DECK_GREY))
    return parts


def visual_mesh(mesh: VisualMesh) -> VesselMesh:
    """The drawable vessel for a scenario's visual mesh (body frame, m): flat-shaded, in the mesh's own
    colours, or coloured like a hull (bottom, topsides, deck) when the file has none."""
    corners = np.asarray(mesh.vertices, float)[mesh.faces]
    normals = _face_normals(corners)
    colours = mesh.colours if mesh.colours is not None else _hull_colours(corners, normals)
    return _flat(corners, normals, colours)


def part_mesh(part: kit.Part) -> VesselMesh:
    """The drawable mesh of a ship-kit part (body frame, m), in its faces' colours."""
    corners = part.v[part.f]
    colours = np.repeat((part.c / 255.0)[:, None, :], 3, axis=1)
    return _flat(corners, _face_normals(corners), colours)


def buoy_mesh() -> VesselMesh:
    """A safe-water mark (IALA): a red and white float 2.4 m across, a cage tower to 4.5 m, a red ball on top;
    origin at the waterline."""
    red, white = (200, 30, 28), kit.WHITE
    float_ = kit.join([kit.cylinder((0.0, 0.0, -1.0), (0.0, 0.0, 0.4), 1.2, red, sections=16),
                       kit.cylinder((0.0, 0.0, 0.4), (0.0, 0.0, 1.0), 1.2, white, sections=16)])
    legs = [kit.beam((0.9 * np.cos(a), 0.9 * np.sin(a), 1.0), (0.2 * np.cos(a), 0.2 * np.sin(a), 4.0), 0.12,
                     red if i % 2 else white) for i, a in enumerate(np.linspace(0.0, 2 * np.pi, 4, endpoint=False))]
    top = kit.ellipsoid((0.0, 0.0, 4.6), (0.4, 0.4, 0.4), red)
    return part_mesh(kit.join([float_, *legs, top]))


CONTAINER_M = (6.06, 2.44, 2.59)
"""A 20 ft ISO container, length, width and height (m)."""


def container_mesh() -> VesselMesh:
    """A 20 ft container as the crane's load, its bottom's centre at the origin, doors aft."""
    length, width, height = CONTAINER_M
    return part_mesh(kit.box((-length / 2, -width / 2, 0.0), (length / 2, width / 2, height), kit.SHIP_RED))


def wire_mesh(top: np.ndarray, bottom: np.ndarray, width_m: float = 0.12) -> VesselMesh:
    """A crane's wire from ``top`` to ``bottom`` (E frame, m): a thin beam, drawn thicker than the 40 mm rope so that
    it shows from the crane cab."""
    top, bottom = np.asarray(top, float), np.asarray(bottom, float)
    if np.linalg.norm(top - bottom) < 1e-3:
        bottom = top - np.array([0.0, 0.0, 1e-3])
    up = (1.0, 0.0, 0.0) if abs((top - bottom)[2]) > 0.9 * np.linalg.norm(top - bottom) else (0.0, 0.0, 1.0)
    return part_mesh(kit.beam(bottom, top, width_m, kit.BLACK, up=up))


def hawser_mesh(fairlead: np.ndarray, fixed: np.ndarray, sag_m: float, width_m: float = 0.3,
                segments: int = 8) -> VesselMesh:
    """A hawser from ``fairlead`` to ``fixed`` (E frame, m) hanging ``sag_m`` below the chord at mid-span (a
    parabola: a taut line's catenary), in ``segments`` straight pieces of a white nylon rope drawn ``width_m``
    thick."""
    fairlead, fixed = np.asarray(fairlead, float), np.asarray(fixed, float)
    s = np.linspace(0.0, 1.0, segments + 1)[:, None]
    points = fairlead + s * (fixed - fairlead) - 4.0 * sag_m * s * (1.0 - s) * np.array([0.0, 0.0, 1.0])
    return part_mesh(kit.join([kit.beam(p0, p1, width_m, kit.WHITE) for p0, p1 in zip(points[:-1], points[1:])]))


def boom_mesh(heel: np.ndarray, tip: np.ndarray) -> VesselMesh:
    """A crane's boom from ``heel`` to ``tip`` (body frame, m): a yellow box girder, with a sheave block at the tip."""
    return part_mesh(kit.join([kit.beam(heel, tip, 0.9, kit.CRANE_YELLOW, height=0.8),
                               kit.box(np.asarray(tip) - 0.45, np.asarray(tip) + 0.45, kit.CRANE_YELLOW)]))


def _face_normals(corners: np.ndarray) -> np.ndarray:
    """Unit normals (t, 3) of triangles (t, 3, 3) wound counter-clockwise seen from outside."""
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    return normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)


def _hull_colours(corners: np.ndarray, normals: np.ndarray, topsides=TOPSIDES) -> np.ndarray:
    """RGB per corner (t, 3, 3) of triangles (t, 3, 3): bottom below the boot-top, the boot-top about the
    waterline (z = 0), ``topsides`` above it, deck where they face up."""
    centre_z = corners[:, :, 2].mean(axis=1)
    colours = np.where((centre_z < BOOT_TOP_M[0])[:, None], BOTTOM, np.asarray(topsides, float))
    colours[(centre_z >= BOOT_TOP_M[0]) & (centre_z < BOOT_TOP_M[1])] = BOOT_TOP
    colours[(normals[:, 2] > 0.7) & (centre_z > 0.0)] = DECK
    return np.repeat(colours[:, None, :], 3, axis=1)


def _flat(corners: np.ndarray, normals: np.ndarray, colours: np.ndarray) -> VesselMesh:
    """Unindexed flat-shaded triangles from corners (t, 3, 3), face normals (t, 3), corner colours (t, 3, 3)."""
    return VesselMesh(corners.reshape(-1, 3), np.repeat(normals, 3, axis=0), colours.reshape(-1, 3))


def _walls(outline: np.ndarray, top: float, bottom: float = 0.0) -> np.ndarray:
    """Quads from each edge of ``outline`` (counter-clockwise seen from above) from ``bottom`` up to ``top``,
    facing out."""
    a, b = outline.copy(), np.roll(outline, -1, axis=0)
    a_top, b_top = a.copy(), b.copy()
    a[:, 2] = b[:, 2] = bottom
    a_top[:, 2] = b_top[:, 2] = top
    return np.concatenate([np.stack([a, b, b_top], axis=1), np.stack([b_top, a_top, a], axis=1)])


def _fan(outline: np.ndarray, top: float) -> np.ndarray:
    """The deck: a fan from the outline's centroid (each hull's waterplane is star-shaped about it), facing up."""
    ring = outline.copy()
    ring[:, 2] = top
    centre = np.r_[ring[:, :2].mean(axis=0), top]
    fan = np.stack([np.broadcast_to(centre, ring.shape), np.roll(ring, -1, axis=0), ring], axis=1)
    up = np.cross(fan[:, 1] - fan[:, 0], fan[:, 2] - fan[:, 0])[:, 2]
    fan[up < 0] = fan[up < 0][:, ::-1]
    return fan


def _box_corners(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The eight corners (8, 3) of the box ``lo..hi``, z fastest, then y, then x."""
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
