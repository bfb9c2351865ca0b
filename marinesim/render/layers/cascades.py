"""The ocean's cascades on the GPU: each tile's displacement, height and Jacobian, and its slopes,
as texture arrays with mipmaps (one layer per tile), written by the GPU synthesis
(:mod:`~marinesim.render.layers.synthesis`) or uploaded from the CPU's fields."""

from __future__ import annotations

from collections.abc import Sequence

import moderngl
import numpy as np

from marinesim.render.layers.base import tile_texture_array
from marinesim.sea.ocean import TileFields


class CascadeLayer:
    """``tiles`` cascades of ``n`` x ``n`` texels: ``fields`` (displacement x, y, height in m, Jacobian) and
    ``slopes`` (d eta/dx, d eta/dy), E frame."""

    units = 2

    def __init__(self, ctx: moderngl.Context, tiles: int, n: int) -> None:
        self.fields = tile_texture_array(ctx, n, tiles, 4)
        self.slopes = tile_texture_array(ctx, n, tiles, 2)
        self._packed = np.empty((tiles, n, n, 4), np.float32)
        self._packed_slopes = np.empty((tiles, n, n, 2), np.float32)

    def upload(self, fields: Sequence[TileFields]) -> None:
        """Write one frame's fields (one per tile) and build the mipmaps."""
        packed, slopes = self._packed, self._packed_slopes
        for i, f in enumerate(fields):
            packed[i, ..., 0], packed[i, ..., 1] = f.displacement_x, f.displacement_y
            packed[i, ..., 2], packed[i, ..., 3] = f.height, f.jacobian
            slopes[i, ..., 0], slopes[i, ..., 1] = f.slope_x, f.slope_y
        self.fields.write(packed)  # buffer protocol: no copy
        self.slopes.write(slopes)
        self.build_mipmaps()

    def build_mipmaps(self) -> None:
        """The mip levels of both arrays from their level 0 (on the GPU)."""
        self.fields.build_mipmaps()
        self.slopes.build_mipmaps()

    def bind(self, unit: int) -> dict[str, object]:
        self.fields.use(unit)
        self.slopes.use(unit + 1)
        return {"u_cascades": unit, "u_slopes": unit + 1}

    def release(self) -> None:
        self.fields.release()
        self.slopes.release()
