"""The wetted surface: the part of a hull's triangles below the waterline z = 0.

Triangles crossing the waterline are cut exactly along z = 0 (one triangle, or a quadrilateral
split in two), keeping the vertex order so that the normals stay outward. Hydrostatics and the
Kelvin wake are integrals over this surface.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np


@dataclass(frozen=True)
class Surface:
    """Triangles as three corner arrays ``a, b, c`` of shape (m, 3), m, body frame, outward normals."""

    a: np.ndarray
    b: np.ndarray
    c: np.ndarray

    @property
    def vector_areas(self) -> np.ndarray:
        """n dS of each triangle, (m, 3) m^2: area times the outward unit normal."""
        return 0.5 * np.cross(self.b - self.a, self.c - self.a)

    @property
    def corners(self) -> np.ndarray:
        """Every triangle's corners stacked, (3 m, 3) m."""
        return np.concatenate([self.a, self.b, self.c])

    @property
    def areas(self) -> np.ndarray:
        return np.linalg.norm(self.vector_areas, axis=1)

    def __len__(self) -> int:
        return len(self.a)

    def integral(self, f: Callable[[np.ndarray], np.ndarray], normal: int | None = None) -> float:
        """Integral of ``f`` (at most quadratic in x, y, z) over the surface, exactly: of ``f n_normal dS``
        for ``normal`` = 0, 1, 2, of ``f dS`` when None. ``f`` maps points (..., 3) to values (...)."""
        midpoints = np.stack([self.a + self.b, self.b + self.c, self.c + self.a]) / 2.0
        mean = f(midpoints).mean(axis=0)  # the edge-midpoint rule is exact for quadratics
        weight = self.areas if normal is None else self.vector_areas[:, normal]
        return float(np.dot(mean, weight))


def wetted_surface(vertices: np.ndarray, faces: np.ndarray) -> Surface:
    """The triangles of ``faces`` below z = 0, cut at the waterline; degenerate ones dropped."""
    corners = vertices[faces]  # (m, 3 corners, 3)
    below = corners[:, :, 2] < 0.0
    count = below.sum(axis=1)
    above = (corners[:, :, 2] > 0.0).any(axis=1)
    pieces = [corners[(count > 0) & ~above]]
    for rotation in range(3):
        rotated = np.roll(corners, -rotation, axis=1)
        first_below = np.roll(below, -rotation, axis=1)
        one = (count == 1) & above & first_below[:, 0]  # rotated so the wet corner comes first
        a, b, c = (rotated[one, k] for k in range(3))
        pieces.append(np.stack([a, _cut(a, b), _cut(a, c)], axis=1))
        two = (count == 2) & above & first_below[:, 0] & first_below[:, 1]  # the dry corner last
        a, b, c = (rotated[two, k] for k in range(3))
        bc, ca = _cut(b, c), _cut(a, c)
        pieces.append(np.stack([a, b, bc], axis=1))
        pieces.append(np.stack([a, bc, ca], axis=1))
    triangles = np.concatenate(pieces)
    doubled = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    scale = max(float(np.ptp(vertices, axis=0).max()), 1e-300) if len(vertices) else 1.0
    keep = np.linalg.norm(doubled, axis=1) > 1e-12 * scale * scale
    return Surface(*(triangles[keep, k].copy() for k in range(3)))


def _cut(wet: np.ndarray, dry: np.ndarray) -> np.ndarray:
    """The point where the edge from ``wet`` (z < 0) to ``dry`` (z >= 0) crosses z = 0."""
    t = wet[:, 2] / (wet[:, 2] - dry[:, 2])
    point = wet + t[:, None] * (dry - wet)
    point[:, 2] = 0.0
    return point
