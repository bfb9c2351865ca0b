"""The hull in its 6-DOF pose, in the solver's grid: the displaced depth per cell.

The displaced depth ``d`` of a cell is the length of the vertical line through its centre that
lies inside the hull and below the mean free surface z = 0. For a closed mesh with outward
normals every such line enters through a face looking down and leaves through one looking up, so

    d = sum over the faces it crosses of  s * min(z, 0),    s = +1 facing up, -1 facing down,

which is an orthographic render from above with additive blending, one fragment per cell centre.
A wetted-surface-only mesh (a WAMIT .gdf, open at the waterline) gives the same: its missing lid
lies at z >= 0 and would add nothing.

The GPU rasterises; :func:`displaced_depth` is the same render in NumPy. Both see the same vertex
positions, snapped here to 1/SUBPIXEL of a cell (the rasteriser's own sub-pixel grid), and the
NumPy coverage test is exact integer arithmetic on them, so the two cover the same cells. A cell
centre exactly on an edge shared by two faces is given to exactly one (a top-left rule); the
GPU's own tie rule may pick the other, which changes nothing because the two faces meet there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from marinesim.hull.mesh import Hull
from marinesim.pose import Pose
from marinesim.solver.spectral import SUBPIXEL


@dataclass(frozen=True)
class Triangles:
    """Faces ready to rasterise: corners in grid units snapped to 1/SUBPIXEL (integers), their
    world z (m), and a weight per face (+1, or -1 for a pose whose depth is subtracted)."""

    xy: np.ndarray  # (t, 3, 2) int64, grid units * SUBPIXEL; cell (i, j) is centred at (i + 1/2, j + 1/2)
    z: np.ndarray  # (t, 3) m
    weight: np.ndarray  # (t,)

    def vertex_data(self) -> np.ndarray:
        """(3 t, 4) float32 rows ``x, y, z, weight`` per corner, x and y in cells (exact in float32)."""
        t = len(self.z)
        rows = np.empty((t, 3, 4), dtype=np.float32)
        rows[..., :2] = self.xy / SUBPIXEL
        rows[..., 2] = self.z
        rows[..., 3] = self.weight[:, None]
        return rows.reshape(-1, 4)


def hull_triangles(hull: Hull, poses: list[tuple[Pose, float]], origin: tuple[float, float],
                   cell: float) -> Triangles:
    """The hull's faces in each ``(pose, weight)`` placed on the grid whose corner (0, 0) is at
    ``origin`` (m, E frame). Faces wholly above z = 0 are dropped (they add nothing)."""
    xy, z, weight = [], [], []
    for pose, w in poses:
        corners = pose.world(hull.vertices)[hull.faces]                  # (t, 3, 3)
        wet = corners[..., 2].min(axis=1) < 0.0
        corners = corners[wet]
        grid = (corners[..., :2] - np.asarray(origin)) / cell
        xy.append(np.rint(grid * SUBPIXEL).astype(np.int64))
        z.append(corners[..., 2].astype(np.float32))
        weight.append(np.full(len(corners), w, dtype=np.float32))
    return Triangles(np.concatenate(xy), np.concatenate(z), np.concatenate(weight))


def displaced_depth(triangles: Triangles, size: int) -> np.ndarray:
    """The render of :mod:`footprint` in NumPy: (size, size) displaced depth (m), rows y, columns x."""
    depth = np.zeros((size, size))
    p = triangles.xy
    area = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
            - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    keep = area != 0
    up = area[keep] > 0                                       # counter-clockwise from above: facing up
    p, z, weight = p[keep].copy(), triangles.z[keep].astype(float), triangles.weight[keep] * np.where(up, 1.0, -1.0)
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
