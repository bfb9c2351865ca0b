"""The steering gear and the engine: how the rudder and the propeller follow their orders.

Both are exact in time, so an integrator step sees them as known functions over the step:

- the steering gear turns the rudder towards its order at a constant rate (SOLAS II-1/29: from 35 deg
  on one side to 30 deg on the other in 28 s, 2.32 deg/s), never past ``max_angle``;
- the engine's propeller rate follows its order as a first-order lag, ``n(t) = n_c + (n0 - n_c)
  exp(-t / T)``, the order held within ``[-max_astern, max_ahead]``, and taken as reached within
  :data:`SETTLED_RPS`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

TELEGRAPH = ("full astern", "half astern", "slow astern", "dead slow astern", "stop", "dead slow ahead",
             "slow ahead", "half ahead", "full ahead")
"""The engine telegraph's orders, astern to ahead."""
SETTLED_RPS = 1e-10
"""The propeller is at its order once within this (rev/s): an exponential approach never gets there by itself."""
SOLAS_RUDDER_DEG = 35.0
SOLAS_RUDDER_RATE_DEG_S = 2.32
"""SOLAS II-1/29.3: 35 deg on either side; from 35 deg on one side to 30 deg on the other in 28 s."""


@dataclass(frozen=True)
class SteeringGear:
    """Rudder limits: ``max_angle`` (rad) either side, turned at ``rate`` (rad/s)."""

    max_angle: float = math.radians(SOLAS_RUDDER_DEG)
    rate: float = math.radians(SOLAS_RUDDER_RATE_DEG_S)

    def held(self, order: float) -> float:
        """``order`` (rad) within the rudder's limits."""
        return min(max(order, -self.max_angle), self.max_angle)

    def angle(self, delta0: float, order: float, tau: float) -> float:
        """The rudder angle (rad) ``tau`` s after it stood at ``delta0`` with ``order`` (held) given."""
        gap = order - delta0
        travel = self.rate * tau
        return order if abs(gap) <= travel else delta0 + math.copysign(travel, gap)


@dataclass(frozen=True)
class Engine:
    """The propeller's rate: orders within ``[-max_astern_rps, max_rps]`` (rev/s), followed with
    ``time_constant_s``; ``telegraph`` gives each telegraph order's rate (rev/s)."""

    max_rps: float
    max_astern_rps: float
    time_constant_s: float
    telegraph: dict[str, float] = field(default_factory=dict)

    def held(self, order: float) -> float:
        """``order`` (rev/s) within the engine's limits."""
        return min(max(order, -self.max_astern_rps), self.max_rps)

    def rps(self, n0: float, order: float, tau: float) -> float:
        """The propeller's rate (rev/s) ``tau`` s after it turned at ``n0`` with ``order`` (held) given."""
        if abs(n0 - order) <= SETTLED_RPS:
            return order
        n = order + (n0 - order) * math.exp(-tau / self.time_constant_s)
        return order if abs(n - order) <= SETTLED_RPS else n

    @property
    def can_go_astern(self) -> bool:
        return self.max_astern_rps > 0.0

    def step(self, order: str, steps: int, rps: float) -> str:
        """The telegraph order ``steps`` notches from ``order`` (towards ahead if positive), within the orders this
        engine has; from an engine set for a speed (not a telegraph order), the first notch is the next order above
        or below its rate ``rps`` (rev/s)."""
        have = [name for name in TELEGRAPH if name in self.telegraph]
        if order in have:
            here = have.index(order) + steps
        elif steps > 0:
            here = next((i for i, name in enumerate(have) if self.telegraph[name] > rps), len(have) - 1) + steps - 1
        else:
            here = max((i for i, name in enumerate(have) if self.telegraph[name] < rps), default=0) + steps + 1
        return have[min(max(here, 0), len(have) - 1)]
