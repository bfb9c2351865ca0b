"""The session's timeline: the ocean, the vessel's pose and motions, its wake and the local solver,
as functions of time.

The timeline owns no GL state; the renderer reads it. Its state is a list of *legs*: the
vessel's straight track and its response to the sea at that time. A live change (sea state,
speed, heading) starts a new leg that blends in over ``ramp_s`` seconds with the weight
``w = 3 s^2 - 2 s^3`` (:func:`~marinesim.sea.ocean.smoothstep`), the one the ocean ramps its
amplitudes with (:meth:`Ocean.ramp_to`): the response is linear in the amplitudes, so blending
the two legs' motions with ``w`` is the response to the ramping sea. Track position and heading
blend with the same weight, which turns the ship along a smooth curve. A change asked for while
another blends waits for it to end. Motions, poses and recordings at any time come from the
timeline, so the same scenario, seed and changes give the same numbers whatever the frame rate.
The local wave solver, when started, is stepped with the clock.
"""

from __future__ import annotations

import contextvars
import dataclasses
import math
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from marinesim.angles import compass_to_math, math_to_compass, wave_compass_from_beta
from marinesim.constants import KNOT
from marinesim.errors import ParameterError, require_at_least, require_positive
from marinesim.pose import Pose
from marinesim.recent import Recent
from marinesim.scenario import Scenario
from marinesim.scenario.model import CHANGE_RAMP_S, MAX_SPEED_KN, WEATHER, EnvironmentOptions
from marinesim.sea.ocean import smoothstep
from marinesim.sea.seastate import SeaState, scaled_sea
from marinesim.session.assembly import Assembly
from marinesim.vessel.response import Response, Track
from marinesim.wake.cache import cached_wake
from marinesim.wake.compute import QUALITATIVE_BELOW_FROUDE, Wake, WakeGrid

if TYPE_CHECKING:  # the solver's module (moderngl's compute side) loads only where a solver runs
    from marinesim.solver.local import LocalSolver

PREPARE_S = 0.5
"""A sea change starts this long (s) after it is asked for, or when the blend before it ends if
later: meanwhile a worker thread computes its amplitudes (:meth:`Ocean.prepare`, 0.1-0.2 s at
4 x 256^2), so the frames go on without a hitch. The start is a fixed time, never "when the
worker is done": the same changes give the same timeline whatever the machine."""
WAKE_GRID = WakeGrid()
"""The viewer's wake grid: the default one, so the viewer reads the wakes the headless run cached."""


@dataclass(frozen=True)
class _Change:
    """A change asked for and not yet started; ``None`` leaves that quantity as it is."""

    sea: SeaState | None
    speed: float | None
    heading: float | None
    ramp_s: float
    ready_at: float                 # s, the earliest start
    prepared: Future | None = None  # the ocean's PreparedSea for ``sea``, computing


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
    """From ``start`` (s) the vessel follows ``track`` in ``sea``, blending in over ``ramp_s``."""

    start: float
    ramp_s: float
    sea: SeaState
    track: Track

    def weight(self, t: np.ndarray) -> np.ndarray:
        s = np.clip((np.asarray(t, float) - self.start) / self.ramp_s, 0.0, 1.0) if self.ramp_s > 0 else 1.0
        return np.broadcast_to(smoothstep(s), np.shape(t)).astype(float)

    def track_point(self, t: np.ndarray) -> np.ndarray:
        """(T, 2) track point (m, E frame)."""
        tr = self.track
        t = np.atleast_1d(np.asarray(t, float))
        return np.c_[tr.x0 + tr.speed * math.cos(tr.heading) * t, tr.y0 + tr.speed * math.sin(tr.heading) * t]


class Simulation:
    """The scenario's ocean, vessel and wake, advanced by :meth:`advance` and queried at any time."""

    def __init__(self, scenario: Scenario, *, wake: bool = True, wake_grid: WakeGrid = WAKE_GRID,
                 assembly: Assembly | None = None) -> None:
        self.scenario = scenario
        self.assembly = Assembly(scenario) if assembly is None else assembly
        self.ocean = self.assembly.ocean
        self.time = 0.0
        self._weather = _WeatherRamp(0.0, 0.0, scenario.environment, scenario.environment)
        self.vessel = scenario.vessel
        heading = compass_to_math(self.vessel.heading_deg) if self.vessel else 0.0
        speed = self.vessel.speed_m_s if self.vessel else 0.0
        self.legs = [Leg(0.0, 0.0, scenario.sea, Track(heading, speed))]
        self._responses = Recent(self._respond)
        """The vessel's response on each leg (the newest kept, older recomputed: memory stays flat)."""
        self._pending: list[_Change] = []
        self._preparing = ThreadPoolExecutor(max_workers=1, thread_name_prefix="sea-change")
        self._last_pose: tuple[float, int, Pose | None] = (math.nan, 0, None)
        self.wake_on = wake and self.vessel is not None and self.vessel.hull is not None
        self._wake_grid = wake_grid
        self._wakes: dict[float, Future | Wake | None] = {}
        self._pool = ThreadPoolExecutor(max_workers=1) if self.wake_on else None
        self.solver: LocalSolver | None = None
        if self.wake_on:
            self._request_wake(speed, wait=True)

    # -- timeline -----------------------------------------------------------------------------

    def _respond(self, index: int) -> Response:
        """The response on leg ``index``: to the sea it blends into, along its track."""
        if index == 0:
            return self.assembly.response
        leg = self.legs[index]
        components = self.assembly.components(t=leg.start + leg.ramp_s)
        return Response(self.vessel.rao, components, leg.track, self.vessel.points)

    def response(self, index: int) -> Response:
        """The vessel's response on leg ``index`` (the scenario must have a vessel)."""
        return self._responses.get(index, len(self.legs) - 1)

    def advance(self, dt: float, step_solver: bool = True) -> None:
        """Move the clock on by ``dt`` (s), start the changes waiting for a blend to end, step the solver
        (unless told not to: a seek places it once at the end)."""
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
        while self._pending and self.time >= (at := self._next_start()):
            self._start(self._pending.pop(0), at)

    def _next_start(self) -> float:
        """When the first waiting change starts (s): once asked and prepared, after the blend before it."""
        last = self.legs[-1]
        return max(last.start + last.ramp_s, self._pending[0].ready_at)

    def _requested(self, field: str):
        """The newest waiting change's value of ``field`` (sea, speed, heading), or None."""
        values = (getattr(change, field) for change in reversed(self._pending))
        return next((value for value in values if value is not None), None)

    @property
    def sea(self) -> SeaState:
        """The sea state the ocean is at, ramping to, or will ramp to once the waiting changes start."""
        requested = self._requested("sea")
        return self.legs[-1].sea if requested is None else requested

    @property
    def speed_m_s(self) -> float:
        """Speed the vessel is at or changing to (waiting changes included)."""
        requested = self._requested("speed")
        return self.legs[-1].track.speed if requested is None else requested

    @property
    def heading_deg(self) -> float:
        """Compass heading the vessel is on or turning to (waiting changes included)."""
        requested = self._requested("heading")
        return math_to_compass(self.legs[-1].track.heading if requested is None else requested)

    def change(self, *, hs_factor: float = 1.0, tp_factor: float = 1.0, turn_waves_deg: float = 0.0,
               sea: SeaState | None = None, speed_kn: float | None = None, heading_deg: float | None = None,
               ramp_s: float = CHANGE_RAMP_S, at: float | None = None) -> None:
        """Ask for a change: all wave heights times ``hs_factor``, periods times ``tp_factor``,
        directions turned by ``turn_waves_deg`` (compass, clockwise), or a new ``sea``; a new speed or
        compass heading. It starts at ``at`` (s; default now, a sea change :data:`PREPARE_S` later),
        or when the blend before it ends if later."""
        if speed_kn is not None and not 0.0 <= speed_kn <= MAX_SPEED_KN:
            raise ParameterError(f"speed must be within 0..{MAX_SPEED_KN:g} kn, got {speed_kn!r}")
        speed = None if speed_kn is None else speed_kn * KNOT
        heading = None if heading_deg is None else compass_to_math(heading_deg % 360.0)
        start = self.time if at is None else require_at_least("start of a change (s)", at, 0.0)
        change = _Change(None, speed, heading, require_at_least("ramp time (s)", ramp_s, 0.0), start)
        if (hs_factor, tp_factor, turn_waves_deg) != (1.0, 1.0, 0.0):
            if sea is not None:
                raise ParameterError("give a new sea or factors of the present one, not both")
            sea = scaled_sea(self.sea, hs_factor, tp_factor, turn_waves_deg)
        if sea is not None:
            require_positive("ramp time of a sea change (s)", ramp_s)  # refused now, not when it starts
            self.ocean.check(sea)
            change = dataclasses.replace(change, sea=sea, ready_at=start + (PREPARE_S if at is None else 0.0),
                                         prepared=self._preparing.submit(self.ocean.prepare, sea))
        self._pending.append(change)
        self._move_clock(self.time)

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
        ramp = require_at_least("ramp time (s)", ramp_s, 0.0)
        self._weather = _WeatherRamp(self.time, ramp, before.changed(hours) if hours else before, after)

    def _start(self, change: _Change, at: float) -> None:
        t, last = at, self.legs[-1]
        if change.sea is not None:
            self.ocean.ramp_to(change.prepared.result(), t, change.ramp_s)  # ready unless the machine is slow
        x, y = last.track_point(t)[0]
        heading = last.track.heading if change.heading is None else change.heading
        speed = last.track.speed if change.speed is None else change.speed
        start = (x - speed * math.cos(heading) * t, y - speed * math.sin(heading) * t)
        self.legs.append(Leg(t, change.ramp_s, change.sea or last.sea, Track(heading, speed, *start)))
        if self.vessel is not None:
            self.response(len(self.legs) - 1)  # computed now, at the change, not in the next frame
        if self.wake_on:
            self._request_wake(speed)

    def _legs_at(self, t: float) -> tuple[Leg, Leg, float]:
        """(previous leg, current leg, weight of the current) at time ``t``."""
        index = max(i for i, leg in enumerate(self.legs) if leg.start <= t or i == 0)
        leg = self.legs[index]
        previous = self.legs[max(index - 1, 0)]
        return previous, leg, float(leg.weight(t))

    # -- queries ------------------------------------------------------------------------------

    def pose(self, t: float | None = None) -> Pose:
        """Track point, heading and 6-DOF motion (m, rad) at ``t`` (default: now).

        The renderer, the camera and the HUD all ask for the pose at the same time each frame:
        the last one is kept."""
        t = self.time if t is None else t
        if self._last_pose[0] == t and len(self.legs) == self._last_pose[1]:
            return self._last_pose[2]
        previous, leg, w = self._legs_at(t)
        x, y = (1.0 - w) * previous.track_point(t)[0] + w * leg.track_point(t)[0]
        turn = math.remainder(leg.track.heading - previous.track.heading, 2.0 * math.pi)
        motion = (0.0,) * 6
        if self.vessel is not None:
            motion = tuple(float(v) for v in self._linear(np.array([t]))[0, :6])
        pose = Pose(float(x), float(y), previous.track.heading + w * turn, motion)
        self._last_pose = (t, len(self.legs), pose)
        return pose

    def frame(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """Motion columns (as ``marinesim export``) at ``times`` (s), blended across legs."""
        times = np.asarray(times, float).ravel()
        if self.vessel is None:
            raise ParameterError("the scenario has no vessel: no motions to record")
        return self.response(len(self.legs) - 1).frame(times, self._linear(times))

    def frame_steps(self, start: float, dt: float, steps: int) -> dict[str, np.ndarray]:
        """:meth:`frame` at ``start + dt * arange(steps)``, each leg through its response's block product
        (:meth:`Response.linear_steps`, tables reused across blocks), a blend as the two legs' weighted sum."""
        times = start + dt * np.arange(steps)
        last = len(self.legs) - 1
        linear = np.empty((steps, self.response(last).linear(times[:0]).shape[1]))
        k = 0
        while k < steps:
            index = max(i for i, leg in enumerate(self.legs) if leg.start <= times[k] or i == 0)
            leg = self.legs[index]
            after = self.legs[index + 1].start if index < last else math.inf
            steady = leg.start + leg.ramp_s
            blending = times[k] < steady
            end = k + int(np.searchsorted(times[k:], min(steady, after) if blending else after, side="left"))
            end = max(end, k + 1)
            linear[k:end] = self._steps_of(index, times[k], dt, end - k)
            if blending:
                w = leg.weight(times[k:end])[:, None]
                linear[k:end] = w * linear[k:end] + (1.0 - w) * self._steps_of(index - 1, times[k], dt, end - k)
            k = end
        return self.response(last).frame(times, linear)

    def _steps_of(self, index: int, start: float, dt: float, steps: int) -> np.ndarray:
        """Leg ``index``'s response's linear outputs at ``start + dt * arange(steps)`` (its block product)."""
        return np.concatenate([out for _, out in self.response(index).linear_steps(start, dt, steps)])

    def _linear(self, times: np.ndarray) -> np.ndarray:
        """The responses' linear outputs (:meth:`Response.linear`) at ``times``, blended across legs;
        the previous leg is evaluated only where a blend is under way."""
        out = np.empty((times.size, self.response(len(self.legs) - 1).linear(times[:0]).shape[1]))
        starts = np.array([leg.start for leg in self.legs])
        index = np.maximum(np.searchsorted(starts, times, side="right") - 1, 0)
        for i in np.unique(index):
            at = np.flatnonzero(index == i)
            leg = self.legs[i]
            out[at] = self.response(i).linear(times[at])
            w = leg.weight(times[at])
            blending = at[w < 1.0]
            if blending.size:
                w = w[w < 1.0][:, None]
                out[blending] = w * out[blending] + (1.0 - w) * self.response(i - 1).linear(times[blending])
        return out

    # -- the wake -----------------------------------------------------------------------------

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
        """The Kelvin wakes to draw at ``t`` with their weights (two while a speed change blends).

        A wake still being computed is left out; below Fn 0.1 thin-ship theory gives no wake worth drawing.
        """
        if not self.wake_on:
            return []
        t = self.time if t is None else t
        previous, leg, w = self._legs_at(t)
        out = []
        for speed, weight in ((previous.track.speed, 1.0 - w), (leg.track.speed, w)):
            wake = self._wakes.get(speed)
            if isinstance(wake, Future) and wake.done():
                wake = self._wakes[speed] = wake.result()
            if isinstance(wake, Wake) and weight > 0.0:
                out.append((wake, weight))
        if len(out) == 2 and out[0][0] is out[1][0]:
            out = [(out[0][0], 1.0)]
        return out

    def wake_status(self) -> str:
        """One line for the HUD: what the wake shows."""
        if not self.wake_on:
            return "wake off"
        speed = self.legs[-1].track.speed  # the wake is requested when a speed change starts
        wake = self._wakes.get(speed)
        froude = self.assembly.hydrostatics.froude(speed)
        if wake is None:
            return f"no wake drawn: Fn {froude:.2f} < {QUALITATIVE_BELOW_FROUDE}"
        if isinstance(wake, Future) and not wake.done():
            return f"wake: computing for {speed / KNOT:.1f} kn"
        return f"Kelvin wake Fn {froude:.2f}"

    def close(self) -> None:
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


def _call(function):
    return function()
