"""What a criterion's value is expected to be in the sea the vessel met: the distribution of the value a record
gives, from the spectral moments of the criterion's series, and where a realised value falls in it.

A run is cut into *stretches* of steady sea, heading and speed (:class:`Stretch`), each with the moments of the
criterion's series (:class:`Moments`: m0, m2, and ``s2 = integral S(w_e)^2 dw_e`` on the window's frequency
resolution 2 pi / T) from the spectral engine (:mod:`.spectral`'s transfer functions, the ones the operability
study uses). The series is a zero-mean Gaussian process; what a record makes of it (REFERENCES section 8):

| family | quantities | distribution |
|---|---|---|
| largest value | ``*_max_deg``, ``vertical_velocity_max_m_s`` | ``P(max |x| <= a) = exp(-sum_i 2 d_i nu_i exp(-r^2/2) (1 - exp(-sqrt(pi/2) q r)) / (1 - exp(-r^2/2)))``, r = a / sqrt(m0_i), nu = sqrt(m2/m0) / 2 pi, q = sqrt(1 - m1^2 / (m0 m2)): |x| crosses a at Rice's rate twice (both signs), the crossings clumped as Vanmarcke (1975) derives (with Poisson crossings a JONSWAP record's windows fall 17 % below the 10th percentile; with his empirical q^1.2, 8 %; with q, 10 %: the tests) |
| mean square | ``*_rms_*``, ``heave_rate_significant_m_s`` (2 RMS) | the window's mean square is Gamma with mean ``sum d m0 / T`` and variance ``2 pi sum d s2 / T^2`` (the variance of a record's mean square, Bendat & Piersol 8.2: ``2 pi / T integral S^2``, i.e. 2 B T degrees of freedom) |
| of the mean square | ``relative_motion_exceedance``, ``slamming_probability``, ``msi_pct`` | the value is an increasing function of the window's mean square: its distribution carried over |
| dose | ``msdv_m_s1_5`` | ``MSDV^2 = integral a_w^2 dt``: the mean square's Gamma over the whole exposure |
| largest oscillation | ``mahr_m_s`` | heights Rayleigh, ``P(H > h) = exp(-h^2 / (8 m0))``, d nu oscillations a stretch, each over half its Tz |

A ship's heel in a turn is an offset under the waves' series (roll, the deck's inclination, the lateral specific
force ``g sin(heel)``): its mean square adds to the mean square, and the largest value crosses the barriers a - h
and a + h.

``inclination_max_deg`` is read as the largest value of a series of variance ``m0_roll + m0_pitch`` (the study's
approximation: the tilt's magnitude is not Gaussian). ``mii_per_min`` (level crossings of a force ratio) and the
station's ``offset_max_m`` (not a wave-frequency response) have none.

The *worst* value of a run (what the verdict reads) is the largest of its windows: for the largest-value families
the largest over the whole record (the windows cover it); for the mean-square families the largest over the
monitor's sliding windows, the short ones of the settling included, found by drawing the windows' mean squares
(:func:`_sliding_worst`); a dose's worst is its value at the end.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.special import gammainc

from marinesim.criteria.monitor import EVALUATE_S, SETTLE_FRACTION, Criterion
from marinesim.criteria.quantities import WINDOW_S
from marinesim.criteria.spectral import (ResponseSeries, encounter_frequency, transfers, trapezoid_weights,
                                         value_from_moments)
from marinesim.sea.dispersion import k_from_omega
from marinesim.sea.seastate import SeaState
from marinesim.sea.spreading import LongCrested
from marinesim.vessel.rao import RaoTable

OMEGA = np.geomspace(2.0 * math.pi / 40.0, 2.0 * math.pi / 0.8, 560)
"""Wave frequencies of the quadrature (rad/s): periods 40 to 0.8 s, a step of 0.7 % of w."""
THETA = np.radians(np.arange(0.0, 360.0, 2.5))
"""Travel directions of the quadrature (rad, CCW from east, docs/CONVENTIONS.md); a long-crested system is put on
the nearest."""
MAX_FAMILY = {"roll_max_deg", "pitch_max_deg", "vertical_velocity_max_m_s", "inclination_max_deg"}
RMS_FAMILY = {"roll_rms_deg": 1.0, "pitch_rms_deg": 1.0, "heave_rms_m": 1.0, "vertical_acc_rms_m_s2": 1.0,
              "lateral_acc_rms_m_s2": 1.0, "heave_rate_significant_m_s": 2.0}
"""Quantities that are a multiple (the value) of the window's RMS."""
WORST_RUNS = 400
"""Draws of a run that give the distribution of a windowed mean square's worst (:func:`_sliding_worst`)."""
WORST_SEED = 37
"""Their seed: the same run gives the same expectation."""
OF_MEAN_SQUARE = {"relative_motion_exceedance", "slamming_probability", "msi_pct"}
EXPECTED = MAX_FAMILY | set(RMS_FAMILY) | OF_MEAN_SQUARE | {"msdv_m_s1_5", "mahr_m_s"}
"""The quantities this module gives a distribution for."""


@dataclass(frozen=True)
class Moments:
    """A series' spectral moments in a steady sea over encounter frequency: ``m0`` its variance, ``m1``, ``m2`` its
    rate's variance, and ``s2`` the integral of its spectrum squared (unit^4 s/rad), resolved at the window's
    2 pi / T."""

    m0: float
    m1: float
    m2: float
    s2: float


@dataclass(frozen=True)
class Stretch:
    """``duration_s`` (s) of record in a steady sea, the criterion's series having ``moments`` there about a slowly
    varying offset (a ship's heel in a turn) of mean square ``offset_ms`` (unit^2) and largest size ``offset_max``
    (the series' unit)."""

    duration_s: float
    moments: Moments
    offset_ms: float = 0.0
    offset_max: float = 0.0


class Expected:
    """A value's distribution: :meth:`cdf`, :meth:`quantile`, the :attr:`median`."""

    def __init__(self, cdf: Callable[[float], float], scale: float) -> None:
        self._cdf = cdf
        self.scale = scale
        """A typical size of the value (its unit): where the search for a quantile starts."""

    def cdf(self, x: float) -> float:
        """P(value <= ``x``)."""
        return float(min(max(self._cdf(float(x)), 0.0), 1.0))

    def quantile(self, p: float) -> float:
        """The value below which the share ``p`` of outcomes lies (bisection to 1e-6 of its scale)."""
        lo, hi = 0.0, self.scale
        while self.cdf(hi) < p:
            hi *= 2.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.cdf(mid) < p else (lo, mid)
            if hi - lo < 1e-6 * self.scale:
                break
        return 0.5 * (lo + hi)

    @cached_property
    def median(self) -> float:
        return self.quantile(0.5)

    def percentile(self, x: float) -> float:
        """Where ``x`` falls, in percent of outcomes at or below it."""
        return 100.0 * self.cdf(x)


def directional_density(sea: SeaState) -> np.ndarray | None:
    """``S(w) D(theta)`` of ``sea``'s spectral systems on :data:`OMEGA` x :data:`THETA` (W, D), m^2 s/rad^2 per rad
    of direction; None for a sea with regular waves (a regular wave's response is not random)."""
    if sea.regular_waves:
        return None
    out = np.zeros((OMEGA.size, THETA.size))
    step = THETA[1] - THETA[0]
    for system in sea.spectral_systems:
        if isinstance(system.spreading, LongCrested):
            column = int(np.round(np.mod(system.beta, 2.0 * math.pi) / step)) % THETA.size
            out[:, column] += system.spectrum.density(OMEGA) / step
        else:
            grid_w, grid_t = np.meshgrid(OMEGA, THETA, indexing="ij")
            out += system.directional_density(grid_w, grid_t)
    return out


@dataclass(frozen=True)
class Met:
    """The vessel's transfer functions on the quadrature's grid as she meets it heading ``heading_rad`` (rad, CCW
    from east) at ``speed_m_s``: ``x`` (W, D, 6) her RAOs, ``omega_e`` (W, D) rad/s, ``k`` (W,) rad/m, ``beta`` (D,)
    the relative headings (rad)."""

    x: np.ndarray
    omega_e: np.ndarray
    k: np.ndarray
    beta: np.ndarray

    @classmethod
    def of(cls, rao: RaoTable, heading_rad: float, speed_m_s: float, depth_m: float) -> Met:
        beta = THETA - heading_rad
        grid_w, grid_b = np.meshgrid(OMEGA, beta, indexing="ij")
        x = rao(grid_w.ravel(), grid_b.ravel(), speed_m_s).reshape(OMEGA.size, THETA.size, 6)
        k = k_from_omega(OMEGA, depth_m, rao.g)
        return cls(x, encounter_frequency(OMEGA, k, beta, speed_m_s), k, beta)


def sea_moments(met: Met, points: dict[str, tuple[float, float, float]], criteria: Sequence[Criterion],
                density: np.ndarray) -> list[Moments | None]:
    """The moments of each criterion's series (None where :data:`EXPECTED` has no family for it) in the sea of
    ``density`` (:func:`directional_density`) met as ``met`` says, the points in the body frame (m)."""
    weight = density * (trapezoid_weights(OMEGA)[:, None] * (THETA[1] - THETA[0]))  # (W, D) m^2
    series = ResponseSeries(met.x, met.omega_e, met.k, met.beta, points, weight[None])
    out: list[Moments | None] = []
    for criterion in criteria:
        if criterion.quantity not in EXPECTED:
            out.append(None)
            continue
        m0 = m1 = m2 = 0.0
        resolution = 2.0 * math.pi / (criterion.window or WINDOW_S)
        edges = np.arange(0.0, met.omega_e.max() + 2.0 * resolution, resolution)
        spectrum = np.zeros(edges.size - 1)
        for transfer in transfers(criterion, series):
            power = np.abs(transfer) ** 2 * weight
            m0 += float(power.sum())
            m1 += float((power * met.omega_e).sum())
            m2 += float((power * met.omega_e ** 2).sum())
            spectrum += np.histogram(met.omega_e, edges, weights=power)[0]
        out.append(Moments(m0, m1, m2, float(np.sum(spectrum ** 2) / resolution)))
    return out


def _gamma_cdf(stretches: Sequence[Stretch]) -> tuple[Callable[[float], float], float]:
    """The cdf of a record's mean square over ``stretches`` (the waves' Gamma, moments matched, on top of the
    offsets' mean square) and its mean."""
    total = sum(s.duration_s for s in stretches)
    mean = sum(s.duration_s * s.moments.m0 for s in stretches) / total
    offset = sum(s.duration_s * s.offset_ms for s in stretches) / total
    variance = 2.0 * math.pi * sum(s.duration_s * s.moments.s2 for s in stretches) / total ** 2
    if not mean > 0.0 or not variance > 0.0:
        return (lambda y: 1.0 if y >= mean + offset else 0.0), mean + offset
    shape, scale = mean * mean / variance, variance / mean
    return (lambda y: float(gammainc(shape, max(y - offset, 0.0) / scale))), mean + offset


def _rate(m: Moments) -> float:
    """Mean zero-upcrossing rate (1/s)."""
    return math.sqrt(m.m2 / m.m0) / (2.0 * math.pi) if m.m0 > 0.0 else 0.0


def _crossings(m: Moments, a: float, barriers: int = 2) -> float:
    """Vanmarcke's rate (1/s) of first crossings of a level ``a`` above the mean: of |x| = a (``barriers`` 2), or of
    x = a alone (1); Rice's rate, clumped. A level at or below the mean is crossed at once."""
    if a <= 0.0:
        return math.inf
    if not (m.m0 > 0.0 and m.m2 > 0.0):
        return 0.0
    r2 = a * a / m.m0
    q = math.sqrt(max(1.0 - m.m1 * m.m1 / (m.m0 * m.m2), 0.0))
    clump = math.sqrt((0.5 if barriers == 2 else 2.0) * math.pi * r2) * q
    return barriers * _rate(m) * math.exp(-0.5 * r2) * -math.expm1(-clump) / -math.expm1(-0.5 * r2)


def _largest(stretches: Sequence[Stretch]) -> Expected:
    sigma = math.sqrt(max(s.moments.m0 for s in stretches))

    def cdf(a: float) -> float:  # an offset h: the single barriers a - h and a + h
        return math.exp(-sum(s.duration_s * (_crossings(s.moments, a) if s.offset_max == 0.0 else (
            _crossings(s.moments, a - s.offset_max, 1) + _crossings(s.moments, a + s.offset_max, 1)))
                             for s in stretches))
    return Expected(cdf, max(sigma, 1e-12))


def _mahr(stretches: Sequence[Stretch]) -> Expected:
    sigma = math.sqrt(max(s.moments.m0 for s in stretches))

    def cdf(x: float) -> float:
        count = 0.0
        for s in stretches:
            m = s.moments
            if m.m0 > 0.0 and m.m2 > 0.0:
                half_tz = math.pi * math.sqrt(m.m0 / m.m2)
                count += s.duration_s * _rate(m) * math.exp(-(x * half_tz) ** 2 / (8.0 * m.m0))
        return math.exp(-count)
    return Expected(cdf, max(sigma, 1e-12))


def _mean_square_to_value(criterion: Criterion, stretches: Sequence[Stretch]) -> Callable[[float], float]:
    """The criterion's value as a function of the window's mean square (:data:`OF_MEAN_SQUARE`): its spectral formula
    (:func:`~marinesim.criteria.spectral.value_from_moments`) with the rate's mean square in the stretches'
    proportion m2 / m0."""
    m0 = sum(s.duration_s * s.moments.m0 for s in stretches)
    ratio = sum(s.duration_s * s.moments.m2 for s in stretches) / m0 if m0 > 0 else 0.0
    return lambda y: float(value_from_moments(criterion, y, y * ratio, 0.0)) if y > 0 else 0.0


def _window(criterion: Criterion, stretches: Sequence[Stretch]) -> Expected:
    """The distribution of the value of one window of record made of ``stretches``."""
    q = criterion.quantity
    if q in MAX_FAMILY:
        return _largest(stretches)
    if q == "mahr_m_s":
        return _mahr(stretches)
    cdf, mean = _gamma_cdf(stretches)
    if q in RMS_FAMILY:
        factor = RMS_FAMILY[q]
        return Expected(lambda x: cdf((x / factor) ** 2), factor * math.sqrt(max(mean, 1e-24)))
    if q == "msdv_m_s1_5":
        total = sum(s.duration_s for s in stretches)
        return Expected(lambda x: cdf(x * x / total), math.sqrt(max(mean * total, 1e-24)))
    value = _mean_square_to_value(criterion, stretches)
    top = value(mean) if mean > 0 else 1.0

    def of_value(v: float) -> float:  # the mean square giving v, by bisection on the increasing map
        if v <= 0.0:
            return 0.0
        lo, hi = 0.0, max(mean, 1e-24)
        while value(hi) < v and hi < 1e12 * max(mean, 1e-24):
            hi *= 2.0
        if value(hi) < v:
            return 1.0
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if value(mid) < v else (lo, mid)
        return cdf(0.5 * (lo + hi))
    return Expected(of_value, max(top, 1e-12))


def window_expected(criterion: Criterion, stretches: Sequence[Stretch]) -> Expected | None:
    """The distribution of ``criterion``'s value over one window of record made of ``stretches`` (None: no family
    for its quantity, or no record)."""
    stretches = [s for s in stretches if s.duration_s > 0.0]
    if criterion.quantity not in EXPECTED or not stretches:
        return None
    return _window(criterion, stretches)


def run_expected(criterion: Criterion, stretches: Sequence[Stretch]) -> Expected | None:
    """The distribution of ``criterion``'s worst value over a run made of ``stretches`` (in time order): the
    largest over the whole record, the largest of the monitor's sliding windows (:func:`_sliding_worst`), or the
    dose at the end (the module's docstring)."""
    stretches = [s for s in stretches if s.duration_s > 0.0]
    if criterion.quantity not in EXPECTED or not stretches:
        return None
    q = criterion.quantity
    if q in MAX_FAMILY or q == "mahr_m_s" or q == "msdv_m_s1_5":
        return _window(criterion, stretches)
    worst = _sliding_worst(stretches, criterion.window)
    if q in RMS_FAMILY:
        values = RMS_FAMILY[q] * np.sqrt(worst)
    else:
        to_value = _mean_square_to_value(criterion, stretches)
        values = np.array([to_value(y) for y in worst])
    shares = (np.arange(values.size) + 0.5) / values.size
    return Expected(lambda x: float(np.interp(x, values, shares, left=0.0, right=1.0)),
                    max(float(np.median(values)), 1e-12))


def _sliding_worst(stretches: Sequence[Stretch], window_s: float) -> np.ndarray:
    """The largest mean square of the monitor's windows over a run of ``stretches`` in :data:`WORST_RUNS` seeded draws,
    sorted (unit^2): windows of ``window_s`` ending every :data:`EVALUATE_S`, counted once a quarter full
    (:data:`SETTLE_FRACTION`). Within a window the series' mean square is its envelope's, ``m0 |u|^2`` plus the
    offset, ``u`` a complex Ornstein-Uhlenbeck process of unit variance whose correlation time ``2 pi s2 / m0^2``
    gives a full window's mean square the variance of :func:`_gamma_cdf`."""
    ends = np.cumsum([s.duration_s for s in stretches])
    times = np.arange(0.5 * EVALUATE_S, ends[-1], EVALUATE_S)
    at = [stretches[i] for i in np.minimum(np.searchsorted(ends, times, side="right"), len(stretches) - 1)]
    m0 = np.array([s.moments.m0 for s in at])
    offset = np.array([s.offset_ms for s in at])
    with np.errstate(divide="ignore", invalid="ignore"):
        tau = np.where(m0 > 0, 2.0 * math.pi * np.array([s.moments.s2 for s in at]) / m0 ** 2, 1.0)
    rho = np.exp(-EVALUATE_S / np.maximum(tau, 1e-6))
    rng = np.random.default_rng(WORST_SEED)
    u = (rng.standard_normal(WORST_RUNS) + 1j * rng.standard_normal(WORST_RUNS)) / math.sqrt(2.0)
    square = np.empty((times.size, WORST_RUNS))
    for k in range(times.size):
        if k:
            noise = (rng.standard_normal(WORST_RUNS) + 1j * rng.standard_normal(WORST_RUNS)) / math.sqrt(2.0)
            u = rho[k] * u + math.sqrt(1.0 - rho[k] ** 2) * noise
        square[k] = m0[k] * np.abs(u) ** 2 + offset[k]
    total = np.vstack([np.zeros(WORST_RUNS), np.cumsum(square, axis=0)])
    last = np.arange(1, times.size + 1)
    length = np.minimum(last, max(int(round(window_s / EVALUATE_S)), 1))
    counted = length * EVALUATE_S >= min(SETTLE_FRACTION * window_s, times.size * EVALUATE_S) - 1e-9
    means = (total[last[counted]] - total[last[counted] - length[counted]]) / length[counted][:, None]
    return np.sort(means.max(axis=0))
