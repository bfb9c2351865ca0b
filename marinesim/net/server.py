"""``marinesim serve``: one exercise, run at real-time pace in one authoritative process, for an instructor's web
page and the stations that follow it, over WebSockets (aiohttp).

The exercise (:class:`~marinesim.session.exercise.Exercise`: timeline, own-ship, criteria, alarms, journal) moves
on every :data:`TICK_S` of wall time to the time the :class:`Pace` gives (frozen, or scaled). Actions from the page
and the stations are checked as a session log's are (:func:`~marinesim.session.log.action_problem`), queued, and
applied at the start of the next tick, at the exercise's time then, through :meth:`Exercise.act`: the journal is the
one record, the session log is written from it when the exercise ends, and ``replay``/``report`` read it as they
read a viewer's. Every :data:`STATE_S` each client gets the state (own-ship, the other bodies, criteria, alarms,
the sea and the weather) and the journal entries since the last; a station applies their actions to its own copy of
the exercise at the same times (:mod:`marinesim.net.station`), so it sees what the server sees.

Safe by default: it binds the loopback unless told otherwise; the page, the WebSocket and every message need the
token printed at start (compared in constant time); a message is at most :data:`MAX_MESSAGE_BYTES`, a client at most
:data:`RATE_PER_S` a second (:data:`BURST` at once): what goes beyond is refused with a reason and changes nothing.
The protocol is in ``docs/NETWORK.md``.
"""

from __future__ import annotations

import asyncio
import hmac
import json
import math
import secrets
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from marinesim import __version__
from marinesim.angles import wave_compass_from_beta
from marinesim.atomic import strict_json
from marinesim.constants import KNOT
from marinesim.errors import MarinesimError, ParameterError
from marinesim.offshore.traffic import DCPA_LIMIT_M
from marinesim.scenario.schema import briefing_paragraphs
from marinesim.session.exercise import EVERYONE, MAX_STATION, Exercise, quiet
from marinesim.session.log import action_problem, is_a, write_log
from marinesim.session.others import nearest
from marinesim.session.sidecar import sha256

TICK_S = 0.1
"""The exercise moves on every this many seconds of wall time."""
STATE_S = 0.25
"""Every client gets the state this often (s of wall time): four times a second."""
TRACK_S = 5.0
"""Own-ship's track as the page draws it: one point every this many simulated seconds."""
PREDICT_S, PREDICT_STEP_S = 180.0, 10.0
"""The predicted track: this far ahead (s), a point every this many (s), at the present speed and rate of turn."""
MAX_MESSAGE_BYTES = 4096
"""The largest message a client may send (bytes); a larger one closes its connection (WebSocket code 1009)."""
RATE_PER_S, BURST = 20.0, 40
"""A client's messages: this many a second on average, this many at once; those beyond are refused."""
MAX_CLIENTS = 64
"""Pages and stations connected at once; one more is refused."""
SEND_S = 2.0
"""A client that has not taken a state within this many seconds is dropped: one slow machine does not hold up the
exercise for everyone (it joins again at the current time)."""
STATION_ACTIONS = frozenset({"order", "acknowledge", "report"})
"""What a station may do: the trainee's orders (not the instructor's faults), acknowledgements, reports."""
SCALES = (0.25, 0.5, 1.0, 2.0, 4.0, 8.0)
"""The time scales an instructor may set (on the page, and ``marinesim serve --time-scale``)."""
PAGE = Path(__file__).parent / "page"
"""The instructor page's files (HTML, JS, CSS, uPlot)."""
OTHER_KEYS = ("east_m", "north_m", "heading_deg", "speed_kn", "range_m", "bearing_deg", "cpa_m", "tcpa_s")
"""What the state gives of each other body: its record columns (``NAME_`` + key, :mod:`marinesim.session.others`)."""
TCPA_DANGER_S = 720.0
"""A body own-ship will pass closer than :data:`~marinesim.offshore.traffic.DCPA_LIMIT_M` (0.5 NM) within this many
seconds (12 min) is dangerous: the page shows it in red."""


class Pace:
    """The exercise's time (s) against the wall clock ``now()`` (s): ``scale`` simulated seconds a second, none while
    frozen; each change starts again from the time reached."""

    def __init__(self, start_s: float = 0.0, now: Callable[[], float] = time.monotonic) -> None:
        self._now = now
        self._anchor = (start_s, now())
        self.scale = 1.0
        self.frozen = False

    def time(self) -> float:
        sim, wall = self._anchor
        return sim if self.frozen else sim + (self._now() - wall) * self.scale

    def _restart(self) -> None:
        self._anchor = (self.time(), self._now())

    def freeze(self) -> None:
        self._restart()
        self.frozen = True

    def resume(self) -> None:
        self._restart()
        self.frozen = False

    def set_scale(self, scale: float) -> None:
        self._restart()
        self.scale = scale


class Bucket:
    """A token bucket: :data:`RATE_PER_S` messages a second, :data:`BURST` at once."""

    def __init__(self, now: Callable[[], float] = time.monotonic) -> None:
        self._now, self.tokens, self._at = now, float(BURST), now()

    def take(self) -> bool:
        now = self._now()
        self.tokens = min(BURST, self.tokens + (now - self._at) * RATE_PER_S)
        self._at = now
        if self.tokens < 1.0:
            return False
        self.tokens -= 1.0
        return True


@dataclass
class Load:
    """The ticks' wall times (s): how many, their sum, the longest, and how many took longer than :data:`TICK_S`."""

    ticks: int = 0
    total_s: float = 0.0
    longest_s: float = 0.0
    over_budget: int = 0

    def add(self, seconds: float) -> None:
        self.ticks += 1
        self.total_s += seconds
        self.longest_s = max(self.longest_s, seconds)
        self.over_budget += seconds > TICK_S


@dataclass(eq=False)
class Client:
    """One connected page or station: its socket, its role, its station's name, its message budget."""

    ws: Any
    role: str = ""
    station: str = ""
    bucket: Bucket = field(default_factory=Bucket)
    sent: int = 0
    """Journal entries it has been sent."""
    lag_s: float | None = None
    """How far the station's own copy of the exercise is behind the server's (s), as it last said."""


def record_row(exercise: Exercise) -> dict[str, float] | None:
    """The record's row (:meth:`Simulation.frame`, column -> value) at the exercise's time; None without a
    vessel."""
    sim = exercise.sim
    if sim.vessel is None:
        return None
    return {name: float(column[0]) for name, column in sim.frame(np.array([sim.time])).items()}


def ship_state(exercise: Exercise, row: dict[str, float]) -> dict[str, Any]:
    """Own-ship now, as the page shows it: from the record's ``row`` at the exercise's time (:func:`record_row`:
    position north and east of the start in m, compass heading, course and speed over ground, rate of turn, rudder,
    roll, pitch, heave), the set course and the engine order."""
    conning = exercise.sim.conning()
    keys = ("north_m", "east_m", "heading_deg", "course_over_ground_deg", "speed_over_ground_kn",
            "rate_of_turn_deg_min", "rudder_deg", "roll_deg", "pitch_deg", "heave_m")
    return {key: round(row[key], 4) for key in keys} | {"course_deg": conning["course_deg"],
                                                          "engine": conning["engine"]}


def others_state(exercise: Exercise, row: dict[str, float]) -> list[dict[str, Any]]:
    """The other bodies now, as the page shows them, in the scenario's order: each one's name, kind and its
    :data:`OTHER_KEYS` from the record's ``row`` (:func:`record_row`: E frame m from own-ship's start, compass
    heading, speed in kn, own-ship's range in m, true bearing, CPA in m and TCPA in s to it); ``nearest``: the one
    own-ship comes closest to next (:func:`~marinesim.session.others.nearest`); ``danger``: a CPA under
    :data:`~marinesim.offshore.traffic.DCPA_LIMIT_M` with 0 < TCPA < :data:`TCPA_DANGER_S`."""
    bodies = tuple(body.other for body in exercise.sim.bodies)
    closest = nearest(row, bodies)
    out = []
    for other in bodies:
        values = {key: row[f"{other.name}_{key}"] for key in OTHER_KEYS}
        out.append({"name": other.name, "kind": other.kind} | values
                   | {"nearest": other.name == closest,
                      "danger": values["cpa_m"] < DCPA_LIMIT_M and 0.0 < values["tcpa_s"] < TCPA_DANGER_S})
    return out


def predicted(ship: dict[str, Any]) -> list[list[float]]:
    """The track ahead (north, east in m) over :data:`PREDICT_S` at the ship's present speed and course over ground,
    turning at her present rate: the curved predictor an ECDIS draws."""
    speed = ship["speed_over_ground_kn"] * KNOT
    course = math.radians(ship["course_over_ground_deg"])
    rate = math.radians(ship["rate_of_turn_deg_min"]) / 60.0
    points = []
    for t in np.arange(PREDICT_STEP_S, PREDICT_S + 1e-9, PREDICT_STEP_S):
        if abs(rate) < 1e-6:
            north, east = speed * t * math.cos(course), speed * t * math.sin(course)
        else:  # a circle of radius speed / rate
            north = speed / rate * (math.sin(course + rate * t) - math.sin(course))
            east = speed / rate * (math.cos(course) - math.cos(course + rate * t))
        points.append([round(ship["north_m"] + north, 2), round(ship["east_m"] + east, 2)])
    return points


def describe(exercise: Exercise, faults: tuple[str, ...]) -> dict[str, Any]:
    """The exercise as the page's welcome gives it: name, briefing, objectives, events, criteria, faults, and the
    other ships the instructor may drive (those under their own manoeuvring model)."""
    scenario = exercise.scenario
    briefing = scenario.briefing
    events = [{"index": i, "trigger": f"at {e.at_s:g} s" if e.at_s is not None else f"when {e.condition}",
               "what": e.describe().partition(": ")[2], "message": e.message} for i, e in enumerate(exercise.events)]
    criteria = [{"name": c.label, "unit": c.measure.unit, "limit": c.limit, "caution": c.caution}
                for c in exercise.criteria]
    paragraphs = briefing_paragraphs(briefing.text if briefing else "")
    return {"name": scenario.name, "title": scenario.name.replace("_", " "), "sha256": sha256(scenario.path),
            "briefing": "\n\n".join("\n".join(lines) for lines in paragraphs),
            "objectives": [o.text for o in briefing.objectives] if briefing else [],
            "duration_s": exercise.duration_s, "seed": scenario.run.seed, "events": events, "criteria": criteria,
            "faults": list(faults),
            "driven": [body.other.name for body in exercise.sim.bodies if body.other.ship is not None]}


class ExerciseServer:
    """Serves ``exercise`` (fresh, at time 0) with ``token``; its session log goes to ``log_path`` when it ends (None:
    none; a paced run that only streams, :meth:`run` without :meth:`start`).
    ``streams``: where own-ship's state goes out each second besides (NMEA, DIS; :mod:`marinesim.net.streams`);
    ``say``: where the server's lines go (a station joined, the exercise ended)."""

    def __init__(self, exercise: Exercise, log_path: Path | None, token: str | None = None, streams: Any = None,
                 say: Callable[[str], None] = quiet, pace: Pace | None = None) -> None:
        self.exercise, self.log_path, self.streams, self.say = exercise, log_path, streams, say
        self.token = token or secrets.token_urlsafe(24)
        """The instructor's: the page, every action and control."""
        self.station_token = secrets.token_urlsafe(24)
        """The stations': the trainee's actions only (:data:`STATION_ACTIONS`)."""
        self.pace = pace or Pace()
        self.clients: list[Client] = []
        self.track: list[list[float]] = []
        self.ended = asyncio.Event()
        self.log_written: Path | None = None
        self.load = Load()
        """How long each tick took (wall s): the budget is :data:`TICK_S`."""
        self._queue: deque[tuple[Client, dict]] = deque()
        self._lock = asyncio.Lock()
        """Held while the exercise moves (a tick) and while a welcome is read from it."""
        self._ticking: asyncio.Future | None = None
        self._stop = False
        sim = exercise.sim
        ship = sim.voyage.ship if sim.vessel is not None else None
        faults = ((*ship.unit_faults, *(f"line:{name}" for name in ship.line_names if ship.dp is not None),
                   *(("reference drift",) if ship.dp is not None else ())) if sim.station is not None else ())
        self.scenario = describe(exercise, faults)
        self._runner = None

    # -- the web side --------------------------------------------------------------------------

    def app(self):
        from aiohttp import web

        app = web.Application(client_max_size=MAX_MESSAGE_BYTES)
        app.router.add_get("/", self._page)
        app.router.add_get("/ws", self._socket)
        app.router.add_static("/static/", PAGE, show_index=False, follow_symlinks=False)
        return app

    async def start(self, host: str = "127.0.0.1", port: int = 8765) -> tuple[str, int]:
        """Listen on ``host:port`` (port 0: any free one); returns the address bound."""
        from aiohttp import web

        self._runner = web.AppRunner(self.app(), access_log=None)
        await self._runner.setup()
        site = web.TCPSite(self._runner, host, port, reuse_address=True)
        try:
            await site.start()
        except OSError as error:
            await self._runner.cleanup()
            raise ParameterError(f"--bind {host}:{port}: cannot listen there ({error.strerror or error})") from None
        bound = site._server.sockets[0].getsockname()
        return bound[0], bound[1]

    async def close(self) -> None:
        for client in list(self.clients):
            await client.ws.close()
        if self._runner is not None:
            await self._runner.cleanup()

    def _allowed(self, token: object, role: str = "instructor") -> bool:
        """Whether ``token`` is ``role``'s (the instructor's token serves a station too)."""
        if not isinstance(token, str):
            return False
        tokens = (self.token,) if role == "instructor" else (self.token, self.station_token)
        return any(hmac.compare_digest(token.encode(), ours.encode()) for ours in tokens)

    async def _page(self, request):
        from aiohttp import web

        if not self._allowed(request.query.get("token")):
            return web.Response(status=403, text="marinesim serve: this page needs the token the server printed\n")
        return web.FileResponse(PAGE / "instructor.html")

    async def _socket(self, request):
        from aiohttp import WSMsgType, web

        if not self._allowed(request.query.get("token"), "station"):
            return web.Response(status=403, text="marinesim serve: the WebSocket needs the server's token\n")
        if len(self.clients) >= MAX_CLIENTS:
            return web.Response(status=503, text=f"marinesim serve: {MAX_CLIENTS} clients are connected already\n")
        ws = web.WebSocketResponse(max_msg_size=MAX_MESSAGE_BYTES, heartbeat=20.0)
        await ws.prepare(request)
        client = Client(ws)
        try:
            async for message in ws:
                if message.type != WSMsgType.TEXT:
                    await self._refuse(client, "expected JSON text messages")
                    continue
                await self._receive(client, message.data)
        finally:
            self._drop(client)
        return ws

    async def _refuse(self, client: Client, why: str, fatal: bool = False) -> None:
        """Tell ``client`` why its message changed nothing; ``fatal``: and why it cannot go on."""
        await self._send(client, json.dumps({"type": "error", "message": why} | ({"fatal": True} if fatal else {})))

    async def _send(self, client: Client, text: str) -> None:
        """Send ``text``; a client gone, or too slow to take it within :data:`SEND_S`, is dropped."""
        if client.ws.closed:
            return
        try:
            await asyncio.wait_for(client.ws.send_str(text), SEND_S)
        except (ConnectionError, RuntimeError, asyncio.TimeoutError):
            self._drop(client)
            await client.ws.close()

    def _drop(self, client: Client) -> None:
        if client in self.clients:
            self.clients.remove(client)
            if client.role == "station":
                self._queue.append((client, {"type": "leave"}))

    async def _receive(self, client: Client, data: str) -> None:
        if not client.bucket.take():
            await self._refuse(client, f"too many messages: at most {RATE_PER_S:g} a second; this one was dropped")
            return
        try:
            message = json.loads(data)
        except ValueError:
            await self._refuse(client, "not JSON: each message is one JSON object")
            return
        if not isinstance(message, dict):
            await self._refuse(client, "expected a JSON object")
            return
        role = message.get("role", "instructor") if message.get("type") == "hello" else client.role or "station"
        if not self._allowed(message.get("token"), role):
            await self._refuse(client, "refused: the message has no token or a wrong one; nothing was changed")
            return
        kind = message.get("type")
        if kind == "hello":
            if client in self.clients:
                await self._refuse(client, "hello: this connection has said hello already")
            else:
                await self._hello(client, message)
        elif client not in self.clients:
            await self._refuse(client, "say hello first: {\"type\": \"hello\", \"role\": ...}")
        elif kind == "action":
            fields = message.get("fields", {})
            entry = {"action": message.get("action"), **fields} if isinstance(fields, dict) else {"action": None}
            problem = action_problem(entry)
            if problem is None and client.role == "station" and (entry["action"] not in STATION_ACTIONS
                                                                 or "fault" in entry or "vessel" in entry):
                problem = f"{entry['action']}: the instructor's, not a station's (a station orders own-ship, " \
                          "acknowledges, reports)"
            if problem is None and entry["action"] == "report":
                entry["station"] = client.station
            if problem is not None:
                await self._refuse(client, f"action refused: {problem}")
            else:
                self._queue.append((client, {"type": "action", "entry": entry}))
        elif kind == "control" and client.role == "instructor":
            control, value = message.get("control"), message.get("value")
            if control in ("freeze", "resume") or (control == "scale" and not isinstance(value, bool)
                                                   and value in SCALES):
                self._queue.append((client, {"type": "control", "control": control, "value": value}))
            else:
                await self._refuse(client, f"control refused: expected freeze, resume or scale with one of "
                                           f"{', '.join(map(str, SCALES))}")
        elif kind == "lag" and client.role == "station":
            if is_a(message.get("lag_s"), float):  # JSON allows NaN and 1e400; the outputs do not
                client.lag_s = float(message["lag_s"])
            else:
                await self._refuse(client, f"lag: expected a finite number of seconds, got {message.get('lag_s')!r}")
        else:
            await self._refuse(client, f"unknown message type {kind!r} for a {client.role or 'client'}")

    async def _hello(self, client: Client, message: dict) -> None:
        role, station = message.get("role"), message.get("station", "")
        if role not in ("instructor", "station"):
            await self._refuse(client, f"hello: role must be instructor or station, got {role!r}")
            return
        if role == "station":
            if not (isinstance(station, str) and 0 < len(station) <= MAX_STATION and station.isprintable()) \
                    or station == EVERYONE:
                await self._refuse(client, f"hello: a station needs a name of 1 to {MAX_STATION} characters (not "
                                           f"{EVERYONE!r})", fatal=True)
                return
            if station in self.stations():
                await self._refuse(client, f"hello: a station named {station!r} is connected already", fatal=True)
                return
            for key, ours in (("scenario_sha256", self.scenario["sha256"]), ("marinesim", __version__)):
                if message.get(key) != ours:
                    what = (f"scenario file ({self.exercise.scenario.path})" if key == "scenario_sha256"
                            else f"marinesim version ({__version__})")
                    await self._refuse(client, f"hello: this server runs another {what}; {key} differs: a station "
                                               "runs the same to follow it", fatal=True)
                    await client.ws.close()
                    return
        client.role, client.station = role, station
        async with self._lock:  # between ticks: the time and the journal agree
            self.clients.append(client)
            if role == "station":
                self._queue.append((client, {"type": "join"}))
            client.sent = len(self.exercise.journal)
            welcome = {"type": "welcome", "marinesim": __version__, "t": self.exercise.sim.time,
                       "scenario": self.scenario | {"stations": self.stations()}, "track": list(self.track),
                       "journal": self.exercise.journal[:client.sent]}
        await self._send(client, strict_json(welcome))

    def stations(self) -> list[str]:
        return sorted({c.station for c in self.clients if c.role == "station"})

    # -- the exercise --------------------------------------------------------------------------

    async def run(self) -> None:
        """Move the exercise on at the pace until it ends (or :meth:`stop`), then write its session log."""
        next_state = time.monotonic()  # states on a grid of STATE_S: four a second on average, whatever the ticks
        duration = self.exercise.duration_s
        try:
            while True:
                started = time.monotonic()
                target = min(self.pace.time(), duration)
                async with self._lock:
                    self._ticking = asyncio.ensure_future(asyncio.to_thread(self._tick, target))
                    replies = await asyncio.shield(self._ticking)
                for client, why in replies:
                    await self._refuse(client, why)
                now = time.monotonic()
                end = self.exercise.sim.time >= duration or self._stop
                if end:
                    self.exercise.note("end")  # in the last state's journal: every station has it
                if end or now >= next_state:
                    next_state = next_state + STATE_S if now - next_state < STATE_S else now + STATE_S
                    await self._broadcast(end)
                self.load.add(time.monotonic() - started)
                if end:
                    break
                await asyncio.sleep(TICK_S)
        finally:
            if self._ticking is not None and not self._ticking.done():  # cancelled (Ctrl-C) while the exercise moved
                await asyncio.wait([self._ticking])
            self._finish()

    def stop(self) -> None:
        """End the exercise at the next tick (its log says where it stopped)."""
        self._stop = True

    def _tick(self, target: float) -> list[tuple[Client, str]]:
        """Apply what was queued at the exercise's time, then move it on to ``target`` (s); in a worker thread,
        the one place the exercise changes. Returns the refusals to send."""
        exercise, refused = self.exercise, []
        while self._queue:
            client, item = self._queue.popleft()
            kind = item["type"]
            if kind == "action":
                try:
                    exercise.act(**item["entry"])
                except MarinesimError as error:
                    refused.append((client, f"action refused: {error}"))
                except Exception as error:  # noqa: BLE001 (an action the vessel cannot take must not end the exercise)
                    refused.append((client, f"action refused: {item['entry']['action']} cannot be applied to this "
                                            f"exercise ({type(error).__name__}: {error})"))
            elif kind == "control":
                self._control(item["control"], item["value"])
            else:
                exercise.note(kind, station=client.station)
                self.say(f"t {exercise.sim.time:7.1f} s  station {client.station} {kind}s")
        if not self.pace.frozen and target > exercise.sim.time:
            exercise.advance_to(target)
        t = exercise.sim.time
        if self.exercise.sim.vessel is not None and (not self.track or t >= self.track[-1][0] + TRACK_S):
            ship = ship_state(exercise, record_row(exercise))
            self.track.append([round(t, 3), ship["north_m"], ship["east_m"]])
        if self.streams is not None and self.exercise.sim.vessel is not None:
            for at in self.streams.pending(t):  # each output time passed, at that time: none skipped by a slow tick
                self.streams.send(at, {name: float(c[0]) for name, c in exercise.sim.frame(np.array([at])).items()})
        return refused

    def _control(self, control: str, value: float | None) -> None:
        if control == "freeze" and not self.pace.frozen:
            self.pace.freeze()
            self.exercise.note("pause")
        elif control == "resume" and self.pace.frozen:
            self.pace.resume()
            self.exercise.note("resume")
        elif control == "scale":
            self.pace.set_scale(float(value))
            self.exercise.note("time_scale", scale=float(value))

    def state(self, ended: bool = False) -> dict[str, Any]:
        """What every client is sent four times a second (less the journal entries, which are each client's own)."""
        exercise, sim = self.exercise, self.exercise.sim
        row = record_row(exercise)
        ship = ship_state(exercise, row) if row is not None else None
        sea = sim.sea
        largest = max(sea.systems, key=lambda system: system.spectrum.hs**2 / 16.0 if hasattr(system, "spectrum")
                      else system.variance)
        environment = sim.environment
        return {"type": "state", "t": sim.time, "frozen": self.pace.frozen, "scale": self.pace.scale, "ended": ended,
                "ship": ship, "predicted": predicted(ship) if ship else [],
                "others": others_state(exercise, row) if row is not None else [],
                "lag_s": {c.station: c.lag_s for c in self.clients if c.role == "station" and c.lag_s is not None},
                "sea": {"hs_m": round(sea.hs, 3), "tp_s": round(sea.tp, 3),
                        "from_deg": round(wave_compass_from_beta(largest.beta), 1)},
                "weather": {key: getattr(environment, key) for key in
                            ("visibility_m", "cloud_cover_oktas", "wind_speed_m_s", "rain_mm_h")},
                "criteria": [{"value": value, "level": str(level)} for _, value, level in exercise.readings()],
                "alarms": [{"criterion": a.name, "raised_s": a.raised_s, "value": a.value, "limit": a.limit,
                            "acknowledged_s": a.acknowledged_s, "cleared_s": a.cleared_s} for a in exercise.alarms],
                "pending": exercise.pending_events(), "stations": self.stations()}

    async def _broadcast(self, ended: bool) -> None:
        if not self.clients:
            return
        state = self.state(ended)
        journal = self.exercise.journal
        clients = list(self.clients)
        texts = []
        for client in clients:
            texts.append(strict_json(state | {"journal": journal[client.sent:]}))
            client.sent = len(journal)
        await asyncio.gather(*(self._send(client, text) for client, text in zip(clients, texts)))

    def _finish(self) -> None:
        if self.log_written is None and self.log_path is not None:
            if not self.exercise.journal or self.exercise.journal[-1]["kind"] != "end":
                self.exercise.note("end")
            self.log_written = write_log(self.log_path, self.exercise)
            self.say(f"t {self.exercise.sim.time:7.1f} s  the exercise ended: session log {self.log_written}")
        self.ended.set()
