"""A served exercise on a thread of its own, for the tests that drive a browser or stations from theirs."""

from __future__ import annotations

import asyncio
import threading
from pathlib import Path

from marinesim.net.server import ExerciseServer, Pace
from marinesim.session.exercise import Exercise
from marinesim.session.timeline import Simulation

WAIT_S = 300.0
"""s: what a test waits for at most (a hang; a loaded machine answers within seconds)."""


class ServedInThread:
    """A server over ``scenario`` at ``scale`` x real time on an event loop of its own, on a thread (the test drives
    a browser or stations from its own); its session log goes to ``log``."""

    def __init__(self, scenario, log: Path, scale: float = 1.0) -> None:
        self.sim = Simulation(scenario, wake=False)
        pace = Pace()
        pace.set_scale(scale)
        self.server = ExerciseServer(Exercise(self.sim), log, pace=pace)
        self.loop = asyncio.new_event_loop()
        self.started = threading.Event()
        self.thread = threading.Thread(target=self.loop.run_until_complete, args=(self._main(),), daemon=True)
        self.thread.start()
        assert self.started.wait(WAIT_S), "the server did not start"

    async def _main(self) -> None:
        self.host, self.port = await self.server.start("127.0.0.1", 0)
        self.started.set()
        try:
            await self.server.run()
        finally:
            await self.server.close()

    def close(self) -> None:
        self.loop.call_soon_threadsafe(self.server.stop)
        self.thread.join(WAIT_S)
        self.sim.close()

    @property
    def url(self) -> str:
        """The station's URL, with the token."""
        return f"ws://127.0.0.1:{self.port}/ws?token={self.server.token}"
