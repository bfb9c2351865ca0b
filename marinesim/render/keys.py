"""The viewer's keymap: one table of bindings, grouped by who uses them, from which the controls dispatch a key to
their method (:class:`~marinesim.render.controls.Controls`), the help overlay (H) is written and the key table of
docs/USAGE.md is generated: ``python -m marinesim.render.keys docs/USAGE.md`` rewrites it.

A key is named as pyglet names it (``pyglet.window.key.symbol_string``), e.g. ``"BRACKETRIGHT"``, ``"_1"``. A
binding acts in one context (:data:`CONTEXTS`): a live session or a replay, the kind of vessel, a message being
typed, the free camera; no key is bound twice in the contexts a session is in at once.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

from marinesim.render.camera import BINOCULAR_POWER
from marinesim.scenario.model import CHANGE_RAMP_S

HS_STEP = 1.1
"""[ / ]: wave heights / 1.1 or x 1.1."""
TP_STEP = 1.05
""", / .: wave periods / 1.05 or x 1.05."""
TURN_STEP_DEG = 15.0
"""; / ': the waves turn this much anticlockwise / clockwise."""
HELM_STEP_DEG = 5.0
"""LEFT / RIGHT: the rudder order this much to port / starboard (a vessel on station: her heading)."""
COURSE_STEPS_DEG = (1.0, 10.0)
"""U / I and 9 / 0: the autopilot's course this much to port / starboard."""
SET_POINT_STEP_M = 1.0
"""How far a key moves a DP's position set point (m): the reference model takes her there at 0.3 m/s."""
VISIBILITY_STEP = 2.0
"""F / G: visibility / 2 (fog thickens) or x 2 (it lifts)."""
TIME_STEP_H = 1.0
"""T / Y: the scenario's clock this much on / back (h)."""
RAIN_STEPS_MM_H = (0.0, 2.5, 10.0, 50.0)
"""The instructor's O steps the rain through these: none, light, heavy, violent showers."""
HOIST_STEP_M_S = 0.1
"""PAGE UP / PAGE DOWN: the crane's hoist this much faster up / down (m/s), to its hoist speed."""
SLEW_STEP_DEG_S = 0.5
"""INSERT / DELETE: the crane's slew this much faster to port / starboard (deg/s), to its slew rate."""
SEEK_STEP_S = 30.0
"""A replay's LEFT / RIGHT: back / forward this long (s)."""

CONTEXTS = {
    "always": "always",
    "own_clock": "a session on its own clock (not a station)",
    "free": "the free camera, while held",
    "live": "a live session",
    "instructor": "the instructor at the viewer (not a station)",
    "follow": "a station of a served exercise (run --connect)",
    "typing": "typing a message (M)",
    "ship": "a ship under helm and engine",
    "station": "a vessel held on station",
    "faults": "the instructor, a vessel on DP or moorings",
    "dp": "a vessel on DP",
    "dp_faults": "the instructor, a vessel on DP",
    "crane": "a vessel with a crane ([crane])",
    "helicopter": "a helicopter approaching her helideck ([helicopter])",
    "replay": "a replay",
}
"""Where a binding acts, and the words for it: a session is in several at once (a live DP session: always, live,
station, faults, dp); while a message is being typed only the typing keys act."""

KEY_NAMES = {
    "_0": "0", "_1": "1", "_2": "2", "_3": "3", "_4": "4", "_5": "5", "_6": "6", "_9": "9", "ESCAPE": "ESC",
    "PLUS": "+", "EQUAL": "=", "NUM_ADD": "keypad +", "MINUS": "-", "NUM_SUBTRACT": "keypad -", "BRACKETLEFT": "[",
    "BRACKETRIGHT": "]", "COMMA": ",", "PERIOD": ".", "SEMICOLON": ";", "APOSTROPHE": "'", "PAGEUP": "PAGE UP",
    "PAGEDOWN": "PAGE DOWN",
}
"""What is written on a key whose pyglet name is not it (the rest are written as named)."""

MOUSE = "mouse: drag turns the view, scroll zooms (orbit, bridge) or flies (free camera)"
REPLAY_MOUSE = "a click on the replay's time slider seeks there"


@dataclass(frozen=True)
class Binding:
    """``keys`` (any of them) call the controls' method ``action`` with ``args``, which does what ``words`` say;
    ``when``: the context it acts in (:data:`CONTEXTS`; empty: its group's). A ``held`` key acts each frame while
    it is down (its method also takes the frame's wall time, s, first) instead of once when pressed."""

    keys: tuple[str, ...]
    action: str
    words: str
    args: tuple[float | str, ...] = ()
    when: str = ""
    held: bool = False

    @property
    def label(self) -> str:
        """The keys as written on the keyboard, e.g. ``+ / = / keypad +``."""
        return " / ".join(KEY_NAMES.get(key, key) for key in self.keys)


@dataclass(frozen=True)
class Group:
    """The bindings of one user of the viewer (``name``: the docs' "who"; ``title``: the help's); ``when``: the
    context its bindings act in unless they name their own."""

    name: str
    title: str
    when: str
    bindings: tuple[Binding, ...]

    def contexts(self) -> Iterator[tuple[Binding, str]]:
        """Each binding with the context it acts in."""
        for binding in self.bindings:
            yield binding, binding.when or self.when


KEYMAP = (
    Group("view", "the view and the session", "always", (
        Binding(("H",), "toggle_help", "this help"),
        Binding(("TAB",), "toggle_panels", "HUD: compact strip / full panels and charts"),
        Binding(("SPACE",), "toggle_pause", "freeze / resume", when="own_clock"),
        Binding(("PLUS", "EQUAL", "NUM_ADD"), "scale_time", "time faster", (1,), "own_clock"),
        Binding(("MINUS", "NUM_SUBTRACT"), "scale_time", "time slower", (-1,), "own_clock"),
        Binding(("_1",), "camera", "orbit camera", ("orbit",)),
        Binding(("_2",), "camera", "bridge camera", ("bridge",)),
        Binding(("_3",), "camera", "free camera", ("free",)),
        Binding(("_4",), "next_camera", "the scenario's named cameras in turn ([[cameras]])"),
        Binding(("B",), "toggle_binoculars", f"binoculars up / down (bridge, {BINOCULAR_POWER:g}x)"),
        Binding(("_5",), "toggle_radar", "radar picture of the traffic shown / hidden (HUD)"),
        Binding(("_6",), "radar_range", "radar range: auto, then each standard scale in turn"),
        Binding(("W",), "fly", "free camera: forward", (1.0, 0.0, 0.0), "free", held=True),
        Binding(("S",), "fly", "free camera: back", (-1.0, 0.0, 0.0), "free", held=True),
        Binding(("A",), "fly", "free camera: left", (0.0, -1.0, 0.0), "free", held=True),
        Binding(("D",), "fly", "free camera: right", (0.0, 1.0, 0.0), "free", held=True),
        Binding(("E",), "fly", "free camera: up", (0.0, 0.0, 1.0), "free", held=True),
        Binding(("C",), "fly", "free camera: down", (0.0, 0.0, -1.0), "free", held=True),
        Binding(("R",), "toggle_recording", "start / stop recording the motions (CSV)"),
        Binding(("ESCAPE",), "quit", "quit (a live session writes its log)"),
    )),
    Group("sea", f"the sea (instructor; each change over {CHANGE_RAMP_S:g} s)", "instructor", (
        Binding(("BRACKETRIGHT",), "wave_height", f"wave height up (x {HS_STEP:g})", (1,)),
        Binding(("BRACKETLEFT",), "wave_height", f"wave height down (/ {HS_STEP:g})", (-1,)),
        Binding(("PERIOD",), "wave_period", f"wave period up (x {TP_STEP:g})", (1,)),
        Binding(("COMMA",), "wave_period", f"wave period down (/ {TP_STEP:g})", (-1,)),
        Binding(("APOSTROPHE",), "turn_waves", f"waves turn clockwise {TURN_STEP_DEG:g} deg", (1,)),
        Binding(("SEMICOLON",), "turn_waves", f"waves turn anticlockwise {TURN_STEP_DEG:g} deg", (-1,)),
    )),
    Group("exercise", "the exercise", "live", (
        Binding(("ENTER",), "acknowledge", "acknowledge the alarms"),
        Binding(("N",), "trigger_next", "instructor: the next scripted event now", when="instructor"),
        Binding(("M",), "start_message", "instructor: type a message", when="instructor"),
        Binding(("M",), "start_message", "station: type a report to the instructor", when="follow"),
        Binding(("ENTER",), "send_message", "typing a message: send it", when="typing"),
        Binding(("ESCAPE",), "cancel_message", "typing a message: drop it", when="typing"),
        Binding(("BACKSPACE",), "erase", "typing a message: rub out a character", when="typing"),
    )),
    Group("instructor", "the instructor: weather and faults", "instructor", (
        Binding(("F",), "visibility", f"fog thickens (visibility / {VISIBILITY_STEP:g})", (-1,)),
        Binding(("G",), "visibility", f"fog lifts (visibility x {VISIBILITY_STEP:g})", (1,)),
        Binding(("K",), "clouds", "cloud cover + 1 okta", (1,)),
        Binding(("J",), "clouds", "cloud cover - 1 okta", (-1,)),
        Binding(("T",), "clock", f"clock + {TIME_STEP_H:g} h (a scenario with time_utc)", (1,)),
        Binding(("Y",), "clock", f"clock - {TIME_STEP_H:g} h", (-1,)),
        Binding(("O",), "rain", "rain: none / light / heavy / violent showers"),
        Binding(("L",), "next_fault", "next thruster lost (DP) or line parted", when="faults"),
        Binding(("Q",), "drift_reference", "the position reference drifts (DP)", when="dp_faults"),
    )),
    Group("ship", "the ship (trainee): helm, telegraph, autopilot", "ship", (
        Binding(("LEFT",), "helm", f"helm {HELM_STEP_DEG:g} deg to port (hand steering)", (-1,)),
        Binding(("RIGHT",), "helm", f"helm {HELM_STEP_DEG:g} deg to starboard (hand steering)", (1,)),
        Binding(("Z",), "rudder_hard", "hard a-port", (-1,)),
        Binding(("X",), "rudder_hard", "midships", (0,)),
        Binding(("V",), "rudder_hard", "hard a-starboard", (1,)),
        Binding(("UP",), "telegraph", "telegraph one step ahead", (1,)),
        Binding(("DOWN",), "telegraph", "telegraph one step astern", (-1,)),
        Binding(("P",), "toggle_autopilot", "autopilot on (holds the heading) / off"),
        Binding(("U",), "steer", f"autopilot course {COURSE_STEPS_DEG[0]:g} deg to port", (-COURSE_STEPS_DEG[0],)),
        Binding(("I",), "steer", f"autopilot course {COURSE_STEPS_DEG[0]:g} deg to starboard",
                (COURSE_STEPS_DEG[0],)),
        Binding(("_9",), "steer", f"autopilot course {COURSE_STEPS_DEG[1]:g} deg to port", (-COURSE_STEPS_DEG[1],)),
        Binding(("_0",), "steer", f"autopilot course {COURSE_STEPS_DEG[1]:g} deg to starboard",
                (COURSE_STEPS_DEG[1],)),
    )),
    Group("station", "a vessel on station (trainee): heading, DP set point", "station", (
        Binding(("LEFT",), "steer", f"heading {HELM_STEP_DEG:g} deg to port", (-HELM_STEP_DEG,)),
        Binding(("RIGHT",), "steer", f"heading {HELM_STEP_DEG:g} deg to starboard", (HELM_STEP_DEG,)),
        Binding(("UP",), "move_set_point", f"set point {SET_POINT_STEP_M:g} m ahead", (SET_POINT_STEP_M, 0.0),
                "dp"),
        Binding(("DOWN",), "move_set_point", f"set point {SET_POINT_STEP_M:g} m astern", (-SET_POINT_STEP_M, 0.0),
                "dp"),
        Binding(("Z",), "move_set_point", f"set point {SET_POINT_STEP_M:g} m to port", (0.0, -SET_POINT_STEP_M),
                "dp"),
        Binding(("V",), "move_set_point", f"set point {SET_POINT_STEP_M:g} m to starboard",
                (0.0, SET_POINT_STEP_M), "dp"),
    )),
    Group("crane", "the crane operator: hoist and slew", "crane", (
        Binding(("PAGEUP",), "hoist", f"hoist {HOIST_STEP_M_S:g} m/s faster up (slower down)", (HOIST_STEP_M_S,)),
        Binding(("PAGEDOWN",), "hoist", f"hoist {HOIST_STEP_M_S:g} m/s faster down (slower up)",
                (-HOIST_STEP_M_S,)),
        Binding(("INSERT",), "slew", f"slew {SLEW_STEP_DEG_S:g} deg/s faster to port", (SLEW_STEP_DEG_S,)),
        Binding(("DELETE",), "slew", f"slew {SLEW_STEP_DEG_S:g} deg/s faster to starboard", (-SLEW_STEP_DEG_S,)),
        Binding(("END",), "crane_stop", "crane: stop hoist and slew"),
    )),
    Group("helicopter", "the helideck landing officer: the deck's word to the pilot", "helicopter", (
        Binding(("F1",), "deck_word", "deck GREEN: cleared to land", ("permit",)),
        Binding(("F2",), "deck_word", "deck RED: hold in the hover", ("hold",)),
        Binding(("F3",), "deck_word", "wave off", ("wave_off",)),
    )),
    Group("replay", "a replay", "replay", (
        Binding(("LEFT",), "seek_by", f"back {SEEK_STEP_S:g} s", (-SEEK_STEP_S,)),
        Binding(("RIGHT",), "seek_by", f"forward {SEEK_STEP_S:g} s", (SEEK_STEP_S,)),
        Binding(("HOME",), "seek", "back to the start", (0.0,)),
    )),
)
"""Every key of the viewer, by who uses it."""


def bindings(contexts: Iterable[str] | None = None) -> Iterator[tuple[Group, Binding, str]]:
    """Each binding with its group and context, in the table's order; with ``contexts``, those acting in them."""
    wanted = None if contexts is None else set(contexts)
    for group in KEYMAP:
        for binding, when in group.contexts():
            if wanted is None or when in wanted:
                yield group, binding, when


def dispatch(contexts: Iterable[str], held: bool = False) -> dict[str, Binding]:
    """Key name -> the binding it calls in ``contexts``: those pressed once, or with ``held`` those acting while
    down."""
    return {key: binding for _, binding, _ in bindings(contexts) if binding.held == held for key in binding.keys}


def help_lines(contexts: Iterable[str], columns: int = 2) -> list[str]:
    """The help overlay: the bindings acting in ``contexts``, a block for each group, the blocks in ``columns``
    columns of about equal height."""
    contexts = set(contexts)
    shown = [(group, [b for g, b, _ in bindings(contexts) if g is group]) for group in KEYMAP]
    shown = [(group, found) for group, found in shown if found]
    per_column = -(-sum(len(found) + 2 for _, found in shown) // columns)  # a block: its title, lines, a gap
    stacks: list[list[tuple[Group, list[Binding]]]] = [[]]
    for group, found in shown:
        height = sum(len(f) + 2 for _, f in stacks[-1])
        if stacks[-1] and height + len(found) + 2 > per_column and len(stacks) < columns:
            stacks.append([])
        stacks[-1].append((group, found))
    texts = []
    for stack in stacks:
        width = max((len(binding.label) for _, found in stack for binding in found), default=0)
        texts.append([line for group, found in stack
                      for line in [group.title, *(f"  {b.label:<{width}}  {b.words}" for b in found), ""]])
    cell = max((len(line) for text in texts for line in text), default=0) + 3
    rows = max(map(len, texts))
    lines = ["".join((text[row] if row < len(text) else "").ljust(cell) for text in texts).rstrip()
             for row in range(rows)]
    while lines and not lines[-1]:
        lines.pop()
    mouse = [MOUSE] + ([REPLAY_MOUSE] if "replay" in contexts else [])
    return ["marinesim viewer: the keys", *mouse, "", *lines]


def reference() -> str:
    """Every binding as a markdown table, generated from :data:`KEYMAP` (docs/USAGE.md)."""
    rows = ["| who | keys | what they do | acts in |", "|---|---|---|---|"]
    for group, binding, when in bindings():
        keys = " ".join(f"`{KEY_NAMES.get(key, key)}`" for key in binding.keys)
        rows.append(f"| {group.name} | {keys} | {binding.words} | {CONTEXTS[when]} |")
    return "\n".join(rows) + f"\n\n{MOUSE[0].upper()}{MOUSE[1:]};\n{REPLAY_MOUSE}.\n"


MARKERS = ("<!-- keys:start -->\n", "<!-- keys:end -->")


def with_reference(text: str) -> str:
    """``text`` with what lies between the key table's :data:`MARKERS` replaced by :func:`reference`."""
    start, end = text.index(MARKERS[0]) + len(MARKERS[0]), text.index(MARKERS[1])
    return text[:start] + reference() + text[end:]


if __name__ == "__main__":
    path = Path(sys.argv[1])
    path.write_text(with_reference(path.read_text(encoding="utf-8")), encoding="utf-8")
