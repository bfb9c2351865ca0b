"""``marinesim assess``: run a scenario headless, events included, and report its motion criteria."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from marinesim.atomic import strict_json
from marinesim.cli.common import bars

if TYPE_CHECKING:
    from marinesim.session.exercise import Assessment


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "assess", help="run a scenario's exercise headless and report its criteria",
        description="Run the scenario headless over its duration, its events included, evaluate each "
                    "[[criteria]] entry over its running window, and report the worst value of each, the "
                    "time spent above its limit and when it first went above, the events and a verdict.")
    p.add_argument("scenario", type=Path, help="scenario TOML file with [[criteria]]")
    p.add_argument("--json", action="store_true", help="print the assessment as JSON")
    p.add_argument("--duration", type=float, help="run length, s (default: the scenario's)")
    p.add_argument("--seed", type=int, help="random seed (default: the scenario's)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.errors import ScenarioError
    from marinesim.progress import reporting
    from marinesim.scenario import load_scenario, with_run
    from marinesim.session.exercise import run_exercise

    scenario = with_run(load_scenario(args.scenario), args.duration, seed=args.seed)
    if not scenario.criteria:
        raise ScenarioError(f"{scenario.path}: no [[criteria]]: nothing to assess")
    log = (lambda line: print(line, file=sys.stderr)) if args.json else print
    with reporting(bars(args.quiet)):
        exercise = run_exercise(scenario, log=log)
    result = exercise.assessment()
    print(strict_json(result.as_dict(), indent=2) if args.json else "\n".join(table(result)))
    return 0


def table(result: Assessment) -> list[str]:
    """The assessment as text lines: one per criterion, then the verdict; a run stopped early says how much of it
    ran, and the level of each criterion it could not judge is marked so."""
    from marinesim.criteria.monitor import value_and_limit
    from marinesim.session.exercise import ran_words, share_words

    rows = [("criterion", "worst", "limit", "unit", "level", "above limit", "first above", "expected", "percentile",
             "chance above limit")]
    for c in result.criteria:
        if c.value is None:
            worst, limit = "settling", f"{c.limit:.3g}"
        else:
            worst, limit = value_and_limit(c.value, c.limit)
        first = "-" if c.first_exceeded_s is None else f"{c.first_exceeded_s:.0f} s"
        level = c.level.value if c.judged else f"{c.level.value} (not judged)"
        rows.append((c.name, worst, limit, c.unit or "-", level, f"{c.time_exceeded_s:.0f} s", first,
                     "-" if c.expected is None else f"{c.expected:.3g}",
                     "-" if c.percentile is None else f"{c.percentile:.0f}",
                     "-" if c.chance_exceeded is None else share_words(c.chance_exceeded)))
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    lines = [f"{result.scenario}: {result.duration_s:g} s at dt {result.dt_s:g} s, seed {result.seed}"]
    if any(c.expected is not None for c in result.criteria):
        lines.append("expected: the worst value's median over seeds in the sea met (docs/FORMULAS.md); percentile: "
                     "where this run's worst falls among seeds")
    if not result.complete:
        lines.append(f"stopped early: ran {ran_words(result.duration_s, result.planned_s)}")
    lines += ["  ".join(cell.ljust(width) for cell, width in zip(row, widths)).rstrip() for row in rows]
    return lines + [f"verdict: {result.verdict}"]
