"""No water inside the hull: the waterplane (inside the waterline loops) rasterised in the vessel frame."""

from __future__ import annotations

import moderngl
import numpy as np

from marinesim.hull import Hull
from marinesim.hull.waterplane import inside, waterline_loops
from marinesim.render.layers.base import blank_texture

HULL_MASK_CELLS = (512, 128)
"""Mask cells along (x) and across (y) the waterplane's padded bounding box."""

Rect = tuple[float, float, float, float]


def waterplane_cells(hull: Hull) -> tuple[np.ndarray, Rect]:
    """The cells inside the waterplane, (ny, nx) bool over the waterline loops' bounding box padded by 2 % a side,
    shrunk by one cell so that the water meets the hull instead of leaving a gap beside it; and the grid's rect
    (x, y of its corner, 1 / width, 1 / height; m, vessel frame)."""
    loops = waterline_loops(hull)
    corners = np.concatenate(loops)
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    pad = 0.02 * (hi - lo)
    lo, hi = lo - pad, hi + pad
    nx, ny = HULL_MASK_CELLS
    x = lo[0] + (np.arange(nx) + 0.5) * (hi[0] - lo[0]) / nx
    y = lo[1] + (np.arange(ny) + 0.5) * (hi[1] - lo[1]) / ny
    cells = inside(loops, x, y)
    cells[1:-1, 1:-1] &= cells[:-2, 1:-1] & cells[2:, 1:-1] & cells[1:-1, :-2] & cells[1:-1, 2:]
    return cells, (lo[0], lo[1], 1.0 / (hi[0] - lo[0]), 1.0 / (hi[1] - lo[1]))


class HullMaskLayer:
    """The waterplane mask of ``hull`` (1 inside), or an empty rect that masks nothing without a hull."""

    units = 1

    def __init__(self, ctx: moderngl.Context, hull: Hull | None) -> None:
        self.cells: np.ndarray | None = None
        if hull is None:
            self.texture, self.rect = blank_texture(ctx), (0.0, 0.0, 0.0, 0.0)
            return
        self.cells, self.rect = waterplane_cells(hull)
        ny, nx = self.cells.shape
        self.texture = ctx.texture((nx, ny), 1, (self.cells * 255).astype(np.uint8).tobytes())
        self.texture.repeat_x = self.texture.repeat_y = False

    def bind(self, unit: int) -> dict[str, object]:
        self.texture.use(unit)
        return {"u_hull_mask": unit, "u_hull_rect": self.rect}

    def release(self) -> None:
        self.texture.release()
