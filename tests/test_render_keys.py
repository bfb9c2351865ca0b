"""The viewer's keymap is one table: docs/USAGE.md's key table is the one generated from it, every binding names a
key pyglet sends and a method of the controls, and the controls on real scenes (a ship, a vessel on station, on
moorings, on DP, with a crane, with a helicopter coming, a replay; a real EGL context) act on exactly the keys the
table binds there, and the help overlay shows each of them."""

from __future__ import annotations

import inspect
import json
import re
import subprocess
import sys

import pytest

from conftest import DEFAULT, HANG_S, ROOT
from marinesim.render.keys import CONTEXTS, KEYMAP, bindings, dispatch, help_lines, with_reference

USAGE = ROOT / "docs" / "USAGE.md"
SESSIONS = {
    "ship": {"always", "own_clock", "free", "live", "instructor", "typing", "ship"},
    "station": {"always", "own_clock", "free", "live", "instructor", "typing", "station"},
    "moored": {"always", "own_clock", "free", "live", "instructor", "typing", "station", "faults"},
    "dp": {"always", "own_clock", "free", "live", "instructor", "typing", "station", "faults", "dp", "dp_faults"},
    "replay": {"always", "own_clock", "free", "replay"},
    "station of a served exercise": {"always", "free", "live", "follow", "typing", "ship"},
    "crane": {"always", "own_clock", "free", "live", "instructor", "typing", "station", "faults", "dp", "dp_faults",
              "crane"},
    "helicopter": {"always", "own_clock", "free", "live", "instructor", "typing", "station", "faults", "dp",
                   "dp_faults", "helicopter"},
}
"""The contexts each kind of session can be in (``Controls.session_contexts``; a station's in tests/test_net_station.py)."""
SCENES = {"ship": DEFAULT, "station": ROOT / "configs" / "semisub_swell.toml",
          "moored": ROOT / "configs" / "semisub_moored.toml", "dp": ROOT / "configs" / "supply_dp.toml",
          "replay": DEFAULT, "crane": ROOT / "configs" / "training" / "crane_lift.toml",
          "helicopter": ROOT / "configs" / "training" / "helideck_landing.toml"}


def test_the_docs_key_table_is_the_generated_one():
    """If this fails, the keymap (marinesim/render/keys.py) changed and docs/USAGE.md's key table was not written
    again: run ``python -m marinesim.render.keys docs/USAGE.md``."""
    text = USAGE.read_text(encoding="utf-8")
    assert text == with_reference(text), "run: python -m marinesim.render.keys docs/USAGE.md"


@pytest.fixture(scope="module")
def pyglet_keys() -> set[str]:
    """Every key name a pyglet window sends (``symbol_string`` of its key symbols), asked of pyglet in a process
    of its own: pyglet's window module makes a context when imported, which the rest of the suite must not see."""
    script = ("import json, pyglet; pyglet.options['headless'] = True; from pyglet.window import key; "
              "print(json.dumps(sorted({key.symbol_string(v) for n, v in vars(key).items() "
              "if n == n.upper() and isinstance(v, int) and not n.startswith(('_' * 2, 'MOD_', 'MOTION_'))})))")
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=HANG_S)
    assert result.returncode == 0, result.stderr[-2000:]
    return set(json.loads(result.stdout))


def test_every_binding_names_a_key_pyglet_sends_and_a_method_of_the_controls(pyglet_keys):
    """A key name pyglet never sends (``RETURN``: pyglet calls it ``ENTER``) would be listed and do nothing; an
    action the controls lack, or whose arguments it does not take, would fail at the keyboard."""
    from marinesim.render.controls import Controls

    assert len(pyglet_keys) > 100
    for group, binding, when in bindings():
        assert set(binding.keys) <= pyglet_keys, f"{binding.keys} ({binding.words}): not keys pyglet sends"
        assert when in CONTEXTS and binding.words and group.title
        method = getattr(Controls, binding.action, None)
        assert callable(method), f"{binding.action} ({binding.words}) is no method of the controls"
        inspect.signature(method).bind(None, *((0.1,) if binding.held else ()), *binding.args)


@pytest.mark.parametrize("kind", sorted(SESSIONS))
def test_no_key_is_bound_twice_where_it_acts(kind):
    """In each state a session can be in (typing a message or not, the free camera or not), a key calls one
    binding at most."""
    base = SESSIONS[kind] - {"typing", "free"}
    for contexts in (base, base | {"free"}, {"typing"}):
        for held in (False, True):
            keys = [key for _, b, _ in bindings(contexts) if b.held == held for key in b.keys]
            assert len(keys) == len(set(keys)), f"{kind} {sorted(contexts)}: {sorted(keys)}"


def test_the_help_shows_every_binding_and_fits_the_window():
    """Over the kinds of session the help has every binding's words; each session's help fits a 1280 x 720
    window at the HUD's font (DejaVu Sans Mono, 14 px: 9 px a character, 17 px a line)."""
    shown = "\n".join(line for contexts in SESSIONS.values() for line in help_lines(contexts))
    missing = [binding.words for _, binding, _ in bindings() if binding.words not in shown]
    assert not missing, missing
    for kind, contexts in SESSIONS.items():
        lines = help_lines(contexts)
        assert max(map(len, lines)) * 9 + 24 <= 1280 and len(lines) * 17 + 24 <= 720, (kind, lines)


def _state(controls, calls: list) -> tuple:
    """What a key may change: the journal (less the key notes), the controls' and the scene's settings, the
    clock, what the controls asked of the window."""
    scene = controls.scene
    journal = [entry for entry in scene.exercise.journal if entry["kind"] != "key"]
    return (len(journal), controls.show_help, controls.paused, controls.time_scale_index, controls.typing,
            controls.message, controls.recorder is not None, scene.camera_name, scene.panels, scene.hud_shown,
            scene.radar_shown, scene.radar_scale_nm, scene.cameras["bridge"].binoculars,
            scene.cameras["free"].position, scene.sim.time, len(calls))


@pytest.fixture(scope="module", params=sorted(SCENES))
def session(request, gl_context, tmp_path_factory):
    """(kind, controls on a real scene of that kind, the calls the controls made to the window)."""
    from marinesim.render.controls import Controls
    from marinesim.render.renderer import RenderOptions
    from marinesim.render.scene import Scene
    from marinesim.scenario import load_scenario
    from marinesim.session.log import read_log, write_log
    from marinesim.session.replay import Replay

    kind, folder = request.param, tmp_path_factory.mktemp(request.param)
    scenario = load_scenario(SCENES[kind])
    options = RenderOptions(wake=False, foam=False, spray=False, vessel=False)
    scene = Scene(gl_context, scenario, options=options)
    calls: list = []
    if kind == "replay":  # a 20 s session, replayed from 10 s
        scene.exercise.advance(20.0)
        scene.exercise.note("end")
        log = read_log(write_log(folder / "session.jsonl", scene.exercise))
        scene.release()
        scene = Scene(gl_context, scenario, options=options)
        scene.replay = Replay(scene.exercise, log.actions(), log)
    controls = Controls(scene, recordings=folder, restart=lambda t: calls.append(("restart", t)),
                        on_quit=lambda: calls.append(("quit",)))
    if kind == "replay":
        controls.seek(10.0)
    yield kind, controls, calls
    if controls.recorder is not None:
        controls.toggle_recording()
    scene.release()


def test_the_controls_act_on_exactly_the_keys_the_table_binds(session, pyglet_keys):
    """Every key pyglet sends, pressed on the scene: those that change something (the journal, a setting, the
    clock, the window) are the keys the table binds in this session, once from the orbit and, where that
    changed nothing, from the bridge camera (1 and 2 pick the camera they are on). Then the same while a message
    is typed (only the message's keys act), and each key held a frame with the free camera (its keys fly it)."""
    kind, controls, calls = session
    assert controls.session_contexts() == SESSIONS[kind]

    def acts(key: str, typing: str | None, camera: str) -> bool:
        controls.typing, controls.message, controls.paused = typing, "", False
        controls.time_scale_index = 3
        controls.scene.camera_name = camera
        before = _state(controls, calls)
        controls.press(key)
        return _state(controls, calls) != before

    acting = {key for key in sorted(pyglet_keys) if acts(key, None, "orbit") or acts(key, None, "bridge")}
    assert acting == set(dispatch(SESSIONS[kind] - {"typing", "free"})), kind
    if "typing" in SESSIONS[kind]:
        typed = {key for key in sorted(pyglet_keys) if acts(key, "abc", "orbit")}
        assert typed == set(dispatch({"typing"})) == {"ENTER", "ESCAPE", "BACKSPACE"}
    controls.typing, controls.paused, controls.scene.camera_name = None, True, "free"
    flying = set()
    for key in sorted(pyglet_keys):
        before = controls.scene.cameras["free"].position
        controls.frame(0.1, {key})
        if controls.scene.cameras["free"].position != before:
            flying.add(key)
    assert flying == set(dispatch(SESSIONS[kind] - {"typing"}, held=True)) == set("WASDEC")


def test_the_help_overlay_shows_each_binding_of_the_session(session):
    """What H shows on this scene: every binding acting in its session, key and words, and no group with nothing
    acting here (a ship's help has no DP set point)."""
    kind, controls, _ = session
    shown = "\n".join(controls.help_lines())
    for group, binding, when in bindings(SESSIONS[kind]):
        pattern = rf"(^|   )  {re.escape(binding.label)} +{re.escape(binding.words)}(   |$)"
        assert re.search(pattern, shown, re.MULTILINE), (kind, binding)
    for group in KEYMAP:
        acting = any(True for g, _, _ in bindings(SESSIONS[kind]) if g is group)
        assert (group.title in shown) == acting, (kind, group.title)


def test_the_generator_writes_the_table_between_the_markers(tmp_path):
    """``python -m marinesim.render.keys FILE`` rewrites only what lies between the markers."""
    page = tmp_path / "page.md"
    page.write_text("before\n<!-- keys:start -->\nstale row\n<!-- keys:end -->\nafter\n", encoding="utf-8")
    result = subprocess.run([sys.executable, "-m", "marinesim.render.keys", str(page)], capture_output=True,
                            text=True, timeout=HANG_S)
    assert result.returncode == 0, result.stderr[-2000:]
    text = page.read_text(encoding="utf-8")
    assert text.startswith("before\n<!-- keys:start -->\n| who | keys |")
    assert text.endswith("<!-- keys:end -->\nafter\n")
    assert "stale row" not in text and text.count("\n| ") == sum(len(g.bindings) for g in KEYMAP) + 1

