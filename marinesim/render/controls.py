"""The viewer's live controls: keys and mouse to actions on a scene, and the motion recorder.

Kept apart from the window so that they act the same in a test as at the keyboard: a key is
named as pyglet names it (``pyglet.window.key.symbol_string``), e.g. ``"BRACKETRIGHT"``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from marinesim.atomic import AtomicFile
from marinesim.constants import KNOT
from marinesim.errors import MarinesimError
from marinesim.render.scene import Scene
from marinesim.scenario.model import MAX_SPEED_KN
from marinesim.session.export import write_csv_block
from marinesim.session.timeline import CHANGE_RAMP_S

HS_STEP = 1.1       # each press: heights x 1.1 (or / 1.1)
TP_STEP = 1.05      # periods x 1.05
TURN_STEP_DEG = 15.0
SPEED_STEP_KN = 1.0
HEADING_STEP_DEG = 5.0
TIME_SCALES = (0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0)
FREE_SPEED_M_S = 40.0
MAX_FRAME_S = 0.1
"""A frame never advances the simulation by more than this (s of wall time): after a stall or a
paused debugger the ship does not jump, and the solver is not asked to catch up minutes."""


class Recorder:
    """Motion rows at the scenario's dt, from start to stop, written as ``marinesim export`` writes
    them. Rows go to a temporary file beside ``path``, renamed to ``path`` on :meth:`stop`."""

    def __init__(self, scene: Scene, path: Path) -> None:
        self.scene, self.path = scene, Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._file = AtomicFile(self.path)
        self._handle = self._file.temp.open("w", encoding="utf-8", newline="")
        self._dt = scene.sim.scenario.run.dt_s
        self._next = math.ceil(scene.sim.time / self._dt - 1e-9)  # index of the next row's time
        self.rows = 0

    def catch_up(self) -> None:
        """Write the rows up to the simulation's time."""
        last = math.floor(self.scene.sim.time / self._dt + 1e-9)
        if last < self._next:
            return
        times = np.arange(self._next, last + 1) * self._dt
        write_csv_block(self._handle, self.scene.sim.frame(times), header=self.rows == 0)
        self.rows += len(times)
        self._next = last + 1

    def stop(self) -> Path:
        self.catch_up()
        self._handle.close()
        return self._file.commit()

    def abandon(self) -> None:
        """Close and delete the temporary file, keeping nothing (writing it failed)."""
        self._handle.close()
        self._file.discard()


@dataclass
class Controls:
    """What the keys do to ``scene``; ``recordings`` is where recordings go."""

    scene: Scene
    recordings: Path = Path("recordings")
    paused: bool = False
    time_scale_index: int = TIME_SCALES.index(1.0)
    show_help: bool = False
    recorder: Recorder | None = None
    message: str = ""

    @property
    def time_scale(self) -> float:
        return TIME_SCALES[self.time_scale_index]

    def frame(self, wall_dt: float, held: set[str] = frozenset()) -> None:
        """One frame of ``wall_dt`` seconds: move the free camera for held keys, advance the run."""
        wall_dt = min(max(wall_dt, 0.0), MAX_FRAME_S)
        if self.scene.camera_name == "free":
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

    def press(self, key: str) -> None:
        """React to the key named ``key``; unknown keys do nothing."""
        action = self.actions().get(key)
        if action is not None:
            try:
                action()
            except MarinesimError as error:  # e.g. a period change the ocean's tiles cannot carry
                self.message = str(error)

    def actions(self) -> dict[str, Callable[[], None]]:
        sim = self.scene.sim

        def change(**kwargs) -> Callable[[], None]:
            return lambda: sim.change(ramp_s=CHANGE_RAMP_S, **kwargs)

        def camera(name: str) -> Callable[[], None]:
            return lambda: setattr(self.scene, "camera_name", name)

        actions = {
            "H": self.toggle_help, "SPACE": self.toggle_pause, "R": self.toggle_recording,
            "1": camera("orbit"), "2": camera("bridge"), "3": camera("free"),
            "PLUS": lambda: self._scale_time(1), "EQUAL": lambda: self._scale_time(1),
            "MINUS": lambda: self._scale_time(-1),
            "BRACKETRIGHT": change(hs_factor=HS_STEP), "BRACKETLEFT": change(hs_factor=1.0 / HS_STEP),
            "PERIOD": change(tp_factor=TP_STEP), "COMMA": change(tp_factor=1.0 / TP_STEP),
            "APOSTROPHE": change(turn_waves_deg=TURN_STEP_DEG), "SEMICOLON": change(turn_waves_deg=-TURN_STEP_DEG),
        }
        if sim.vessel is not None:
            actions |= {
                "UP": lambda: sim.change(speed_kn=min(sim.speed_m_s / KNOT + SPEED_STEP_KN, MAX_SPEED_KN),
                                         ramp_s=CHANGE_RAMP_S),
                "DOWN": lambda: sim.change(speed_kn=max(sim.speed_m_s / KNOT - SPEED_STEP_KN, 0.0),
                                           ramp_s=CHANGE_RAMP_S),
                "RIGHT": change(heading_deg=sim.heading_deg + HEADING_STEP_DEG),
                "LEFT": change(heading_deg=sim.heading_deg - HEADING_STEP_DEG),
            }
        return actions

    def toggle_help(self) -> None:
        self.show_help = not self.show_help

    def toggle_pause(self) -> None:
        self.paused = not self.paused

    def _scale_time(self, direction: int) -> None:
        self.time_scale_index = int(np.clip(self.time_scale_index + direction, 0, len(TIME_SCALES) - 1))

    def toggle_recording(self) -> None:
        if self.recorder is None:
            if self.scene.sim.vessel is None:
                self.message = "nothing to record: the scenario has no vessel"
                return
            name = f"{self.scene.sim.scenario.name}_{self.scene.sim.time:08.1f}s.csv"
            self.recorder = Recorder(self.scene, self.recordings / name)
            self.message = f"recording to {self.recorder.path}"
        else:
            recorder, self.recorder = self.recorder, None
            try:
                path = recorder.stop()
                self.message = f"recorded {recorder.rows} rows to {path}"
            except OSError as error:  # a full disk must not end the session
                recorder.abandon()
                self.message = f"the recording could not be written: {error}"

    def status(self) -> list[str]:
        state = "PAUSED" if self.paused else f"time x{self.time_scale:g}"
        recording = f"   REC {self.recorder.rows} rows" if self.recorder else ""
        lines = [f"{state}{recording}   H: help"]
        return lines + ([self.message] if self.message else [])


HELP = [
    "marinesim viewer",
    "",
    "mouse drag     turn the view        scroll   zoom (orbit), fly (free)",
    "1 / 2 / 3      orbit / bridge / free camera",
    "W A S D E C    fly the free camera (forward, left, back, right, up, down)",
    "SPACE          pause                + / -    time faster / slower",
    "[ / ]          wave height down / up (x1.1, over 10 s)",
    ", / .          wave period down / up (x1.05)",
    "; / '          waves turn anticlockwise / clockwise 15 deg",
    "UP / DOWN      speed +/- 1 kn       LEFT / RIGHT   heading -/+ 5 deg",
    "R              start / stop recording the motions (CSV, as marinesim export)",
    "H              this help            ESC      quit",
]
