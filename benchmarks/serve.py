"""Benchmark: the exercise server's work per simulated second against the stations connected, and a journal that
loses and reorders nothing under load.

The server (``ExerciseServer``, in this process, on the loopback) runs the heavy-weather transit at real time. Each
station is ``marinesim run --connect ... --headless`` in a process of its own (its own copy of the exercise, as a
station machine would run it); an instructor sends a numbered message twice a second. Printed for each number of
stations (the baseline, none, first, in the same run): the server's CPU seconds per simulated second, its ticks'
mean and longest wall time against the budget (a tick every ``TICK_S``), the states it sent, whether every message
is in the journal once and in order, and whether each station applied every action.
Run: ``python benchmarks/serve.py [--stations 0 8] [--seconds 600]``.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import platform
import re
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

import aiohttp

from marinesim.net.server import TICK_S, ExerciseServer
from marinesim.scenario import load_scenario, with_run
from marinesim.session.exercise import Exercise
from marinesim.session.timeline import Simulation

TRANSIT = Path(__file__).resolve().parents[1] / "configs" / "training" / "heavy_weather_transit.toml"


def cpu_s() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


async def one(stations: int, seconds: float, folder: Path) -> dict:
    scenario = with_run(load_scenario(TRANSIT), seconds)
    with Simulation(scenario, wake=False) as sim:
        server = ExerciseServer(Exercise(sim), folder / f"served-{stations}.jsonl")
        host, port = await server.start("127.0.0.1", 0)
        url = f"ws://{host}:{port}/ws?token={server.token}"
        processes = [await asyncio.create_subprocess_exec(
            sys.executable, "-m", "marinesim", "run", str(TRANSIT), "--duration", str(seconds), "--connect", url,
            "--headless", "--station", f"station {k}", stdout=asyncio.subprocess.PIPE,
            stderr=asyncio.subprocess.STDOUT) for k in range(stations)]
        while len(server.stations()) < stations:  # every station built its exercise and joined
            await asyncio.sleep(0.5)
        cpu0, t0 = cpu_s(), sim.time
        sent = 0
        running = asyncio.create_task(server.run())
        async with aiohttp.ClientSession() as session, session.ws_connect(url) as ws:
            await ws.send_json({"type": "hello", "role": "instructor", "token": server.token})
            states = 0
            loop = asyncio.get_running_loop()
            while not running.done():
                await ws.send_json({"type": "action", "token": server.token, "action": "message",
                                    "fields": {"text": f"message {sent}", "to": "all"}})
                sent += 1
                next_send = loop.time() + 0.5
                try:
                    while (left := next_send - loop.time()) > 0:
                        message = await asyncio.wait_for(ws.receive_json(), left)
                        states += message.get("type") == "state"
                except (asyncio.TimeoutError, TypeError):  # time for the next message; the server closed
                    pass
        await running
        cpu = cpu_s() - cpu0
        outputs = [(await p.communicate())[0].decode() for p in processes]
        await server.close()
    journal = [e["text"] for e in server.exercise.journal if e.get("action") == "message"]
    applied = [int(m.group(1)) for out in outputs for m in [re.search(r"\((\d+) action\(s\) applied", out)] if m]
    actions = sum(e["kind"] == "action" for e in server.exercise.journal)
    return {"stations": stations, "cpu_per_sim_s": cpu / (sim.time - t0), "mean_tick_ms": 1e3 * server.load.total_s
            / max(server.load.ticks, 1), "longest_tick_ms": 1e3 * server.load.longest_s,
            "over_budget": server.load.over_budget, "ticks": server.load.ticks, "states_to_instructor": states,
            "messages_sent": sent, "in_order_once": journal == [f"message {i}" for i in range(len(journal))],
            "journaled": len(journal), "stations_applied_all": applied == [actions] * stations}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--stations", type=int, nargs="+", default=[0, 8])
    parser.add_argument("--seconds", type=float, default=600.0, help="simulated (and wall) seconds per run")
    args = parser.parse_args()
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"tick budget {1e3 * TICK_S:.0f} ms; {args.seconds:g} s at real time per run")
    with tempfile.TemporaryDirectory() as folder:
        rows = [asyncio.run(one(k, args.seconds, Path(folder))) for k in args.stations]
    base = rows[0]["cpu_per_sim_s"]
    for row in rows:
        print(f"{row['stations']} stations: server CPU {row['cpu_per_sim_s']:.4f} s per simulated s "
              f"(x{row['cpu_per_sim_s'] / base:.2f} the {rows[0]['stations']}-station baseline); ticks: mean "
              f"{row['mean_tick_ms']:.1f} ms, longest {row['longest_tick_ms']:.1f} ms, {row['over_budget']} of "
              f"{row['ticks']} over budget; {row['states_to_instructor']} states to the instructor; messages: "
              f"{row['journaled']} of {row['messages_sent']} journaled, once and in order: {row['in_order_once']}; "
              f"every station applied every action: {row['stations_applied_all']}")


if __name__ == "__main__":
    main()
