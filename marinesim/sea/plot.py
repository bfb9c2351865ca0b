"""Pictures of a sea state: the spectrum and a height map of the synthesised surface."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.figures import figure, save
from marinesim.sea.ocean import Ocean, TileFields


def height_on_grid(fields: list[TileFields], x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Sum of the tiles' height fields at points (x, y) (m), bilinear with periodic wrap."""
    total = np.zeros(np.broadcast(x, y).shape)
    for f in fields:
        n = f.tile.resolution
        u = np.asarray(x) / f.tile.spacing
        v = np.asarray(y) / f.tile.spacing
        i0, j0 = np.floor(u).astype(int), np.floor(v).astype(int)
        fu, fv = u - i0, v - j0
        i1, j1 = (i0 + 1) % n, (j0 + 1) % n
        i0, j0 = i0 % n, j0 % n
        h = f.height
        total += ((1 - fu) * (1 - fv) * h[j0, i0] + fu * (1 - fv) * h[j0, i1]
                  + (1 - fu) * fv * h[j1, i0] + fu * fv * h[j1, i1])
    return total


def plot_sea(ocean: Ocean, path: Path, t: float = 0.0, extent_m: float | None = None) -> None:
    """Write a PNG: the 1-D spectrum (total and per system) and a height map at time ``t``."""
    sea = ocean.sea
    fig = figure(13, 5.2)
    ax_s, ax_h = fig.subplots(1, 2)
    wp = 2.0 * math.pi / sea.tp
    omega = np.linspace(0.02 * wp, 4.0 * wp, 1500)
    if sea.spectral_systems:
        ax_s.plot(omega, sea.density(omega), "k", lw=2, label="total")
        for i, system in enumerate(sea.spectral_systems):
            if len(sea.spectral_systems) > 1:
                ax_s.plot(omega, system.spectrum.density(omega), "--", label=f"system {i + 1}")
    for wave in sea.regular_waves:
        ax_s.axvline(wave.omega, color="tab:red", label=f"regular H={wave.height:g} m T={wave.period:g} s")
    ax_s.set_xlabel("angular frequency w [rad/s]")
    ax_s.set_ylabel("S(w) [m$^2$ s/rad]")
    ax_s.set_title(f"Hs = {sea.hs:.2f} m, Tp = {sea.tp:.2f} s, Tz = {sea.tz:.2f} s")
    ax_s.legend()
    ax_s.grid(alpha=0.3)

    extent = extent_m or min(ocean.tiles[0].size, 8.0 * 2.0 * math.pi / float(sea.wavenumber(wp)))
    coords = np.linspace(0.0, extent, 400)
    x, y = np.meshgrid(coords, coords)
    height = height_on_grid(ocean.fields(t, reproducible=True), x, y)
    limit = float(np.abs(height).max())
    image = ax_h.imshow(height, origin="lower", extent=(0, extent, 0, extent), cmap="RdBu_r",
                        vmin=-limit, vmax=limit)
    fig.colorbar(image, ax=ax_h, label="elevation [m]")
    ax_h.set_xlabel("x east [m]")
    ax_h.set_ylabel("y north [m]")
    ax_h.set_title(f"surface at t = {t:g} s (seed {ocean.seed})")
    fig.tight_layout()
    save(fig, path)


def plot_series(times: np.ndarray, values: np.ndarray, label: str, title: str, path: Path) -> None:
    """Write a PNG of one time series (``label`` names the quantity and its unit)."""
    fig = figure(12, 3.6)
    ax = fig.subplots()
    ax.plot(times, values, lw=0.8)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(label)
    ax.set_title(title)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, path)
