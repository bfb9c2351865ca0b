"""The ship's manoeuvring state and the orders she answers, in the manoeuvring literature's axes.

The models are written as their coefficients are published (SNAME): body axes x forward, y to
starboard, z down; the position ``north``, ``east`` (m) of the model's origin (midship) and the heading
``psi`` clockwise from north (rad, not wrapped: a turning circle's heading goes on past 360 deg);
``u`` surge and ``v`` sway (to starboard) in m/s, ``r`` yaw rate (to starboard), ``p`` roll rate (rad/s)
and ``phi`` heel (starboard down, rad: the same sign as CONVENTIONS' roll). The rudder angle ``delta``
is positive to starboard: it turns the ship to starboard, as a helm order and NMEA's RSA say. The
propeller turns at ``n`` rev/s, negative astern. :func:`marinesim.manoeuvring.voyage` converts to
CONVENTIONS (x east, y north, the heading a math angle, body y to port) in one place.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class ShipState:
    """Where the ship is and how she moves (see the module's axes), her rudder and its order, her propeller, the
    rate of turn the autopilot asks for, ``r_ref`` (rad/s; on station: the heading's reference rate), and the
    further states her model keeps."""

    north: float = 0.0
    east: float = 0.0
    psi: float = 0.0
    u: float = 0.0
    v: float = 0.0
    r: float = 0.0
    p: float = 0.0
    phi: float = 0.0
    delta: float = 0.0
    n: float = 0.0
    rudder_order: float = 0.0
    r_ref: float = 0.0
    extra: tuple[float, ...] = ()
    """A ship's own further states, in her own order (a DP computer's estimates, her thrusters' forces)."""

    @property
    def speed(self) -> float:
        """Speed through the water (m/s)."""
        return math.hypot(self.u, self.v)


@dataclass(frozen=True)
class Orders:
    """What the bridge asks for: a rudder angle by hand (rad, positive to starboard) or a course by the
    autopilot (rad, clockwise from north), and a propeller rate (rev/s, negative astern). ``engine`` names the
    telegraph order that set the rate (e.g. ``"half ahead"``), or the speed it was set for (``"12.0 kn"``). On
    station: the set point ``north``, ``east`` (m) with the heading ``course``, and the ``faults`` the instructor
    has given (:mod:`marinesim.station.vessel`)."""

    rudder: float = 0.0
    rps: float = 0.0
    autopilot: bool = False
    course: float = 0.0
    engine: str = "stop"
    north: float = 0.0
    east: float = 0.0
    faults: frozenset[str] = frozenset()
