"""The ocean pass: rings of vertices around the camera out to ``OCEAN_RADIUS_M``, displaced and shaded by the
layers it samples (``shaders/ocean.*``, ``surface.glsl``, ``sky.glsl``)."""

from __future__ import annotations

import math
from collections.abc import Sequence

import moderngl
import numpy as np

from marinesim.gl import Program
from marinesim.pose import Pose
from marinesim.render.layers.base import Sampled, View, mat4
from marinesim.sea.cascades import Tile

OCEAN_RADIUS_M = 20_000.0
RING_SEGMENTS = 192
INNER_SPACING_M = 0.5
FOAM_J_START, FOAM_J_FULL = 0.90, 0.60
"""Jacobian of the surface where foam starts and where it covers the surface fully."""


def ring_grid(radius_m: float, segments: int, inner_spacing_m: float) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``segments`` vertices whose spacing grows with the radius (cells stay square),
    from ``inner_spacing_m`` out to ``radius_m``, and a disc in the middle. Returns float32 rows
    (x, y, spacing) in m and uint32 triangle indices."""
    step = 2.0 * math.pi / segments
    radii = [0.0]
    r = inner_spacing_m / step
    uniform_rings = int(r / inner_spacing_m)
    radii += list(inner_spacing_m * np.arange(1, uniform_rings + 1))
    r = radii[-1]
    while r < radius_m:
        r *= 1.0 + step
        radii.append(r)
    radii = np.array(radii[1:])
    angle = np.arange(segments) * step
    x = (radii[:, None] * np.cos(angle)).ravel()
    y = (radii[:, None] * np.sin(angle)).ravel()
    spacing = np.repeat(np.maximum(radii * step, inner_spacing_m), segments)
    vertices = np.c_[np.r_[0.0, x], np.r_[0.0, y], np.r_[inner_spacing_m, spacing]].astype(np.float32)
    ring = np.arange(segments)
    following = (ring + 1) % segments
    triangles = [np.c_[np.zeros(segments, int), ring + 1, following + 1]]
    for i in range(len(radii) - 1):
        a, b = 1 + i * segments, 1 + (i + 1) * segments
        triangles.append(np.c_[a + ring, b + ring, b + following])
        triangles.append(np.c_[a + ring, b + following, a + following])
    return vertices, np.concatenate(triangles).astype(np.uint32)


class OceanLayer:
    """The water over ``tiles`` cascades of ``n``^2 texels; ``foam_on`` False draws no foam (comparisons)."""

    def __init__(self, ctx: moderngl.Context, tiles: Sequence[Tile], n: int, foam_on: bool = True) -> None:
        self.foam_on = foam_on
        self.program = Program.from_files(ctx, "ocean", TILES=len(tiles), TILE_LOD=f"{math.log2(n):.1f}",
                                          FOAM_J_START=FOAM_J_START, FOAM_J_FULL=FOAM_J_FULL)
        grid, indices = ring_grid(OCEAN_RADIUS_M, RING_SEGMENTS, INNER_SPACING_M)
        self._vbo, self._ibo = ctx.buffer(grid.tobytes()), ctx.buffer(indices.tobytes())
        self.vao = ctx.vertex_array(self.program.gl, [(self._vbo, "3f", "in_grid")], self._ibo)
        # as bytes: moderngl takes a one-element array uniform only as a scalar
        self.program["u_tile_size"] = np.array([t.size for t in tiles], np.float32).tobytes()
        self.program["u_tile_spacing"] = np.array([t.spacing for t in tiles], np.float32).tobytes()

    def draw(self, view: View, pose: Pose, sampled: Sequence[Sampled]) -> None:
        """The rings around the eye, the vessel frame at ``pose``'s track point and heading; the ``sampled``
        layers bound to consecutive texture units from 0."""
        centre = np.floor(view.eye.position[:2] / (4.0 * INNER_SPACING_M)) * (4.0 * INNER_SPACING_M)
        values = view.shared() | {"u_view_projection": mat4(view.view_projection), "u_centre": tuple(centre),
                                  "u_track": (pose.x, pose.y, pose.heading), "u_foam_on": float(self.foam_on),
                                  "u_wind": view.light.wind}
        unit = 0
        for layer in sampled:
            values |= layer.bind(unit)
            unit += layer.units
        self.program.update(values)
        self.vao.render(moderngl.TRIANGLES)

    def release(self) -> None:
        for resource in (self.vao, self._vbo, self._ibo, self.program):
            resource.release()
