"""The weather on a vessel keeping station (:class:`~marinesim.station.vessel.Environment`): wind with gusts, a
uniform current, and the waves' second-order drift.

The wind's mean speed and direction follow the scenario and its changes (:meth:`Weather.change`: each blends in
linearly over its ramp from the wind of its moment, the direction the short way round), the gusts ride on the mean
(:class:`~marinesim.station.wind.Gusts`), and the load comes from the vessel's coefficients at the wind relative
to her (:class:`~marinesim.station.wind.WindLoads`). The wave drift and the wave-frequency motion are the
session's (they come from the ocean's components, sea leg by sea leg): given here as functions of time.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from marinesim.manoeuvring.autopilot import wrap

GUST_GRID_S = 0.05
"""The gusts are computed in blocks on this grid (s): the 0.1 s steps and their Runge-Kutta half-steps ..."""
GUST_BLOCK = 1200
"""... a minute at a time."""
WINDS_KEPT = 4
"""How many of the newest winds :meth:`Weather.wind` keeps by time."""


@dataclass(frozen=True)
class WindChange:
    """From ``start`` (s) over ``ramp_s`` (s) the mean wind goes from (``speed0`` m/s, from ``from0`` rad) to
    (``speed1``, ``from1``): directions are where it comes from, clockwise from north."""

    start: float
    ramp_s: float
    speed0: float
    from0: float
    speed1: float
    from1: float

    def at(self, t: float) -> tuple[float, float]:
        s = 1.0 if self.ramp_s <= 0.0 else min(max((t - self.start) / self.ramp_s, 0.0), 1.0)
        return (self.speed0 + s * (self.speed1 - self.speed0),
                self.from0 + s * wrap(self.from1 - self.from0))


class Weather:
    """Wind (``loads``: the vessel's :class:`~marinesim.station.wind.WindLoads`, ``gusts`` or None for a steady
    wind) from (``speed`` m/s, ``from_rad``), a current of ``current`` (north, east m/s), the waves' slowly
    varying drift ``drift(t, psi) -> (3,)`` (body X, Y, N) and the wave-frequency motion ``wave_motion(t) ->
    (north m, east m, psi rad)`` of the vessel's origin."""

    def __init__(self, loads, speed: float, from_rad: float, *, gusts=None, current: tuple[float, float] = (0.0, 0.0),
                 drift: Callable[[float, float], np.ndarray] | None = None,
                 wave_motion: Callable[[float], tuple[float, float, float]] | None = None) -> None:
        self.wind_loads, self.gusts = loads, gusts
        self.changes = [WindChange(0.0, 0.0, speed, from_rad, speed, from_rad)]
        self._current = current
        self._drift, self._wave_motion = drift, wave_motion
        self._gust_block = functools.lru_cache(maxsize=4)(self._gust_block)
        self._winds: dict[float, tuple[float, float]] = {}
        """The newest winds by time (:data:`WINDS_KEPT`): a step asks at its start, middle and end, and the DP's wind
        sensor reads its start again."""

    def change(self, start: float, ramp_s: float, speed: float | None = None, from_rad: float | None = None) -> None:
        """The mean wind changes from ``start`` (s) over ``ramp_s`` (s) to ``speed`` (m/s) and/or ``from_rad``
        (rad), from the wind of that moment; later changes than ``start`` are dropped (asked again if wanted)."""
        self.changes = [c for c in self.changes if c.start < start] or self.changes[:1]
        self._winds.clear()
        speed0, from0 = self.mean_wind(start)
        self.changes.append(WindChange(start, ramp_s, speed0, from0, speed0 if speed is None else speed,
                                       from0 if from_rad is None else from_rad))

    def mean_wind(self, t: float) -> tuple[float, float]:
        """The mean wind (m/s, from rad) at ``t`` (s)."""
        change = self.changes[0]
        for c in self.changes:
            if c.start <= t:
                change = c
        return change.at(t)

    def wind(self, t: float) -> tuple[float, float]:
        """The wind at 10 m (m/s, from rad) at ``t`` (s): the mean and its gust."""
        found = self._winds.get(t)
        if found is not None:
            return found
        speed, direction = self.mean_wind(t)
        if self.gusts is not None and speed > 0.0:
            speed = max(self._gust(t) * speed / self.gusts.u0, 0.0)
        if len(self._winds) >= WINDS_KEPT:
            del self._winds[next(iter(self._winds))]
        self._winds[t] = speed, direction
        return speed, direction

    def _gust(self, t: float) -> float:
        """The gusting wind for the gusts' own mean at ``t`` (s): on the :data:`GUST_GRID_S` grid (the stepping's
        times and half-steps) from blocks computed at once, elsewhere by itself."""
        k = round(t / GUST_GRID_S)
        if abs(k * GUST_GRID_S - t) > 1e-9:
            return self.gusts.speed(t)
        block, at = divmod(k, GUST_BLOCK)
        return float(self._gust_block(block)[at])

    def _gust_block(self, block: int) -> np.ndarray:
        times = (block * GUST_BLOCK + np.arange(GUST_BLOCK)) * GUST_GRID_S
        return self.gusts.speeds(np.minimum(times, self.gusts.duration))

    def wind_load(self, t: float, psi: float, u: float, v: float) -> np.ndarray:
        """The wind's load (X N, Y N, N N m; (3,)) at ``t`` (s) on the vessel heading ``psi`` (rad) at (``u``,
        ``v``) (m/s, body axes)."""
        speed, direction = self.wind(t)
        return np.zeros(3) if speed <= 0.0 else self.wind_loads.force(u, v, psi, speed, direction)

    def drift(self, t: float, psi: float) -> np.ndarray:
        """The waves' slowly varying drift (X N, Y N, N N m; (3,)) at ``t`` (s) on heading ``psi`` (rad)."""
        return np.zeros(3) if self._drift is None else self._drift(t, psi)

    def current(self, t: float) -> tuple[float, float]:
        return self._current

    def wave_motion(self, t: float) -> tuple[float, float, float]:
        return (0.0, 0.0, 0.0) if self._wave_motion is None else self._wave_motion(t)


def current_vector(speed: float, to_deg: float) -> tuple[float, float]:
    """A current of ``speed`` (m/s) setting towards the compass bearing ``to_deg`` as (north, east) m/s."""
    return speed * math.cos(math.radians(to_deg)), speed * math.sin(math.radians(to_deg))
