"""One-sided wave spectra ``S(w)`` in m^2 s/rad (formulas: docs/REFERENCES.md §1).

Every spectrum is a frozen dataclass with ``density(omega)``, its significant wave height
``hs`` (= 4 sqrt(m0)) and peak period ``tp``. Spectra given by (Hs, Tp) are normalised
numerically so that ``4 sqrt(m0) = Hs`` exactly (the DNV factor ``A_g`` is only approximate).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Callable, Protocol

import numpy as np
from scipy import integrate

from marinesim.constants import G
from marinesim.errors import ParameterError, require_at_least, require_positive
from marinesim.sea.dispersion import k_from_omega
from marinesim.sea.kinds import fetch_limited


class Spectrum(Protocol):
    """What the sea module needs of a continuous spectrum."""

    @property
    def hs(self) -> float: ...

    @property
    def tp(self) -> float: ...

    def density(self, omega: np.ndarray) -> np.ndarray: ...


def spectral_moment(density: Callable[[np.ndarray], np.ndarray], n: int, omega_peak: float) -> float:
    """``m_n = integral_0^inf w^n S(w) dw`` by adaptive quadrature (breakpoints around the peak)."""

    def integrand(w: float) -> float:
        return float(w**n * density(np.array([w]))[0])

    points = [0.3 * omega_peak, 0.8 * omega_peak, omega_peak, 1.3 * omega_peak, 3.0 * omega_peak]
    finite, _ = integrate.quad(integrand, 0.0, 10.0 * omega_peak, points=points, limit=200)
    tail, _ = integrate.quad(integrand, 10.0 * omega_peak, math.inf, limit=200)
    return finite + tail


def dnv_gamma(hs: float, tp: float) -> float:
    """DNV-RP-C205 default peak enhancement factor for a JONSWAP sea of (Hs, Tp)."""
    ratio = tp / math.sqrt(hs)
    if ratio <= 3.6:
        return 5.0
    if ratio >= 5.0:
        return 1.0
    return math.exp(5.75 - 1.15 * ratio)


def _pm_shape(omega: np.ndarray, omega_peak: float) -> np.ndarray:
    """``w^-5 exp(-5/4 (wp/w)^4)``, zero at w <= 0."""
    omega = np.asarray(omega, dtype=float)
    out = np.zeros_like(omega)
    pos = omega > 0
    w = omega[pos]
    out[pos] = w**-5 * np.exp(-1.25 * (omega_peak / w) ** 4)
    return out


def _peak_enhancement(omega: np.ndarray, omega_peak: float, gamma: float) -> np.ndarray:
    """``gamma^r``, ``r = exp(-(w - wp)^2 / (2 sigma^2 wp^2))``, sigma 0.07 below wp, 0.09 above."""
    omega = np.asarray(omega, dtype=float)
    sigma = np.where(omega <= omega_peak, 0.07, 0.09)
    r = np.exp(-((omega - omega_peak) ** 2) / (2.0 * sigma**2 * omega_peak**2))
    return gamma**r


def kitaigorodskii_factor(omega: np.ndarray, depth: float, g: float = G) -> np.ndarray:
    """Exact TMA depth factor ``tanh^2(kh) / (1 + 2kh / sinh(2kh))`` (1 in deep water)."""
    omega = np.asarray(omega, dtype=float)
    if math.isinf(depth):
        return np.ones_like(omega)
    kh = k_from_omega(omega, depth, g) * depth
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        e = np.exp(-2.0 * kh)
        ratio = np.where(kh > 0, 4.0 * kh * e / (1.0 - e * e), 1.0)  # 2kh / sinh(2kh)
    return np.tanh(kh) ** 2 / (1.0 + ratio)


@dataclass(frozen=True)
class PiersonMoskowitz:
    """Pierson-Moskowitz: ``S = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (wp/w)^4)`` (m0 = Hs^2/16 exactly)."""

    hs: float
    tp: float

    def __post_init__(self) -> None:
        require_positive("hs", self.hs)
        require_positive("tp", self.tp)

    @property
    def omega_peak(self) -> float:
        return 2.0 * math.pi / self.tp

    def density(self, omega: np.ndarray) -> np.ndarray:
        wp = self.omega_peak
        return 5.0 / 16.0 * self.hs**2 * wp**4 * _pm_shape(omega, wp)


@dataclass(frozen=True)
class Jonswap:
    """JONSWAP from (Hs, Tp, gamma), DNV form, renormalised to exact Hs.

    ``gamma=None`` takes the DNV default from Tp / sqrt(Hs). With finite ``depth`` this is the
    TMA spectrum: the JONSWAP shape times the exact Kitaigorodskii factor, renormalised so
    that Hs is still the given one (Tp is that of the deep-water parent).
    """

    hs: float
    tp: float
    gamma: float | None = None
    depth: float = math.inf
    g: float = G
    _scale: float = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        hs, tp = require_positive("hs", self.hs), require_positive("tp", self.tp)
        depth = require_positive("depth", self.depth, allow_infinite=True)
        gamma = require_at_least("gamma", dnv_gamma(hs, tp) if self.gamma is None else self.gamma, 1.0)
        if gamma > 20.0:
            raise ParameterError(f"gamma must be <= 20, got {self.gamma!r}")
        for name, value in (("hs", hs), ("tp", tp), ("gamma", gamma), ("depth", depth), ("g", float(self.g))):
            object.__setattr__(self, name, value)  # plain floats: the m0 cache's key, and one arithmetic
        m0 = _jonswap_shape_m0(self.tp, self.gamma, self.depth, self.g)
        object.__setattr__(self, "_scale", self.hs**2 / 16.0 / m0)

    @property
    def omega_peak(self) -> float:
        return 2.0 * math.pi / self.tp

    def density(self, omega: np.ndarray) -> np.ndarray:
        return self._scale * _jonswap_shape(omega, self.tp, self.gamma, self.depth, self.g)


def _jonswap_shape(omega: np.ndarray, tp: float, gamma: float, depth: float, g: float) -> np.ndarray:
    """The JONSWAP (TMA at finite depth) shape before scaling to Hs."""
    wp = 2.0 * math.pi / tp
    return _pm_shape(omega, wp) * _peak_enhancement(omega, wp, gamma) * kitaigorodskii_factor(omega, depth, g)


@functools.lru_cache(maxsize=256)
def _jonswap_shape_m0(tp: float, gamma: float, depth: float, g: float) -> float:
    """m0 of :func:`_jonswap_shape`, kept: a live change of Hs alone needs no new quadrature."""
    return spectral_moment(lambda w: _jonswap_shape(w, tp, gamma, depth, g), 0, 2.0 * math.pi / tp)


@dataclass(frozen=True)
class JonswapFetch:
    """JONSWAP from wind speed U10 (m/s) and fetch (m), Hasselmann et al. 1973, gamma = 3.3.

    ``alpha = 0.076 x^-0.22``, ``wp = 22 (g / U10) x^(-1/3)`` with ``x = g F / U10^2``, the fetch counting up to a
    fully developed sea's (:func:`~marinesim.sea.kinds.fetch_limited`). Hs follows from the spectrum (it is an
    output here, not an input).
    """

    u10: float
    fetch: float
    gamma: float = 3.3
    g: float = G
    hs: float = field(init=False)

    def __post_init__(self) -> None:
        require_positive("u10", self.u10)
        require_positive("fetch", self.fetch)
        require_at_least("gamma", self.gamma, 1.0)
        object.__setattr__(self, "hs", 4.0 * math.sqrt(spectral_moment(self.density, 0, self.omega_peak)))

    @property
    def alpha(self) -> float:
        return 0.076 * fetch_limited(self.u10, self.fetch, self.g)[0] ** -0.22

    @property
    def omega_peak(self) -> float:
        return fetch_limited(self.u10, self.fetch, self.g)[1]

    @property
    def tp(self) -> float:
        return 2.0 * math.pi / self.omega_peak

    def density(self, omega: np.ndarray) -> np.ndarray:
        wp = self.omega_peak
        shape = _pm_shape(omega, wp) * _peak_enhancement(omega, wp, self.gamma)
        return self.alpha * self.g**2 * shape


@dataclass(frozen=True)
class Tma(Jonswap):
    """TMA spectrum: JONSWAP at finite depth (Bouws et al. 1985), see :class:`Jonswap`."""

    def __post_init__(self) -> None:
        if math.isinf(self.depth):
            raise ParameterError("depth must be finite for a TMA spectrum")
        super().__post_init__()
