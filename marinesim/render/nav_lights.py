"""Navigation lights (COLREG 1972, Rules 20 to 23, 27 and 30, Annex I): where a vessel carries them, the sector each
shows, how bright each must be, and how bright it is at an eye.

- Sectors, as bearings of the eye from the light relative to the bow (deg, positive to port): a masthead light
  shows from right ahead to 22.5 deg abaft the beam on either side (225 deg), a sidelight from right ahead to
  22.5 deg abaft the beam on its own side (112.5 deg; red to port, green to starboard), the sternlight the
  135 deg aft, an anchor light all round. Annex I lets the intensity fall to the cut-off within 1 to 3 deg
  outside a sector: here over 2 deg.
- Intensity from the range (Annex I section 8): ``I = 3.43e6 T D^2 K^-D`` cd for a range ``D`` (nm), the
  threshold ``T = 2e-7`` lux and the atmospheric transmissivity ``K = 0.8`` per nm; the ranges by length from
  Rule 22.
- At an eye ``d`` m away the illuminance is ``E = I exp(-sigma d) / d^2`` (Allard's law), with the haze's
  ``sigma = ln 20 / V`` (Koschmieder) for the scenario's visibility ``V``: at ``E = T`` the light is at the limit
  of being seen.
- Lit from sunset to sunrise and in restricted visibility (Rule 20), here below 2 nm.
- A vessel restricted in her ability to manoeuvre (Rule 27 (b): dredging, diving, a crane lift, a DP operation)
  adds three all-round lights in a vertical line, red, white, red, 2 m apart; not making way (on DP), only those.

Positions are in the body frame (m): x forward, y to port, z up from the waterline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.constants import NAUTICAL_MILE

THRESHOLD_LUX = 2e-7
"""Annex I's threshold of illuminance at night: the light is just seen."""
TRANSMISSIVITY = 0.8
"""Annex I's atmospheric transmissivity per nautical mile (a meteorological visibility of about 13 nm)."""
CUT_OFF_DEG = 2.0
"""Outside its sector a light falls to nothing over this many degrees (Annex I allows 1 to 3)."""
RESTRICTED_VISIBILITY_M = 2.0 * NAUTICAL_MILE
"""Below this visibility the lights are lit by day too (Rule 20 (b))."""
AFTER_MASTHEAD_ABOVE_M = 4.5
"""Annex I 2 (a)(ii): the after masthead light is at least this much above the forward one."""
WHITE = (1.0, 0.95, 0.85)
RED = (1.0, 0.08, 0.05)
GREEN = (0.05, 1.0, 0.55)


@dataclass(frozen=True)
class NavLight:
    """One light: ``position`` (body frame, m), ``colour`` (linear RGB), its sector as bearings relative to the bow
    (deg, positive to port) from ``sector_deg[0]`` anticlockwise to ``sector_deg[1]``, and its range (nm)."""

    name: str
    position: tuple[float, float, float]
    colour: tuple[float, float, float]
    sector_deg: tuple[float, float]
    range_nm: float

    @property
    def intensity_cd(self) -> float:
        """Luminous intensity for its range (Annex I section 8)."""
        return luminous_intensity_cd(self.range_nm)


def luminous_intensity_cd(range_nm: float) -> float:
    """Annex I's minimum luminous intensity (cd) for a light seen to ``range_nm`` at night."""
    return 3.43e6 * THRESHOLD_LUX * range_nm**2 * TRANSMISSIVITY ** (-range_nm)


def illuminance_lux(intensity_cd: float, distance_m: np.ndarray, visibility_m: float) -> np.ndarray:
    """Allard's law: the illuminance (lux) at ``distance_m`` through air of meteorological ``visibility_m``."""
    d = np.maximum(np.asarray(distance_m, float), 1.0)
    return intensity_cd * np.exp(-math.log(20.0) * d / visibility_m) / d**2


def sector_weight(light: NavLight, bearing_deg: np.ndarray) -> np.ndarray:
    """How much of the light shows at ``bearing_deg`` (relative to the bow, positive to port): 1 inside its
    sector, falling to 0 over :data:`CUT_OFF_DEG` outside it."""
    start, end = light.sector_deg
    width = (end - start) % 360.0 or 360.0
    if width >= 360.0:
        return np.ones_like(np.asarray(bearing_deg, float))
    into = (np.asarray(bearing_deg, float) - start) % 360.0       # 0..360 anticlockwise from the sector's start
    outside = np.minimum(np.maximum(into - width, 0.0), 360.0 - into) * (into > width)
    return np.clip(1.0 - outside / CUT_OFF_DEG, 0.0, 1.0)


def ranges_nm(length_m: float) -> dict[str, float]:
    """Rule 22's ranges (nm) by the vessel's length: masthead, side, stern, all-round."""
    if length_m >= 50.0:
        return {"masthead": 6.0, "side": 3.0, "stern": 3.0, "all_round": 3.0}
    if length_m >= 12.0:
        return {"masthead": 5.0 if length_m >= 20.0 else 3.0, "side": 2.0, "stern": 2.0, "all_round": 2.0}
    return {"masthead": 2.0, "side": 1.0, "stern": 2.0, "all_round": 2.0}


def place_lights(positions: np.ndarray, kind: str, bridge: tuple[float, float, float] | None = None,
                 making_way: bool = True) -> list[NavLight]:
    """The lights of a vessel drawn by the body-frame vertices ``positions`` (n, 3) m, showing ``kind`` (one of
    :data:`~marinesim.scenario.model.NAV_LIGHTS`): the masthead lights on its centreline (the after one over the
    bridge, or a fifth of the length from the stern), the sidelights at its sides abreast the bridge, the sternlight
    at the stern's top. ``making_way``: a vessel restricted in her ability to manoeuvre shows the lights of a vessel
    underway only when making way through the water (Rule 27 (b)(iii))."""
    if kind == "none" or len(positions) == 0:
        return []
    p = np.asarray(positions, float)
    x_min, x_max = float(p[:, 0].min()), float(p[:, 0].max())
    length = x_max - x_min
    half_beam = float(np.abs(p[:, 1]).max())
    reach = ranges_nm(length)

    def top_near(x: float, band: float) -> float:
        near = p[np.abs(p[:, 0] - x) <= band]
        return float(near[:, 2].max()) if len(near) else float(p[:, 2].max())

    fore_x = x_max - 0.08 * length
    fore_z = top_near(fore_x, 0.08 * length) + 2.0
    aft_x = bridge[0] if bridge is not None else x_min + 0.2 * length
    aft_z = max(top_near(aft_x, 0.05 * length) + 2.0, fore_z + AFTER_MASTHEAD_ABOVE_M)
    if kind == "restricted":  # Rule 27 (b): red, white, red all round in a vertical line over the after mast; when
        lights = place_lights(p, "underway", bridge) if making_way else []  # making way, a vessel's lights too
        top = aft_z + 2.0 + 2.0 * np.arange(3)
        return lights + [NavLight(f"restricted {name}", (aft_x - 1.0, 0.0, z), colour, (0.0, 360.0), reach["all_round"])
                         for name, colour, z in (("lower red", RED, top[0]), ("white", WHITE, top[1]),
                                                 ("upper red", RED, top[2]))]
    if kind == "anchored":
        return [NavLight("anchor forward", (fore_x, 0.0, aft_z), WHITE, (0.0, 360.0), reach["all_round"]),
                NavLight("anchor aft", (x_min + 0.05 * length, 0.0, aft_z - AFTER_MASTHEAD_ABOVE_M), WHITE,
                         (0.0, 360.0), reach["all_round"])]
    side_z = bridge[2] - 1.0 if bridge is not None else top_near(aft_x, 0.05 * length) - 1.0
    stern_z = top_near(x_min, 0.02 * length) + 1.0
    lights = [NavLight("masthead forward", (fore_x, 0.0, fore_z), WHITE, (-112.5, 112.5), reach["masthead"]),
              NavLight("port sidelight", (aft_x, half_beam, side_z), RED, (0.0, 112.5), reach["side"]),
              NavLight("starboard sidelight", (aft_x, -half_beam, side_z), GREEN, (-112.5, 0.0), reach["side"]),
              NavLight("sternlight", (x_min, 0.0, stern_z), WHITE, (112.5, 247.5), reach["stern"])]
    if length >= 50.0:  # Rule 23 (a)(ii): a second masthead light abaft and higher than the forward one
        lights.insert(1, NavLight("masthead aft", (aft_x, 0.0, aft_z), WHITE, (-112.5, 112.5), reach["masthead"]))
    return lights


def lit(sun_elevation_z: float, visibility_m: float) -> bool:
    """Whether the lights are on: the sun below the horizon (``sun_elevation_z``: the sun vector's z) or
    restricted visibility (Rule 20)."""
    return sun_elevation_z < 0.0 or visibility_m < RESTRICTED_VISIBILITY_M
