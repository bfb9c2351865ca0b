"""Tuck's amplitude function A(theta) of a hull and its Michell wave resistance.

Thin-ship (Michell) theory, REFERENCES section 5, for a hull moving forward at speed U
(``k0 = g / U^2``). With x forward in the body frame and the far field written behind the
hull in downstream coordinates (xi = -x, eta),

    zeta(xi, eta) = Re int_{-pi/2}^{pi/2} A(theta) exp(-i k0 sec^2(theta) (xi cos(theta) + eta sin(theta))) d theta,

    A(theta) = (k0 sec^3(theta) / pi) int_S n_x exp(k0 sec^2(theta) z - i k0 sec(theta) x) dS

over the wetted surface S with outward normals: on each side of a thin hull ``n_x dS = Y_xi
dxi dz`` (Y the half-breadth, xi downstream), so this is Tuck's ``(2/pi) k0 sec^3 int int Y_xi
exp(k0 sec^2 z + i k0 sec xi) dxi dz``, and on a closed mesh it includes transom sterns. The
phase is pinned by the physics of a source: the bow (n_x > 0, a source) leaves a crest behind
it, A(0) > 0 for a lone bow (tests/test_wake_field.py). The integral is exact on each
triangle (:mod:`marinesim.wake.triangle`). A depends on theta only through sec(theta), so it is
even and the wake is symmetric about the track.

Wave resistance: ``R = (pi/2) rho U^2 int |A|^2 cos^3(theta) d theta`` (equal to Michell's
integral), evaluated with sec(theta) = cosh(u), d theta = du / cosh(u):
``R = pi rho U^2 int_0^inf |A(cosh u)|^2 cosh(u)^-4 du``, by Gauss-Legendre panels up to
sec = RESISTANCE_SEC_MAX and an extrapolated tail beyond.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

from marinesim.constants import G, RHO_SEAWATER
from marinesim.errors import ParameterError, require_positive
from marinesim.hull import Hull, Surface
from marinesim.progress import task
from marinesim.wake.triangle import exp_divided_difference

WORK_PER_CHUNK = 500_000  # (angle, triangle) pairs per chunk: about 100 MB of temporaries
DECAY_CUTOFF = 40.0  # exp(-40) = 4e-18: triangles this many decay lengths down are skipped
RESISTANCE_SEC_MAX = 40.0  # the sum stops here; the tail beyond is extrapolated (resistance_from_amplitude)
PANEL_RADIANS = 6.0  # phase change per Gauss-Legendre panel ...
PANEL_ORDER = 8  # ... of this many nodes: 1.3 nodes per radian, error ~ 2e-6 per panel


def tuck_amplitude(surface: Surface, k0: float, sec: np.ndarray) -> np.ndarray:
    """A(theta) at ``sec = sec(theta)`` (array, >= 1), m; ``k0 = g / U^2`` in 1/m.

    Triangles deeper than the decay ``exp(k0 sec^2 z)`` lets matter (their shallowest corner
    ``DECAY_CUTOFF / (k0 sec^2)`` below the shallowest point of the hull) are skipped: they would
    add less than exp(-DECAY_CUTOFF) of the surface's contribution.
    """
    sec = np.asarray(sec, dtype=float)
    flat = sec.ravel()
    order = np.argsort(flat)
    top = np.maximum(np.maximum(surface.a[:, 2], surface.b[:, 2]), surface.c[:, 2])
    by_depth = np.argsort(-top, kind="stable")
    corners = [p[by_depth] for p in (surface.a, surface.b, surface.c)]
    weight = 2.0 * surface.vector_areas[by_depth, 0]  # 2 n_x |T|: int_T exp(s) n_x dS = weight e[s0, s1, s2]
    depth = top[by_depth[0]] - top[by_depth]  # below the shallowest point, increasing
    out = np.empty(flat.shape, dtype=complex)
    start = 0
    with task("A(theta)", len(flat), "angle") as bar:
        while start < len(flat):
            active = int(np.searchsorted(depth, DECAY_CUTOFF / (k0 * flat[order[start]] ** 2), side="right"))
            stop = min(len(flat), start + max(1, WORK_PER_CHUNK // active))
            s = flat[order[start:stop], None]
            exponents = [k0 * s * s * p[:active, 2] - 1j * k0 * s * p[:active, 0] for p in corners]
            out[order[start:stop]] = exp_divided_difference(*exponents) @ weight[:active]
            bar.update(stop - start)
            start = stop
    return (k0 * flat**3 / math.pi * out).reshape(sec.shape)


def wave_resistance(hull: Hull, speed_m_s: float, *, rho: float = RHO_SEAWATER, g: float = G) -> float:
    """Michell's wave resistance R, N, of ``hull`` at ``speed_m_s`` (through A(theta))."""
    surface = hull.wetted()
    k0 = wavenumber(speed_m_s, g)
    u, w = resistance_quadrature(k0, hull_reach(surface))
    sec = np.cosh(u)
    return resistance_from_amplitude(tuck_amplitude(surface, k0, sec), sec, w, speed_m_s, rho)


def resistance_quadrature(k0: float, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Nodes u and weights for int_0^{acosh(RESISTANCE_SEC_MAX)} f(u) du resolving the oscillation
    of |A|^2 (at most 2 k0 reach per unit sec, ``reach`` = max |x| of the hull)."""
    return phase_quadrature(lambda u: 2.0 * k0 * reach * (np.cosh(u) - 1.0) + 8.0 * u,
                            math.acosh(RESISTANCE_SEC_MAX))


def resistance_from_amplitude(a: np.ndarray, sec: np.ndarray, weights: np.ndarray, speed_m_s: float,
                              rho: float) -> float:
    """``pi rho U^2 sum w |A|^2 / sec^4`` (u-quadrature of Michell's integral) plus its tail, N.

    Beyond sec = RESISTANCE_SEC_MAX the integrand, averaged over its oscillation, falls like a
    power of sec (sec^-3 per d sec for a transom or a blunt bow, faster for fine ends); the
    power is measured from the last two octaves and the tail added as a geometric series.
    """
    terms = weights * np.abs(a) ** 2 / sec**4
    octaves = [terms[(sec >= RESISTANCE_SEC_MAX / 2 ** (k + 1)) & (sec < RESISTANCE_SEC_MAX / 2**k)].sum()
               for k in (1, 0)]
    ratio = octaves[0] / octaves[1] if octaves[1] > 0 else math.inf
    tail = octaves[1] / (ratio - 1.0) if ratio > 1.0 else 0.0
    return float(math.pi * rho * speed_m_s**2 * (terms.sum() + tail))


def wavenumber(speed_m_s: float, g: float = G) -> float:
    """k0 = g / U^2, 1/m: the wavenumber of the transverse waves (wavelength 2 pi U^2 / g)."""
    speed = require_positive("speed", speed_m_s)
    if speed > 40.0:
        raise ParameterError(f"speed must be at most 40 m/s (78 kn) for a displacement hull, got {speed:g} m/s")
    return g / speed**2


def hull_reach(surface: Surface) -> float:
    """The largest |x| on the wetted surface, m: A(theta) oscillates at most k0 times this per unit sec."""
    return float(np.abs(surface.corners[:, 0]).max())


def phase_quadrature(phase: Callable[[np.ndarray], np.ndarray], u_max: float) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on [0, u_max], panels of equal increments of ``phase(u)``.

    ``phase`` is increasing and bounds the phase change of the integrand, so each panel spans at
    most PANEL_RADIANS of oscillation whatever the integrand's local frequency.
    """
    fine = np.linspace(0.0, u_max, 65537)
    values = phase(fine)
    panels = max(1, math.ceil((values[-1] - values[0]) / PANEL_RADIANS))
    edges = np.interp(np.linspace(values[0], values[-1], panels + 1), values, fine)
    x, w = np.polynomial.legendre.leggauss(PANEL_ORDER)
    half = 0.5 * np.diff(edges)[:, None]
    nodes = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half * x
    return nodes.ravel(), (half * w).ravel()
