"""``marinesim capability``: the DP capability envelope of a scenario's vessel (:mod:`marinesim.station.capability`)."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import refuse_overwriting


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "capability", help="the DP capability envelope: the strongest wind she holds station in, per direction",
        description="For each direction the wind, its sea and a 0.75 m/s current come from together (relative to "
                    "the bow), the strongest mean wind at which the thrusters of the scenario's vessel on DP "
                    "([station]) still balance them: a static balance in the manner of DNV-ST-0111 level 1.")
    p.add_argument("scenario", type=Path, help="scenario (.toml) with a [station] on DP")
    p.add_argument("--lose", action="append", default=[], metavar="THRUSTER",
                   help="leave this thruster out (a failure); may be given more than once")
    p.add_argument("--json", action="store_true",
                   help='print one JSON object: {"directions_deg": [...], "limiting_wind_m_s": [...], ...}')
    p.add_argument("--plot", type=Path, metavar="PATH", help="draw the envelope as a polar plot (PNG)")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.atomic import atomic_path, strict_json
    from marinesim.errors import ParameterError, ScenarioError
    from marinesim.scenario import load_scenario
    from marinesim.station.capability import envelope

    if args.plot is not None and not args.plot.resolve().parent.is_dir():
        raise ParameterError(f"cannot write {args.plot}: folder {args.plot.resolve().parent} does not exist")
    scenario = load_scenario(args.scenario)
    station = scenario.station
    if station is None or scenario.vessel.ship.thrusters is None:
        raise ScenarioError(f"{args.scenario}: no vessel on DP ([station] with mode = \"dp\"): no capability")
    ship = scenario.vessel.ship
    for name in args.lose:
        ship.thrusters.index(name)
    refuse_overwriting(args.plot, "--plot")
    result = envelope(ship.thrusters, station.wind, ship.d, station.drift, tuple(args.lose))
    if args.plot is not None:
        from marinesim.station.plot import plot_capability

        intact = envelope(ship.thrusters, station.wind, ship.d, station.drift) if args.lose else None
        with atomic_path(args.plot) as temp:
            plot_capability(result, temp, ship.name, intact)
    if args.json:
        print(strict_json(result.as_json(), indent=2))
        return 0
    lost = f" without {', '.join(args.lose)}" if args.lose else ""
    print(f"DP capability of the {ship.name}{lost}: limiting mean wind (m/s) with its sea and a 0.75 m/s current, "
          f"all from the direction (deg from the bow, clockwise)")
    if not result.waves:
        print("  her station-keeping file has no drift table: the waves' drift is left out (the envelope is "
              "optimistic)")
    for deg, wind in zip(result.directions_deg, result.limiting_wind_m_s):
        print(f"  {deg:5.0f}  {wind:5.1f}" + ("+" if wind >= 40.0 else ""))
    return 0
