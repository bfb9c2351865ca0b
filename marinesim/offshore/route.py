"""A vessel on a planned route: straight legs between waypoints joined by turns of one radius, sailed at one speed,
as an ECDIS route or a radar simulator's target ship sails it.

The route starts at ``start`` (E frame, m) and runs through the waypoints; at each waypoint the track leaves the
incoming leg ``R tan(D / 2)`` before it on the circle of radius ``R`` tangent to both legs (``D`` the change of
course), so the heading is continuous and the rate of turn is ``U / R`` in the turn, 0 on a leg. After the last
waypoint she goes on along the last leg. Positions are a function of the distance sailed ``s = U t`` alone: the same
route gives the same bits at any times asked, in any order. Her heel in a turn is not modelled (0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.errors import ParameterError
from marinesim.vessel.along import ShipPath
from marinesim.vessel.response import Track

MAX_WAYPOINTS = 64
MIN_TURN_DEG = 0.01
"""A change of course smaller than this at a waypoint is sailed straight through (no turn)."""


@dataclass(frozen=True)
class _Piece:
    """A stretch of the route from distance ``s0`` (m) on: a leg from ``start`` (E, m) along the math angle
    ``heading`` (rad), or (``turn`` the signed curvature 1/m, positive to port) an arc of the circle tangent to it
    there; ``length`` (m; the last leg: inf)."""

    s0: float
    length: float
    start: tuple[float, float]
    heading: float
    turn: float = 0.0


class Route:
    """Sail from ``start`` (E frame, m) through ``waypoints`` ((n, 2), E frame, m) at ``speed_m_s`` with turns of
    ``turn_radius_m``; without waypoints, straight on along ``heading`` (math angle, rad)."""

    def __init__(self, start: tuple[float, float], speed_m_s: float, heading: float = 0.0,
                 waypoints: np.ndarray | None = None, turn_radius_m: float = 500.0) -> None:
        if not (math.isfinite(speed_m_s) and speed_m_s >= 0.0):
            raise ParameterError(f"speed must be a finite number >= 0 m/s, got {speed_m_s!r}")
        if not (math.isfinite(turn_radius_m) and turn_radius_m > 0.0):
            raise ParameterError(f"turn radius must be a finite number > 0 m, got {turn_radius_m!r}")
        points = np.vstack([np.asarray(start, float).reshape(1, 2),
                            np.zeros((0, 2)) if waypoints is None else np.asarray(waypoints, float).reshape(-1, 2)])
        if len(points) > MAX_WAYPOINTS + 1:
            raise ParameterError(f"a route has at most {MAX_WAYPOINTS} waypoints, got {len(points) - 1}")
        if not np.all(np.isfinite(points)):
            raise ParameterError("waypoints must be finite numbers (m east, m north)")
        self.speed = float(speed_m_s)
        self.radius = float(turn_radius_m)
        self.pieces = _pieces(points, heading, self.radius)

    def _at(self, times: np.ndarray) -> tuple[np.ndarray, ...]:
        """Piece index, position (x, y), heading and curvature at ``times`` (s)."""
        s = self.speed * np.asarray(times, float)
        starts = np.array([p.s0 for p in self.pieces])
        index = np.clip(np.searchsorted(starts, s, side="right") - 1, 0, len(self.pieces) - 1)
        x, y, heading, turn = (np.empty(s.shape) for _ in range(4))
        for i in np.unique(index):
            at = index == i
            piece = self.pieces[i]
            d = s[at] - piece.s0
            if piece.turn == 0.0:
                x[at] = piece.start[0] + d * math.cos(piece.heading)
                y[at] = piece.start[1] + d * math.sin(piece.heading)
                heading[at] = piece.heading
            else:
                k = piece.turn
                angle = piece.heading + k * d
                x[at] = piece.start[0] + (np.sin(angle) - math.sin(piece.heading)) / k
                y[at] = piece.start[1] - (np.cos(angle) - math.cos(piece.heading)) / k
                heading[at] = angle
            turn[at] = piece.turn
        return index, x, y, heading, turn

    def path(self, times: np.ndarray) -> ShipPath:
        """Her track at ``times`` (s) (:class:`~marinesim.vessel.along.ShipPath`; no heel)."""
        times = np.asarray(times, float).ravel()
        _, x, y, heading, turn = self._at(times)
        u = self.speed
        vx, vy = u * np.cos(heading), u * np.sin(heading)
        rate = u * turn
        zero = np.zeros(times.shape)
        return ShipPath(times, x, y, vx, vy, -rate * vy, rate * vx, heading, rate, zero, np.full(times.shape, u),
                        zero, zero, zero)

    def runs(self, times: np.ndarray) -> list[tuple[int, int, int]]:
        """``times`` (s, increasing) cut where she enters a new piece: (lo, hi, the piece's index) for
        ``times[lo:hi]``; :meth:`track` gives a leg's straight track, None for a turn."""
        times = np.asarray(times, float).ravel()
        if not times.size:
            return []
        index = self._at(times)[0]
        bounds = np.r_[0, np.flatnonzero(np.diff(index)) + 1, times.size]
        return [(int(lo), int(hi), int(index[lo])) for lo, hi in zip(bounds[:-1], bounds[1:])]

    def track(self, index: int) -> Track | None:
        """Piece ``index``'s straight track (where she would have been at t = 0 on it, its heading and speed), or
        None where the piece is a turn."""
        piece = self.pieces[index]
        if piece.turn:
            return None
        back = piece.s0
        return Track(piece.heading, self.speed, piece.start[0] - back * math.cos(piece.heading),
                     piece.start[1] - back * math.sin(piece.heading))


def _pieces(points: np.ndarray, heading: float, radius: float) -> tuple[_Piece, ...]:
    """The legs and turns through ``points`` ((n, 2), the start first), turns of ``radius`` (m)."""
    legs = np.diff(points, axis=0)
    lengths = np.hypot(legs[:, 0], legs[:, 1])
    if np.any(lengths <= 0.0):
        i = int(np.flatnonzero(lengths <= 0.0)[0])
        raise ParameterError(f"waypoint {i + 1} is where the route already is: give distinct waypoints")
    headings = np.arctan2(legs[:, 1], legs[:, 0]) if len(legs) else np.array([heading])
    changes = [math.remainder(b - a, math.tau) for a, b in zip(headings[:-1], headings[1:])]
    cut = [radius * math.tan(abs(c) / 2.0) if abs(c) >= math.radians(MIN_TURN_DEG) else 0.0 for c in changes]
    for i, c in enumerate(changes):
        if abs(c) > math.radians(179.0):
            raise ParameterError(f"waypoint {i + 1} turns the route back on itself: a turn of at most 179 deg")
    for i, length in enumerate(lengths):
        used = (cut[i - 1] if i > 0 else 0.0) + (cut[i] if i < len(cut) else 0.0)
        if used > length:
            raise ParameterError(f"leg {i + 1} of the route ({length:.0f} m) is too short for its turns of radius "
                                 f"{radius:.0f} m ({used:.0f} m): move the waypoints apart or give a smaller radius")
    pieces: list[_Piece] = []
    s, here = 0.0, (float(points[0, 0]), float(points[0, 1]))
    for i, h in enumerate(headings):
        h = float(h)
        begin = cut[i - 1] if i > 0 else 0.0
        last = i == len(headings) - 1
        straight = math.inf if last else float(lengths[i]) - begin - cut[i]
        pieces.append(_Piece(s, straight, here, h))
        if last:
            break
        here = (here[0] + straight * math.cos(h), here[1] + straight * math.sin(h))
        s += straight
        if cut[i] > 0.0:
            k = math.copysign(1.0 / radius, changes[i])
            arc = abs(changes[i]) * radius
            pieces.append(_Piece(s, arc, here, h, k))
            after = h + k * arc
            here = (here[0] + (math.sin(after) - math.sin(h)) / k, here[1] - (math.cos(after) - math.cos(h)) / k)
            s += arc
    return tuple(pieces)
