"""A ship's voyage: her manoeuvring state at any time, under the orders given at their times.

The ship is stepped on a fixed grid ``k h`` (:data:`~marinesim.manoeuvring.ship.STEP_S`) from her start; an
order given at ``t`` acts from step ``ceil(t / h)``, so the same orders at the same times give the same voyage
to the last bit, whatever asks for it and in what order. Between steps the states are cubic Hermite
interpolants of the steps' states and derivatives: positions, heading and heel are C1 in time, and the
velocities and accelerations given with them are the interpolants' own derivatives. Once the ship is settled
on a straight course at steady speed (:meth:`Ship.settled`) the voyage goes on exactly straight until the next
order, in one piece (what the response's fast path takes).

The voyage is computed ahead on demand and an order drops what was computed past its step (a forecast under the old
orders). Orders are kept as asked ("rudder 10 to starboard", "autopilot on") and worked out against the ship's state
at their step, so an order given now before one already given for a moment later (a scripted event asked ahead) acts
first, and the later one on top of it. Memory stays bounded: the steps are kept in blocks, of which only the newest
are held; an older block is stepped again from its first state when asked for, to the same bits.

:meth:`Voyage.path` gives the track in CONVENTIONS (x east, y north, heading a math angle): the one conversion
from the manoeuvring axes (:mod:`marinesim.manoeuvring.state`).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np

from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.manoeuvring.state import Orders, ShipState
from marinesim.vessel.along import ShipPath

BLOCK_STEPS = 3000
"""Steps per block of a manoeuvre (5 min at 0.1 s)."""
CHUNK_STEPS = 50
"""A manoeuvre is stepped this far beyond the step asked for (5 s at 0.1 s)."""
BLOCKS_KEPT = 8
"""Blocks held in memory (40 minutes of manoeuvring, some 4 MB); older ones are stepped again when asked for."""
FIELDS = ("north", "east", "psi", "u", "v", "r", "p", "phi", "delta", "n", "rudder_order", "r_ref")
"""A step's state as a row, followed by the derivatives of the first eight (north ... phi) and the state's ``extra``
(a ship's own states: a DP computer's, her thrusters')."""
HERMITE = 8
"""The first fields, interpolated with their derivatives."""
SAMPLED = (*FIELDS, "north_dot", "east_dot", "psi_dot", "psi_ddot", "north_ddot", "east_ddot", "phi_dot", "phi_ddot")
"""What :meth:`Voyage.sample` gives."""
SHIP_COLUMNS = ("north_m", "east_m", "heading_deg", "course_over_ground_deg", "speed_over_ground_kn",
                "rate_of_turn_deg_min", "rudder_deg", "rudder_order_deg", "propeller_rpm", "drift_angle_deg")
"""The ship's columns of the record (:meth:`Voyage.record`)."""


class Stepper(Protocol):
    """A ship (:class:`~marinesim.manoeuvring.ship.Ship`) or a vessel without a model
    (:class:`~marinesim.manoeuvring.station.StationKeeping`)."""

    def step(self, s: ShipState, orders: Orders, h: float, t: float = 0.0) -> tuple[ShipState, tuple[float, ...]]: ...

    def settled(self, s: ShipState, orders: Orders, rates: tuple[float, ...]) -> bool: ...

    def order(self, orders: Orders, state: ShipState, **request) -> Orders: ...


@dataclass
class _Piece:
    """Steps ``first..last`` under one set of orders (``last`` None: open-ended). A straight run holds its first
    state and goes on at its speed; a manoeuvre holds its first state and, while kept, its steps' rows
    (:data:`FIELDS` and the derivatives, (last - first + 1, 20))."""

    first: int
    last: int | None
    start: ShipState
    straight: bool
    rows: np.ndarray | None = None
    growing: bool = False
    """A manoeuvre still being stepped on (up to ``end``), from its state after the last row, ``following``."""
    end: int = 0
    following: ShipState | None = None


class Voyage:
    """``ship`` from ``start`` (her state at t = 0) under ``orders``, then as the bridge asks (:meth:`order`), on
    steps of ``h`` s."""

    def __init__(self, ship: Stepper, start: ShipState, orders: Orders, h: float) -> None:
        self.ship, self.h = ship, h
        self._requests: list[tuple[int, int, dict]] = []
        """(step, the order it was given in, what was asked): the bridge's orders, in time order."""
        self._initial = orders
        self._orders: list[tuple[int, Orders]] = []
        """The orders in effect from each step an order was given for, worked out as the voyage is stepped."""
        self._pieces: list[_Piece] = []
        self._start = start
        self._held: list[_Piece] = []
        self._memo: dict[tuple[float, int], dict[str, np.ndarray]] = {}
        self._epoch = 0
        """Counts the orders given: a sample kept from before one may be stale."""

    # -- orders ---------------------------------------------------------------------------------

    def step_of(self, t: float) -> int:
        """The step from which an order given at ``t`` (s) acts."""
        return math.ceil(t / self.h - 1e-9)

    def order(self, t: float, **request) -> None:
        """From ``t`` (s) the ship answers ``request`` (:meth:`Ship.order`'s keywords), on top of the orders given
        before it; refused (:class:`ParameterError`) if out of range. An order placed before others already given
        for later acts first, and they on top of it."""
        k = self.step_of(t)
        self.ship.order(self.orders_at(k * self.h), self.state(k * self.h), **request)
        entry = (k, len(self._requests), dict(request))
        self._requests.insert(bisect.bisect_right(self._requests, (k, math.inf)), entry)
        self._orders = [(step, o) for step, o in self._orders if step < k]
        self._truncate(k)
        self._epoch += 1

    def changed(self, t: float) -> None:
        """The world the ship steps in (the wind, the sea) changes from ``t`` (s): what was computed past the step
        from which the change acts is forgotten, and stepped again in the new world when asked for."""
        k = self.step_of(t)
        self._orders = [(step, o) for step, o in self._orders if step < k]
        self._truncate(k)
        self._epoch += 1

    def orders_at(self, t: float) -> Orders:
        """The orders in effect at ``t`` (s)."""
        k = math.floor(t / self.h + 1e-9)
        self._extend(k + 1)  # the orders given for step k are worked out once the voyage steps on from it
        return self._orders_from(k)

    @property
    def orders(self) -> Orders:
        """The orders in effect after every order given so far."""
        last = self._requests[-1][0] if self._requests else 0
        self._extend(last + 1)
        return self._orders_from(last)

    def _orders_from(self, k: int) -> Orders:
        index = bisect.bisect_right([step for step, _ in self._orders], k) - 1
        return self._orders[index][1] if index >= 0 else self._initial

    def _apply_requests(self, k: int, state: ShipState) -> None:
        """Work out the orders from step ``k`` (the ship in ``state`` there) if orders were given for it."""
        asked = [request for step, _, request in self._requests if step == k]
        if not asked or (self._orders and self._orders[-1][0] == k):
            return
        orders = self._orders_from(k)
        for request in asked:
            orders = self.ship.order(orders, state, **request)
        self._orders.append((k, orders))

    def _next_request(self, k: int) -> int | None:
        return next((step for step, _, _ in self._requests if step > k), None)

    def _truncate(self, k: int) -> None:
        """Forget what was computed past step ``k`` (the state at ``k`` stays: an order there acts after it)."""
        while self._pieces and self._pieces[-1].first >= k:
            self._forget(self._pieces.pop())
        if self._pieces:
            piece = self._pieces[-1]
            if piece.last is None or piece.last > k:
                piece.last = k
                if piece.rows is not None:
                    piece.rows = piece.rows[: k - piece.first + 1]
            piece.growing = False

    def _forget(self, piece: _Piece) -> None:
        if piece in self._held:
            self._held.remove(piece)

    # -- stepping -------------------------------------------------------------------------------

    def _computed_to(self) -> float:
        """The last step computed (-1: none; inf: straight on)."""
        if not self._pieces:
            return -1
        last = self._pieces[-1].last
        return math.inf if last is None else last

    def _extend(self, k_target: float) -> None:
        """Compute the voyage up to step ``k_target`` at least (a manoeuvre :data:`CHUNK_STEPS` further, so that
        a clock moving on by frames does not step the ship a few steps at a time)."""
        while self._computed_to() < k_target:
            last = self._pieces[-1] if self._pieces else None
            if last is not None and last.growing:
                self._grow(last, int(k_target) + CHUNK_STEPS)
                continue
            k = int(max(self._computed_to(), 0))
            state = self._state(last, k) if last is not None else self._start
            self._apply_requests(k, state)
            orders = self._orders_from(k)
            following = self._next_request(k)
            after, rates = self.ship.step(state, orders, self.h, k * self.h)
            if self.ship.settled(state, orders, rates):
                self._pieces.append(_Piece(k, following, _straightened(state), True))
                continue
            piece = _Piece(k, k, state, False, np.array([_row(state, rates)]), growing=True, following=after)
            piece.end = k + BLOCK_STEPS if following is None else min(k + BLOCK_STEPS, following)
            self._pieces.append(piece)
            self._hold(piece)
            self._grow(piece, int(k_target) + CHUNK_STEPS)

    def _grow(self, piece: _Piece, k_target: int) -> None:
        """Step a manoeuvre on to ``k_target`` or its end (its block's, the next order's), or to where the ship
        settles, whichever comes first."""
        orders = self._orders_from(piece.first)
        state = piece.following
        rows = []
        k = piece.last
        while k < min(k_target, piece.end):  # ``state`` is step k + 1's
            following, rates = self.ship.step(state, orders, self.h, (k + 1) * self.h)
            rows.append(_row(state, rates))
            settled = self.ship.settled(state, orders, rates)
            k += 1
            piece.following = state = following
            if settled:
                piece.growing = False
                break
        if rows:
            piece.rows = np.vstack([self._rows(piece), np.array(rows)])
            piece.last = k
        if k >= piece.end:
            piece.growing = False

    def _step_rows(self, piece: _Piece) -> np.ndarray:
        """A manoeuvre's rows from its first state to its last step, stepped again (as :meth:`_grow` stepped
        them: to the same bits)."""
        state, orders, rows = piece.start, self._orders_from(piece.first), []
        for k in range(piece.first, piece.last + 1):
            following, rates = self.ship.step(state, orders, self.h, k * self.h)
            rows.append(_row(state, rates))
            state = following
        return np.array(rows)

    def _hold(self, piece: _Piece) -> None:
        self._held.append(piece)
        while len(self._held) > BLOCKS_KEPT:
            oldest = next((p for p in self._held if not p.growing), None)  # a manoeuvre still growing stays
            if oldest is None:
                break
            self._held.remove(oldest)
            oldest.rows = None

    def _rows(self, piece: _Piece) -> np.ndarray:
        """A manoeuvre's rows, stepped again from its first state if they were let go."""
        if piece.rows is None:
            piece.rows = self._step_rows(piece)
            self._hold(piece)
        return piece.rows

    def _state(self, piece: _Piece, k: int) -> ShipState:
        """The state at step ``k`` of ``piece``."""
        if piece.straight:
            return _moved(piece.start, (k - piece.first) * self.h)
        row = self._rows(piece)[k - piece.first]
        return ShipState(*row[:len(FIELDS)].tolist(), extra=tuple(row[len(FIELDS) + HERMITE:].tolist()))

    def state(self, t: float) -> ShipState:
        """The state at the step at or before ``t`` (s)."""
        k = math.floor(t / self.h + 1e-9)
        self._extend(k)
        if not self._pieces:
            return self._start
        return self._state(self._piece(k), k)

    def _piece(self, k: int) -> _Piece:
        index = bisect.bisect_right([p.first for p in self._pieces], k) - 1
        return self._pieces[index]

    # -- sampling -------------------------------------------------------------------------------

    def _left(self, times: np.ndarray) -> np.ndarray:
        """The step each of ``times`` (s) is interpolated from: the one before the step an order given at that time
        would act from (:meth:`step_of`), so what is sampled at ``t`` never depends on an order given at ``t``."""
        return np.maximum(np.ceil(times / self.h - 1e-9).astype(np.int64) - 1, 0)

    def _pieces_of(self, steps: np.ndarray) -> np.ndarray:
        """The index of the piece holding each of ``steps`` (as the interval from it)."""
        firsts = np.array([p.first for p in self._pieces])
        return np.searchsorted(firsts, steps, side="right") - 1

    def sample(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The manoeuvring state at ``times`` (s, >= 0), (T,) each: :data:`FIELDS` (``delta`` and ``n`` linear
        between steps, ``rudder_order`` and ``r_ref`` those of the step), the derivatives ``north_dot``,
        ``east_dot``, ``psi_dot``, ``psi_ddot``, ``north_ddot``, ``east_ddot``, ``phi_dot``, ``phi_ddot`` (those of
        the interpolants)."""
        times = np.asarray(times, dtype=float).ravel()
        if times.size == 1:
            return self._sample_one(float(times[0]))
        out = {name: np.empty(times.size) for name in SAMPLED}
        if not times.size:
            return out
        if times.min() < 0.0 or not np.all(np.isfinite(times)):
            raise ParameterError("a voyage is sampled at finite times from 0 s")
        steps = self._left(times)
        self._extend(int(steps.max()) + 1)
        which = self._pieces_of(steps)
        for index in np.unique(which):
            at = np.flatnonzero(which == index)
            piece = self._pieces[index]
            if piece.straight:
                _fill_straight(out, at, piece, times[at] - piece.first * self.h)
            else:
                self._fill_manoeuvre(out, at, piece, times[at], steps[at])
        return out

    def _sample_one(self, t: float) -> dict[str, np.ndarray]:
        """:meth:`sample` at one time ``t`` (s), in plain floats (the viewer asks for the present several times a
        frame: the last few are kept)."""
        key = (t, self._epoch)
        if key in self._memo:
            return self._memo[key]
        if not (math.isfinite(t) and t >= 0.0):
            raise ParameterError("a voyage is sampled at finite times from 0 s")
        h = self.h
        k = max(math.ceil(t / h - 1e-9) - 1, 0)
        self._extend(k + 1)
        piece = self._piece(k)
        if piece.straight:
            out = {name: np.empty(1) for name in SAMPLED}
            _fill_straight(out, np.array([0]), piece, np.array([t - piece.first * h]))
        else:
            rows = self._rows(piece)
            left, right = rows[k - piece.first].tolist(), rows[k + 1 - piece.first].tolist()
            s = (t - k * h) / h
            (a, b, c, d), (da, db, dd), (ca, cb, cd) = _hermite(s, h)
            n = len(FIELDS)
            values: dict[str, float] = {}
            for j, name in enumerate(FIELDS[:HERMITE]):
                f0, f1, d0, d1 = left[j], right[j], left[n + j], right[n + j]
                values[name] = a * f0 + b * d0 + c * f1 + d * d1
                if name in ("north", "east", "psi", "phi"):
                    values[f"{name}_dot"] = da * (f0 - f1) + db * d0 + dd * d1
                    values[f"{name}_ddot"] = ca * (f0 - f1) + cb * d0 + cd * d1
            for name in ("delta", "n"):
                j = FIELDS.index(name)
                values[name] = left[j] + s * (right[j] - left[j])
            for name in ("rudder_order", "r_ref"):
                values[name] = right[FIELDS.index(name)]
            out = {name: np.array([values[name]]) for name in SAMPLED}
        for column in out.values():
            column.flags.writeable = False  # kept: nobody may change it
        if len(self._memo) >= 8:
            self._memo.pop(next(iter(self._memo)))
        self._memo[key] = out
        return out

    def _fill_manoeuvre(self, out: dict[str, np.ndarray], at: np.ndarray, piece: _Piece, times: np.ndarray,
                        steps: np.ndarray) -> None:
        h = self.h
        rows = self._rows(piece)
        k = steps - piece.first        # each step k < last: its interval ends on the piece's own rows
        left, right = rows[k], rows[k + 1]
        s = ((times - steps * h) / h)[:, None]
        n = len(FIELDS)
        f0, f1 = left[:, :HERMITE], right[:, :HERMITE]
        d0, d1 = left[:, n:n + HERMITE], right[:, n:n + HERMITE]
        (a, b, c, d), (da, db, dd), (ca, cb, cd) = _hermite(s, h)
        value = a * f0 + b * d0 + c * f1 + d * d1
        slope = da * (f0 - f1) + db * d0 + dd * d1
        curve = ca * (f0 - f1) + cb * d0 + cd * d1
        for j, name in enumerate(FIELDS[:HERMITE]):
            out[name][at] = value[:, j]
        s = s[:, 0]
        for name in ("delta", "n"):
            j = FIELDS.index(name)
            out[name][at] = left[:, j] + s * (right[:, j] - left[:, j])
        for name in ("rudder_order", "r_ref"):
            out[name][at] = right[:, FIELDS.index(name)]
        for name, j in (("north", 0), ("east", 1), ("psi", 2), ("phi", 7)):
            out[f"{name}_dot"][at] = slope[:, j]
            out[f"{name}_ddot"][at] = curve[:, j]

    def path(self, times: np.ndarray) -> ShipPath:
        """The track at ``times`` (s) in CONVENTIONS: the model's origin (midship, taken as the RAO table's reference
        point): its position (m, E frame: x east, y north),
        velocity and acceleration, the heading (a math angle, rad, unwrapped) and its rate and acceleration, the
        speed through the water (m/s), the heel (rad, CONVENTIONS' roll) and its rate and acceleration."""
        return _as_path(np.asarray(times, dtype=float).ravel(), self.sample(times))

    def record(self, times: np.ndarray, yaw: np.ndarray) -> dict[str, np.ndarray]:
        """The :data:`SHIP_COLUMNS` at ``times`` (s), the wave-frequency yaw being ``yaw`` (rad, positive to port):
        the model's origin north and east of the start (m); the compass heading of the bow (the manoeuvring
        heading less the yaw) and the course over ground (deg); the speed over ground (kn); the rate of turn
        (deg/min, positive to starboard, as NMEA's ROT); the rudder and its order (deg, positive to starboard, as
        NMEA's RSA); the propeller (rpm, negative astern); the drift angle, heading less course over ground (deg,
        positive with the bow to starboard of the track: inside a starboard turn). Course, speed and drift are the
        manoeuvring motion's (the wave-frequency surge and sway have columns of their own)."""
        s = self.sample(times)
        speed = np.hypot(s["north_dot"], s["east_dot"])
        moving = speed > 1e-9
        course = np.where(moving, np.arctan2(s["east_dot"], s["north_dot"]), s["psi"])
        drift = (s["psi"] - course + math.pi) % (2.0 * math.pi) - math.pi
        return {"north_m": s["north"], "east_m": s["east"],
                "heading_deg": np.degrees(s["psi"] - np.asarray(yaw, dtype=float)) % 360.0,
                "course_over_ground_deg": np.degrees(course) % 360.0, "speed_over_ground_kn": speed / KNOT,
                "rate_of_turn_deg_min": np.degrees(s["psi_dot"]) * 60.0, "rudder_deg": np.degrees(s["delta"]),
                "rudder_order_deg": np.degrees(s["rudder_order"]), "propeller_rpm": 60.0 * s["n"],
                "drift_angle_deg": np.degrees(drift)}

    def runs(self, times: np.ndarray) -> list[tuple[int, int, ShipPath | None]]:
        """``times`` (s, increasing) in runs of the voyage's pieces: (first index, end index, the straight run's path
        at its first step) for a straight run, (first, end, None) for a manoeuvre."""
        times = np.asarray(times, dtype=float).ravel()
        if not times.size:
            return []
        steps = self._left(times)
        self._extend(int(steps.max()) + 1)
        which = self._pieces_of(steps)
        bounds = np.r_[0, np.flatnonzero(np.diff(which)) + 1, times.size]
        out = []
        for lo, hi in zip(bounds[:-1], bounds[1:]):
            piece = self._pieces[which[lo]]
            run = None
            if piece.straight:  # its own first state: exactly straight, as the run goes on
                start = {name: np.empty(1) for name in SAMPLED}
                _fill_straight(start, np.array([0]), piece, np.zeros(1))
                run = _as_path(np.array([piece.first * self.h]), start)
            out.append((int(lo), int(hi), run))
        return out


def _row(state: ShipState, rates: tuple[float, ...]) -> tuple[float, ...]:
    return tuple(getattr(state, name) for name in FIELDS) + tuple(rates) + state.extra


def _straightened(state: ShipState) -> ShipState:
    """A settled state as exactly steady: no sway, turn, heel or rudder."""
    return replace(state, v=0.0, r=0.0, p=0.0, phi=0.0, delta=0.0, rudder_order=0.0, r_ref=0.0)


def _moved(state: ShipState, dt: float) -> ShipState:
    """A straight run's state ``dt`` s on."""
    return replace(state, north=state.north + state.u * math.cos(state.psi) * dt,
                   east=state.east + state.u * math.sin(state.psi) * dt)


def _fill_straight(out: dict[str, np.ndarray], at: np.ndarray, piece: _Piece, dt: np.ndarray) -> None:
    s = piece.start
    c, sn = math.cos(s.psi), math.sin(s.psi)
    for name in FIELDS:
        out[name][at] = getattr(s, name)
    out["north"][at] = s.north + s.u * c * dt
    out["east"][at] = s.east + s.u * sn * dt
    out["north_dot"][at], out["east_dot"][at] = s.u * c, s.u * sn
    for name in ("psi_dot", "psi_ddot", "north_ddot", "east_ddot", "phi_dot", "phi_ddot"):
        out[name][at] = 0.0


def _as_path(times: np.ndarray, s: dict[str, np.ndarray]) -> ShipPath:
    """A sample (:meth:`Voyage.sample`) in CONVENTIONS: the one conversion from the manoeuvring axes."""
    return ShipPath(times=times, x=s["east"], y=s["north"], vx=s["east_dot"], vy=s["north_dot"], ax=s["east_ddot"],
                    ay=s["north_ddot"], heading=0.5 * math.pi - s["psi"], rate=-s["psi_dot"], rate_dot=-s["psi_ddot"],
                    speed=np.hypot(s["u"], s["v"]), roll=s["phi"], roll_rate=s["phi_dot"], roll_acc=s["phi_ddot"])


def _hermite(s, h: float) -> tuple[tuple, tuple, tuple]:
    """The cubic Hermite weights at ``s`` in [0, 1] of a step of ``h`` s, of (f0, h f0', f1, h f1') for the value,
    and of (f0 - f1, f0', f1') for the first and second time derivatives; the same arithmetic for floats and
    arrays, so one time and many give the same bits."""
    s2, s3 = s * s, s * s * s
    return ((2 * s3 - 3 * s2 + 1, (s3 - 2 * s2 + s) * h, 3 * s2 - 2 * s3, (s3 - s2) * h),
            ((6 * s2 - 6 * s) / h, 3 * s2 - 4 * s + 1, 3 * s2 - 2 * s),
            ((12 * s - 6) / (h * h), (6 * s - 4) / h, (6 * s - 2) / h))
