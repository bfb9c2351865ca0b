"""The specific force felt on deck, and motion-induced interruptions (Graham 1990).

Specific force at a body point p: ``f = R^T (a_p + g e_z)`` in the deck (body) frame, a_p the point's
acceleration in the steady z-up frame and ``R = Rz(yaw) Ry(pitch) Rx(roll)``. At rest it is (0, 0, g);
a static roll phi (positive: port side up) gives lateral ``f_y = g sin(phi)``, normal ``f_z = g cos(phi)``.
Its lateral component is what ``lateral_acc_rms_m_s2`` measures (NORDFORSK's lateral acceleration,
gravity from roll included).

A person standing athwartships tips when the lateral force exceeds the tipping coefficient l/h (half
stance width over the height of the centre of gravity, about 0.25) times the normal force: each time
``f_y / f_z`` passes ``+l/h`` upward or ``-l/h`` downward is one motion-induced interruption. This is
Graham's lateral force estimator in its rigid-body form: his estimator adds a term ``(h/3) roll_acc``
for the person's own rotational inertia, which is left out here (it needs h itself, not only l/h).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

from marinesim.constants import G
from marinesim.pose import RotationKinematics

DEFAULT_TIPPING_COEFFICIENT = 0.25
"""l/h for lateral tipping (Graham 1990)."""


def deck_specific_force(angles_deg: np.ndarray, rates_deg_s: np.ndarray, accelerations_deg_s2: np.ndarray,
                        translational_acc_m_s2: np.ndarray, offset: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(lateral, normal) specific force (m/s^2, each (T,)) along the deck's y and z axes at the body
    point ``offset`` (3,) (m), from the roll, pitch, yaw angles, rates and accelerations (T, 3)
    (deg, deg/s, deg/s^2) and the surge, sway, heave accelerations (T, 3) (m/s^2)."""
    angles = np.radians(angles_deg)
    kinematics = RotationKinematics(angles, np.radians(rates_deg_s), np.radians(accelerations_deg_s2))
    zeros = np.zeros_like(translational_acc_m_s2)
    _, _, acceleration = kinematics.points(np.asarray(offset, float)[None, :], zeros, zeros, translational_acc_m_s2)
    force = acceleration[:, 0] + np.array([0.0, 0.0, G])
    deck = Rotation.from_euler("ZYX", angles[:, ::-1]).inv().apply(force)
    return deck[:, 1], deck[:, 2]


def tipping_count(ratio: np.ndarray, threshold: float) -> int:
    """Tips in a record of ``ratio`` = lateral / normal force: upcrossings of ``+threshold`` plus
    downcrossings of ``-threshold``."""
    r = np.asarray(ratio, float)
    up = np.count_nonzero((r[:-1] < threshold) & (r[1:] >= threshold))
    down = np.count_nonzero((r[:-1] > -threshold) & (r[1:] <= -threshold))
    return int(up + down)


def mii_per_minute(lateral: np.ndarray, normal: np.ndarray, dt: float,
                   tipping_coefficient: float = DEFAULT_TIPPING_COEFFICIENT) -> float:
    """Motion-induced interruptions per minute over a record (every ``dt`` s) of the lateral and
    normal specific force (m/s^2)."""
    lateral = np.asarray(lateral, float)
    return tipping_count(lateral / np.asarray(normal, float), tipping_coefficient) / (lateral.size * dt / 60.0)
