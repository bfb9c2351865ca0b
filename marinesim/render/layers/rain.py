"""The rain pass: streaks of falling drops over the scene, as many as the visible drops of ``[environment]
rain_mm_h`` against a cloudburst's (:func:`~marinesim.render.daylight.visible_drops_m3`; ``shaders/rain.frag``, on
the sky pass's full-screen triangle)."""

from __future__ import annotations

import moderngl
import numpy as np

from marinesim.gl import Program, shader_source
from marinesim.render.layers.base import View, mat4
from marinesim.render.daylight import visible_drops_m3
from marinesim.scenario.model import MAX_RAIN_MM_H


LAYERS = 4
"""Cylinders of drops around the eye (``rain.frag``: 3 x 2.2^layer m out)."""


class RainLayer:
    """Draws the rain of the view's light over the scene, blended, each cylinder of drops at its own depth (depth test
    on, no depth writes)."""

    def __init__(self, ctx: moderngl.Context) -> None:
        self.ctx = ctx
        self.program = Program(ctx, "rain", vertex_shader=shader_source("sky.vert"),
                               fragment_shader=shader_source("rain.frag"))
        self.vao = ctx.vertex_array(self.program.gl, [])

    def draw(self, view: View, time_s: float) -> None:
        """The rain at ``time_s`` (s), one cylinder of drops a pass, each at its depth."""
        if view.light.rain_mm_h <= 0.0:
            return
        self.ctx.enable(moderngl.BLEND)
        self.ctx.blend_func = moderngl.DEFAULT_BLENDING
        self.ctx.depth_mask = False
        self.program.update(view.shared() | {
            "u_inverse_view_projection": mat4(np.linalg.inv(view.view_projection)),
            "u_view_projection": mat4(view.view_projection), "u_time": time_s % 3600.0,
            "u_drops": min(visible_drops_m3(view.light.rain_mm_h) / visible_drops_m3(MAX_RAIN_MM_H), 1.0),
            "u_wind": view.light.wind})
        for layer in range(LAYERS):
            self.program["u_layer"] = layer
            self.vao.render(moderngl.TRIANGLES, vertices=3)
        self.ctx.depth_mask = True
        self.ctx.disable(moderngl.BLEND)

    def release(self) -> None:
        self.vao.release()
        self.program.release()
