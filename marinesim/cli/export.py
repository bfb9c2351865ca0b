"""``marinesim export``: the vessel's motion time series as CSV or Parquet, with a JSON sidecar."""

from __future__ import annotations

import argparse
from pathlib import Path

from marinesim.cli.common import add_motion_options, bars, motion_scenario, refuse_overwriting
from marinesim.errors import ParameterError


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "export", help="write the vessel's motion time series (CSV + JSON sidecar)",
        description="Compute the vessel's 6-DOF motions, velocities, accelerations, named points and the wave "
                    "elevation for a scenario, or for an RAO file in a sea given as options (--rao), and write them "
                    "atomically, with a JSON sidecar beside.")
    p.add_argument("scenario", nargs="?", type=Path,
                   help="scenario TOML file (needs a [vessel] section); or --rao FILE and the sea options")
    p.add_argument("--out", type=Path, required=True, help="output file (e.g. motions.csv)")
    p.add_argument("--duration", type=float, help="run length, s (default: the scenario's)")
    p.add_argument("--dt", type=float, help="time step, s (default: the scenario's)")
    p.add_argument("--seed", type=int, help="random seed (default: the scenario's)")
    p.add_argument("--format", choices=("csv", "parquet"),
                   help="table format (default: from the extension, .csv or .parquet; else csv)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    add_motion_options(p, "<out>.toml beside the table: m.csv.toml")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.progress import reporting
    from marinesim.session.assembly import Assembly
    from marinesim.session.export import export_motions, outside_table_note

    kept = _beside(args.out)  # before anything: an --out with no file name is refused
    scenario = motion_scenario(args, lambda rao: kept, tables=(args.out,))
    refuse_overwriting(args.out, "--out", sidecar=True)
    with reporting(bars(args.quiet)):
        result = export_motions(Assembly(scenario), args.out, args.format)
    made = f"; scenario: {scenario.path}" if args.rao is not None else ""
    print(f"wrote {result.rows} rows x {len(result.columns)} columns to {result.table} "
          f"(metadata: {result.sidecar}{made})")
    note = outside_table_note(result.outside_table)
    if note is not None:
        print(note)
    for note in scenario.notes:
        print(f"note: {note}")
    return 0


def _beside(table: Path) -> Path:
    """Where the scenario of the options goes without --save-scenario: beside the ``table``, its name and .toml."""
    if table.name in ("", ".", ".."):
        raise ParameterError(f"the export needs a file name, got {str(table)!r}")
    return table.with_name(f"{table.name}.toml")
