"""The helicopter approaching own-ship's helideck in the timeline (:mod:`marinesim.offshore.helicopter`): the deck's
centre carried by her mean track and heading for the approach, its wave-moved height for the touchdown, and the
record's ``helicopter_*`` columns.
"""

from __future__ import annotations

import numpy as np

from marinesim.angles import math_to_compass
from marinesim.offshore.helicopter import HelicopterApproach
from marinesim.scenario.model import HelicopterOptions
from marinesim.session.lifting import Motion, points_in_earth

COLUMNS = ("helicopter_east_m", "helicopter_north_m", "helicopter_z_m", "helicopter_heading_deg",
           "helicopter_above_deck_m")
"""Where the helicopter is (E frame, m; its landing gear), its heading (compass) and its height above the deck."""


def approach(options: HelicopterOptions, point: tuple[float, float, float], motion: Motion,
             wind_from_deg: float) -> HelicopterApproach:
    """The approach ``options`` asks for to the helideck at body ``point`` (m) of a vessel moving as ``motion`` says,
    into the wind from ``wind_from_deg`` (compass)."""
    p = np.asarray(point, float)

    def deck(times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        path, _ = motion(np.maximum(times, 0.0))  # a wave-off at 0 s looks a millisecond back: the start
        c, s = np.cos(path.heading), np.sin(path.heading)
        centre = np.stack([path.x + c * p[0] - s * p[1], path.y + s * p[0] + c * p[1], np.full(times.shape, p[2])],
                          -1)
        return centre, np.array([math_to_compass(h) for h in path.heading])

    def deck_z(times: np.ndarray) -> np.ndarray:
        path, linear = motion(np.maximum(times, 0.0))
        return points_in_earth(path, linear, np.broadcast_to(p, (times.size, 3)))[0][:, 2]

    return HelicopterApproach(deck, deck_z, wind_from_deg, approach_speed_kn=options.approach_speed_kn,
                              glide_angle_deg=options.glide_angle_deg, hover_height_ft=options.hover_height_ft,
                              deck_side=options.deck_side, start_s=options.start_s)


def record(helicopter: HelicopterApproach, times: np.ndarray) -> dict[str, np.ndarray]:
    """The helicopter's columns at ``times`` (s)."""
    sample = helicopter.sample(times)
    return dict(zip(COLUMNS, (sample["x"], sample["y"], sample["z"], sample["heading_deg"],
                              sample["height_above_deck_m"])))
