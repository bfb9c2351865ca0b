"""A ship that answers her helm and her engine: a manoeuvring model with its steering gear, engine and
autopilot, stepped in time.

One step of ``h`` s: the autopilot (when on) gives the rudder order, held over the step; the steering gear
and the engine move the rudder and the propeller exactly (:mod:`marinesim.manoeuvring.actuators`); the
rigid-body states go by the classical fourth-order Runge-Kutta step with those known in time. The
kinematics (axes of :mod:`marinesim.manoeuvring.state`): ``d north/dt = u cos psi - v cos phi sin psi``,
``d east/dt = u sin psi + v cos phi cos psi``, ``d psi/dt = r cos phi``, ``d phi/dt = p``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np
from scipy.optimize import brentq

from marinesim.constants import KNOT
from marinesim.errors import ParameterError, require_within
from marinesim.manoeuvring.actuators import Engine, SteeringGear
from marinesim.manoeuvring.autopilot import Autopilot, wrap
from marinesim.manoeuvring.state import Orders, ShipState

MAX_SPEED_KN_ORDER = 40.0
"""The fastest speed that may be ordered (kn): the scenario's limit."""
SETTLED = {"v": 1e-7, "r": 1e-10, "psi": 1e-8, "delta": 1e-9, "n": 1e-10, "du": 1e-7}
"""Below these (m/s, rad/s, rad, rad, rev/s, m/s^2) a straight run is steady: a heading drift of 1e-10 rad/s
turns the ship by 2e-5 deg in an hour; a surge acceleration of 1e-7 m/s^2, the last of an approach to her
steady speed with a surge time constant of some minutes, leaves 3e-5 m/s of it (0.1 m an hour)."""
STEP_S = 0.1
"""The integrator's step (s): the fastest ship dynamics (the steering gear's 2.32 deg/s, a small vessel's yaw
time constant of a few seconds) are resolved many times over."""


class Model(Protocol):
    """A manoeuvring model: its length (m) and its accelerations (du/dt, dv/dt, dr/dt, dp/dt) at midship for
    the state and the rudder (rad) and propeller (rev/s), in the axes of :mod:`marinesim.manoeuvring.state`."""

    dof: int
    label: str

    @property
    def length_m(self) -> float: ...

    def accelerations(self, u: float, v: float, r: float, p: float, phi: float, delta: float, n: float
                      ) -> tuple[float, float, float, float]: ...


@dataclass(frozen=True)
class Ship:
    """``model`` with its ``steering`` gear, ``engine`` and ``autopilot``; ``name`` for people."""

    kind = "ship"

    name: str
    model: Model
    steering: SteeringGear
    engine: Engine
    autopilot: Autopilot | None = None
    approach_speed: float = 0.0
    """The speed of her trials (m/s)."""

    @property
    def length_m(self) -> float:
        return self.model.length_m

    def step(self, s: ShipState, orders: Orders, h: float = STEP_S, t: float = 0.0
             ) -> tuple[ShipState, tuple[float, ...]]:
        """The state ``h`` s after ``s`` (at ``t`` s: calm water, so no matter) under ``orders``, and the time derivatives of (north, east, psi, u, v, r,
        p, phi) at ``s`` (the step's first stage: the rudder and the propeller as they stood)."""
        if orders.autopilot and self.autopilot is not None:
            rudder, r_ref = self.autopilot.command(s.psi, s.r, orders.course, math.hypot(s.u, s.v))
        else:
            rudder, r_ref = orders.rudder, 0.0
        gear, engine, accelerations = self.steering, self.engine, self.model.accelerations
        rudder, rps = gear.held(rudder), engine.held(orders.rps)
        d0, n0 = s.delta, s.n
        half, sixth = 0.5 * h, h / 6.0
        # the rudder and the propeller at the stages' times (the step's start, middle and end), exact
        actuators = [(gear.angle(d0, rudder, tau), engine.rps(n0, rps, tau)) for tau in (0.0, half, h)]

        def f(stage: int, north: float, east: float, psi: float, u: float, v: float, r: float, p: float,
              phi: float) -> tuple[float, ...]:
            """The derivatives of (north, east, psi, u, v, r, p, phi) at the time of ``stage`` (0, 1, 2)."""
            du, dv, dr, dp = accelerations(u, v, r, p, phi, *actuators[stage])
            c, sn, cphi = math.cos(psi), math.sin(psi), math.cos(phi)
            return u * c - v * cphi * sn, u * sn + v * cphi * c, r * cphi, du, dv, dr, dp, p

        y0 = (s.north, s.east, s.psi, s.u, s.v, s.r, s.p, s.phi)
        k1 = f(0, *y0)
        k2 = f(1, *[a + half * b for a, b in zip(y0, k1)])
        k3 = f(1, *[a + half * b for a, b in zip(y0, k2)])
        k4 = f(2, *[a + h * b for a, b in zip(y0, k3)])
        y = [a + sixth * (b1 + 2.0 * b2 + 2.0 * b3 + b4) for a, b1, b2, b3, b4 in zip(y0, k1, k2, k3, k4)]
        delta, n = actuators[2]
        return ShipState(*y, delta=delta, n=n, rudder_order=rudder, r_ref=r_ref), k1

    def settled(self, s: ShipState, orders: Orders, rates: tuple[float, ...]) -> bool:
        """Whether ``s`` is a straight run at constant speed under ``orders`` to within what no output shows
        (:data:`SETTLED`), ``rates`` being its time derivatives: from there on the ship keeps her course and
        speed until the next order."""
        if orders.autopilot:
            if abs(wrap(orders.course - s.psi)) > SETTLED["psi"]:
                return False
        elif s.delta != orders.rudder:
            return False
        return (abs(s.delta) <= SETTLED["delta"] and abs(s.n - self.engine.held(orders.rps)) <= SETTLED["n"]
                and abs(s.v) <= SETTLED["v"] and abs(s.r) <= SETTLED["r"] and abs(s.r_ref) <= SETTLED["r"]
                and abs(s.p) <= SETTLED["r"] and abs(s.phi) <= SETTLED["psi"] and abs(rates[3]) <= SETTLED["du"])

    def rps_for_speed(self, speed: float) -> float:
        """The propeller rate (rev/s) that holds ``speed`` (m/s, ahead) steady on a straight course: surge in
        equilibrium, ``du/dt = 0``."""
        if speed <= 0.0:
            return 0.0
        def surge(n: float) -> float:
            return self.model.accelerations(speed, 0.0, 0.0, 0.0, 0.0, 0.0, n)[0]
        top = self.engine.max_rps
        if surge(top) < 0.0:
            raise ParameterError(f"{self.name}: {speed / KNOT:.3g} kn is faster than her engine drives her "
                                 f"at full ahead ({60 * top:.4g} rpm)")
        return brentq(surge, 0.0, top, xtol=1e-14, rtol=1e-15)

    def steady(self, speed: float, psi: float = 0.0, north: float = 0.0, east: float = 0.0) -> ShipState:
        """Straight ahead at ``speed`` (m/s) on heading ``psi`` (rad), the propeller at the rate that holds it."""
        return ShipState(north=north, east=east, psi=psi, u=speed, n=self.rps_for_speed(speed))

    def linear_system(self, speed: float, eps: float = 1e-6) -> tuple[np.ndarray, np.ndarray]:
        """The model linearised about a straight course at ``speed`` (m/s), the propeller at the rate that holds it:
        ``dx/dt = A x + b delta`` for ``x`` = (v, r) (3 DOF) or (v, r, p, phi) (4 DOF), by central differences of
        step ``eps``; returns (A, b)."""
        n = self.rps_for_speed(speed)
        size = 2 if self.model.dof == 3 else 4

        def rates(x: np.ndarray, delta: float) -> np.ndarray:
            v, r, p, phi = (*x, 0.0, 0.0)[:4]
            _, dv, dr, dp = self.model.accelerations(speed, v, r, p, phi, delta, n)
            return np.array([dv, dr, dp, p][:size])

        zero = np.zeros(size)
        a = np.column_stack([(rates(zero + eps * e, 0.0) - rates(zero - eps * e, 0.0)) / (2 * eps)
                             for e in np.eye(size)])
        b = (rates(zero, eps) - rates(zero, -eps)) / (2 * eps)
        return a, b

    def linear_yaw(self, speed: float) -> tuple[float, float]:
        """The first-order Nomoto model ``T dr/dt + r = K delta`` of :meth:`linear_system` at ``speed`` (m/s): the
        static gain ``K = -c A^-1 b`` (1/s) and ``T = c A^-2 b / K`` (s), the first moment of the yaw rate's
        response (``T1 + T2 - T3`` of the second-order Nomoto model), ``r = c x``. A course-unstable ship has
        ``K``, ``T`` < 0."""
        a, b = self.linear_system(speed)
        first = np.linalg.solve(a, b)
        k = -float(first[1])
        return k, float(np.linalg.solve(a, first)[1]) / k

    def yaw_authority(self, speed: float, eps: float = 1e-6) -> float:
        """The yaw acceleration per radian of rudder (1/s^2) on a straight course at ``speed`` (m/s), the propeller
        at the rate that holds it: ``d(dr/dt)/d delta``."""
        n = self.rps_for_speed(speed)
        up = self.model.accelerations(speed, 0.0, 0.0, 0.0, 0.0, eps, n)[2]
        down = self.model.accelerations(speed, 0.0, 0.0, 0.0, 0.0, -eps, n)[2]
        return (up - down) / (2.0 * eps)

    def describe(self) -> str:
        """The model in a few words."""
        return self.model.label

    def start(self, speed: float, psi: float) -> tuple[ShipState, Orders]:
        """Her state and orders on a straight course ``psi`` (rad, clockwise from north) at ``speed`` (m/s): the
        propeller at the rate that holds it, the autopilot on that course."""
        state = self.steady(speed, psi)
        return state, Orders(rps=state.n, autopilot=self.autopilot is not None, course=psi,
                             engine=self._engine_label(state.n, speed))

    def _engine_label(self, rps: float, speed: float | None = None) -> str:
        named = [name for name, n in self.engine.telegraph.items() if abs(n - rps) < 1e-9]
        if named:
            return named[0]
        return f"{speed / KNOT:.1f} kn" if speed is not None else f"{60.0 * rps:.0f} rpm"

    def order(self, orders: Orders, state: ShipState, *, rudder_deg: float | None = None, engine: str | None = None,
              speed_kn: float | None = None, autopilot: bool | None = None, course_deg: float | None = None) -> Orders:
        """``orders`` changed as the bridge asks (the ship being in ``state``): the rudder by hand (deg, positive to
        starboard: the autopilot off), a telegraph order or the engine set for a speed (kn), the autopilot on (on
        the present heading) or off (the rudder held where its order stands), a course for the autopilot (compass
        deg). An order out of range raises :class:`ParameterError` naming it."""
        new = orders
        if autopilot is not None:
            if autopilot and self.autopilot is None:
                raise ParameterError(f"{self.name} has no autopilot")
            new = replace(new, autopilot=autopilot, course=state.psi % (2.0 * math.pi), rudder=state.rudder_order)
        if course_deg is not None:
            if self.autopilot is None:
                raise ParameterError(f"{self.name} has no autopilot to steer a course")
            new = replace(new, autopilot=True, course=math.radians(require_within("course", course_deg, 0.0, 360.0,
                                                                                   "deg") % 360.0))
        if rudder_deg is not None:
            limit = math.degrees(self.steering.max_angle)
            rudder = require_within("rudder order", rudder_deg, -limit, limit, "deg (positive to starboard)")
            new = replace(new, rudder=math.radians(rudder), autopilot=False)
        if engine is not None:
            if engine not in self.engine.telegraph:
                raise ParameterError(f"engine order {engine!r}: {self.name}'s telegraph has "
                                     f"{', '.join(self.engine.telegraph)}")
            new = replace(new, rps=self.engine.telegraph[engine], engine=engine)
        if speed_kn is not None:
            speed = require_within("speed order", speed_kn, 0.0, MAX_SPEED_KN_ORDER, "kn") * KNOT
            rps = self.rps_for_speed(speed)
            new = replace(new, rps=rps, engine=self._engine_label(rps, speed))
        return new

    def with_autopilot(self, autopilot: Autopilot) -> Ship:
        return replace(self, autopilot=autopilot)

