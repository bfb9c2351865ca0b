"""The local flow about a moving hull: the water raised ahead of the stem and at the stern, lowered along the
shoulders. It is the zero-Froude (double-body) part of the steady field; the waves are A(theta)'s
(:mod:`marinesim.wake.field`).

Sources of strength ``m = U n_x dS`` on the wetted surface (the thin-ship sources A(theta) is made of) and
their images above the still water level (a rigid lid: the limit of the linear free-surface condition as
U^2 kx^2 << g k) give at z = 0 the horizontal velocity

    (u, v) = sum_j m_j (x - x_j, y - y_j) / (2 pi r_j^3),   r_j^2 = (x - x_j)^2 + (y - y_j)^2 + z_j^2,

and the water stands at Bernoulli's head ``zeta = (U^2 - (U - u)^2 - v^2) / (2 g)`` (the hull moving +x through
still water), never above the stagnation head U^2 / (2 g). Its linear part ``U u / g`` is the low-Froude limit
of Michell's whole linear field, ``zeta_hat = -i U^2 kx M_hat / (g k - U^2 kx^2) -> -i (U^2 / g)(kx / k) M_hat``:
the near field that the far-field waves leave out.

The sum is one FFT per depth layer on a grid about the hull: the transform of ``x / r^3`` at depth h is
``-2 pi i kx exp(-k h) / k``. Triangles are split until their sides are under two cells, each piece a source at
its centre spread over the four nearest cells and the two nearest layers (depths growing by
:data:`LAYER_RATIO` from one cell; a source nearer the surface than a cell is taken a cell down, which rounds
off the stem's singular head at the grid's scale). The grid is padded to twice its size, so the sources'
images in the FFT's periodic copies lie over a hull length away, and the field is tapered to the still level
over the outer quarter of its margin.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.constants import G
from marinesim.errors import ParameterError, require_memory, require_positive
from marinesim.hull import Surface

CELLS_PER_LENGTH = 400
"""Grid cells along the hull's length."""
MARGIN_LENGTHS = 0.5
"""The grid reaches this many hull lengths beyond the hull on every side."""
LAYER_RATIO = 1.5
"""Each depth layer this many times deeper than the one above (the first a cell down)."""
MAX_PIECES = 2_000_000
"""Most sources the split triangles may make."""


@dataclass(frozen=True)
class LocalFlow:
    """The local flow's elevation (ny, nx) (m) on a grid of ``cell_m`` whose first cell centre is at
    (``x0``, ``y0``) (m, vessel frame: x forward, y to port), and the velocity (u, v) there (m/s)."""

    elevation: np.ndarray
    u: np.ndarray
    v: np.ndarray
    x0: float
    y0: float
    cell_m: float

    def axes(self) -> tuple[np.ndarray, np.ndarray]:
        """The cell centres' x (nx,) and y (ny,) (m, vessel frame)."""
        ny, nx = self.elevation.shape
        return self.x0 + self.cell_m * np.arange(nx), self.y0 + self.cell_m * np.arange(ny)

    def sample(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """The elevation (m) bilinearly at points ``x`` (n,) and rows ``y`` (m,) of a grid: (m, n); 0 outside."""
        ny, nx = self.elevation.shape
        fx, fy = (np.asarray(x, float) - self.x0) / self.cell_m, (np.asarray(y, float) - self.y0) / self.cell_m
        ix, iy = np.clip(np.floor(fx).astype(int), 0, nx - 2), np.clip(np.floor(fy).astype(int), 0, ny - 2)
        wx, wy = np.clip(fx - ix, 0.0, 1.0), np.clip(fy - iy, 0.0, 1.0)
        e = self.elevation
        out = ((1 - wy)[:, None] * ((1 - wx) * e[iy][:, ix] + wx * e[iy][:, ix + 1])
               + wy[:, None] * ((1 - wx) * e[iy + 1][:, ix] + wx * e[iy + 1][:, ix + 1]))
        inside = ((fy >= 0) & (fy <= ny - 1))[:, None] & ((fx >= 0) & (fx <= nx - 1))[None, :]
        return np.where(inside, out, 0.0)


def sources(surface: Surface, cell_m: float) -> tuple[np.ndarray, np.ndarray]:
    """The surface's triangles split until their sides are under two cells: the pieces' centres (n, 3) (m) and
    their ``n_x dS`` (n,) (m^2)."""
    sides = np.stack([np.linalg.norm(surface.b - surface.a, axis=1), np.linalg.norm(surface.c - surface.b, axis=1),
                      np.linalg.norm(surface.a - surface.c, axis=1)]).max(axis=0)
    splits = np.maximum(np.ceil(sides / (2.0 * cell_m)).astype(int), 1)
    pieces = int(np.sum(splits ** 2))
    if pieces > MAX_PIECES:
        raise ParameterError(f"the hull splits into {pieces} sources at a {cell_m:.3g} m cell (at most {MAX_PIECES})")
    weight = surface.vector_areas[:, 0]
    centres, strengths = [], []
    for n in np.unique(splits):
        on = splits == n
        i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
        up = np.c_[(i + 1 / 3).ravel(), (j + 1 / 3).ravel()][(i + j).ravel() < n]       # n(n+1)/2 upright pieces
        down = np.c_[(i + 2 / 3).ravel(), (j + 2 / 3).ravel()][(i + j).ravel() < n - 1]  # n(n-1)/2 inverted ones
        bary = np.concatenate([up, down]) / n                                             # (n^2, 2): weights of b, c
        a, b, c = surface.a[on], surface.b[on], surface.c[on]
        points = a[:, None] + bary[None, :, :1] * (b - a)[:, None] + bary[None, :, 1:] * (c - a)[:, None]
        centres.append(points.reshape(-1, 3))
        strengths.append(np.repeat(weight[on] / n**2, n * n))
    return np.concatenate(centres), np.concatenate(strengths)


def local_flow(surface: Surface, speed_m_s: float, g: float = G) -> LocalFlow:
    """The local flow of ``surface`` (the wetted hull, body frame) moving at ``speed_m_s`` (m/s)."""
    speed = require_positive("speed", speed_m_s)
    corners = surface.corners
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    length = float(hi[0] - lo[0])
    cell = length / CELLS_PER_LENGTH
    margin = MARGIN_LENGTHS * length
    nx = int(math.ceil((hi[0] - lo[0] + 2 * margin) / cell)) + 1
    ny = int(math.ceil((hi[1] - lo[1] + 2 * margin) / cell)) + 1
    require_memory(f"a local-flow grid of {2 * nx} x {2 * ny}", 64 * 4 * nx * ny)
    x0, y0 = float(lo[0] - margin), float(lo[1] - margin)
    points, strength = sources(surface, cell)
    strength = strength * speed                                      # m = U n_x dS, m^3/s
    depth = np.maximum(-points[:, 2], cell)
    count = max(int(math.ceil(math.log(depth.max() / cell, LAYER_RATIO))), 1) + 1    # two at least
    layers = cell * LAYER_RATIO ** np.arange(count)
    upper = np.clip(np.searchsorted(layers, depth, side="right") - 1, 0, len(layers) - 2)
    w_lower = np.clip((depth - layers[upper]) / (layers[upper + 1] - layers[upper]), 0.0, 1.0)

    shape = (2 * ny, 2 * nx)
    kx = 2.0 * math.pi * np.fft.rfftfreq(shape[1], cell)[None, :]
    ky = 2.0 * math.pi * np.fft.fftfreq(shape[0], cell)[:, None]
    k = np.hypot(kx, ky)
    k[0, 0] = 1.0
    fx, fy = (points[:, 0] - x0) / cell, (points[:, 1] - y0) / cell
    ix, iy = np.floor(fx).astype(int), np.floor(fy).astype(int)
    wx, wy = fx - ix, fy - iy
    u_hat = np.zeros(k.shape, complex)
    v_hat = np.zeros(k.shape, complex)
    for layer in range(len(layers)):
        share = np.where(upper == layer, 1.0 - w_lower, 0.0) + np.where(upper + 1 == layer, w_lower, 0.0)
        if not share.any():
            continue
        on = share > 0.0
        grid = np.zeros(shape[0] * shape[1])
        for dx, dy, w in ((0, 0, (1 - wx) * (1 - wy)), (1, 0, wx * (1 - wy)), (0, 1, (1 - wx) * wy),
                          (1, 1, wx * wy)):
            cells = (iy[on] + dy) * shape[1] + ix[on] + dx
            grid += np.bincount(cells, (strength * share * w)[on], grid.size)
        grid = grid.reshape(shape)
        decay = np.fft.rfft2(grid) * np.exp(-k * layers[layer]) / k
        u_hat += -1j * kx * decay
        v_hat += -1j * ky * decay
    u = np.fft.irfft2(u_hat, shape)[:ny, :nx] / cell**2
    v = np.fft.irfft2(v_hat, shape)[:ny, :nx] / cell**2
    elevation = (speed**2 - (speed - u) ** 2 - v**2) / (2.0 * g) * _edge_taper(ny, nx, margin / cell)
    return LocalFlow(elevation, u, v, x0, y0, cell)


def _edge_taper(ny: int, nx: int, margin_cells: float) -> np.ndarray:
    """(ny, nx): 1 inside, falling smoothly to 0 over the outer quarter of the margin, so that the field ends
    at the still level where the grid does (its 1 / r^2 tail is a few cm there)."""
    def ramp(n: int) -> np.ndarray:
        r = np.clip(np.minimum(np.arange(n), n - 1 - np.arange(n)) / (0.25 * margin_cells), 0.0, 1.0)
        return r * r * (3.0 - 2.0 * r)
    return ramp(ny)[:, None] * ramp(nx)[None, :]
