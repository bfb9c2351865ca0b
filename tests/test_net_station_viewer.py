"""A station's window (pyglet's headless EGL mode, the viewer ``run --connect`` opens) on a served exercise, driven
with pyglet's own key events: the trainee's helm goes to the server and comes back, the instructor's message to the
station shows, the instructor's keys do nothing there, and the status line names the station.

The window runs in a fresh Python process (as tests/test_render_viewer.py explains: pyglet's EGL context only in a
process that has made no other context); the test reads its verdict (exit 0; 77: no headless window here)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

NO_WINDOW = 77


@pytest.mark.slow
def test_a_station_window_sends_the_helm_and_shows_the_instructors_message(tmp_path):
    result = subprocess.run([sys.executable, __file__, str(tmp_path)], capture_output=True, text=True, timeout=600,
                            cwd=Path(__file__).parent)
    if result.returncode == NO_WINDOW:
        pytest.skip(f"no headless pyglet window: {result.stdout.strip()}")
    assert result.returncode == 0, result.stderr[-3000:]


def walkthrough(tmp_path: Path) -> None:
    from marinesim.gl import GraphicsError
    from marinesim.net.station import Link, Station
    from marinesim.render.viewer import NoDisplay, Viewer
    from marinesim.resources import resource_dir
    from marinesim.scenario import load_scenario, with_run
    from served import WAIT_S, ServedInThread

    scenario = with_run(load_scenario(resource_dir("configs") / "training" / "heavy_weather_transit.toml"), 600.0)
    try:
        viewer = Viewer(scenario, "bridge", "off", size=(320, 180), headless=True, log_path=None)
    except (NoDisplay, GraphicsError) as error:
        print(error)
        sys.exit(NO_WINDOW)
    import pyglet

    key = pyglet.window.key
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=2.0)
    instructor = Link(served.url, {"type": "hello", "role": "instructor"})
    station = viewer.scene.follow = Station.join(viewer.scene.exercise, served.url, "bridge")
    sim = viewer.scene.sim

    def press(symbol: int, text: str | None = None) -> None:
        viewer.window.dispatch_event("on_key_press", symbol, 0)
        if text is not None:
            viewer.window.dispatch_event("on_text", text)
        viewer.window.dispatch_event("on_key_release", symbol, 0)
        viewer.window.dispatch_events()

    def sim_messages() -> list[str]:
        """The messages the station's HUD shows now (its exercise's, to it or to all)."""
        return viewer.scene.exercise.messages(station="bridge")

    def until(condition, what: str) -> None:
        for _ in range(int(WAIT_S / 0.05)):
            if condition():
                return
            station.poll(0.05)
            viewer.tick(0.1)
        raise AssertionError(f"never: {what}")

    try:
        until(lambda: station.joined and sim.time > 2.0, "the station follows the served exercise")
        assert "STATION bridge" in viewer.controls.status()[0]
        hs = sim.sea.hs
        press(key.BRACKETRIGHT, "]")                      # the instructor's key: not bound at a station
        press(key.SPACE, " ")                             # the clock is the server's: no pause here
        assert not viewer.controls.paused
        press(key.RIGHT)                                  # the helm 5 deg to starboard, through the server
        until(lambda: sim.voyage.orders.rudder > 0.0, "the helm order came back and was applied")
        instructor.send({"type": "action", "action": "message", "fields": {"text": "Bridge, report the roll",
                                                                           "to": "bridge"}})
        until(lambda: any("report the roll" in m for m in sim_messages()), "the instructor's message shows")
        press(key.M, "m")                                 # the trainee's report back
        for char in "Rolling 5 deg":
            viewer.window.dispatch_event("on_text", char)
        press(key.ENTER)
        until(lambda: any(e.get("action") == "report" for e in station.journal), "the report reached the server")
        viewer.draw()
    finally:
        instructor.close()
        station.close()
        served.close()
    journal = served.server.exercise.journal
    actions = [e for e in journal if e["kind"] == "action"]
    assert [a["action"] for a in actions] == ["order", "message", "report"], actions
    assert actions[0]["rudder_deg"] == 5.0
    assert actions[2] == actions[2] | {"text": "Rolling 5 deg", "station": "bridge"}
    assert sim.sea.hs == hs  # no sea change from the station's keys
    viewer.close()


if __name__ == "__main__":
    walkthrough(Path(sys.argv[1]))
