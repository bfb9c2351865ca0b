"""The vessel's pose and the one rotation of CONVENTIONS: ``R = Rz(yaw) Ry(pitch) Rx(roll)``.

Roll about body x, pitch about y (positive bow down), yaw about z (positive bow to port). A body
point ``p`` (m, body frame) is at ``track + Rz(heading) (motion_xyz + R p)`` in the Earth frame
(x east, y north, z up). :func:`body_rotation` is the matrix written out (scipy's intrinsic z-y-x
Euler rotation is the same, tests/test_pose.py); :class:`RotationKinematics` applies R with its exact first
and second time derivatives, per time step, for the velocities and accelerations of points on board.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def rotation_y(angle: float) -> np.ndarray:
    """Ry (3, 3) for ``angle`` rad about y: a positive angle takes +x towards -z (bow down)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def body_rotation(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` (3, 3): body vectors to the steady vessel frame (angles in rad)."""
    cr, sr, cp, sp = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


@dataclass(frozen=True)
class Pose:
    """Where the vessel is: the track point ``(x, y)`` (m, E frame), the heading (math angle of the
    bow, rad) and the 6-DOF motion about it in the steady vessel frame (surge, sway, heave in m;
    roll, pitch, yaw in rad)."""

    x: float = 0.0
    y: float = 0.0
    heading: float = 0.0
    motion: tuple[float, float, float, float, float, float] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)

    def steady(self) -> Pose:
        """The same track point and heading without the motion (what the Kelvin wake assumes)."""
        return Pose(self.x, self.y, self.heading)

    def toward(self, other: Pose, fraction: float) -> Pose:
        """Linear interpolation to ``other`` (angles too: poses one sub-step apart are close)."""
        def mix(a: float, b: float) -> float:
            return a + (b - a) * fraction
        turn = math.remainder(other.heading - self.heading, 2.0 * math.pi)
        return Pose(mix(self.x, other.x), mix(self.y, other.y), self.heading + turn * fraction,
                    tuple(mix(a, b) for a, b in zip(self.motion, other.motion)))

    def matrix(self) -> np.ndarray:
        """4 x 4 transform of body-frame points (m) to the E frame: ``[Rz(heading) R, t; 0 1]``."""
        surge, sway, heave, roll, pitch, yaw = self.motion
        c, s = math.cos(self.heading), math.sin(self.heading)
        out = np.eye(4)
        out[:3, :3] = body_rotation(roll, pitch, self.heading + yaw)  # Rz(heading) Rz(yaw) = Rz(heading + yaw)
        out[:3, 3] = (self.x + c * surge - s * sway, self.y + s * surge + c * sway, heave)
        return out

    def world(self, body: np.ndarray) -> np.ndarray:
        """Body-frame points (n, 3) in the E frame (m)."""
        m = self.matrix()
        return body @ m[:3, :3].T + m[:3, 3]


class RotationKinematics:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` applied to body vectors, with exact first and second time
    derivatives, per time step. ``angles``, ``rates``, ``accelerations``: (T, 3) roll, pitch, yaw
    (rad, rad/s, rad/s^2)."""

    AXES = (2, 1, 0)  # factors of R from the left: yaw about z, pitch about y, roll about x

    def __init__(self, angles: np.ndarray, rates: np.ndarray, accelerations: np.ndarray) -> None:
        self._factors = [(axis, np.cos(angles[:, axis])[:, None], np.sin(angles[:, axis])[:, None],
                          rates[:, axis, None], accelerations[:, axis, None]) for axis in self.AXES]

    def points(self, p: np.ndarray, xi: np.ndarray, xi_dot: np.ndarray, xi_ddot: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Positions, velocities and accelerations (T, P, 3) of body points ``p`` (P, 3), given the
        translations (T, 3) and their derivatives."""
        v = np.broadcast_to(np.asarray(p, dtype=float), (xi.shape[0],) + np.shape(p))
        # d^n/dt^n (A B C) p: the orders of the three factors' time derivatives and their weights
        first = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
        second = ((2, 0, 0), (0, 2, 0), (0, 0, 2), (1, 1, 0), (1, 0, 1), (0, 1, 1))
        position = self._apply((0, 0, 0), v)
        velocity = sum(self._apply(orders, v) for orders in first)
        acceleration = sum(self._apply(orders, v) * (1.0 if 2 in orders else 2.0) for orders in second)
        return xi[:, None] + position, xi_dot[:, None] + velocity, xi_ddot[:, None] + acceleration

    def _apply(self, orders: tuple[int, int, int], v: np.ndarray) -> np.ndarray:
        """``F1 F2 F3 v`` where each factor is R, dR/dt or d2R/dt2 as ``orders`` says."""
        for (axis, c, s, rate, acceleration), order in zip(reversed(self._factors), reversed(orders)):
            if order == 0:
                v = _turn(axis, 0, c, s, v)
            elif order == 1:
                v = _turn(axis, 1, c, s, v) * rate[..., None]
            else:
                v = (_turn(axis, 2, c, s, v) * (rate ** 2)[..., None]
                     + _turn(axis, 1, c, s, v) * acceleration[..., None])
        return v


def _turn(axis: int, order: int, c: np.ndarray, s: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The ``order``-th derivative with respect to the angle of the rotation about ``axis``
    (0 x, 1 y, 2 z) with cosine ``c`` and sine ``s``, applied to vectors ``v`` (T, P, 3). The
    n-th derivative turns the plane by ``angle + n pi/2`` and drops the axis component (n >= 1)."""
    i, j = ((1, 2), (2, 0), (0, 1))[axis]          # the plane rotated: y-z, z-x, x-y
    c, s = ((c, s), (-s, c), (-c, -s))[order]      # cos and sin of angle + order pi/2
    out = np.empty(v.shape)
    out[..., i] = c * v[..., i] - s * v[..., j]
    out[..., j] = s * v[..., i] + c * v[..., j]
    out[..., axis] = v[..., axis] if order == 0 else 0.0
    return out
