"""A station on a served exercise (``marinesim run SCENARIO --connect ws://HOST:PORT/ws?token=... --station NAME``):
its own copy of the exercise, following the server's.

Only the clock and the journal travel: the station builds the exercise from the same scenario file (the server
checks its sha256) and seed, and applies the journal's actions at their simulated times as a replay does
(:class:`~marinesim.session.replay.Replay`). The exercise is deterministic, so its timeline, motions and picture at a
given simulated time are the server's and a standalone replay's. The station never runs ahead of the last time the
server gave; where its own computing falls behind, :attr:`Station.lag_s` says by how much, the station shows it and
tells the server. Its orders and reports go to the server and come back in the journal like everyone's.

The socket lives on a thread of its own (:class:`Link`); the exercise is moved only by the thread that draws it
(:meth:`Station.step`), so the viewer and a headless loop follow it the same way.
"""

from __future__ import annotations

import asyncio
import json
import queue
import threading
import time
from collections.abc import Callable
from typing import Any
from urllib.parse import parse_qs, urlsplit

from marinesim import __version__
from marinesim.errors import MarinesimError, ParameterError
from marinesim.session.exercise import EVERYONE, MAX_STATION, Exercise, quiet
from marinesim.session.replay import Replay
from marinesim.session.sidecar import sha256

LAG_REPORT_S = 1.0
"""A station tells the server how far behind it is at most this often (s of wall time)."""
CATCH_UP_S = 1.0
"""A station more than this behind the server (s) jumps to within it rather than showing a slow-motion past."""
RECONNECT_S = (0.5, 1.0, 2.0, 4.0, 8.0)
"""Waits (s) before each try to join again after the server went away; after the last the station gives up."""


def station_url(url: str) -> tuple[str, str]:
    """``ws://HOST:PORT[/ws][?token=T]`` as (the WebSocket's URL without the token, the token); a
    :class:`~marinesim.errors.ParameterError` names what is wrong with any other."""
    parts = urlsplit(url)
    if parts.scheme not in ("ws", "wss") or not parts.hostname:
        raise ParameterError(f"--connect {url}: expected ws://HOST:PORT/ws?token=TOKEN, as marinesim serve prints it")
    try:
        port = parts.port
    except ValueError:
        port = None
    if port is None:
        raise ParameterError(f"--connect {url}: expected a port (ws://HOST:PORT/ws?token=TOKEN)")
    token = parse_qs(parts.query).get("token", [""])[0]
    if not token:
        raise ParameterError(f"--connect {url}: no token; give the URL marinesim serve printed, with ?token=")
    return f"{parts.scheme}://{parts.netloc}{parts.path if parts.path not in ('', '/') else '/ws'}", token


def station_name(name: str) -> str:
    """A station's name as ``--station`` gives it; refused if empty, too long or not printable."""
    if not (0 < len(name) <= MAX_STATION and name.isprintable()) or name == EVERYONE:
        raise ParameterError(f"--station {name!r}: expected a name of 1 to {MAX_STATION} characters (not "
                             f"{EVERYONE!r})")
    return name


class Link:
    """The connection to the server at ``url`` (with its token), on a thread of its own: it says ``hello`` on every
    (re)join, queues what the server sends (:meth:`received`) and sends what it is given (:meth:`send`). A server
    that goes away is joined again at its current time (:data:`RECONNECT_S`); ``say`` is told each time."""

    def __init__(self, url: str, hello: dict[str, Any], say: Callable[[str], None] = quiet) -> None:
        self.address, self.token = station_url(url)
        self.hello = hello | {"token": self.token}
        self.say = say
        self._inbox: queue.SimpleQueue = queue.SimpleQueue()
        self._closing = False
        self._loop = asyncio.new_event_loop()
        self._outbox: asyncio.Queue = asyncio.Queue()
        self._thread = threading.Thread(target=self._run, daemon=True, name="marinesim-station-link")
        self._thread.start()

    def received(self, wait_s: float | None = None) -> list[dict[str, Any]]:
        """What the server sent since the last call (waiting up to ``wait_s`` for the first, if none yet)."""
        out = []
        try:
            out.append(self._inbox.get(timeout=wait_s) if wait_s else self._inbox.get_nowait())
            while True:
                out.append(self._inbox.get_nowait())
        except queue.Empty:
            pass
        return out

    def send(self, message: dict[str, Any]) -> None:
        """Send ``message`` (a JSON object; the token is added) as soon as the socket can."""
        self._loop.call_soon_threadsafe(self._outbox.put_nowait, message | {"token": self.token})

    def close(self) -> None:
        self._closing = True
        if self._thread.is_alive():
            self._loop.call_soon_threadsafe(self._outbox.put_nowait, None)
            self._thread.join(timeout=10.0)

    def _run(self) -> None:
        """The thread: the connection until the exercise ends or the station closes; whatever stops it otherwise
        is put in the inbox, so the station says so instead of waiting for ever."""
        try:
            self._loop.run_until_complete(self._main())
        except Exception as error:  # noqa: BLE001 (any failure of the link is the station's to report)
            self._inbox.put({"type": "failed", "message": f"--connect {self.address}: the link failed ({error})"})

    async def _main(self) -> None:
        import aiohttp

        tries = 0
        async with aiohttp.ClientSession() as session:
            while True:
                try:
                    async with session.ws_connect(f"{self.address}?token={self.token}", heartbeat=20.0) as ws:
                        await ws.send_json(self.hello)
                        tries = 0
                        if await self._session(ws):
                            return
                    self.say("the server closed the connection; joining again at the current time")
                    await asyncio.sleep(RECONNECT_S[0])
                except aiohttp.WSServerHandshakeError as error:
                    why = {403: "wrong token", 503: "the server is full"}.get(error.status, error.message)
                    self._inbox.put({"type": "failed", "message": f"--connect {self.address}: the server refused the "
                                                                  f"station ({error.status}: {why})"})
                    return
                except (aiohttp.ClientError, ConnectionError, asyncio.TimeoutError) as error:
                    if tries >= len(RECONNECT_S):
                        self._inbox.put({"type": "failed", "message": f"--connect {self.address}: the server went "
                                                                      f"away and did not come back ({error})"})
                        return
                    self.say(f"the server went away ({error or type(error).__name__}); joining again in "
                             f"{RECONNECT_S[tries]:g} s")
                    await asyncio.sleep(RECONNECT_S[tries])
                    tries += 1

    async def _session(self, ws) -> bool:
        """One connection: messages in to the inbox, the outbox out; True when it should not be joined again (the
        exercise ended, the station closed, or the server refused it for good)."""
        import aiohttp

        sender = asyncio.create_task(self._send_all(ws))
        try:
            async for message in ws:
                if message.type != aiohttp.WSMsgType.TEXT:
                    break
                data = json.loads(message.data)
                if data.get("type") == "error" and data.get("fatal"):
                    self._inbox.put({"type": "failed", "message": f"--connect: {data.get('message')}"})
                    return True
                self._inbox.put(data)
                if data.get("ended"):
                    return True
            return self._closing
        finally:
            sender.cancel()

    async def _send_all(self, ws) -> None:
        while (message := await self._outbox.get()) is not None:
            try:
                await ws.send_json(message)
            except ConnectionError:  # the socket dropped: the reader sees it and joins again
                return
        await ws.close()


class Station:
    """``exercise`` (fresh, at time 0, of the served scenario) following the server through ``link`` as the station
    ``name``: what a viewer's scene steps (``scene.follow``) or a headless loop (:func:`follow_headless`)."""

    def __init__(self, exercise: Exercise, link: Link, name: str, say: Callable[[str], None] = quiet) -> None:
        self.exercise, self.link, self.name, self.say = exercise, link, name, say
        self.replay = Replay(exercise, [])
        self.journal: list[dict[str, Any]] = []
        self.server_s = 0.0
        """The last time the server gave (s)."""
        self.scale = 1.0
        """The server's time scale (simulated s a second)."""
        self.frozen = self.joined = self.ended = False
        self._since_lag = LAG_REPORT_S

    @classmethod
    def join(cls, exercise: Exercise, url: str, name: str, say: Callable[[str], None] = quiet) -> Station:
        """Join the exercise served at ``url`` as ``name`` with the local, fresh ``exercise``."""
        hello = {"type": "hello", "role": "station", "station": station_name(name),
                 "scenario_sha256": sha256(exercise.scenario.path), "marinesim": __version__}
        return cls(exercise, Link(url, hello, say), name, say)

    def poll(self, wait_s: float | None = None) -> None:
        """Take in what the server sent (waiting up to ``wait_s`` for it): welcomes, states, refusals."""
        for message in self.link.received(wait_s):
            kind = message.get("type")
            if kind == "failed":
                raise MarinesimError(message["message"])
            if kind == "error":
                self.say(f"server: {message.get('message')}")
            elif kind == "welcome":  # on a rejoin, only the entries this station has not had
                self.joined = True
                self._receive(message | {"journal": message["journal"][len(self.journal):]})
            elif kind == "state" and self.joined:
                self.frozen, self.scale = bool(message.get("frozen")), float(message.get("scale", 1.0))
                self._receive(message)

    def _receive(self, message: dict[str, Any]) -> None:
        entries = message.get("journal", [])
        self.journal += entries
        self.replay.add(entries)
        self.server_s = max(self.server_s, float(message["t"]))
        self.ended = self.ended or bool(message.get("ended"))

    def step(self, dt: float) -> None:
        """``dt`` s of wall time: what came in taken in, the local exercise moved on at the server's pace, never past
        the server's time and never more than :data:`CATCH_UP_S` behind it (to it, while the server is frozen)."""
        self.poll()
        sim = self.exercise.sim
        target = self.server_s if self.frozen else min(self.server_s, max(sim.time + dt * self.scale,
                                                                          self.server_s - CATCH_UP_S))
        if target > sim.time:
            self.replay.advance_to(target)
        self._since_lag += dt
        if self.joined and self._since_lag >= LAG_REPORT_S:
            self._since_lag = 0.0
            self.link.send({"type": "lag", "lag_s": self.lag_s})

    def catch_up(self) -> None:
        """Move the local exercise on to the server's last time."""
        self.poll()
        self.replay.advance_to(self.server_s)

    @property
    def lag_s(self) -> float:
        """How far the local exercise is behind the server's time (s)."""
        return max(self.server_s - self.exercise.sim.time, 0.0)

    def send(self, action: str, fields: dict[str, Any]) -> None:
        """The trainee's ``action`` (an order, an acknowledgement, a report) to the server; it comes back in the
        journal and is applied then, here as everywhere."""
        self.link.send({"type": "action", "action": action, "fields": fields})

    def close(self) -> None:
        self.link.close()


def follow_headless(station: Station, on_step: Callable[[Station], None] = lambda s: None,
                    wait_s: float = 5.0) -> None:
    """Follow ``station``'s exercise to its end without a window: each time the server speaks, catch up to its time,
    then ``on_step(station)``."""
    said = -LAG_REPORT_S
    while not station.ended:
        station.poll(wait_s)
        station.catch_up()
        on_step(station)
        if station.joined and time.monotonic() - said >= LAG_REPORT_S:
            said = time.monotonic()
            station.link.send({"type": "lag", "lag_s": station.lag_s})
