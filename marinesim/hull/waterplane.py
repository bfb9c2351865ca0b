"""The waterplane of a hull: its waterline loops (one per hull of a multihull) and the cells inside.

The waterline is the hull's section just below z = 0 (trimesh's mesh-plane intersection, chained
into closed loops), so a wetted-surface-only mesh, open exactly at z = 0, is cut as well as a
closed one, and a catamaran gives two loops, computed once per hull (a :class:`Hull` is immutable) for all who
draw or mask it. :func:`inside` is the one polygon mask of the project (the viewer's hull mask, the local solver's
obstacles): a cell is inside if it lies in any loop.
"""

from __future__ import annotations

import weakref

import numpy as np
from matplotlib.path import Path as PolygonPath

from marinesim.compiled import read_only
from marinesim.hull.mesh import Hull
from marinesim.hull.trimesh_held import trimesh

SECTION_BELOW = 1e-6
"""The section is taken this fraction of the hull's length below z = 0 (exactly at z = 0 a
wetted-surface mesh has only boundary edges, which a plane section does not cut cleanly)."""


_LOOPS: dict[int, tuple[np.ndarray, ...]] = {}
"""The loops of each live hull, by its id (a :class:`Hull` holds arrays: it has no hash); dropped with the hull."""


def waterline_loops(hull: Hull) -> tuple[np.ndarray, ...]:
    """The closed waterline loops (n, 2), m, body frame, each counter-clockwise seen from above and
    without its first point repeated; the largest first. Computed on the first call for ``hull``; later calls
    return the same read-only arrays."""
    loops = _LOOPS.get(id(hull))
    if loops is None:
        loops = _LOOPS[id(hull)] = read_only(*_section(hull))
        weakref.finalize(hull, _LOOPS.pop, id(hull), None)
    return loops


def _section(hull: Hull) -> list[np.ndarray]:
    """The loops of :func:`waterline_loops`, computed: trimesh's section of the hull, chained into loops."""
    mesh = trimesh.Trimesh(hull.vertices, hull.faces, process=False)
    depth = SECTION_BELOW * max(hull.overall_length_m, 1.0)
    segments = trimesh.intersections.mesh_plane(mesh, [0.0, 0.0, 1.0], [0.0, 0.0, -depth])
    if len(segments) == 0:
        return []
    loops = []
    for loop in trimesh.load_path(segments).discrete:
        points = np.asarray(loop, float)[:-1, :2] if np.allclose(loop[0], loop[-1]) else np.asarray(loop, float)[:, :2]
        if len(points) >= 3:
            loops.append(points if signed_area(points) > 0.0 else points[::-1])
    return sorted(loops, key=lambda p: -abs(signed_area(p)))


def signed_area(loop: np.ndarray) -> float:
    """Area (m^2) enclosed by a closed loop (n, 2): positive counter-clockwise (shoelace formula)."""
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def inside(loops: list[np.ndarray] | tuple[np.ndarray, ...], x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Whether each cell centre of the grid with columns at ``x`` and rows at ``y`` (m) lies inside any of
    the loops (n, 2): a (len(y), len(x)) boolean array."""
    xx, yy = np.meshgrid(x, y)
    points = np.column_stack([xx.ravel(), yy.ravel()])
    mask = np.zeros(points.shape[0], dtype=bool)
    for loop in loops:
        mask |= PolygonPath(np.asarray(loop, float)).contains_points(points)
    return mask.reshape(len(y), len(x))
