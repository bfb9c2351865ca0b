"""A vessel keeping station in the session: her weather (:class:`~marinesim.station.environment.Weather`) made from
the scenario and the timeline's sea legs, and her columns of the record.

The waves reach her two ways, both from the same components the picture and the RAO response use, sea leg by sea
leg (blended with the legs' weights): the slowly varying drift (Newman's approximation, where her file has a drift
table) and the wave-frequency motion of her origin, which is in the position her DP measures. Both are taken at the
set point on her starting heading (the drift at her heading of the moment): the low-frequency excursions are metres,
the waves' phases hardly change over them.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence

import numpy as np

from marinesim.manoeuvring.ship import STEP_S
from marinesim.manoeuvring.voyage import Voyage
from marinesim.sea.ocean import Components
from marinesim.station.drift import SlowDrift
from marinesim.station.environment import Weather, current_vector
from marinesim.station.vessel import Station
from marinesim.station.wind import Gusts
from marinesim.vessel.response import Response, Track

GUST_MARGIN_S = 3600.0
"""The gusts go on this long (s) past the run's end: the voyage is stepped a little ahead of the clock, and a viewer
may be left running."""
MEASURED_SHARE_LEFT = 1e-2
"""The share of the wave-frequency motion's variance the DP's measured position leaves out (smallest components)."""
BLOCK_STEPS = 600
"""The wave-frequency motion is computed in blocks of this many steps (a minute at 0.1 s) ..."""
SUB_STEPS = 60
"""... from one table of phasors over this many steps, turned to each sub-block's start."""


class StationWorld:
    """The weather of ``station`` in ``scenario``: ``legs()`` the timeline's sea legs (:class:`Leg`),
    ``components(i)`` its component set ``i``."""

    def __init__(self, scenario, station: Station, setup, legs: Callable[[], Sequence],
                 components: Callable[[int], Components]) -> None:
        self.scenario, self.setup = scenario, setup
        self._legs, self._components = legs, components
        env = scenario.environment
        speed, from_deg = scenario.wind
        gusts = Gusts(speed, seed=scenario.run.seed, duration=scenario.run.duration_s + GUST_MARGIN_S) if (
            env.wind_gusts and speed > 0.0) else None
        self.heading0 = 0.5 * math.pi - math.radians(scenario.vessel.heading_deg)
        self.weather = Weather(setup.wind, speed, math.radians(from_deg), gusts=gusts,
                               current=current_vector(env.current_speed_m_s, env.current_to_deg),
                               drift=self._drift if setup.drift is not None else None,
                               wave_motion=self._wave_motion)
        self._motion_block = functools.lru_cache(maxsize=16)(self._motion_block)
        self._slow_drift = functools.lru_cache(maxsize=4)(self._slow_drift)
        self._wave_model = functools.lru_cache(maxsize=4)(self._wave_model)

    # -- the waves, leg by leg -----------------------------------------------------------------

    def _blend(self, t: float, value: Callable[[int], np.ndarray]) -> np.ndarray:
        """``value(set)`` at ``t`` blended over the sea legs as the timeline blends the response: ``value``'s own
        array (read-only, perhaps shared) where one leg has all the weight."""
        legs = self._legs()
        leg = legs[0]
        for candidate in legs:
            if candidate.start <= t:
                leg = candidate
        w = float(leg.weight(t))
        if w == 1.0:
            return value(leg.after)
        out = w * value(leg.after)
        if w < 1.0:
            for index, weight in leg.before:
                out = out + (1.0 - w) * weight * value(index)
        return out

    def _wave_model(self, index: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Set ``index``'s wave-frequency (north, east, psi) as ``Re sum c exp(i w t)``: (w (n,), c (n, 3), and the
        phasors ``exp(i w j h)`` of a sub-block, (SUB_STEPS, n)), the components holding all but
        :data:`MEASURED_SHARE_LEFT` of each motion's variance (the DP's position sensor needs the motion, not its
        last hundredth)."""
        vessel = self.scenario.vessel
        response = Response(vessel.rao, self._components(index), Track(self.heading0, 0.0), {}, strict=False)
        x, y, yaw = response.motion_coefficients()[:, [0, 1, 5]].T
        c, s = math.cos(self.heading0), math.sin(self.heading0)
        coefficients = np.column_stack([x * s + y * c, x * c - y * s, -yaw])
        power = np.abs(coefficients) ** 2
        kept = np.zeros(len(power), dtype=bool)
        for j in range(3):
            order = np.argsort(power[:, j])[::-1]
            total = np.cumsum(power[order, j])
            count = int(np.searchsorted(total, (1.0 - MEASURED_SHARE_LEFT) * total[-1])) + 1
            kept[order[:count]] = True
        omega = response.omega_e[kept]
        return omega, coefficients[kept], np.exp(1j * np.outer(np.arange(SUB_STEPS) * STEP_S, omega))

    def _motion_block(self, key: tuple[int, int]) -> np.ndarray:
        """Set ``key[0]``'s wave-frequency (north m, east m, psi rad) over block ``key[1]`` of steps, (BLOCK, 3): a
        sub-block's phasors times each sub-block's start, ``exp(i w (t0 + j h)) = exp(i w t0) exp(i w j h)``."""
        index, block = key
        omega, coefficients, table = self._wave_model(index)
        out = np.empty((BLOCK_STEPS, 3))
        for first in range(0, BLOCK_STEPS, SUB_STEPS):
            start = (block * BLOCK_STEPS + first) * STEP_S
            out[first:first + SUB_STEPS] = (table @ (np.exp(1j * omega * start)[:, None] * coefficients)).real
        return out

    def _wave_motion(self, t: float) -> tuple[float, float, float]:
        step = round(t / STEP_S)
        block, at = divmod(step, BLOCK_STEPS)
        return tuple(self._blend(t, lambda i: self._motion_block((i, block))[at]).tolist())

    def _slow_drift(self, index: int) -> SlowDrift:
        return SlowDrift.from_components(self._components(index), self.setup.drift)

    def _drift(self, t: float, psi: float) -> np.ndarray:
        heading = 0.5 * math.pi - psi
        return self._blend(t, lambda i: self._slow_drift(i).force(t, heading))


STATION_COLUMNS = ("set_point_offset_m", "north_of_set_point_m", "east_of_set_point_m", "wind_speed_m_s",
                   "wind_from_deg", "wind_force_x_kn", "wind_force_y_kn", "wind_moment_knm")
"""Every station-keeping vessel's columns; then her thrusters' or mooring lines'."""


def station_columns(station: Station) -> list[str]:
    """A station-keeping vessel's columns of the record (after the ship's): her offset from the set point, the
    wind and its load, each thruster's use, each mooring line's tension."""
    return list(STATION_COLUMNS) + thruster_columns(station) + line_columns(station)


def station_record(station: Station, voyage: Voyage, times: np.ndarray) -> dict[str, np.ndarray]:
    """The :func:`station_columns` at ``times`` (s): the step's state at or before each time."""
    env = station.environment
    states = [voyage.state(float(t)) for t in times]
    extra = np.array([s.extra for s in states])
    ref = station.set_point(extra)
    north, east = np.array([s.north for s in states]) - ref[:, 0], np.array([s.east for s in states]) - ref[:, 1]
    out = {"set_point_offset_m": np.hypot(north, east), "north_of_set_point_m": north, "east_of_set_point_m": east}
    wind = np.array([env.wind(float(t)) for t in times]).reshape(-1, 2)
    load = np.array([env.wind_load(float(t), s.psi, s.u, s.v) for t, s in zip(times, states)]).reshape(-1, 3)
    out |= {"wind_speed_m_s": wind[:, 0], "wind_from_deg": np.degrees(wind[:, 1]) % 360.0,
            "wind_force_x_kn": load[:, 0] / 1e3, "wind_force_y_kn": load[:, 1] / 1e3,
            "wind_moment_knm": load[:, 2] / 1e3}
    if station.thrusters is not None:
        use = station.thruster_use(extra)
        for j, column in enumerate(thruster_columns(station)):
            out[column] = 100.0 * use[:, j]
    if station.moorings is not None:
        tension = np.array([station.line_tensions(s, voyage.orders_at(float(t)).faults)
                            for t, s in zip(times, states)]).reshape(len(times), -1)
        for j, column in enumerate(line_columns(station)):
            out[column] = tension[:, j] / 1e3
    return out


def thruster_columns(station: Station) -> list[str]:
    """Each thruster's use column (%), in her thrusters' order."""
    return [] if station.thrusters is None else [f"thruster_{_slug(t.name)}_pct" for t in station.thrusters.units]


def line_columns(station: Station) -> list[str]:
    """Each mooring line's tension column (kN), in her lines' order."""
    return [f"line_{_slug(name)}_tension_kn" for name in station.line_names]


def _slug(name: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in name.lower()).strip("_")
