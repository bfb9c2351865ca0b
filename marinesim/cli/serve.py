"""``marinesim serve``: an exercise run at real-time pace for an instructor's web page and the stations that join."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import add_stream_options, bars, next_log, open_streams, refuse_overwriting

DEFAULT_BIND = "127.0.0.1:8765"
"""The loopback: another machine reaches the server only where ``--bind`` says so."""


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "serve", help="run an exercise for an instructor's web page and networked stations",
        description="Run the scenario's exercise headless at real-time pace in this process and serve the "
                    "instructor's page (chart, briefing, criteria, alarms, events, sea and weather controls, "
                    "messages, freeze and time scale) and the stations that join it (marinesim run --connect). "
                    "It prints the page's address with a secret token; every control needs that token. The session "
                    "log is written when the exercise ends or the server is stopped (Ctrl-C).")
    p.add_argument("scenario", type=Path, help="scenario TOML file")
    p.add_argument("--bind", default=DEFAULT_BIND, metavar="HOST:PORT",
                   help=f"where to listen (default {DEFAULT_BIND}, this machine only; 0.0.0.0:PORT lets other "
                        "machines join, with the token; port 0 takes a free one)")
    p.add_argument("--log", type=Path, help="the session log (default sessions/<scenario name>-NNN.jsonl)")
    p.add_argument("--duration", type=float, help="run length, s (default: the scenario's)")
    p.add_argument("--seed", type=int, help="random seed (default: the scenario's)")
    p.add_argument("--time-scale", type=float, default=1.0, metavar="X",
                   help="simulated seconds a second at the start (0.25, 0.5, 1, 2, 4 or 8; default 1, real time; "
                        "the page changes it)")
    p.add_argument("--frozen", action="store_true",
                   help="start frozen at 0 s: the stations join and the briefing is given, then the instructor's "
                        "resume starts the clock")
    add_stream_options(p)
    p.add_argument("--quiet", action="store_true", help="no progress bar while the exercise is prepared")
    p.set_defaults(handler=handle)


def bind_address(text: str) -> tuple[str, int]:
    """``HOST:PORT`` as (host, port); a :class:`~marinesim.errors.ParameterError` for anything else."""
    from marinesim.errors import ParameterError

    host, _, port = text.rpartition(":")
    if not host or not port.isdigit() or not 0 <= int(port) <= 65535:
        raise ParameterError(f"--bind {text}: expected HOST:PORT, e.g. {DEFAULT_BIND} (port 0 to 65535)")
    return host.strip("[]"), int(port)


def handle(args: argparse.Namespace) -> int:
    import asyncio

    from marinesim.errors import ParameterError
    from marinesim.net.server import SCALES, ExerciseServer, Pace
    from marinesim.progress import reporting
    from marinesim.scenario import load_scenario, with_run
    from marinesim.session.exercise import Exercise
    from marinesim.session.timeline import Simulation

    host, port = bind_address(args.bind)
    if args.time_scale not in SCALES:
        raise ParameterError(f"--time-scale {args.time_scale:g}: expected one of {', '.join(f'{x:g}' for x in SCALES)}")
    scenario = with_run(load_scenario(args.scenario), args.duration, seed=args.seed)
    streams = open_streams(args, scenario)
    log_path = args.log or next_log(scenario.name)
    refuse_overwriting(log_path, "--log", sidecar=True)  # before the exercise runs, not at its end
    with reporting(bars(args.quiet)), Simulation(scenario, wake=False) as simulation:
        exercise = Exercise(simulation, log=print)
        pace = Pace()
        pace.set_scale(args.time_scale)
        if args.frozen:
            pace.freeze()
        server = ExerciseServer(exercise, log_path, streams=streams, say=print, pace=pace)

        async def serve() -> None:
            bound = await server.start(host, port)
            where = f"{bound[0]}:{bound[1]}" if ":" not in bound[0] else f"[{bound[0]}]:{bound[1]}"
            print(f"serving {scenario.name} ({scenario.run.duration_s:g} s, seed {scenario.run.seed}) on {where}"
                  f"{'' if host in ('127.0.0.1', 'localhost', '::1') else ' (reachable from other machines)'}")
            print(f"instructor page: http://{where}/?token={server.token}"
                  + ("  (frozen at 0 s: resume on the page starts the exercise)" if args.frozen else ""))
            print(f"a station joins: marinesim run {scenario.path} --connect "
                  f"'ws://{where}/ws?token={server.station_token}' --station NAME")
            try:
                await server.run()
            finally:
                await server.close()

        try:
            if streams is not None:
                with streams:
                    asyncio.run(serve())
            else:
                asyncio.run(serve())
        except KeyboardInterrupt:
            print(f"stopped at t {exercise.sim.time:.1f} s; session log {server.log_written}")
    if streams is not None:
        print(f"streamed {streams.sent_nmea} NMEA sentences and {streams.sent_dis} DIS PDUs ({streams.describe()})")
    print(f"debrief it: marinesim report {server.log_written}")
    return 0
