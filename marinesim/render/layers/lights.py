"""The navigation lights pass: each light a glowing point whose size and strength follow the illuminance it gives
at the eye, through its sector and the haze (:mod:`~marinesim.render.nav_lights`; ``shaders/lights.*``)."""

from __future__ import annotations


import moderngl
import numpy as np

from marinesim.gl import Program
from marinesim.pose import Pose
from marinesim.render.layers.base import View, mat4
from marinesim.render.nav_lights import THRESHOLD_LUX, NavLight, illuminance_lux, lit, sector_weight

CORE_PX, PX_PER_DECADE = 3.0, 3.0
"""A light at the threshold is a point of CORE_PX; each decade of illuminance above it widens its glow by
PX_PER_DECADE (pixels at a 1080-line frame, scaled with the frame's height)."""


class NavLightsLayer:
    """Draws ``lights`` (body frame) carried by the vessel's pose, additively, behind what hides them."""

    def __init__(self, ctx: moderngl.Context, lights: list[NavLight]) -> None:
        self.ctx, self.lights = ctx, lights
        self.program = Program.from_files(ctx, "lights")
        self._vbo = ctx.buffer(reserve=max(len(lights), 1) * 8 * 4)
        self.vao = ctx.vertex_array(self.program.gl, [(self._vbo, "3f 3f 1f 1f", "in_position", "in_colour",
                                                      "in_size", "in_strength")])

    def sprites(self, view: View, pose: Pose, height_px: int) -> np.ndarray:
        """(lights, 8) float32 rows: E-frame position (m), colour, glow diameter (px) and strength (0..1)."""
        if not self.lights or not lit(view.light.sun[2], view.light.visibility_m):
            return np.zeros((0, 8), np.float32)
        to_world = pose.matrix()
        body = np.array([light.position for light in self.lights])
        world = body @ to_world[:3, :3].T + to_world[:3, 3]
        to_eye = (view.eye.position - world) @ to_world[:3, :3]    # body frame
        bearing = np.degrees(np.arctan2(to_eye[:, 1], to_eye[:, 0]))
        distance = np.linalg.norm(to_eye, axis=1)
        lux = np.array([illuminance_lux(light.intensity_cd, d, view.light.visibility_m) * sector_weight(light, b)
                        for light, d, b in zip(self.lights, distance, bearing)])
        decades = np.log10(np.maximum(lux, 1e-30) / THRESHOLD_LUX)
        scale = height_px / 1080.0
        size = (CORE_PX + PX_PER_DECADE * np.clip(decades, 0.0, None)) * max(scale, 0.5)
        strength = np.clip(decades / 1.5, 0.0, 1.0)
        colours = np.array([light.colour for light in self.lights])
        return np.c_[world, colours, size, strength].astype(np.float32)

    def draw(self, view: View, pose: Pose, height_px: int) -> None:
        rows = self.sprites(view, pose, height_px)
        rows = rows[rows[:, 7] > 0.0]
        if not len(rows):
            return
        self._vbo.write(rows.tobytes())
        self.ctx.enable(moderngl.PROGRAM_POINT_SIZE | moderngl.BLEND)
        self.ctx.blend_func = moderngl.ONE, moderngl.ONE
        self.ctx.depth_mask = False
        self.program.update({"u_view_projection": mat4(view.view_projection)})
        self.vao.render(moderngl.POINTS, vertices=len(rows))
        self.ctx.depth_mask = True
        self.ctx.blend_func = moderngl.DEFAULT_BLENDING
        self.ctx.disable(moderngl.PROGRAM_POINT_SIZE | moderngl.BLEND)

    def release(self) -> None:
        for resource in (self.vao, self._vbo, self.program):
            resource.release()


