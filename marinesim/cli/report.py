"""``marinesim report``: the after-action report of a session log or a scenario, one HTML file."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import bars, refuse_overwriting


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "report", help="write the after-action report of a session log or a scenario (HTML)",
        description="Run a session log again (or a scenario's exercise, headless) and write the debrief as one "
                    "self-contained HTML file: the briefing and a verdict per objective, every criterion over "
                    "time with its limit, caution line and the events, exceedance statistics, the alarms with "
                    "their acknowledgement delays, motion sickness (MSI, MSDV) and the conditions. The debrief of a "
                    "session log that is not verified (no sidecar, a sha256 or signature that does not match, no end "
                    "entry, signed on another installation) carries an UNVERIFIED LOG banner saying why.")
    p.add_argument("source", type=Path, help="session log (.jsonl) or scenario (.toml)")
    p.add_argument("--out", type=Path, required=True, help="the report's HTML file")
    p.add_argument("--duration", type=float, help="a scenario's run length, s (default: the scenario's)")
    p.add_argument("--seed", type=int, help="a scenario's random seed (default: the scenario's)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.errors import ParameterError
    from marinesim.progress import reporting
    from marinesim.report.debrief import debrief, sickness_criteria
    from marinesim.report.html import write_report
    from marinesim.scenario import load_scenario, with_run
    from marinesim.session.exercise import ran_words, run_exercise
    from marinesim.session.log import read_log
    from marinesim.session.replay import replay_session, session_scenario

    is_log = args.source.suffix.lower() in (".jsonl", ".log")
    with reporting(bars(args.quiet)):
        if is_log:
            if args.duration is not None or args.seed is not None:
                raise ParameterError("--duration and --seed are the session's own: give them with a scenario")
            session = read_log(args.source)
            print(f"session log {session.verification.summary()}")
            watch = sickness_criteria(session_scenario(session, args.source))
            refuse_overwriting(args.out, "--out")
            exercise = replay_session(session, watch=watch, log=print)
        else:
            session = None
            scenario = with_run(load_scenario(args.source), args.duration, seed=args.seed)
            refuse_overwriting(args.out, "--out")
            exercise = run_exercise(scenario, log=print, watch=sickness_criteria(scenario))
    out = write_report(debrief(exercise, session), args.out)
    result = exercise.assessment()
    ran = "" if result.complete else f" (stopped early: ran {ran_words(result.duration_s, result.planned_s)})"
    print(f"verdict: {result.verdict}{ran}")
    marked = " (marked UNVERIFIED LOG)" if session is not None and not session.verification.verified else ""
    print(f"wrote the after-action report: {out}{marked}")
    return 0
