"""``marinesim replay``: a session log opened again in the viewer with a time slider, or replayed headless."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import add_view_options, bars, refuse_overwriting, render_options


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "replay", help="replay a session log: in the viewer with a time slider, or headless",
        description="Open a session log (written by the viewer when it closes, JSON lines) in the viewer: "
                    "the same scenario, seed and live actions at the same times, with a time slider (LEFT/RIGHT "
                    "seek 30 s, HOME start, click the slider, SPACE pause, + / - pace). With --export, or "
                    "without a display, replay it headless to its end: with --export the motions are written as "
                    "the session's recorder wrote them, to the same bytes. A log that is not verified (no sidecar, "
                    "a sha256 or signature that does not match, no end entry, signed on another installation) "
                    "is refused unless --unverified is given.")
    p.add_argument("log", type=Path, help="session log (.jsonl)")
    p.add_argument("--export", type=Path, help="write the session's motions (CSV, with its sidecar) and exit")
    p.add_argument("--headless", action="store_true", help="do not open a window even if there is a display")
    p.add_argument("--unverified", action="store_true",
                   help="replay a log that is not verified, said to be UNVERIFIED (default: refused)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    add_view_options(p)
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.cli.assess import table
    from marinesim.errors import MarinesimError
    from marinesim.progress import reporting
    from marinesim.session.log import describe, read_log
    from marinesim.session.replay import replay_session, session_scenario

    session = read_log(args.log)
    refuse_overwriting(args.export, "--export", sidecar=True)
    check = session.verification
    if not check.verified and not args.unverified:
        raise MarinesimError(f"{args.log}: {check.summary()}; give --unverified to replay it anyway")
    print(f"session {args.log}: {describe(session)}")
    print(f"session log {check.summary()}")
    if args.export is None and not args.headless:
        from marinesim.render.viewer import NoDisplay, Viewer

        scenario = session_scenario(session, args.log)
        try:
            with reporting(bars(args.quiet)):
                viewer = Viewer(scenario, args.camera, args.solver, options=render_options(args), replay=session)
        except NoDisplay as reason:
            print(f"{reason}: replaying headless instead")
        else:
            print("replay open: LEFT/RIGHT seek, SPACE pause, H lists the keys, ESC quits")
            viewer.run()
            return 0
    with reporting(bars(args.quiet)):
        exercise = replay_session(session, args.export, log=print)
    if exercise.monitor is not None:
        print("\n".join(table(exercise.assessment())))
    if args.export is not None:
        print(f"wrote the session's motions: {args.export} (sidecar {args.export}.json)")
    return 0
