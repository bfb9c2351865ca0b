"""The session's timeline: the ocean, the vessel's voyage, pose and motions, her wake and the local solver,
as functions of time.

The timeline owns no GL state; the renderer reads it. Two things move independently:

- the sea, in *legs*: a sea change starts a leg that blends in over ``ramp_s`` seconds with the weight
  ``w = 3 s^2 - 2 s^3`` (:func:`~marinesim.sea.ocean.smoothstep`), the one the ocean ramps its amplitudes with
  (:meth:`Ocean.ramp_to`), from the sea of that moment (a blend still under way included) to the new one; the
  response is linear in the amplitudes, so blending the responses to the two with ``w`` is the response to
  the ramping sea;
- the ship, on her voyage (:class:`~marinesim.manoeuvring.voyage.Voyage`): her manoeuvring model answers
  the helm, the telegraph and the autopilot from the moment each order is given, never waiting for a sea
  change.

The wave-frequency motions follow the ship's heading and speed as they change
(:mod:`marinesim.vessel.along`), exactly as on a straight track (:class:`~marinesim.vessel.response.Response`)
where she runs straight and steady; her own heel in a turn adds to the roll. Motions, poses and recordings at
any time come from the timeline, so the same scenario, seed, changes and orders give the same numbers
whatever the frame rate. The local wave solver, when started, is stepped with the clock.
"""

from __future__ import annotations

import contextvars
import dataclasses
import math
from collections.abc import Callable, Iterable
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from marinesim.angles import math_to_compass, wave_compass_from_beta
from marinesim.constants import KNOT
from marinesim.errors import ParameterError, require_at_least, require_positive, require_within
from marinesim.manoeuvring.ship import STEP_S
from marinesim.manoeuvring.voyage import SHIP_COLUMNS, Voyage
from marinesim.offshore.crane import Lift
from marinesim.offshore.helicopter import HelicopterApproach
from marinesim.pose import Pose
from marinesim.recent import Newest, Recent
from marinesim.scenario import Scenario
from marinesim.scenario.model import (CHANGE_RAMP_S, HELICOPTER_DECISIONS, MAX_DURATION_S, MAX_SPEED_KN, WEATHER,
                                      EnvironmentOptions)
from marinesim.sea.ocean import Components, smoothstep
from marinesim.sea.seastate import SeaState, scaled_sea
from marinesim.session import helideck, lifting, others
from marinesim.session.assembly import Assembly
from marinesim.session.station import StationWorld, station_columns, station_record
from marinesim.station.vessel import Station
from marinesim.vessel.along import KNOT_S, KNOT_SETS_KEPT, Knots, ShipPath, linear_along
from marinesim.vessel.response import PhasorTables, Response, Track, motion_columns
from marinesim.wake.cache import cached_wake
from marinesim.wake.compute import QUALITATIVE_BELOW_FROUDE, Wake, WakeGrid

if TYPE_CHECKING:  # the solver's module (moderngl's compute side) loads only where a solver runs
    from marinesim.solver.local import LocalSolver

STATION_HEADING_DEG = 0.5
"""A vessel keeping station responds to the waves as on her heading to this step (deg): the RAOs change little
over it, and a heading held by a DP wandering a tenth of a degree keeps one response."""
FACTOR_RANGE = (0.1, 10.0)
"""What a live change may multiply the wave heights or periods by, at once (the ocean's tiles carry the periods; a
sea ten times higher is a different exercise)."""
PREPARE_S = 0.5
"""A sea change starts this long (s) after it is asked for: meanwhile a worker thread computes its amplitudes
(:meth:`Ocean.prepare`, 0.1-0.2 s at 4 x 256^2), so the frames go on without a hitch. The start is a fixed time,
never "when the worker is done": the same changes give the same timeline whatever the machine."""
WAKE_STEP_KN = 1.0
"""Kelvin wakes are computed at the scenario's speeds and at whole knots between: a ship changing speed shows the
two nearest, blended by her speed."""
MOTION_BLOCK = 256
"""Own-ship's motions on the crane's and helicopter's grid (:data:`.lifting.GRID_S`) are computed in blocks of this
many grid times (64 s) ..."""
MOTION_BLOCKS_KEPT = 64
"""... the newest this many kept (68 minutes of motions, 2.4 MB): the helicopter's record asks for its whole run
several times over."""
RESPONSES_KEPT = 3
"""Responses to straight runs held at once (a few MB each: the run she is on, the one before, one more)."""
REST_TABLES_KEPT = 2
"""Phasor tables a set's responses at rest share (:data:`~marinesim.vessel.response.SHARED_ROWS` rows, one per
time step asked), the newest this many ..."""
REST_SETS_KEPT = 2
"""... for the newest this many component sets (a sea change blends two)."""
WAKE_GRID = WakeGrid()
"""The viewer's wake grid: the default one, so the viewer reads the wakes the headless run cached."""

SHIP_ORDER_KEYS = frozenset({"course_deg", "speed_kn", "rudder_deg", "engine", "autopilot"})
"""The orders another ship takes (:meth:`Simulation.order` with ``vessel``)."""


@dataclass(frozen=True)
class _Change:
    """A sea change asked for and not yet started."""

    sea: SeaState
    ramp_s: float
    ready_at: float    # s, its start
    prepared: Future   # the ocean's PreparedSea for ``sea``, computing


@dataclass(frozen=True)
class _WeatherRamp:
    """A weather change from ``before`` to ``after`` over ``ramp_s`` from ``start`` (s), with the sea's smoothstep:
    the fog thickens as its extinction (1 / visibility) blends, cloud, wind and rain blend linearly; a key that
    one side leaves to the sea (the wind) changes at once."""

    start: float
    ramp_s: float
    before: EnvironmentOptions
    after: EnvironmentOptions

    def at(self, t: float) -> EnvironmentOptions:
        s = (t - self.start) / self.ramp_s if self.ramp_s > 0.0 else 1.0
        if s >= 1.0:
            return self.after
        w = float(smoothstep(max(s, 0.0)))
        keys: dict[str, float] = {}
        for key in WEATHER:
            a, b = getattr(self.before, key), getattr(self.after, key)
            if a is None or b is None or a == b:
                continue
            keys[key] = 1.0 / ((1.0 - w) / a + w / b) if key == "visibility_m" else (1.0 - w) * a + w * b
        return self.after.changed(**keys) if keys else self.after


@dataclass(frozen=True)
class Leg:
    """From ``start`` (s) the sea blends over ``ramp_s`` from the sea of that moment, ``before`` (component sets
    and their weights: one set, or the blend under way then), to component set ``after`` (``sea``'s)."""

    start: float
    ramp_s: float
    sea: SeaState
    before: tuple[tuple[int, float], ...]
    after: int

    def mix(self, w: float) -> dict[int, float]:
        """The component sets' weights (set index -> weight) when ``after`` has the weight ``w``: the sets blended
        before it share the rest."""
        out = {self.after: w}
        for index, weight in self.before if w < 1.0 else ():
            out[index] = out.get(index, 0.0) + (1.0 - w) * weight
        return out

    def weight(self, t: np.ndarray) -> np.ndarray:
        """The weight of ``after`` at ``t`` (s): an array of ``t``'s shape, or a float for a float ``t`` (a stepped
        vessel's weather asks once a stage)."""
        if isinstance(t, float):
            return float(smoothstep(min(max((t - self.start) / self.ramp_s, 0.0), 1.0))) if self.ramp_s > 0 else 1.0
        s = np.clip((np.asarray(t, float) - self.start) / self.ramp_s, 0.0, 1.0) if self.ramp_s > 0 else 1.0
        return np.broadcast_to(smoothstep(s), np.shape(t)).astype(float)

    def weight_rates(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The weight's first and second time derivatives (1/s, 1/s^2) at ``t`` (s)."""
        if self.ramp_s <= 0:
            return np.zeros(np.shape(t)), np.zeros(np.shape(t))
        s = (np.asarray(t, float) - self.start) / self.ramp_s
        inside = (s > 0.0) & (s < 1.0)
        return (np.where(inside, 6.0 * s * (1.0 - s) / self.ramp_s, 0.0),
                np.where(inside, 6.0 * (1.0 - 2.0 * s) / self.ramp_s**2, 0.0))


class Simulation:
    """The scenario's ocean, vessel and wake, advanced by :meth:`advance` and queried at any time; a context manager
    that closes it (:meth:`close`)."""

    def __init__(self, scenario: Scenario, *, wake: bool = True, wake_grid: WakeGrid = WAKE_GRID,
                 assembly: Assembly | None = None) -> None:
        self.scenario = scenario
        self.assembly = Assembly(scenario) if assembly is None else assembly
        self.ocean = self.assembly.ocean
        self.time = 0.0
        self._weather = _WeatherRamp(0.0, 0.0, scenario.environment, scenario.environment)
        self.vessel = scenario.vessel
        self.legs = [Leg(0.0, 0.0, scenario.sea, ((0, 1.0),), 0)]
        self._set_times = [0.0]
        """When each component set is taken from the ocean (its amplitudes then)."""
        self._sets = Recent(lambda i: self.assembly.components(t=self._set_times[i]))
        self._knots: Newest[int, Knots] = Newest(KNOT_SETS_KEPT)
        """Sets' transfer functions at a manoeuvre's knots (:class:`~marinesim.vessel.along.Knots`)."""
        self._rest_tables: Newest[int, PhasorTables] = Newest(REST_SETS_KEPT)
        """Sets' phasor tables shared by a vessel keeping station on her headings (:meth:`_along_station`)."""
        self._pending: list[_Change] = []
        self._preparing = ThreadPoolExecutor(max_workers=1, thread_name_prefix="sea-change")
        self._last_pose: tuple[float, int, Pose | None] = (math.nan, 0, None)
        self._straight: dict[tuple, Response] = {}
        self.voyage: Voyage | None = None
        self.station: StationWorld | None = None
        if self.vessel is not None:
            ship = self.vessel.ship
            if isinstance(ship, Station):
                self.station = StationWorld(scenario, ship, scenario.station, lambda: self.legs, self.components)
                ship = dataclasses.replace(ship, environment=self.station.weather)
            start, orders = ship.start(self.vessel.speed_m_s, math.radians(self.vessel.heading_deg))
            self.voyage = Voyage(ship, start, orders, STEP_S)
        self.version = 0
        """Counts the changes of the timeline (a sea change started, an order given): rows computed before a
        change are stale after it."""
        self.wake_on = wake and self.vessel is not None and self.vessel.hull is not None
        self._wake_grid = wake_grid
        self._wakes: dict[float, Future | Wake | None] = {}
        whole_knots = (k * WAKE_STEP_KN * KNOT for k in range(1, int(MAX_SPEED_KN / WAKE_STEP_KN) + 1))
        self._wake_grid_speeds = sorted({*(self.vessel.wake_speeds_m_s if self.vessel is not None else ()),
                                         *whole_knots})
        """The speeds (m/s) wakes are computed at: the scenario's and whole knots."""
        self._pool = ThreadPoolExecutor(max_workers=1) if self.wake_on else None
        self.solver: LocalSolver | None = None
        self.bodies = [others.Body(other, self.components) for other in scenario.others]
        """The other vessels and structures (:mod:`marinesim.session.others`)."""
        self._last_others: tuple[float, int, list[Pose]] = (math.nan, 0, [])
        self._motion_blocks: dict[tuple[int, int], np.ndarray] = {}
        self.lift: Lift | None = None
        """Own-ship's crane and its load (:mod:`marinesim.session.lifting`), with a ``[crane]``."""
        if scenario.lifting is not None:
            self.lift = lifting.lift(scenario.lifting, lifting.on_grid(self.voyage.path, self._motion_grid),
                                     scenario.ocean.depth_m)
        self.helicopter: HelicopterApproach | None = None
        """A helicopter approaching her helideck (:mod:`marinesim.session.helideck`), with a ``[helicopter]``."""
        if scenario.helicopter is not None:
            self.helicopter = helideck.approach(scenario.helicopter, self.vessel.points[scenario.helicopter.deck_point],
                                                lifting.on_grid(self.voyage.path, self._motion_grid),
                                                scenario.wind[1])
        if self.wake_on:
            self._request_wake(self.vessel.speed_m_s, wait=True)

    # -- timeline -----------------------------------------------------------------------------

    def components(self, index: int) -> Components:
        """Component set ``index`` (:meth:`Assembly.components` at its time): set 0 the scenario's sea."""
        return self._sets.get(index, len(self._set_times) - 1)

    def advance(self, dt: float, step_solver: bool = True) -> None:
        """Move the clock on by ``dt`` (s), start the sea changes due, step the solver (unless told not to: a seek
        places it once at the end)."""
        self.advance_to(self.time + dt, step_solver)

    def advance_to(self, t: float, step_solver: bool = True) -> None:
        """:meth:`advance` to exactly ``t`` (s): a replay that stops where the live session stopped has
        the same clock to the last bit."""
        dt = t - self.time
        self._move_clock(t)
        if self.solver is not None and dt > 0 and step_solver:
            self.solver.step(dt, self.pose())

    def seek(self, t: float) -> None:
        """Jump the clock forward to ``t`` (s); the solver's water starts at rest around the new pose."""
        self._move_clock(t)
        if self.solver is not None:
            self.solver.place(self.pose())

    def start_solver(self, solver: LocalSolver) -> None:
        """Step ``solver`` (placed at the current pose) with the clock from now on; the timeline releases it."""
        solver.place(self.pose())
        self.solver = solver

    def _move_clock(self, t: float) -> None:
        if not math.isfinite(t) or t < self.time:
            raise ParameterError(f"time step must be a finite non-negative number of seconds, got {t - self.time!r}")
        self.time = t
        while self._pending and self.time >= self._pending[0].ready_at:
            self._start(self._pending.pop(0))

    @property
    def sea(self) -> SeaState:
        """The sea state the ocean is at, ramping to, or will ramp to once the waiting changes start."""
        return self._pending[-1].sea if self._pending else self.legs[-1].sea

    def change(self, *, hs_factor: float = 1.0, tp_factor: float = 1.0, turn_waves_deg: float = 0.0,
               sea: SeaState | None = None, speed_kn: float | None = None, heading_deg: float | None = None,
               ramp_s: float = CHANGE_RAMP_S, at: float | None = None) -> None:
        """Ask for a change: all wave heights times ``hs_factor``, periods times ``tp_factor``,
        directions turned by ``turn_waves_deg`` (compass, clockwise), or a new ``sea``, blending in over ``ramp_s``
        from ``at`` (s; default :data:`PREPARE_S` from now) whatever the sea is doing then; ``speed_kn`` and
        ``heading_deg`` are orders to the engine and the autopilot (:meth:`order`), given at ``at`` (default now)."""
        start = self.time if at is None else require_at_least("start of a change (s)", at, 0.0)
        require_within("Hs factor", hs_factor, *FACTOR_RANGE)
        require_within("Tp factor", tp_factor, *FACTOR_RANGE)
        require_within("turn of the waves", turn_waves_deg, -360.0, 360.0, "deg")
        require_within("ramp time of a sea change", ramp_s, 0.0, MAX_DURATION_S, "s")
        if (hs_factor, tp_factor, turn_waves_deg) != (1.0, 1.0, 0.0):
            if sea is not None:
                raise ParameterError("give a new sea or factors of the present one, not both")
            sea = scaled_sea(self.sea, hs_factor, tp_factor, turn_waves_deg)
        if sea is not None:  # refused before any part of the change is taken
            ramp = require_positive("ramp time of a sea change (s)", ramp_s)
            self.ocean.check(sea)
        if speed_kn is not None or heading_deg is not None:
            self.order(speed_kn=speed_kn, course_deg=heading_deg, at=at)
        if sea is None:
            return
        ready = max(start + (PREPARE_S if at is None else 0.0), self._pending[-1].ready_at if self._pending else 0.0)
        self._pending.append(_Change(sea, ramp, ready, self._preparing.submit(self.ocean.prepare, sea)))
        self._move_clock(self.time)

    def order(self, *, rudder_deg: float | None = None, engine: str | None = None, speed_kn: float | None = None,
              autopilot: bool | None = None, course_deg: float | None = None, set_north_m: float | None = None,
              set_east_m: float | None = None, fault: str | None = None, hoist_m_s: float | None = None,
              slew_deg_s: float | None = None, helicopter: str | None = None, vessel: str | None = None,
              at: float | None = None) -> None:
        """Orders to the ship from ``at`` (s; default now): the rudder by hand (deg, positive to starboard; the
        autopilot off), a telegraph order or the engine set for a speed (kn), the autopilot on (on the present
        heading) or off (the rudder held where it stands), or a course (compass deg) for the autopilot (a DP's
        heading); a DP's position set point (m north and east of her start) or an instructor's ``fault`` on a vessel
        keeping station (:mod:`marinesim.station.vessel`); to her crane, hoist (m/s, positive up, 0 stops) and slew
        (deg/s, positive to port, 0 stops); to the helicopter, the deck's word (permit, hold, wave_off). With
        ``vessel``, the helm, engine and autopilot orders are that other ship's (:meth:`others.Body.order`)."""
        if self.vessel is None:
            raise ParameterError("the scenario has no vessel: no orders")
        t = self.time if at is None else require_at_least("time of an order (s)", at, self.time)
        if vessel is not None:
            self._order_other(vessel, t, rudder_deg=rudder_deg, engine=engine, speed_kn=speed_kn,
                              autopilot=autopilot, course_deg=course_deg, set_north_m=set_north_m,
                              set_east_m=set_east_m, fault=fault, hoist_m_s=hoist_m_s, slew_deg_s=slew_deg_s,
                              helicopter=helicopter)
            return
        if (hoist_m_s is not None or slew_deg_s is not None) and self.lift is None:
            raise ParameterError("the scenario has no [crane]: no hoist or slew")
        if helicopter is not None and self.helicopter is None:
            raise ParameterError("the scenario has no [helicopter]: no word to give it")
        if helicopter is not None and helicopter not in HELICOPTER_DECISIONS:
            raise ParameterError(f"the deck's word to the helicopter is one of {', '.join(HELICOPTER_DECISIONS)}, "
                                 f"got {helicopter!r}")
        asked = {"rudder_deg": rudder_deg, "engine": engine, "speed_kn": speed_kn, "autopilot": autopilot,
                 "course_deg": course_deg, "set_north_m": set_north_m, "set_east_m": set_east_m, "fault": fault}
        asked = {key: value for key, value in asked.items() if value is not None}
        if asked:
            self.voyage.order(t, **asked)
            if self.lift is not None:  # her motion changes from the step the order acts at
                self.lift.changed(self.voyage.step_of(t) * STEP_S)
        if hoist_m_s is not None:
            self.lift.hoist(t, hoist_m_s)
        if slew_deg_s is not None:
            self.lift.slew(t, slew_deg_s)
        if helicopter is not None:
            {"permit": self.helicopter.permit, "hold": self.helicopter.hold,
             "wave_off": self.helicopter.wave_off}[helicopter](t)
        self.version += 1

    def _order_other(self, name: str, t: float, **asked) -> None:
        """Helm, engine and autopilot orders ``asked`` to the other ship ``name`` from ``t`` (s)."""
        driven = {body.other.name: body for body in self.bodies if body.other.ship is not None}
        if name not in driven:
            raise ParameterError(f"no ship {name!r} under her manoeuvring model to take orders "
                                 f"({', '.join(driven) or 'none'})")
        helm = {key: value for key, value in asked.items() if value is not None}
        wrong = sorted(helm.keys() - SHIP_ORDER_KEYS)
        if wrong or not helm:
            raise ParameterError(f"orders to {name} are her helm, engine and autopilot "
                                 f"({', '.join(sorted(SHIP_ORDER_KEYS))})" + (f", not {wrong[0]}" if wrong else ""))
        driven[name].order(t, **helm)
        self.version += 1

    @property
    def environment(self) -> EnvironmentOptions:
        """The light and the air now: the scenario's, as events and the instructor have changed them, a change
        under way blended (:class:`_WeatherRamp`)."""
        return self._weather.at(self.time)

    @environment.setter
    def environment(self, value: EnvironmentOptions) -> None:
        self._weather = _WeatherRamp(self.time, 0.0, value, value)

    def change_weather(self, hours: float = 0.0, ramp_s: float = 0.0, **keys: float) -> None:
        """Change the weather now: ``keys`` (the :data:`~marinesim.scenario.model.WEATHER` keys) blend in over
        ``ramp_s`` (s) from the weather of the moment; the clock (``hours``, with ``time_utc``) moves at once."""
        before = self.environment
        after = before.changed(hours, **keys)
        ramp = require_within("ramp time of a weather change", ramp_s, 0.0, MAX_DURATION_S, "s")
        self._weather = _WeatherRamp(self.time, ramp, before.changed(hours) if hours else before, after)
        self.version += 1
        if self.station is not None and "wind_speed_m_s" in keys:  # from the step it acts at, as an order
            start = self.voyage.step_of(self.time) * STEP_S
            self.station.weather.change(start, ramp, speed=keys["wind_speed_m_s"])
            self.voyage.changed(start)
            if self.lift is not None:
                self.lift.changed(start)

    def _start(self, change: _Change) -> None:
        t, last = change.ready_at, self.legs[-1]
        self.ocean.ramp_to(change.prepared.result(), t, change.ramp_s)  # ready unless the machine is slow
        before = last.mix(float(last.weight(t)))  # a blend under way: it goes on from the mix of now
        self.legs.append(Leg(t, change.ramp_s, change.sea, tuple(before.items()), self._new_set(t + change.ramp_s)))
        if self.station is not None:  # the waves' drift and motion change: she is stepped again from here
            self.voyage.changed(t)
        if self.lift is not None:
            self.lift.changed(t)
        self.version += 1

    def _new_set(self, t: float) -> int:
        self._set_times.append(t)
        index = len(self._set_times) - 1
        self.components(index)  # computed now, at the change, not in the next frame
        return index

    # -- the ship -----------------------------------------------------------------------------

    @property
    def speed_m_s(self) -> float:
        """Speed through the water now (m/s)."""
        return float(self.voyage.path(np.array([self.time])).speed[0]) if self.voyage else 0.0

    @property
    def heading_deg(self) -> float:
        """Compass heading of the bow now (the manoeuvring heading, deg)."""
        return math_to_compass(float(self.voyage.path(np.array([self.time])).heading[0])) if self.voyage else 0.0

    def conning(self, t: float | None = None) -> dict[str, float | str | bool | None]:
        """The conning display at ``t`` (default now): heading, set course (None by hand), rudder order and angle
        (deg, positive to starboard), propeller rpm and the engine order, rate of turn (deg/min, positive to
        starboard), speed and course over ground (kn, deg), the ship's name and model."""
        t = self.time if t is None else t
        row = self.voyage.record(np.array([t]), np.zeros(1))
        orders = self.voyage.orders_at(t)
        ship = self.vessel.ship
        return {"heading_deg": float(row["heading_deg"][0]),
                "course_deg": math.degrees(orders.course) % 360.0 if orders.autopilot else None,
                "rudder_order_deg": float(row["rudder_order_deg"][0]), "rudder_deg": float(row["rudder_deg"][0]),
                "rpm": float(row["propeller_rpm"][0]), "engine": orders.engine,
                "rate_of_turn_deg_min": float(row["rate_of_turn_deg_min"][0]),
                "speed_over_ground_kn": float(row["speed_over_ground_kn"][0]),
                "course_over_ground_deg": float(row["course_over_ground_deg"][0]),
                "ship": ship.name, "model": ship.describe()}

    # -- queries ------------------------------------------------------------------------------

    def pose(self, t: float | None = None) -> Pose:
        """Track point, heading and 6-DOF motion (m, rad) at ``t`` (default: now).

        The renderer, the camera and the HUD all ask for the pose at the same time each frame:
        the last one is kept."""
        t = self.time if t is None else t
        if self._last_pose[0] == t and self._last_pose[1] == self.version:
            return self._last_pose[2]
        if self.vessel is None:
            pose = Pose()
        else:
            path = self.voyage.path(np.array([t]))
            motion = tuple(float(v) for v in self._linear(np.array([t]))[0, :6])
            pose = Pose(float(path.x[0]), float(path.y[0]), float(path.heading[0]), motion)
        self._last_pose = (t, self.version, pose)
        return pose

    def _motion_grid(self, k0: int, n: int) -> np.ndarray:
        """Own-ship's linear outputs (n, 18) at ``(k0 + arange(n)) * lifting.GRID_S``, from blocks of
        :data:`MOTION_BLOCK` grid times counted from 0 (the block product's bits then do not depend on which stretch
        is asked), the newest :data:`MOTION_BLOCKS_KEPT` kept: the crane's tip, its landing deck and the helicopter's
        deck ask for the same stretch."""
        first, last = k0 // MOTION_BLOCK, (k0 + n - 1) // MOTION_BLOCK
        grid = np.concatenate([self._motion_block(block) for block in range(first, last + 1)])
        return grid[k0 - first * MOTION_BLOCK:][:n]

    def _motion_block(self, block: int) -> np.ndarray:
        key = (block, self.version)
        found = self._motion_blocks.get(key)
        if found is None:
            times = (block * MOTION_BLOCK + np.arange(MOTION_BLOCK)) * lifting.GRID_S
            found = self._linear(times, lifting.GRID_S)[:, :18]
            if len(self._motion_blocks) >= MOTION_BLOCKS_KEPT:
                self._motion_blocks.pop(next(iter(self._motion_blocks)))
            self._motion_blocks[key] = found
        return found

    def other_poses(self, t: float | None = None) -> list[Pose]:
        """Each other body's track point, heading and 6-DOF motion at ``t`` (default: now), as :attr:`bodies`."""
        t = self.time if t is None else t
        if self._last_others[0] == t and self._last_others[1] == self.version:
            return self._last_others[2]
        times = np.array([t])
        poses = []
        for body in self.bodies:
            path = body.path(times)
            motion = tuple(float(v) for v in self._blended(body.along, others.WIDTH, times)[0, :6])
            poses.append(Pose(float(path.x[0]), float(path.y[0]), float(path.heading[0]), motion))
        self._last_others = (t, self.version, poses)
        return poses

    @property
    def columns(self) -> list[str]:
        """The record's columns (:meth:`frame`)."""
        return record_columns(self.scenario)

    def frame(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The record (as ``marinesim export``) at ``times`` (s, increasing): the motion columns, blended across
        sea legs, and the ship's own (:data:`~marinesim.manoeuvring.voyage.SHIP_COLUMNS`)."""
        times = np.asarray(times, float).ravel()
        if self.vessel is None:
            raise ParameterError("the scenario has no vessel: no motions to record")
        return self._record(times, self._linear(times), None)

    def frame_steps(self, start: float, dt: float, steps: int, wanted: frozenset[str] | None = None
                    ) -> dict[str, np.ndarray]:
        """:meth:`frame` at ``start + dt * arange(steps)``; straight runs through their response's block product
        (:meth:`Response.linear_steps`, tables reused across blocks). ``wanted``: the columns asked for (None: all);
        the motions' and the ship's columns always come, the others' groups (a station-keeping vessel's, the crane's,
        the helicopter's, the other bodies') only where one of their columns is wanted."""
        times = start + dt * np.arange(steps)
        return self._record(times, self._linear(times, dt), dt, wanted)

    def _record(self, times: np.ndarray, linear: np.ndarray, dt: float | None,
                wanted: frozenset[str] | None = None) -> dict[str, np.ndarray]:
        def asked(columns: Iterable[str]) -> bool:
            return wanted is None or not wanted.isdisjoint(columns)
        out = self.assembly.response.frame(times, linear) | self.voyage.record(times, linear[:, 5])
        if self.station is not None and asked(station_columns(self.voyage.ship)):
            out |= station_record(self.voyage.ship, self.voyage, times)
        if self.lift is not None and asked(lifting.columns()):
            out |= lifting.record(self.lift, times)
        if self.helicopter is not None and asked(helideck.COLUMNS):
            out |= helideck.record(self.helicopter, times)
        if self.bodies and asked(others.columns(self.scenario.others)):
            out |= others.record(self.bodies, [self._blended(body.along, others.WIDTH, times, dt)
                                               for body in self.bodies], self.voyage.path(times))
        return out

    def _linear(self, times: np.ndarray, dt: float | None = None) -> np.ndarray:
        """Own-ship's linear outputs (:meth:`Response.linear`) at ``times`` (increasing; a grid of step ``dt``
        where given), the sea legs blended, the ship's own heel added to the roll."""
        out = self._blended(self._along, 19 + len(self.vessel.points), times, dt)
        path = self.voyage.path(times)
        out[:, 3] += path.roll
        out[:, 9] += path.roll_rate
        out[:, 15] += path.roll_acc
        return out

    def _blended(self, along: Callable[[int, np.ndarray, float | None], np.ndarray], width: int, times: np.ndarray,
                 dt: float | None = None) -> np.ndarray:
        """A body's linear outputs (T, ``width``) at ``times``, ``along(set, times, dt)`` its response to one
        component set, blended across the sea legs (the ramp's own share of the rates included)."""
        out = np.empty((times.size, width))
        starts = np.array([leg.start for leg in self.legs])
        index = np.maximum(np.searchsorted(starts, times, side="right") - 1, 0)
        for i in np.unique(index):
            at = np.flatnonzero(index == i)
            leg = self.legs[i]
            out[at] = along(leg.after, times[at], dt)
            w = leg.weight(times[at])
            blending = w < 1.0
            if np.any(blending):
                sel = at[blending]
                before = sum(weight * along(index, times[sel], dt) for index, weight in leg.before)
                w = w[blending][:, None]
                rate, curve = (r[:, None] for r in leg.weight_rates(times[sel]))
                after = out[sel]
                out[sel] = w * after + (1.0 - w) * before
                # the ramp's own share of the derivatives: d/dt (w a + (1 - w) b)
                out[sel, 6:12] += rate * (after[:, 0:6] - before[:, 0:6])
                out[sel, 12:18] += 2.0 * rate * (after[:, 6:12] - before[:, 6:12]) + curve * (after[:, 0:6]
                                                                                             - before[:, 0:6])
        return out

    def _along(self, index: int, times: np.ndarray, dt: float | None) -> np.ndarray:
        """Set ``index``'s response at ``times``: straight runs by :class:`Response`, manoeuvres by
        :func:`~marinesim.vessel.along.linear_along`, a vessel keeping station on her heading
        (:meth:`_along_station`)."""
        out = np.empty((times.size, 19 + len(self.vessel.points)))
        if not times.size:
            return out
        if self.station is not None:
            return self._along_station(index, times, dt, out)
        vessel = self.vessel
        for lo, hi, run in self.voyage.runs(times):
            if run is None:
                knots = self._knots.get(index, lambda: Knots(vessel.rao, self.components(index)))
                out[lo:hi] = linear_along(knots, vessel.points, self.voyage.path, times[lo:hi])
            else:
                out[lo:hi] = _linear(self._straight_response(index, run), times[lo:hi], dt)
        return out

    def _along_station(self, index: int, times: np.ndarray, dt: float | None, out: np.ndarray) -> np.ndarray:
        """Set ``index``'s response into ``out`` for a vessel keeping station: on her heading of each time, to the
        nearest :data:`STATION_HEADING_DEG`, at rest at the set point (her excursions, metres, hardly shift the
        waves' phases). At rest the waves meet her at their own frequencies on every heading: the responses share
        their phasor tables."""
        headings = np.round(np.degrees(self.voyage.path(times).heading) / STATION_HEADING_DEG) * STATION_HEADING_DEG
        bounds = np.r_[0, np.flatnonzero(np.diff(headings)) + 1, times.size]
        tables = self._rest_tables.get(index, lambda: Newest(REST_TABLES_KEPT))
        for lo, hi in zip(bounds[:-1], bounds[1:]):
            heading = float(headings[lo])
            response = self._kept((index, "station", heading), index, Track(math.radians(heading), 0.0), tables)
            out[lo:hi] = _linear(response, times[lo:hi], dt)
        return out

    def _straight_response(self, index: int, run: ShipPath | None) -> Response:
        """Set ``index``'s response on the straight run ``run`` (its path at its first step; None: the scenario's
        track)."""
        if run is None or (index == 0 and run.times[0] == 0.0):
            if index == 0:
                return self.assembly.response
            run = self.voyage.path(np.array([0.0]))
        t0 = float(run.times[0])
        heading, speed = float(run.heading[0]), float(run.speed[0])
        x0, y0 = float(run.x[0]) - speed * math.cos(heading) * t0, float(run.y[0]) - speed * math.sin(heading) * t0
        return self._kept((index, t0, float(run.x[0]), float(run.y[0]), heading, speed), index,
                          Track(heading, speed, x0, y0))

    def _kept(self, key: tuple, index: int, track: Track, tables: PhasorTables | None = None) -> Response:
        """Set ``index``'s response on ``track``, kept by ``key`` (the :data:`RESPONSES_KEPT` newest); ``tables``:
        phasor tables it shares at rest (:class:`~marinesim.vessel.response.Response`)."""
        response = self._straight.get(key)
        if response is None:
            vessel = self.vessel
            response = Response(vessel.rao, self.components(index), track, vessel.points, strict=False, tables=tables)
            if len(self._straight) >= RESPONSES_KEPT:
                self._straight.pop(next(iter(self._straight)))
            self._straight[key] = response
        return response

    def response_now(self) -> Response:
        """The newest sea's response on the track the ship is on now (her heading, speed and place; in a turn, the
        tangent to it, taken each second): what the spray's stem reads."""
        return self.response_at(self.legs[-1].after, math.floor(self.time / KNOT_S) * KNOT_S)

    def response_at(self, index: int, t: float) -> Response:
        """Component set ``index``'s response on the track the ship is on at ``t`` (s): her straight run, or in a
        manoeuvre the straight track through her place then at her heading and speed."""
        _, _, run = self.voyage.runs(np.array([t]))[0]
        return self._straight_response(index, run if run is not None else self.voyage.path(np.array([t])))

    def velocity(self) -> np.ndarray:
        """The vessel's velocity over ground now (E frame, m/s, (2,)); zero without a vessel."""
        if self.vessel is None:
            return np.zeros(2)
        path = self.voyage.path(np.array([self.time]))
        return np.array([path.vx[0], path.vy[0]])

    # -- the wake -----------------------------------------------------------------------------

    def _wake_speeds(self, speed: float) -> list[tuple[float, float]]:
        """The wake speeds (m/s) to draw at ``speed`` (m/s) with their weights: the scenario's speeds and whole
        knots, the two around ``speed`` blended linearly."""
        grid = self._wake_grid_speeds
        near = [u for u in grid if abs(u - speed) < 0.05 * KNOT]
        if near:
            return [(near[0], 1.0)]
        above = next((u for u in grid if u > speed), grid[-1])
        below = max((u for u in grid if u < speed), default=0.0)
        if below <= 0.0 or above <= speed:
            return [(above if below <= 0.0 else below, 1.0)]
        w = (speed - below) / (above - below)
        return [(below, 1.0 - w), (above, w)]

    def _request_wake(self, speed: float, wait: bool = False) -> None:
        if speed in self._wakes:
            return
        if self.assembly.hydrostatics.froude(speed) < QUALITATIVE_BELOW_FROUDE:
            self._wakes[speed] = None
            return
        hull, grid = self.vessel.hull, self._wake_grid
        compute = (contextvars.copy_context().run if wait else _call)  # a wake waited for shows its progress
        future = self._pool.submit(compute, lambda: cached_wake(hull, speed, grid)[0])
        self._wakes[speed] = future.result() if wait else future

    def wakes(self, t: float | None = None) -> list[tuple[Wake, float]]:
        """The Kelvin wakes to draw at ``t`` with their weights (two while the speed lies between wake speeds).

        A wake still being computed is left out; below Fn 0.1 thin-ship theory gives no wake worth drawing.
        """
        if not self.wake_on:
            return []
        t = self.time if t is None else t
        speed = float(self.voyage.path(np.array([t])).speed[0])
        out = []
        for u, weight in self._wake_speeds(speed):
            self._request_wake(u)
            wake = self._wakes.get(u)
            if isinstance(wake, Future) and wake.done():
                wake = self._wakes[u] = wake.result()
            if isinstance(wake, Wake) and weight > 0.0:
                out.append((wake, weight))
        return out

    def wake_status(self) -> str:
        """One line for the HUD: what the wake shows."""
        if not self.wake_on:
            return "wake off"
        speed = self.speed_m_s
        froude = self.assembly.hydrostatics.froude(speed)
        if froude < QUALITATIVE_BELOW_FROUDE:
            return f"no wake drawn: Fn {froude:.2f} < {QUALITATIVE_BELOW_FROUDE}"
        waiting = [u for u, _ in self._wake_speeds(speed) if isinstance(self._wakes.get(u), Future)
                   and not self._wakes[u].done()]
        if waiting:
            return f"wake: computing for {waiting[0] / KNOT:.1f} kn"
        return f"Kelvin wake Fn {froude:.2f}"

    def __enter__(self) -> Simulation:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    def close(self) -> None:
        """Stop the sea-change and wake workers and release the solver (``with Simulation(...) as sim:`` does it on
        leaving the block)."""
        self._preparing.shutdown(wait=False, cancel_futures=True)
        if self._pool is not None:
            self._pool.shutdown(wait=False, cancel_futures=True)
        if self.solver is not None:
            self.solver.release()

    def describe(self) -> list[str]:
        """HUD lines: the sea state and the vessel's course."""
        sea = self.sea
        lines = [f"t {self.time:8.1f} s   Hs {sea.hs:4.2f} m   Tp {sea.tp:4.1f} s   "
                 f"waves from {wave_compass_from_beta(sea.systems[0].beta):5.1f} deg ({len(sea.systems)} system(s))"]
        if self.vessel is not None:
            lines.append(f"speed {self.speed_m_s / KNOT:4.1f} kn   heading {self.heading_deg:5.1f} deg   "
                         + self.wake_status())
        return lines


def _linear(response: Response, times: np.ndarray, dt: float | None) -> np.ndarray:
    """``response``'s linear outputs at ``times`` (s; a grid of step ``dt`` where given: the block product)."""
    if dt is None or times.size < 2:
        return response.linear(times)
    return np.concatenate([o for _, o in response.linear_steps(float(times[0]), dt, times.size)])


def record_columns(scenario: Scenario) -> list[str]:
    """The record's columns: the motions' (:func:`~marinesim.vessel.response.motion_columns`), then the ship's
    (:data:`~marinesim.manoeuvring.voyage.SHIP_COLUMNS`), then a station-keeping vessel's
    (:func:`~marinesim.session.station.station_columns`), the crane's (:func:`.lifting.columns`), the helicopter's
    (:data:`.helideck.COLUMNS`), then the other bodies' (:func:`.others.columns`)."""
    vessel = scenario.vessel
    station = station_columns(vessel.ship) if isinstance(vessel.ship, Station) else []
    crane = lifting.columns() if scenario.lifting is not None else []
    helicopter = list(helideck.COLUMNS) if scenario.helicopter is not None else []
    return (motion_columns(vessel.points) + list(SHIP_COLUMNS) + station + crane + helicopter
            + others.columns(scenario.others))


def _call(function):
    return function()
