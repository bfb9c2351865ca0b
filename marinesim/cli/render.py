"""``marinesim render``: a scenario drawn headless through EGL, as an MP4 with its motions or a PNG."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import add_view_options, bars, refuse_overwriting, render_options
from marinesim.errors import ParameterError


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "render", help="render a scenario headless: an MP4 video with its motion CSV, or a screenshot",
        description="Render a scenario without a window (EGL). A video gets the motions over its length "
        "beside it (the same file `marinesim export --duration SECONDS` writes).",
    )
    p.add_argument("scenario", nargs="?", type=Path, help="scenario TOML file (default: the shipped default.toml)")
    p.add_argument("--out", type=Path, help="video file (.mp4); its motions go beside it as .csv")
    p.add_argument("--seconds", type=float, default=20.0, help="video length, s of simulated time (default 20)")
    p.add_argument("--fps", type=float, default=30.0, help="frames per second (default 30)")
    p.add_argument("--size", default="1280x720", help="WIDTHxHEIGHT in pixels, even (default 1280x720)")
    p.add_argument("--screenshot", type=Path, metavar="PNG", help="write one frame as a PNG instead of a video")
    p.add_argument("--time", type=float, default=0.0, help="time of the screenshot, s (default 0)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    add_view_options(p)
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.progress import reporting
    from marinesim.render.offscreen import parse_size, render_video, screenshot
    from marinesim.resources import default_scenario
    from marinesim.scenario import load_scenario

    size = parse_size(args.size)
    if (args.out is None) == (args.screenshot is None):
        raise ParameterError("give either --out VIDEO.mp4 or --screenshot SHOT.png")
    scenario = load_scenario(args.scenario or default_scenario())
    refuse_overwriting(args.screenshot, "--screenshot")
    refuse_overwriting(args.out, "--out")
    refuse_overwriting(None if args.out is None else args.out.with_suffix(".csv"), "--out", sidecar=True)
    if args.screenshot is not None:
        path = screenshot(scenario, args.screenshot, args.time, size, args.camera, args.solver, render_options(args))
        print(f"wrote the frame at {args.time:g} s ({size[0]}x{size[1]}, camera {args.camera}): {path}")
        return 0
    if args.out.suffix.lower() != ".mp4":
        raise ParameterError(f"--out must be an .mp4 file, got {args.out}")
    with reporting(bars(args.quiet)):
        result = render_video(scenario, args.out, args.seconds, size, args.fps, args.camera, args.solver,
                              render_options(args))
    print(f"wrote {result.frames} frames ({args.seconds:g} s at {result.fps:g} frames/s, {size[0]}x{size[1]}, "
          f"solver {'on' if result.solver else 'off'}): {result.video}")
    if result.motions is not None:
        print(f"wrote the motions over the video (as marinesim export): {result.motions}")
    return 0
