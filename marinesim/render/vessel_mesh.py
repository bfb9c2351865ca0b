"""The vessel as drawn: flat-shaded triangles with colours, in the body frame (m).

A hull file that stops at the waterline (a WAMIT ``.gdf`` holds only the wetted surface) gets
topsides: each of its waterline loops (:func:`~marinesim.hull.waterplane.waterline_loops`; two for
a catamaran) extruded up by the freeboard and closed with a deck. A point on
board above the deck (the bridge) gets a deckhouse around it. Colours: anti-fouling red below the
waterline, dark topsides, a deck, a white deckhouse. Faces are wound counter-clockwise seen from
outside, so back-face culling hides the deckhouse from an eye inside it (the bridge camera).
A scenario's visual mesh is drawn instead when it has one, in its own colours or these.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from marinesim.hull import Hull, VisualMesh
from marinesim.hull.waterplane import waterline_loops

BOTTOM = (0.45, 0.09, 0.07)
TOPSIDES = (0.10, 0.12, 0.16)
DECK = (0.33, 0.30, 0.26)
HOUSE = (0.86, 0.86, 0.84)
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


def vessel_mesh(hull: Hull, freeboard_m: float | None = None, house_at: tuple[float, float, float] | None = None
                ) -> VesselMesh:
    """The drawable vessel for ``hull``; ``freeboard_m`` (default 0.6 x draft) for open hulls,
    a deckhouse enclosing ``house_at`` (body frame, m) when it lies above the deck."""
    v, f = np.asarray(hull.vertices, float), np.asarray(hull.faces)
    triangles = [v[f]]
    draft = -float(v[:, 2].min())
    deck_z = float(v[:, 2].max())
    if deck_z < OPEN_TOP_BELOW_M:
        deck_z = freeboard_m if freeboard_m is not None else max(0.6 * draft, 1.0)
        for loop in waterline_loops(hull):
            outline = np.c_[loop, np.zeros(len(loop))]
            triangles += [_walls(outline, deck_z), _fan(outline, deck_z)]
    house = house_at is not None and house_at[2] > deck_z + 1.0
    if house:
        triangles.append(_house(v, house_at, deck_z))
    corners = np.concatenate(triangles)
    normals = _face_normals(corners)
    colours = _hull_colours(corners, normals)
    if house:
        colours[-12:] = HOUSE  # the house's 12 triangles, appended last
    return _flat(corners, normals, colours)


def visual_mesh(mesh: VisualMesh) -> VesselMesh:
    """The drawable vessel for a scenario's visual mesh (body frame, m): flat-shaded, in the mesh's own
    colours, or coloured like a hull (bottom, topsides, deck) when the file has none."""
    corners = np.asarray(mesh.vertices, float)[mesh.faces]
    normals = _face_normals(corners)
    colours = mesh.colours if mesh.colours is not None else _hull_colours(corners, normals)
    return _flat(corners, normals, colours)


def _face_normals(corners: np.ndarray) -> np.ndarray:
    """Unit normals (t, 3) of triangles (t, 3, 3) wound counter-clockwise seen from outside."""
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    return normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)


def _hull_colours(corners: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """RGB per corner (t, 3, 3) of triangles (t, 3, 3): bottom below the waterline (z = 0), topsides above
    it, deck where they face up."""
    centre_z = corners[:, :, 2].mean(axis=1)
    colours = np.where((centre_z < 0.0)[:, None], BOTTOM, TOPSIDES)
    colours[(normals[:, 2] > 0.7) & (centre_z > 0.0)] = DECK
    return np.repeat(colours[:, None, :], 3, axis=1)


def _flat(corners: np.ndarray, normals: np.ndarray, colours: np.ndarray) -> VesselMesh:
    """Unindexed flat-shaded triangles from corners (t, 3, 3), face normals (t, 3), corner colours (t, 3, 3)."""
    return VesselMesh(corners.reshape(-1, 3), np.repeat(normals, 3, axis=0), colours.reshape(-1, 3))


def _walls(outline: np.ndarray, top: float) -> np.ndarray:
    """Quads from each waterline edge (counter-clockwise seen from above) up to ``top``, facing out."""
    a, b = outline, np.roll(outline, -1, axis=0)
    a_top, b_top = a.copy(), b.copy()
    a[:, 2] = b[:, 2] = 0.0
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


def _house(v: np.ndarray, point: tuple[float, float, float], deck_z: float) -> np.ndarray:
    """A box from the deck to 1.5 m above ``point``: 6 % of the length aft of it to 1 m ahead, 70 % of the beam."""
    length, beam = np.ptp(v[:, 0]), np.ptp(v[:, 1])
    lo = np.array([point[0] - 0.06 * length, -0.35 * beam, deck_z])
    hi = np.array([point[0] + 1.0, 0.35 * beam, point[2] + 1.5])
    c = _box_corners(lo, hi)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (1, 5, 7, 3), (0, 2, 6, 4)]
    return np.array([[c[q[0]], c[q[1]], c[q[2]]] for q in quads] + [[c[q[0]], c[q[2]], c[q[3]]] for q in quads])


def _box_corners(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The eight corners (8, 3) of the box ``lo..hi``, z fastest, then y, then x."""
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
