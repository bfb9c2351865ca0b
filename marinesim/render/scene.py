"""What is drawn of a session: its simulation, the renderer, the HUD, the cameras and the motion history.

The window (:mod:`marinesim.render.viewer`) and the headless renders
(:mod:`marinesim.render.offscreen`) both draw their frames through :meth:`Scene.draw`, so a
video shows exactly what the window shows. The local wave solver runs on the scene's context, so
the scene makes it and hands it to the simulation, which steps it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from datetime import timedelta, timezone
from typing import Any, Protocol

import moderngl
import numpy as np

from marinesim.angles import math_to_compass, wave_compass_from_beta
from marinesim.constants import NAUTICAL_MILE
from marinesim.criteria.monitor import Level, value_and_limit
from marinesim.errors import ParameterError
from marinesim.gl import is_software
from marinesim.render import HUDS
from marinesim.pose import Pose
from marinesim.render.camera import NAKED_EYE_FOV_DEG, BridgeCamera, Eye, FreeCamera, OrbitCamera
from marinesim.render.clock import FrameClock
from marinesim.render.hud import (ALARM_COLOR, FOOTPRINT_MIN_WIDTH, LEVEL_COLORS, Banner, Contact, Footprint, Hud,
                                  Radar, Slider, StripChart, StripHistory, font_px_for)
from marinesim.render.renderer import Renderer, RenderOptions
from marinesim.scenario import Scenario
from marinesim.scenario.model import CAMERA_BODIES
from marinesim.session.exercise import Exercise, quiet
from marinesim.session.replay import Replay
from marinesim.session.station import line_columns, thruster_columns
from marinesim.session.timeline import Simulation

CHARTED = (("heave", "heave_m", "m"), ("roll", "roll_deg", "deg"), ("pitch", "pitch_deg", "deg"))
"""Strip charts: title, motion column, unit."""
STATION_CHARTED = (("offset", "set_point_offset_m", "m"),)
"""A vessel keeping station charts her offset from the set point as well."""
FOOTPRINT_TRACK = (("east of set point", "east_of_set_point_m", "m"), ("north of set point", "north_of_set_point_m",
                                                                       "m"))
"""... and keeps her position for the footprint plot (not charted)."""
CHART_SPAN_S = 60.0
"""The strip charts show the last minute."""
FOOTPRINT_SPAN_S = 600.0
"""The footprint plot shows the last ten minutes (1,500 samples of the history)."""
HISTORY_STEP_S = 0.2
"""Spacing of the strip charts' samples (s of simulated time)."""
NOT_DRAWN = "vessel not drawn: the scenario names no hull or visual_mesh (its motions are computed)"
"""What the HUD says, strip or panels, of a vessel with neither a hull nor a visual mesh."""
HELIDECK = "helideck"
"""The criteria at this point, or named starting with it, make the helideck status light."""
HELIDECK_LIGHTS = {Level.OK: ("GREEN", "landing permitted"), Level.CAUTION: ("AMBER", "landing with caution"),
                   Level.EXCEEDED: ("RED", "landing not permitted"), Level.SETTLING: ("--", "measuring motions")}
"""Helideck monitoring status by the worst level of the helideck's criteria (CAP 437 style)."""
RADAR_SCALES_NM = (0.75, 1.5, 3.0, 6.0, 12.0, 24.0)
"""The radar's range scales (nm, the outer ring's): the auto range is the smallest holding the nearest contact (the
largest beyond it); key 6 steps through auto and these."""
RADAR_EMPTY_NM = 3.0
"""The auto range with no contacts (nm)."""
TRACK_SPAN_S = 600.0
TRACK_STEP_S = 10.0
"""The radar's past track of own ship: her positions at the multiples of :data:`TRACK_STEP_S` over the last
:data:`TRACK_SPAN_S` (s of simulated time), then where she is now."""


class Follow(Protocol):
    """A served exercise the scene's clock follows, at a station (:class:`marinesim.net.station.Station`)."""

    name: str
    """The station's name: the instructor's messages to it are shown with those to all."""

    @property
    def lag_s(self) -> float:
        """How far the scene's exercise is behind the server's (s)."""

    def step(self, dt: float) -> None:
        """Move the scene's exercise on by up to ``dt`` s, at the server's pace, never past the server's time."""

    def send(self, action: str, fields: dict[str, Any]) -> None:
        """The trainee's action, to the server (it comes back in the journal, and is applied then)."""


def solver_wanted(ctx: moderngl.Context, choice: str) -> bool:
    """``"on"``, ``"off"``, or ``"auto"``: on with a GPU, off on a software renderer (too slow there)."""
    if choice not in ("auto", "on", "off"):
        raise ParameterError(f"--solver must be auto, on or off, got {choice!r}")
    return choice == "on" or (choice == "auto" and not is_software(ctx))


PANEL_SHARE = 0.5
"""The criteria panel takes at most this share of the target's width: beyond it the rows go without the expected
values (a 640 px frame), which would cover the vessel."""


def _reading(value: float | None, limit: float) -> tuple[str, str]:
    """A criterion's value and its limit as the panel prints them: ``--`` while settling, 0 under 1e-4 of the limit,
    else with the digits that tell them apart (:func:`~marinesim.criteria.monitor.value_and_limit`)."""
    if value is None or abs(value) < 1e-4 * abs(limit):
        return "--" if value is None else "0", f"{limit:.3g}"
    return value_and_limit(value, limit)


class Scene:
    """Draws ``scenario`` on ``ctx``: ``camera`` is one of :data:`~marinesim.render.CAMERAS` or of the scenario's
    named cameras (on own ship or on another body, moving with it); the bridge camera sits on the scenario's point
    named ``bridge`` (else 10 m above the reference point)."""

    def __init__(self, ctx: moderngl.Context, scenario: Scenario, camera: str = "orbit",
                 options: RenderOptions = RenderOptions(), log: Callable[[str], None] = quiet) -> None:
        self.ctx = ctx
        self.sim = Simulation(scenario, wake=options.wake)
        self.exercise = Exercise(self.sim, log=log)
        """The scenario's events and criteria, moved on with the clock (``log``: each event as it happens)."""
        vessel = scenario.vessel
        if options.solver and vessel is not None and vessel.hull is not None:
            from marinesim.solver.gpu import GpuSolver
            from marinesim.solver.local import SolverConfig

            config = SolverConfig.for_hull(vessel.hull, size=options.solver_size)
            self.sim.start_solver(GpuSolver(config, vessel.hull, self.sim.pose(), ctx=ctx))
        if options.hud not in HUDS:
            raise ParameterError(f"--hud must be one of {', '.join(HUDS)}, got {options.hud!r}")
        self.renderer = Renderer(ctx, self.sim, options)
        self.hud = Hud(ctx)
        self.hud_shown = options.hud != "off"
        self.panels = options.hud == "panels"
        """The full panels (text block, strip charts, every criterion) instead of the compact strip (TAB)."""
        mesh = self.renderer.mesh  # the vessel as drawn frames the orbit camera
        length = float(np.ptp(mesh.positions[:, 0])) if mesh is not None else 100.0
        bridge = vessel.points.get("bridge", (0.0, 0.0, 10.0)) if vessel is not None else (0.0, 0.0, 10.0)
        self.cameras = {"orbit": OrbitCamera(distance_m=2.2 * length), "bridge": BridgeCamera(tuple(bridge)),
                        "free": FreeCamera()}
        for named in scenario.cameras:  # [[cameras]]: on board, as the bridge camera, each with its own look
            self.cameras[named.name] = BridgeCamera(named.point, named.look_yaw_deg, named.look_pitch_deg,
                                                    named.fov_deg, widest_deg=max(named.fov_deg, NAKED_EYE_FOV_DEG))
        self.named_cameras = tuple(named.name for named in scenario.cameras)
        """The scenario's cameras (key 4 goes through them)."""
        bodies = [body.other.name for body in self.sim.bodies]
        self._camera_bodies = {named.name: bodies.index(named.body) for named in scenario.cameras
                               if named.body not in CAMERA_BODIES}
        """A named camera on another body: the body's index in :attr:`Simulation.bodies`, by the camera's name."""
        self.camera_name = camera
        self.charted = CHARTED + (STATION_CHARTED if self.sim.station is not None else ())
        kept = self.charted + (FOOTPRINT_TRACK if self.sim.station is not None else ())
        self._kept_columns = [column for _, column, _ in kept]
        self.history = StripHistory([name for name, _, _ in kept], capacity=8192,
                                    span_s=FOOTPRINT_SPAN_S if self.sim.station is not None else CHART_SPAN_S)
        self._next_sample = 0.0
        self.clock: FrameClock | None = None
        """The window's frame clock (measured frame time and real-time factor); None (a headless render):
        no clock time in the picture, so that the same scenario gives the same pixels."""
        self.status: list[str] = []
        self.interactive = False
        """The window's scene (set by the viewer): the HUD shows what keys do (TAB, ENTER); a headless render (a
        video, a screenshot) shows no such hints."""
        self.replay: Replay | None = None
        """The session log the clock follows (a replay), or None (live)."""
        self.follow: Follow | None = None
        """The served exercise the clock follows (a station), or None."""
        self.slider: Slider | None = None
        self.radar_shown = bool(self.sim.bodies)
        """The radar picture in the HUD (key 5): shown at first where the scenario has other vessels."""
        self.radar_scale_nm: float | None = None
        """The radar's range, one of :data:`RADAR_SCALES_NM` (nm), or None: the auto range (key 6)."""
        self._track: tuple[tuple[int, int], np.ndarray] = ((-1, -1), np.empty((0, 2)))
        """Own ship's past track on the radar (E, m, (n, 2)), by its last sample's index and the timeline's
        version."""

    @property
    def camera_name(self) -> str:
        return self._camera_name

    @camera_name.setter
    def camera_name(self, name: str) -> None:
        if name not in self.cameras:
            raise ParameterError(f"unknown camera {name!r} (known: {', '.join(self.cameras)})")
        self._camera_name = name

    @property
    def camera(self):
        return self.cameras[self._camera_name]

    def camera_pose(self) -> Pose:
        """The pose of what the camera is on now: another body's for a named camera on it (``body = NAME``),
        own-ship's for the others."""
        body = self._camera_bodies.get(self._camera_name)
        return self.sim.pose() if body is None else self.sim.other_poses()[body]

    def eye(self) -> Eye:
        """Where the camera is and where it looks now (E frame), moving with what it is on."""
        return self.camera.eye(self.camera_pose())

    def step(self, dt: float) -> None:
        """Advance the simulation ``dt`` s (through the replay's actions in a replay), sample the strip
        charts, bring the GPU up to date."""
        if self.follow is not None:
            self.follow.step(dt)
        elif self.replay is not None:
            self.replay.advance_to(self.sim.time + dt)
        else:
            self.exercise.advance(dt)
        self._sample_history()
        self.renderer.update()

    def prefill_history(self) -> None:
        """Fill the strip charts with the last 60 s before now (a render that starts mid-run)."""
        self.history.clear()
        self._next_sample = max(self.sim.time - self.history.span_s, 0.0)
        self._sample_history()

    def _sample_history(self) -> None:
        if self.sim.vessel is None or self._next_sample > self.sim.time:
            return
        times = np.arange(self._next_sample, self.sim.time + 1e-9, HISTORY_STEP_S)
        frame = self.sim.frame(times)
        for i, t in enumerate(times):
            self.history.append(float(t), [frame[column][i] for column in self._kept_columns])
        self._next_sample = times[-1] + HISTORY_STEP_S

    def draw(self, size: tuple[int, int], hud: bool = True, help_lines: list[str] | None = None) -> None:
        """The frame into the bound framebuffer of ``size`` (w, h) px; ``hud=False`` leaves the HUD out."""
        self.renderer.draw(self.eye(), size)
        if hud and self.hud_shown:
            if font_px_for(size) != self.hud.font_px:  # the HUD keeps its share of a resized target
                self.hud.release()
                self.hud = Hud(self.ctx, font_px_for(size))
            if self.panels:
                lines, panel = self.hud_lines(size[0]), self.criteria_panel(width=size[0])
            else:
                lines, panel = self.strip_lines(size[0]), self.criteria_strip(size[0])
            station = self.follow.name if self.follow is not None else None
            self.hud.draw(size, lines, self.charts(), help_lines, panel, self.exercise.messages(station=station),
                          self.banners(), self.slider, self.footprint(), self.radar())

    def charts(self) -> list[StripChart]:
        """The strip charts drawn: the motions' over the last minute, with the panels and a vessel."""
        if not (self.panels and self.sim.vessel):
            return []
        return [self.history.chart(name, unit, CHART_SPAN_S) for name, _, unit in self.charted]

    def footprint(self) -> Footprint | None:
        """A vessel keeping station's position plot over the last :data:`FOOTPRINT_SPAN_S`, with the panels."""
        if not self.panels or self.sim.station is None:
            return None
        east, north = (self.history.chart(name, unit).values for name, _, unit in FOOTPRINT_TRACK)
        return Footprint(east, north, self.sim.scenario.station.footprint_m)

    def radar(self) -> Radar | None:
        """The radar picture now, while it is shown (:attr:`radar_shown`): own ship's compass heading, velocity
        over ground and past track (:meth:`radar_track`), and each other body as a contact, its place relative to
        own ship's track point (E, m), its velocity over ground and heading from its route, on
        :meth:`radar_range_m`."""
        if not self.radar_shown:
            return None
        sim, now = self.sim, np.array([self.sim.time])
        pose = sim.pose()
        here = np.array([pose.x, pose.y])
        contacts = []
        for body in sim.bodies:
            path = body.path(now)
            contacts.append(Contact(body.other.name, np.array([path.x[0], path.y[0]]) - here,
                                    np.array([path.vx[0], path.vy[0]]), math_to_compass(float(path.heading[0]))))
        return Radar(sim.heading_deg, sim.velocity(), self.radar_track() - here, self.radar_range_m(contacts),
                     tuple(contacts))

    def radar_range_m(self, contacts: Sequence[Contact]) -> float:
        """The radar's range (m): the one chosen (:attr:`radar_scale_nm`), else the smallest of
        :data:`RADAR_SCALES_NM` holding the nearest of ``contacts`` (:data:`RADAR_EMPTY_NM` with none)."""
        if self.radar_scale_nm is not None:
            return self.radar_scale_nm * NAUTICAL_MILE
        if not contacts:
            return RADAR_EMPTY_NM * NAUTICAL_MILE
        nearest = min(math.hypot(*contact.position) for contact in contacts)
        return next((s for s in RADAR_SCALES_NM if nearest <= s * NAUTICAL_MILE), RADAR_SCALES_NM[-1]) * NAUTICAL_MILE

    def radar_track(self) -> np.ndarray:
        """Own ship's track point (E, m, (n, 2), oldest first) at the multiples of :data:`TRACK_STEP_S` before now
        within :data:`TRACK_SPAN_S`, then now; those samples are kept until the next multiple or a change of the
        timeline. Empty without a vessel."""
        sim = self.sim
        if sim.voyage is None:
            return np.empty((0, 2))
        last = math.ceil(sim.time / TRACK_STEP_S - 1e-9) - 1  # the last multiple before now
        if self._track[0] != (last, sim.version):
            first = max(last - round(TRACK_SPAN_S / TRACK_STEP_S) + 1, 0)
            times = TRACK_STEP_S * np.arange(first, last + 1)
            path = sim.voyage.path(times) if times.size else None
            self._track = ((last, sim.version), np.empty((0, 2)) if path is None else np.column_stack([path.x, path.y]))
        pose = sim.pose()
        return np.vstack([self._track[1], [pose.x, pose.y]])

    def banners(self) -> list[Banner]:
        """The helideck's status light, then the alarms waiting for an acknowledgement (flashing at 1 Hz
        of simulated time, so a screenshot repeats)."""
        out = []
        helideck = [level for c, _, level in self.exercise.readings()
                    if c.point == HELIDECK or c.label.lower().startswith(HELIDECK)]
        if helideck:
            worst = max(helideck)
            light, meaning = HELIDECK_LIGHTS[worst]
            color = LEVEL_COLORS[worst]
            out.append(Banner(f"HELIDECK {light}: {meaning}", (*[0.35 * c for c in color[:3]], 0.9), color))
        bright = math.floor(2.0 * self.sim.time) % 2 == 0
        for alarm in self.exercise.unacknowledged():
            state = "" if alarm.cleared_s is None else " (back within limit)"
            background = ALARM_COLOR if bright else (0.45, 0.04, 0.04, 0.92)
            value, limit = value_and_limit(alarm.value, alarm.limit)
            out.append(Banner(f"ALARM  {alarm.name}: {value} > {limit}{state}" + self.hint("ENTER: acknowledge"),
                              background))
        return out

    def hint(self, keys: str) -> str:
        """``keys`` (what a key does) after three spaces, in the window; nothing in a headless render."""
        return f"   {keys}" if self.interactive else ""

    def criteria_panel(self, levels: tuple[Level, ...] = tuple(Level), width: int | None = None
                       ) -> list[tuple[str, Level]]:
        """(text, level) rows of the criteria panel, those at ``levels``: name, latest value / limit and unit,
        level, and what the sea she meets makes of the window: its expected value (the median over seeds) and
        the percentile of the latest value in that distribution (``exp 2.1 P64``), in columns as narrow as the
        rows need; on a target ``width`` px wide where the rows would take more than :data:`PANEL_SHARE` of it,
        without the expectation. A value under 1e-4 of its limit reads 0 (a green-water probability of 1e-12 is
        none a crew would see)."""
        cells = []
        for i, (criterion, value, level) in enumerate(self.exercise.readings()):
            if level not in levels:
                continue
            shown, limit = _reading(value, criterion.limit)
            expected = self.exercise.expected_now(i)
            odds = ""
            if expected is not None:
                odds = "exp " + _reading(expected.median, criterion.limit)[0]
                odds += "" if value is None else f" P{min(expected.percentile(value), 99.0):.0f}"
            cells.append(((criterion.label, shown, f"/ {limit}", criterion.measure.unit, level.value, odds), level))
        if not cells:
            return []
        widths = [max(len(row[k]) for row, _ in cells) for k in range(6)]
        if width is not None and (sum(widths) + 10) * self.hud.advance > PANEL_SHARE * width:
            widths[5] = 0
            cells = [((*row[:5], ""), level) for row, level in cells]
        return [("  ".join(cell.rjust(width) if k == 1 else cell.ljust(width)
                           for k, (cell, width) in enumerate(zip(row, widths))).rstrip(), level)
                for row, level in cells]

    def criteria_strip(self, width: int | None = None) -> list[tuple[str, Level]]:
        """The criteria in the compact strip: each one at caution or exceeded as in the panel (on a target ``width``
        px wide), else one row counting them by level, coloured by the worst."""
        alert = self.criteria_panel((Level.CAUTION, Level.EXCEEDED), width)
        levels = [level for _, _, level in self.exercise.readings()]
        if alert or not levels:
            return alert
        counts = ", ".join(f"{levels.count(level)} {level.value}" for level in Level if level in levels)
        return [(f"criteria: {counts}" + self.hint("TAB: all"), max(levels))]

    def strip_lines(self, width: int) -> list[str]:
        """The compact strip for a target ``width`` px wide: time, sea, course, motions, camera, weather, clock
        and status, packed into as few lines as fit."""
        sim, sea = self.sim, self.sim.sea
        segments = [f"t {sim.time:.1f} s",
                    f"Hs {sea.hs:.1f} m  Tp {sea.tp:.1f} s  from {wave_compass_from_beta(sea.systems[0].beta):03.0f}"]
        if sim.vessel is not None:
            m = sim.pose().motion
            segments += [self.conning_line(),
                         f"heave {m[2]:+.2f} m  roll {math.degrees(m[3]):+.1f}  pitch {math.degrees(m[4]):+.1f} deg"]
        segments.append(self.camera_name + (" 7x" if self.camera_name == "bridge" and self.cameras["bridge"].binoculars
                                            else ""))
        segments.append(self.weather_line())
        if self.clock is not None:
            segments.append(self.clock.line())
        if self.interactive:
            segments.append("TAB: panels")
        lines = self.hud.pack(segments + self.status, width)
        if sim.vessel is not None and self.renderer.mesh is None:
            lines.append(NOT_DRAWN)
        return lines

    def conning_line(self, full: bool = False) -> str:
        """The conning display in one line: heading; the autopilot's course or hand steering; the rudder's angle
        and (after the arrow, where it differs) its order, S starboard, P port; the rate of turn (deg/min, +
        starboard); propeller rpm and the engine order; speed and course over ground. A vessel on station: her
        heading and, while she turns, the one ordered (``full``: and her speed over ground, as the panels show it)."""
        c = self.sim.conning()
        if self.sim.vessel.ship.kind == "station":
            ordered = c["course_deg"]
            turning = f" > {ordered:03.0f}" if ordered is not None and abs(
                (ordered - c["heading_deg"] + 180.0) % 360.0 - 180.0) > 0.5 else ""
            offset = ""
            if self.sim.station is not None:
                offset = f" {self.sim.frame(np.array([self.sim.time]))['set_point_offset_m'][0]:.1f} m"
            if not full:  # the strip: as short as a ship's speed and heading were
                return f"HDG {c['heading_deg']:03.0f}{turning} {self.sim.vessel.ship.label}{offset}"
            return (f"HDG {c['heading_deg']:03.0f}{turning} {c['engine'].upper()}{offset}   "
                    f"SOG {c['speed_over_ground_kn']:.1f} kn")

        def side(deg: float) -> str:
            return "mid" if abs(deg) < 0.5 else f"{abs(deg):.0f}{'S' if deg > 0 else 'P'}"

        steer = f"AUTO {c['course_deg']:05.1f}" if c["course_deg"] is not None else "HAND"
        rudder = side(c["rudder_deg"]) + ("" if side(c["rudder_deg"]) == side(c["rudder_order_deg"])
                                          else f">{side(c['rudder_order_deg'])}")
        telegraph = self.sim.vessel.ship.engine.telegraph
        engine = c["engine"].upper() if c["engine"] in telegraph else f"(for {c['engine']})"
        return (f"HDG {c['heading_deg']:05.1f}  {steer}  RUD {rudder}  ROT {c['rate_of_turn_deg_min']:+.0f}/min  "
                f"{c['rpm']:.0f} rpm {engine}  SOG {c['speed_over_ground_kn']:.1f} kn  "
                f"COG {c['course_over_ground_deg']:05.1f}")

    def hud_lines(self, width: int | None = None) -> list[str]:
        """The panels' text block; a vessel keeping station adds her DP line on a target ``width`` px wide enough
        for it beside the vessel (:data:`~marinesim.render.hud.FOOTPRINT_MIN_WIDTH`; None: always)."""
        lines = self.sim.describe()[:1]
        pose = self.sim.pose()
        if self.sim.vessel is not None:
            lines.append(f"{self.conning_line(full=True)}   {self.sim.wake_status()}")
            m = pose.motion
            lines.append(f"surge {m[0]:+6.2f}  sway {m[1]:+6.2f}  heave {m[2]:+6.2f} m")
            lines.append(f"roll {math.degrees(m[3]):+6.2f}  pitch {math.degrees(m[4]):+6.2f}  "
                         f"yaw {math.degrees(m[5]):+6.2f} deg")
            if self.sim.station is not None and (width is None or width >= FOOTPRINT_MIN_WIDTH):
                lines.append(self.station_line())
        if self.sim.vessel is not None and self.renderer.mesh is None:
            lines.append(NOT_DRAWN)
        line = f"camera {self.camera_name}"
        if self.camera_name == "bridge" and self.cameras["bridge"].binoculars:
            line += " (binoculars 7x)"
        line += f"   {self.weather_line()}"
        if self.clock is not None:
            line += f"   {self.clock.line()}"
        return lines + [line] + self.status

    def station_line(self) -> str:
        """A vessel keeping station now: her offset against the footprint, the wind she feels and each thruster's
        use (%, X lost) or mooring line's tension (kN, X parted)."""
        sim = self.sim
        ship, t = sim.voyage.ship, sim.time
        row = sim.frame(np.array([t]))
        faults = sim.voyage.orders_at(t).faults
        words = [f"{ship.label}  offset {row['set_point_offset_m'][0]:.1f} / {sim.scenario.station.footprint_m:g} m",
                 f"wind {row['wind_speed_m_s'][0]:.0f} m/s from {row['wind_from_deg'][0]:03.0f}"]
        if ship.thrusters is not None:
            use = " ".join("X" if f"thruster:{th.name}" in faults else
                           f"{row[c][0]:.0f}" for th, c in zip(ship.thrusters.units, thruster_columns(ship)))
            words.append(f"thrust % {use}")
        if ship.moorings is not None:
            tensions = " ".join("X" if f"line:{name}" in faults else f"{row[c][0]:.0f}"
                                for name, c in zip(ship.line_names, line_columns(ship)))
            words.append(f"lines kN {tensions}")
        return "   ".join(words)

    def weather_line(self) -> str:
        """The light and the air now, as the instructor sets them: the clock (UTC) where the scenario has one, the
        sun's elevation, visibility, cloud and wind."""
        air = self.sim.environment
        light = self.renderer.light()
        clock = ""
        if air.time_utc is not None:
            clock = f"{(air.time_utc + timedelta(seconds=self.sim.time)).astimezone(timezone.utc):%H:%M} UTC  "
        elevation = math.degrees(math.asin(light.sun[2]))
        rain = f"  rain {air.rain_mm_h:g} mm/h" if air.rain_mm_h > 0.0 else ""
        return (f"{clock}sun {elevation:+.0f}  vis {air.visibility_m / 1000:.3g} km  "
                f"cloud {air.cloud_cover_oktas:g}/8  wind {light.wind[2]:.0f} m/s{rain}")

    def release(self) -> None:
        self.sim.close()
        self.hud.release()
        self.renderer.release()
