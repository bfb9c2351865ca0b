"""The hull in its 6-DOF pose, in the solver's grid: the displaced depth per cell.

The displaced depth ``d`` of a cell is the length of the vertical line through its centre that
lies inside the hull and below the mean free surface z = 0. For a closed mesh with outward
normals every such line enters through a face looking down and leaves through one looking up, so

    d = sum over the faces it crosses of  s * min(z, 0),    s = +1 facing up, -1 facing down,

which is an orthographic render from above with additive blending, one fragment per cell centre.
A wetted-surface-only mesh (a WAMIT .gdf, open at the waterline) gives the same: its missing lid
lies at z >= 0 and would add nothing.

The GPU rasterises; :func:`displaced_depth` is the same render in NumPy. Both place the hull's body
vertices with the same (4, 4) map in double precision (:func:`to_grid`; on the GPU in the vertex
shader, so a sub-step uploads a matrix, not the mesh) and snap them to 1/SUBPIXEL of a cell (the
rasteriser's own sub-pixel grid); the NumPy coverage test is exact integer arithmetic on them, so
the two cover the same cells (a snap could differ only at an exact tie, in the last bit). A cell
centre exactly on an edge shared by two faces is given to exactly one (a top-left rule); the
GPU's own tie rule may pick the other, which changes nothing because the two faces meet there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from marinesim.hull.mesh import Hull
from marinesim.pose import Pose
from marinesim.solver.spectral import SUBPIXEL


Placement = tuple[np.ndarray, float]
"""The hull in one pose on the grid: the (4, 4) map of :func:`to_grid` and the pose's weight (+1, or -1 for a
pose whose depth is subtracted)."""


def to_grid(pose: Pose, origin: tuple[float, float], cell: float) -> np.ndarray:
    """(4, 4) float64: a body point (m) in ``pose`` to ``(x, y, z, 1)``, x and y in grid units times SUBPIXEL
    on the grid whose corner (0, 0) is at ``origin`` (m, E frame) with cells of ``cell`` m, z the world z (m).
    Snapping x and y to integers (round half to even) gives the corners both renders use."""
    scale = np.diag([SUBPIXEL / cell, SUBPIXEL / cell, 1.0, 1.0])
    scale[:2, 3] = -np.asarray(origin, float) * SUBPIXEL / cell
    return scale @ pose.matrix()


@dataclass(frozen=True)
class Triangles:
    """Faces ready to rasterise in NumPy, indexed: corners in grid units snapped to 1/SUBPIXEL (integers),
    their world z (m) and the weight of the pose they belong to, and the faces as three corner indices."""

    xy: np.ndarray  # (v, 2) int64, grid units * SUBPIXEL; cell (i, j) is centred at (i + 1/2, j + 1/2)
    z: np.ndarray  # (v,) m
    weight: np.ndarray  # (v,)
    faces: np.ndarray  # (t, 3) indices into the corners


def hull_triangles(hull: Hull, placements: list[Placement]) -> Triangles:
    """The hull's faces in each placement: the body vertices through its :func:`to_grid` map, as the GPU's
    vertex shader does (``hull_depth.vert``, in double precision). Faces wholly above z = 0 are dropped
    (they add nothing)."""
    xy, z, weight, faces = [], [], [], []
    count = len(hull.vertices)
    for k, (matrix, w) in enumerate(placements):
        grid = hull.vertices @ matrix[:3, :3].T + matrix[:3, 3]          # (v, 3)
        corner_z = grid[:, 2][hull.faces]
        wet = np.minimum(np.minimum(corner_z[:, 0], corner_z[:, 1]), corner_z[:, 2]) < 0.0
        xy.append(np.rint(grid[:, :2]).astype(np.int64))
        z.append(grid[:, 2].astype(np.float32))
        weight.append(np.full(count, w, dtype=np.float32))
        faces.append(hull.faces[wet] + k * count)
    return Triangles(np.concatenate(xy), np.concatenate(z), np.concatenate(weight), np.concatenate(faces))


def displaced_depth(triangles: Triangles, size: int) -> np.ndarray:
    """The render of :mod:`footprint` in NumPy: (size, size) displaced depth (m), rows y, columns x."""
    depth = np.zeros((size, size))
    p = triangles.xy[triangles.faces]
    area = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
            - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    keep = area != 0
    up = area[keep] > 0                                       # counter-clockwise from above: facing up
    z, weight = triangles.z[triangles.faces][keep].astype(float), triangles.weight[triangles.faces[keep, 0]]
    p, weight = p[keep].copy(), weight * np.where(up, 1.0, -1.0)
    p[~up] = p[~up][:, [0, 2, 1]]                             # every face counter-clockwise
    z[~up] = z[~up][:, [0, 2, 1]]
    half = SUBPIXEL // 2
    lo = np.clip(np.ceil((p.min(axis=1) - half) / SUBPIXEL).astype(np.int64), 0, size)
    hi = np.clip(np.floor((p.max(axis=1) - half) / SUBPIXEL).astype(np.int64) + 1, 0, size)
    span = np.maximum(hi - lo, 0)
    count = span[:, 0] * span[:, 1]
    face = np.repeat(np.arange(len(p)), count)
    offset = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
    i = lo[face, 0] + offset % span[face, 0]
    j = lo[face, 1] + offset // span[face, 0]
    centre = np.stack([i * SUBPIXEL + half, j * SUBPIXEL + half], axis=1)
    inside = np.ones(len(face), dtype=bool)
    bary = []
    for a, b in ((1, 2), (2, 0), (0, 1)):                      # edge opposite corner 0, 1, 2
        pa, pb = p[face, a], p[face, b]
        edge = pb - pa
        e = edge[:, 0] * (centre[:, 1] - pa[:, 1]) - edge[:, 1] * (centre[:, 0] - pa[:, 0])
        top_left = (edge[:, 1] < 0) | ((edge[:, 1] == 0) & (edge[:, 0] > 0))
        inside &= (e > 0) | ((e == 0) & top_left)
        bary.append(e)
    total = bary[0] + bary[1] + bary[2]
    height = sum(b * z[face, n] for n, b in enumerate(bary)) / total
    value = weight[face] * np.minimum(height, 0.0)
    np.add.at(depth, (j[inside], i[inside]), value[inside])
    return depth
