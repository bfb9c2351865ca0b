"""The served exercise: an instructor's actions over a real WebSocket on the loopback reach the exercise once and
every station at the same simulated time; without the token nothing is served or changed; bad messages are refused
and leave the exercise and its log as they were."""

from __future__ import annotations

import asyncio
import json
import math
from pathlib import Path

import aiohttp
import numpy as np
import pytest

from conftest import ROOT, write
from marinesim import __version__
from marinesim.cli.serve import DEFAULT_BIND, bind_address
from marinesim.errors import ParameterError
from marinesim.net.server import BURST, MAX_MESSAGE_BYTES, RATE_PER_S, Bucket, ExerciseServer, Pace, predicted
from marinesim.net.station import Station, follow_headless, station_url
from marinesim.resources import resource_dir
from marinesim.scenario import load_scenario, with_run
from marinesim.session.exercise import Exercise
from marinesim.session.log import read_log
from marinesim.session.replay import replay_session
from marinesim.session.timeline import Simulation

TRANSIT = resource_dir("configs") / "training" / "heavy_weather_transit.toml"
HANG_S = 300.0
"""s: no message from the server for this long is a hang (it sends four a second)."""
SCALE = 4.0
"""The served exercises run this many times real time: a test's 30 s exercise takes a few seconds of wall time."""


TANKER = ROOT / "rao" / "tanker" / "tanker.4"
TRAFFIC = f"""
[ocean]
resolution = 64
tiles = 2

[[sea]]
type = "jonswap"
hs_m = 2.0
tp_s = 9.0
from_deg = 0.0

[vessel]
rao = "{TANKER}"
speed_kn = 5.0
heading_deg = 90.0

[run]
duration_s = 600.0
dt_s = 0.1
seed = 5

[[vessels]]
name = "coaster"
kind = "ship"
rao = "{TANKER}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
position_m = [400.0, -250.0]
speed_kn = 6.0
heading_deg = 0.0

[[vessels]]
name = "fairway"
kind = "buoy"
position_m = [2500.0, 100.0]
"""
"""Own-ship east at 5 kn; a coaster 400 m east and 250 m south of her start, north at 6 kn (at t = 0: relative
position r = (400, -250) m, velocity v = (-2.572, 3.087) m/s, tcpa = -r.v / |v|^2 = 111.5 s, dcpa = 147 m: dangerous);
a buoy 2.5 km ahead, 100 m north of her track (dcpa 100 m in 972 s: the nearest ahead, not yet dangerous)."""


def traffic_scenario(folder: Path):
    """:data:`TRAFFIC` written to ``folder`` and loaded."""
    return load_scenario(write(folder, TRAFFIC, "traffic.toml"))


def _scenario(duration_s: float = 600.0):
    """The transit over ``duration_s`` (s): long enough at :data:`SCALE` that a test on a loaded machine is done
    before it ends; a test that needs the end stops the server (its log says where)."""
    return with_run(load_scenario(TRANSIT), duration_s)


class Served:
    """A server on the loopback (a free port) over a fresh exercise of ``scenario``, its log in ``folder``."""

    def __init__(self, scenario, folder: Path) -> None:
        self.scenario, self.folder = scenario, folder

    async def __aenter__(self) -> Served:
        self.sim = Simulation(self.scenario, wake=False)
        pace = Pace()
        pace.set_scale(SCALE)
        self.server = ExerciseServer(Exercise(self.sim), self.folder / "served.jsonl", pace=pace)
        self.host, self.port = await self.server.start("127.0.0.1", 0)
        self.http = f"http://{self.host}:{self.port}"
        self.url = f"ws://{self.host}:{self.port}/ws?token={self.server.token}"
        self.task = asyncio.create_task(self.server.run())
        return self

    async def __aexit__(self, *exc) -> None:
        self.server.stop()
        await self.task
        await self.server.close()
        self.sim.close()


async def _instructor(session: aiohttp.ClientSession, served: Served):
    ws = await session.ws_connect(served.url)
    await ws.send_json({"type": "hello", "role": "instructor", "token": served.server.token})
    welcome = await ws.receive_json()
    assert welcome["type"] == "welcome"
    return ws, welcome


async def _until(ws, predicate) -> dict:
    """Messages from ``ws`` until one satisfies ``predicate``; returns it (the server's state comes 4 times a
    second, so this waits on the exercise, not on a clock). The exercise's end, when something else is awaited, or
    :data:`HANG_S` without a message fail the test rather than hang it."""
    while True:
        message = await asyncio.wait_for(ws.receive_json(), HANG_S)
        if predicate(message):
            return message
        assert not message.get("ended"), "the exercise ended before the message awaited came"


def test_the_server_binds_the_loopback_unless_told_otherwise():
    """A server reachable from other machines by default would let anyone on the network watch the exercise."""
    assert bind_address(DEFAULT_BIND)[0] == "127.0.0.1"
    assert bind_address("0.0.0.0:9000") == ("0.0.0.0", 9000)
    for bad in ("8765", "host:", "host:99999", ":80"):
        with pytest.raises(ParameterError, match="--bind"):
            bind_address(bad)


def test_a_station_url_needs_a_websocket_address_and_a_token():
    """A station that joined without the token would be refused by the server with a less helpful error."""
    assert station_url("ws://127.0.0.1:8765/ws?token=abc") == ("ws://127.0.0.1:8765/ws", "abc")
    assert station_url("ws://10.0.0.2:9000?token=abc") == ("ws://10.0.0.2:9000/ws", "abc")
    for bad in ("http://127.0.0.1:8765/ws?token=a", "ws://127.0.0.1/ws?token=a", "ws://127.0.0.1:8765/ws"):
        with pytest.raises(ParameterError, match="--connect"):
            station_url(bad)


def test_the_pace_follows_the_wall_clock_scaled_and_stops_when_frozen():
    """A served exercise must run at real time (x the instructor's scale) and stand still while frozen."""
    wall = [100.0]
    pace = Pace(now=lambda: wall[0])
    wall[0] += 10.0
    assert pace.time() == pytest.approx(10.0)
    pace.set_scale(4.0)
    wall[0] += 5.0
    assert pace.time() == pytest.approx(30.0)
    pace.freeze()
    wall[0] += 60.0
    assert pace.time() == pytest.approx(30.0)
    pace.resume()
    wall[0] += 1.0
    assert pace.time() == pytest.approx(34.0)


def test_a_client_gets_its_burst_then_its_rate():
    """A page or station that floods the server must not take its time from the exercise: past the burst, messages
    are refused until the bucket refills at the rate."""
    wall = [0.0]
    bucket = Bucket(now=lambda: wall[0])
    assert all(bucket.take() for _ in range(BURST))
    assert not bucket.take()
    wall[0] += 1.0
    taken = sum(bucket.take() for _ in range(10 * BURST))
    assert taken == int(RATE_PER_S)


def test_the_predicted_track_is_the_circle_of_the_present_turn():
    """The instructor's chart would show the ship going somewhere else than her rate of turn takes her: at v and
    r the predictor's points lie on a circle of radius v / r through the ship, and on the course line with no turn."""
    ship = {"north_m": 100.0, "east_m": -50.0, "speed_over_ground_kn": 12.0, "course_over_ground_deg": 30.0,
            "rate_of_turn_deg_min": 0.0}
    v = 12.0 * 1852.0 / 3600.0
    for k, (north, east) in enumerate(predicted(ship), start=1):
        assert north - 100.0 == pytest.approx(v * 10.0 * k * math.cos(math.radians(30.0)), abs=0.005)  # to the cm
        assert east + 50.0 == pytest.approx(v * 10.0 * k * math.sin(math.radians(30.0)), abs=0.005)
    turning = ship | {"rate_of_turn_deg_min": 30.0}  # to starboard
    r = math.radians(30.0) / 60.0
    course = math.radians(30.0)
    centre = (100.0 - v / r * math.sin(course), -50.0 + v / r * math.cos(course))  # to starboard of the ship
    points = np.array(predicted(turning))
    radius = np.hypot(points[:, 0] - centre[0], points[:, 1] - centre[1])
    np.testing.assert_allclose(radius, v / r, atol=0.01)  # the points are given to the cm
    assert points[0, 1] > -50.0  # heading 030 and turning: first east of where she is


def test_without_the_token_nothing_is_served_and_nothing_changes(tmp_path):
    """Anyone who can reach the port could otherwise watch the exercise or change its sea: the page and the socket
    need the token, and a message with a wrong one is refused and journals nothing."""

    async def scenario() -> None:
        async with Served(_scenario(), tmp_path) as served:
            server, base = served.server, served.http
            async with aiohttp.ClientSession() as session:
                for url in (f"{base}/", f"{base}/?token=wrong", f"{base}/ws", f"{base}/ws?token=wrong"):
                    async with session.get(url) as response:
                        assert response.status == 403, url
                async with session.get(f"{base}/?token={server.token}") as response:
                    assert response.status == 200 and "<html" in (await response.text()).lower()
                with pytest.raises(aiohttp.WSServerHandshakeError):
                    await session.ws_connect(f"{base.replace('http', 'ws')}/ws?token=wrong")
                ws, _ = await _instructor(session, served)
                for token in (None, "", "wrong", server.token + "x"):
                    message = {"type": "action", "action": "change", "fields": {"hs_factor": 2.0}}
                    await ws.send_json(message | ({"token": token} if token is not None else {}))
                    reply = await _until(ws, lambda m: m["type"] == "error")
                    assert "token" in reply["message"]
                await ws.send_json({"type": "control", "control": "freeze", "token": "wrong"})
                await _until(ws, lambda m: m["type"] == "error")
                await ws.close()
                station = await session.ws_connect(served.url.replace(server.token, server.station_token))
                await station.send_json({"type": "hello", "role": "instructor", "token": server.station_token})
                assert "token" in (await _until(station, lambda m: m["type"] == "error"))["message"]
                await station.close()
            changed = [e for e in server.exercise.journal if e["kind"] in ("action", "pause")]
            assert changed == [] and server.exercise.sim.sea.hs == pytest.approx(_scenario().sea.hs)

    asyncio.run(scenario())


def test_a_station_sees_the_instructors_actions_at_the_same_simulated_time(tmp_path):
    """The instructor changes the sea, brings an event forward and sends a message; a station following the
    exercise applies each once at the server's time, so its motions are the server's and a standalone replay's of
    the log, bit for bit; a station that did not would show the trainee another sea than the instructor set."""
    scenario = _scenario()

    async def run() -> tuple[ExerciseServer, Exercise, list[str]]:
        seen: list[str] = []
        async with Served(scenario, tmp_path) as served:
            server = served.server
            with Simulation(scenario, wake=False) as local:
                station = Exercise(local)
                bridge = Station.join(station, served.url, "bridge", say=seen.append)
                following = asyncio.create_task(asyncio.to_thread(follow_headless, bridge))
                async with aiohttp.ClientSession() as session:
                    ws, welcome = await _instructor(session, served)
                    assert [e["index"] for e in welcome["scenario"]["events"]] == list(range(len(scenario.events)))
                    await _until(ws, lambda m: m["type"] == "state" and "bridge" in m["stations"])
                    pending = (await _until(ws, lambda m: m["type"] == "state"))["pending"]
                    token = server.token
                    await ws.send_json({"type": "action", "token": token, "action": "change",
                                        "fields": {"hs_factor": 1.4, "turn_waves_deg": 20.0, "ramp_s": 5.0}})
                    await ws.send_json({"type": "action", "token": token, "action": "trigger",
                                        "fields": {"index": pending[0]}})
                    await ws.send_json({"type": "action", "token": token, "action": "message",
                                        "fields": {"text": "Bridge, report your motions", "to": "bridge"}})
                    state = await _until(ws, lambda m: m["type"] == "state" and any(
                        e.get("action") == "message" for e in m["journal"]))
                    assert state["t"] < scenario.run.duration_s
                    server.stop()
                    await _until(ws, lambda m: m["type"] == "state" and m["ended"])
                    await ws.close()
                await following
                bridge.close()
                return server, station, seen

    server, station, _ = asyncio.run(run())
    actions = [e for e in server.exercise.journal if e["kind"] == "action"]
    assert [a["action"] for a in actions] == ["change", "trigger", "message"]
    assert [e for e in station.journal if e["kind"] == "action"] == actions
    end = server.exercise.sim.time
    assert station.sim.time == end and read_log(server.log_written).end_s == end
    assert station.messages(t=actions[-1]["t"], station="bridge")[-1].endswith("Bridge, report your motions")
    assert not any("report your motions" in m for m in station.messages(t=actions[-1]["t"], station="crane"))
    replayed = replay_session(read_log(server.log_written))
    times = np.linspace(0.0, end, 31)
    served_rows = server.exercise.sim.frame(times)
    for other in (station.sim.frame(times), replayed.sim.frame(times)):
        for name, column in served_rows.items():
            np.testing.assert_array_equal(other[name], column, err_msg=name)
    assert station.sim.sea.hs == server.exercise.sim.sea.hs != scenario.sea.hs  # the sea the instructor made


def test_bad_messages_are_refused_and_the_exercise_goes_on(tmp_path):
    """A malformed, oversized or unknown message, a flood, and a station of another scenario or version each get a
    reason and change nothing: the exercise runs to its end and its log reads back whole. A server that crashed or
    journaled them would lose the exercise for everyone."""
    scenario = _scenario()

    async def run() -> ExerciseServer:
        async with Served(scenario, tmp_path) as served:
            server, url = served.server, served.url
            token = server.token
            async with aiohttp.ClientSession() as session:
                ws = await session.ws_connect(url)
                await ws.send_json({"type": "action", "token": token, "action": "message", "fields": {"text": "x"}})
                assert "hello first" in (await _until(ws, lambda m: m["type"] == "error"))["message"]
                await ws.send_json({"type": "hello", "role": "instructor", "token": token})
                await _until(ws, lambda m: m["type"] == "welcome")
                refusals = {"{not json": "not JSON", "[1, 2]": "JSON object",
                            json.dumps({"type": "dance", "token": token}): "unknown message type",
                            json.dumps({"type": "action", "token": token, "action": "order",
                                        "fields": {"rudder_deg": "hard"}}): "expected a number",
                            json.dumps({"type": "action", "token": token, "action": "launch"}): "key 'action'",
                            json.dumps({"type": "action", "token": token, "action": "trigger",
                                        "fields": {"index": 99}}): "event 99",
                            json.dumps({"type": "control", "token": token, "control": "scale", "value": 1000}):
                                "control refused"}
                for text, why in refusals.items():
                    await ws.send_str(text)
                    assert why in (await _until(ws, lambda m: m["type"] == "error"))["message"], text
                flood = BURST + 60
                for _ in range(flood):  # "lag" is a station's message: each is refused, for one reason or the other
                    await ws.send_json({"type": "lag", "token": token, "lag_s": 0.0})
                refused = [(await _until(ws, lambda m: m["type"] == "error"))["message"] for _ in range(flood)]
                assert all("unknown message type" in why or "too many" in why for why in refused)
                big = await session.ws_connect(url)
                await big.send_str("x" * (MAX_MESSAGE_BYTES + 1))
                closed = await big.receive()
                assert closed.type in (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED)
                assert big.close_code == aiohttp.WSCloseCode.MESSAGE_TOO_BIG
                hello = {"type": "hello", "token": server.station_token, "role": "station", "station": "bridge",
                         "scenario_sha256": server.scenario["sha256"], "marinesim": __version__}
                bridge = await session.ws_connect(url)
                await bridge.send_json(hello)
                await _until(bridge, lambda m: m["type"] == "welcome")
                station_refusals = {
                    json.dumps(hello): "said hello already",
                    json.dumps({"type": "action", "token": server.station_token, "action": "change",
                                "fields": {"hs_factor": 2.0}}): "the instructor's, not a station's",
                    json.dumps({"type": "action", "token": server.station_token, "action": "order",
                                "fields": {"fault": "thruster:bow"}}): "the instructor's, not a station's",
                    json.dumps({"type": "action", "token": server.station_token, "action": "order",
                                "fields": {"vessel": "tanker", "course_deg": 300.0}}):
                        "the instructor's, not a station's",
                    json.dumps({"type": "lag", "token": server.station_token, "lag_s": float("nan")}): "finite",
                    '{"type": "lag", "token": "%s", "lag_s": 1e400}' % server.station_token: "finite",
                    json.dumps({"type": "control", "token": server.station_token, "control": "freeze"}):
                        "unknown message type"}
                for text, why in station_refusals.items():
                    await bridge.send_str(text)
                    assert why in (await _until(bridge, lambda m: m["type"] == "error"))["message"], text
                twin = await session.ws_connect(url)
                await twin.send_json(hello)
                assert "connected already" in (await _until(twin, lambda m: m["type"] == "error"))["message"]
                await twin.close()
                await bridge.close()
                for key, value in (("scenario_sha256", "0" * 64), ("marinesim", "0.0.0")):
                    other = await session.ws_connect(url)
                    hello = {"type": "hello", "token": token, "role": "station", "station": "bridge",
                             "scenario_sha256": server.scenario["sha256"], "marinesim": __version__}
                    await other.send_json(hello | {key: value})
                    refused = await other.receive_json()
                    assert refused["fatal"] and key in refused["message"]
                    await other.close()
                server.stop()
                await _until(ws, lambda m: m["type"] == "state" and m["ended"])
                await ws.close()
            return server

    server = asyncio.run(run())
    assert [e for e in server.exercise.journal if e["kind"] == "action"] == []
    assert [e["kind"] for e in server.exercise.journal if e["kind"] in ("join", "leave")] == ["join", "leave"]
    assert 0.0 < server.exercise.sim.time < scenario.run.duration_s
    log = read_log(server.log_written)
    assert log.entries[-1]["kind"] == "end" and log.verification.verified


def test_the_state_gives_the_other_bodies_as_the_record_has_them(tmp_path):
    """Each state's ``others`` are the record's columns (Simulation.frame) of each body at the state's time, in the
    scenario's order, with the coaster (dcpa 147 m in 112 s) dangerous and the buoy (dcpa 100 m, in 16 min) the
    nearest ahead. A server that computed them another way, at another time, or that mixed up the bodies would show
    the instructor traffic the trainee's radar does not."""
    scenario = traffic_scenario(tmp_path)

    async def run() -> list[dict]:
        async with Served(scenario, tmp_path) as served:
            async with aiohttp.ClientSession() as session:
                ws, _ = await _instructor(session, served)
                states = [await _until(ws, lambda m: m["type"] == "state" and m["t"] > 0.0) for _ in range(3)]
                await ws.close()
            return states

    states = asyncio.run(run())
    assert len({state["t"] for state in states}) > 1  # the bodies moved between the states
    with Simulation(scenario, wake=False) as sim:
        for state in states:
            row = sim.frame(np.array([state["t"]]))
            others = state["others"]
            assert [(o["name"], o["kind"]) for o in others] == [("coaster", "ship"), ("fairway", "buoy")]
            for other in others:
                for key in ("east_m", "north_m", "heading_deg", "speed_kn", "range_m", "bearing_deg", "cpa_m",
                            "tcpa_s"):
                    assert other[key] == row[f"{other['name']}_{key}"][0], (state["t"], other["name"], key)
            coaster, fairway = others
            assert coaster["danger"] and not fairway["danger"]
            assert fairway["nearest"] and not coaster["nearest"]
    knot = 1852.0 / 3600.0
    r, v = np.array([400.0, -250.0]), np.array([-5.0 * knot, 6.0 * knot])  # TRAFFIC's note: both on straight tracks
    tcpa = -(r @ v) / (v @ v)
    for state in states:
        coaster = state["others"][0]
        assert coaster["cpa_m"] == pytest.approx(np.hypot(*(r + v * tcpa)), abs=1e-6)
        assert coaster["tcpa_s"] == pytest.approx(tcpa - state["t"], abs=1e-6)
