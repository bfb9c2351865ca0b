"""``marinesim trials``: the IMO standard manoeuvres of a scenario's vessel (or of a manoeuvring file) in calm
water, with the criteria."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import bars, refuse_overwriting


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "trials", help="the IMO standard manoeuvres of a vessel in calm water, with the criteria",
        description="Turning circles (hard over to port and starboard), 10/10 and 20/20 zig-zags and the crash stop "
                    "(where the engine can go astern) of the scenario's vessel from its speed (or, at rest, its "
                    "approach speed), in calm water, against the criteria of IMO MSC.137(76). SCENARIO may also be "
                    "a manoeuvring file (configs/vessels/*.toml), trialled at its approach speed.")
    p.add_argument("scenario", type=Path, help="scenario (.toml) or manoeuvring file")
    p.add_argument("--json", action="store_true", help="print one JSON object: turning, zigzag, stopping, imo")
    p.add_argument("--plot", type=Path, metavar="PATH", help="draw the tracks and the zig-zags (PNG)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    import tomllib

    from marinesim.atomic import atomic_path, strict_json
    from marinesim.constants import KNOT
    from marinesim.errors import ParameterError, ScenarioError
    from marinesim.manoeuvring.trials import trials
    from marinesim.progress import reporting
    from marinesim.scenario import load_scenario
    from marinesim.scenario.ship_file import load_ship

    if args.plot is not None and not args.plot.resolve().parent.is_dir():
        raise ParameterError(f"cannot write {args.plot}: folder {args.plot.resolve().parent} does not exist")
    if _is_ship_file(args.scenario, tomllib):
        file, ship = load_ship(args.scenario)
        speed = file.approach_speed_kn * KNOT
    else:
        vessel = load_scenario(args.scenario).vessel
        if vessel is None:
            raise ScenarioError(f"{args.scenario}: no [vessel]: nothing to trial")
        ship = vessel.ship
        if ship.kind != "ship":
            raise ParameterError(f"{args.scenario}: {ship.name}: {ship.describe()}; no manoeuvring model to trial")
        speed = vessel.speed_m_s if vessel.speed_m_s > 0.0 else ship.approach_speed
    refuse_overwriting(args.plot, "--plot")
    with reporting(bars(args.quiet or args.json)):
        result = trials(ship, speed)
    if args.plot is not None:
        from marinesim.manoeuvring.plot import plot_trials

        with atomic_path(args.plot) as temp:
            plot_trials(result, temp)
    if args.json:
        print(strict_json(result.as_dict(), indent=2))
    else:
        print(_table(result))
    return 0


def _is_ship_file(path: Path, tomllib) -> bool:
    """Whether ``path`` holds a manoeuvring file (a top-level ``model`` and no ``[vessel]``), not a scenario."""
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return False  # the scenario loader words the error
    return "model" in data and "vessel" not in data


def _table(result) -> str:
    from marinesim.constants import KNOT

    length = result.length_m
    lines = [f"{result.name}: L {length:.1f} m, approach {result.speed_m_s / KNOT:.2f} kn, calm water"]
    for turn in (result.port, result.starboard):
        lines.append(f"  turning {turn.rudder_deg:+.0f} deg: advance {turn.advance_m:.0f} m "
                     f"({turn.advance_m / length:.2f} "
                     f"L), transfer {turn.transfer_m:.0f} m, tactical diameter {turn.tactical_diameter_m:.0f} m "
                     f"({turn.tactical_diameter_m / length:.2f} L), steady diameter {turn.steady_diameter_m:.0f} m, "
                     f"final speed {turn.final_speed_kn:.1f} kn")
    for z in (result.zigzag_10, result.zigzag_20):
        lines.append(f"  zig-zag {z.rudder_deg:g}/{z.heading_deg:g}: first overshoot {z.first_overshoot_deg:.1f} deg, "
                     f"second {z.second_overshoot_deg:.1f} deg")
    if result.stopping is None:
        lines.append("  crash stop: the engine cannot go astern")
    else:
        s = result.stopping
        lines.append(f"  crash stop: track reach {s.track_reach_m:.0f} m ({s.track_reach_m / length:.2f} L), "
                     "head reach "
                     f"{s.head_reach_m:.0f} m, {s.time_s:.0f} s")
    lines.append("IMO MSC.137(76): " + ("all criteria met" if result.passed else "NOT all criteria met"))
    for c in result.criteria:
        lines.append(f"  {'pass' if c['pass'] else 'FAIL'}  {c['name']}: {c['value']:.2f} {c['unit']} "
                     f"(limit {c['limit']:.3g})")
    return "\n".join(lines)
