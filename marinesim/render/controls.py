"""The viewer's controls: keys to actions on a scene, for the trainee, the instructor and a replay.

Kept apart from the window so that they act the same in a test as at the keyboard: a key is
named as pyglet names it (``pyglet.window.key.symbol_string``), e.g. ``"BRACKETRIGHT"``, ``"_1"``.
Every key press goes into the session's journal, and every action that changes the exercise goes
through :meth:`Exercise.act`, so that a replay of the log applies it again at the same time. In a
replay the timeline is the log's: keys seek, pause and change the pace instead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from marinesim.render.hud import LEVEL_COLORS, MESSAGE_COLOR, Slider

from marinesim.errors import MarinesimError
from marinesim.render.scene import Scene
from marinesim.scenario.model import MAX_VISIBILITY_M, MIN_VISIBILITY_M
from marinesim.session.recorder import Recorder
from marinesim.session.timeline import CHANGE_RAMP_S

HS_STEP = 1.1       # each press: heights x 1.1 (or / 1.1)
TP_STEP = 1.05      # periods x 1.05
TURN_STEP_DEG = 15.0
HELM_STEP_DEG = 5.0
"""LEFT / RIGHT: the rudder order this much to port / starboard (a vessel on station: her heading)."""
COURSE_STEPS_DEG = (1.0, 10.0)
"""U / I and 9 / 0: the autopilot's course this much to port / starboard."""
SET_POINT_STEP_M = 1.0
"""How far a key moves a DP's position set point (m): the reference model takes her there at 0.3 m/s."""
TIME_SCALES = (0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0)
VISIBILITY_STEP = 2.0  # each press: visibility / 2 (fog thickens) or x 2 (it lifts)
TIME_STEP_H = 1.0
RAIN_STEPS_MM_H = (0.0, 2.5, 10.0, 50.0)
"""The instructor's O steps the rain through these: none, light, heavy, violent showers."""
SEEK_STEP_S = 30.0
"""A replay's LEFT / RIGHT: back / forward this long (s)."""
FREE_SPEED_M_S = 40.0
MESSAGE_S = 8.0
"""A status message stays up this long (s of wall time), then goes."""
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

    def frame(self, wall_dt: float, held: set[str] = frozenset()) -> None:
        """One frame of ``wall_dt`` seconds: move the free camera for held keys, advance the run."""
        self.message_age_s += max(wall_dt, 0.0)
        wall_dt = min(max(wall_dt, 0.0), MAX_FRAME_S)
        if self.scene.camera_name == "free" and self.typing is None:
            step = FREE_SPEED_M_S * wall_dt
            moves = {"W": (step, 0, 0), "S": (-step, 0, 0), "D": (0, step, 0), "A": (0, -step, 0),
                     "E": (0, 0, step), "C": (0, 0, -step)}
            for key in held & moves.keys():
                self.scene.cameras["free"].move(*moves[key])
        if not self.paused and wall_dt > 0:
            self.scene.step(wall_dt * self.time_scale)
        if self.recorder is not None:
            self.recorder.catch_up()
        self.scene.status = self.status()
        self.scene.slider = self.slider()

    def press(self, key: str) -> None:
        """React to the key named ``key`` (journaled); unknown keys do nothing."""
        if self.typing is not None:
            self._type_key(key)
            return
        self.exercise.note("key", key=key)
        action = self.actions().get(key)
        if action is not None:
            try:
                action()
            except MarinesimError as error:  # e.g. a period change the ocean's tiles cannot carry
                self.say(str(error))

    def text(self, text: str) -> None:
        """Characters typed (pyglet's ``on_text``): they go into a message being typed."""
        if self.typing is not None and not self._opened_now:
            self.typing += "".join(c for c in text if c.isprintable())
        self._opened_now = False

    def _type_key(self, key: str) -> None:
        if key in ("RETURN", "ENTER"):
            text, self.typing = self.typing, None
            if text.strip():
                self._act("message", text=text)
        elif key == "ESCAPE":
            self.typing = None
        elif key == "BACKSPACE":
            self.typing = self.typing[:-1]

    def _act(self, action: str, **fields) -> None:
        self.exercise.act(action, **fields)

    def actions(self) -> dict[str, Callable[[], None]]:
        sim = self.scene.sim

        def change(**kwargs) -> Callable[[], None]:
            return lambda: self._act("change", ramp_s=CHANGE_RAMP_S, **kwargs)

        def camera(name: str) -> Callable[[], None]:
            return lambda: setattr(self.scene, "camera_name", name)

        def weather(**kwargs) -> Callable[[], None]:
            return lambda: self._act("weather", **kwargs)

        air = sim.environment

        actions = {
            "H": self.toggle_help, "TAB": self.toggle_panels, "SPACE": self.toggle_pause, "R": self.toggle_recording,
            "_1": camera("orbit"), "_2": camera("bridge"), "_3": camera("free"), "B": self.toggle_binoculars,
            "PLUS": lambda: self._scale_time(1), "EQUAL": lambda: self._scale_time(1),
            "NUM_ADD": lambda: self._scale_time(1), "MINUS": lambda: self._scale_time(-1),
            "NUM_SUBTRACT": lambda: self._scale_time(-1),
        }
        if self.scene.replay is not None:
            return actions | {"LEFT": lambda: self.seek(sim.time - SEEK_STEP_S),
                              "RIGHT": lambda: self.seek(sim.time + SEEK_STEP_S), "HOME": lambda: self.seek(0.0)}
        actions |= {
            "RETURN": lambda: self._act("acknowledge"), "ENTER": lambda: self._act("acknowledge"),
            "N": self.trigger_next, "M": self.start_message,
            "BRACKETRIGHT": change(hs_factor=HS_STEP), "BRACKETLEFT": change(hs_factor=1.0 / HS_STEP),
            "PERIOD": change(tp_factor=TP_STEP), "COMMA": change(tp_factor=1.0 / TP_STEP),
            "APOSTROPHE": change(turn_waves_deg=TURN_STEP_DEG), "SEMICOLON": change(turn_waves_deg=-TURN_STEP_DEG),
            "F": weather(visibility_m=max(air.visibility_m / VISIBILITY_STEP, MIN_VISIBILITY_M)),
            "G": weather(visibility_m=min(air.visibility_m * VISIBILITY_STEP, MAX_VISIBILITY_M)),
            "K": weather(cloud_cover_oktas=min(air.cloud_cover_oktas + 1.0, 8.0)),
            "J": weather(cloud_cover_oktas=max(air.cloud_cover_oktas - 1.0, 0.0)),
            "T": weather(hours=TIME_STEP_H), "Y": weather(hours=-TIME_STEP_H),
            "O": weather(rain_mm_h=next((r for r in RAIN_STEPS_MM_H if r > air.rain_mm_h), 0.0)),
        }
        if sim.vessel is not None:
            actions |= self._bridge_keys()
        return actions

    def _bridge_keys(self) -> dict[str, Callable[[], None]]:
        """The trainee's orders to the ship: helm, telegraph, autopilot and its course (a vessel on station: her
        heading)."""
        sim = self.scene.sim
        ship, c, orders = sim.vessel.ship, sim.conning(), sim.voyage.orders  # the orders given, not yet answered too

        def order(**fields) -> Callable[[], None]:
            return lambda: self._act("order", **fields)

        course = math.degrees(orders.course) % 360.0 if orders.autopilot else c["heading_deg"]

        def steer(step: float) -> Callable[[], None]:
            return order(course_deg=round((course + step) % 360.0, 6))

        if ship.kind == "station":
            keys = {"LEFT": steer(-HELM_STEP_DEG), "RIGHT": steer(HELM_STEP_DEG)}
            if sim.station is not None:  # the instructor's faults on a vessel on DP or moorings
                keys["L"] = self.next_fault
                if ship.dp is not None:
                    keys["Q"] = order(fault="reference drift")
                    keys |= self._set_point_keys(order, orders)
            return keys
        hard = math.degrees(ship.steering.max_angle)
        rudder = math.degrees(orders.rudder) if not orders.autopilot else c["rudder_order_deg"]

        def helm(step: float) -> Callable[[], None]:
            return order(rudder_deg=round(max(min(rudder + step, hard), -hard), 6))

        def telegraph(steps: int) -> Callable[[], None]:
            return order(engine=ship.engine.step(orders.engine, steps, orders.rps))

        small, large = COURSE_STEPS_DEG
        return {"LEFT": helm(-HELM_STEP_DEG), "RIGHT": helm(HELM_STEP_DEG), "X": order(rudder_deg=0.0),
                "Z": order(rudder_deg=-hard), "V": order(rudder_deg=hard),
                "UP": telegraph(1), "DOWN": telegraph(-1),
                "P": order(autopilot=not orders.autopilot),
                "U": steer(-small), "I": steer(small), "_9": steer(-large), "_0": steer(large)}

    def _set_point_keys(self, order, orders) -> dict[str, Callable[[], None]]:
        """The DP operator's set point moved :data:`SET_POINT_STEP_M` ahead or astern (UP/DOWN) and to port or
        starboard (Z/V) of her heading set point."""
        psi = orders.course

        def move(ahead: float, starboard: float) -> Callable[[], None]:
            north = orders.north + ahead * math.cos(psi) - starboard * math.sin(psi)
            east = orders.east + ahead * math.sin(psi) + starboard * math.cos(psi)
            return order(set_north_m=round(north, 6), set_east_m=round(east, 6))

        step = SET_POINT_STEP_M
        return {"UP": move(step, 0.0), "DOWN": move(-step, 0.0), "Z": move(0.0, -step), "V": move(0.0, step)}

    def next_fault(self) -> None:
        """The instructor fails the next thruster still working (a vessel on DP) or parts the next line still
        holding (moored)."""
        sim = self.scene.sim
        ship, faults = sim.voyage.ship, sim.voyage.orders.faults
        names = ([f"thruster:{t.name}" for t in ship.thrusters.units] if ship.thrusters is not None
                 else [f"line:{name}" for name in ship.line_names])
        left = [name for name in names if name not in faults]
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

    def start_message(self) -> None:
        self.typing, self._opened_now = "", True

    def toggle_binoculars(self) -> None:
        """On the bridge: raise the binoculars to the eye, or lower them."""
        if self.scene.camera_name != "bridge":
            self.say("binoculars: on the bridge (key 2)")
            return
        self.scene.cameras["bridge"].binoculars = not self.scene.cameras["bridge"].binoculars

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

    def _scale_time(self, direction: int) -> None:
        self.time_scale_index = int(np.clip(self.time_scale_index + direction, 0, len(TIME_SCALES) - 1))
        self.exercise.note("time_scale", scale=self.time_scale)

    def seek(self, t: float) -> None:
        """A replay's clock to ``t`` (s, within the session): forward through the log, back by starting again."""
        replay = self.scene.replay
        t = min(max(t, 0.0), replay.log.end_s)
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
        mode = "   REPLAY" if self.scene.replay is not None else ""
        lines = [f"{state}{recording}{mode}   H: help"]
        if self.typing is not None:
            lines.append(f"message: {self.typing}_   (ENTER send, ESC cancel)")
        return lines + ([self.message] if self.message and self.message_age_s < MESSAGE_S else [])

    def slider(self) -> Slider | None:
        """A replay's time slider: where the clock is in the session, its events and alarms marked."""
        replay = self.scene.replay
        if replay is None:
            return None
        end = max(replay.log.end_s, 1e-9)
        marks = [(entry["t"] / end, LEVEL_COLORS["exceeded"] if entry["kind"] == "alarm" else MESSAGE_COLOR)
                 for entry in replay.log.entries if entry["kind"] in ("event", "alarm")]
        return Slider(self.scene.sim.time / end, marks,
                      f"replay {self.scene.sim.time:7.1f} / {replay.log.end_s:.1f} s   "
                      "LEFT/RIGHT -/+30 s  HOME start  click: seek")


HELP = [
    "marinesim viewer",
    "",
    "ENTER          acknowledge the alarms",
    "N              instructor: trigger the next scripted event now",
    "M              instructor: type a message (ENTER sends, ESC cancels)",
    "mouse drag     turn the view        scroll   zoom (orbit, bridge), fly (free)",
    "1 / 2 / 3      orbit / bridge / free camera      B   binoculars (bridge, 7x)",
    "W A S D E C    fly the free camera (forward, left, back, right, up, down)",
    "SPACE          freeze / resume      + / -    time faster / slower",
    "[ / ]          wave height down / up (x1.1, over 10 s)",
    ", / .          wave period down / up (x1.05)",
    "; / '          waves turn anticlockwise / clockwise 15 deg",
    "LEFT / RIGHT   helm 5 deg to port / starboard (hand steering; on station: heading 5 deg)",
    "Z / X / V      hard a-port / midships / hard a-starboard",
    "UP / DOWN      telegraph one step ahead / astern (full ahead ... stop ... full astern)",
    "P              autopilot on (holds the heading) / off (hand steering)",
    "U / I  9 / 0   autopilot course 1 / 10 deg to port / starboard",
    "F / G          instructor: fog thickens / lifts (visibility / 2, x 2)",
    "J / K          instructor: cloud cover -/+ 1 okta    Y / T   clock -/+ 1 h (scenarios with time_utc)",
    "O              instructor: rain none / light / heavy / violent showers",
    "UP/DOWN Z/V    on DP: set point 1 m ahead / astern, to port / starboard",
    "L / Q          instructor (DP, moorings): next thruster lost or line parted / position reference drifts",
    "R              start / stop recording the motions (CSV, as marinesim export)",
    "TAB            HUD: compact strip / full panels (motions, charts, every criterion)",
    "H              this help            ESC      quit",
]
