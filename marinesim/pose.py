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

from marinesim.compiled import compiled
from marinesim.errors import ParameterError


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

    def __init__(self, angles: np.ndarray, rates: np.ndarray, accelerations: np.ndarray) -> None:
        angles = np.asarray(angles, dtype=float)
        self._cos = np.column_stack([np.cos(angles[:, axis]) for axis in range(3)])
        self._sin = np.column_stack([np.sin(angles[:, axis]) for axis in range(3)])
        self._rates = np.ascontiguousarray(rates, dtype=float)
        self._accelerations = np.ascontiguousarray(accelerations, dtype=float)
        if not self._rates.shape == self._accelerations.shape == angles.shape[:1] + (3,):
            raise ParameterError(f"angles, rates and accelerations must be (T, 3) alike, got {angles.shape}, "
                                 f"{self._rates.shape} and {self._accelerations.shape}")

    def points(self, p: np.ndarray, xi: np.ndarray, xi_dot: np.ndarray, xi_ddot: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Positions, velocities and accelerations (T, P, 3) of body points ``p`` (P, 3), given the
        translations (T, 3) and their derivatives."""
        p = np.ascontiguousarray(p, dtype=float)
        translations = [np.ascontiguousarray(x, dtype=float) for x in (xi, xi_dot, xi_ddot)]
        steps = self._cos.shape[0]
        if p.ndim != 2 or p.shape[1] != 3 or any(x.shape != (steps, 3) for x in translations):
            raise ParameterError(f"points must be (P, 3) and the translations ({steps}, 3), got {p.shape} and "
                                 f"{', '.join(str(x.shape) for x in translations)}")
        out = tuple(np.empty((steps, p.shape[0], 3)) for _ in range(3))
        _points(self._cos, self._sin, self._rates, self._accelerations, p, *translations, *out)
        return out


@compiled
def _turn(axis: int, order: int, c: float, s: float, v: tuple[float, float, float]) -> tuple[float, float, float]:
    """The ``order``-th derivative with respect to the angle of the rotation about ``axis`` (0 x, 1 y, 2 z) with
    cosine ``c`` and sine ``s``, applied to the vector ``v``. The n-th derivative turns the plane by
    ``angle + n pi/2`` and drops the axis component (n >= 1)."""
    if order == 1:
        c, s = -s, c
    elif order == 2:
        c, s = -c, -s
    kept = v[axis] if order == 0 else 0.0
    if axis == 0:    # the y-z plane
        return kept, c * v[1] - s * v[2], s * v[1] + c * v[2]
    if axis == 1:    # the z-x plane
        return s * v[2] + c * v[0], kept, c * v[2] - s * v[0]
    return c * v[0] - s * v[1], s * v[0] + c * v[1], kept  # the x-y plane


@compiled
def _applied(orders: tuple[int, int, int], c: np.ndarray, s: np.ndarray, rate: np.ndarray,
             acceleration: np.ndarray, v: tuple[float, float, float]) -> tuple[float, float, float]:
    """``F1 F2 F3 v`` for ``R = Rz Ry Rx`` at one time, each factor R, dR/dt or d2R/dt2 as ``orders`` (yaw's,
    pitch's, roll's) says; ``c``, ``s``, ``rate``, ``acceleration`` (3,) per axis (roll, pitch, yaw)."""
    for axis in range(3):  # roll's factor first: it is the rightmost
        order = orders[2 - axis]
        if order == 0:
            v = _turn(axis, 0, c[axis], s[axis], v)
        elif order == 1:
            a = _turn(axis, 1, c[axis], s[axis], v)
            v = (a[0] * rate[axis], a[1] * rate[axis], a[2] * rate[axis])
        else:
            square = rate[axis] * rate[axis]
            a, b = _turn(axis, 2, c[axis], s[axis], v), _turn(axis, 1, c[axis], s[axis], v)
            v = (a[0] * square + b[0] * acceleration[axis], a[1] * square + b[1] * acceleration[axis],
                 a[2] * square + b[2] * acceleration[axis])
    return v


@compiled
def _points(c: np.ndarray, s: np.ndarray, rates: np.ndarray, accelerations: np.ndarray, p: np.ndarray,
            xi: np.ndarray, xi_dot: np.ndarray, xi_ddot: np.ndarray, position_out: np.ndarray,
            velocity_out: np.ndarray, acceleration_out: np.ndarray) -> None:
    """Each time's (T) and point's (P) position, velocity and acceleration into the three (T, P, 3): d^n/dt^n of
    ``xi + R p``, R's derivative the sum over its factors' derivatives (the product rule), element by element so
    that a time's values do not depend on the others asked with it."""
    first = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    second = ((2, 0, 0), (0, 2, 0), (0, 0, 2), (1, 1, 0), (1, 0, 1), (0, 1, 1))
    for t in range(c.shape[0]):
        for k in range(p.shape[0]):
            v = (p[k, 0], p[k, 1], p[k, 2])
            position = _applied((0, 0, 0), c[t], s[t], rates[t], accelerations[t], v)
            velocity = (0.0, 0.0, 0.0)
            for orders in first:
                a = _applied(orders, c[t], s[t], rates[t], accelerations[t], v)
                velocity = (velocity[0] + a[0], velocity[1] + a[1], velocity[2] + a[2])
            acceleration = (0.0, 0.0, 0.0)
            for orders in second:
                weight = 1.0 if orders[0] == 2 or orders[1] == 2 or orders[2] == 2 else 2.0
                a = _applied(orders, c[t], s[t], rates[t], accelerations[t], v)
                acceleration = (acceleration[0] + a[0] * weight, acceleration[1] + a[1] * weight,
                                acceleration[2] + a[2] * weight)
            for i in range(3):
                position_out[t, k, i] = xi[t, i] + position[i]
                velocity_out[t, k, i] = xi_dot[t, i] + velocity[i]
                acceleration_out[t, k, i] = xi_ddot[t, i] + acceleration[i]
