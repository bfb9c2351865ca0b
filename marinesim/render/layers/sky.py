"""The sky pass: one full-screen triangle, analytic sky, sun and haze below the horizon (``shaders/sky.*``)."""

from __future__ import annotations

import moderngl
import numpy as np

from marinesim.gl import Program
from marinesim.render.layers.base import View, mat4


class SkyLayer:
    """Draws the sky behind everything, without depth testing."""

    def __init__(self, ctx: moderngl.Context) -> None:
        self.ctx = ctx
        self.program = Program.from_files(ctx, "sky")
        self.vao = ctx.vertex_array(self.program.gl, [])

    def draw(self, view: View) -> None:
        self.ctx.disable(moderngl.DEPTH_TEST)
        self.program.update(view.shared() | {
            "u_inverse_view_projection": mat4(np.linalg.inv(view.view_projection))})
        self.vao.render(moderngl.TRIANGLES, vertices=3)
        self.ctx.enable(moderngl.DEPTH_TEST)

    def release(self) -> None:
        self.vao.release()
        self.program.release()
