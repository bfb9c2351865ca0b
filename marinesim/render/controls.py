"""The viewer's controls: keys to actions on a scene, for the trainee, the instructor and a replay.

Which key calls which method, and in which context, is the keymap's table (:mod:`marinesim.render.keys`). Kept
apart from the window so that they act the same in a test as at the keyboard: a key is named as pyglet names it
(``pyglet.window.key.symbol_string``), e.g. ``"BRACKETRIGHT"``, ``"_1"``. Every key press goes into the session's
journal, and every action that changes the exercise goes through :meth:`Exercise.act`, so that a replay of the log
applies it again at the same time. In a replay the timeline is the log's: keys seek, pause and change the pace
instead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from marinesim.errors import MarinesimError
from marinesim.render.hud import LEVEL_COLORS, MESSAGE_COLOR, Slider
from marinesim.render.keys import (HELM_STEP_DEG, HS_STEP, RAIN_STEPS_MM_H, TIME_STEP_H, TP_STEP, TURN_STEP_DEG,
                                   VISIBILITY_STEP, dispatch, help_lines)
from marinesim.render.scene import RADAR_SCALES_NM, Scene
from marinesim.scenario.model import MAX_VISIBILITY_M, MIN_VISIBILITY_M
from marinesim.session.recorder import Recorder
from marinesim.session.timeline import CHANGE_RAMP_S

TIME_SCALES = (0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0)
FREE_SPEED_M_S = 40.0
MESSAGE_S = 8.0
"""A status message stays up this long (s of wall time), then goes."""
LAG_SHOWN_S = 0.5
"""A station shows that it lags behind the served exercise once it is this far behind (s; it is a state message,
a quarter of a second, behind as a rule)."""
MAX_FRAME_S = 0.1
"""A frame never advances the simulation by more than this (s of wall time): after a stall or a
paused debugger the ship does not jump, and the solver is not asked to catch up minutes."""


@dataclass
class Controls:
    """What the keys do to ``scene``; ``recordings`` is where recordings go. In a replay
    (``scene.replay`` set), ``restart(t)`` opens the session again at ``t`` (s) for a seek back."""

    scene: Scene
    recordings: Path = Path("recordings")
    paused: bool = False
    time_scale_index: int = TIME_SCALES.index(1.0)
    show_help: bool = False
    recorder: Recorder | None = None
    message: str = ""
    """The last status message (:meth:`say`); shown for :data:`MESSAGE_S` of wall time."""
    message_age_s: float = 0.0
    typing: str | None = None
    """The instructor's message being typed (None: not typing)."""
    restart: Callable[[float], None] | None = None
    on_quit: Callable[[], None] | None = None
    """What ESC calls (the viewer's: close the window)."""
    _opened_now: bool = field(default=False, init=False, repr=False)
    """The key that opened the message is still to come as text: it is not part of the message."""

    @property
    def exercise(self):
        return self.scene.exercise

    @property
    def time_scale(self) -> float:
        return TIME_SCALES[self.time_scale_index]

    def say(self, text: str) -> None:
        """Show ``text`` on the status lines for :data:`MESSAGE_S` of wall time."""
        self.message, self.message_age_s = text, 0.0

    def contexts(self) -> set[str]:
        """The contexts of :data:`~marinesim.render.keys.CONTEXTS` the keys act in now: while a message is being
        typed only ``typing``; the free camera's keys with the free camera."""
        if self.typing is not None:
            return {"typing"}
        found = self.session_contexts() - {"typing", "free"}
        return found | ({"free"} if self.scene.camera_name == "free" else set())

    def session_contexts(self) -> set[str]:
        """Every context this session's keys can act in: live or a replay, and the vessel's kind."""
        if self.scene.replay is not None:
            return {"always", "own_clock", "free", "replay"}
        station = self.scene.follow is not None  # the instructor is elsewhere, on the served exercise's page
        found = {"always", "free", "live", "typing"} | ({"follow"} if station else {"instructor", "own_clock"})
        sim = self.scene.sim
        found |= ({"crane"} if sim.lift is not None else set()) | ({"helicopter"} if sim.helicopter is not None
                                                                    else set())
        if sim.vessel is not None:
            ship = sim.vessel.ship
            if ship.kind != "station":
                found.add("ship")
            else:
                found.add("station")
                if sim.station is not None:
                    found |= ({"dp"} if ship.dp is not None else set())
                    if not station:
                        found |= {"faults"} | ({"dp_faults"} if ship.dp is not None else set())
        return found

    def help_lines(self) -> list[str]:
        """The help overlay (H): what every key of this session does."""
        return help_lines(self.session_contexts())

    def frame(self, wall_dt: float, held: set[str] = frozenset()) -> None:
        """One frame of ``wall_dt`` seconds: act on the keys held (the free camera's), advance the run."""
        self.message_age_s += max(wall_dt, 0.0)
        wall_dt = min(max(wall_dt, 0.0), MAX_FRAME_S)
        for key, binding in dispatch(self.contexts(), held=True).items():
            if key in held:
                getattr(self, binding.action)(wall_dt, *binding.args)
        if not self.paused and wall_dt > 0:
            self.scene.step(wall_dt * self.time_scale)
        if self.recorder is not None:
            self.recorder.catch_up()
        self.scene.status = self.status()
        self.scene.slider = self.slider()

    def press(self, key: str) -> None:
        """React to the key named ``key`` as :data:`~marinesim.render.keys.KEYMAP` says (journaled, except the keys
        of a message being typed, which are the message's); unbound keys do nothing."""
        if self.typing is None:
            self.exercise.note("key", key=key)
        binding = dispatch(self.contexts()).get(key)
        if binding is not None:
            try:
                getattr(self, binding.action)(*binding.args)
            except MarinesimError as error:  # e.g. a period change the ocean's tiles cannot carry
                self.say(str(error))

    def text(self, text: str) -> None:
        """Characters typed (pyglet's ``on_text``): they go into a message being typed."""
        if self.typing is not None and not self._opened_now:
            self.typing += "".join(c for c in text if c.isprintable())
        self._opened_now = False

    def _act(self, action: str, **fields) -> None:
        """Apply ``action`` to the exercise; at a station of a served exercise, send it to the server, which
        journals it and sends it back to every station."""
        if self.scene.follow is not None:
            self.scene.follow.send(action, fields)
        else:
            self.exercise.act(action, **fields)

    # the view and the session

    def camera(self, name: str) -> None:
        """Look through the camera ``name`` (one of :data:`~marinesim.render.CAMERAS`)."""
        self.scene.camera_name = name

    def next_camera(self) -> None:
        """Look through the scenario's next named camera (``[[cameras]]``), in turn."""
        named = self.scene.named_cameras
        if not named:
            self.say("no named cameras: the scenario's [[cameras]] adds them")
            return
        now = self.scene.camera_name
        self.scene.camera_name = named[(named.index(now) + 1) % len(named)] if now in named else named[0]
        self.say(f"camera {self.scene.camera_name}")

    def fly(self, wall_dt: float, forward: float, right: float, up: float) -> None:
        """The free camera flies ``wall_dt`` s at :data:`FREE_SPEED_M_S` along (forward, right, up)."""
        step = FREE_SPEED_M_S * wall_dt
        self.scene.cameras["free"].move(step * forward, step * right, step * up)

    def quit(self) -> None:
        """Close the window (``on_quit``, the viewer's): a live session writes its log."""
        if self.on_quit is not None:
            self.on_quit()

    # the sea, over CHANGE_RAMP_S

    def _change(self, **fields) -> None:
        self._act("change", ramp_s=CHANGE_RAMP_S, **fields)

    def wave_height(self, direction: int) -> None:
        """Wave heights x :data:`HS_STEP` (``direction`` 1) or / it (-1)."""
        self._change(hs_factor=HS_STEP if direction > 0 else 1.0 / HS_STEP)

    def wave_period(self, direction: int) -> None:
        """Wave periods x :data:`TP_STEP` (``direction`` 1) or / it (-1)."""
        self._change(tp_factor=TP_STEP if direction > 0 else 1.0 / TP_STEP)

    def turn_waves(self, direction: int) -> None:
        """The waves turn :data:`TURN_STEP_DEG` clockwise (``direction`` 1) or anticlockwise (-1)."""
        self._change(turn_waves_deg=direction * TURN_STEP_DEG)

    # the exercise

    def acknowledge(self) -> None:
        """The trainee acknowledges the alarms."""
        self._act("acknowledge")

    def start_message(self) -> None:
        self.typing, self._opened_now = "", True

    def send_message(self) -> None:
        text, self.typing = self.typing, None
        if text.strip():  # at a station, a report to the instructor
            self._act("report" if self.scene.follow is not None else "message", text=text)

    def cancel_message(self) -> None:
        self.typing = None

    def erase(self) -> None:
        """The message being typed loses its last character."""
        self.typing = self.typing[:-1]

    # the instructor: weather and faults

    def _weather(self, **fields) -> None:
        self._act("weather", **fields)

    def visibility(self, direction: int) -> None:
        """The fog lifts (``direction`` 1: visibility x :data:`VISIBILITY_STEP`) or thickens (-1: / it)."""
        air = self.scene.sim.environment
        if direction > 0:
            self._weather(visibility_m=min(air.visibility_m * VISIBILITY_STEP, MAX_VISIBILITY_M))
        else:
            self._weather(visibility_m=max(air.visibility_m / VISIBILITY_STEP, MIN_VISIBILITY_M))

    def clouds(self, oktas: int) -> None:
        """The cloud cover ``oktas`` more (fewer when negative), within 0 to 8."""
        cover = self.scene.sim.environment.cloud_cover_oktas + float(oktas)
        self._weather(cloud_cover_oktas=min(max(cover, 0.0), 8.0))

    def clock(self, direction: int) -> None:
        """The scenario's clock :data:`TIME_STEP_H` on (``direction`` 1) or back (-1)."""
        self._weather(hours=direction * TIME_STEP_H)

    def rain(self) -> None:
        """The rain's next step of :data:`RAIN_STEPS_MM_H` (after the last: none)."""
        now = self.scene.sim.environment.rain_mm_h
        self._weather(rain_mm_h=next((r for r in RAIN_STEPS_MM_H if r > now), 0.0))

    def drift_reference(self) -> None:
        """The DP's position reference drifts."""
        self._act("order", fault="reference drift")

    # the ship: helm, telegraph, autopilot (the orders given, not yet answered too)

    def _order(self, **fields) -> None:
        self._act("order", **fields)

    def helm(self, direction: int) -> None:
        """The rudder order :data:`HELM_STEP_DEG` to starboard (``direction`` 1) or port (-1), hand steering."""
        sim = self.scene.sim
        hard, orders = math.degrees(sim.vessel.ship.steering.max_angle), sim.voyage.orders
        rudder = math.degrees(orders.rudder) if not orders.autopilot else sim.conning()["rudder_order_deg"]
        self._order(rudder_deg=round(max(min(rudder + direction * HELM_STEP_DEG, hard), -hard), 6))

    def rudder_hard(self, side: int) -> None:
        """The rudder hard a-starboard (``side`` 1), hard a-port (-1) or midships (0)."""
        self._order(rudder_deg=side * math.degrees(self.scene.sim.vessel.ship.steering.max_angle))

    def telegraph(self, steps: int) -> None:
        """The telegraph ``steps`` notches ahead (astern when negative)."""
        sim = self.scene.sim
        orders = sim.voyage.orders
        self._order(engine=sim.vessel.ship.engine.step(orders.engine, steps, orders.rps))

    def toggle_autopilot(self) -> None:
        self._order(autopilot=not self.scene.sim.voyage.orders.autopilot)

    def steer(self, step_deg: float) -> None:
        """The course ``step_deg`` to starboard (to port when negative) of the autopilot's, or of her heading (hand
        steering; a vessel on station: her heading order)."""
        sim = self.scene.sim
        orders = sim.voyage.orders
        course = math.degrees(orders.course) % 360.0 if orders.autopilot else sim.conning()["heading_deg"]
        self._order(course_deg=round((course + step_deg) % 360.0, 6))

    def hoist(self, step_m_s: float) -> None:
        """The crane's hoist ``step_m_s`` faster up (down when negative), within its hoist speed."""
        lift = self.scene.sim.lift
        limit = lift.crane.hoist_speed_m_s
        up, _ = lift.ordered(self.scene.sim.time)
        self._order(hoist_m_s=round(max(min(up + step_m_s, limit), -limit), 6))

    def slew(self, step_deg_s: float) -> None:
        """The crane's slew ``step_deg_s`` faster to port (starboard when negative), within its slew rate."""
        lift = self.scene.sim.lift
        limit = lift.crane.slew_rate_deg_s
        _, rate = lift.ordered(self.scene.sim.time)
        self._order(slew_deg_s=round(max(min(rate + step_deg_s, limit), -limit), 6))

    def crane_stop(self) -> None:
        """The crane's hoist and slew stopped."""
        self._order(hoist_m_s=0.0, slew_deg_s=0.0)

    def deck_word(self, word: str) -> None:
        """The deck's word to the helicopter: permit (GREEN), hold (RED) or wave_off."""
        self._order(helicopter=word)

    def move_set_point(self, ahead: float, starboard: float) -> None:
        """The DP's position set point ``ahead`` and to ``starboard`` (m) of where it is, along her heading set
        point."""
        orders = self.scene.sim.voyage.orders
        psi = orders.course
        north = orders.north + ahead * math.cos(psi) - starboard * math.sin(psi)
        east = orders.east + ahead * math.sin(psi) + starboard * math.cos(psi)
        self._order(set_north_m=round(north, 6), set_east_m=round(east, 6))

    def next_fault(self) -> None:
        """The instructor fails the next thruster still working (a vessel on DP) or parts the next line still
        holding (moored)."""
        sim = self.scene.sim
        ship, faults = sim.voyage.ship, sim.voyage.orders.faults
        left = [name for name in ship.unit_faults if name not in faults]
        if not left:
            self.say("every thruster is lost" if ship.thrusters is not None else "every line has parted")
            return
        self._act("order", fault=left[0])
        self.say(f"instructor: {left[0].replace(':', ' ')} {'lost' if ship.thrusters is not None else 'parted'}")

    def trigger_next(self) -> None:
        """The instructor brings the next scripted event forward to now."""
        pending = self.exercise.pending_events()
        if not pending:
            self.say("no scripted event left to trigger")
            return
        self._act("trigger", index=pending[0])

    def toggle_binoculars(self) -> None:
        """On the bridge: raise the binoculars to the eye, or lower them."""
        if self.scene.camera_name != "bridge":
            self.say("binoculars: on the bridge (key 2)")
            return
        self.scene.cameras["bridge"].binoculars = not self.scene.cameras["bridge"].binoculars

    def toggle_radar(self) -> None:
        """The radar picture of the traffic shown or hidden; a HUD turned off (``--hud off``) comes back with it
        shown."""
        scene = self.scene
        scene.radar_shown = not (scene.radar_shown and scene.hud_shown)
        scene.hud_shown = True

    def radar_range(self) -> None:
        """The radar's next range: auto, then each of :data:`~marinesim.render.scene.RADAR_SCALES_NM`, then auto
        again; the radar shown."""
        scene = self.scene
        ranges = (None, *RADAR_SCALES_NM)
        scene.radar_scale_nm = ranges[(ranges.index(scene.radar_scale_nm) + 1) % len(ranges)]
        scene.radar_shown = scene.hud_shown = True
        self.say("radar range auto" if scene.radar_scale_nm is None else f"radar range {scene.radar_scale_nm:g} nm")

    def toggle_help(self) -> None:
        self.show_help = not self.show_help

    def toggle_panels(self) -> None:
        """The HUD's compact strip, or its full panels (text block, strip charts, every criterion); a HUD turned
        off (``--hud off``) comes back as it was."""
        if self.scene.hud_shown:
            self.scene.panels = not self.scene.panels
        self.scene.hud_shown = True

    def toggle_pause(self) -> None:
        self.paused = not self.paused
        self.exercise.note("pause" if self.paused else "resume")

    def scale_time(self, direction: int) -> None:
        self.time_scale_index = int(np.clip(self.time_scale_index + direction, 0, len(TIME_SCALES) - 1))
        self.exercise.note("time_scale", scale=self.time_scale)

    def seek_by(self, seconds: float) -> None:
        """A replay's clock ``seconds`` on (back when negative)."""
        self.seek(self.scene.sim.time + seconds)

    def seek(self, t: float) -> None:
        """A replay's clock to ``t`` (s, within the session): forward through the log, back by starting again."""
        replay = self.scene.replay
        t = min(max(t, 0.0), replay.source.end_s)
        if t >= self.scene.sim.time:
            replay.advance_to(t)
            self.scene.sim.seek(t)
            self.scene.prefill_history()
            self.scene.renderer.update()
        elif self.restart is not None:
            self.restart(t)

    def toggle_recording(self) -> None:
        if self.recorder is None:
            name = f"{self.scene.sim.scenario.name}_{self.scene.sim.time:08.1f}s.csv"
            try:
                self.recorder = Recorder(self.exercise, self.recordings / name)
            except MarinesimError as error:
                self.say(str(error))
                return
            self.exercise.note("recording", file=str(self.recorder.path))
            self.say(f"recording to {self.recorder.path}")
        else:
            recorder, self.recorder = self.recorder, None
            try:
                path = recorder.stop()
                self.exercise.note("recorded", file=str(path), rows=recorder.rows)
                self.say(f"recorded {recorder.rows} rows to {path}")
            except (OSError, MarinesimError) as error:  # a full disk must not end the session
                recorder.abandon()
                self.say(f"the recording could not be written: {error}")

    def status(self) -> list[str]:
        state = "PAUSED" if self.paused else f"time x{self.time_scale:g}"
        recording = f"   REC {self.recorder.rows} rows" if self.recorder else ""
        follow = self.scene.follow
        mode = "   REPLAY" if self.scene.replay is not None else ""
        if follow is not None:
            lag = follow.lag_s
            mode = f"   STATION {follow.name}" + (f"   LAGS {lag:.1f} s" if lag > LAG_SHOWN_S else "")
        lines = [f"{state}{recording}{mode}   H: help"]
        if self.typing is not None:
            lines.append(f"message: {self.typing}_   (ENTER send, ESC cancel)")
        return lines + ([self.message] if self.message and self.message_age_s < MESSAGE_S else [])

    def slider(self) -> Slider | None:
        """A replay's time slider: where the clock is in the session, its events and alarms marked."""
        replay = self.scene.replay
        if replay is None:
            return None
        end = max(replay.source.end_s, 1e-9)
        marks = [(entry["t"] / end, LEVEL_COLORS["exceeded"] if entry["kind"] == "alarm" else MESSAGE_COLOR)
                 for entry in replay.source.entries if entry["kind"] in ("event", "alarm")]
        return Slider(self.scene.sim.time / end, marks,
                      f"replay {self.scene.sim.time:7.1f} / {replay.source.end_s:.1f} s   "
                      "LEFT/RIGHT -/+30 s  HOME start  click: seek")

