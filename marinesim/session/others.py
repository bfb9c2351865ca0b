"""The other bodies of a scenario in the timeline's sea: each ship and FPSO responds through her own RAO table at her
own place (the components carry their phase in space, ``exp(-i k . x)``), a buoy follows the water's surface, a
platform stands still. No body shelters another from the waves.

A body's response to one component set is :func:`along` (the timeline blends the sets across sea changes as it
does own-ship's); :func:`columns` and :func:`record` give the record's columns for the bodies, named by body, and
own-ship's range, bearing and closest point of approach to each (:func:`~marinesim.offshore.traffic.cpa`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from marinesim.angles import math_to_compass
from marinesim.constants import KNOT
from marinesim.offshore.route import Route
from marinesim.offshore.sailing import Sailed
from marinesim.offshore.traffic import bearing_deg, cpa
from marinesim.recent import Newest
from marinesim.scenario.schema import OtherVessel
from marinesim.sea.ocean import Components
from marinesim.vessel.along import KNOT_SETS_KEPT, Knots, ShipPath, linear_along
from marinesim.vessel.response import Response

WIDTH = 19
"""A body's linear outputs (:meth:`Response.linear`): 6 DOF displacement, velocity, acceleration, the elevation at
its reference point."""
RESPONSES_KEPT = 4
"""Straight-leg responses held per body."""
SUFFIXES = ("east_m", "north_m", "heading_deg", "speed_kn", "heave_m", "roll_deg", "pitch_deg", "range_m",
            "bearing_deg", "cpa_m", "tcpa_s")
"""A body's columns, each after ``NAME_``: where it is (E frame, m from own-ship's start), its heading (compass),
speed, its wave motions (CONVENTIONS' signs), and own-ship's range and true bearing to it and their closest point of
approach and its time (s from now; negative: past) on straight tracks at their velocities now."""


class Body:
    """``other``'s response to component set ``index`` of ``components``, its straight legs' responses kept."""

    def __init__(self, other: OtherVessel, components: Callable[[int], Components]) -> None:
        self.other = other
        self._components = components
        self._kept: dict[tuple[int, object], Response] = {}
        self._knots: Newest[int, Knots] = Newest(KNOT_SETS_KEPT)
        """Sets' transfer functions at her manoeuvres' knots (:class:`~marinesim.vessel.along.Knots`)."""
        self.route: Route | Sailed = other.route if other.ship is None else Sailed(other.route, other.ship)
        """Her route: sailed exactly, or by her manoeuvring model (:mod:`marinesim.offshore.sailing`)."""

    def order(self, t: float, **request) -> None:
        """The instructor's order to her from ``t`` (s) (:meth:`Sailed.order`): she leaves her route for it."""
        self.route.order(t, **request)
        self._kept.clear()

    def along(self, index: int, times: np.ndarray, dt: float | None = None) -> np.ndarray:
        """The linear outputs (T, :data:`WIDTH`) at ``times`` (s, increasing; a grid of step ``dt`` where given) in
        set ``index``."""
        out = np.zeros((times.size, WIDTH))
        other = self.other
        if not times.size or other.kind == "platform":
            return out
        components = self._components(index)
        route = self.route
        if other.kind == "buoy":
            x, y = route.pieces[0].start
            return _follower(components, x, y, times, out)
        for lo, hi, leg in route.runs(times):
            track = route.track(leg)
            if track is None:
                knots = self._knots.get(index, lambda: Knots(other.rao, components))
                out[lo:hi] = linear_along(knots, {}, route.path, times[lo:hi])
                continue
            response = self._kept.get((index, leg))
            if response is None:
                response = Response(other.rao, components, track, None, strict=False)
                if len(self._kept) >= RESPONSES_KEPT:
                    self._kept.pop(next(iter(self._kept)))
                self._kept[(index, leg)] = response
            chunk = times[lo:hi]
            if dt is None or chunk.size < 2:
                out[lo:hi] = response.linear(chunk)
            else:
                out[lo:hi] = np.concatenate([o for _, o in response.linear_steps(float(chunk[0]), dt, chunk.size)])
        return out

    def path(self, times: np.ndarray) -> ShipPath:
        """Its track at ``times`` (s)."""
        return self.route.path(times)


def _follower(components: Components, x: float, y: float, times: np.ndarray, out: np.ndarray) -> np.ndarray:
    """A wave follower at (x, y) (E, m): heave, its rate and acceleration, and the elevation, the water's own."""
    at_point = components.amplitude * np.exp(-1j * (components.kx * x + components.ky * y))
    phase = np.exp(1j * np.outer(times, components.omega))                      # (T, n)
    w = components.omega
    out[:, 2] = (phase @ at_point).real
    out[:, 8] = (phase @ (1j * w * at_point)).real
    out[:, 14] = (phase @ (-w * w * at_point)).real
    out[:, 18] = out[:, 2]
    return out


def columns(others: tuple[OtherVessel, ...]) -> list[str]:
    """The record's columns for ``others``: :data:`SUFFIXES` after each body's name."""
    return [f"{other.name}_{suffix}" for other in others for suffix in SUFFIXES]


def record(bodies: list[Body], linear: list[np.ndarray], own: ShipPath) -> dict[str, np.ndarray]:
    """The columns of :func:`columns` at ``own.times``: each body's place and motions (``linear[i]``, (T, WIDTH)),
    own-ship's range, bearing and CPA to it from her track ``own``."""
    out: dict[str, np.ndarray] = {}
    own_xy = np.stack([own.x, own.y], axis=-1)
    own_v = np.stack([own.vx, own.vy], axis=-1)
    for body, motion in zip(bodies, linear):
        path = body.path(own.times)
        name = body.other.name
        xy = np.stack([path.x, path.y], axis=-1)
        v = np.stack([path.vx, path.vy], axis=-1)
        d = xy - own_xy
        dcpa, tcpa = cpa(own_xy, own_v, xy, v)
        out |= {f"{name}_east_m": path.x, f"{name}_north_m": path.y,
                f"{name}_heading_deg": np.array([math_to_compass(h) for h in path.heading]),
                f"{name}_speed_kn": path.speed / KNOT, f"{name}_heave_m": motion[:, 2],
                f"{name}_roll_deg": np.degrees(motion[:, 3]), f"{name}_pitch_deg": np.degrees(motion[:, 4]),
                f"{name}_range_m": np.hypot(d[:, 0], d[:, 1]),
                f"{name}_bearing_deg": bearing_deg(own_xy, xy),
                f"{name}_cpa_m": dcpa, f"{name}_tcpa_s": tcpa}
    return out


def nearest(record_row: dict[str, float], others: tuple[OtherVessel, ...]) -> str | None:
    """The name of the body own-ship comes closest to next (smallest CPA ahead) in one row of the record."""
    ahead = [(record_row[f"{o.name}_cpa_m"], o.name) for o in others
             if math.isfinite(record_row[f"{o.name}_tcpa_s"]) and record_row[f"{o.name}_tcpa_s"] > 0.0]
    return min(ahead)[1] if ahead else None
