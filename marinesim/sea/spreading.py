"""Directional spreading functions ``D(dtheta; w)`` (docs/REFERENCES.md §2).

``dtheta`` is the angle (rad) between a component's travel direction and the system's mean
travel direction. Every spreading integrates to 1 over the full circle at every frequency.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.special import gammaln

from marinesim.angles import wrap_angle
from marinesim.errors import ParameterError, require_at_least, require_positive


def cos2s_normalisation(s: np.ndarray | float) -> np.ndarray:
    """``C(s) = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2))`` (log-gamma form, no overflow)."""
    s = np.asarray(s, dtype=float)
    return np.exp(gammaln(s + 1.0) - gammaln(s + 0.5)) / (2.0 * math.sqrt(math.pi))


def _cos2s(dtheta: np.ndarray, s: np.ndarray | float) -> np.ndarray:
    half = np.cos(0.5 * wrap_angle(dtheta))
    return cos2s_normalisation(s) * np.abs(half) ** (2.0 * np.asarray(s))


@dataclass(frozen=True)
class LongCrested:
    """No spreading: a delta in angle. It has no ``density``; the ocean samples it along a ray."""

    def mean_resultant_length(self, omega: np.ndarray) -> np.ndarray:
        return np.ones_like(np.asarray(omega, dtype=float))


@dataclass(frozen=True)
class Cos2s:
    """Longuet-Higgins ``D = C(s) cos^{2s}(dtheta / 2)`` on (-pi, pi], constant s."""

    s: float

    def __post_init__(self) -> None:
        require_positive("spreading s", self.s)
        if self.s > 1000.0:
            raise ParameterError(f"spreading s must be <= 1000 (use long-crested), got {self.s!r}")

    def density(self, dtheta: np.ndarray, omega: np.ndarray) -> np.ndarray:
        return _cos2s(dtheta, self.s) * np.ones_like(np.asarray(omega, dtype=float))

    def mean_resultant_length(self, omega: np.ndarray) -> np.ndarray:
        """``integral D cos(dtheta) = s / (s + 1)``."""
        return np.full_like(np.asarray(omega, dtype=float), self.s / (self.s + 1.0))


@dataclass(frozen=True)
class Mitsuyasu:
    """cos-2s with frequency-dependent ``s = s_p (w/wp)^5`` below the peak, ``(w/wp)^-2.5`` above.

    ``s_peak`` is s at the peak frequency ``omega_peak``; for a wind sea Mitsuyasu gives
    ``s_p = 11.5 (wp U10 / g)^-2.5`` (:meth:`from_wind`).
    """

    s_peak: float
    omega_peak: float

    def __post_init__(self) -> None:
        require_positive("spreading s", self.s_peak)
        require_positive("omega_peak", self.omega_peak)

    @classmethod
    def from_wind(cls, u10: float, omega_peak: float, g: float) -> "Mitsuyasu":
        return cls(11.5 * (omega_peak * u10 / g) ** -2.5, omega_peak)

    def s(self, omega: np.ndarray) -> np.ndarray:
        r = np.asarray(omega, dtype=float) / self.omega_peak
        with np.errstate(divide="ignore"):
            s = self.s_peak * np.where(r <= 1.0, r**5, r**-2.5)
        return np.clip(s, 1e-6, 1000.0)

    def density(self, dtheta: np.ndarray, omega: np.ndarray) -> np.ndarray:
        return _cos2s(dtheta, self.s(omega))

    def mean_resultant_length(self, omega: np.ndarray) -> np.ndarray:
        s = self.s(omega)
        return s / (s + 1.0)


@dataclass(frozen=True)
class HalfPlaneCos2n:
    """``D = cos^{2n}(dtheta) / C1`` on [-pi/2, pi/2], zero behind; ``C1 = sqrt(pi) G(n+1/2)/G(n+1)``.

    The form of seed 003 (OceanSimulator); not the same function as cos-2s.
    """

    n: float

    def __post_init__(self) -> None:
        require_at_least("spreading n", self.n, 0.5)
        if self.n > 1000.0:
            raise ParameterError(f"spreading n must be <= 1000, got {self.n!r}")

    def _c1(self) -> float:
        return math.sqrt(math.pi) * math.exp(gammaln(self.n + 0.5) - gammaln(self.n + 1.0))

    def density(self, dtheta: np.ndarray, omega: np.ndarray) -> np.ndarray:
        d = wrap_angle(dtheta)
        value = np.where(np.abs(d) <= 0.5 * math.pi, np.cos(d) ** (2.0 * self.n), 0.0) / self._c1()
        return value * np.ones_like(np.asarray(omega, dtype=float))

    def mean_resultant_length(self, omega: np.ndarray) -> np.ndarray:
        """``integral cos^{2n+1} / C1 = Gamma(n+1)^2 / (Gamma(n+1/2) Gamma(n+3/2))``."""
        n = self.n
        r = math.exp(2.0 * gammaln(n + 1.0) - gammaln(n + 0.5) - gammaln(n + 1.5))
        return np.full_like(np.asarray(omega, dtype=float), r)


Spreading = LongCrested | Cos2s | Mitsuyasu | HalfPlaneCos2n
