"""The standard manoeuvres of IMO MSC.137(76) (with MSC/Circ.1053) in calm water, and the criteria.

Every manoeuvre starts on a straight course at the approach speed with the propeller at the rate that holds
it (:meth:`Ship.steady`); the order is given at t = 0 and the steering gear and the engine carry it out at
their rates. Distances are those of the model's origin (midship) from where the order was given.

- Turning circle: the rudder hard over (the steering gear's limit, 35 deg by SOLAS) until the heading has changed
  720 deg. Advance: the distance along the original course when the heading has changed 90 deg; transfer: across it
  then; tactical diameter: across it at 180 deg; the steady diameter: the distance between the positions at 540 and
  720 deg (half a steady circle apart); the final speed at 720 deg.
- Zig-zag a/b: the rudder to a deg starboard; when the heading has changed b deg, to a deg port; when it has changed
  b deg to port, back to starboard; the first overshoot is how far the heading goes past b after the first reversal,
  the second past -b after the second. Initial turning: the distance run until the heading has changed 10 deg with
  10 deg of rudder.
- Crash stop: full astern from the approach; track reach the distance run along the track until the ship stops (no
  headway), head reach the distance along the original course.
- Criteria (MSC.137(76) 5.3): advance <= 4.5 L, tactical diameter <= 5 L; initial turning <= 2.5 L; 10/10 first
  overshoot <= 10 deg if L/V < 10 s, <= 20 deg if L/V >= 30 s, 5 + L/(2V) between, the second <= 25, 40 and 17.5 +
  0.75 L/V; 20/20 first overshoot <= 25 deg; crash-stop track reach <= 15 L (an Administration may allow 20 L for
  large ships).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.manoeuvring.ship import STEP_S, Ship
from marinesim.manoeuvring.state import Orders, ShipState
from marinesim.progress import task

MAX_TRIAL_S = 7200.0
"""A manoeuvre that has not finished in two hours never will (a ship that barely answers her helm)."""


@dataclass(frozen=True)
class Record:
    """A manoeuvre's time series (T,): time (s), north, east (m), heading change (deg, positive to starboard),
    rudder (deg, positive to starboard), speed (m/s), distance run along the track (m)."""

    time: np.ndarray
    north: np.ndarray
    east: np.ndarray
    heading: np.ndarray
    rudder: np.ndarray
    speed: np.ndarray
    run: np.ndarray


@dataclass(frozen=True)
class Turning:
    rudder_deg: float
    advance_m: float
    transfer_m: float
    tactical_diameter_m: float
    steady_diameter_m: float
    final_speed_kn: float
    record: Record = field(repr=False)

    def as_dict(self) -> dict:
        return {"rudder_deg": self.rudder_deg, "advance_m": self.advance_m, "transfer_m": self.transfer_m,
                "tactical_diameter_m": self.tactical_diameter_m, "steady_diameter_m": self.steady_diameter_m,
                "final_speed_kn": self.final_speed_kn}


@dataclass(frozen=True)
class Zigzag:
    rudder_deg: float
    heading_deg: float
    first_overshoot_deg: float
    second_overshoot_deg: float
    initial_turning_m: float
    record: Record = field(repr=False)

    def as_dict(self) -> dict:
        return {"first_overshoot_deg": self.first_overshoot_deg, "second_overshoot_deg": self.second_overshoot_deg}


@dataclass(frozen=True)
class Stopping:
    track_reach_m: float
    head_reach_m: float
    time_s: float
    record: Record = field(repr=False)

    def as_dict(self) -> dict:
        return {"track_reach_m": self.track_reach_m, "head_reach_m": self.head_reach_m, "time_s": self.time_s}


@dataclass(frozen=True)
class Trials:
    """The trials of ``ship`` at ``speed`` (m/s): both turning circles, the 10/10 and 20/20 zig-zags (to
    starboard first), the crash stop (None where the engine cannot go astern), the IMO criteria."""

    name: str
    length_m: float
    speed_m_s: float
    port: Turning
    starboard: Turning
    zigzag_10: Zigzag
    zigzag_20: Zigzag
    stopping: Stopping | None
    criteria: list[dict]

    @property
    def passed(self) -> bool:
        return all(c["pass"] for c in self.criteria)

    def as_dict(self) -> dict:
        """The ``marinesim trials --json`` object."""
        return {"turning": {"port": self.port.as_dict(), "starboard": self.starboard.as_dict()},
                "zigzag": {"10/10": self.zigzag_10.as_dict(), "20/20": self.zigzag_20.as_dict()},
                "stopping": None if self.stopping is None else self.stopping.as_dict(),
                "imo": {"pass": self.passed, "criteria": self.criteria}}


def _run(ship: Ship, speed: float, control, until) -> Record:
    """Step ``ship`` from a steady approach at ``speed`` (m/s) heading north; ``control(state, change)`` gives the
    orders (``change`` the heading change, deg to starboard), ``until(state, change)`` ends the run."""
    state = ship.steady(speed)
    columns: list[tuple[float, ...]] = []
    run, t = 0.0, 0.0
    while True:
        change = math.degrees(state.psi)
        columns.append((t, state.north, state.east, change, math.degrees(state.delta), state.speed, run))
        _check(ship, state, speed, t)
        if until(state, change) or t > MAX_TRIAL_S:
            break
        following, _ = ship.step(state, control(state, change), STEP_S)
        run += 0.5 * (state.speed + following.speed) * STEP_S
        state, t = following, t + STEP_S
    if t > MAX_TRIAL_S:
        raise ParameterError(f"{ship.name}: the manoeuvre did not finish in {MAX_TRIAL_S:g} s: the ship hardly "
                             "answers her helm at this speed")
    return Record(*(np.array(c) for c in zip(*columns)))


def _check(ship: Ship, state: ShipState, speed: float, t: float) -> None:
    """Refuse a model that leaves the physical: numbers gone, a spin, a drift across the flow, a capsize."""
    values = (state.u, state.v, state.r, state.phi)
    l_over_u = ship.length_m / max(state.speed, 0.1 * speed)
    if (not all(map(math.isfinite, values)) or state.speed > 2.0 * speed or abs(state.r) * l_over_u > 4.0
            or abs(state.phi) > math.radians(45.0)):
        raise ParameterError(
            f"{ship.name}: the model is unstable at {math.degrees(state.delta):+.0f} deg of rudder from "
            f"{speed / KNOT:.3g} kn: after {t:.0f} s its speed is {state.speed / KNOT:.3g} kn, its rate of turn "
            f"{math.degrees(state.r):.3g} deg/s, its heel {math.degrees(state.phi):.3g} deg: check its coefficients")


def _at(record: Record, column: np.ndarray, level: float) -> int:
    """The first index where ``|column|`` reaches ``level``."""
    index = int(np.argmax(np.abs(column) >= level))
    if abs(column[index]) < level:
        raise ParameterError(f"the heading never changed {level:g} deg")
    return index


def _interpolated(record: Record, name: str, index: int, level: float) -> float:
    """``record.name`` where ``|heading|`` crosses ``level`` between ``index - 1`` and ``index``."""
    values, heading = getattr(record, name), np.abs(record.heading)
    if index == 0:
        return float(values[0])
    f = (level - heading[index - 1]) / (heading[index] - heading[index - 1])
    return float(values[index - 1] + f * (values[index] - values[index - 1]))


def turning_circle(ship: Ship, speed: float, side: int) -> Turning:
    """The hard-over turning circle to starboard (``side`` +1) or port (-1) from ``speed`` (m/s)."""
    rudder, rps = side * ship.steering.max_angle, ship.rps_for_speed(speed)
    record = _run(ship, speed, lambda s, c: Orders(rudder=rudder, rps=rps), lambda s, c: abs(c) >= 720.0)
    i90, i180 = _at(record, record.heading, 90.0), _at(record, record.heading, 180.0)
    i540, i720 = _at(record, record.heading, 540.0), len(record.time) - 1

    def point(index: int, level: float) -> np.ndarray:
        return np.array([_interpolated(record, "north", index, level), _interpolated(record, "east", index, level)])

    steady = float(np.linalg.norm(point(i720, 720.0) - point(i540, 540.0)))
    return Turning(math.degrees(rudder), _interpolated(record, "north", i90, 90.0),
                   abs(_interpolated(record, "east", i90, 90.0)), abs(_interpolated(record, "east", i180, 180.0)),
                   steady, _interpolated(record, "speed", i720, 720.0) / KNOT, record)


def hard_over(ship: Ship, speed: float) -> None:
    """Refuse (:class:`ParameterError`) a model that goes unstable in a hard-over turn to starboard from ``speed``
    (m/s), turned through 360 deg."""
    rudder, rps = ship.steering.max_angle, ship.rps_for_speed(speed)
    _run(ship, speed, lambda s, c: Orders(rudder=rudder, rps=rps), lambda s, c: abs(c) >= 360.0)


def zigzag(ship: Ship, speed: float, angle_deg: float, side: int = 1) -> Zigzag:
    """The ``angle_deg``/``angle_deg`` zig-zag from ``speed`` (m/s), the first rudder to starboard (``side`` +1)
    or port (-1)."""
    rudder, rps = side * math.radians(angle_deg), ship.rps_for_speed(speed)
    phase = {"sign": 1, "reversals": 0, "peak": 0.0, "overshoots": []}

    def control(state: ShipState, change: float) -> Orders:
        sign = phase["sign"]
        if sign * side * change >= angle_deg:
            phase["sign"], phase["reversals"] = -sign, phase["reversals"] + 1
            if phase["reversals"] > 1:
                phase["overshoots"].append(phase["peak"])
            phase["peak"] = 0.0
        if phase["reversals"]:
            phase["peak"] = max(phase["peak"], -phase["sign"] * side * change - angle_deg)
        return Orders(rudder=phase["sign"] * rudder, rps=rps)

    def until(state: ShipState, change: float) -> bool:
        return len(phase["overshoots"]) >= 2

    record = _run(ship, speed, control, until)
    initial = _interpolated(record, "run", _at(record, record.heading, 10.0), 10.0) if angle_deg == 10.0 else math.nan
    first, second = phase["overshoots"][:2]
    return Zigzag(angle_deg, angle_deg, first, second, initial, record)


def crash_stop(ship: Ship, speed: float) -> Stopping | None:
    """Full astern from ``speed`` (m/s), the rudder amidships; None where the engine cannot go astern."""
    if not ship.engine.can_go_astern:
        return None
    astern = -ship.engine.max_astern_rps
    record = _run(ship, speed, lambda s, c: Orders(rudder=0.0, rps=astern), lambda s, c: s.u <= 0.0)
    return Stopping(float(record.run[-1]), float(record.north[-1]), float(record.time[-1]), record)


def overshoot_limits(length_m: float, speed: float) -> tuple[float, float]:
    """MSC.137(76) 5.3.3.1: the 10/10 first and second overshoot limits (deg) for ``length_m`` at ``speed`` (m/s)."""
    l_over_v = length_m / speed
    first = 10.0 if l_over_v < 10.0 else 20.0 if l_over_v >= 30.0 else 5.0 + 0.5 * l_over_v
    second = 25.0 if l_over_v < 10.0 else 40.0 if l_over_v >= 30.0 else 17.5 + 0.75 * l_over_v
    return first, second


def trials(ship: Ship, speed: float) -> Trials:
    """Every manoeuvre of the module at ``speed`` (m/s), and the criteria."""
    length = ship.length_m
    with task("trials", 5, "manoeuvre") as bar:
        port = turning_circle(ship, speed, -1)
        bar.update(1)
        starboard = turning_circle(ship, speed, 1)
        bar.update(1)
        z10 = zigzag(ship, speed, 10.0)
        bar.update(1)
        z20 = zigzag(ship, speed, 20.0)
        bar.update(1)
        stop = crash_stop(ship, speed)
        bar.update(1)
    first, second = overshoot_limits(length, speed)

    def criterion(name: str, value: float, limit: float, unit: str) -> dict:
        return {"name": name, "value": value, "limit": limit, "unit": unit, "pass": bool(value <= limit)}

    criteria = [criterion(f"advance, {side}", turn.advance_m / length, 4.5, "L")
                for side, turn in (("port", port), ("starboard", starboard))]
    criteria += [criterion(f"tactical diameter, {side}", turn.tactical_diameter_m / length, 5.0, "L")
                 for side, turn in (("port", port), ("starboard", starboard))]
    criteria += [criterion("initial turning, 10 deg rudder", z10.initial_turning_m / length, 2.5, "L"),
                 criterion("10/10 zig-zag, first overshoot", z10.first_overshoot_deg, first, "deg"),
                 criterion("10/10 zig-zag, second overshoot", z10.second_overshoot_deg, second, "deg"),
                 criterion("20/20 zig-zag, first overshoot", z20.first_overshoot_deg, 25.0, "deg")]
    if stop is not None:
        criteria.append(criterion("crash stop, track reach", stop.track_reach_m / length, 15.0, "L"))
    return Trials(getattr(ship, "name", "ship"), length, speed, port, starboard, z10, z20, stop, criteria)
