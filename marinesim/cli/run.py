"""``marinesim run``: the viewer on a scenario, or, without a display, the headless run and a short video."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from marinesim.cli.common import (add_motion_options, add_stream_options, add_view_options, bars, motion_scenario,
                                  next_log, open_streams, render_options)

HEADLESS_VIDEO = {"seconds": 10.0, "size": (640, 360), "fps": 25.0}
"""The video a headless ``run --video`` renders: short and small, so that a software renderer makes it in about
half a minute."""
DESCRIBED = {"sea_plot": "the sea state picture", "motions": "the vessel's 6-DOF motions",
             "sidecar": "their metadata", "motions_plot": "a plot of the motions", "rao_plot": "the RAOs",
             "elevation": "the wave elevation at (0, 0)", "elevation_plot": "a plot of it",
             "wake_plot": "the Kelvin wake", "video": "a video of the first seconds",
             "assessment": "the exercise's criteria and events", "session_log": "its session log"}
"""What each file of a headless run is, as the closing lines say."""


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "run", help="open the viewer on a scenario (default: the shipped configs/default.toml)",
        description="Open the viewer on a scenario: the vessel moving in the rendered sea with its wake "
        "(H in the window lists the keys). Without a display it runs headless instead: plots of the sea, "
        "the motions and the RAOs, the motion CSV over the scenario's run (an exercise's assessment and session "
        "log too), with --video a 10 s video, and says where they are.",
    )
    p.add_argument("scenario", nargs="?", type=Path, help="scenario TOML file (default: the shipped default.toml); "
                                                         "or --rao FILE and the sea options")
    p.add_argument("--out", type=Path, help="output folder of a headless run (default out/<scenario name>)")
    p.add_argument("--duration", type=float, help="run length, s (default: the scenario's); the video is the "
                                                  "first 10 s of it at most")
    p.add_argument("--dt", type=float, help="time step, s (default: the scenario's)")
    p.add_argument("--seed", type=int, help="random seed (default: the scenario's)")
    p.add_argument("--video", action="store_true", help="a headless run also renders the first 10 s as a "
                                                        "640x360 video (video.mp4)")
    p.add_argument("--headless", action="store_true", help="do not open a window even if there is a display")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--log", type=Path, help="the viewer session's log, written when the window closes "
                                            "(default sessions/<scenario name>-NNN.jsonl, the next free number; "
                                            "a headless run of an exercise writes session.jsonl in its --out)")
    add_motion_options(p, "<out>/<RAO name>.toml: the run's output folder, --out or out/<RAO name>")
    add_view_options(p)
    p.add_argument("--yaw-offset-deg", type=float, default=0.0, metavar="D",
                   help="the bridge camera looks D deg to starboard of the bow (a 3-channel bridge: -60, 0, 60)")
    g = p.add_argument_group("a station of a served exercise (marinesim serve)")
    g.add_argument("--connect", metavar="ws://HOST:PORT/ws?token=T",
                   help="follow the exercise marinesim serve runs there (the same scenario file): its clock, the "
                        "instructor's changes and messages; this station's orders and reports (M) go to it")
    g.add_argument("--station", default="bridge", help="this station's name, as the instructor's page lists it and "
                                                        "addresses messages to it (default bridge)")
    add_stream_options(p)
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.errors import ParameterError
    from marinesim.progress import reporting
    from marinesim.resources import default_scenario
    from marinesim.session.assembly import Assembly
    from marinesim.session.headless import run_headless

    scenario = motion_scenario(args, lambda rao: (args.out or Path("out") / rao.stem) / f"{rao.stem}.toml",
                               default_scenario(), make_folder=True)
    print(f"scenario {scenario.path}: {len(scenario.sea.systems)} wave system(s), Hs {scenario.sea.hs:.2f} m, "
          f"Tp {scenario.sea.tp:.2f} s, {scenario.run.duration_s:g} s at dt {scenario.run.dt_s:g} s, "
          f"seed {scenario.run.seed}")
    vessel = scenario.vessel
    if vessel is not None:
        print(f"vessel: {vessel.rao_path.name} ({vessel.rao.source_format}), {vessel.speed_kn:.3g} kn, "
              f"heading {vessel.heading_deg:g} deg, points: {', '.join(vessel.points) or 'none'}")
        print(f"manoeuvring: {vessel.ship.name}, {vessel.ship.describe()}")
    for note in scenario.notes:
        print(f"note: {note}")
    if args.connect:
        if args.nmea or args.dis:
            raise ParameterError("--nmea and --dis stream from marinesim serve, the exercise's one process, not "
                                 "from a station")
        return _station(args, scenario)
    streams = open_streams(args, scenario)
    if not args.headless:
        from marinesim.render.viewer import NoDisplay, Viewer

        try:
            with reporting(bars(args.quiet)):
                viewer = Viewer(scenario, args.camera, args.solver, options=render_options(args),
                                log_path=args.log or next_log(scenario.name))
        except NoDisplay as reason:
            print(f"{reason}: running headless instead")
        else:
            viewer.scene.cameras["bridge"].look_yaw_deg = -args.yaw_offset_deg
            print("viewer open: H lists the keys, ESC quits")
            if streams is not None:
                _stream_from_viewer(viewer, streams)
            try:
                viewer.run()
            finally:
                if streams is not None:
                    streams.close()
            return 0
    out_dir = args.out or Path("out") / scenario.name
    if streams is not None:
        _paced(scenario, streams)
    with reporting(bars(args.quiet)):
        headless = run_headless(Assembly(scenario), out_dir, log=print)
        for note in headless.notes:
            print(note)
        files = headless.files | (_video(scenario, out_dir, args) if args.video else {})
    width = max(len(DESCRIBED[key]) for key in files)
    for key, path in files.items():
        print(f"wrote {DESCRIBED[key] + ':':{width + 1}s} {path}")
    if "session_log" in files:
        log = files["session_log"]
        print(f"debrief it: marinesim report {log}; replay it: marinesim replay {log} --export replay.csv")
    if not args.video:
        print("no video: --video adds the first 10 s as video.mp4")
    return 0


def _station(args: argparse.Namespace, scenario) -> int:
    """Follow the exercise served at ``--connect`` as the station ``--station``: in the viewer, or without a display
    headless, saying what the instructor sends this station."""
    from marinesim.net.station import Station, follow_headless, station_url
    from marinesim.progress import reporting

    station_url(args.connect)  # refused before anything is built
    if not args.headless:
        from marinesim.render.viewer import NoDisplay, Viewer

        try:
            with reporting(bars(args.quiet)):
                viewer = Viewer(scenario, args.camera, args.solver, options=render_options(args), log_path=None)
        except NoDisplay as reason:
            print(f"{reason}: following headless instead")
        else:
            viewer.scene.cameras["bridge"].look_yaw_deg = -args.yaw_offset_deg
            viewer.scene.follow = station = Station.join(viewer.scene.exercise, args.connect, args.station,
                                                         say=print)
            print(f"station {args.station} open: following {station.link.address}; M reports to the instructor")
            try:
                viewer.run()
            finally:
                station.close()
            return 0
    from marinesim.session.exercise import Exercise
    from marinesim.session.timeline import Simulation

    with Simulation(scenario, wake=False) as simulation:
        exercise = Exercise(simulation, log=print)
        station = Station.join(exercise, args.connect, args.station, say=print)
        shown = 0

        def tell(_: Station) -> None:
            """Print the messages this station has not shown yet: the events' and the instructor's to it or all."""
            nonlocal shown
            lines = exercise.messages(span_s=math.inf, station=args.station)
            for line in lines[shown:]:
                print(line)
            shown = len(lines)

        print(f"station {args.station}: following {station.link.address} headless")
        try:
            follow_headless(station, tell)
        finally:
            station.close()
        actions = sum(entry["kind"] == "action" for entry in station.journal)
        print(f"station {args.station}: followed the exercise to t {exercise.sim.time:.1f} s "
              f"({actions} action(s) applied at their times)")
    return 0


def _paced(scenario, streams) -> None:
    """Run the exercise at real-time pace, streaming own-ship's state (``--nmea``, ``--dis``), before the headless
    run's files are written."""
    import asyncio

    from marinesim.net.server import ExerciseServer
    from marinesim.session.exercise import Exercise
    from marinesim.session.timeline import Simulation

    print(f"streaming own-ship in real time for {scenario.run.duration_s:g} s ({streams.describe()}); Ctrl-C stops")
    with Simulation(scenario, wake=False) as simulation, streams:
        asyncio.run(ExerciseServer(Exercise(simulation, log=print), None, streams=streams).run())
    print(f"streamed {streams.sent_nmea} NMEA sentences and {streams.sent_dis} DIS PDUs")


def _stream_from_viewer(viewer, streams) -> None:
    """Own-ship's state out each second of the viewer's clock (``--nmea``, ``--dis``)."""
    import numpy as np
    import pyglet

    def send(_: float) -> None:
        sim = viewer.scene.sim
        for at in streams.pending(sim.time):
            streams.send(at, {name: float(c[0]) for name, c in sim.frame(np.array([at])).items()})

    pyglet.clock.schedule_interval(send, 0.1)


def _video(scenario, out_dir: Path, args: argparse.Namespace) -> dict[str, Path]:
    """The first seconds of ``scenario`` as a small video, drawn through EGL."""
    from marinesim.render.offscreen import render_video

    video = HEADLESS_VIDEO
    seconds = min(video["seconds"], scenario.run.duration_s)
    size = video["size"]
    print(f"rendering {seconds:g} s of video at {size[0]}x{size[1]}, {video['fps']:g} frames/s through EGL "
          f"(camera {args.camera})")
    result = render_video(scenario, out_dir / "video.mp4", seconds, size, video["fps"], args.camera, args.solver,
                          render_options(args), motions=False)
    solver = "on" if result.solver else "off (software renderer; --solver on forces it)"
    cascades = "GPU" if result.gpu_cascades else "CPU (software renderer; --cascades gpu forces the GPU)"
    print(f"the local wave solver was {solver}; the ocean's waves were synthesised on the {cascades}")
    return {"video": result.video}
