"""The spray pass: the puffs of :mod:`~marinesim.session.spray` as soft sprites of white water, lit like the foam,
hazed with distance, each as wide as its puff (``shaders/spray.*``)."""

from __future__ import annotations

import math

import moderngl
import numpy as np

from marinesim.gl import Program
from marinesim.render.layers.base import View, mat4
from marinesim.session.spray import LIFE_S, MAX_PUFFS, Puffs

SIZE_M = np.array([1.5, 3.0])
"""Diameter (m) of a bow-spray puff and of a spindrift puff when it leaves the water."""
SPREAD_M_S = np.array([3.0, 2.0])
"""How fast each kind of puff widens (m/s) as its drops scatter."""
OPACITY = np.array([0.7, 0.3])
"""Opacity at the centre of a fresh puff: overlapping puffs make a sheet of spray that hides what is behind it;
spindrift veils it."""


def sprites(puffs: Puffs) -> np.ndarray:
    """(puffs, 5) float32 rows: E-frame position (m), diameter (m), opacity (fading as the puff ages)."""
    kind = puffs.kind.astype(int)
    size = SIZE_M[kind] + SPREAD_M_S[kind] * puffs.age
    opacity = OPACITY[kind] * (1.0 - puffs.age / LIFE_S) ** 2
    return np.c_[puffs.position, size, opacity].astype(np.float32)


class SprayLayer:
    """Draws puffs blended over the scene, behind what hides them (depth test on, no depth writes)."""

    def __init__(self, ctx: moderngl.Context) -> None:
        self.ctx = ctx
        self.program = Program.from_files(ctx, "spray")
        self._vbo = ctx.buffer(reserve=MAX_PUFFS * 5 * 4)
        self.vao = ctx.vertex_array(self.program.gl, [(self._vbo, "3f 1f 1f", "in_position", "in_size",
                                                      "in_opacity")])

    def draw(self, view: View, puffs: Puffs, height_px: int) -> None:
        if not len(puffs):
            return
        rows = sprites(puffs)
        self._vbo.write(rows.tobytes())
        self.ctx.enable(moderngl.PROGRAM_POINT_SIZE | moderngl.BLEND)
        self.ctx.blend_func = moderngl.DEFAULT_BLENDING
        self.ctx.depth_mask = False
        pixels_per_m = height_px / (2.0 * math.tan(math.radians(view.eye.fov_y_deg) / 2.0))
        self.program.update(view.shared() | {"u_view_projection": mat4(view.view_projection),
                                             "u_pixels_per_m": pixels_per_m})
        self.vao.render(moderngl.POINTS, vertices=len(rows))
        self.ctx.depth_mask = True
        self.ctx.disable(moderngl.PROGRAM_POINT_SIZE | moderngl.BLEND)

    def release(self) -> None:
        for resource in (self.vao, self._vbo, self.program):
            resource.release()
