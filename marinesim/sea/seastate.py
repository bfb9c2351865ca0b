"""Sea states: one or more wave systems (wind sea, swell, regular waves) over a common depth.

Directions are internal (docs/CONVENTIONS.md): ``beta`` is the travel direction, rad, CCW from
east. Use :func:`marinesim.angles.wave_beta_from_compass` at the edges.
"""

from __future__ import annotations

import math
import dataclasses
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from scipy import optimize

from marinesim.constants import G
from marinesim.errors import ParameterError, require_finite, require_positive
from marinesim.sea.dispersion import k_from_omega
from marinesim.sea.kinds import BREAKING_DEPTH_RATIO, MAX_DEPTH_M
from marinesim.sea.spectra import Jonswap, JonswapFetch, Spectrum, spectral_moment
from marinesim.sea.spreading import LongCrested, Spreading


@dataclass(frozen=True)
class WaveSystem:
    """A continuous spectrum travelling towards ``beta`` (rad) with a directional spreading."""

    spectrum: Spectrum
    beta: float
    spreading: Spreading = field(default_factory=LongCrested)

    def __post_init__(self) -> None:
        require_finite("wave direction", self.beta)

    def directional_density(self, omega: np.ndarray, theta: np.ndarray) -> np.ndarray:
        """``S(w) D(theta - beta; w)`` in m^2 s/rad^2 (spread systems only)."""
        return self.spectrum.density(omega) * self.spreading.density(theta - self.beta, omega)


@dataclass(frozen=True)
class RegularWave:
    """An Airy wave ``eta = H/2 cos(w t - k.x + phase)`` travelling towards ``beta`` (rad)."""

    height: float
    period: float
    beta: float
    phase: float = 0.0

    def __post_init__(self) -> None:
        require_positive("wave height", self.height)
        require_positive("wave period", self.period)
        require_finite("wave direction", self.beta)
        require_finite("wave phase", self.phase)

    @property
    def omega(self) -> float:
        return 2.0 * math.pi / self.period

    @property
    def variance(self) -> float:
        """Variance of the elevation, ``H^2 / 8`` (m^2)."""
        return self.height**2 / 8.0


@dataclass(frozen=True)
class SeaState:
    """The sum of wave systems over water of ``depth`` (m; ``math.inf`` = deep).

    Immutable: its integral figures (Hs, Tz, Tp, mean direction) are computed once and kept, so a
    display may ask for them every frame."""

    systems: tuple[WaveSystem | RegularWave, ...]
    depth: float = math.inf
    g: float = G

    def __post_init__(self) -> None:
        object.__setattr__(self, "systems", tuple(self.systems))
        if not self.systems:
            raise ParameterError("a sea state needs at least one wave system")
        if require_positive("depth", self.depth, allow_infinite=True) > MAX_DEPTH_M and not math.isinf(self.depth):
            raise ParameterError(f"depth must be <= {MAX_DEPTH_M:g} m (or infinite: deep water), got {self.depth!r}")
        height = math.sqrt(sum(s.spectrum.hs**2 for s in self.spectral_systems)
                           + sum(r.height**2 for r in self.regular_waves))  # Hs, or a regular wave's H
        if height > BREAKING_DEPTH_RATIO * self.depth:
            raise ParameterError(f"depth {self.depth:g} m is too shallow for a sea of {height:.3g} m: waves break "
                                 f"where H > {BREAKING_DEPTH_RATIO:g} x depth, so it needs at least "
                                 f"{height / BREAKING_DEPTH_RATIO:.3g} m")
        for system in self.spectral_systems:
            spectrum_depth = getattr(system.spectrum, "depth", math.inf)
            if spectrum_depth != self.depth and not math.isinf(spectrum_depth):
                raise ParameterError(
                    f"depth of the TMA spectrum ({spectrum_depth:g} m) differs from the sea "
                    f"state's depth ({self.depth:g} m)"
                )

    @property
    def spectral_systems(self) -> list[WaveSystem]:
        return [s for s in self.systems if isinstance(s, WaveSystem)]

    @property
    def regular_waves(self) -> list[RegularWave]:
        return [s for s in self.systems if isinstance(s, RegularWave)]

    def density(self, omega: np.ndarray) -> np.ndarray:
        """Sum of the continuous spectra, ``S(w)`` in m^2 s/rad (regular waves excluded)."""
        omega = np.asarray(omega, dtype=float)
        return sum((s.spectrum.density(omega) for s in self.spectral_systems), np.zeros_like(omega))

    def moment(self, n: int) -> float:
        """``m_n``: continuous spectra by quadrature plus regular waves ``H^2/8 w^n``."""
        m = sum(spectral_moment(s.spectrum.density, n, _omega_peak(s)) for s in self.spectral_systems)
        return m + sum(r.variance * r.omega**n for r in self.regular_waves)

    @cached_property
    def hs(self) -> float:
        """Significant wave height ``4 sqrt(m0)`` (m)."""
        return 4.0 * math.sqrt(self.moment(0))

    @cached_property
    def tz(self) -> float:
        """Mean zero-crossing period ``2 pi sqrt(m0 / m2)`` (s)."""
        return 2.0 * math.pi * math.sqrt(self.moment(0) / self.moment(2))

    @cached_property
    def tp(self) -> float:
        """Peak period (s) of the summed continuous spectra; of the largest regular wave if none."""
        if not self.spectral_systems:
            return max(self.regular_waves, key=lambda r: r.variance).period
        peaks = [_omega_peak(s) for s in self.spectral_systems]
        grid = np.linspace(0.3 * min(peaks), 2.0 * max(peaks), 4000)
        i = int(np.argmax(self.density(grid)))
        lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
        best = optimize.minimize_scalar(
            lambda w: -float(self.density(np.array([w]))[0]), bounds=(lo, hi), method="bounded",
            options={"xatol": 1e-10},
        )
        return 2.0 * math.pi / best.x

    @cached_property
    def mean_beta(self) -> float:
        """Energy-weighted circular mean travel direction (rad): ``arg integral S D e^{i theta}``."""
        vector = 0j
        for s in self.spectral_systems:
            def weighted(w, s=s):
                return s.spectrum.density(w) * s.spreading.mean_resultant_length(w)
            vector += spectral_moment(weighted, 0, _omega_peak(s)) * np.exp(1j * s.beta)
        for r in self.regular_waves:
            vector += r.variance * np.exp(1j * r.beta)
        return float(np.angle(vector))

    def omega_quantile(self, q: float) -> float:
        """Frequency (rad/s) below which the fraction ``q`` of the continuous spectra's m0 lies."""
        top = 40.0 * max(_omega_peak(s) for s in self.spectral_systems)
        grid = np.linspace(top * 1e-5, top, 400_000)
        cdf = np.cumsum(self.density(grid))
        return float(np.interp(q * cdf[-1], cdf, grid))

    def wavenumber(self, omega: np.ndarray | float) -> np.ndarray:
        """Wave number (rad/m) of ``omega`` at this sea state's depth."""
        return k_from_omega(omega, self.depth, self.g)


def _omega_peak(system: WaveSystem) -> float:
    return 2.0 * math.pi / system.spectrum.tp


def scaled_sea(sea: SeaState, hs_factor: float, tp_factor: float, turn_deg: float) -> SeaState:
    """``sea`` with every height times ``hs_factor``, every period times ``tp_factor`` and every
    direction turned ``turn_deg`` clockwise (compass); spreading unchanged. Hs scales exactly."""
    for name, value in (("Hs factor", hs_factor), ("Tp factor", tp_factor)):
        if not (math.isfinite(value) and value > 0):
            raise ParameterError(f"{name} must be a positive number, got {value!r}")
    turn = -math.radians(turn_deg)  # compass clockwise = math clockwise
    systems = []
    for system in sea.systems:
        if isinstance(system, RegularWave):
            systems.append(dataclasses.replace(system, height=system.height * hs_factor,
                                               period=system.period * tp_factor, beta=system.beta + turn))
            continue
        spectrum = system.spectrum
        if isinstance(spectrum, JonswapFetch):
            spectrum = Jonswap(spectrum.hs, spectrum.tp, spectrum.gamma, g=spectrum.g)
        spectrum = dataclasses.replace(spectrum, hs=spectrum.hs * hs_factor, tp=spectrum.tp * tp_factor)
        systems.append(WaveSystem(spectrum, system.beta + turn, system.spreading))
    return SeaState(tuple(systems), depth=sea.depth, g=sea.g)
