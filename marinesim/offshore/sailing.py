"""A ship sailing her route under her own manoeuvring model, or driven by the instructor.

The route (:class:`~marinesim.offshore.route.Route`) is sailed as an officer of the watch sails an ECDIS route: the ship
(a :class:`~marinesim.manoeuvring.ship.Ship` with an autopilot) starts on her first leg at the route's speed (the engine
at the rate that holds it), and when the distance left to a waypoint along the leg she is on comes down to its
wheel-over distance ``R' tan(D / 2) + U / k_psi`` (``R'`` the route's turn radius, or the wider ``U / r_max`` her
autopilot's rate-of-turn limit gives; ``D`` the change of course; ``U / k_psi`` what she sails while her autopilot eases
onto a course) the autopilot is given the next leg's course. What her model makes of the turn (its radius, the speed
lost in it) is hers, as on a real bridge; every :data:`STEER_S` the course is set again by line of sight to bring her
back onto the leg she is on, as a track pilot does. Her track is looked at on a grid of :data:`LOOK_S` from the start,
in order, so the same route gives the same voyage to the last bit whatever asks for it, in whatever order.

The instructor may take her over: an order (helm, engine, autopilot course) from a time on drops the route's
wheel-overs from then, and she answers the instructor's orders alone. Her manoeuvring is not moved by the wind or
the waves (own-ship's answers to them where her model has them); her wave-frequency motions are her RAO table's.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from marinesim.angles import compass_to_math, math_to_compass
from marinesim.manoeuvring.ship import STEP_S, Ship
from marinesim.manoeuvring.voyage import Voyage
from marinesim.offshore.route import Route
from marinesim.vessel.along import ShipPath
from marinesim.vessel.response import Track

LOOK_S = 1.0
"""How often (s) the distance to the next wheel-over point is looked at: some 8 m of her track at 15 kn."""
LOOK_CHUNK = 120
"""Her track is looked at this many looks at a time."""
STEER_S = 30.0
"""How often (s) the course is set again to bring her back onto her leg (line of sight, :data:`LOOKAHEAD_LENGTHS`
ahead): a track pilot's correction."""
STEER_TOLERANCE_DEG = 0.5
"""The least change of course (deg) given as a correction."""
STEADY_DEG = 2.0
"""A correction is given only once her heading is this close (deg) to the course last given: not in a turn."""
LOOKAHEAD_LENGTHS = 5.0
"""The line-of-sight steering aims this many ship lengths ahead on her leg: ``course = leg - atan(e / lookahead)``,
``e`` her distance off it (to port positive)."""


class Sailed:
    """``route`` sailed by ``ship`` (see the module): the :class:`Route` interface, :meth:`path`, :meth:`runs` and
    :meth:`track` over her voyage in the E frame from own-ship's start, ``speed`` and ``pieces`` the planned route's
    (her speed at the start, her legs)."""

    def __init__(self, route: Route, ship: Ship) -> None:
        self.route, self.ship = route, ship
        self.speed = route.speed
        self.pieces = route.pieces
        self._legs = [p for p in route.pieces if not p.turn]
        """Her legs in order: wheel-over i leaves leg i for leg i + 1."""
        pilot = ship.autopilot
        radius = max(route.radius, route.speed / pilot.rate_limit)
        easing = route.speed / (pilot.k_psi * max(route.speed / pilot.speed, 0.25))
        self._wheel_over = [radius * math.tan(abs(math.remainder(b.heading - a.heading, math.tau)) / 2.0) + easing
                            for a, b in zip(self._legs[:-1], self._legs[1:])]
        """The distance (m) before each leg's waypoint at which the turn onto the next begins: on the route's radius,
        or the wider one her autopilot's rate-of-turn limit turns her at, ``U / r_max``, and as far again as she
        sails in the time constant her autopilot eases onto a course with, ``U / k_psi``."""
        self._lookahead = LOOKAHEAD_LENGTHS * ship.length_m
        self._requests: list[tuple[float, dict, str]] = []
        """(time s, order, what gave it: "wheel-over", "steer" or "instructor") given to her so far."""
        self._driven_from = math.inf
        """From when (s) the instructor drives her: the route no longer steers her past it."""
        self._new_voyage()

    def _new_voyage(self) -> None:
        """Her voyage from the start under the orders kept; the route steers her on from the last of its orders."""
        start, orders = self.ship.start(self.speed, math.radians(math_to_compass(self._legs[0].heading)))
        x0, y0 = self.route.pieces[0].start
        self.voyage = Voyage(self.ship, replace(start, north=y0, east=x0), orders, STEP_S)
        for t, request, _ in self._requests:
            self.voyage.order(t, **request)
        route = [(t, request, by) for t, request, by in self._requests if by != "instructor"]
        self._next = sum(1 for *_, by in route if by == "wheel-over")
        """The index of the leg she is on (of the next wheel-over)."""
        self._course = self._legs[0].heading if not route else compass_to_math(route[-1][1]["course_deg"])
        """The course (math angle, rad) last given by the route."""
        self._looked = route[-1][0] if route else 0.0
        """How far (s) the route has steered her."""

    def order(self, t: float, **request) -> None:
        """The instructor's order from ``t`` (s) (:meth:`Ship.order`'s keywords): the route's orders from ``t`` on are
        dropped and she answers the instructor alone from then."""
        self._look(t)  # the route's own orders up to then stand
        self.ship.order(self.voyage.orders_at(t), self.voyage.state(t), **request)  # refused here if out of range
        self._requests = [entry for entry in self._requests if entry[0] < t or entry[2] == "instructor"]
        self._driven_from = min(self._driven_from, t)
        self._requests.append((t, dict(request), "instructor"))
        self._requests.sort(key=lambda entry: entry[0])
        self._new_voyage()

    def _look(self, until: float) -> None:
        """Steer her along the route up to ``until`` (s): each wheel-over's course where she reaches it, and on the
        grid of :data:`STEER_S` the course back onto her leg where it has moved by :data:`STEER_TOLERANCE_DEG`."""
        while self._looked < min(until, self._driven_from):
            times = self._looked + LOOK_S * np.arange(1, LOOK_CHUNK + 1)
            times = times[times < self._driven_from]
            if not times.size:
                break
            s = self.voyage.sample(times)
            leg = self._legs[self._next]
            first = times.size
            kind = ""
            if self._next < len(self._wheel_over):
                after = self._legs[self._next + 1]
                reached = np.flatnonzero(_left_on_leg(leg, after, s["east"], s["north"])
                                         <= self._wheel_over[self._next])
                if reached.size:
                    first, kind = int(reached[0]), "wheel-over"
            steer = np.flatnonzero(np.round(times / STEER_S) * STEER_S == times)
            off = -(s["east"] - leg.start[0]) * math.sin(leg.heading) + (s["north"] - leg.start[1]) * math.cos(
                leg.heading)
            courses = leg.heading - np.arctan(off / self._lookahead)
            heading = 0.5 * math.pi - s["psi"]
            for j in steer[steer < first]:
                if abs(math.degrees(math.remainder(heading[j] - self._course, math.tau))) > STEADY_DEG:
                    continue  # still turning to the last course: a track pilot corrects once she is on it
                if abs(math.degrees(math.remainder(courses[j] - self._course, math.tau))) >= STEER_TOLERANCE_DEG:
                    first, kind = int(j), "steer"
                    break
            if not kind:
                self._looked = float(times[-1])
                continue
            t = float(times[first])
            course = self._legs[self._next + 1].heading if kind == "wheel-over" else float(courses[first])
            request = {"course_deg": math_to_compass(course)}
            self.voyage.order(t, **request)
            self._requests.append((t, request, kind))
            self._course, self._looked = course, t
            self._next += kind == "wheel-over"

    # -- the Route interface -------------------------------------------------------------------

    def path(self, times: np.ndarray) -> ShipPath:
        """Her track at ``times`` (s) (:class:`~marinesim.vessel.along.ShipPath`)."""
        times = np.asarray(times, float).ravel()
        if times.size:
            self._look(float(times.max()))
        return self.voyage.path(times)

    def runs(self, times: np.ndarray) -> list[tuple[int, int, tuple | None]]:
        """``times`` (s, increasing) in runs of her voyage: (lo, hi, a straight run's key for :meth:`track`) or
        (lo, hi, None) for a manoeuvre."""
        times = np.asarray(times, float).ravel()
        if times.size:
            self._look(float(times.max()))
        out = []
        for lo, hi, run in self.voyage.runs(times):
            key = None
            if run is not None:
                t0, heading, speed = float(run.times[0]), float(run.heading[0]), float(run.speed[0])
                key = (t0, float(run.x[0]) - speed * math.cos(heading) * t0,
                       float(run.y[0]) - speed * math.sin(heading) * t0, heading, speed)
            out.append((lo, hi, key))
        return out

    @staticmethod
    def track(key: tuple | None) -> Track | None:
        """A straight run's track (from :meth:`runs`), None for a manoeuvre."""
        if key is None:
            return None
        _, x0, y0, heading, speed = key
        return Track(heading, speed, x0, y0)


def _left_on_leg(leg, after, east: np.ndarray, north: np.ndarray) -> np.ndarray:
    """The distance (m) left along ``leg`` to its waypoint (where the planned legs ``leg`` and ``after`` meet) from
    (east, north)."""
    c, s = math.cos(leg.heading), math.sin(leg.heading)
    ca, sa = math.cos(after.heading), math.sin(after.heading)
    dx, dy = after.start[0] - leg.start[0], after.start[1] - leg.start[1]
    cross = c * sa - s * ca
    along = (dx * sa - dy * ca) / cross if abs(cross) > 1e-12 else dx * c + dy * s
    wx, wy = leg.start[0] + along * c, leg.start[1] + along * s
    return (wx - east) * c + (wy - north) * s
