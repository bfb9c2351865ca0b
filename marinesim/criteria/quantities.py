"""The quantities a criterion can name, each with its unit, its default window, the motion columns
it reads and the formula that makes one value of them (REFERENCES section 8).

A quantity is computed over a *window* of the motion record (the columns of
:func:`~marinesim.vessel.response.motion_columns`, sampled at the run's dt), or, for a dose,
accumulated over the whole run. Quantities ``at_point`` read a named point's columns (``{p}``
below); the others read the vessel's own DOFs. Two series are derived from the columns: a point's
lateral and normal specific force in the deck frame (:func:`~marinesim.criteria.interruptions.deck_specific_force`).

| quantity | meaning | formula in |
|---|---|---|
| ``roll_rms_deg``, ``pitch_rms_deg``, ``heave_rms_m`` | RMS over the window (NORDFORSK 1987 limits) | :mod:`.statistics` |
| ``roll_max_deg``, ``pitch_max_deg`` | largest single value in the window | :mod:`.statistics` |
| ``inclination_max_deg`` | largest tilt of the deck plane, roll and pitch combined (CAP 437) | :mod:`.statistics` |
| ``vertical_acc_rms_m_s2`` | RMS vertical acceleration at a point (NORDFORSK) | :mod:`.statistics` |
| ``lateral_acc_rms_m_s2`` | RMS lateral specific force in the deck plane, gravity from roll included | :mod:`.interruptions` |
| ``vertical_velocity_max_m_s`` | largest vertical speed of a point (crane tip, landing) | :mod:`.statistics` |
| ``heave_rate_significant_m_s`` | 2 x RMS vertical velocity (helideck monitoring) | :mod:`.helideck` |
| ``mahr_m_s`` | maximum average heave rate (helideck monitoring) | :mod:`.helideck` |
| ``relative_motion_exceedance`` | Rayleigh probability per oscillation that the relative motion exceeds ``threshold_m`` | :mod:`.statistics` |
| ``slamming_probability`` | probability per oscillation that the relative motion crosses ``threshold_m`` faster than ``threshold_velocity_m_s`` (Ochi 1964) | :func:`slamming_probability` |
| ``msi_pct`` | motion sickness incidence, 2 h (O'Hanlon & McCauley 1974) | :mod:`.sickness` |
| ``msdv_m_s1_5`` | motion sickness dose value over the run (ISO 2631-1, W_f) | :mod:`.sickness` |
| ``mii_per_min`` | motion-induced interruptions, lateral tipping (Graham 1990) | :mod:`.interruptions` |
| ``offset_max_m`` | largest distance of a vessel keeping station from her set point (the DP footprint) | :mod:`.statistics` |
| ``swing_max_deg`` | largest angle of the crane's wire from the vertical (the load's swing) | :mod:`.statistics` |
| ``wire_tension_max_kn`` | largest tension in the crane's wire (snap loads when it comes taut) | :mod:`.statistics` |
| ``set_down_velocity_max_m_s`` | fastest closing of load and deck at a touchdown (DNV-ST-N001 set-down) | :func:`set_down_velocity` |
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from marinesim.constants import G
from marinesim.criteria import helideck, interruptions, sickness, statistics

WINDOW_S = 600.0
"""A criterion's running window unless it says otherwise (s)."""
HELIDECK_WINDOW_S = 1200.0
"""The helideck quantities' window: helideck monitoring systems report over 20 minutes (CAP 437)."""
FOOTPRINT_WINDOW_S = 30.0
"""The footprint's window (s): a DP alarm sounds within seconds of her leaving it, and is cleared as soon."""
STATION_QUANTITIES = ("offset_max_m",)
"""Quantities of a vessel keeping station only (her record has their columns)."""
CRANE_QUANTITIES = ("swing_max_deg", "wire_tension_max_kn", "set_down_velocity_max_m_s")
"""Quantities of a crane's load only (the record has their columns with a ``[crane]``)."""
LATERAL, NORMAL = "{p}_lateral_sf_m_s2", "{p}_normal_sf_m_s2"
"""The derived series: a point's specific force along the deck's y and z axes (m/s^2)."""
OCHI_THRESHOLD = 0.093
"""Ochi's (1964) slamming threshold velocity over sqrt(g L), L the ship's length."""


def ochi_threshold_velocity(length_m: float) -> float:
    """Ochi's slamming threshold velocity ``0.093 sqrt(g L)`` (m/s) for a ship of length ``length_m`` (m)."""
    return OCHI_THRESHOLD * math.sqrt(G * length_m)


@dataclass(frozen=True)
class Options:
    """A criterion's options a quantity may read: ``threshold_m`` (relative motion, m), the
    ``tipping_coefficient`` l/h (interruptions) and ``threshold_velocity_m_s`` (slamming, m/s)."""

    threshold_m: float | None = None
    tipping_coefficient: float = interruptions.DEFAULT_TIPPING_COEFFICIENT
    threshold_velocity_m_s: float | None = None


@dataclass(frozen=True)
class Measure:
    """One quantity: ``value(series, dt, options)`` from the window's ``series`` (name -> 1-D array,
    the names in :attr:`series` with ``{p}`` filled in), or with :attr:`dose` a running total fed
    block by block from the start of the run."""

    unit: str
    what: str
    series: tuple[str, ...]
    value: Callable[[list[np.ndarray], float, Options], float] | None = None
    at_point: bool = False
    window_s: float = WINDOW_S
    dose: Callable[[float], Dose] | None = None
    options: tuple[str, ...] = field(default=())

    def columns(self, point: str | None) -> list[str]:
        """The series this quantity reads, for ``point``."""
        return [name.format(p=point) for name in self.series]


class Dose:
    """A quantity accumulated over the run: the ISO 2631-1 motion sickness dose value of a point's
    W_f-weighted vertical acceleration."""

    def __init__(self, dt: float) -> None:
        self.dt = dt
        self._filter = sickness.WfFilter(dt)
        self._sum = 0.0

    def feed(self, series: list[np.ndarray]) -> None:
        weighted = self._filter.apply(series[0])
        self._sum += float(np.sum(weighted ** 2)) * self.dt

    def value(self) -> float:
        return float(np.sqrt(self._sum))


def _one(function: Callable[[np.ndarray], float]) -> Callable[[list[np.ndarray], float, Options], float]:
    return lambda series, dt, options: function(series[0])


def _inclination(series: list[np.ndarray], dt: float, options: Options) -> float:
    return float(np.max(statistics.inclination_deg(series[0], series[1]), initial=0.0))


def _exceedance(series: list[np.ndarray], dt: float, options: Options) -> float:
    return statistics.rayleigh_exceedance(statistics.rms(series[0]), options.threshold_m)


def relative_velocity(relative: np.ndarray, dt: float) -> np.ndarray:
    """The rate (m/s) of a relative motion record ``relative`` (m, sampled every ``dt`` s) at its samples but the
    first and last two: the fourth-order central difference ``(r[i-2] - 8 r[i-1] + 8 r[i+1] - r[i+2]) / (12 dt)``,
    which gives a sinusoid of frequency w its rate times ``1 - (w dt)^4 / 30`` (1e-5 at w dt = 0.13)."""
    r = np.asarray(relative, float)
    return (r[:-4] - 8.0 * r[1:-3] + 8.0 * r[3:-1] - r[4:]) / (12.0 * dt)


def slamming_probability(relative: np.ndarray, dt: float, threshold_m: float, threshold_velocity_m_s: float) -> float:
    """Probability per oscillation (zero-upcrossing) that a zero-mean Gaussian relative motion ``relative`` (m, every
    ``dt`` s) crosses ``threshold_m`` upwards faster than ``threshold_velocity_m_s`` (m/s), as many times as it
    comes back down through it faster (Ochi's slam, at the re-entry): Rice's rate of those crossings over the
    zero-upcrossing rate, ``exp(-T^2 / (2 sigma_r^2)) exp(-v^2 / (2 sigma_v^2))`` (the motion and its rate are
    independent at one instant), sigma_r and sigma_v the RMS of the record and of its rate
    (:func:`relative_velocity`); NaN for fewer than 5 samples."""
    if np.size(relative) < 5:
        return math.nan
    emergence = statistics.rayleigh_exceedance(statistics.rms(relative), threshold_m)
    return emergence * statistics.rayleigh_exceedance(statistics.rms(relative_velocity(relative, dt)),
                                                      threshold_velocity_m_s)


def _slamming(series: list[np.ndarray], dt: float, options: Options) -> float:
    return slamming_probability(series[0], dt, options.threshold_m, options.threshold_velocity_m_s)


def set_down_velocity(closing: np.ndarray, deck_force: np.ndarray) -> float:
    """The fastest closing speed (m/s) of load and deck at a touchdown: at each row where the deck starts to push
    (``deck_force`` from 0 to > 0), the ``closing`` speed (deck's vertical velocity less the load's) of the row
    before; 0 without a touchdown in the window."""
    touching = np.nan_to_num(np.asarray(deck_force, float)) > 0.0
    onsets = np.flatnonzero(touching[1:] & ~touching[:-1])
    return float(np.max(np.asarray(closing, float)[onsets], initial=0.0))


def _mii(series: list[np.ndarray], dt: float, options: Options) -> float:
    return interruptions.mii_per_minute(series[0], series[1], dt, options.tipping_coefficient)


QUANTITIES: dict[str, Measure] = {
    "roll_rms_deg": Measure("deg", "RMS roll", ("roll_deg",), _one(statistics.rms)),
    "pitch_rms_deg": Measure("deg", "RMS pitch", ("pitch_deg",), _one(statistics.rms)),
    "heave_rms_m": Measure("m", "RMS heave", ("heave_m",), _one(statistics.rms)),
    "roll_max_deg": Measure("deg", "largest roll", ("roll_deg",), _one(statistics.max_abs)),
    "pitch_max_deg": Measure("deg", "largest pitch", ("pitch_deg",), _one(statistics.max_abs)),
    "inclination_max_deg": Measure("deg", "largest deck inclination", ("roll_deg", "pitch_deg"), _inclination,
                                   window_s=HELIDECK_WINDOW_S),
    "vertical_acc_rms_m_s2": Measure("m/s^2", "RMS vertical acceleration", ("{p}_az_m_s2",),
                                     _one(statistics.rms), at_point=True),
    "lateral_acc_rms_m_s2": Measure("m/s^2", "RMS lateral acceleration", (LATERAL,), _one(statistics.rms),
                                    at_point=True),
    "vertical_velocity_max_m_s": Measure("m/s", "largest vertical velocity", ("{p}_vz_m_s",),
                                         _one(statistics.max_abs), at_point=True),
    "heave_rate_significant_m_s": Measure("m/s", "significant heave rate", ("{p}_vz_m_s",),
                                          _one(helideck.significant_heave_rate), at_point=True,
                                          window_s=HELIDECK_WINDOW_S),
    "mahr_m_s": Measure("m/s", "maximum average heave rate", ("{p}_z_m",),
                        lambda series, dt, options: helideck.mahr(series[0], dt), at_point=True,
                        window_s=HELIDECK_WINDOW_S),
    "relative_motion_exceedance": Measure("", "probability the relative motion exceeds threshold_m",
                                          ("{p}_relative_m",), _exceedance, at_point=True,
                                          options=("threshold_m",)),
    "slamming_probability": Measure("", "probability the relative motion crosses threshold_m faster than "
                                        "threshold_velocity_m_s", ("{p}_relative_m",), _slamming,
                                    at_point=True, options=("threshold_m", "threshold_velocity_m_s")),
    "msi_pct": Measure("%", "motion sickness incidence (2 h)", ("{p}_az_m_s2",),
                       lambda series, dt, options: sickness.msi_of_record(series[0], dt), at_point=True),
    "msdv_m_s1_5": Measure("m/s^1.5", "motion sickness dose value", ("{p}_az_m_s2",), at_point=True, dose=Dose),
    "offset_max_m": Measure("m", "largest offset from the set point", ("set_point_offset_m",),
                            _one(statistics.max_abs), window_s=FOOTPRINT_WINDOW_S),
    "swing_max_deg": Measure("deg", "largest swing of the load", ("crane_swing_deg",), _one(statistics.max_abs),
                             window_s=120.0),
    "wire_tension_max_kn": Measure("kN", "largest wire tension", ("crane_tension_kn",), _one(statistics.max_abs),
                                   window_s=120.0),
    "set_down_velocity_max_m_s": Measure("m/s", "fastest set-down", ("crane_relative_velocity_m_s",
                                                                     "crane_deck_force_kn"),
                                         lambda series, dt, options: set_down_velocity(series[0], series[1]),
                                         window_s=120.0),
    "mii_per_min": Measure("1/min", "motion-induced interruptions", (LATERAL, NORMAL), _mii, at_point=True,
                           options=("tipping_coefficient",)),
}
"""Every quantity a ``[[criteria]]`` entry or an event's condition may name."""
