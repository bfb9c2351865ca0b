"""A vessel without a manoeuvring model: kept on station, or on a steady passage.

A vessel kept on station this way (``manoeuvring = "station"``; a scenario's ``[station]`` puts her on dynamic
positioning or moorings under the weather instead: :mod:`marinesim.station`) holds her position exactly, and a
heading order turns her at no more than ``rate_limit`` about her own origin, the rate of turn following the
autopilot's reference model (:mod:`marinesim.manoeuvring.autopilot`): ``r -> clip(omega (course - psi),
+-rate_limit)`` with ``time_constant_s``. A vessel under way with no model (no hull, no manoeuvring file) keeps the scenario's course
and speed and takes no orders. Axes as :mod:`marinesim.manoeuvring.state`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from marinesim.errors import ParameterError, require_within
from marinesim.manoeuvring.autopilot import wrap
from marinesim.manoeuvring.state import Orders, ShipState

DP_RATE_DEG_MIN = 10.0
"""A DP vessel's usual heading change rate (deg/min)."""


@dataclass(frozen=True)
class StationKeeping:
    """Position held (``speed`` 0) with the heading to the ordered course at up to ``rate_limit`` (rad/s), by the
    reference model's ``omega`` (1/s) and ``time_constant_s``; or (``speed`` > 0, m/s) a steady passage."""

    name: str
    speed: float = 0.0
    rate_limit: float = math.radians(DP_RATE_DEG_MIN / 60.0)
    omega: float = 0.05
    time_constant_s: float = 5.0
    """``1 / (4 omega)``: the reference model critically damped, so a heading order is not swung past."""
    kind = "station"

    def describe(self) -> str:
        if self.speed > 0.0:
            return "no manoeuvring model: a steady course and speed"
        return "on station: position held exactly, heading by order (a [station] puts her on DP or moorings)"

    @property
    def label(self) -> str:
        """One word for the conning strip."""
        return "STEADY" if self.speed > 0.0 else "STATION"

    def start(self, speed: float, psi: float) -> tuple[ShipState, Orders]:
        """Her state and orders on heading ``psi`` (rad, clockwise from north) at her speed."""
        return (ShipState(psi=psi, u=self.speed),
                Orders(autopilot=True, course=psi, engine="steady" if self.speed > 0.0 else "on station"))

    def order(self, orders: Orders, state: ShipState, *, rudder_deg: float | None = None, engine: str | None = None,
              speed_kn: float | None = None, autopilot: bool | None = None, course_deg: float | None = None) -> Orders:
        """A heading order (``course_deg``, compass) while on station; anything else is refused."""
        if self.speed > 0.0 or any(o is not None for o in (rudder_deg, engine, speed_kn, autopilot)):
            raise ParameterError(f"{self.name}: {self.describe()}; she takes "
                                 + ("no orders" if self.speed > 0.0 else "heading orders only"))
        if course_deg is None:
            return orders
        return replace(orders, course=math.radians(require_within("course", course_deg, 0.0, 360.0, "deg") % 360.0))

    def step(self, s: ShipState, orders: Orders, h: float, t: float = 0.0) -> tuple[ShipState, tuple[float, ...]]:
        """The state ``h`` s after ``s`` (heading towards ``orders.course``, or straight on at her speed) and the
        derivatives of (north, east, psi, u, v, r, p, phi) at ``s``."""
        if self.speed > 0.0:
            c, sn = math.cos(s.psi), math.sin(s.psi)
            return (replace(s, north=s.north + self.speed * c * h, east=s.east + self.speed * sn * h),
                    (self.speed * c, self.speed * sn, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))
        wanted = min(max(self.omega * wrap(orders.course - s.psi), -self.rate_limit), self.rate_limit)
        lag = math.exp(-h / self.time_constant_s)
        r = wanted + (s.r - wanted) * lag
        psi = s.psi + wanted * h + (s.r - wanted) * self.time_constant_s * (1.0 - lag)
        rates = (0.0, 0.0, s.r, 0.0, 0.0, (wanted - s.r) / self.time_constant_s, 0.0, 0.0)
        return ShipState(north=s.north, east=s.east, psi=psi, r=r, r_ref=wanted), rates

    def settled(self, s: ShipState, orders: Orders, rates: tuple[float, ...]) -> bool:
        """Whether she is on the ordered heading, not turning (always, on passage)."""
        return self.speed > 0.0 or (abs(wrap(orders.course - s.psi)) <= 1e-8 and abs(s.r) <= 1e-10)
