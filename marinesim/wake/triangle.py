"""Exact integral of the exponential of a linear function over a triangle.

For a triangle with corners p0, p1, p2 and a function linear in position, s(p) = c . p
(complex), the integral is

    int_T exp(s) dS = 2 |T| e[s0, s1, s2],

where s_j = s(p_j), |T| is the area and e[s0, s1, s2] is the second divided difference of exp
(the Hermite-Genocchi formula). The textbook closed form
``sum_j e^{s_j} / prod_{m != j} (s_j - s_m)`` cancels catastrophically when the s_j are close
and divides by zero when two are equal (an edge along which s does not change, e.g. a
horizontal edge across the hull), so :func:`exp_divided_difference` evaluates it robustly:
by the Taylor series around s0 when all pairwise differences are small, otherwise by the
recursion ``e[a, m, b] = (e[m, b] - e[a, m]) / (b - a)`` with (a, b) the pair furthest apart,
whose first divided differences use ``expm1`` when their points are close.
"""

from __future__ import annotations

import math

import numpy as np

SERIES_RADIUS = 0.25  # pairwise differences below this: Taylor series; above, the recursion loses
# at most a factor 1 / SERIES_RADIUS of precision
SERIES_TERMS = 11  # (n + 1) 0.25^n / (n + 2)! < 1e-17 at n = 11: full double precision within the radius


def exp_divided_difference(s0: np.ndarray, s1: np.ndarray, s2: np.ndarray) -> np.ndarray:
    """e[s0, s1, s2] for complex arrays of one shape; ``int_T exp(s) dS = 2 |T| e[s0, s1, s2]``."""
    d01, d02, d12 = s1 - s0, s2 - s0, s2 - s1
    gaps = np.stack([np.abs(d02), np.abs(d01), np.abs(d12)])
    e0, e1, e2 = np.exp(s0), np.exp(s1), np.exp(s2)
    f01, f02, f12 = _first(e0, e1, d01), _first(e0, e2, d02), _first(e1, e2, d12)
    # the outer pair is the one furthest apart, so the division is by at least SERIES_RADIUS
    # where the result is kept; the series replaces the rest
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.choose(np.argmax(gaps, axis=0), [(f12 - f01) / d02,  # e[s0, s1, s2]
                                                  (f12 - f02) / d01,  # e[s0, s2, s1]
                                                  (f02 - f01) / d12])  # e[s1, s0, s2]
    near = gaps.max(axis=0) < SERIES_RADIUS
    if near.any():
        out[near] = e0[near] * _series(d01[near], d02[near])
    return out


def _first(ea: np.ndarray, eb: np.ndarray, d: np.ndarray) -> np.ndarray:
    """e[a, b] = (e^b - e^a) / (b - a) given e^a, e^b and d = b - a, accurate for small d."""
    with np.errstate(divide="ignore", invalid="ignore"):
        out = (eb - ea) / d
    small = np.abs(d) < SERIES_RADIUS
    if small.any():
        ds = d[small]
        nonzero = ds != 0
        ratio = np.ones_like(ds)
        ratio[nonzero] = np.expm1(ds[nonzero]) / ds[nonzero]
        out[small] = ea[small] * ratio
    return out


def _series(d1: np.ndarray, d2: np.ndarray) -> np.ndarray:
    """sum_n h_n(d1, d2) / (n + 2)! = e^{-s0} e[s0, s0 + d1, s0 + d2], h_n the complete homogeneous
    polynomial of degree n."""
    h = np.ones_like(d1)
    power = np.ones_like(d1)
    total = h / 2.0
    for n in range(1, SERIES_TERMS + 1):
        power = power * d1
        h = d2 * h + power
        total = total + h / math.factorial(n + 2)
    return total
