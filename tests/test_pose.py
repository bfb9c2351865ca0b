"""The vessel pose and the one rotation R = Rz(yaw) Ry(pitch) Rx(roll) (docs/CONVENTIONS.md).

A sign or order error here moves every point on board, the camera on the bridge and the hull the
local solver sees; the checks are against matrices written out by hand and against finite
differences of the positions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.pose import Pose, RotationKinematics, body_rotation, rotation_y


def rx(a):
    return np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])


def ry(a):
    return np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])


def rz(a):
    return np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])


@pytest.mark.parametrize("roll, pitch, yaw", [(0.1, 0.0, 0.0), (0.0, 0.2, 0.0), (0.0, 0.0, 0.3), (0.3, -0.2, 0.7)])
def test_body_rotation_is_rz_ry_rx_in_that_order(roll, pitch, yaw):
    """The written-out matrix is Rz(yaw) Ry(pitch) Rx(roll) (not the reverse order), and so is scipy's
    intrinsic z-y-x Euler rotation, a second method."""
    from scipy.spatial.transform import Rotation

    assert body_rotation(roll, pitch, yaw) == pytest.approx(rz(yaw) @ ry(pitch) @ rx(roll), abs=1e-14)
    assert body_rotation(roll, pitch, yaw) == pytest.approx(
        Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_matrix(), abs=1e-14)
    assert rotation_y(pitch) == pytest.approx(ry(pitch), abs=1e-15)


def test_signs_follow_the_conventions():
    """Positive pitch puts the bow down, positive roll lifts the port side, positive yaw turns the bow to port."""
    bow, port = np.array([50.0, 0.0, 0.0]), np.array([0.0, 10.0, 0.0])
    assert (body_rotation(0.0, 0.1, 0.0) @ bow)[2] < 0.0
    assert (body_rotation(0.1, 0.0, 0.0) @ port)[2] > 0.0
    assert (body_rotation(0.0, 0.0, 0.1) @ bow)[1] > 0.0


def test_a_pose_places_body_points_on_the_track():
    """A body point goes to track + Rz(heading) (motion + R p), heading a math angle (bow at 90 deg: north)."""
    motion = (1.0, -2.0, 0.5, 0.05, -0.03, 0.02)
    pose = Pose(100.0, 200.0, math.pi / 2, motion)
    p = np.array([[50.0, 5.0, 10.0]])
    expected = np.array([100.0, 200.0, 0.0]) + rz(math.pi / 2) @ (np.array(motion[:3]) + rz(0.02) @ ry(-0.03)
                                                                  @ rx(0.05) @ p[0])
    assert pose.world(p)[0] == pytest.approx(expected, abs=1e-12)
    assert pose.steady().world(np.zeros((1, 3)))[0] == pytest.approx([100.0, 200.0, 0.0])


def test_rotation_kinematics_agree_with_finite_differences():
    """The exact velocities and accelerations of points on board equal central differences of their positions
    (a dropped cross term of dR/dt would leave a residual of the order of the rates' product)."""
    t = np.linspace(0.0, 20.0, 4001)
    dt = t[1] - t[0]
    w = np.array([0.6, 0.9, 0.4])
    amplitude = np.array([0.3, 0.15, 0.1])
    angles = amplitude * np.sin(np.outer(t, w))
    rates = amplitude * w * np.cos(np.outer(t, w))
    accelerations = -amplitude * w**2 * np.sin(np.outer(t, w))
    xi = np.zeros((len(t), 3))
    points = np.array([[60.0, -8.0, 25.0], [-40.0, 12.0, 5.0]])
    position, velocity, acceleration = RotationKinematics(angles, rates, accelerations).points(points, xi, xi, xi)
    direct = np.stack([[body_rotation(*a) @ p for p in points] for a in angles[::400]])
    assert position[::400] == pytest.approx(direct, abs=1e-12)
    fd_velocity = (position[2:] - position[:-2]) / (2 * dt)
    fd_acceleration = (position[2:] - 2 * position[1:-1] + position[:-2]) / dt**2
    scale_v, scale_a = np.abs(velocity).max(), np.abs(acceleration).max()
    assert np.abs(fd_velocity - velocity[1:-1]).max() < 1e-4 * scale_v
    assert np.abs(fd_acceleration - acceleration[1:-1]).max() < 1e-3 * scale_a
