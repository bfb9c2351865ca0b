"""A scenario put together once: its ocean, the vessel's response to it, the hull's hydrostatics.

Everything above the physics (the timeline, the export, the headless run, the viewer) starts from
an :class:`Assembly`, so a run builds its ocean once and every output sees the same waves: the
vessel responds to exactly the components the ocean draws (:data:`VARIANCE_FRACTION` of them).
"""

from __future__ import annotations

from functools import cached_property

from marinesim.angles import compass_to_math
from marinesim.errors import ScenarioError
from marinesim.hull import Hydrostatics, hydrostatics
from marinesim.scenario import Scenario
from marinesim.sea.ocean import Components, Ocean
from marinesim.vessel.response import Response, Track

VARIANCE_FRACTION = 0.999
"""Share of the elevation variance the vessel's wave components carry (the rest: short ripples
that move no ship). The viewer, the export and the headless run use the same selection."""


class Assembly:
    """``scenario``'s ocean (seeded with the run's seed), and with a vessel its track, response and
    hull hydrostatics, each built on first use and kept."""

    def __init__(self, scenario: Scenario) -> None:
        self.scenario = scenario
        o = scenario.ocean
        self.ocean = Ocean(scenario.sea, tile_count=o.tiles, resolution=o.resolution, seed=scenario.run.seed,
                           choppiness=o.choppiness)

    def components(self, t: float = 0.0) -> Components:
        """The wave components the vessel responds to at ``t`` (s): the ocean's, pruned to the variance kept."""
        return self.ocean.components(t=t, variance_fraction=VARIANCE_FRACTION)

    @property
    def track(self) -> Track:
        """The scenario's track: the reference point from the origin at its speed and compass heading."""
        vessel = self._vessel()
        return Track(heading=compass_to_math(vessel.heading_deg), speed=vessel.speed_m_s)

    @cached_property
    def response(self) -> Response:
        """The vessel's response in the scenario's sea on :attr:`track`."""
        vessel = self._vessel()
        return Response(vessel.rao, self.components(), self.track, vessel.points)

    @cached_property
    def hydrostatics(self) -> Hydrostatics | None:
        """The hull's hydrostatics (None without a hull)."""
        vessel = self.scenario.vessel
        return hydrostatics(vessel.hull) if vessel is not None and vessel.hull is not None else None

    def _vessel(self):
        if self.scenario.vessel is None:
            raise ScenarioError(f"{self.scenario.path}: no [vessel] section: nothing to move")
        return self.scenario.vessel
