"""FFT cascades: square tiles of different sizes that split wave-number space by |k|.

Each tile of size L (m) and N x N samples carries the wave numbers ``q = 2 pi n / L`` whose
modulus lies in its band ``[k_lo, k_hi)``; bands of successive tiles touch, so every wave number
is sampled by exactly one tile and the variances add up (docs/REFERENCES.md §3). Every band
ends at half the tile's Nyquist wave number (``|n| < N/4``): the fields are oversampled twice,
which keeps bilinear texture lookups and finite differences of them accurate.

Tile sizes follow from the sea state: the largest tile puts the frequency below which only
0.1 % of m0 lies at ``|n| = 8`` (the peak near |n| = 19); each next tile is smaller by
``phi^3`` (an irrational ratio, so the tiles never share a period). A short sea (Tp under about
6 s) would then repeat its peak waves within a kilometre, a pattern the eye picks out from the
bridge or the air. There the smallest tile stays and the ratio grows until the largest tile
spans :data:`VIEW_TILE_M`, as far as two limits allow:
- the peak stays at ``|n| <= 0.625 N/4`` of the largest tile, so its band keeps the peak's
  energy (at N = 256 this reaches 1 km at Tp = 4 s; shorter seas need N = 512);
- the ratio stays below ``(N/4) / 8``, where the next band would start under ``|n| = 8``,
  and off that exact (rational) value.
A regular wave gets a tile of its own whose size makes its wave vector fall exactly on the grid.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.errors import ParameterError
from marinesim.sea.dispersion import group_velocity, omega_from_k
from marinesim.sea.kinds import MAX_RESOLUTION
from marinesim.sea.seastate import RegularWave, SeaState, WaveSystem
from marinesim.sea.spreading import LongCrested

TILE_RATIO = ((1.0 + math.sqrt(5.0)) / 2.0) ** 3
"""Size ratio of successive tiles: phi^3 = 4.236..."""

LOWEST_INDEX = 8
"""Grid index |n| of the 0.1 % lower frequency quantile in the largest tile."""

VIEW_TILE_M = 1000.0
"""The largest tile spans at least this (m) where the limits allow: no visible tiling at 1 km."""

PEAK_INDEX_LIMIT = 0.625
"""Highest grid index of the spectral peak in a stretched largest tile, as a share of N/4."""

_GAUSS_X = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
_GAUSS_W = np.array([5.0, 8.0, 5.0]) / 9.0


@dataclass(frozen=True)
class Tile:
    """One cascade: an ``size`` x ``size`` m periodic tile of ``resolution``^2 samples.

    ``k_lo <= |k| < k_hi`` (rad/m) is the band of wave numbers it carries. A tile made for a
    regular wave carries only the grid point ``wave_index`` (and its Hermitian mirror).
    """

    size: float
    resolution: int
    k_lo: float
    k_hi: float
    wave_index: tuple[int, int] | None = None

    @property
    def dk(self) -> float:
        """Wave-number spacing ``2 pi / L`` (rad/m)."""
        return 2.0 * math.pi / self.size

    @property
    def spacing(self) -> float:
        """Distance between samples (m)."""
        return self.size / self.resolution

    def wavenumbers(self) -> tuple[np.ndarray, np.ndarray]:
        """``(qx, qy)`` of every grid cell in FFT order, arrays indexed ``[iy, ix]`` (rad/m)."""
        q = np.fft.fftfreq(self.resolution, d=1.0 / self.resolution) * self.dk
        return np.meshgrid(q, q, indexing="xy")

    def coordinates(self) -> tuple[np.ndarray, np.ndarray]:
        """Sample positions ``(x, y)`` (m, earth frame, tile origin at 0), indexed ``[iy, ix]``."""
        x = np.arange(self.resolution) * self.spacing
        return np.meshgrid(x, x, indexing="xy")

    def as_dict(self) -> dict:
        return {
            "size_m": self.size,
            "resolution": self.resolution,
            "spacing_m": self.spacing,
            "k_lo_rad_m": self.k_lo,
            "k_hi_rad_m": self.k_hi,
            "wavelengths_m": [2.0 * math.pi / self.k_hi, 2.0 * math.pi / self.k_lo],
            "regular_wave": self.wave_index is not None,
        }


def check_resolution(resolution: int) -> int:
    """Tiles need a power-of-two resolution of at least 16 (raises naming the value)."""
    if isinstance(resolution, bool) or not isinstance(resolution, (int, np.integer)):
        raise ParameterError(f"tile resolution N must be an integer power of two, got {resolution!r}")
    if resolution < 16 or resolution & (resolution - 1) or resolution > MAX_RESOLUTION:
        raise ParameterError(f"tile resolution N must be a power of two in 16..{MAX_RESOLUTION}, got {resolution}")
    return int(resolution)


def check_tile_count(count: int) -> int:
    """1 to 8 spectral cascades (raises naming the value)."""
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or not 1 <= count <= 8:
        raise ParameterError(f"number of tiles must be an integer from 1 to 8, got {count!r}")
    return int(count)


def choose_tiles(sea: SeaState, count: int = 4, resolution: int = 256) -> list[Tile]:
    """Tiles for ``sea``: ``count`` spectral cascades (if it has spectra) + one per regular wave."""
    resolution = check_resolution(resolution)
    count = check_tile_count(count)
    tiles: list[Tile] = []
    if sea.spectral_systems:
        k_low = float(sea.wavenumber(sea.omega_quantile(0.001)))
        size, ratio = LOWEST_INDEX * 2.0 * math.pi / k_low, TILE_RATIO
        wanted = min(VIEW_TILE_M, PEAK_INDEX_LIMIT * (resolution // 4) * sea.g * float(sea.tp) ** 2 / (2.0 * math.pi))
        if count > 1 and size < wanted:  # the peak wavelength is the deep-water g Tp^2 / 2 pi at most
            smallest = size / TILE_RATIO ** (count - 1)
            widest = max(TILE_RATIO, 0.97 * (resolution // 4) / LOWEST_INDEX)
            ratio = min((wanted / smallest) ** (1.0 / (count - 1)), widest)
            size = smallest * ratio ** (count - 1)
        k_lo = 0.5 * 2.0 * math.pi / size  # everything but the mean (DC) cell
        for _ in range(count):
            k_hi = (resolution // 4) * 2.0 * math.pi / size
            tiles.append(Tile(size, resolution, k_lo, k_hi))
            size /= ratio
            k_lo = k_hi
    tiles.extend(regular_tile(wave, sea, resolution) for wave in sea.regular_waves)
    return tiles


def regular_tile(wave: RegularWave, sea: SeaState, resolution: int) -> Tile:
    """A tile whose grid holds the wave vector exactly, direction to the nearest lattice angle."""
    reach = resolution // 4 - 1
    n = np.arange(-reach, reach + 1)
    nx, ny = (a.ravel() for a in np.meshgrid(n, n))
    length = np.hypot(nx, ny)
    usable = length >= LOWEST_INDEX
    error = np.abs(np.angle(np.exp(1j * (np.arctan2(ny, nx) - wave.beta))))
    error = np.where(usable, error, np.inf)
    best = np.flatnonzero(error <= error.min() + 1e-12)
    best = best[np.argmin(length[best])]
    k = float(sea.wavenumber(wave.omega))
    size = 2.0 * math.pi * length[best] / k
    return Tile(size, resolution, 0.999 * k, 1.001 * k, (int(nx[best]), int(ny[best])))


def cell_variances(tile: Tile, sea: SeaState) -> np.ndarray:
    """Variance (m^2) that ``sea`` puts into each grid cell of ``tile``, indexed ``[iy, ix]``.

    Spread systems: ``integral S(w, theta) (dw/dk) / k dkx dky`` over the cell by 3 x 3
    Gauss-Legendre points, each point counted only if its |k| is in the tile's band. Long-crested
    systems: ``integral S(w) (dw/dk) dk`` along the ray in the mean direction, binned to the
    nearest cell. Regular waves are not a density: their tiles get zeros here.
    """
    variance = np.zeros((tile.resolution, tile.resolution))
    if tile.wave_index is not None:
        return variance  # a regular wave's tile: the ocean sets that one amplitude exactly
    for system in sea.spectral_systems:
        if isinstance(system.spreading, LongCrested):
            _add_ray(variance, tile, sea, system)
        else:
            _add_spread(variance, tile, sea, system)
    variance[0, 0] = 0.0  # the mean level is not a wave
    return variance


def _add_spread(variance: np.ndarray, tile: Tile, sea: SeaState, system: WaveSystem) -> None:
    qx, qy = tile.wavenumbers()
    centre = np.hypot(qx, qy)
    near = (centre >= tile.k_lo - tile.dk) & (centre < tile.k_hi + tile.dk)
    cx, cy = qx[near], qy[near]
    total = np.zeros(cx.size)
    half = 0.5 * tile.dk
    for ox, wx in zip(_GAUSS_X, _GAUSS_W):
        for oy, wy in zip(_GAUSS_X, _GAUSS_W):
            kx, ky = cx + ox * half, cy + oy * half
            k = np.hypot(kx, ky)
            inside = (k >= tile.k_lo) & (k < tile.k_hi)
            omega = omega_from_k(k[inside], sea.depth, sea.g)
            theta = np.arctan2(ky[inside], kx[inside])
            density = system.directional_density(omega, theta)
            density *= group_velocity(k[inside], sea.depth, sea.g) / k[inside]
            total[inside] += wx * wy * density
    variance[near] += total * half**2


def _add_ray(variance: np.ndarray, tile: Tile, sea: SeaState, system: WaveSystem) -> None:
    step = tile.dk / 32.0
    k = np.arange(tile.k_lo + 0.5 * step, tile.k_hi, step)
    omega = omega_from_k(k, sea.depth, sea.g)
    weight = system.spectrum.density(omega) * group_velocity(k, sea.depth, sea.g) * step
    ix = np.rint(k * math.cos(system.beta) / tile.dk).astype(int) % tile.resolution
    iy = np.rint(k * math.sin(system.beta) / tile.dk).astype(int) % tile.resolution
    np.add.at(variance, (iy, ix), weight)
