"""The geometry of traffic: closest point of approach, bearings, and the COLREG encounter (Rules 13-15, 17).

Positions and velocities are in the earth frame E (x east, y north; m and m/s, docs/CONVENTIONS.md), as arrays whose
last axis is (east, north) and whose other axes broadcast. Bearings and headings are compass degrees (0 = north,
90 = east, clockwise), the mariner's.
"""

from __future__ import annotations

import enum

import numpy as np

from marinesim.constants import NAUTICAL_MILE
from marinesim.errors import ParameterError, require_finite, require_positive

HEAD_ON_DEG = 6.0
"""Rule 14: courses within this many degrees of reciprocal are "nearly reciprocal" (a common practical bound, about
the 1-3 deg cut-off of the sidelights beyond right ahead, Annex I 9(a), with the uncertainty of a compass and a
radar's bearing added)."""
ABAFT_THE_BEAM_DEG = 112.5
"""Rule 13(b): a vessel coming up from a direction more than 22.5 deg abaft the beam (relative bearing beyond
90 + 22.5 deg, either side) of the vessel ahead is overtaking: by night she would see only the sternlight."""
DCPA_LIMIT_M = 0.5 * NAUTICAL_MILE
"""The passing distance under which a closing vessel is taken to involve risk of collision (an officer's usual
CPA alarm in open water), m."""


class Encounter(str, enum.Enum):
    """What another vessel is to own ship, and own ship's duty (both power-driven vessels underway in sight of one
    another, Rule 11; restricted visibility is Rule 19, not modelled)."""

    CLEAR = "clear"
    """No risk of collision: she passes farther than the CPA limit, or is opening (Rule 7 judged on the CPA)."""
    OVERTAKING = "overtaking"
    """Own ship is overtaking her: own ship keeps out of the way (Rule 13(a))."""
    OVERTAKEN = "overtaken"
    """She is overtaking own ship: own ship stands on (Rules 13(a), 17)."""
    HEAD_ON = "head-on"
    """Reciprocal or nearly reciprocal courses: each alters to starboard (Rule 14)."""
    CROSSING_GIVE_WAY = "crossing, give way"
    """She is on own ship's starboard side: own ship keeps out of the way (Rules 15, 16)."""
    CROSSING_STAND_ON = "crossing, stand on"
    """She is on own ship's port side: own ship keeps her course and speed (Rules 15, 17)."""

    @property
    def gives_way(self) -> bool:
        """Whether own ship must act: keep out of the way (Rules 13, 15) or alter to starboard (Rule 14)."""
        return self in (Encounter.OVERTAKING, Encounter.HEAD_ON, Encounter.CROSSING_GIVE_WAY)


def _xy(name: str, value: object) -> np.ndarray:
    """``value`` as a float array of shape (..., 2), or raise naming ``name``."""
    array = np.asarray(value, dtype=float)
    if array.ndim == 0 or array.shape[-1] != 2:
        raise ParameterError(f"{name} must be an array of shape (..., 2) (east, north), got shape {array.shape}")
    if not np.isfinite(array).all():
        raise ParameterError(f"{name} must be finite, got {value!r}")
    return array


STEADY_M_S = 1e-6
"""A relative speed below this (m/s: 3.6 mm an hour) is none: a CPA would be a rounding error's."""


def cpa(own_xy: object, own_v: object, other_xy: object, other_v: object) -> tuple[np.ndarray, np.ndarray]:
    """Distance (m) and time (s) of the closest point of approach of two vessels on straight tracks at constant
    velocity, now at ``own_xy`` and ``other_xy`` (E, m) with velocities ``own_v`` and ``other_v`` (E, m/s); arrays
    (..., 2) that broadcast, results of their broadcast shape without the last axis.

    With r = other - own and v = other_v - own_v: ``tcpa = -(r.v) / |v|^2`` and ``dcpa = |r + v tcpa|``. A negative
    tcpa means the closest point is past (the range is opening). Where the relative speed is below
    :data:`STEADY_M_S` (ships in company, their velocities equal but for rounding) the range does not change: every
    time is the closest, and tcpa is 0 (now) with dcpa the present range."""
    r = _xy("other_xy", other_xy) - _xy("own_xy", own_xy)
    v = _xy("other_v", other_v) - _xy("own_v", own_v)
    r, v = np.broadcast_arrays(r, v)
    speed2 = np.einsum("...i,...i->...", v, v)
    moving = speed2 > STEADY_M_S**2
    tcpa = np.where(moving, -np.einsum("...i,...i->...", r, v) / np.where(moving, speed2, 1.0), 0.0)
    dcpa = np.hypot(*np.moveaxis(r + v * tcpa[..., None], -1, 0))
    return dcpa, tcpa


def bearing_deg(own_xy: object, other_xy: object) -> np.ndarray:
    """True (compass) bearing of ``other_xy`` from ``own_xy`` (E, m, arrays (..., 2)), deg in [0, 360); 0 where the
    two points coincide."""
    east, north = np.moveaxis(_xy("other_xy", other_xy) - _xy("own_xy", own_xy), -1, 0)
    return np.mod(np.degrees(np.arctan2(east, north)), 360.0)


def relative_bearing_deg(own_heading_deg: object, bearing: object) -> np.ndarray:
    """A true ``bearing`` (deg) relative to the bow of a vessel heading ``own_heading_deg`` (compass deg), clockwise
    in [0, 360): 0 right ahead, 90 starboard beam, 180 right astern, 270 port beam."""
    return np.mod(np.asarray(bearing, dtype=float) - np.asarray(own_heading_deg, dtype=float), 360.0)


def _abaft_the_beam(relative: float) -> bool:
    """Rule 13(b): a relative bearing (deg, [0, 360)) more than 22.5 deg abaft the beam, either side."""
    return ABAFT_THE_BEAM_DEG < relative < 360.0 - ABAFT_THE_BEAM_DEG


def encounter(own_heading_deg: float, own_v: object, other_rel_xy: object, other_heading_deg: float,
              other_v: object, dcpa_limit_m: float = DCPA_LIMIT_M) -> Encounter:
    """The COLREG encounter of own ship (heading ``own_heading_deg``, compass deg; velocity ``own_v``, E, m/s) with a
    vessel at ``other_rel_xy`` (E, m, relative to own ship) heading ``other_heading_deg`` at ``other_v``; shapes (2,).

    In order, as the Rules take precedence:
    - CLEAR when there is no risk of collision (Rule 7): she passes at ``dcpa_limit_m`` (m) or more, or tcpa <= 0
      (opening, or no relative motion).
    - Rule 13 ("notwithstanding" Rules 14 and 15): OVERTAKEN when she bears more than 22.5 deg abaft own ship's
      beam (relative bearing beyond :data:`ABAFT_THE_BEAM_DEG`, either side), OVERTAKING when own ship bears more
      than 22.5 deg abaft hers (her aspect). Exactly 112.5 deg is not overtaking.
    - Rule 14: HEAD_ON when the headings are within :data:`HEAD_ON_DEG` of reciprocal (14(c): in doubt, assume it).
    - Rule 15: CROSSING_GIVE_WAY when she is on own ship's starboard side, relative bearing in [0, 180) (right ahead
      counted as starboard: in doubt, own ship keeps out of the way rather than stand on); CROSSING_STAND_ON on the
      port side."""
    own_heading = require_finite("own_heading_deg", own_heading_deg)
    other_heading = require_finite("other_heading_deg", other_heading_deg)
    limit = require_positive("dcpa_limit_m", dcpa_limit_m)
    rel, own, other = (_xy(name, value) for name, value in
                       (("other_rel_xy", other_rel_xy), ("own_v", own_v), ("other_v", other_v)))
    for name, array in (("other_rel_xy", rel), ("own_v", own), ("other_v", other)):
        if array.shape != (2,):
            raise ParameterError(f"{name} must have shape (2,) (east, north), got shape {array.shape}")
    dcpa, tcpa = cpa(np.zeros(2), own, rel, other)
    if not (dcpa < limit and tcpa > 0.0):
        return Encounter.CLEAR
    bearing = float(bearing_deg(np.zeros(2), rel))
    relative = float(relative_bearing_deg(own_heading, bearing))
    aspect = float(relative_bearing_deg(other_heading, (bearing + 180.0) % 360.0))
    if _abaft_the_beam(relative):
        return Encounter.OVERTAKEN
    if _abaft_the_beam(aspect):
        return Encounter.OVERTAKING
    if abs((other_heading - own_heading) % 360.0 - 180.0) <= HEAD_ON_DEG:
        return Encounter.HEAD_ON
    return Encounter.CROSSING_GIVE_WAY if relative < 180.0 else Encounter.CROSSING_STAND_ON
