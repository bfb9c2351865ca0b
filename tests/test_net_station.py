"""Stations of a served exercise drawing their own pictures (Mesa's OpenGL through EGL): two stations and a standalone
replay of the server's log show the same frame at the same simulated times, the trainee's helm at one station
reaches every station through the server, and a station's keys are the trainee's, not the instructor's."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from conftest import RENDER_SIZE
from marinesim.errors import MarinesimError
from marinesim.net.station import Link, Station
from marinesim.render.controls import Controls
from marinesim.render.offscreen import Offscreen
from marinesim.render.renderer import RenderOptions
from marinesim.resources import resource_dir
from marinesim.scenario import load_scenario, with_run
from marinesim.session.log import read_log
from marinesim.session.replay import Replay
from served import WAIT_S, ServedInThread

TRANSIT = resource_dir("configs") / "training" / "heavy_weather_transit.toml"
OPTIONS = RenderOptions(wake=False, foam=False, spray=False, reproducible=True, hud="off")
"""A picture that is a function of the simulated time alone: the foam and the spray integrate over the frames a
window happened to draw (a station draws as its wall clock lets it), the wake is computed in the background."""
STEPS_S = (0.1, 0.37)
"""The two stations step at these (wall) intervals, as two machines of different speeds would."""


def _view(scenario) -> Offscreen:
    from marinesim.gl import GraphicsError

    try:
        return Offscreen(scenario, RENDER_SIZE, "bridge", "off", OPTIONS)
    except GraphicsError as error:
        pytest.skip(f"no EGL OpenGL 4.3 here: {error}")


def _follow(view: Offscreen, dt: float, until) -> None:
    """Step ``view``'s station by ``dt`` until ``until(station)`` (the server's messages arrive on their own thread)."""
    station = view.scene.follow
    for _ in range(int(WAIT_S / 0.05)):
        if until(station):
            return
        station.poll(0.05)
        view.scene.step(dt)
    raise AssertionError("the station never got there")


def test_two_stations_and_a_replay_draw_the_same_frames(tmp_path):
    """The bridge's helm (a key at one station) and the instructor's sea change reach both stations through the
    server; frozen at a time and at the end, both stations' frames equal, pixel for pixel, a standalone replay's of
    the server's log at that time. A station that applied an order at another time, or drew another sea, would
    show its trainee a ship the instructor and the debrief do not see."""
    scenario = with_run(load_scenario(TRANSIT), 600.0)  # stopped by the test, however slow the machine
    views = [_view(scenario) for _ in STEPS_S]  # drawn before the server starts the clock
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=4.0)
    instructor = Link(served.url, {"type": "hello", "role": "instructor"})
    try:
        for view, name in zip(views, ("bridge", "bridge wing")):
            view.scene.follow = Station.join(view.scene.exercise, served.url, name)
        bridge = Controls(views[0].scene, recordings=tmp_path)
        assert "instructor" not in bridge.session_contexts() and "follow" in bridge.session_contexts()
        assert "STATION bridge" in bridge.status()[0]
        _follow(views[0], STEPS_S[0], lambda s: s.server_s > 4.0)
        before = views[0].scene.sim.sea.hs
        bridge.press("RIGHT")  # helm 5 deg to starboard: to the server, back in the journal, then applied
        bridge.press("BRACKETRIGHT")  # the instructor's key for a higher sea: not the bridge's
        instructor.send({"type": "action", "action": "change", "fields": {"hs_factor": 1.3, "ramp_s": 5.0}})
        _follow(views[0], STEPS_S[0], lambda s: s.server_s > 15.0)
        instructor.send({"type": "control", "control": "freeze"})
        frames = []
        for view, dt in zip(views, STEPS_S):
            _follow(view, dt, lambda s: s.frozen and s.exercise.sim.time == s.server_s)
        frozen_s = views[0].scene.sim.time
        assert views[1].scene.sim.time == frozen_s
        frames.append([view.frame(hud=False) for view in views])
        instructor.send({"type": "control", "control": "resume"})
        _follow(views[0], STEPS_S[0], lambda s: s.server_s > frozen_s + 5.0)
        served.loop.call_soon_threadsafe(served.server.stop)  # the exercise ends there; its last state says so
        for view, dt in zip(views, STEPS_S):
            _follow(view, dt, lambda s: s.ended and s.exercise.sim.time == s.server_s)
        frames.append([view.frame(hud=False) for view in views])
        end_s = views[0].scene.sim.time
    finally:
        instructor.close()
        for view in views:
            if view.scene.follow is not None:
                view.scene.follow.close()
        served.close()
    assert end_s == served.server.exercise.sim.time > frozen_s
    actions = [e for e in served.server.exercise.journal if e["kind"] == "action"]
    assert sorted(a["action"] for a in actions) == ["change", "order"]  # from two machines: either may come first
    assert next(a for a in actions if a["action"] == "order")["rudder_deg"] > 0
    for view in views:
        assert [e for e in view.scene.follow.journal if e["kind"] == "action"] == actions
    assert views[0].scene.sim.sea.hs != before
    log = read_log(served.server.log_written)
    with _view(scenario) as replay:
        replay.scene.replay = Replay(replay.scene.exercise, log.actions(), log)
        for (a, b), t in zip(frames, (frozen_s, end_s)):
            replay.scene.step(t - replay.scene.sim.time)
            assert replay.scene.sim.time == t
            alone = replay.frame(hud=False)
            assert alone.std() > 5.0  # a picture, not a blank frame
            np.testing.assert_array_equal(a, alone, err_msg=f"station 1 at {t} s")
            np.testing.assert_array_equal(b, alone, err_msg=f"station 2 at {t} s")
    for view in views:
        view.release()


def test_a_station_of_another_scenario_is_told_so(tmp_path):
    """A station started on another scenario file would show its trainee another exercise: the server refuses it in
    one line naming its own scenario, and the station stops with it rather than hanging."""
    from marinesim.session.exercise import Exercise
    from marinesim.session.timeline import Simulation

    scenario = with_run(load_scenario(TRANSIT), 600.0)
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=4.0)
    try:
        with Simulation(scenario, wake=False) as local:
            exercise = Exercise(local)
            exercise.scenario = dataclasses.replace(scenario, path=resource_dir("configs") / "default.toml")
            station = Station.join(exercise, served.url, "bridge")
            with pytest.raises(MarinesimError, match=f"another scenario file \\({TRANSIT}"):
                for _ in range(int(WAIT_S / 0.5)):
                    station.poll(0.5)
            station.close()
    finally:
        served.close()


def test_a_station_that_drops_joins_again_at_the_current_time(tmp_path):
    """The server drops the station's connection mid-exercise (a network fault); the station joins again, takes the
    journal it missed, and follows to the end with every action the server applied. A station that stayed away, or
    applied the missed actions at the wrong time, would leave its trainee in another exercise."""
    from marinesim.net.station import follow_headless
    from marinesim.session.exercise import Exercise
    from marinesim.session.timeline import Simulation

    scenario = with_run(load_scenario(TRANSIT), 600.0)
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=4.0)
    instructor = Link(served.url, {"type": "hello", "role": "instructor"})
    said: list[str] = []
    dropped, stopped = [], []

    def drop_once(station: Station) -> None:
        """After 5 s, the server closes the station's socket once, and the instructor changes the sea while the
        station is away; once the station has the change, the exercise ends."""
        if not dropped and station.server_s > 5.0:
            dropped.append(station.server_s)
            client = next(c for c in served.server.clients if c.role == "station")
            served.loop.call_soon_threadsafe(lambda: served.loop.create_task(client.ws.close()))
            instructor.send({"type": "action", "action": "change", "fields": {"hs_factor": 1.2, "ramp_s": 5.0}})
        elif dropped and not stopped and any(e.get("action") == "change" for e in station.journal):
            stopped.append(station.server_s)
            served.loop.call_soon_threadsafe(served.server.stop)

    try:
        with Simulation(scenario, wake=False) as local:
            station = Station.join(Exercise(local), served.url, "bridge", say=said.append)
            follow_headless(station, drop_once, wait_s=1.0)
            station.close()
            assert local.time == served.server.exercise.sim.time > dropped[0]
    finally:
        instructor.close()
        served.close()
    assert dropped and any("joining again" in line for line in said), said
    joins = [e["kind"] for e in served.server.exercise.journal if e["kind"] in ("join", "leave")]
    assert joins[:3] == ["join", "leave", "join"]
    actions = [e for e in served.server.exercise.journal if e["kind"] == "action"]
    assert [a["action"] for a in actions] == ["change"]
    assert [e for e in station.journal if e["kind"] == "action"] == actions
