"""The criteria's expectations along an exercise's timeline: the sea the vessel met, her heading and speed, cut into
stretches of :data:`STEP_S`, each with its criteria's spectral moments (:mod:`marinesim.criteria.expectation`).

The sea of a moment is the timeline's: a sea change blends the component sets' amplitudes with the leg's weight w,
each wave cell keeping its seeded noise, so the directional spectrum of the blend is
``(w sqrt(S_after) + (1 - w) sum_b w_b sqrt(S_b))^2``. A stretch takes the sea, heading and speed of its start,
the blend's weight to :data:`WEIGHT_STEP`, the heading to :data:`HEADING_STEP_DEG` and the speed to
:data:`SPEED_STEP_M_S` (what is computed once and shared between stretches); a vessel keeping station is at
rest, as her response is. An order or a sea change redraws the stretches from its time on. The ship's own heel in
a turn, sampled every second, is the offset of the roll, the deck's inclination and the lateral specific force
(:data:`HEELED`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from marinesim.criteria.expectation import (Expected, Met, Moments, Stretch, directional_density, run_expected,
                                            sea_moments, window_expected)
from marinesim.constants import G
from marinesim.criteria.monitor import Criterion
from marinesim.session.timeline import Simulation

STEP_S = 10.0
"""A stretch of steady sea, heading and speed (s): short against a window, long against a wave."""
HEELED = {"roll_rms_deg", "roll_max_deg", "inclination_max_deg", "lateral_acc_rms_m_s2"}
"""Quantities whose series carry the heel: in degrees, or as ``g sin(heel)`` (the lateral specific force)."""
MET_KEPT = 3
"""Headings and speeds whose transfer functions are kept at once (8 MB each); the moments of every one are kept."""
WEIGHT_STEP = 0.05
HEADING_STEP_DEG = 1.0
SPEED_STEP_M_S = 0.1


class Expectations:
    """``criteria`` (of ``simulation``'s vessel) expected along ``simulation``'s timeline."""

    def __init__(self, simulation: Simulation, criteria: Sequence[Criterion]) -> None:
        self.sim = simulation
        self.criteria = tuple(criteria)
        self._stretches: list[list[Moments | None] | None] = []
        self._heels: list[np.ndarray] = []
        self._met: dict[tuple[float, float], Met] = {}
        self._seas: dict[tuple, list[Moments | None] | None] = {}
        self._density: dict[int, np.ndarray | None] = {}
        self._version = simulation.version

    def window(self, index: int, t: float) -> Expected | None:
        """The distribution of criterion ``index``'s value over its window ending at ``t`` (s), a dose's from the
        start."""
        criterion = self.criteria[index]
        start = 0.0 if criterion.window is None else max(t - criterion.window, 0.0)
        return window_expected(criterion, self._stretches_of(index, start, t))

    def run(self, index: int, t: float) -> Expected | None:
        """The distribution of criterion ``index``'s worst value over the run from 0 to ``t`` (s)."""
        return run_expected(self.criteria[index], self._stretches_of(index, 0.0, t))

    def _stretches_of(self, index: int, start: float, end: float) -> list[Stretch]:
        out = []
        first, last = math.floor(start / STEP_S), math.ceil(end / STEP_S)
        for i in range(first, last):
            lo, hi = max(i * STEP_S, start), min((i + 1) * STEP_S, end)
            moments = self._moments(i)
            if hi > lo and moments is not None and moments[index] is not None:
                out.append(Stretch(hi - lo, moments[index], *self._offset(index, i)))
            elif hi > lo:
                return []  # a stretch without a distribution (a regular wave): none for the window
        return out

    def _moments(self, i: int) -> list[Moments | None] | None:
        if self._version != self.sim.version:  # an order or a sea change: the stretches from now on are redrawn
            kept = math.floor(self.sim.time / STEP_S)
            del self._stretches[kept:], self._heels[kept:]
            self._version = self.sim.version
        while len(self._stretches) <= i:
            t = len(self._stretches) * STEP_S
            self._stretches.append(self._at(t))
            self._heels.append(self.sim.voyage.path(t + np.arange(STEP_S)).roll)
        return self._stretches[i]

    def _offset(self, index: int, i: int) -> tuple[float, float]:
        """(mean square, largest size) of criterion ``index``'s offset over stretch ``i``: the heel's."""
        quantity = self.criteria[index].quantity
        if quantity not in HEELED:
            return 0.0, 0.0
        heel = self._heels[i]
        offset = G * np.sin(heel) if quantity == "lateral_acc_rms_m_s2" else np.degrees(heel)
        return float(np.mean(offset ** 2)), float(np.max(np.abs(offset)))

    def _at(self, t: float) -> list[Moments | None] | None:
        """The criteria's moments in the sea, heading and speed of ``t`` (s)."""
        sim = self.sim
        path = sim.voyage.path(np.array([t]))
        heading = math.radians(HEADING_STEP_DEG * round(math.degrees(float(path.heading[0])) / HEADING_STEP_DEG))
        speed = 0.0 if sim.station is not None else SPEED_STEP_M_S * round(float(path.speed[0]) / SPEED_STEP_M_S)
        starts = [leg.start for leg in sim.legs]
        leg = sim.legs[max(int(np.searchsorted(starts, t, side="right")) - 1, 0)]
        mix = leg.mix(WEIGHT_STEP * round(float(leg.weight(np.array([t]))[0]) / WEIGHT_STEP))
        sea_key = tuple(sorted((index, round(weight, 6)) for index, weight in mix.items() if weight > 0.0))
        key = (sea_key, heading, speed)
        if key not in self._seas:
            amplitude = 0.0
            for index, weight in sea_key:
                density = self._set_density(index)
                if density is None:
                    self._seas[key] = None
                    return None
                amplitude = amplitude + weight * np.sqrt(density)
            vessel = sim.vessel
            met = self._met.get((heading, speed))
            if met is None:
                if len(self._met) >= MET_KEPT:
                    del self._met[next(iter(self._met))]
                met = self._met[heading, speed] = Met.of(vessel.rao, heading, speed, sim.legs[0].sea.depth)
            self._seas[key] = sea_moments(met, vessel.points, self.criteria, amplitude ** 2)
        return self._seas[key]

    def _set_density(self, index: int) -> np.ndarray | None:
        if index not in self._density:
            sea = next(leg.sea for leg in self.sim.legs if leg.after == index)
            self._density[index] = directional_density(sea)
        return self._density[index]
