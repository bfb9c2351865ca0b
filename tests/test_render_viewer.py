"""The viewer window through pyglet's headless EGL mode: keys (pyglet's own key symbols and text
events, dispatched to the window), recording, pause, help, the instructor's message and event, the
session log and its replay to the recorder's bytes, redraws.

The walkthrough runs in a fresh Python process: moderngl finds pyglet's headless EGL context only
in a process that has made no other context (the rest of the suite makes many), so the test runs
this file as a script and reads its verdict (exit 0, 77 = no headless window here, else the error).
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from conftest import DEFAULT
from marinesim.cli import main
from marinesim.gl import GraphicsError
from marinesim.render.controls import CHANGE_RAMP_S, HS_STEP, MAX_FRAME_S
from marinesim.scenario import load_scenario
from marinesim.session.replay import replay_session

NO_WINDOW = 77


@pytest.mark.slow
def test_an_operator_session_records_changes_the_sea_and_pauses(tmp_path):
    result = subprocess.run([sys.executable, __file__, str(tmp_path)], capture_output=True, text=True, timeout=600)
    if result.returncode == NO_WINDOW:
        pytest.skip(f"no headless pyglet window: {result.stdout.strip()}")
    assert result.returncode == 0, result.stderr[-3000:]


def walkthrough(tmp_path: Path) -> None:
    from marinesim.render.viewer import NoDisplay, Viewer

    scenario = load_scenario(DEFAULT)
    try:
        viewer = Viewer(scenario, size=(320, 180), headless=True)
    except (NoDisplay, GraphicsError) as error:  # no EGL here: nothing to test
        print(error)
        sys.exit(NO_WINDOW)
    import pyglet

    key = pyglet.window.key
    controls, sim = viewer.controls, viewer.scene.sim
    controls.recordings = tmp_path
    viewer.log_path = tmp_path / "session.jsonl"

    def press(symbol: int, text: str | None = None) -> None:
        """A key as the window gets it: the press, then its text (as pyglet sends both), queued and then
        dispatched by the window as its event loop does."""
        viewer.window.dispatch_event("on_key_press", symbol, 0)
        if text is not None:
            viewer.window.dispatch_event("on_text", text)
        viewer.window.dispatch_event("on_key_release", symbol, 0)
        viewer.window.dispatch_events()

    def type_text(text: str) -> None:
        for char in text:
            viewer.window.dispatch_event("on_text", char)
        viewer.window.dispatch_events()

    try:
        press(key.R, "r")                                 # record from t = 0
        for _ in range(30):
            viewer.tick(0.1)
        viewer.draw()
        press(key.R, "r")
        recorded = pd.read_csv(next(tmp_path.glob("*.csv")))
        assert main(["export", str(DEFAULT), "--out", str(tmp_path / "export.out"), "--duration", "3",
                     "--quiet"]) == 0
        exported = pd.read_csv(tmp_path / "export.out")
        assert list(recorded.columns) == list(exported.columns)
        assert len(recorded) == len(exported) == 31
        np.testing.assert_allclose(recorded.to_numpy(), exported.to_numpy(), rtol=1e-9, atol=1e-9)
        assert not list(tmp_path.glob(".*")), "the recording left its temporary file"

        hs = sim.sea.hs
        conning = viewer.scene.conning_line()
        assert conning.startswith("HDG 260.0  AUTO 260.0  RUD mid  ROT +0/min") and "(for 4.0 kn)" in conning, conning
        assert "TAB: panels" in "   ".join(viewer.scene.strip_lines(3840))  # the window says what its keys do
        press(key.R, "r")                                 # record the rest of the session
        press(key.BRACKETRIGHT, "]")                      # waves up by 10 % over CHANGE_RAMP_S
        press(key.RIGHT)                                  # the helm 5 deg to starboard: hand steering, at once
        press(key.UP)                                     # the telegraph a notch up: dead slow ahead
        viewer.tick(0.1)
        assert sim.voyage.orders.rudder == pytest.approx(np.radians(5.0)) and not sim.voyage.orders.autopilot
        for _ in range(int(2.2 * CHANGE_RAMP_S / MAX_FRAME_S)):
            viewer.tick(5.0)                               # a stalled frame still advances only 0.1 s
        assert sim.time == pytest.approx(2.2 * CHANGE_RAMP_S + 3.1, abs=1e-6)
        assert sim.sea.hs == pytest.approx(HS_STEP * hs, rel=1e-9)  # the sea changed beside the orders
        conning = viewer.scene.conning_line()
        assert "HAND  RUD 5S" in conning and "DEAD SLOW AHEAD" in conning, conning
        rot = sim.conning()["rate_of_turn_deg_min"]
        assert rot > 0.0 and sim.conning()["heading_deg"] > 260.0  # she swings to starboard, at her own rate
        start_rpm = 60.0 * scenario.vessel.ship.rps_for_speed(4.0 * 0.514444)
        lag = np.exp(-(sim.time - 3.0) / 20.0)             # the telegraph at 3 s, the engine's 20 s time constant
        assert sim.conning()["rpm"] == pytest.approx(0.35 * 105.0 + (start_rpm - 0.35 * 105.0) * lag, rel=1e-3)
        press(key.P, "p")                                 # the autopilot on: it holds the heading of the moment
        held = sim.conning()["heading_deg"]
        press(key.I, "i")                                 # and a degree to starboard
        viewer.tick(0.1)
        assert sim.conning()["course_deg"] == pytest.approx(round(held + 1.0, 6) % 360.0, abs=1e-6)
        assert "AUTO" in viewer.scene.conning_line()

        press(key.SPACE, " ")
        before = sim.time
        viewer.tick(0.1)
        assert sim.time == before, "paused, the simulation must not move"
        press(key.SPACE, " ")

        viewer.scene.clock.restart()                      # a window drawing 2.5 frames/s at "time x1"
        for i in range(4):
            viewer.tick(0.4)
            viewer.draw(wall_s=1000.0 + 0.4 * i)
        lines = viewer.scene.hud_lines()
        clock_line = next(line for line in lines if line.startswith("camera"))
        assert any(line.startswith("time x1 ") for line in lines)
        assert "frame 400.0 ms (   2 frames/s)   real time x0.25" in clock_line, clock_line  # 0.1 s a frame

        cameras = []
        for symbol, text in ((key._2, "2"), (key.H, "h"), (key._3, "3"), (key.W, "w"), (key._1, "1")):
            press(symbol, text)
            cameras.append(viewer.scene.camera_name)
            viewer.tick(0.05)
            viewer.draw()
            assert viewer.ctx.error == "GL_NO_ERROR"
        assert cameras == ["bridge", "bridge", "free", "free", "orbit"] and controls.show_help

        assert not viewer.scene.panels and not viewer.scene.charts(), "the HUD opens as the compact strip"
        press(key.TAB, "\t")                               # the full panels: text block, charts, criteria
        assert viewer.scene.panels and len(viewer.scene.charts()) == 3
        viewer.draw()
        press(key.TAB, "\t")
        assert not viewer.scene.panels
        viewer.scene.hud_shown = False                    # --hud off: TAB brings the strip back
        press(key.TAB, "\t")
        assert viewer.scene.hud_shown and not viewer.scene.panels

        press(key._2, "2")                                # on the bridge, binoculars up: 7 times larger
        naked = viewer.scene.camera.eye(sim.pose()).fov_y_deg
        press(key.B, "b")
        raised = viewer.scene.camera.eye(sim.pose()).fov_y_deg
        assert np.tan(np.radians(naked / 2)) / np.tan(np.radians(raised / 2)) == pytest.approx(7.0)
        press(key.B, "b")
        press(key._1, "1")
        assert viewer.scene.camera.eye(sim.pose()).fov_y_deg != raised

        clear = sim.environment
        press(key.F, "f")                                 # the instructor: fog thickens, a cloud comes
        press(key.F, "f")
        press(key.K, "k")
        press(key.O, "o")                                 # a rain shower
        press(key.T, "t")                                 # the default's sun is fixed: said, nothing changes
        assert sim.environment.visibility_m == clear.visibility_m / 4 and sim.environment.cloud_cover_oktas == 1
        assert sim.environment.rain_mm_h == 2.5
        assert "only a time_utc moves it" in controls.message
        press(key.NUM_ADD)                                # the keypad's + and - scale time as + and - do
        assert controls.time_scale == 2.0
        press(key.NUM_SUBTRACT)
        assert controls.time_scale == 1.0
        viewer.tick(0.1)
        assert any("only a time_utc" in line for line in viewer.scene.status)
        viewer.tick(9.0)                                  # 9 s of wall time later the message has gone
        assert not any("only a time_utc" in line for line in viewer.scene.status)

        press(key.M, "m")                                 # the instructor types a message
        type_text("Fog ahead")
        press(key.BACKSPACE)
        press(key.ESCAPE)                                 # ESC while typing cancels the message only
        assert controls.typing is None and viewer.window.has_exit is False
        press(key.M, "m")
        type_text("Fog ahead")
        press(key.RETURN, "\r")
        viewer.tick(0.1)
        assert viewer.scene.exercise.said[-1][1] == "Fog ahead"
        assert any("instructor: Fog ahead" in m for m in viewer.scene.exercise.messages())
        viewer.draw()
        for _ in range(7):
            viewer.tick(0.1)
        environment = sim.environment
    finally:
        viewer.close()
    session = tmp_path / "session.jsonl"
    lines = [json.loads(line) for line in session.read_text().splitlines()[1:]]
    keys = [e["key"] for e in lines if e["kind"] == "key"]
    assert keys[:7] == ["R", "R", "R", "BRACKETRIGHT", "RIGHT", "UP", "P"] and "RETURN" not in keys  # typing keys are the message's
    actions = [e for e in lines if e["kind"] == "action"]
    assert [e["action"] for e in actions] == ["change", "order", "order", "order", "order", "weather", "weather",
                                              "weather", "weather", "message"]
    assert [{k: v for k, v in e.items() if k not in ("t", "kind", "action")} for e in actions[1:5]] == [
        {"rudder_deg": 5.0}, {"engine": "dead slow ahead"}, {"autopilot": True},
        {"course_deg": pytest.approx(round(held + 1.0, 6) % 360.0)}]
    again = replay_session(session)
    assert again.sim.environment == environment, "the replay's weather is not the session's"
    recording = sorted(tmp_path.glob(f"{scenario.name}_*.csv"))[-1]  # the second: from t = 3 s to the end
    assert main(["replay", str(session), "--export", str(tmp_path / "replayed.csv"), "--quiet"]) == 0
    recorded, replayed = recording.read_text().splitlines(), (tmp_path / "replayed.csv").read_text().splitlines()
    assert recorded[0] == replayed[0] and recorded[1:] == replayed[31:], "the replay's rows are not the recording's"


if __name__ == "__main__":
    walkthrough(Path(sys.argv[1]))
