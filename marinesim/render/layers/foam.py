"""Foam memory: each cascade texel's Jacobian held at its lowest and relaxing back to 1 (``shaders/foam.comp``)."""

from __future__ import annotations

import math

import moderngl
import numpy as np

from marinesim.gl import GROUP, Program
from marinesim.render.layers.base import tile_texture_array
from marinesim.render.layers.cascades import CascadeLayer

FOAM_TAU_S = 4.0
"""The held Jacobian relaxes back to 1 as exp(-t / tau) once the surface stops folding (foam.comp)."""


class FoamLayer:
    """The held Jacobian and its square per cascade texel (``tiles`` layers of ``n`` x ``n``), mipmapped so that
    a pixel's footprint gives their mean and variance."""

    units = 1

    def __init__(self, ctx: moderngl.Context, tiles: int, n: int) -> None:
        self.ctx, self._tiles, self._n = ctx, tiles, n
        self.held = tile_texture_array(ctx, n, tiles, 2)
        self.held.write(np.ones((tiles, n, n, 2), np.float32).tobytes())  # nothing folded yet
        self.program = Program.from_files(ctx, "foam", compute=True)

    def update(self, cascades: CascadeLayer, dt: float) -> None:
        """Hold the cascades' current Jacobians, the older ones relaxed over ``dt`` (s)."""
        cascades.fields.use(0)
        self.held.bind_to_image(0, read=True, write=True)
        self.program.update({"u_cascades": 0, "u_decay": math.exp(-dt / FOAM_TAU_S)})
        self.program.run(self._n // GROUP, self._n // GROUP, self._tiles)
        self.ctx.memory_barrier()
        self.held.build_mipmaps()

    def bind(self, unit: int) -> dict[str, object]:
        self.held.use(unit)
        return {"u_foam": unit}

    def release(self) -> None:
        self.held.release()
        self.program.release()
