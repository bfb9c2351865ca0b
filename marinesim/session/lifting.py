"""Own-ship's crane lift in the timeline: the boom tip and the landing deck carried by her motions, the load on the
wire (:class:`~marinesim.offshore.crane.Lift`), and the record's ``crane_*`` columns.

A body point ``p`` is at ``r = c + Rz(psi) (xi + R p)`` in the E frame (CONVENTIONS: ``c`` the track point,
``psi`` the heading, ``xi`` surge, sway, heave, ``R = Rz(yaw) Ry(pitch) Rx(roll)``) and moves at
``c' + psi' e_z x Rz(psi) (xi + R p) + Rz(psi) (xi' + w x R p)``, with the angular velocity of the Euler rates
``w = roll' Rz(yaw) Ry(pitch) e_x + pitch' Rz(yaw) e_y + yaw' e_z``.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from marinesim.offshore.crane import Lift
from marinesim.scenario.schema import Lifting
from marinesim.vessel.along import ShipPath

COLUMNS = ("load_x_m", "load_y_m", "load_z_m", "load_vz_m_s", "tip_x_m", "tip_y_m", "tip_z_m", "wire_length_m",
           "slew_deg", "tension_kn", "swing_deg", "deck_force_kn", "load_above_spot_m", "relative_velocity_m_s")
"""What the record keeps of a lift (:meth:`Lift.sample`'s), each after ``crane_``."""

Motion = Callable[[np.ndarray], tuple[ShipPath, np.ndarray]]
"""``motion(times) -> (her track, her linear outputs (T, >= 12): 6 DOF displacements then velocities)``."""
GRID_S = 0.25
"""Her wave motions are computed on this grid (s) and interpolated to the load's steps (cubic Hermite, from the
displacements with the velocities and the velocities with the accelerations): the interpolation's error is about
``(w h)^4 / 384`` of a wave's part, 5e-5 at 1.5 rad/s (measured: 1e-5 of her motions), where computing them at the
load's steps (512 a second) would cost 128 times as much. Where her accelerations jump (the ends of a sea change's
ramp) her velocities are off by up to 7e-4 for one grid step."""


def on_grid(path: Callable[[np.ndarray], ShipPath], grid: Callable[[int, int], np.ndarray]) -> Motion:
    """Her motion at any times from her exact track ``path(times)`` and her linear outputs ``grid(k0, n)`` ((n, >= 18):
    displacements, velocities, accelerations) at ``(k0 + arange(n)) * GRID_S``, interpolated."""
    def motion(times: np.ndarray) -> tuple[ShipPath, np.ndarray]:
        times = np.asarray(times, float)
        s = times / GRID_S
        k0 = int(np.floor(s.min()))
        n = int(np.floor(s.max())) - k0 + 2
        knots = grid(k0, n)
        i = np.minimum(np.floor(s).astype(np.int64) - k0, n - 2)
        u = (s - k0 - i)[:, None]
        u2, u3 = u * u, u * u * u
        w0, w1, w2, w3 = 2 * u3 - 3 * u2 + 1, (u3 - 2 * u2 + u) * GRID_S, 3 * u2 - 2 * u3, (u3 - u2) * GRID_S
        a, b = knots[i], knots[i + 1]
        linear = np.concatenate([w0 * a[:, 0:6] + w1 * a[:, 6:12] + w2 * b[:, 0:6] + w3 * b[:, 6:12],
                                 w0 * a[:, 6:12] + w1 * a[:, 12:18] + w2 * b[:, 6:12] + w3 * b[:, 12:18]], axis=1)
        return path(times), linear
    return motion


def points_in_earth(path: ShipPath, linear: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Positions and velocities (T, 3) in the E frame (m, m/s) of body points ``points`` ((T, 3), one a row) for
    her track ``path`` and motions ``linear`` at the same T times (the module's formulas)."""
    roll, pitch, yaw = linear[:, 3], linear[:, 4], linear[:, 5]
    cr, sr, cp, sp, cy, sy = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    rotation = np.stack([np.stack([cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr], -1),
                         np.stack([sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr], -1),
                         np.stack([-sp, cp * sr, cp * cr], -1)], axis=1)                       # (T, 3, 3)
    turned = np.einsum("tij,tj->ti", rotation, points)
    zero = np.zeros_like(roll)
    omega = (linear[:, 9, None] * np.stack([cy * cp, sy * cp, -sp], -1)
             + linear[:, 10, None] * np.stack([-sy, cy, zero], -1)
             + linear[:, 11, None] * np.stack([zero, zero, np.ones_like(roll)], -1))
    local = linear[:, 0:3] + turned
    local_rate = linear[:, 6:9] + np.cross(omega, turned)
    c, s = np.cos(path.heading), np.sin(path.heading)
    earth = np.stack([c * local[:, 0] - s * local[:, 1], s * local[:, 0] + c * local[:, 1], local[:, 2]], -1)
    earth_rate = np.stack([c * local_rate[:, 0] - s * local_rate[:, 1], s * local_rate[:, 0] + c * local_rate[:, 1],
                           local_rate[:, 2]], -1)
    spin = np.stack([-path.rate * earth[:, 1], path.rate * earth[:, 0], zero], -1)
    position = earth + np.stack([path.x, path.y, zero], -1)
    velocity = earth_rate + spin + np.stack([path.vx, path.vy, zero], -1)
    return position, velocity


def lift(lifting: Lifting, motion: Motion, depth_m: float | None) -> Lift:
    """The load of ``lifting`` on its wire, the crane and a landing point carried by own-ship's ``motion``."""
    def tip(times: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        path, linear = motion(times)
        return points_in_earth(path, linear, points)

    spot = None
    if lifting.landing_point is not None:
        point = np.asarray(lifting.landing_point, float)

        def spot(times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            position, velocity = tip(times, np.broadcast_to(point, (times.size, 3)))
            return position[:, 2], velocity[:, 2]
    elif lifting.landing_deck_m is not None:
        deck = float(lifting.landing_deck_m)

        def spot(times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            return np.full(times.shape, deck), np.zeros(times.shape)
    return Lift(lifting.crane, lifting.load, lifting.wire_m, tip, spot, depth_m)


def columns() -> list[str]:
    """The record's lift columns."""
    return [f"crane_{name}" for name in COLUMNS]


def record(lifted: Lift, times: np.ndarray) -> dict[str, np.ndarray]:
    """The lift's columns at ``times`` (s); the swing is the wire's angle from the vertical while the load hangs,
    0 while it is on the deck (the wire slack over a load at rest says nothing of a swing)."""
    sample = lifted.sample(times)
    out = {f"crane_{name}": np.asarray(sample[name], float) for name in COLUMNS}
    out["crane_swing_deg"] = np.where(sample["landed"], 0.0, out["crane_swing_deg"])
    return out
