"""No water inside the hull: the waterplane (inside the waterline loops) rasterised in the vessel frame; its mip
levels blur it into the ring where the ocean draws foam against the hull. With it the ocean gets what it needs
for the wash astern: the stern, the beam and the speed."""

from __future__ import annotations

from collections.abc import Callable

import moderngl
import numpy as np

from marinesim.hull import Hull
from marinesim.hull.waterplane import inside, waterline_loops
from marinesim.render.layers.base import blank_texture

HULL_MASK_CELLS = (512, 128)
"""Mask cells along (x) and across (y) the waterplane's padded bounding box."""

CONTACT_REACH_M = 10.0
"""How far outside the waterline the mask reaches: the foam ring against the hull lies within it."""

Rect = tuple[float, float, float, float]


def waterplane_cells(hull: Hull) -> tuple[np.ndarray, Rect]:
    """The cells inside the waterplane, (ny, nx) bool over the waterline loops' bounding box padded by 2 % a side
    and :data:`CONTACT_REACH_M`, shrunk by one cell so that the water meets the hull instead of leaving a gap
    beside it; and the grid's rect (x, y of its corner, 1 / width, 1 / height; m, vessel frame)."""
    loops = waterline_loops(hull)
    corners = np.concatenate(loops)
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    pad = 0.02 * (hi - lo) + CONTACT_REACH_M
    lo, hi = lo - pad, hi + pad
    nx, ny = HULL_MASK_CELLS
    x = lo[0] + (np.arange(nx) + 0.5) * (hi[0] - lo[0]) / nx
    y = lo[1] + (np.arange(ny) + 0.5) * (hi[1] - lo[1]) / ny
    cells = inside(loops, x, y)
    cells[1:-1, 1:-1] &= cells[:-2, 1:-1] & cells[2:, 1:-1] & cells[1:-1, :-2] & cells[1:-1, 2:]
    return cells, (lo[0], lo[1], 1.0 / (hi[0] - lo[0]), 1.0 / (hi[1] - lo[1]))


class HullMaskLayer:
    """The waterplane mask of ``hull`` (1 inside), or an empty rect that masks nothing without a hull; ``speed``
    gives the vessel's speed now (m/s)."""

    units = 1

    def __init__(self, ctx: moderngl.Context, hull: Hull | None, speed: Callable[[], float] = lambda: 0.0) -> None:
        self.cells: np.ndarray | None = None
        self.speed = speed
        if hull is None:
            self.texture, self.rect, self._wash = blank_texture(ctx), (0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
            return
        self.cells, self.rect = waterplane_cells(hull)
        ny, nx = self.cells.shape
        self.texture = ctx.texture((nx, ny), 1, (self.cells * 255).astype(np.uint8).tobytes())
        self.texture.repeat_x = self.texture.repeat_y = False
        self.texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
        self.texture.build_mipmaps()
        v = np.asarray(hull.vertices, float)
        self._wash = (float(v[:, 0].min()), 0.5 * float(np.ptp(v[:, 1])), 1.0)

    def bind(self, unit: int) -> dict[str, object]:
        self.texture.use(unit)
        stern, half_beam, hull = self._wash
        return {"u_hull_mask": unit, "u_hull_rect": self.rect, "u_wash": (stern, half_beam, self.speed(), hull)}

    def release(self) -> None:
        self.texture.release()
