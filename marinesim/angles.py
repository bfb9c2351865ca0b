"""The one pair of conversions between mariners' compass degrees and internal math angles.

Inside the code a wave direction is ``beta``: the direction the wave travels *towards*, in
radians counter-clockwise from east (+x of the earth frame E, x east, y north). Scenario files
and the CLI speak compass degrees, clockwise from north, and waves are given as *coming from*
(docs/CONVENTIONS.md).
"""

from __future__ import annotations

import math

import numpy as np


def compass_to_math(compass_deg: float) -> float:
    """Compass bearing (deg, 0 = north, 90 = east) -> math angle (rad, CCW from east)."""
    return wrap_angle(math.radians(90.0 - compass_deg))


def math_to_compass(angle_rad: float) -> float:
    """Math angle (rad, CCW from east) -> compass bearing in [0, 360) degrees."""
    return (90.0 - math.degrees(angle_rad)) % 360.0


def wave_beta_from_compass(coming_from_deg: float) -> float:
    """Compass 'coming from' direction (deg) -> internal travel direction beta (rad)."""
    return compass_to_math(coming_from_deg + 180.0)


def wave_compass_from_beta(beta_rad: float) -> float:
    """Internal travel direction beta (rad) -> compass 'coming from' direction (deg)."""
    return (math_to_compass(beta_rad) + 180.0) % 360.0


def wrap_angle(angle: float | np.ndarray) -> float | np.ndarray:
    """Wrap an angle (rad) to (-pi, pi]."""
    wrapped = np.pi - np.mod(np.pi - np.asarray(angle, dtype=float), 2.0 * np.pi)
    return float(wrapped) if np.ndim(wrapped) == 0 else wrapped
