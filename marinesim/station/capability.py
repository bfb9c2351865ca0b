"""DP capability: the strongest wind a vessel holds her position and heading in, per direction.

A static balance in the manner of DNV-ST-0111's level 1 (quasi-static, environment collinear, no dynamic
allowance): for each direction the environment comes from (relative to the bow, clockwise: 0 ahead, 90 from
starboard), the limiting wind is the largest mean wind speed at 10 m for which the thrusters, allocated as the
DP allocates them (:meth:`Thrusters.can_hold`), balance

- the wind's load at that speed (the vessel's coefficients, :class:`~marinesim.station.wind.WindLoads`),
- the current's, ``D nu_c`` at :data:`CURRENT_M_S` (the low-frequency damping the simulation uses), and
- the waves' mean drift (:func:`~marinesim.station.drift.mean_drift`) in a long-crested JONSWAP sea of the
  Hs and Tp that go with the wind (:data:`BEAUFORT`, linear between its rows), where her file has a drift table;
  without one the waves are left out and the result says so.

:data:`BEAUFORT` and :data:`CURRENT_M_S` are the environment of DNV-ST-0111's level 1 as we read its Table 3-1
(check them against the current edition before quoting a capability number).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.sea.spectra import Jonswap
from marinesim.station.drift import mean_drift
from marinesim.station.thrusters import Thrusters
from marinesim.vessel.drift import DriftTable

BEAUFORT = ((0.0, 0.0, 0.0), (1.5, 0.1, 3.5), (3.4, 0.4, 4.5), (5.4, 0.8, 5.5), (7.9, 1.3, 6.5), (10.7, 2.1, 7.5),
            (13.8, 3.1, 8.5), (17.1, 4.2, 9.0), (20.7, 5.7, 10.0), (24.4, 7.4, 10.5), (28.4, 9.5, 11.5),
            (32.6, 12.1, 12.0))
"""(wind m/s, Hs m, Tp s) at Beaufort 0 to 11."""
CURRENT_M_S = 0.75
"""The current acting with the wind and the waves (m/s)."""
MAX_WIND_M_S = 40.0
"""The search stops here: a vessel that holds more is reported as holding this."""
DIRECTIONS_DEG = tuple(float(d) for d in range(0, 360, 10))


@dataclass(frozen=True)
class Envelope:
    """The limiting wind (m/s, (n,)) per direction the environment comes from (deg relative to the bow,
    clockwise, (n,)); ``lost`` the thrusters left out; ``waves`` whether the waves' drift was in it."""

    directions_deg: tuple[float, ...]
    limiting_wind_m_s: tuple[float, ...]
    lost: tuple[str, ...]
    waves: bool

    def as_json(self) -> dict:
        return {"directions_deg": list(self.directions_deg), "limiting_wind_m_s": list(self.limiting_wind_m_s),
                "lost_thrusters": list(self.lost), "current_m_s": CURRENT_M_S, "waves_included": self.waves}


def sea_of_wind(speed: float) -> tuple[float, float]:
    """(Hs m, Tp s) that go with a mean wind of ``speed`` (m/s) (:data:`BEAUFORT`, linear between rows)."""
    wind, hs, tp = (np.array(c) for c in zip(*BEAUFORT))
    return float(np.interp(speed, wind, hs)), float(np.interp(speed, wind, tp))


def environment_load(direction: float, speed: float, wind_loads, damping: np.ndarray,
                     drift: DriftTable | None) -> np.ndarray:
    """The load (X N, Y N, N N m; body axes) of wind ``speed`` (m/s), its sea and the current, all from
    ``direction`` (rad relative to the bow, clockwise), on a vessel at rest."""
    load = wind_loads.force(0.0, 0.0, 0.0, speed, direction) if speed > 0.0 else np.zeros(3)
    current = -CURRENT_M_S * np.array([math.cos(direction), math.sin(direction), 0.0])
    load = load + damping @ current
    hs, tp = sea_of_wind(speed)
    if drift is not None and hs > 0.0:
        spectrum = Jonswap(hs, tp)
        omega = np.linspace(0.2, 3.0, 400) * (2.0 * math.pi / tp)
        load = load + mean_drift(drift, omega, spectrum.density, math.pi - direction)
    return load


def envelope(thrusters: Thrusters, wind_loads, damping: np.ndarray, drift: DriftTable | None,
             lost: tuple[str, ...] = (), directions_deg: tuple[float, ...] = DIRECTIONS_DEG,
             tolerance_m_s: float = 0.05) -> Envelope:
    """The capability :class:`Envelope` of a vessel with ``thrusters`` (less ``lost``), windage ``wind_loads``,
    low-frequency damping ``damping`` (3, 3) and mean drift table ``drift`` (or None), by bisection to
    ``tolerance_m_s``."""
    out = []
    gone = frozenset(lost)
    for deg in directions_deg:
        direction = math.radians(deg)

        def holds(speed: float) -> bool:
            return thrusters.can_hold(-environment_load(direction, speed, wind_loads, damping, drift), gone)

        if not holds(0.0):
            out.append(0.0)
            continue
        if holds(MAX_WIND_M_S):
            out.append(MAX_WIND_M_S)
            continue
        lo, hi = 0.0, MAX_WIND_M_S
        while hi - lo > tolerance_m_s:
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if holds(mid) else (lo, mid)
        out.append(round(lo, 2))
    return Envelope(tuple(directions_deg), tuple(out), tuple(lost), drift is not None)
