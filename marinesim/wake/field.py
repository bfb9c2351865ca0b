"""The far-field Kelvin wake on a grid in the vessel frame, by angular quadrature and an FFT.

With A even in theta, the far field of :mod:`marinesim.wake.amplitude` is

    zeta(xi, eta) = Re int_0^{pi/2} 2 A(theta) cos(k_y eta) exp(-i k_x xi) d theta,
    k_x = k0 sec(theta),  k_y = k0 sec^2(theta) sin(theta),

xi = -x downstream, eta = |y|: one half is computed and mirrored. The integral is taken in
u (sec theta = cosh u, d theta = du / cosh u), smooth at theta = 0 where k_x has a square-root
branch (sampling theta on the FFT's uniform k_x grid, as seed 003 did, is what cost it ~20 %),
by Gauss-Legendre panels of equal phase change for every grid point (:func:`phase_quadrature`).
The sum over the nodes along the track is one non-uniform FFT per row
(:mod:`marinesim.wake.nufft`): ``J (M log M)`` instead of ``J M`` exponentials per row.

Reach: the FFT along the track holds k_x up to pi / d (grid spacing d), so the integral stops at
sec(theta) = pi / (d k0), with a raised-cosine taper over the last TAPER of that band (a hard stop
rings). Across the track each row is summed directly, so every k_y is exact there. The waves cut
off are diverging waves shorter than two cells, which stand within a few degrees of the track
(their ray angle is atan(tan(theta) / (1 + 2 tan^2(theta))): 3.6 deg at sec(theta) = 8); outside
5 deg of the track they change the field by less than 1 % of its peak (measured in
tests/test_wake_field.py). A(theta) is sampled exactly on a uniform sec grid fine enough for its
oscillation (SAMPLES_PER_PERIOD per period 2 pi / (k0 max|x|)) and interpolated by a cubic
spline at the quadrature nodes.

Near the hull the far-field expression is only indicative: the field is faded in from zero at
the bow to full strength at the stern, and is zero ahead of the bow.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline

from marinesim.errors import ParameterError, require_memory
from marinesim.hull import Surface
from marinesim.progress import task
from marinesim.wake.amplitude import PANEL_ORDER, PANEL_RADIANS, hull_reach, phase_quadrature, tuck_amplitude
from marinesim.wake.nufft import NonuniformSum

TAPER = 0.3  # fraction of the band (in wavenumber) over which the spectrum rolls off to zero
SAMPLES_PER_PERIOD = 16  # exact A(theta) samples per oscillation period in sec(theta)
ROWS_PER_CHUNK = 64
BYTES_PER_NODE = 32 * ROWS_PER_CHUNK + 256
"""Memory per quadrature node (bytes): its complex terms for a chunk of rows, and its dozen node arrays."""


@dataclass(frozen=True)
class WakeSpectrum:
    """The wake as a sum of plane waves: zeta = Re sum_j weight_j cos(ky_j eta) exp(-i kx_j xi)."""

    kx: np.ndarray  # 1/m, along the track, >= k0
    ky: np.ndarray  # 1/m, across the track, >= 0
    weight: np.ndarray  # m: Gauss-Legendre weight in u / cosh(u) x 2 A x band-limit taper

    def direct(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """zeta at vessel-frame points (x forward, y to port), m, by direct summation (reference)."""
        x, y = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
        shape, x, y = x.shape, x.ravel(), y.ravel()
        out = np.empty(x.shape)
        for start in range(0, len(x), 256):
            xs, ys = x[start:start + 256, None], y[start:start + 256, None]
            out[start:start + 256] = (np.cos(ys * self.ky) * np.exp(1j * xs * self.kx) @ self.weight).real
        return out.reshape(shape)

    def on_grid(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """zeta on the grid ``x`` (uniform, increasing) by ``y`` (symmetric about 0), shape (len(y), len(x))."""
        dx = (x[-1] - x[0]) / (len(x) - 1)
        rows, inverse = np.unique(np.round(np.abs(y), 9), return_inverse=True)
        # xi = -(x0 + m dx): exp(-i kx xi) = exp(i kx x0) exp(i m kx dx)
        nufft = NonuniformSum(self.kx * dx, self.weight * np.exp(1j * self.kx * x[0]), len(x))
        half = np.empty((len(rows), len(x)))
        chunks = range(0, len(rows), ROWS_PER_CHUNK)
        with task("wake field", len(chunks), "chunk") as bar:
            for start in chunks:
                eta = rows[start:start + ROWS_PER_CHUNK]
                half[start:start + len(eta)] = nufft(np.cos(np.outer(self.ky, eta))).real.T
                bar.update(1)
        return half[inverse.ravel()]


def wake_spectrum(surface: Surface, k0: float, xi_max: float, eta_max: float, spacing: float,
                  refinement: float = 1.0) -> WakeSpectrum:
    """The quadrature of the far-field integral for a grid reaching ``xi_max`` downstream and
    ``eta_max`` across (m) at ``spacing`` (m); ``refinement`` multiplies the nodes per radian."""
    k_band = math.pi / spacing
    if k0 >= (1.0 - TAPER) * k_band:
        raise ParameterError(f"grid spacing {spacing:.3g} m cannot hold the transverse waves (wavelength "
                             f"{2 * math.pi / k0:.3g} m): it must be below {(1 - TAPER) * math.pi / k0:.3g} m")
    u_max = math.acosh(k_band / k0)
    reach = hull_reach(surface)

    def phase(u: np.ndarray) -> np.ndarray:
        return (refinement * k0 * (xi_max * (np.cosh(u) - 1.0) + eta_max * np.sinh(u) * np.cosh(u)
                                   + reach * (np.cosh(u) - 1.0)) + 8.0 * u)

    nodes = PANEL_ORDER * math.ceil(float(phase(np.array(u_max))) / PANEL_RADIANS)
    require_memory(f"the wake's quadrature ({nodes:.3g} nodes at {spacing:.3g} m spacing)", nodes * BYTES_PER_NODE)
    u, w = phase_quadrature(phase, u_max)
    sec, tan = np.cosh(u), np.sinh(u)
    kx, ky = k0 * sec, k0 * sec * tan
    band = kx / k_band
    taper = np.where(band <= 1.0 - TAPER, 1.0, np.cos(0.5 * math.pi * (band - 1.0 + TAPER) / TAPER) ** 2)
    a = _amplitude_spline(surface, k0, sec[-1], reach)(sec)
    return WakeSpectrum(kx, ky, w / sec * 2.0 * a * taper)


def _amplitude_spline(surface: Surface, k0: float, sec_max: float, reach: float) -> CubicSpline:
    """A(sec) sampled exactly on a uniform sec grid and interpolated."""
    step = 2.0 * math.pi / (k0 * max(reach, 1e-9)) / SAMPLES_PER_PERIOD
    count = max(16, math.ceil((sec_max - 1.0) / step) + 1)
    samples = np.linspace(1.0, sec_max, count)
    return CubicSpline(samples, tuck_amplitude(surface, k0, samples))


