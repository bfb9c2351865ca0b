"""The heading autopilot: a rate-of-turn controller under a heading loop, as bridge autopilots steer.

The heading loop asks for a rate of turn towards the set course, proportional to the heading error and
never more than the rate-of-turn limit: ``r_c = clip(k_psi wrap(course - psi), -r_max, r_max)``; the rate
loop gives the rudder that brings the rate of turn to it, ``delta = clip(k_r (r_c - r), -delta_max,
delta_max)``, held over each step (zero-order hold, as a digital autopilot). A ship thus comes round at the
limited rate and eases onto the new course. The gains come from the ship's yaw response to her rudder by pole
placement at a design speed ``U0`` (:func:`tuned`) and are scheduled with her speed ``U`` as the rudder's
authority goes with ``U^2``: ``k_psi`` with ``U / U0``, ``k_r`` with ``U0 / U`` (``U`` no less than a quarter of
``U0``). No integral action: calm water holds no steady disturbance (wind and current, with dynamic
positioning, come next).
"""

from __future__ import annotations

import math
from dataclasses import dataclass


def wrap(angle: float) -> float:
    """``angle`` (rad) wrapped to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


@dataclass(frozen=True)
class Autopilot:
    """Heading controller: the heading loop's gain ``k_psi`` (1/s) and the rate loop's ``k_r`` (s: rad of rudder per
    rad/s of rate error) at the design speed ``speed`` (m/s), ``rudder_limit`` (rad) and ``rate_limit`` (rad/s, the
    rate of turn it asks for at most)."""

    k_psi: float
    k_r: float
    rudder_limit: float
    rate_limit: float
    speed: float = 1.0

    def command(self, psi: float, r: float, course: float, speed: float) -> tuple[float, float]:
        """(rudder order (rad), the rate of turn asked for (rad/s)) on heading ``psi`` (rad) turning at ``r``
        (rad/s) for ``course`` (rad), going through the water at ``speed`` (m/s)."""
        q = max(speed / self.speed, 0.25)
        wanted = min(max(q * self.k_psi * wrap(course - psi), -self.rate_limit), self.rate_limit)
        order = self.k_r / q * (wanted - r)
        return min(max(order, -self.rudder_limit), self.rudder_limit), wanted


def tuned(authority: float, rudder_limit: float, rate_limit: float, length_m: float, speed_m_s: float) -> Autopilot:
    """An autopilot for a ship whose yaw acceleration per radian of rudder is ``authority`` (1/s^2) at ``speed_m_s``
    (:meth:`Ship.yaw_authority`): the heading loop closes at ``w = 0.8 U / L`` (a ship length in about eight of
    her own seconds), the rate loop six times faster, ``k_r = 6 w / b`` (fast enough that the ship's own yaw
    damping, stabilising or not, does not matter to it)."""
    omega = 0.8 * max(speed_m_s, 1.0) / length_m
    return Autopilot(k_psi=omega, k_r=6.0 * omega / authority, rudder_limit=rudder_limit, rate_limit=rate_limit,
                     speed=max(speed_m_s, 1.0))
