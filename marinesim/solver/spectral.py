"""The numerics both solvers share: deep-water waves advanced by an exact rotation in k-space.

State per cell: the surface elevation ``h`` (m) and the surface velocity potential ``phi``
(m^2/s). Linear deep-water waves under a surface pressure ``p = rho g d`` obey (REFERENCES §6)

    h_t = |k| phi,      phi_t = -g (h + d)           (|k| = sqrt(-laplacian), in k-space)

so every wavenumber is an oscillator of frequency ``omega = sqrt(g |k|)`` about the static
surface ``h = -d``. For ``d`` held over a step of length ``dt`` the exact solution is a rotation of
``(u, phi)``, ``u = h + d``, by ``omega dt``:

    u'   = cos(w dt) u + (|k| / w) sin(w dt) phi
    phi' = cos(w dt) phi - (g / w) sin(w dt) u

Why this and not iWave's convolution kernel: a kernel of finite radius has a Fourier symbol that
is smooth at k = 0 and so cannot follow |k| for waves longer than a few kernel radii (the long
waves a heaving hull radiates), and a leapfrog step adds its own phase error. The rotation is the
dispersion relation itself, for every wavelength the grid holds, and it is stable for any step.

Packing: the two real fields travel as one complex field ``z = u + i phi``. With
``Z(k) = FFT z`` and ``W = conj Z(-k)`` the rotation becomes ``Z' = A Z + B W`` with

    A = cos(w dt) - i sin(w dt) (|k| + g) / (2 w),     B = -i sin(w dt) (g - |k|) / (2 w),

both even in k, so one complex FFT pair serves both fields. At k = 0 the mean elevation is kept
and the mean potential set to zero (``Z' = Re Z``): the potential's constant is a gauge, and
fixing it keeps obstacles, which hold phi = 0, from seeing a uniform potential as motion. Light
damping is a k^2 viscosity, ``exp(-2 nu k^2 dt)`` on both.
"""

from __future__ import annotations

import math

import numpy as np

SUBPIXEL = 256
"""Vertex positions of the rasterised hull are snapped to 1/256 of a cell (the rasteriser's own grid)."""


def wavenumbers(size: int, cell: float) -> np.ndarray:
    """|k| (rad/m) of an FFT grid of ``size`` x ``size`` cells of ``cell`` m, in FFT order."""
    k1 = 2.0 * math.pi * np.fft.fftfreq(size, d=cell)
    return np.hypot(k1[None, :], k1[:, None])


def viscosity(cell: float, shortest_wave_efolding_s: float | None) -> float:
    """k^2 viscosity (m^2/s) that damps the shortest wave on the grid (2 cells) by e in the given
    time; waves ``m`` times longer last ``m^2`` times longer. ``None``: no damping."""
    if shortest_wave_efolding_s is None:
        return 0.0
    k_shortest = math.pi / cell
    return 1.0 / (2.0 * k_shortest ** 2 * shortest_wave_efolding_s)


def rotation(size: int, cell: float, dt: float, g: float, nu: float) -> tuple[np.ndarray, np.ndarray]:
    """The coefficients ``(A, B)`` of one step (complex128, FFT order), damping included."""
    k = wavenumbers(size, cell)
    omega = np.sqrt(g * k)
    c, s = np.cos(omega * dt), np.sin(omega * dt)
    with np.errstate(divide="ignore", invalid="ignore"):
        a = c - 1j * s * (k + g) / (2.0 * omega)
        b = -1j * s * (g - k) / (2.0 * omega)
    a[0, 0], b[0, 0] = 0.5, 0.5                       # Z' = Re Z: mean h kept, mean phi zero
    decay = np.exp(-2.0 * nu * k ** 2 * dt)
    return a * decay, b * decay


def sponge(size: int, width: int, cell: float, g: float, dt: float) -> np.ndarray:
    """Factor ``exp(-gamma dt)`` per cell, ``gamma = sponge_rate ((width - e) / width)^2`` within
    ``width`` cells of an edge (``e`` the distance of the cell centre from it, in cells), 1 inside."""
    if width == 0:
        return np.ones((size, size))
    e = np.arange(size) + 0.5
    ramp = np.clip((width - np.minimum(e, size - e)) / width, 0.0, 1.0) ** 2
    gamma = sponge_rate(width, cell, g) * np.maximum(ramp[None, :], ramp[:, None])
    return np.exp(-gamma * dt)


def sponge_rate(width: int, cell: float, g: float) -> float:
    """Peak absorption rate (1/s) of a sponge ``width`` cells wide: half the frequency of a wave as
    long as the sponge. Measured with the packets of tests/test_solver_local.py (256 cells, sponge 32):
    amplitude reflected 0.02 / 0.06 / 0.2 / 1.2 % and let through to the far side 0 / 0.02 / 0.2 /
    1.0 % for waves 4 / 8 / 16 / 32 cells long; waves twice the sponge width reflect 15 % and pass
    6 %. Twice this rate reflects 6 % at the sponge width (the ramp looks like a wall); half of it
    lets long waves through.
    """
    return 0.5 * math.sqrt(g * 2.0 * math.pi / (width * cell))


def energy(h: np.ndarray, phi: np.ndarray, cell: float, g: float, rho: float) -> float:
    """Wave energy (J) of the field: potential ``rho g h^2 / 2`` plus kinetic
    ``rho phi |k| phi / 2`` (the kinetic energy of deep water below the surface), both summed."""
    k = wavenumbers(h.shape[0], cell)
    phi_hat = np.fft.fft2(phi)
    kinetic = 0.5 * rho * np.sum(k * np.abs(phi_hat) ** 2) / phi.size
    potential = 0.5 * rho * g * np.sum(h ** 2)
    return float((kinetic + potential) * cell ** 2)


def substep_limit(cell: float, max_speed: float, g: float) -> float:
    """Longest sub-step (s).

    The rotation is stable for any step; what limits the step is the forcing, which is held
    constant over it. Two limits, the smaller wins: the hull moves at most half a cell per
    sub-step (so each cell of the rasterised footprint switches on its own sub-step), and the
    fastest wave the grid holds (2 cells across the diagonal, ``w_max = sqrt(g pi sqrt(2) / cell)``)
    turns by at most a quarter period (pi / 2), so the forcing is sampled four times per period of
    every resolved wave.
    """
    omega_max = math.sqrt(g * math.pi * math.sqrt(2.0) / cell)
    return min(0.5 * cell / max_speed, 0.5 * math.pi / omega_max)
