"""Michell wave resistance of a meshed Wigley hull against Michell's integral of the analytic hull.

``marinesim.wake.wave_resistance`` integrates the Kochin function exactly over the triangles of
a mesh. The reference here never sees a mesh or anything from marinesim: it is Michell's
thin-ship integral (lambda form) of the analytic Wigley half-breadth
Y = (B/2)(1 - (2x/L)^2)(1 - (z/T)^2), evaluated by scipy quadrature,

    R = 4 rho g^2 / (pi U^2) * int_1^inf |I(l)|^2 l^2 / sqrt(l^2 - 1) dl,
    I(l) = int int Y_x exp(k0 l^2 z + i k0 l x) dx dz,   k0 = g / U^2,

with l = cosh(u) removing the square-root singularity. I is separable for this hull: an
x-integral done by QAWO (``weight="sin"``) times a z-integral. The outer integral is split into
one piece per oscillation period of |I|^2 in l (2 pi / (k0 L)) and truncated at l = 100, where
the tail (which falls like l^-4) is below 1e-6 of the total. Checked apart from this file
against the theta form with closed-form I and composite Gauss-Legendre (agreement to 1e-7), and
I against a brute-force 2-D grid (1e-11).
"""

import functools
import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad

from marinesim.hull import Hull, wigley_hull
from marinesim.wake import wave_resistance

RHO, G = 1025.0, 9.80665
LENGTH, BEAM, DRAFT = 100.0, 10.0, 6.25
LAMBDA_MAX = 100.0


def speed(froude: float) -> float:
    return froude * math.sqrt(G * LENGTH)


def kochin_squared(lam: float, k0: float) -> float:
    """|I(lambda)|^2 of the analytic Wigley hull: Y_x = -(4B/L^2) x (1 - (z/T)^2), separable."""
    # The even part of exp(i a x) drops out against the odd x: int x e^{iax} = 2i int_0^{L/2} x sin(ax).
    x_part = 2.0 * quad(lambda x: x, 0.0, LENGTH / 2, weight="sin", wvar=k0 * lam)[0]
    z_part = quad(lambda z: (1.0 - (z / DRAFT) ** 2) * math.exp(k0 * lam**2 * z), -DRAFT, 0.0)[0]
    return (4.0 * BEAM / LENGTH**2 * x_part * z_part) ** 2


@functools.lru_cache
def michell_resistance(froude: float) -> float:
    """Michell's wave resistance (N) of the analytic Wigley hull at this Froude number."""
    u = speed(froude)
    k0 = G / u**2
    pieces = math.ceil(k0 * LENGTH * (LAMBDA_MAX - 1.0) / (2.0 * math.pi))
    edges = np.arccosh(np.linspace(1.0, LAMBDA_MAX, pieces + 1))

    def integrand(t: float) -> float:
        lam = math.cosh(t)
        return kochin_squared(lam, k0) * lam**2

    total = math.fsum(quad(integrand, a, b)[0] for a, b in itertools.pairwise(edges))
    return 4.0 * RHO * G**2 / (math.pi * u**2) * total


@pytest.fixture(scope="module")
def fine_hull() -> Hull:
    return wigley_hull(LENGTH, BEAM, DRAFT, nx=80, nz=16)


@pytest.fixture(scope="module")
def coarse_hull() -> Hull:
    return wigley_hull(LENGTH, BEAM, DRAFT, nx=40, nz=8)


@pytest.mark.parametrize("froude", [0.25, 0.3, 0.35, 0.4, 0.5, 0.6])
def test_wigley_michell_resistance_matches_quadrature(fine_hull: Hull, froude: float) -> None:
    expected = michell_resistance(froude)
    got = wave_resistance(fine_hull, speed(froude), rho=RHO, g=G)
    error = got / expected - 1.0
    assert abs(error) <= 0.01, (f"wave resistance off by {100 * error:+.2f}% at Fn {froude}: "
                                f"{got:.5g} N from the mesh, {expected:.5g} N from Michell's integral")


@pytest.mark.parametrize("froude", [0.3, 0.5])
def test_two_mesh_resolutions_agree(coarse_hull: Hull, fine_hull: Hull, froude: float) -> None:
    expected = michell_resistance(froude)
    coarse = wave_resistance(coarse_hull, speed(froude), rho=RHO, g=G)
    fine = wave_resistance(fine_hull, speed(froude), rho=RHO, g=G)
    assert abs(coarse / fine - 1.0) <= 0.01, (
        f"wave resistance changes by {100 * (coarse / fine - 1.0):+.2f}% at Fn {froude} when the mesh "
        f"is halved (nx 80 -> 40, nz 16 -> 8): {fine:.5g} N vs {coarse:.5g} N")
    assert abs(fine - expected) < abs(coarse - expected), (
        f"refining the mesh does not bring the wave resistance closer to Michell's integral at Fn {froude}: "
        f"error {fine - expected:+.4g} N fine vs {coarse - expected:+.4g} N coarse")
